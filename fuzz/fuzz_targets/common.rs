//! What the targets do: with a parsed mesh, every method at a density and at a mass, with the
//! default repairs, with exact welding and with holes refused. Any panic is a bug; errors are
//! the expected answer to bad input.

use std::path::Path;

use massprops::defects::{Holes, Weld};
use massprops::{BodyFile, MassSpec, MeshFile, Method, Repairs};

pub fn analyze_every_way(file: &MeshFile) {
    let quick = Repairs {
        // The comparison of shells has a budget of its own; a short one keeps runs fast.
        overlap_budget: 10_000_000,
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

/// Body-file text that parses must be written back as text that parses to the same parts.
pub fn body_round_trip(text: &str) {
    let Ok(body) = BodyFile::parse(text, Path::new("fuzz.toml")) else {
        return;
    };
    let again = BodyFile::parse(&body.to_toml(), Path::new("fuzz.toml"))
        .unwrap_or_else(|e| panic!("written text reads back: {e}\n{}", body.to_toml()));
    assert_eq!(again.parts.len(), body.parts.len());
    for (a, b) in again.parts.iter().zip(&body.parts) {
        assert_eq!((&a.name, &a.mesh, &a.object), (&b.name, &b.mesh, &b.object));
        assert_eq!(
            (&a.material, a.void, a.thin_wall),
            (&b.material, b.void, b.thin_wall)
        );
        assert_eq!((a.rotation, a.translation), (b.rotation, b.translation));
    }
}
