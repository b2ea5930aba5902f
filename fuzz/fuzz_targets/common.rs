//! What both targets do with a parsed mesh: every method at a density and at a mass, with the
//! default repairs, with exact welding and with holes refused. Any panic is a bug; errors are
//! the expected answer to bad input.

use std::time::Duration;

use massprops::{Holes, MassSpec, MeshFile, Method, Repairs, Weld};

pub fn analyze_every_way(file: &MeshFile) {
    let quick = Repairs {
        // The comparison of shells has a budget of its own; a short one keeps runs fast.
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
                if let Ok(a) = file.analyze(method, spec, repairs) {
                    check(&a);
                }
            }
        }
    }
}

/// What every successful analysis promises.
fn check(a: &massprops::Analysis) {
    let p = &a.properties;
    assert!(p.mass.is_finite() && p.mass > 0.0, "mass {}", p.mass);
    assert!(p.center_of_mass.coords.iter().all(|c| c.is_finite()));
    assert!(p.inertia_com.iter().all(|c| c.is_finite()));
    for w in &a.warnings {
        assert!(w.faces.len() <= 5, "{w:?}");
        assert!(
            w.faces.iter().all(|&f| f < a.diagnostics.faces),
            "{w:?} names a face past {}",
            a.diagnostics.faces
        );
        if let Some(e) = w.effect_on_mass {
            assert!(!e.is_nan(), "{w:?}");
        }
    }
}
