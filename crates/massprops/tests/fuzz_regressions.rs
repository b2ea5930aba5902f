//! Inputs the fuzz targets (`fuzz/`) found to crash, replayed the way the targets run them:
//! every method, mass given and density given, with default, exact and coarse welding. Each
//! must give a result or an error, never a panic.

use std::path::Path;
use std::time::Duration;

use massprops::{Holes, MassSpec, MeshError, Method, Repairs, Weld, parse_mesh};

fn every_way(path: &Path) {
    let bytes = std::fs::read(path).expect("readable");
    let Ok(file) = parse_mesh(&bytes, path) else {
        return;
    };
    let quick = Repairs {
        overlap_budget: Duration::from_millis(20),
        ..Repairs::default()
    };
    let variants = [
        quick,
        Repairs {
            weld: Weld::Exact,
            ..quick
        },
        Repairs {
            holes: Holes::Refuse,
            weld: Weld::Distance(0.5),
            ..quick
        },
    ];
    for method in [
        Method::Volume,
        Method::Shell,
        Method::Points,
        Method::BoundingBox,
    ] {
        for spec in [MassSpec::Density(1000.0), MassSpec::Mass(2.5)] {
            for repairs in &variants {
                let _ = file.analyze(method, spec, repairs);
            }
        }
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
