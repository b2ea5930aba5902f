//! The COLLADA reader against the OBJ's cube, closed forms placed through node trees in
//! centimetres (translate, rotate, scale, matrix, instanced library nodes, mirroring), each
//! primitive kind, and bad files refused by name.

use std::path::Path;

use nalgebra::{Rotation3, Vector3};

use super::super::tests::{
    assert_close, placed_box, properties, signed_volume, two_unit_cubes_four_apart,
};
use super::*;
use crate::mass_properties;

/// The unit cube [0, 1]³ as OBJ writes it (from 1), outward quads.
const CUBE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\n\
                        v 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n\
                        f 4 1 5 8\n";

/// The same cube as a COLLADA `<geometry>` of side `side` (in the file's units): positions and
/// six normals, the quads as a `<polylist>` whose corners carry a normal and a position index
/// (offsets 0 and 1).
fn cube_geometry(id: &str, side: f64) -> String {
    let corners = [
        [0, 0, 0],
        [1, 0, 0],
        [1, 1, 0],
        [0, 1, 0],
        [0, 0, 1],
        [1, 0, 1],
        [1, 1, 1],
        [0, 1, 1],
    ];
    let positions: Vec<String> = corners
        .iter()
        .flatten()
        .map(|&c| format!("{}", f64::from(c) * side))
        .collect();
    let quads = [
        [0, 3, 2, 1],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
    ];
    let p: Vec<String> = quads
        .iter()
        .enumerate()
        .flat_map(|(f, q)| q.iter().map(move |c| format!("{f} {c}")))
        .collect();
    format!(
        r##"<geometry id="{id}" name="{id}"><mesh>
  <source id="{id}-pos"><float_array id="{id}-pos-array" count="24">{}</float_array>
    <technique_common><accessor source="#{id}-pos-array" count="8" stride="3">
      <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
    </accessor></technique_common></source>
  <source id="{id}-nor"><float_array id="{id}-nor-array" count="18">0 0 -1 0 0 1 0 -1 0 1 0 0 0 1 0 -1 0 0</float_array>
    <technique_common><accessor source="#{id}-nor-array" count="6" stride="3"/></technique_common></source>
  <vertices id="{id}-vtx"><input semantic="POSITION" source="#{id}-pos"/></vertices>
  <polylist count="6" material="m">
    <input semantic="VERTEX" source="#{id}-vtx" offset="1"/>
    <input semantic="NORMAL" source="#{id}-nor" offset="0"/>
    <vcount>4 4 4 4 4 4</vcount><p>{}</p>
  </polylist>
</mesh></geometry>"##,
        positions.join(" "),
        p.join(" ")
    )
}

/// A COLLADA document: its unit (metres per unit) and axis, geometries, library nodes and the
/// visual scene's nodes.
fn dae(unit: f64, up: &str, geometries: &str, library: &str, scene: &str) -> String {
    format!(
        r##"<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="u" meter="{unit}"/><up_axis>{up}</up_axis></asset>
  <library_geometries>{geometries}</library_geometries>
  <library_nodes>{library}</library_nodes>
  <library_visual_scenes><visual_scene id="scene">{scene}</visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>"##
    )
}

fn read(text: &str) -> ColladaFile {
    parse_collada_file(text.as_bytes(), Path::new("scene.dae")).expect("reads")
}

/// The cube in metres, placed nowhere, is the OBJ's mesh corner for corner.
#[test]
fn the_cube_is_the_objs() {
    let obj = super::super::parse_obj(CUBE_OBJ.as_bytes(), Path::new("c.obj")).expect("obj");
    let scene = r##"<node id="n" name="cube"><instance_geometry url="#cube"/></node>"##;
    let file = read(&dae(1.0, "Z_UP", &cube_geometry("cube", 1.0), "", scene));
    assert_eq!(
        super::super::tests::face_points(&file.file.mesh),
        super::super::tests::face_points(&obj.mesh)
    );
    assert_eq!(
        mass_properties(&file.file.mesh, 1.0).expect("dae"),
        mass_properties(&obj.mesh, 1.0).expect("obj")
    );
    assert_eq!(file.file.part_names, ["cube"]);
    assert_eq!(file.up_axis, "Z_UP");
    assert_eq!(file.file.warnings, []);
    assert_eq!(file.file.face_lines.len(), 6);
}

/// A cube of 100 cm under a node that moves it (100, 200, 300) cm, turns it 30° about z,
/// scales it 2 × 3 × 4 and centres it, in document order: the 2 × 3 × 4 m box's closed form; and
/// the same as one row-major `<matrix>`.
#[test]
fn transforms_compose_in_document_order_in_metres() {
    let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), 30f64.to_radians());
    let expected = placed_box([2.0, 3.0, 4.0], *turn.matrix(), [1.0, 2.0, 3.0]);
    let trs = r##"<node id="arm" name="arm"><translate>100 200 300</translate>
        <rotate>0 0 1 30</rotate>
        <node id="brick" name="brick"><scale>2 3 4</scale><translate>-50 -50 -50</translate>
          <instance_geometry url="#cube"/></node></node>"##;
    let m = nalgebra::Matrix4::new_translation(&Vector3::new(100.0, 200.0, 300.0))
        * turn.to_homogeneous()
        * nalgebra::Matrix4::new_nonuniform_scaling(&Vector3::new(2.0, 3.0, 4.0))
        * nalgebra::Matrix4::new_translation(&Vector3::new(-50.0, -50.0, -50.0));
    let rows: Vec<String> = (0..4)
        .flat_map(|r| (0..4).map(move |c| (r, c)))
        .map(|(r, c)| format!("{:?}", m[(r, c)]))
        .collect();
    let matrix = format!(
        r##"<node id="brick" name="brick"><matrix>{}</matrix>
        <instance_geometry url="#cube"/></node>"##,
        rows.join(" ")
    );
    for (scene, what) in [
        (trs, "translate, rotate, scale"),
        (matrix.as_str(), "matrix"),
    ] {
        let file = read(&dae(0.01, "Z_UP", &cube_geometry("cube", 100.0), "", scene));
        assert_close(&properties(&file.file), &expected, what);
        assert_eq!(file.file.part_names, ["brick"], "{what}");
        assert_eq!(file.metres_per_unit, 0.01);
    }
}

/// A library node instanced twice is two parts; a mirrored instance stays outward.
#[test]
fn instances_are_parts_and_mirrors_stay_outward() {
    let library = r##"<node id="wheel" name="wheel"><translate>-0.5 -0.5 -0.5</translate>
        <instance_geometry url="#cube"/></node>"##;
    let scene = r##"<node id="a"><instance_node url="#wheel"/></node>
        <node id="b"><translate>4 0 0</translate><scale>-1 1 1</scale>
          <instance_node url="#wheel"/></node>"##;
    let read_y = read(&dae(
        1.0,
        "Y_UP",
        &cube_geometry("cube", 1.0),
        library,
        scene,
    ));
    assert_eq!(read_y.up_axis, "Y_UP");
    let codes: Vec<&str> = read_y
        .file
        .warnings
        .iter()
        .map(crate::Warning::code)
        .collect();
    assert_eq!(
        codes,
        ["up_axis_not_applied"],
        "Y_UP is reported, not applied"
    );
    let file = read_y.file;
    assert_eq!(file.part_names, ["wheel", "wheel 2"]);
    assert!((signed_volume(&file.mesh) - 2.0).abs() < 1e-12);
    assert_close(
        &properties(&file),
        &two_unit_cubes_four_apart(),
        "two instances",
    );
}

/// The unit tetrahedron (volume 1/6) as triangles, polygons, one strip and fans: each part
/// encloses +1/6 wound outward; lines are passed over.
#[test]
fn every_primitive_kind_makes_faces() {
    let source = r##"<source id="ID-pos"><float_array id="ID-arr" count="12">0 0 0 1 0 0 0 1 0 0 0 1</float_array>
        <technique_common><accessor source="#ID-arr" count="4" stride="3"/></technique_common></source>
        <vertices id="ID-vtx"><input semantic="POSITION" source="#ID-pos"/></vertices>"##;
    let input = r##"<input semantic="VERTEX" source="#ID-vtx" offset="0"/>"##;
    let kinds = [
        (
            "tri",
            "<triangles count=\"4\">INPUT<p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>",
        ),
        (
            "poly",
            "<polygons count=\"4\">INPUT<p>0 2 1</p><p>0 1 3</p><p>0 3 2</p><p>1 2 3</p></polygons>",
        ),
        (
            "strip",
            "<tristrips count=\"1\">INPUT<p>0 2 1 3 0 2</p></tristrips>",
        ),
        (
            "fan",
            "<trifans count=\"2\">INPUT<p>0 2 1 3 2</p><p>1 2 3</p></trifans>\
             <lines count=\"1\">INPUT<p>0 1</p></lines>",
        ),
    ];
    let mut geometries = String::new();
    let mut scene = String::new();
    for (k, (id, primitive)) in kinds.iter().enumerate() {
        let body = primitive.replace("INPUT", input);
        geometries += &format!(
            "<geometry id=\"{id}\"><mesh>{}{}</mesh></geometry>",
            source.replace("ID", id),
            body.replace("ID", id)
        );
        scene += &format!(
            "<node name=\"{id}\"><translate>{} 2 1</translate><instance_geometry url=\"#{id}\"/></node>",
            3 * k + 1
        );
    }
    let file = read(&dae(1.0, "Z_UP", &geometries, "", &scene)).file;
    let parts = file.parts();
    assert_eq!(
        parts
            .iter()
            .map(|(n, f)| (n.as_str(), f.len()))
            .collect::<Vec<_>>(),
        [("tri", 4), ("poly", 4), ("strip", 4), ("fan", 4)]
    );
    for (name, faces) in &parts {
        let volume = signed_volume(&file.mesh.subset(faces).expect("a part"));
        assert!((volume - 1.0 / 6.0).abs() < 1e-15, "{name}: {volume}");
    }
}

/// Bad files are refused by name: the element, its id and its line.
#[test]
fn bad_files_are_refused_by_name() {
    let said = |text: &str| {
        parse_collada(text.as_bytes(), Path::new("bad.dae"))
            .map(|_| ())
            .map_err(|e| e.to_string())
    };
    let cube = cube_geometry("cube", 1.0);
    let node = r##"<node id="n"><instance_geometry url="#cube"/></node>"##;
    let good = dae(1.0, "Z_UP", &cube, "", node);
    assert_eq!(said(&good), Ok(()));
    for (text, expected) in [
        (
            dae(
                1.0,
                "Z_UP",
                &cube,
                "",
                r##"<node id="n"><instance_geometry url="#gone"/></node>"##,
            ),
            "bad.dae, line 19: <instance_geometry>: url=\"#gone\" names no element of this file",
        ),
        (
            dae(
                1.0,
                "Z_UP",
                &cube.replacen("4 4 4 4 4 4", "4 4 4 4 4 3", 1),
                "",
                node,
            ),
            "bad.dae, line 15: <polylist>: the faces' corner counts add up to 23, but <p> has 24 \
             corners",
        ),
        (
            dae(
                1.0,
                "Z_UP",
                &cube.replacen("<p>0 0 0 3", "<p>0 0 0 8", 1),
                "",
                node,
            ),
            "bad.dae, line 12: <polylist>: a corner names position 8, but <source id=\"cube-pos\"> \
             has 8",
        ),
        (
            dae(
                1.0,
                "Z_UP",
                &cube,
                "",
                r##"<node id="n"><lookat>0 0 0 1 0 0 0 0 1</lookat></node>"##,
            ),
            "bad.dae, line 19: <node id=\"n\">: a <lookat> transform is not read",
        ),
        (
            dae(
                1.0,
                "Z_UP",
                &cube,
                r##"<node id="loop"><instance_node url="#loop"/></node>"##,
                r##"<node id="n"><instance_node url="#loop"/></node>"##,
            ),
            "bad.dae, line 18: <node id=\"loop\"> instances itself",
        ),
        (
            dae(
                1.0,
                "Z_UP",
                &cube.replacen("stride=\"3\"", "stride=\"2\"", 1),
                "",
                node,
            ),
            "bad.dae, line 6: <source id=\"cube-pos\">: positions need a stride of 3 or more, not 2",
        ),
        (
            dae(0.0, "Z_UP", &cube, "", node),
            "bad.dae, line 3: <unit meter=\"0\">: not a positive number",
        ),
        (
            "<mesh/>".to_owned(),
            "bad.dae: not a COLLADA file: its root element is <mesh>",
        ),
        (
            dae(
                1.0,
                "Z_UP",
                &cube.replacen("count=\"24\">0 ", "count=\"24\">x ", 1),
                "",
                node,
            ),
            "bad.dae, line 5: <float_array id=\"cube-pos-array\">: \"x\" is not a number",
        ),
    ] {
        assert_eq!(said(&text), Err(expected.to_owned()), "{text}");
    }
    let not_xml = said("<COLLADA><asset></COLLADA>");
    assert!(
        matches!(&not_xml, Err(e) if e.starts_with("bad.dae, line 1: not XML: ")),
        "{not_xml:?}"
    );
}
