//! The 3MF reader against the OBJ's tetrahedron, every unit, closed forms placed through build
//! items and nested components (in millimetres), instances and mirrors, components in another
//! model part, stored and deflated packages, and bad packages refused by name.

use std::path::Path;

use nalgebra::{Matrix3, Rotation3, Vector3};

use super::super::tests::{assert_close, placed_box, properties, signed_volume};
use super::super::zip::crc32;
use super::*;
use crate::mass_properties;

/// A ZIP archive of these files, each stored or deflated, as packagers write them.
fn zip(files: &[(&str, &[u8], bool)]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut central = Vec::new();
    for &(name, data, deflate) in files {
        let stored = if deflate {
            miniz_oxide::deflate::compress_to_vec(data, 6)
        } else {
            data.to_vec()
        };
        let method: u16 = if deflate { 8 } else { 0 };
        let offset = out.len() as u32;
        let common = |v: &mut Vec<u8>| {
            v.extend_from_slice(&20u16.to_le_bytes());
            v.extend_from_slice(&0u16.to_le_bytes());
            v.extend_from_slice(&method.to_le_bytes());
            v.extend_from_slice(&[0; 4]);
            v.extend_from_slice(&crc32(data).to_le_bytes());
            v.extend_from_slice(&(stored.len() as u32).to_le_bytes());
            v.extend_from_slice(&(data.len() as u32).to_le_bytes());
            v.extend_from_slice(&(name.len() as u16).to_le_bytes());
            v.extend_from_slice(&0u16.to_le_bytes());
        };
        out.extend_from_slice(b"PK\x03\x04");
        common(&mut out);
        out.extend_from_slice(name.as_bytes());
        out.extend_from_slice(&stored);
        central.extend_from_slice(b"PK\x01\x02");
        central.extend_from_slice(&20u16.to_le_bytes());
        common(&mut central);
        central.extend_from_slice(&[0; 10]);
        central.extend_from_slice(&offset.to_le_bytes());
        central.extend_from_slice(name.as_bytes());
    }
    let directory = out.len() as u32;
    out.extend_from_slice(&central);
    out.extend_from_slice(b"PK\x05\x06");
    out.extend_from_slice(&[0; 4]);
    out.extend_from_slice(&(files.len() as u16).to_le_bytes());
    out.extend_from_slice(&(files.len() as u16).to_le_bytes());
    out.extend_from_slice(&(central.len() as u32).to_le_bytes());
    out.extend_from_slice(&directory.to_le_bytes());
    out.extend_from_slice(&0u16.to_le_bytes());
    out
}

const RELS: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
  <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>"#;

const CONTENT_TYPES: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
  <Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
  <Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>
</Types>"#;

/// A package of one model part (and others, by name), deflated or not.
fn package(model: &str, others: &[(&str, &str)], deflate: bool) -> Vec<u8> {
    let mut files: Vec<(&str, &[u8], bool)> = vec![
        ("[Content_Types].xml", CONTENT_TYPES.as_bytes(), deflate),
        ("_rels/.rels", RELS.as_bytes(), deflate),
        ("3D/3dmodel.model", model.as_bytes(), deflate),
    ];
    files.extend(others.iter().map(|(n, t)| (*n, t.as_bytes(), deflate)));
    zip(&files)
}

/// A model part in `unit` of these resources and build items.
fn model(unit: &str, resources: &str, build: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<model unit="{unit}" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02" xmlns:p="http://schemas.microsoft.com/3dmanufacturing/production/2015/06">
<resources>
{resources}
</resources>
<build>
{build}
</build>
</model>"#
    )
}

/// An object of a box `[lo, hi]³`: its eight corners and twelve outward triangles.
fn cube_object(id: u32, name: &str, lo: f64, hi: f64) -> String {
    let vertices: String = (0..8)
        .map(|i| {
            let c = [0, 1, 2].map(|a| if (i >> a) & 1 == 1 { hi } else { lo });
            format!("<vertex x=\"{}\" y=\"{}\" z=\"{}\"/>", c[0], c[1], c[2])
        })
        .collect();
    let triangles: String = [
        [0, 2, 3],
        [0, 3, 1],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 6, 7],
        [2, 7, 3],
        [0, 4, 6],
        [0, 6, 2],
        [1, 3, 7],
        [1, 7, 5],
    ]
    .iter()
    .map(|t| {
        format!(
            "<triangle v1=\"{}\" v2=\"{}\" v3=\"{}\"/>\n",
            t[0], t[1], t[2]
        )
    })
    .collect();
    format!(
        "<object id=\"{id}\" name=\"{name}\" type=\"model\"><mesh><vertices>{vertices}</vertices>\
         <triangles>\n{triangles}</triangles></mesh></object>"
    )
}

fn read(bytes: &[u8]) -> MeshFile {
    parse_3mf(bytes, Path::new("print.3mf")).expect("reads")
}

/// The tetrahedron in metres is the OBJ's, stored or deflated.
#[test]
fn the_tetrahedron_is_the_objs() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    let obj = super::super::parse_obj(obj.as_bytes(), Path::new("t.obj")).expect("obj");
    let tetra = r#"<object id="1" name="tetra"><mesh><vertices>
        <vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/><vertex x="0" y="1" z="0"/>
        <vertex x="0" y="0" z="1"/></vertices><triangles>
        <triangle v1="0" v2="2" v3="1"/><triangle v1="0" v2="1" v3="3"/>
        <triangle v1="0" v2="3" v3="2"/><triangle v1="1" v2="2" v3="3"/>
        </triangles></mesh></object>"#;
    for deflate in [false, true] {
        let file = read(&package(
            &model("meter", tetra, r#"<item objectid="1"/>"#),
            &[],
            deflate,
        ));
        assert_eq!(
            super::super::tests::face_points(&file.mesh),
            super::super::tests::face_points(&obj.mesh)
        );
        assert_eq!(
            mass_properties(&file.mesh, 1.0).expect("3mf"),
            mass_properties(&obj.mesh, 1.0).expect("obj")
        );
        assert_eq!(file.part_names, ["tetra"]);
        assert_eq!(file.face_lines, [7, 7, 8, 8]);
    }
}

/// A cube of side 10 in each of 3MF's units is (10 u)³ m³; millimetres when no unit is given.
#[test]
fn every_unit_is_converted_to_metres() {
    for (unit, metres) in [
        ("micron", 1e-6),
        ("millimeter", 1e-3),
        ("centimeter", 1e-2),
        ("inch", 0.0254),
        ("foot", 0.3048),
        ("meter", 1.0),
    ] {
        let text = model(
            unit,
            &cube_object(1, "c", 0.0, 10.0),
            r#"<item objectid="1"/>"#,
        );
        let volume = mass_properties(&read(&package(&text, &[], true)).mesh, 1.0)
            .expect(unit)
            .mass;
        let expected = (10.0 * metres) * (10.0 * metres) * (10.0 * metres);
        assert!((volume / expected - 1.0).abs() < 1e-12, "{unit}: {volume}");
    }
    let text = model(
        "meter",
        &cube_object(1, "c", 0.0, 10.0),
        r#"<item objectid="1"/>"#,
    )
    .replace("unit=\"meter\" ", "");
    let volume = mass_properties(&read(&package(&text, &[], false)).mesh, 1.0)
        .expect("no unit")
        .mass;
    assert!((volume / 1e-6 - 1.0).abs() < 1e-12, "no unit: {volume}");
}

/// A 1000 mm cube, scaled 2 × 3 × 4 by a component, placed by a build item that turns it by
/// atan2(0.8, 0.6) about z and moves it (1000, 2000, 3000) mm: the 2 × 3 × 4 m box's closed form. The
/// transforms are row-vector matrices: the item's 3 × 3 block is the turn transposed.
#[test]
fn components_and_items_compose_in_metres() {
    let resources = format!(
        r#"{}
        <object id="2" name="brick"><components>
          <component objectid="1" transform="2 0 0 0 3 0 0 0 4 0 0 0"/></components></object>"#,
        cube_object(1, "cube", -500.0, 500.0)
    );
    let build = r#"<item objectid="2" transform="0.6 0.8 0 -0.8 0.6 0 0 0 1 1000 2000 3000"/>"#;
    let file = read(&package(&model("millimeter", &resources, build), &[], true));
    let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), 0.8f64.atan2(0.6));
    assert_close(
        &properties(&file),
        &placed_box([2.0, 3.0, 4.0], *turn.matrix(), [1.0, 2.0, 3.0]),
        "component in item",
    );
    assert_eq!(file.part_names, ["brick"]);
}

/// Two items of one object are two parts; the mirrored one stays outward; a component in
/// another model part (the production extension's `p:path`) is followed.
#[test]
fn instances_mirrors_and_other_parts() {
    let other = model("meter", &cube_object(7, "far cube", -0.5, 0.5), "");
    let resources = format!(
        r#"{}
        <object id="3" name="wheel"><components>
          <component objectid="7" p:path="/3D/other.model"/></components></object>"#,
        cube_object(1, "cube", -0.5, 0.5)
    );
    let build = r#"<item objectid="1"/>
        <item objectid="1" transform="-1 0 0 0 1 0 0 0 1 4 0 0"/>
        <item objectid="3" transform="1 0 0 0 1 0 0 0 1 0 8 0"/>"#;
    let file = read(&package(
        &model("meter", &resources, build),
        &[("3D/other.model", &other)],
        true,
    ));
    assert_eq!(file.part_names, ["cube", "cube 2", "wheel"]);
    let parts = file.parts();
    for ((name, faces), center) in parts
        .iter()
        .zip([[0.0; 3], [4.0, 0.0, 0.0], [0.0, 8.0, 0.0]])
    {
        let part = file.mesh.subset(faces).expect("a part");
        assert!((signed_volume(&part) - 1.0).abs() < 1e-12, "{name}");
        assert_close(
            &mass_properties(&part, 1.0).expect("integrates"),
            &placed_box([1.0; 3], Matrix3::identity(), center),
            name,
        );
    }
}

/// Bad packages are refused by name: the part, the element and its line.
#[test]
fn bad_packages_are_refused_by_name() {
    let said = |bytes: &[u8]| {
        parse_3mf(bytes, Path::new("bad.3mf"))
            .map(|_| ())
            .map_err(|e| e.to_string())
    };
    let cube = cube_object(1, "c", 0.0, 1.0);
    let item = r#"<item objectid="1"/>"#;
    let good = model("meter", &cube, item);
    assert_eq!(said(&package(&good, &[], true)), Ok(()));
    for (text, expected) in [
        (
            model("meter", &cube, r#"<item objectid="9"/>"#),
            "bad.3mf, line 20: 3D/3dmodel.model: objectid 9 names no object of 3D/3dmodel.model",
        ),
        (
            model("meter", &cube.replacen("v3=\"3\"", "v3=\"8\"", 1), item),
            "bad.3mf, line 5: 3D/3dmodel.model: a <triangle>'s v3 is not one of the mesh's 8 \
             vertices",
        ),
        (
            model("furlong", &cube, item),
            "bad.3mf, line 2: 3D/3dmodel.model: unit=\"furlong\" is not one of 3MF's units",
        ),
        (
            model("meter", &cube, r#"<item objectid="1" transform="1 0 0"/>"#),
            "bad.3mf, line 20: 3D/3dmodel.model: transform=\"1 0 0\" is not twelve finite numbers",
        ),
        (
            model(
                "meter",
                r#"<object id="5"><components><component objectid="5"/></components></object>"#,
                r#"<item objectid="5"/>"#,
            ),
            "bad.3mf, line 4: 3D/3dmodel.model: object 5 contains itself",
        ),
        (
            model("meter", &cube.replacen("x=\"1\"", "x=\"a\"", 1), item),
            "bad.3mf, line 4: 3D/3dmodel.model: a <vertex> needs a finite x",
        ),
    ] {
        assert_eq!(
            said(&package(&text, &[], true)),
            Err(expected.to_owned()),
            "{text}"
        );
    }
    assert_eq!(
        said(b"PK\x03\x04 not really"),
        Err("bad.3mf: not a ZIP archive: no end-of-central-directory record".to_owned())
    );
    let mut damaged = package(&good, &[], false);
    let at = damaged
        .windows(6)
        .position(|w| w == b"vertex")
        .expect("stored text");
    damaged[at] = b'V';
    assert_eq!(
        said(&damaged),
        Err(
            "bad.3mf: 3D/3dmodel.model: its CRC-32 does not match: the archive is damaged"
                .to_owned()
        )
    );
    let no_model = zip(&[("_rels/.rels", RELS.as_bytes(), true)]);
    assert_eq!(
        said(&no_model),
        Err("bad.3mf: the package has no model part 3D/3dmodel.model".to_owned())
    );
}
