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
    assert_eq!(j["schema_version"], 2);
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
    assert_eq!(j["warnings"][0]["code"], "open_mesh");
    assert_eq!(j["warnings"][0]["boundary_edges"], 4);
    assert!(
        j["warnings"][0]["message"]
            .as_str()
            .is_some_and(|w| w.contains("open"))
    );

    // The same cube closed but wound inwards: same numbers, flipped and a warning.
    let inward = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 2 3 4\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\nf 5 8 7 6\n";
    let file = TempFile::new("inward.obj", inward);
    let j = props_json(&[file.path()]);
    assert_eq!(j["mesh"]["flipped"], true);
    assert!(close(f(&j["volume"]), 1.0, 1e-15));
    assert!(close(f(&j["inertia_com"][0][0]), 1.0 / 6.0, 1e-14));
}

#[test]
fn committed_assets_match_their_generator() {
    for (name, comment, mesh) in massprops::shapes::samples() {
        let committed = std::fs::read_to_string(root().join(format!("assets/{name}.obj")))
            .expect("asset present");
        assert_eq!(
            committed,
            massprops::shapes::to_obj(name, comment, &mesh),
            "assets/{name}.obj is stale: run `cargo run -p massprops --example generate_assets`"
        );
    }
}
