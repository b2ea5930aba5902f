//! Diagnostics and errors on crafted bad meshes and files, and the loaders (OBJ, binary and ASCII
//! STL) on good ones. Error messages must say where the problem is.

use crate::common;

use std::path::{Path, PathBuf};

use common::{assert_mat, assert_rel, box_tensor};
use massprops::diagnostics::diagnose;
use massprops::shapes::{self, MeshBuilder};
use massprops::shell::shell_properties;
use massprops::solid::solid_properties;
use massprops::{
    Defect, MassSpec, MeshError, Method, PolyMesh, analyze, load_mesh, mass_properties, parse_mesh,
};
use nalgebra::{Matrix3, Point3, Vector3};

fn obj(text: &str) -> Result<PolyMesh, MeshError> {
    parse_mesh(text.as_bytes(), Path::new("part.obj")).map(|f| f.mesh)
}

/// The error's message, which must name the file and, where given, the line.
#[track_caller]
fn obj_error(text: &str) -> String {
    let e = obj(text).expect_err("the file is bad");
    let msg = e.to_string();
    assert!(
        msg.contains("part.obj"),
        "the message names the file: {msg}"
    );
    msg
}

/// A unique scratch path (no temp-file crate: process id, test name and a counter).
fn scratch(name: &str) -> PathBuf {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static N: AtomicUsize = AtomicUsize::new(0);
    let n = N.fetch_add(1, Ordering::Relaxed);
    std::env::temp_dir().join(format!("massprops-test-{}-{n}-{name}", std::process::id()))
}

/// A box with dyadic corners (exact in f32, so STL loses nothing): 2 × 1 × 0.5 at (0.5, -1, 4).
fn dyadic_box() -> MeshBuilder {
    shapes::cuboid(Vector3::new(2.0, 1.0, 0.5), Point3::new(0.5, -1.0, 4.0))
}

const CUBE_OBJ: &str = "\
# unit cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
";

#[test]
fn the_reference_cube_file_is_good() {
    let m = obj(CUBE_OBJ).expect("valid");
    let d = diagnose(&m);
    assert!(d.is_closed() && d.is_consistently_oriented(), "{d:?}");
    assert_eq!((d.vertices, d.faces, d.triangles, d.edges), (8, 6, 12, 12));
    assert_rel(d.surface_area, 6.0, 1e-15, "area");
    let p = mass_properties(&m, 1.0).expect("closed");
    assert_mat(&p.inertia_com, &(Matrix3::identity() / 6.0), 1e-15, "cube");
}

#[test]
fn open_mesh_counts_its_boundary_edges() {
    let mut b = shapes::cube();
    b.faces.remove(1); // the top
    let mesh = b.build();
    let d = diagnose(&mesh);
    assert_eq!(d.open_edges, 4);
    assert_eq!(d.nonmanifold_edges, 0);
    assert!(!d.is_closed());
    assert_eq!(d.open_edge_examples.len(), 4);
    for (a, b) in &d.open_edge_examples {
        assert!(
            (4..8).contains(a) && (4..8).contains(b),
            "top edges: {a}-{b}"
        );
    }
    // Capping restores the cube exactly: the cap is four triangles filling the top.
    let a = analyze(&mesh, Method::Volume, MassSpec::Density(1.0)).expect("capped");
    assert_eq!(a.warnings.len(), 1, "{:?}", a.warnings);
    assert_eq!(a.warnings[0].code(), "holes_capped");
    assert_rel(a.properties.mass, 1.0, 1e-15, "capped cube");
    assert_mat(
        &a.properties.inertia_com,
        &box_tensor(1.0, 1.0, 1.0, 1.0),
        1e-15,
        "capped cube",
    );
    // Refusing names the hole.
    let refuse = massprops::Repairs {
        holes: massprops::defects::Holes::Refuse,
        ..Default::default()
    };
    let e = massprops::analyze_with(&mesh, Method::Volume, MassSpec::Density(1.0), &refuse)
        .expect_err("open");
    assert_eq!(
        e.to_string(),
        "the mesh is open: 4 edge(s) used by only one face, in 1 hole(s), around faces 1, 2, 3, \
         4 (counting from 0); the volume it encloses is not defined (cap the holes, or use the \
         shell method for sheets)"
    );
    // The shell method is meant for open meshes: nothing is capped there.
    let s = analyze(&mesh, Method::Shell, MassSpec::Density(1.0)).expect("area");
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert_rel(s.properties.mass, 5.0, 1e-15, "five unit faces");
}

#[test]
fn non_manifold_edge_between_two_boxes_touching_along_an_edge() {
    // Box [0,1]³ and box [1,2]×[1,2]×[0,1] share the edge x = y = 1: four faces use it.
    let mut b = shapes::cuboid(Vector3::repeat(1.0), Point3::new(0.5, 0.5, 0.5));
    b.append(&shapes::cuboid(
        Vector3::repeat(1.0),
        Point3::new(1.5, 1.5, 0.5),
    ));
    let (positions, remap) = massprops::mesh::weld_exact(&b.positions);
    let faces: Vec<Vec<usize>> = b
        .faces
        .iter()
        .map(|f| f.iter().map(|&i| remap[i] as usize).collect())
        .collect();
    let mesh = PolyMesh::new(positions, &faces).expect("valid");
    let d = diagnose(&mesh);
    assert_eq!(d.vertices, 14);
    assert_eq!(d.nonmanifold_edges, 1);
    assert_eq!(d.open_edges, 0);
    assert!(!d.is_closed());
    let a = analyze(&mesh, Method::Volume, MassSpec::Density(1.0)).expect("volume 2");
    assert_rel(a.properties.mass, 2.0, 1e-15, "two unit boxes");
    // The edge is named with the four faces that share it, two from each box.
    // Two shells that only touch: nothing overlaps, nothing is nested.
    assert_eq!(a.warnings.len(), 1, "{:?}", a.warnings);
    assert_eq!(a.warnings[0].count, 1);
    assert!(
        matches!(&a.warnings[0].defect, Defect::NonmanifoldEdges { edges }
                if edges.len() == 1 && edges[0].1.len() == 4),
        "{:?}",
        a.warnings
    );
    assert_eq!(a.shells.len(), 2);
    assert!(a.shells.iter().all(|s| s.closed && s.depth == Some(0)));
    assert_eq!(d.nonmanifold_edge_examples[0].1.len(), 4);
}

#[test]
fn one_flipped_face_gives_four_inconsistent_edges() {
    // (The top: flipping a face normal to x would cancel all of ∫x·nₓ, which Mirtich's volume
    // uses, and leave no volume to analyse.)
    let mut b = shapes::cube();
    b.faces[1].reverse();
    let mesh = b.build();
    let d = diagnose(&mesh);
    assert_eq!(d.inconsistent_edges, 4);
    assert_eq!(d.open_edges, 0);
    assert!(!d.is_consistently_oriented());
    let a = analyze(&mesh, Method::Volume, MassSpec::Density(1.0)).expect("some volume");
    // Each named pair is the flipped face 1 and one of its four neighbours.
    let pairs = &d.inconsistent_face_examples;
    assert_eq!(pairs.len(), 4);
    assert!(
        pairs.iter().all(|&(a, b)| (a == 1) != (b == 1)),
        "{pairs:?}"
    );
    // The face is turned to agree with its neighbours: one face turned, the same four pairs
    // named, the unit cube's mass.
    let w = a
        .warnings
        .iter()
        .find(|w| w.code() == "inconsistent_winding")
        .expect("inconsistent_winding");
    let Defect::InconsistentWinding { face_pairs } = &w.defect else {
        unreachable!("its code")
    };
    let (mut named, mut expected) = (face_pairs.clone(), pairs.clone());
    named.sort_unstable();
    expected.sort_unstable();
    assert_eq!(named, expected);
    assert_eq!((w.count, w.faces.as_slice()), (1, [1].as_slice()));
    assert_rel(a.properties.mass, 1.0, 1e-15, "unit cube");
}

#[test]
fn inverted_mesh_is_flipped_and_warned_about() {
    let mesh = shapes::book().build().flipped();
    let d = diagnose(&mesh);
    assert!(d.is_closed() && d.is_consistently_oriented());
    let s = solid_properties(&mesh, massprops::integrals::IntegrationPath::Auto).expect("volume");
    assert!(s.flipped);
    assert_rel(s.volume, 28.0, 1e-15, "book volume");
    let a = analyze(&mesh, Method::Volume, MassSpec::Density(2.0)).expect("volume");
    assert!(a.flipped);
    assert_eq!(a.warnings.len(), 1);
    assert_eq!(
        a.warnings[0].defect,
        Defect::Flipped {
            shells: vec![0],
            whole: true
        }
    );
    assert_mat(
        &a.properties.inertia_com,
        &box_tensor(56.0, 1.0, 4.0, 7.0),
        1e-14,
        "flipped book",
    );
}

#[test]
fn degenerate_and_non_planar_faces_are_reported() {
    // A cube with one corner pulled out diagonally: the three quads around it leave their planes.
    let mut b = shapes::cube();
    b.positions[6] += Vector3::new(0.1, 0.05, 0.1);
    let mesh = b.build();
    let d = diagnose(&mesh);
    let around: Vec<usize> = (0..b.faces.len())
        .filter(|&f| b.faces[f].contains(&6))
        .collect();
    assert_eq!(d.nonplanar_faces, 3);
    assert_eq!(d.nonplanar_face_examples, around);
    assert_eq!(d.degenerate_faces, 0);
    let a = analyze(&mesh, Method::Volume, MassSpec::Density(1.0)).expect("volume");
    let w = a
        .warnings
        .iter()
        .find(|w| w.code() == "nonplanar_faces")
        .expect("non-planar");
    assert_eq!((w.count, &w.faces), (3, &around));
    // Independently: each of the three quads split along either diagonal, all eight ways; the
    // volumes span what the warning says.
    let Defect::NonplanarFaces { uncertainty } = w.defect else {
        panic!("{w:?}")
    };
    let mut volumes = Vec::new();
    for choice in 0..8 {
        let mut t = b.clone();
        t.faces = b
            .faces
            .iter()
            .enumerate()
            .flat_map(|(f, q)| {
                let k = around.iter().position(|&g| g == f);
                let split = k.is_some_and(|k| choice & (1 << k) != 0);
                let q: Vec<usize> = if split {
                    vec![q[1], q[2], q[3], q[0]]
                } else {
                    q.clone()
                };
                vec![vec![q[0], q[1], q[2]], vec![q[0], q[2], q[3]]]
            })
            .collect();
        volumes.push(
            massprops::solid::solid_properties(
                &t.build(),
                massprops::integrals::IntegrationPath::Auto,
            )
            .expect("volume")
            .volume,
        );
    }
    let span = volumes.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
        - volumes.iter().cloned().fold(f64::INFINITY, f64::min);
    let volume = a.volume.expect("volume");
    assert!(span > 1e-3, "{span}");
    assert_rel(uncertainty * volume, span, 1e-12, "triangulation spread");
    // Its triangulation is planar by construction.
    assert_eq!(
        diagnose(&b.clone().triangulated().build()).nonplanar_faces,
        0
    );

    // A zero-area triangle (three collinear corners) glued into a closed mesh.
    let mut c = shapes::cube().triangulated();
    let mid = Point3::from((c.positions[0].coords + c.positions[1].coords) / 2.0);
    c.positions.push(mid);
    c.faces.push(vec![0, 8, 1]);
    c.faces.push(vec![1, 8, 0]);
    let d = diagnose(&c.build());
    assert_eq!(d.degenerate_faces, 2);
    assert_eq!(d.degenerate_face_examples, vec![12, 13]);
    let a = analyze(&c.build(), Method::Volume, MassSpec::Density(1.0)).expect("volume");
    let degenerate = a
        .warnings
        .iter()
        .find(|w| w.defect == Defect::DegenerateFaces)
        .expect("degenerate");
    assert_eq!((degenerate.count, &degenerate.faces), (2, &vec![12, 13]));
    // The two are each other's reverse, but of no area: degenerate, not duplicates of a face.
    assert!(
        !a.warnings.iter().any(|w| w.code().contains("duplicate")),
        "{:?}",
        a.warnings
    );
    assert_rel(a.properties.mass, 1.0, 1e-15, "unit cube");
}

#[test]
fn empty_files_are_errors() {
    for text in ["", "# nothing\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"] {
        let e = obj(text).expect_err("no faces");
        assert!(e.to_string().contains("empty"), "{e}");
    }
    let e = parse_mesh(b"", Path::new("part.stl")).expect_err("empty STL");
    assert!(e.to_string().contains("part.stl"), "{e}");
}

#[test]
fn non_finite_coordinates_name_the_line() {
    for bad in ["v 1 nan 0", "v inf 0 0", "v 0 0 1e400", "v 0 -inf 0"] {
        let text = CUBE_OBJ.replacen("v 1 1 0", bad, 1);
        let msg = obj_error(&text);
        assert!(msg.contains("line 4"), "{bad}: {msg}");
        assert!(msg.contains("non-finite"), "{bad}: {msg}");
    }
    // Welding merges the repeated vertices before the check; the error still names the file's
    // vertex (zero-based, in file order), not the welded one.
    let repeated = "v 0 0 0\nv 0 0 0\nv 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 4 5\n";
    let msg = obj_error(repeated);
    assert!(msg.contains("line 5"), "{msg}");
    assert!(msg.contains("vertex 4 "), "{msg}");
}

#[test]
fn indices_out_of_range_name_the_line() {
    for (bad, what) in [
        ("f 5 6 7 9", "past the end"),
        ("f 5 6 7 -9", "relative, before the start"),
        ("f 0 6 7 8", "zero"),
    ] {
        let text = CUBE_OBJ.replacen("f 5 6 7 8", bad, 1);
        let msg = obj_error(&text);
        assert!(msg.contains("line 11"), "{what} ({bad}): {msg}");
    }
    // Relative indices that are in range are fine.
    let rel = CUBE_OBJ.replacen("f 5 6 7 8", "f -4 -3 -2 -1", 1);
    assert!(diagnose(&obj(&rel).expect("valid")).is_closed());
}

#[test]
fn malformed_lines_are_named() {
    for (bad, line) in [
        ("v 1 1", 4),
        ("v 1 x 0", 4),
        ("v 1 1 0 0", 4),   // w = 0 divides by zero
        ("v 1 1 0 1 2", 4), // five numbers: neither w nor a colour
        ("f 5 6 seven 8", 11),
        ("vn 0 0", 3),
    ] {
        let text = if bad.starts_with("vn") {
            CUBE_OBJ.replacen("v 0 0 0\n", "v 0 0 0\nvn 0 0\n", 1)
        } else if bad.starts_with('f') {
            CUBE_OBJ.replacen("f 5 6 7 8", bad, 1)
        } else {
            CUBE_OBJ.replacen("v 1 1 0", bad, 1)
        };
        let msg = obj_error(&text);
        assert!(msg.contains(&format!("line {line}")), "{bad}: {msg}");
    }
}

#[test]
fn records_of_fewer_than_three_corners_are_skipped_and_named_by_line() {
    let file = |text: &str| parse_mesh(text.as_bytes(), Path::new("part.obj")).expect("read");
    let lines_of = |f: &massprops::MeshFile| match &f.warnings[..] {
        [w] => {
            assert_eq!(w.code(), "two_corner_faces");
            assert_eq!(w.effect_on_mass, Some(0.0));
            let Defect::TwoCornerFaces { lines } = &w.defect else {
                panic!("{w:?}")
            };
            (w.count, lines.clone())
        }
        other => panic!("{other:?}"),
    };
    // The top (line 11) written as a segment: skipped; the five other faces remain, and the
    // hole it leaves is capped back to the unit cube.
    let f = file(&CUBE_OBJ.replacen("f 5 6 7 8", "f 5 6", 1));
    assert_eq!(lines_of(&f), (1, vec![11]));
    assert_eq!(f.mesh.face_count(), 5);
    assert_eq!(f.face_lines, vec![10, 12, 13, 14, 15]);
    let a = f
        .analyze(Method::Volume, MassSpec::Density(1.0), &Default::default())
        .expect("capped");
    assert_rel(a.properties.mass, 1.0, 1e-15, "capped cube");
    let codes: Vec<&str> = a.warnings.iter().map(|w| w.code()).collect();
    assert_eq!(codes, ["holes_capped", "two_corner_faces"]);
    // One corner too; points and polylines before them do not shift the lines.
    let text = CUBE_OBJ
        .replacen("f 1 4 3 2", "p 1\nl 1 2\nf 1 4 3 2", 1)
        .replacen("f 5 6 7 8", "f 5 6\nf 5", 1);
    let f = file(&text);
    assert_eq!(lines_of(&f), (2, vec![13, 14]));
    assert_eq!(f.face_lines, vec![12, 15, 16, 17, 18]);
}

#[test]
fn every_solid_of_an_ascii_stl_is_read_and_names_a_part() {
    // stl_io alone reads the first block and silently drops the rest.
    let a = ascii_stl(&shapes::cube(), "solid first");
    let b = ascii_stl(
        &shapes::cuboid(Vector3::repeat(1.0), Point3::new(3.0, 0.0, 0.0)),
        "solid",
    );
    let text = format!("{a}{b}");
    let f = parse_mesh(text.as_bytes(), Path::new("two.stl")).expect("ascii");
    assert_eq!(f.mesh.face_count(), 24);
    assert_eq!(f.part_names, ["first", ""]);
    assert_eq!(f.face_parts, [vec![0; 12], vec![1; 12]].concat());
    // The second block's facets keep their lines: 12 facets of 7 lines after two heading lines.
    assert_eq!(f.face_lines[12], 2 + 7 * 12 + 2);
    let p = mass_properties(&f.mesh, 1.0).expect("closed");
    assert_rel(p.mass, 2.0, 1e-15, "two cubes");
    // Blocks of the same name are one part.
    let same = format!("{a}{}", b.replacen("solid\n", "solid first\n", 1));
    let f = parse_mesh(same.as_bytes(), Path::new("two.stl")).expect("ascii");
    assert_eq!(f.part_names, ["first"]);
    assert_eq!(f.face_parts, vec![0; 24]);
}

#[test]
fn a_vertical_tab_after_f_still_names_the_right_lines() {
    // tobj splits records on any whitespace; the lines and parts must follow it.
    let text = CUBE_OBJ.replacen("f 5 6 7 8", "f\u{b}5 6 7 8", 1);
    let f = parse_mesh(text.as_bytes(), Path::new("part.obj")).expect("reads");
    assert_eq!(f.mesh.face_count(), 6);
    assert_eq!(f.face_lines, vec![10, 11, 12, 13, 14, 15]);
}

#[test]
fn obj_objects_or_else_groups_name_the_parts() {
    let cube = |k: usize| {
        let o = 8 * k;
        let v: String = (0..8)
            .map(|i| {
                let (x, y, z) = (i & 1, (i >> 1) & 1, (i >> 2) & 1);
                format!("v {} {y} {z}\n", x + 3 * k)
            })
            .collect();
        let f: String = [
            [1, 3, 4, 2],
            [5, 6, 8, 7],
            [1, 2, 6, 5],
            [3, 7, 8, 4],
            [1, 5, 7, 3],
            [2, 4, 8, 6],
        ]
        .iter()
        .map(|q| format!("f {} {} {} {}\n", q[0] + o, q[1] + o, q[2] + o, q[3] + o))
        .collect();
        (v, f)
    };
    let ((v0, f0), (v1, f1)) = (cube(0), cube(1));
    let with_objects = format!("{v0}{v1}o head\ng a\n{f0}o handle\ng b\n{f1}");
    let f = parse_mesh(with_objects.as_bytes(), Path::new("parts.obj")).expect("reads");
    assert_eq!(f.part_names, ["head", "handle"]);
    assert_eq!(f.face_parts, [vec![0; 6], vec![1; 6]].concat());
    let with_groups = format!("{v0}{v1}g a\n{f0}g b\n{f1}");
    let f = parse_mesh(with_groups.as_bytes(), Path::new("parts.obj")).expect("reads");
    assert_eq!(f.part_names, ["a", "b"]);
    let neither = format!("{v0}{v1}{f0}{f1}");
    let f = parse_mesh(neither.as_bytes(), Path::new("parts.obj")).expect("reads");
    assert!(f.part_names.is_empty() && f.face_parts.is_empty());
}

#[test]
fn a_byte_order_mark_does_not_shift_the_vertices() {
    let plain = obj(CUBE_OBJ).expect("valid");
    let with_mark = format!("\u{feff}{CUBE_OBJ}");
    assert_eq!(obj(&with_mark).expect("valid"), plain);
    // Even when the first line is a vertex: it would otherwise be lost.
    let first_vertex = CUBE_OBJ.replacen("# unit cube\n", "", 1);
    let with_mark = format!("\u{feff}{first_vertex}");
    assert_eq!(obj(&with_mark).expect("valid"), plain);
    // An ASCII STL with a mark is still ASCII.
    let stl = format!(
        "\u{feff}{}",
        ascii_stl(&shapes::cube().triangulated(), "solid cube")
    );
    let f = parse_mesh(stl.as_bytes(), Path::new("cube.stl")).expect("ascii");
    assert_eq!(f.mesh.face_count(), 12);
    // Each face's line is its facet's: the second line, then every seventh.
    assert_eq!(
        f.face_lines,
        (0..12).map(|t| 2 + 7 * t).collect::<Vec<u32>>()
    );
}

#[test]
fn points_and_polylines_are_not_part_of_the_body() {
    let extra = format!("{CUBE_OBJ}p 1 7\nl 1 7\nl 1 7 3 5\n");
    let m = obj(&extra).expect("valid");
    assert_eq!(m.face_count(), 6, "a polyline of any length bounds nothing");
    let d = diagnose(&m);
    assert!(d.is_closed(), "{d:?}");
}

#[test]
fn a_flat_sheet_has_no_volume_but_a_shell() {
    let sheet = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    let m = obj(sheet).expect("a valid mesh");
    let e = solid_properties(&m, massprops::integrals::IntegrationPath::Auto).expect_err("flat");
    assert!(matches!(e, MeshError::ZeroVolume { .. }), "{e:?}");
    assert!(e.to_string().contains("shell"), "{e}");
    assert!(matches!(
        mass_properties(&m, 1.0),
        Err(MeshError::ZeroVolume { .. })
    ));
    for method in [Method::Volume, Method::Points, Method::BoundingBox] {
        assert!(
            matches!(
                analyze(&m, method, MassSpec::Density(1.0)),
                Err(MeshError::ZeroVolume { .. })
            ),
            "{method:?}"
        );
    }
    let sigma = 2.5;
    let (p, area) = shell_properties(&m, sigma).expect("area 1");
    assert_rel(area, 1.0, 1e-15, "area");
    assert_rel(p.mass, sigma, 1e-15, "mass");
    assert!((p.center_of_mass - Point3::new(0.5, 0.5, 0.0)).amax() < 1e-15);
    let want = Matrix3::from_diagonal(&Vector3::new(1.0 / 12.0, 1.0 / 12.0, 1.0 / 6.0)) * sigma;
    assert_mat(&p.inertia_com, &want, 1e-14, "square sheet");
    let a = analyze(&m, Method::Shell, MassSpec::Density(sigma)).expect("shell works");
    assert_eq!(a.volume, None);
    assert_eq!(a.density, Some(sigma));
    assert_mat(&a.properties.inertia_com, &want, 1e-14, "analyze shell");
    // A double-sided sheet (both windings) encloses nothing either.
    let both = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 4 3 2 1\n";
    assert!(matches!(
        mass_properties(&obj(both).expect("valid"), 1.0),
        Err(MeshError::ZeroVolume { .. })
    ));
}

#[test]
fn unreadable_and_unsupported_files() {
    let missing = scratch("does-not-exist.obj");
    let e = load_mesh(&missing).expect_err("no such file");
    assert!(matches!(e, MeshError::Io { .. }), "{e:?}");
    assert!(e.to_string().contains("does-not-exist.obj"), "{e}");
    for name in ["part.step", "part", "part.obj.gz"] {
        let e = parse_mesh(CUBE_OBJ.as_bytes(), Path::new(name)).expect_err("unsupported");
        assert!(
            matches!(e, MeshError::UnsupportedFormat { .. }),
            "{name}: {e:?}"
        );
        assert!(e.to_string().contains(name), "{e}");
    }
    // Extensions are case-insensitive.
    assert!(parse_mesh(CUBE_OBJ.as_bytes(), Path::new("PART.OBJ")).is_ok());
    // Binary junk named .obj is malformed, not a panic.
    let e = parse_mesh(&[0xff, 0xfe, 0x00, 0x80, 0x81], Path::new("part.obj")).expect_err("binary");
    assert!(e.to_string().contains("line 1"), "{e}");
}

fn binary_stl(mesh: &MeshBuilder, header: &[u8]) -> Vec<u8> {
    let tri = mesh.clone().triangulated();
    let mut out = vec![0u8; 80];
    out[..header.len()].copy_from_slice(header);
    out.extend_from_slice(&(tri.faces.len() as u32).to_le_bytes());
    for f in &tri.faces {
        out.extend_from_slice(&[0u8; 12]); // normal: readers must not need it
        for &i in f {
            for c in tri.positions[i].coords.iter() {
                out.extend_from_slice(&(*c as f32).to_le_bytes());
            }
        }
        out.extend_from_slice(&[0, 0]);
    }
    out
}

fn ascii_stl(mesh: &MeshBuilder, first_line: &str) -> String {
    let tri = mesh.clone().triangulated();
    let mut s = format!("{first_line}\n");
    for f in &tri.faces {
        s.push_str("  facet normal 0 0 0\n    outer loop\n");
        for &i in f {
            let p = tri.positions[i];
            s.push_str(&format!(
                "      vertex {} {} {}\n",
                p.x as f32, p.y as f32, p.z as f32
            ));
        }
        s.push_str("    endloop\n  endfacet\n");
    }
    s.push_str("endsolid box\n");
    s
}

#[test]
fn stl_binary_and_ascii_give_the_obj_result() {
    let b = dyadic_box();
    let from_obj = obj(&shapes::to_obj("box", "test", &b)).expect("valid");
    let want = mass_properties(&from_obj, 3.0).expect("closed");
    assert_rel(want.mass, 3.0, 1e-15, "box volume 1");
    let files: Vec<(&str, Vec<u8>)> = vec![
        ("binary", binary_stl(&b, b"binary STL written by a test")),
        (
            "binary, header starting with \"solid \"",
            binary_stl(&b, b"solid box exported by a CAD program"),
        ),
        (
            "binary, header with a \"solid \" line",
            binary_stl(&b, b"solid box\n"),
        ),
        ("ascii", ascii_stl(&b, "solid box").into_bytes()),
        ("ascii, unnamed solid", ascii_stl(&b, "solid").into_bytes()),
    ];
    for (what, bytes) in files {
        let path = scratch("box.stl");
        std::fs::write(&path, &bytes).expect("temp dir is writable");
        let loaded = load_mesh(&path).map(|f| f.mesh);
        std::fs::remove_file(&path).expect("remove the scratch file");
        let m = loaded.unwrap_or_else(|e| panic!("{what}: {e}"));
        let d = diagnose(&m);
        assert_eq!((d.vertices, d.faces), (8, 12), "{what}: welded");
        assert!(
            d.is_closed() && d.is_consistently_oriented(),
            "{what}: {d:?}"
        );
        let p = mass_properties(&m, 3.0).expect("closed");
        assert_rel(p.mass, want.mass, 1e-15, what);
        assert!(
            (p.center_of_mass - want.center_of_mass).amax() < 1e-15,
            "{what}"
        );
        assert_mat(&p.inertia_com, &want.inertia_com, 1e-14, what);
    }
    // A header that counts 0 triangles (or too few) before whole records: read by the file's
    // size, and said so (it was "empty: it has no faces").
    for announced in [0u32, 5] {
        let mut zero = binary_stl(&b, b"binary");
        zero[80..84].copy_from_slice(&announced.to_le_bytes());
        let file = parse_mesh(&zero, Path::new("zero.stl")).expect("read by its size");
        assert_eq!(file.mesh.face_count(), 12, "{announced}");
        let p = mass_properties(&file.mesh, 3.0).expect("closed");
        assert_rel(p.mass, want.mass, 1e-15, "by size");
        let codes: Vec<&str> = file.warnings.iter().map(|w| w.code()).collect();
        assert_eq!(codes, ["stl_triangle_count"]);
        assert_eq!(
            file.warnings[0].defect,
            Defect::StlTriangleCount {
                header: u64::from(announced),
                records: 12
            }
        );
    }
    // A truncated binary file is malformed, not a panic.
    let mut short = binary_stl(&b, b"binary");
    short.truncate(84 + 50 * 5 + 7);
    let e = parse_mesh(&short, Path::new("cut.stl")).expect_err("truncated");
    // Named as cut short, with what is missing, not "failed to fill whole buffer".
    let n = u32::from_le_bytes([short[80], short[81], short[82], short[83]]);
    let text = e.to_string();
    assert!(text.contains("cut short"), "{text}");
    assert!(
        text.contains(&format!("announces {n} triangles ({} bytes)", 84 + 50 * n)),
        "{text}"
    );
    assert!(
        text.contains(&format!("has {} bytes", 84 + 50 * 5 + 7)),
        "{text}"
    );
    assert!(
        text.contains(&format!("triangles 5 to {}", n - 1)),
        "{text}"
    );
    // The same with a header that starts with "solid", as many CAD exporters write.
    let mut solid_header = binary_stl(&b, b"solid exported by CAD");
    solid_header.truncate(84 + 50 * 5 + 7);
    let cut = parse_mesh(&solid_header, Path::new("cut.stl")).expect_err("truncated");
    assert!(cut.to_string().contains("cut short"), "{cut}");
    let stub = parse_mesh(&short[..40], Path::new("stub.stl")).expect_err("no header");
    assert!(stub.to_string().contains("84-byte header"), "{stub}");
    assert!(matches!(e, MeshError::Malformed { .. }), "{e:?}");
    assert!(e.to_string().contains("cut.stl"), "{e}");
    // Infinity in triangle 5, corner 2: the message names where, not an index of the welded
    // mesh.
    let mut inf_binary = binary_stl(&b, b"binary");
    let at = 84 + 50 * 5 + 12 + 2 * 12;
    inf_binary[at..at + 4].copy_from_slice(&f32::INFINITY.to_le_bytes());
    let ascii = ascii_stl(&b, "solid box");
    let sixth_facet = ascii
        .match_indices("facet normal")
        .nth(5)
        .expect("12 facets")
        .0;
    let third_vertex = sixth_facet
        + ascii[sixth_facet..]
            .match_indices("vertex")
            .nth(2)
            .expect("3")
            .0;
    let line_end = third_vertex + ascii[third_vertex..].find('\n').expect("a line");
    let mut inf_ascii = ascii.clone();
    inf_ascii.replace_range(third_vertex..line_end, "vertex inf 0 0");
    let e = parse_mesh(&inf_binary, Path::new("inf.stl")).expect_err("non-finite");
    assert!(
        e.to_string()
            .contains("inf.stl: triangle 5 (counting from 0), corner 2: non-finite coordinate inf"),
        "{e}"
    );
    // stl_io refuses the ASCII number itself.
    let e = parse_mesh(inf_ascii.as_bytes(), Path::new("inf.stl")).expect_err("non-finite");
    let text = e.to_string();
    assert!(
        text.contains("inf.stl: triangle 5 (counting from 0)") && text.contains("inf"),
        "{text}"
    );
}

#[test]
fn all_objects_and_groups_of_an_obj_form_one_body() {
    let one = shapes::to_obj(
        "a",
        "first",
        &shapes::cuboid(Vector3::repeat(1.0), Point3::origin()),
    );
    let two = shapes::to_obj(
        "b",
        "second",
        &shapes::cuboid(Vector3::repeat(1.0), Point3::new(3.0, 0.0, 0.0)),
    );
    // Indices of the second object continue after the first object's 8 vertices.
    let two_shifted: String = two
        .lines()
        .map(|l| match l.strip_prefix("f ") {
            Some(rest) => {
                let idx: Vec<String> = rest
                    .split(' ')
                    .map(|i| (i.parse::<usize>().expect("index") + 8).to_string())
                    .collect();
                format!("f {}\n", idx.join(" "))
            }
            None => format!("{l}\n"),
        })
        .collect();
    let grouped = format!("{one}g part2\n{two_shifted}").replacen("o b\n", "g second\n", 1);
    for text in [format!("{one}{two_shifted}"), grouped] {
        let m = obj(&text).expect("valid");
        assert_eq!(m.face_count(), 12);
        let p = mass_properties(&m, 1.0).expect("closed");
        assert_rel(p.mass, 2.0, 1e-15, "two unit cubes");
        assert!((p.center_of_mass - Point3::new(1.5, 0.0, 0.0)).amax() < 1e-15);
        // Parallel axis: each cube is 1.5 from the common centre along x.
        let want = Matrix3::identity() / 3.0 + Matrix3::from_diagonal(&Vector3::new(0.0, 4.5, 4.5));
        assert_mat(&p.inertia_com, &want, 1e-14, "two cubes");
    }
}

#[test]
fn per_corner_positions_are_welded() {
    // Every face lists its own copies of its corners (as exporters do for normals and UVs).
    let cube = shapes::cube();
    let mut text = String::from("o cube\nvn 0 0 1\nvt 0 0\n");
    let mut next = 1;
    let mut faces = String::new();
    for f in &cube.faces {
        faces.push('f');
        for &i in f {
            let p = cube.positions[i];
            text.push_str(&format!("v {} {} {}\n", p.x, p.y, p.z));
            faces.push_str(&format!(" {next}/1/1"));
            next += 1;
        }
        faces.push('\n');
    }
    text.push_str(&faces);
    let m = obj(&text).expect("valid");
    let d = diagnose(&m);
    assert_eq!(d.vertices, 8);
    assert_eq!(d.open_edges, 0);
    assert!(d.is_closed() && d.is_consistently_oriented(), "{d:?}");
    let p = mass_properties(&m, 1.0).expect("closed");
    assert_mat(
        &p.inertia_com,
        &(Matrix3::identity() / 6.0),
        1e-15,
        "welded cube",
    );
}

#[test]
fn errors_on_parameters_are_typed() {
    let m = shapes::cube().build();
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(
                mass_properties(&m, bad),
                Err(MeshError::InvalidParameter { .. })
            ),
            "{bad}"
        );
        for spec in [MassSpec::Density(bad), MassSpec::Mass(bad)] {
            let e = analyze(&m, Method::Volume, spec).expect_err("invalid");
            assert!(matches!(e, MeshError::InvalidParameter { .. }), "{e:?}");
        }
        assert!(shell_properties(&m, bad).is_err());
    }
    // Constructing a mesh validates it, face by face.
    let pts = vec![
        Point3::origin(),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(0.0, 1.0, 0.0),
    ];
    let e = PolyMesh::new(pts.clone(), &[vec![0, 1, 2], vec![0, 1, 7]]).expect_err("out of range");
    assert!(
        e.to_string().contains("face 1") && e.to_string().contains("vertex 7"),
        "{e}"
    );
    let e = PolyMesh::new(pts, &[vec![0usize, 1]]).expect_err("two corners");
    assert!(e.to_string().contains("face 0"), "{e}");
}
