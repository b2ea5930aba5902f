//! Inputs the fuzz targets (`fuzz/`) found to crash, replayed by the targets' own code: every
//! method, mass given and density given, with default, exact and coarse welding. Each must give
//! a result or an error, never a panic, and every result must be a body.

use std::path::Path;

use massprops::{MassSpec, MeshError, Method, Repairs, parse_mesh};

use massprops::defects::Weld;

/// What the fuzz targets do with an input, shared with them.
#[path = "../../../fuzz/fuzz_targets/common.rs"]
mod targets;

fn every_way(path: &Path) {
    let bytes = std::fs::read(path).expect("readable");
    if path.extension().is_some_and(|e| e == "toml") {
        targets::body_round_trip(std::str::from_utf8(&bytes).expect("text"));
    } else if let Ok(file) = parse_mesh(&bytes, path) {
        targets::analyze_every_way(&file);
    }
}

#[test]
fn crashes_found_by_fuzzing_stay_fixed() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/fuzz");
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).expect("the regression inputs") {
        every_way(&entry.expect("entry").path());
        n += 1;
    }
    assert!(n > 0);
}

#[test]
fn a_weld_wider_than_the_mesh_is_an_error_not_a_panic() {
    // An open triangle fan 0.1 across, welded at 0.5: every face collapses.
    let text = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 2 3\nf 1 3 4\n";
    let file = parse_mesh(text.as_bytes(), Path::new("tiny.obj")).expect("parses");
    let coarse = Repairs {
        weld: Weld::Distance(0.5),
        ..Repairs::default()
    };
    let e = file
        .analyze(Method::Volume, MassSpec::Density(1.0), &coarse)
        .expect_err("nothing left");
    assert!(matches!(e, MeshError::ZeroVolume { .. }), "{e:?}");
    assert!(e.to_string().contains("collapses every face"), "{e}");
}
