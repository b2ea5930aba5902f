//! What every real body satisfies, checked before a solid's mass properties are reported: a
//! positive mass, positive principal moments that obey the triangle inequality I₁ + I₂ ≥ I₃
//! (each moment is ∫(r² − x_k²)dm, so any two sum to ∫(r² + x_k²)dm ≥ the third), and a centre
//! of mass inside the convex hull of the body's points (it is their weighted mean). A result
//! that breaks one can only come from a defect counted as it is (overlapping or nested shells,
//! faces wound the wrong way, caps that make up a sheet's volume): it is refused, naming the law
//! and the defects found, never reported.
//!
//! The hull is judged by the 13 directions of a 26-sided discrete oriented polytope (the axes,
//! the face diagonals and the body diagonals of a cube): a polytope that contains the hull, so a
//! centre outside it is outside the hull (the converse check is not made).

use nalgebra::Vector3;

use crate::error::MeshError;
use crate::warning::{Defect, Warning};
use crate::{MassProperties, PolyMesh};

/// Relative slack for round-off: a thin plate has I₁ + I₂ = I₃ exactly, and summed integrals
/// carry a few ulps of the largest term.
const SLACK: f64 = 1e-9;

/// Refuses `p`, the solid `mesh` bounds, when it breaks a law of real bodies; `warnings` name
/// the defects that can cause it.
pub(crate) fn check(
    p: &MassProperties,
    mesh: &PolyMesh,
    warnings: &[Warning],
) -> Result<(), MeshError> {
    let m = p.principal.moments;
    let largest = m.amax();
    let broken = if p.mass.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        Some(format!("its mass is {:e}, not positive", p.mass))
    } else if m.iter().any(|&x| x < -SLACK * largest || !x.is_finite()) || largest <= 0.0 {
        Some(format!(
            "its principal moments {:e}, {:e}, {:e} are not all positive",
            m.x, m.y, m.z
        ))
    } else if m.x + m.y < m.z * (1.0 - SLACK) {
        Some(format!(
            "its principal moments break I1 + I2 >= I3 ({:e} + {:e} < {:e})",
            m.x, m.y, m.z
        ))
    } else {
        outside_hull(p, mesh)
    };
    match broken {
        None => Ok(()),
        Some(law) => Err(MeshError::Impossible {
            law,
            cause: cause(warnings),
        }),
    }
}

/// The 13 directions of a 26-DOP.
fn directions() -> [Vector3<f64>; 13] {
    [
        Vector3::new(1.0, 0.0, 0.0),
        Vector3::new(0.0, 1.0, 0.0),
        Vector3::new(0.0, 0.0, 1.0),
        Vector3::new(1.0, 1.0, 0.0),
        Vector3::new(1.0, -1.0, 0.0),
        Vector3::new(1.0, 0.0, 1.0),
        Vector3::new(1.0, 0.0, -1.0),
        Vector3::new(0.0, 1.0, 1.0),
        Vector3::new(0.0, 1.0, -1.0),
        Vector3::new(1.0, 1.0, 1.0),
        Vector3::new(1.0, 1.0, -1.0),
        Vector3::new(1.0, -1.0, 1.0),
        Vector3::new(-1.0, 1.0, 1.0),
    ]
}

/// Which way the centre of mass leaves the polytope of the mesh's points, if it does.
fn outside_hull(p: &MassProperties, mesh: &PolyMesh) -> Option<String> {
    let dirs = directions();
    let mut lo = [f64::INFINITY; 13];
    let mut hi = [f64::NEG_INFINITY; 13];
    for q in mesh.used_positions() {
        for (k, d) in dirs.iter().enumerate() {
            let s = d.dot(&q.coords);
            lo[k] = lo[k].min(s);
            hi[k] = hi[k].max(s);
        }
    }
    let (blo, bhi) = mesh.bounding_box();
    let slack = SLACK * (bhi - blo).norm() * 2.0;
    let c = p.center_of_mass;
    dirs.iter().enumerate().find_map(|(k, d)| {
        let s = d.dot(&c.coords);
        (s < lo[k] - slack || s > hi[k] + slack).then(|| {
            format!(
                "its centre of mass ({:e}, {:e}, {:e}) lies outside the hull of its own points",
                c.x, c.y, c.z
            )
        })
    })
}

/// The defects found that can make a solid's numbers impossible, in words, with what to do.
fn cause(warnings: &[Warning]) -> String {
    let mut causes = Vec::new();
    for w in warnings {
        let why = match &w.defect {
            Defect::OverlappingShells { .. } => {
                "closed shells that overlap, counted as they are (their common volume twice)"
            }
            Defect::NestedShell { .. } => "a shell wound outward inside another, counted twice",
            Defect::InconsistentWinding { .. } => {
                "faces wound the wrong way, counted as negative volume"
            }
            Defect::HolesCapped { .. } => {
                "holes capped by fans whose volume makes up the body (a sheet, a terrain): use \
                 the shell method"
            }
            Defect::NonmanifoldEdges { .. } => "shells touching along edges",
            _ => continue,
        };
        causes.push(why);
    }
    if causes.is_empty() {
        "no defect was found that explains it".to_owned()
    } else {
        format!("the mesh has {}", causes.join("; "))
    }
}
