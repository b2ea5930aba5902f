//! Real meshes (`tests/data/real`, see its README): no false alarm on a clean one, and on two
//! overlapping convex pieces the overlap estimate agrees with an independent Monte Carlo count.

use crate::common;

use std::path::{Path, PathBuf};

use common::assert_rel;
use massprops::defects::Orientation;
use massprops::{Defect, MassSpec, Method, load_mesh};
use nalgebra::{Point3, Vector3};

fn real(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/real")
        .join(name)
}

#[test]
fn a_clean_robot_link_raises_nothing() {
    let file = load_mesh(&real("ur10e_wrist3_collision.stl")).expect("reads");
    let a = file
        .analyze(
            Method::Volume,
            MassSpec::Density(7850.0),
            &Default::default(),
        )
        .expect("closed");
    assert!(a.warnings.is_empty(), "{:?}", a.warnings);
    assert_eq!(a.shells.len(), 1);
    assert!(a.shells[0].closed && a.shells[0].orientation == Orientation::Outward);
    assert_eq!(a.shells[0].depth, Some(0));
}

#[test]
fn overlapping_pieces_agree_with_a_monte_carlo_count_along_another_axis() {
    let file = load_mesh(&real("ur3_wrist3_collision.stl")).expect("reads");
    let a = file
        .analyze(Method::Volume, MassSpec::Density(1.0), &Default::default())
        .expect("closed");
    assert_eq!(a.shells.len(), 2);
    assert!(a.shells.iter().all(|s| s.closed && s.depth == Some(0)));
    // The result is the sum of the two pieces.
    let sum: f64 = a.shells.iter().map(|s| s.volume).sum();
    assert_rel(a.properties.mass, sum, 1e-12, "the sum");
    let w = &a.warnings[0];
    let Defect::OverlappingShells {
        volume,
        uncertainty,
        ..
    } = w.defect
    else {
        panic!("{:?}", a.warnings)
    };
    assert_rel(
        w.effect_on_mass.expect("known"),
        volume / sum,
        1e-12,
        "effect",
    );

    // Independently: points drawn uniformly in the pieces' common box, each tested against both
    // pieces by the parity of crossings along a ray close to +x (the estimate used +z lines).
    let mesh = &file.mesh;
    let pieces = [0..a.shells[0].faces, a.shells[0].faces..mesh.face_count()];
    let triangles: Vec<Vec<[Point3<f64>; 3]>> = pieces
        .iter()
        .map(|range| {
            range
                .clone()
                .map(|f| {
                    let p: Vec<Point3<f64>> = mesh.face_points(f).collect();
                    [p[0], p[1], p[2]]
                })
                .collect()
        })
        .collect();
    let bounds = |t: &[[Point3<f64>; 3]]| {
        let mut lo = Point3::from([f64::INFINITY; 3]);
        let mut hi = Point3::from([f64::NEG_INFINITY; 3]);
        for p in t.iter().flatten() {
            lo = lo.inf(p);
            hi = hi.sup(p);
        }
        (lo, hi)
    };
    let ((lo0, hi0), (lo1, hi1)) = (bounds(&triangles[0]), bounds(&triangles[1]));
    let (lo, hi) = (lo0.sup(&lo1), hi0.inf(&hi1));
    let direction = Vector3::new(1.0, 0.0123, 0.0071).normalize();
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut unit = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let samples = 20_000;
    let mut both = 0usize;
    for _ in 0..samples {
        let p = Point3::new(
            lo.x + unit() * (hi.x - lo.x),
            lo.y + unit() * (hi.y - lo.y),
            lo.z + unit() * (hi.z - lo.z),
        );
        if triangles.iter().all(|t| inside(t, p, direction)) {
            both += 1;
        }
    }
    let box_volume = (hi - lo).product();
    let fraction = both as f64 / samples as f64;
    let mc = fraction * box_volume;
    let mc_error = (fraction * (1.0 - fraction) / samples as f64).sqrt() * box_volume;
    let spread = 4.0 * (mc_error.powi(2) + uncertainty.powi(2)).sqrt();
    assert!(both > 100, "{both}");
    assert!(
        (volume - mc).abs() < spread,
        "rays {volume} ± {uncertainty}, Monte Carlo {mc} ± {mc_error}"
    );
}

/// Whether `p` is inside the closed triangles, by the parity of crossings along `d`
/// (Möller–Trumbore).
fn inside(triangles: &[[Point3<f64>; 3]], p: Point3<f64>, d: Vector3<f64>) -> bool {
    let mut crossings = 0;
    for [a, b, c] in triangles {
        let (e1, e2) = (b - a, c - a);
        let h = d.cross(&e2);
        let det = e1.dot(&h);
        if det.abs() < 1e-300 {
            continue;
        }
        let s = p - a;
        let u = s.dot(&h) / det;
        let q = s.cross(&e1);
        let v = d.dot(&q) / det;
        let t = e2.dot(&q) / det;
        if (0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0 && t > 0.0 {
            crossings += 1;
        }
    }
    crossings % 2 == 1
}
