//! Integration tests of `inertia-lab props`: the real binary on the sample assets and on bad
//! files, checked against closed-form values.

mod common;

use common::{TempFile, root, run};
use serde_json::Value;

fn props_json(args: &[&str]) -> Value {
    let mut all = vec!["props"];
    all.extend_from_slice(args);
    all.push("--json");
    let out = run(&all);
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

fn f(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs().max(f64::MIN_POSITIVE)
}

#[test]
fn t_handle_json_has_the_schema_and_the_parallel_axis_values() {
    let j = props_json(&["assets/t_handle.obj", "--density", "7800"]);
    for key in [
        "schema_version",
        "file",
        "method",
        "density",
        "volume",
        "mass",
        "surface_area",
        "center_of_mass",
        "inertia_com",
        "inertia_origin",
        "principal_moments",
        "principal_axes",
        "bounding_box",
        "inertia_bbox",
        "inertia_points",
        "mesh",
        "warnings",
    ] {
        assert!(j.get(key).is_some(), "missing {key}");
    }
    assert_eq!(j["schema_version"], 4);
    assert_eq!(j["method"], "volume");
    // Two boxes: crossbar 0.08 × 0.012 × 0.012 centred at y = 0.006, stem 0.012 × 0.05 × 0.012
    // centred at y = −0.025.
    let rho = 7800.0;
    let (mb, ms) = (rho * 0.08 * 0.012 * 0.012, rho * 0.012 * 0.05 * 0.012);
    let m = mb + ms;
    let yc = (mb * 0.006 + ms * -0.025) / m;
    assert!(close(f(&j["mass"]), m, 1e-12));
    assert!(close(f(&j["volume"]), m / rho, 1e-12));
    assert!(close(f(&j["center_of_mass"][1]), yc, 1e-12));
    assert!(f(&j["center_of_mass"][0]).abs() < 1e-15);
    let box_i = |m: f64, a: f64, b: f64, c: f64| {
        [
            m / 12.0 * (b * b + c * c),
            m / 12.0 * (a * a + c * c),
            m / 12.0 * (a * a + b * b),
        ]
    };
    let ib = box_i(mb, 0.08, 0.012, 0.012);
    let is = box_i(ms, 0.012, 0.05, 0.012);
    let (db, ds) = (0.006 - yc, -0.025 - yc);
    let ixx = ib[0] + mb * db * db + is[0] + ms * ds * ds;
    let iyy = ib[1] + is[1];
    let izz = ib[2] + mb * db * db + is[2] + ms * ds * ds;
    let icom = &j["inertia_com"];
    assert!(close(f(&icom[0][0]), ixx, 1e-12));
    assert!(close(f(&icom[1][1]), iyy, 1e-12));
    assert!(close(f(&icom[2][2]), izz, 1e-12));
    assert!(f(&icom[0][1]).abs() < 1e-12 * izz);
    // About the origin: Ixx gains m·yc².
    assert!(close(
        f(&j["inertia_origin"][0][0]),
        ixx + m * yc * yc,
        1e-12
    ));
    // Principal moments ascending, axes right-handed and orthonormal.
    let pm: Vec<f64> = (0..3).map(|i| f(&j["principal_moments"][i])).collect();
    let mut expected = [ixx, iyy, izz];
    expected.sort_by(f64::total_cmp);
    for (a, b) in pm.iter().zip(expected) {
        assert!(close(*a, b, 1e-12));
    }
    let ax: Vec<[f64; 3]> = (0..3)
        .map(|i| [0, 1, 2].map(|k| f(&j["principal_axes"][i][k])))
        .collect();
    let cross = [
        ax[0][1] * ax[1][2] - ax[0][2] * ax[1][1],
        ax[0][2] * ax[1][0] - ax[0][0] * ax[1][2],
        ax[0][0] * ax[1][1] - ax[0][1] * ax[1][0],
    ];
    for k in 0..3 {
        assert!((cross[k] - ax[2][k]).abs() < 1e-12);
    }
    let mesh = &j["mesh"];
    assert_eq!(mesh["closed"], true);
    assert_eq!(mesh["consistently_oriented"], true);
    assert_eq!(mesh["open_edges"], 0);
    assert_eq!(mesh["flipped"], false);
    assert_eq!(mesh["vertices"], 16);
    assert_eq!(mesh["faces"], 10);
    // Bounding-box cuboid of the same mass about the box centre: 0.08 × 0.062 × 0.012.
    let bb = box_i(m, 0.08, 0.062, 0.012);
    assert!(close(f(&j["inertia_bbox"][0][0]), bb[0], 1e-12));
    assert!(close(f(&j["inertia_bbox"][2][2]), bb[2], 1e-12));
}

#[test]
fn every_sample_asset_is_a_closed_consistent_body() {
    for name in [
        "t_handle",
        "tennis_racket",
        "book",
        "hammer",
        "l_bracket",
        "cube",
        "torus",
    ] {
        let j = props_json(&[&format!("assets/{name}.obj")]);
        assert_eq!(j["mesh"]["closed"], true, "{name}");
        assert_eq!(j["mesh"]["consistently_oriented"], true, "{name}");
        assert_eq!(j["warnings"].as_array().map(Vec::len), Some(0), "{name}");
        assert!(f(&j["mass"]) > 0.0);
    }
}

#[test]
fn book_mass_option_scale_and_methods() {
    // 1 × 4 × 7 box of mass 3: I = m/12·(b² + c², a² + c², a² + b²).
    let j = props_json(&["assets/book.obj", "--mass", "3"]);
    assert!(close(f(&j["density"]), 3.0 / 28.0, 1e-14));
    let i = [65.0 / 4.0, 50.0 / 4.0, 17.0 / 4.0];
    for (k, v) in i.iter().enumerate() {
        assert!(close(f(&j["inertia_com"][k][k]), *v, 1e-13));
    }
    // Scaling every length by 10 at fixed density multiplies the mass by 1000, I by 1e5.
    let s = props_json(&["assets/book.obj", "--scale", "10"]);
    assert!(close(f(&s["mass"]), 28_000.0, 1e-13));
    assert!(close(
        f(&s["inertia_com"][0][0]),
        28.0 * 65.0 / 12.0 * 1e5,
        1e-13
    ));
    // The bbox method of a box is the box itself.
    let b = props_json(&["assets/book.obj", "--method", "bbox"]);
    assert!(close(f(&b["inertia_com"][0][0]), 28.0 * 65.0 / 12.0, 1e-13));
    assert_eq!(b["method"], "bbox");
    // Shell: six plates, area 2(4 + 7 + 28) = 78.
    let sh = props_json(&["assets/book.obj", "--method", "shell"]);
    assert!(close(f(&sh["mass"]), 78.0, 1e-13));
    // Points: eight masses m/8 at the corners: Ixx = m(2² + 3.5²).
    let p = props_json(&["assets/book.obj", "--method", "points"]);
    assert!(close(
        f(&p["inertia_com"][0][0]),
        28.0 * (4.0 + 12.25),
        1e-13
    ));
}

#[test]
fn human_table_has_ten_digits_and_json_every_digit() {
    let out = run(&["props", "assets/book.obj"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("off-diagonals = -sum(m*x*y)"));
    // I_xx = 28·65/12 = 151.666…: 10 significant digits in the table, all 17 in the JSON.
    assert!(text.contains(" 151.6666667 "), "{text}");
    assert!(!text.contains("151.66666666"), "{text}");
    let j = props_json(&["assets/book.obj"]);
    assert_eq!(f(&j["inertia_com"][0][0]), 151.66666666666666);
    // The book's axes are the mesh axes: round-off off the diagonal prints as 0.
    let rows: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_start().starts_with('['))
        .collect();
    assert!(rows[0].contains(" 0 "), "{}", rows[0]);
}

/// A centre-of-mass coordinate that is round-off (below 1e-12 of the body's size) prints as 0 in
/// the table, for a mesh and for a body of parts; the JSON keeps the number as computed.
#[test]
fn round_off_in_the_centre_of_mass_prints_as_zero_in_the_table() {
    let com_line = |args: &[&str]| {
        let out = run(args);
        assert!(out.status.success(), "{args:?}");
        let text = String::from_utf8_lossy(&out.stdout).into_owned();
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with("centre of mass"))
            .map(str::to_owned);
        line.unwrap_or_else(|| panic!("no centre of mass in {text}"))
    };
    let fields = |line: &str| -> Vec<String> {
        line.split_whitespace().skip(3).map(str::to_owned).collect()
    };
    // The T-handle is symmetric in z: its z is -5.3e-19 as integrated.
    let j = props_json(&["assets/t_handle.obj"]);
    let z = f(&j["center_of_mass"][2]);
    assert!(z != 0.0 && z.abs() < 1e-17, "{z}");
    let line = com_line(&["props", "assets/t_handle.obj"]);
    assert_eq!(fields(&line), ["0", "-0.005923076923", "0"], "{line}");
    // A real coordinate of the same size relative to the body is kept: the handle moved by 1e-9.
    let line = com_line(&["props", "assets/t_handle.obj", "--scale", "1e-9"]);
    assert_eq!(fields(&line)[1], "-5.923076923e-12", "{line}");
    // The hammer's body file: z is 3.7e-18 as summed.
    let line = com_line(&["props", "assets/hammer.toml"]);
    assert_eq!(fields(&line)[2], "0", "{line}");
    assert_ne!(fields(&line)[1], "0", "{line}");
}

/// A given mass is reported as given, in the table and the JSON (ρ·V with ρ = m/V would not be).
#[test]
fn given_mass_is_reported_exactly() {
    for mass in ["0.2", "0.1", "3.3"] {
        let out = run(&["props", "assets/t_handle.obj", "--mass", mass]);
        let text = String::from_utf8_lossy(&out.stdout);
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with("mass "))
            .expect("mass line");
        assert_eq!(line.split_whitespace().nth(1), Some(mass), "{line}");
        let j = props_json(&["assets/t_handle.obj", "--mass", mass]);
        assert_eq!(f(&j["mass"]), mass.parse::<f64>().expect("number"));
        let shell = props_json(&["assets/t_handle.obj", "--mass", mass, "--method", "shell"]);
        assert_eq!(f(&shell["mass"]), mass.parse::<f64>().expect("number"));
    }
}

#[test]
fn bad_input_exits_3_with_file_and_line() {
    let obj = TempFile::new("bad.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    let out = run(&["props", obj.path()]);
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 4"), "{err}");
    assert!(err.contains(obj.path()), "{err}");

    let nan = TempFile::new("nan.obj", b"v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
    let out = run(&["props", nan.path()]);
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8_lossy(&out.stderr);
    // The file's third `v`, numbered as every index in our messages is: from 0.
    assert!(
        err.contains("line 3: vertex 2 (counting from 0) has a non-finite coordinate NaN"),
        "{err}"
    );

    let missing = run(&["props", "no/such/file.obj"]);
    assert_eq!(missing.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("no/such/file.obj"));

    let flat = TempFile::new("flat.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n");
    let out = run(&["props", flat.path()]);
    assert_eq!(out.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&out.stderr).contains("zero volume"));
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(
        run(&["props", "assets/cube.obj", "--density", "-1"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        run(&["props", "assets/cube.obj", "--mass", "1", "--density", "2"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        run(&["props", "assets/cube.obj", "--method", "magic"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(run(&["props"]).status.code(), Some(2));
    let help = run(&["--help"]);
    assert_eq!(help.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&help.stdout).contains("props"));
}

#[test]
fn open_and_inverted_meshes_are_reported() {
    // A cube with its top face missing.
    let open = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    let file = TempFile::new("open.obj", open);
    let j = props_json(&[file.path()]);
    assert_eq!(j["mesh"]["closed"], false);
    assert_eq!(j["mesh"]["open_edges"], 4);
    // Capped: the unit cube again, and the warning says the cap holds a sixth of it (the
    // pyramid from the centre), names the faces around the hole with their lines.
    assert!(close(f(&j["volume"]), 1.0, 1e-15));
    let w = &j["warnings"][0];
    assert_eq!(w["code"], "holes_capped");
    assert_eq!(
        (w["count"].as_u64(), w["boundary_edges"].as_u64()),
        (Some(1), Some(4))
    );
    assert!(close(f(&w["effect_on_mass"]), -1.0 / 6.0, 1e-15), "{w}");
    assert!(close(f(&w["cap_area_fraction"]), 0.2, 1e-15), "{w}");
    assert_eq!(w["faces"], serde_json::json!([1, 2, 3, 4]));
    assert_eq!(w["face_lines"], serde_json::json!([10, 11, 12, 13]));
    let message = w["message"].as_str().expect("text");
    assert!(
        message.contains("1 (line 10)") && message.contains("differ by -17 %"),
        "{message}"
    );
    assert_eq!(j["shells"][0]["closed"], false);
    assert_eq!(j["shells"][0]["depth"], 0);
    // Refused on request, naming the hole; a bad --weld is a usage error.
    let out = run(&["props", file.path(), "--holes", "refuse"]);
    assert_eq!(out.status.code(), Some(3));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("1 hole(s), around faces 1, 2, 3, 4"),
        "{stderr}"
    );
    let out = run(&["props", file.path(), "--weld", "tight"]);
    assert_eq!(out.status.code(), Some(2));

    // The same cube closed but wound inwards: same numbers, flipped and a warning.
    let inward = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 2 3 4\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\nf 5 8 7 6\n";
    let file = TempFile::new("inward.obj", inward);
    let j = props_json(&[file.path()]);
    assert_eq!(j["mesh"]["flipped"], true);
    assert!(close(f(&j["volume"]), 1.0, 1e-15));
    assert!(close(f(&j["inertia_com"][0][0]), 1.0 / 6.0, 1e-14));

    // The outward cube with face 1 (y = 0) wound the other way: the face is turned to agree
    // with its four neighbours (the unit cube), and the warning counts the one face turned and
    // names the four pairs that met wrongly, each holding face 1.
    let one_flipped = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 5 6 2 1\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\nf 5 6 7 8\n";
    let file = TempFile::new("one-flipped.obj", one_flipped);
    let j = props_json(&[file.path()]);
    let w = j["warnings"]
        .as_array()
        .expect("warnings")
        .iter()
        .find(|w| w["code"] == "inconsistent_winding")
        .expect("the winding warning");
    assert_eq!(w["count"], 1);
    assert_eq!(w["faces"], serde_json::json!([1]));
    assert!(close(f(&j["volume"]), 1.0, 1e-15), "{}", j["volume"]);
    let pairs = w["face_pairs"].as_array().expect("face pairs");
    assert_eq!(pairs.len(), 4);
    for p in pairs {
        let (a, b) = (p[0].as_u64(), p[1].as_u64());
        assert!((a == Some(1)) != (b == Some(1)), "{p}");
    }
    let message = w["message"].as_str().expect("text");
    assert!(
        message.contains("met wrongly: 0 (line 9) and 1 (line 10)"),
        "{message}"
    );
}

#[test]
fn a_duplicated_face_counts_once_and_the_json_says_what_it_would_have_added() {
    let cube = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\nf 5 6 7 8\nf 6 7 8 5\n";
    let file = TempFile::new("doubled-top.obj", cube);
    let j = props_json(&[file.path()]);
    assert!(close(f(&j["mass"]), 1.0, 1e-15));
    assert_eq!(j["warnings"].as_array().map(Vec::len), Some(1));
    let w = &j["warnings"][0];
    assert_eq!(w["code"], "duplicate_faces");
    assert_eq!(
        (w["count"].as_u64(), &w["faces"]),
        (Some(1), &serde_json::json!([6]))
    );
    assert_eq!(w["face_lines"], serde_json::json!([15]));
    // About the cube's centre the top face carries the pyramid of a sixth of the volume.
    assert!(close(f(&w["effect_on_mass"]), 1.0 / 6.0, 1e-15), "{w}");
    // The shell's volume to round-off (its last bit depends on the summation order the CPU's
    // vector width gives: 0.9999999999999999 on one machine, 1.0 on another).
    let mut shells = j["shells"].clone();
    assert!(close(f(&shells[0]["volume"]), 1.0, 1e-15), "{shells}");
    shells[0]["volume"] = serde_json::json!(1.0);
    assert_eq!(
        shells,
        serde_json::json!([{
            "faces": 6, "closed": true, "capped": false, "volume": 1.0, "orientation": "outward", "depth": 0
        }])
    );
}

#[test]
fn committed_assets_match_their_generator() {
    let shapes = massprops::shapes::samples()
        .into_iter()
        .chain(massprops::shapes::part_samples());
    for (name, comment, mesh) in shapes {
        let committed = std::fs::read_to_string(root().join(format!("assets/{name}.obj")))
            .expect("asset present");
        assert_eq!(
            committed,
            massprops::shapes::to_obj(name, comment, &mesh),
            "assets/{name}.obj is stale: run `cargo run -p massprops --example generate_assets`"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Bodies written by the tests, with closed-form mass properties.

type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

fn vec3(v: &Value) -> V3 {
    [0, 1, 2].map(|k| f(&v[k]))
}

fn mat3(v: &Value) -> M3 {
    [0, 1, 2].map(|r| vec3(&v[r]))
}

/// Distance from `a` to the nearer of `b` and `−b`.
fn up_to_sign(a: V3, b: V3) -> f64 {
    norm(sub(a, b)).min(norm([a[0] + b[0], a[1] + b[1], a[2] + b[2]]))
}

/// An OBJ of `vertices` and `faces` (0-based here, 1-based in the file), every digit kept.
fn obj(vertices: &[V3], faces: &[Vec<usize>]) -> String {
    let mut s = String::new();
    for v in vertices {
        s += &format!("v {:?} {:?} {:?}\n", v[0], v[1], v[2]);
    }
    for face in faces {
        let idx: Vec<String> = face.iter().map(|i| (i + 1).to_string()).collect();
        s += &format!("f {}\n", idx.join(" "));
    }
    s
}

/// The six outward-wound quads of a box whose corners are numbered as in [`box_corners`].
fn box_faces() -> Vec<Vec<usize>> {
    vec![
        vec![0, 3, 2, 1],
        vec![0, 1, 5, 4],
        vec![1, 2, 6, 5],
        vec![2, 3, 7, 6],
        vec![3, 0, 4, 7],
        vec![4, 5, 6, 7],
    ]
}

/// Corners of the box [0, a] × [0, b] × [0, c] shifted by −`centre`: bottom ring counter-clockwise
/// seen from +z, then the top ring.
fn box_corners(size: V3, centre: V3) -> Vec<V3> {
    let [a, b, c] = size;
    [
        [0.0, 0.0, 0.0],
        [a, 0.0, 0.0],
        [a, b, 0.0],
        [0.0, b, 0.0],
        [0.0, 0.0, c],
        [a, 0.0, c],
        [a, b, c],
        [0.0, b, c],
    ]
    .iter()
    .map(|p| sub(*p, centre))
    .collect()
}

/// Inertia of a solid box of mass `m` and edges `d` about its centre, axes along its edges.
fn box_inertia(m: f64, d: V3) -> M3 {
    let [a, b, c] = d.map(|x| x * x);
    [
        [m * (b + c) / 12.0, 0.0, 0.0],
        [0.0, m * (a + c) / 12.0, 0.0],
        [0.0, 0.0, m * (a + b) / 12.0],
    ]
}

/// m(|d|²E − d dᵀ): a point mass m at d, about the origin (off-diagonals −m·x·y).
fn point_inertia(m: f64, d: V3) -> M3 {
    let n2 = dot(d, d);
    std::array::from_fn(|r| {
        std::array::from_fn(|c| m * (if r == c { n2 } else { 0.0 } - d[r] * d[c]))
    })
}

fn add(a: M3, b: M3) -> M3 {
    std::array::from_fn(|r| std::array::from_fn(|c| a[r][c] + b[r][c]))
}

/// Principal moments (ascending) and unit axes of a tensor with no xz or yz products: the xy
/// block in closed form, z on its own.
fn principal_of_plate(i: M3) -> [(f64, V3); 3] {
    let scale = i[0][0].abs().max(i[1][1].abs()).max(i[2][2].abs());
    assert!(i[0][2].abs() + i[1][2].abs() < 1e-13 * scale, "{i:?}");
    let (a, b, c) = (i[0][0], i[0][1], i[1][1]);
    let (mean, half) = ((a + c) / 2.0, ((a - c) / 2.0).hypot(b));
    assert!(b != 0.0, "the xy block is already diagonal");
    let axis = |l: f64| {
        // (b, λ − a) or (λ − c, b): the better conditioned of the two.
        let (u, v) = if (l - a).abs() > (l - c).abs() {
            (b, l - a)
        } else {
            (l - c, b)
        };
        let n = u.hypot(v);
        [u / n, v / n, 0.0]
    };
    let mut p = [
        (mean - half, axis(mean - half)),
        (mean + half, axis(mean + half)),
        (i[2][2], [0.0, 0.0, 1.0]),
    ];
    p.sort_by(|x, y| x.0.total_cmp(&y.0));
    p
}

/// Angle in degrees between two axes, 0 to 90 (the sign of an axis is free).
fn axis_angle_deg(a: V3, b: V3) -> f64 {
    norm(cross(a, b)).atan2(dot(a, b).abs()).to_degrees()
}

/// An L-shaped prism moved off the origin: the arm [0, 5] × [0, 1] and the arm [0, 1] × [1, 3],
/// 2 thick, shifted by (10, −5, 2); its hexagonal caps are non-convex polygons. Density 1.
struct LPrism {
    file: TempFile,
    vertices: Vec<V3>,
    mass: f64,
    com: V3,
    inertia: M3,
}

const L_SHIFT: V3 = [10.0, -5.0, 2.0];

fn l_prism() -> LPrism {
    let outline = [
        [0.0, 0.0],
        [5.0, 0.0],
        [5.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ];
    let mut vertices = Vec::new();
    for z in [0.0, 2.0] {
        for [x, y] in outline {
            vertices.push([x + L_SHIFT[0], y + L_SHIFT[1], z + L_SHIFT[2]]);
        }
    }
    let mut faces = vec![vec![5, 4, 3, 2, 1, 0], vec![6, 7, 8, 9, 10, 11]];
    for i in 0..6 {
        let j = (i + 1) % 6;
        faces.push(vec![i, j, j + 6, i + 6]);
    }
    let file = TempFile::new("l_prism.obj", obj(&vertices, &faces).as_bytes());
    // Two boxes: (mass, edges, centre before the shift).
    let parts = [
        (10.0, [5.0, 1.0, 2.0], [2.5, 0.5, 1.0]),
        (4.0, [1.0, 2.0, 2.0], [0.5, 2.0, 1.0]),
    ];
    let mass: f64 = parts.iter().map(|p| p.0).sum();
    let com0: V3 = std::array::from_fn(|k| parts.iter().map(|p| p.0 * p.2[k]).sum::<f64>() / mass);
    let mut inertia = [[0.0; 3]; 3];
    for (m, d, c) in parts {
        inertia = add(
            inertia,
            add(box_inertia(m, d), point_inertia(m, sub(c, com0))),
        );
    }
    let com = std::array::from_fn(|k| com0[k] + L_SHIFT[k]);
    LPrism {
        file,
        vertices,
        mass,
        com,
        inertia,
    }
}

fn assert_matrix_close(name: &str, got: M3, expected: M3, rel: f64) {
    let scale = expected
        .iter()
        .flatten()
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    for r in 0..3 {
        for c in 0..3 {
            assert!(
                (got[r][c] - expected[r][c]).abs() <= rel * scale,
                "{name}[{r}][{c}]: {got:?} vs {expected:?}"
            );
        }
    }
}

/// What `props` should report for one approximation of the L prism, computed here.
struct Expected {
    center: V3,
    inertia: M3,
    principal: [(f64, V3); 3],
}

/// The bounding-box cuboid [10, 15] × [−5, −2] × [2, 4] and the twelve vertex masses of the L
/// prism, each at the prism's mass.
fn l_prism_approximations(l: &LPrism) -> (Expected, Expected) {
    let bbox_inertia = box_inertia(l.mass, [5.0, 3.0, 2.0]);
    let bbox = Expected {
        center: [12.5, -3.5, 3.0],
        inertia: bbox_inertia,
        principal: {
            let d = [0, 1, 2].map(|k| {
                (
                    bbox_inertia[k][k],
                    std::array::from_fn(|j| f64::from(u8::from(j == k))),
                )
            });
            let mut d: [(f64, V3); 3] = d;
            d.sort_by(|x, y| x.0.total_cmp(&y.0));
            d
        },
    };
    let n = l.vertices.len() as f64;
    let center: V3 = std::array::from_fn(|k| l.vertices.iter().map(|v| v[k]).sum::<f64>() / n);
    let inertia = l.vertices.iter().fold([[0.0; 3]; 3], |acc, v| {
        add(acc, point_inertia(l.mass / n, sub(*v, center)))
    });
    let points = Expected {
        center,
        inertia,
        principal: principal_of_plate(inertia),
    };
    (bbox, points)
}

#[test]
fn approximations_of_an_off_centre_l_prism_match_closed_forms() {
    let l = l_prism();
    let j = props_json(&[l.file.path()]);
    assert!(close(f(&j["mass"]), l.mass, 1e-13));
    assert_eq!(j["warnings"].as_array().map(Vec::len), Some(0), "{j}");
    let com = vec3(&j["center_of_mass"]);
    for k in 0..3 {
        assert!((com[k] - l.com[k]).abs() < 1e-12, "{com:?} vs {:?}", l.com);
    }
    assert_matrix_close("inertia_com", mat3(&j["inertia_com"]), l.inertia, 1e-12);
    assert_eq!(j["principal_degeneracy"], "distinct");
    let exact = principal_of_plate(l.inertia);
    let moments = vec3(&j["principal_moments"]);
    for i in 0..3 {
        assert!(
            close(moments[i], exact[i].0, 1e-12),
            "{moments:?} vs {exact:?}"
        );
    }
    // 12 corners, 2 hexagons (4 triangles each) + 6 quads, 18 edges: V − E + F = 2.
    let mesh = &j["mesh"];
    assert_eq!(
        [
            &mesh["vertices"],
            &mesh["faces"],
            &mesh["triangles"],
            &mesh["edges"]
        ],
        [12, 8, 20, 18]
    );
    // The bounding box, exactly: integer coordinates.
    assert_eq!(vec3(&j["bounding_box"]["min"]), [10.0, -5.0, 2.0]);
    assert_eq!(vec3(&j["bounding_box"]["max"]), [15.0, -2.0, 4.0]);

    let (bbox, points) = l_prism_approximations(&l);
    for (name, e) in [("bbox", &bbox), ("points", &points)] {
        let a = &j["approximations"][name];
        let center = vec3(&a["center"]);
        for k in 0..3 {
            assert!(
                (center[k] - e.center[k]).abs() < 1e-12,
                "{name} centre {center:?}"
            );
        }
        assert_matrix_close(name, mat3(&a["inertia"]), e.inertia, 1e-12);
        let pm = vec3(&a["principal_moments"]);
        let err = vec3(&a["principal_moment_error"]);
        let angles = &a["principal_axis_angle_deg"];
        for i in 0..3 {
            assert!(
                close(pm[i], e.principal[i].0, 1e-12),
                "{name} moments {pm:?}"
            );
            let expected_err = (e.principal[i].0 - exact[i].0) / exact[i].0;
            assert!(
                (err[i] - expected_err).abs() < 1e-12,
                "{name} moment error {i}: {} vs {expected_err}",
                err[i]
            );
            let expected_angle = axis_angle_deg(e.principal[i].1, exact[i].1);
            let angle = f(&angles[i]);
            assert!(
                (angle - expected_angle).abs() < 1e-9,
                "{name} axis angle {i}: {angle} vs {expected_angle}"
            );
        }
        // The top-level tensors are the same approximations.
        let top = if name == "bbox" {
            "inertia_bbox"
        } else {
            "inertia_points"
        };
        assert_matrix_close(top, mat3(&j[top]), e.inertia, 1e-12);
    }
    // Sanity of the body chosen: the errors and angles are not trivially zero.
    assert!(f(&j["approximations"]["bbox"]["principal_axis_angle_deg"][0]) > 10.0);
    assert!(f(&j["approximations"]["points"]["principal_moment_error"][0]) > 1.0);
}

/// Numbers on the table line that starts with `label` (after trimming), `%`, `°` and `,` dropped.
fn table_numbers(section: &str, label: &str) -> Vec<f64> {
    let line = section
        .lines()
        .find_map(|l| l.trim_start().strip_prefix(label))
        .unwrap_or_else(|| panic!("a line {label:?} in\n{section}"));
    line.split([' ', ','])
        .filter(|w| !w.is_empty())
        .map(|w| {
            let w = w.trim_end_matches(['%', '°']);
            w.parse()
                .unwrap_or_else(|_| panic!("number {w:?} in {line:?}"))
        })
        .collect()
}

#[test]
fn table_approximation_section_of_the_l_prism_matches_closed_forms() {
    let l = l_prism();
    let out = run(&["props", l.file.path()]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    let exact = principal_of_plate(l.inertia);
    let (bbox, points) = l_prism_approximations(&l);
    let bbox_head = "bounding-box cuboid (about the box centre)";
    let points_head = "vertex point masses (about their centre)";
    let start = text.find(bbox_head).unwrap_or_else(|| panic!("{text}"));
    let middle = text.find(points_head).unwrap_or_else(|| panic!("{text}"));
    let end = text.find("\nMesh:").unwrap_or_else(|| panic!("{text}"));
    for (section, e) in [(&text[start..middle], &bbox), (&text[middle..end], &points)] {
        // 10 significant digits: half a unit in the 10th digit.
        let pm = table_numbers(section, "principal moments");
        assert_eq!(pm.len(), 3, "{section}");
        for (printed, (expected, _)) in pm.iter().zip(e.principal) {
            assert!(close(*printed, expected, 5.1e-10), "{section}");
        }
        // Percent with two decimals.
        let err = table_numbers(section, "moment error");
        assert_eq!(err.len(), 3, "{section}");
        for i in 0..3 {
            let expected = 100.0 * (e.principal[i].0 - exact[i].0) / exact[i].0;
            assert!(
                (err[i] - expected).abs() <= 0.005 + 1e-9,
                "{i}: {expected}\n{section}"
            );
        }
        // Degrees with three decimals.
        let angles = table_numbers(section, "axis angles");
        assert_eq!(angles.len(), 3, "{section}");
        for i in 0..3 {
            let expected = axis_angle_deg(e.principal[i].1, exact[i].1);
            assert!(
                (angles[i] - expected).abs() <= 0.0005 + 1e-9,
                "{i}: {expected}\n{section}"
            );
        }
        let offset = table_numbers(section, "centre offset");
        assert!(
            close(offset[0], norm(sub(e.center, l.com)), 5.1e-10),
            "{section}"
        );
    }
}

/// 30° about z, then 40° about x: the rotation matrix Rx(40°)·Rz(30°).
fn rotation_30z_40x() -> M3 {
    let (a, b) = (30f64.to_radians(), 40f64.to_radians());
    let rz = [
        [a.cos(), -a.sin(), 0.0],
        [a.sin(), a.cos(), 0.0],
        [0.0, 0.0, 1.0],
    ];
    let rx = [
        [1.0, 0.0, 0.0],
        [0.0, b.cos(), -b.sin()],
        [0.0, b.sin(), b.cos()],
    ];
    std::array::from_fn(|r| std::array::from_fn(|c| (0..3).map(|k| rx[r][k] * rz[k][c]).sum()))
}

#[test]
fn principal_axes_rows_are_the_rotated_box_edges_in_ascending_moment_order() {
    // A 1 × 2 × 3 box centred at the origin, rotated by R and moved to t. Mass 6 (density 1):
    // I = m(b² + c²)/12 about its 1-edge = 6.5, about its 2-edge = 5, about its 3-edge = 2.5.
    let r = rotation_30z_40x();
    let t = [0.3, -0.7, 1.1];
    let corners: Vec<V3> = box_corners([1.0, 2.0, 3.0], [0.5, 1.0, 1.5])
        .iter()
        .map(|p| std::array::from_fn(|k| dot(r[k], *p) + t[k]))
        .collect();
    let file = TempFile::new("rotated_box.obj", obj(&corners, &box_faces()).as_bytes());
    let j = props_json(&[file.path()]);
    assert!(close(f(&j["mass"]), 6.0, 1e-13));
    assert_eq!(j["principal_degeneracy"], "distinct");
    let moments = vec3(&j["principal_moments"]);
    for (m, expected) in moments.iter().zip([2.5, 5.0, 6.5]) {
        assert!(close(*m, expected, 1e-12), "{moments:?}");
    }
    // Column k of R is the box's k-edge in mesh axes; ascending moments: 3-edge, 2-edge, 1-edge.
    let edge = |k: usize| [r[0][k], r[1][k], r[2][k]];
    let expected = [edge(2), edge(1), edge(0)];
    let axes = mat3(&j["principal_axes"]);
    for i in 0..3 {
        assert!(
            up_to_sign(axes[i], expected[i]) < 1e-12,
            "row {i} = {:?}, expected ±{:?}",
            axes[i],
            expected[i]
        );
        assert!((norm(axes[i]) - 1.0).abs() < 1e-14);
    }
    // Right-handed: row0 × row1 = row2 (not merely ±).
    let c = cross(axes[0], axes[1]);
    assert!(norm(sub(c, axes[2])) < 1e-12, "{c:?} vs {:?}", axes[2]);
    // Columns are not the axes: a rows/columns mix-up would fail the checks above.
    for i in 0..3 {
        let column = [axes[0][i], axes[1][i], axes[2][i]];
        assert!(
            up_to_sign(column, expected[i]) > 0.1,
            "column {i} = {column:?}"
        );
    }
    // The same axes reassemble the tensor: I = Σ Iᵢ aᵢ aᵢᵀ.
    let tensor = mat3(&j["inertia_com"]);
    let rebuilt: M3 = std::array::from_fn(|p| {
        std::array::from_fn(|q| (0..3).map(|i| moments[i] * axes[i][p] * axes[i][q]).sum())
    });
    assert_matrix_close("inertia_com", tensor, rebuilt, 1e-12);
}

#[test]
fn principal_degeneracy_names_equal_moments() {
    let write_box = |size: V3| {
        TempFile::new(
            "box.obj",
            obj(&box_corners(size, [0.0; 3]), &box_faces()).as_bytes(),
        )
    };
    // 1 × 2 × 3: m/12·(13, 10, 5), distinct. 2 × 2 × 1: m/12·(5, 5, 8), I1 = I2.
    // 1 × 1 × 3: m/12·(10, 10, 2), I2 = I3. Unit cube: I1 = I2 = I3.
    let distinct = write_box([1.0, 2.0, 3.0]);
    let flat = write_box([2.0, 2.0, 1.0]);
    let long = write_box([1.0, 1.0, 3.0]);
    for (file, name) in [
        (distinct.path(), "distinct"),
        ("assets/l_bracket.obj", "distinct"),
        (flat.path(), "I1=I2"),
        ("assets/torus.obj", "I1=I2"),
        (long.path(), "I2=I3"),
        ("assets/cube.obj", "I1=I2=I3"),
    ] {
        let j = props_json(&[file]);
        assert_eq!(j["principal_degeneracy"], name, "{file}");
        // Only a unique axis gets an angle; the others are null.
        let angles = &j["approximations"]["bbox"]["principal_axis_angle_deg"];
        let unique = match name {
            "distinct" => [true; 3],
            "I1=I2" => [false, false, true],
            "I2=I3" => [true, false, false],
            _ => [false; 3],
        };
        for i in 0..3 {
            assert_eq!(angles[i].is_number(), unique[i], "{file}: {angles}");
        }
    }
    let text = String::from_utf8_lossy(&run(&["props", "assets/torus.obj"]).stdout).into_owned();
    assert!(
        text.contains("n/a (equal moments), n/a (equal moments), "),
        "{text}"
    );
}

#[test]
fn conventions_object_states_the_documented_conventions() {
    let j = props_json(&["assets/book.obj"]);
    let c = j["conventions"].as_object().expect("an object");
    let mut keys: Vec<&str> = c.keys().map(String::as_str).collect();
    keys.sort_unstable();
    assert_eq!(
        keys,
        ["density", "frame", "principal_axes", "tensor", "units"]
    );
    let text = |k: &str| c[k].as_str().unwrap_or_else(|| panic!("{k} is text"));
    // README, Conventions: I = ∑m(|r|²E − r rᵀ), off-diagonals −∑m·x·y.
    assert_eq!(
        text("tensor"),
        "inertia tensor I = sum m(|r|^2 E - r r^T): diagonal = moments, off-diagonals = -sum(m*x*y)"
    );
    assert_eq!(
        text("frame"),
        "mesh axes; inertia_com about the centre of mass, inertia_origin about the mesh origin"
    );
    assert_eq!(
        text("units"),
        "lengths in the mesh unit times scale; mass in the unit of density times length^3"
    );
    assert_eq!(text("density"), "mass per volume");
    assert_eq!(
        text("principal_axes"),
        "row i is the unit axis of principal_moments[i]; rows form a right-handed orthonormal set"
    );
    // A shell's density is per area.
    let shell = props_json(&["assets/book.obj", "--method", "shell"]);
    assert_eq!(shell["conventions"]["density"], "mass per area");
}

#[test]
fn mesh_counts_of_a_closed_and_an_open_cube_of_quads() {
    let corners = box_corners([1.0, 1.0, 1.0], [0.0; 3]);
    let closed = TempFile::new("cube.obj", obj(&corners, &box_faces()).as_bytes());
    let j = props_json(&[closed.path()]);
    let mesh = &j["mesh"];
    // 8 corners, 6 quads = 12 triangles, 12 edges (V − E + F = 2).
    assert_eq!(mesh["vertices"], 8);
    assert_eq!(mesh["faces"], 6);
    assert_eq!(mesh["triangles"], 12);
    assert_eq!(mesh["edges"], 12);
    assert_eq!(mesh["closed"], true);
    assert_eq!(mesh["consistently_oriented"], true);
    assert_eq!(mesh["open_edges"], 0);
    assert!(close(f(&j["surface_area"]), 6.0, 1e-15));
    assert_eq!(vec3(&j["bounding_box"]["min"]), [0.0; 3]);
    assert_eq!(vec3(&j["bounding_box"]["max"]), [1.0; 3]);

    // Without its top: 5 quads = 10 triangles, still 12 edges of which the top 4 are open; the
    // remaining faces still wind consistently.
    let mut faces = box_faces();
    faces.pop();
    let open = TempFile::new("open_cube.obj", obj(&corners, &faces).as_bytes());
    let j = props_json(&[open.path()]);
    let mesh = &j["mesh"];
    assert_eq!(mesh["vertices"], 8);
    assert_eq!(mesh["faces"], 5);
    assert_eq!(mesh["triangles"], 10);
    assert_eq!(mesh["edges"], 12);
    assert_eq!(mesh["closed"], false);
    assert_eq!(mesh["consistently_oriented"], true);
    assert_eq!(mesh["open_edges"], 4);
    assert!(close(f(&j["surface_area"]), 5.0, 1e-15));
}

#[test]
fn the_hammer_body_file_matches_its_closed_form() {
    // Head: steel box 0.12 × 0.03 × 0.03 centred at (0.02, 0.315, 0). Handle: wooden regular
    // 24-gon prism of circumradius R = 0.015 along y from 0 to 0.3; per unit mass its polar
    // moment is R²(2 + cos θ)/6, θ = 2π/24 (n triangles from the centre), and I_xx = I_zz =
    // R²(2 + cos θ)/12 + L²/12.
    let j = props_json(&["assets/hammer.toml"]);
    assert_eq!(j["kind"], "composite");
    let (n, r, l) = (24.0, 0.015, 0.3);
    let theta = std::f64::consts::TAU / n;
    let handle_area = n / 2.0 * r * r * theta.sin();
    let (mh, ms) = (7850.0 * 0.12 * 0.03 * 0.03, 600.0 * handle_area * l);
    let m = mh + ms;
    let com = [mh * 0.02 / m, (mh * 0.315 + ms * 0.15) / m, 0.0];
    assert!(close(f(&j["mass"]), m, 1e-13));
    for k in 0..2 {
        assert!(close(f(&j["center_of_mass"][k]), com[k], 1e-13), "{k}");
    }
    let polar = ms * r * r * (2.0 + theta.cos()) / 6.0;
    let across = ms * (r * r * (2.0 + theta.cos()) / 12.0 + l * l / 12.0);
    let head = |a: f64, b: f64| mh * (a * a + b * b) / 12.0;
    let (dx_h, dy_h) = (0.02 - com[0], 0.315 - com[1]);
    let (dx_s, dy_s) = (-com[0], 0.15 - com[1]);
    let ixx = head(0.03, 0.03) + mh * dy_h * dy_h + across + ms * dy_s * dy_s;
    let iyy = head(0.12, 0.03) + mh * dx_h * dx_h + polar + ms * dx_s * dx_s;
    let izz = head(0.12, 0.03)
        + mh * (dx_h * dx_h + dy_h * dy_h)
        + across
        + ms * (dx_s * dx_s + dy_s * dy_s);
    let ixy = -(mh * dx_h * dy_h + ms * dx_s * dy_s);
    let got = &j["inertia_com"];
    assert!(close(f(&got[0][0]), ixx, 1e-12), "{got}");
    assert!(close(f(&got[1][1]), iyy, 1e-12), "{got}");
    assert!(close(f(&got[2][2]), izz, 1e-12), "{got}");
    assert!(close(f(&got[0][1]), ixy, 1e-12), "{got}");
    let parts = j["parts"].as_array().expect("parts");
    assert_eq!(parts.len(), 2);
    assert_eq!(parts[0]["name"], "head");
    assert!(close(f(&parts[0]["mass"]), mh, 1e-13));
    assert!(close(f(&parts[1]["density"]), 600.0, 1e-15));
    // The centre of mass is in the head's half.
    assert!(com[1] > 0.15);

    // The same through the mesh file's objects and per-part materials.
    let k = props_json(&[
        "assets/hammer.obj",
        "--material-of",
        "head=steel",
        "--density-of",
        "handle=600",
    ]);
    assert!(close(f(&k["mass"]), m, 1e-13));
    // A part that is not there is named with the ones that are.
    let out = run(&["props", "assets/hammer.obj", "--density-of", "shaft=600"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("no part \"shaft\" (its parts: handle, head)"),
        "{stderr}"
    );
}

#[test]
fn export_takes_a_body_file() {
    let out = run(&["export", "assets/hollow_box.toml", "--format", "json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let j: Value = serde_json::from_slice(&out.stdout).expect("json");
    // 2700 kg/m³ × (2 × 0.3³ − 0.26³).
    let m = 2700.0 * (2.0 * 0.027 - 0.26f64.powi(3));
    let text = j.to_string();
    assert!(text.contains("mass"), "{text}");
    let mass = j["mass"]
        .as_f64()
        .or_else(|| j["mass_kg"].as_f64())
        .expect("mass");
    assert!(close(mass, m, 1e-13), "{mass} vs {m}");
    // A body file brings its own units and materials.
    let out = run(&[
        "export",
        "assets/hammer.toml",
        "--format",
        "urdf",
        "--density",
        "5",
    ]);
    assert_eq!(out.status.code(), Some(2));
}

/// `--method shell` integrates the surface: on an open mesh (a unit cube without its top) the
/// JSON has the five faces' mass and area and `"volume": null` (README: null when the mesh
/// encloses none; no caps are added for a shell); on the closed cube, its volume.
#[test]
fn shell_method_on_an_open_mesh_has_a_null_volume() {
    let open = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    let file = TempFile::new("open-shell.obj", open);
    let j = props_json(&[file.path(), "--method", "shell"]);
    assert_eq!(j["method"], "shell");
    assert!(j["volume"].is_null(), "volume: {}", j["volume"]);
    assert!(close(f(&j["mass"]), 5.0, 1e-15), "{}", j["mass"]);
    assert!(close(f(&j["surface_area"]), 5.0, 1e-15));
    let closed = format!("{}f 5 6 7 8\n", std::str::from_utf8(open).expect("text"));
    let file = TempFile::new("closed-shell.obj", closed.as_bytes());
    let j = props_json(&[file.path(), "--method", "shell"]);
    assert!(
        close(f(&j["volume"]), 1.0, 1e-15),
        "volume: {}",
        j["volume"]
    );
    assert!(close(f(&j["mass"]), 6.0, 1e-15));
}

/// A warning's words state its effect with the sign of `effect_on_mass`: a unit cube without its
/// top is capped, and without the cap (the open file taken literally, minus the capped solid)
/// its mass would be less, so both the number and the words are negative (they were "caps add
/// +17 %" beside −0.167).
#[test]
fn the_holes_message_has_the_sign_of_its_effect() {
    let open = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    let file = TempFile::new("open-capped.obj", open);
    let j = props_json(&[file.path()]);
    let holes = j["warnings"]
        .as_array()
        .expect("warnings")
        .iter()
        .find(|w| w["code"] == "holes_capped")
        .expect("holes_capped");
    let effect = f(&holes["effect_on_mass"]);
    assert!(effect < -0.1, "{effect}");
    let message = holes["message"].as_str().expect("message");
    assert!(message.contains("the mass would differ by -"), "{message}");
    assert!(!message.contains('+'), "{message}");
}

/// The lab's volume (the page's `data-volume`, the side panel's and the diagnostics' line) is
/// the volume `props` reports for every sample: a mesh's enclosed volume, and for a body of parts
/// its parts' volumes less its voids (once mass over the body's density, which made the hammer's
/// volume its mass). Splitting a mesh into parts keeps it.
#[test]
fn the_lab_shows_the_volume_props_gives_every_sample() {
    use inertia_lab::lab::samples::{SAMPLE_BODIES, SAMPLES};
    use inertia_lab::lab::settings::AppSettings;
    use inertia_lab::lab::{Command, Lab};

    let mut lab = Lab::new(AppSettings::default()).expect("lab");
    let meshes = SAMPLES.iter().map(|&(label, file, _)| (label, file, false));
    let bodies = SAMPLE_BODIES
        .iter()
        .map(|&(label, file, _)| (label, file, true));
    for (label, file, parts) in meshes.chain(bodies) {
        let j = props_json(&[&format!("assets/{file}")]);
        let expected = if parts {
            j["parts"]
                .as_array()
                .expect("parts")
                .iter()
                .map(|p| f(&p["volume"]).copysign(f(&p["mass"])))
                .sum::<f64>()
        } else {
            f(&j["volume"])
        };
        lab.apply(Command::LoadSample(label.to_owned()));
        assert!(lab.message().is_none_or(|m| !m.error), "{label}");
        let shown = lab.primary().volume();
        assert!(
            close(shown, expected, 1e-9),
            "{label}: {shown} vs {expected}"
        );
        if !parts {
            lab.apply(Command::SplitIntoParts);
            assert!(lab.message().is_none_or(|m| !m.error), "{label}");
            let split = lab.primary().volume();
            assert!(
                close(split, expected, 1e-9),
                "{label} split: {split} vs {expected}"
            );
        }
    }
}

/// A COLLADA file of two nodes (a 1 m cube "head" and a 0.2 × 0.2 × 2 m "handle", both the unit
/// cube placed by their nodes, in centimetres) is a body of two parts: `--density-of` gives each
/// its own, and the mass is the closed form's.
#[test]
fn the_parts_of_a_collada_file_take_their_own_densities() {
    let dae = r##"<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit meter="0.01"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="cube"><mesh>
    <source id="p"><float_array id="a" count="24">0 0 0 100 0 0 100 100 0 0 100 0 0 0 100 100 0 100 100 100 100 0 100 100</float_array>
      <technique_common><accessor source="#a" count="8" stride="3"/></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <polylist count="6"><input semantic="VERTEX" source="#v" offset="0"/>
      <vcount>4 4 4 4 4 4</vcount><p>0 3 2 1 4 5 6 7 0 1 5 4 1 2 6 5 2 3 7 6 3 0 4 7</p></polylist>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s">
    <node id="head" name="head"><translate>0 0 200</translate><instance_geometry url="#cube"/></node>
    <node id="handle" name="handle"><scale>0.2 0.2 2</scale><instance_geometry url="#cube"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>"##;
    let file = TempFile::new("hammer.dae", dae.as_bytes());
    let j = props_json(&[
        file.path(),
        "--density-of",
        "head=7800",
        "--density-of",
        "handle=600",
    ]);
    let mass = 7800.0 * 1.0 + 600.0 * 0.08;
    assert!(close(f(&j["mass"]), mass, 1e-13), "{}", j["mass"]);
    // The head's centre is 2.5 m up, the handle's 1 m: the centre of mass between them.
    let z = (7800.0 * 2.5 + 48.0 * 1.0) / mass;
    assert!(
        close(f(&j["center_of_mass"][2]), z, 1e-13),
        "{}",
        j["center_of_mass"]
    );
    let parts = j["parts"].as_array().expect("parts");
    let names: Vec<&str> = parts.iter().filter_map(|p| p["name"].as_str()).collect();
    assert_eq!(names, ["head", "handle"]);
}
