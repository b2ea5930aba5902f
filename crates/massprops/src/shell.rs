//! The shell method: a thin wall of uniform surface density σ (kg/m²) on every face, for open
//! meshes and sheets (a sail, a hull plate, a lamp shade).
//!
//! Each face is fan-triangulated from its first corner; fan triangles are weighted by their area
//! signed against the face's Newell normal, which integrates any simple planar polygon exactly,
//! convex or not. Over a triangle with corners a, b, c and area A (e.g. Eberly 2002, §3):
//! ∫dA = A, ∫r dA = A(a+b+c)/3, ∫r rᵀ dA = A/12·(aaᵀ + bbᵀ + ccᵀ + ssᵀ), s = a + b + c.

use nalgebra::{Matrix3, Vector3};

use crate::integrals::{CompensatedSum, mirtich::newell_normal};
use crate::properties::{MassProperties, parallel_axis_term, positive};
use crate::{MeshError, PolyMesh};

/// Mass properties of a shell of surface density `surface_density` on every face of `mesh`,
/// and its area.
pub fn shell_properties(
    mesh: &PolyMesh,
    surface_density: f64,
) -> Result<(MassProperties, f64), MeshError> {
    let sigma = positive("surface density", surface_density)?;
    let reference = mesh.reference_point();
    let mut sums = CompensatedSum::<10>::new();
    let mut corners = Vec::new();
    for f in 0..mesh.face_count() {
        corners.clear();
        corners.extend(mesh.face_points(f).map(|p| p - reference));
        let newell = newell_normal(&corners);
        let len = newell.norm();
        if len == 0.0 {
            continue;
        }
        let n = newell / len;
        let a = corners[0];
        for w in corners[1..].windows(2) {
            let (b, c) = (w[0], w[1]);
            let area = 0.5 * (b - a).cross(&(c - a)).dot(&n);
            let s = a + b + c;
            let outer = |v: &Vector3<f64>| v * v.transpose();
            let m = (outer(&a) + outer(&b) + outer(&c) + outer(&s)) * (area / 12.0);
            sums.add(&[
                area,
                area * s.x / 3.0,
                area * s.y / 3.0,
                area * s.z / 3.0,
                m[(0, 0)],
                m[(1, 1)],
                m[(2, 2)],
                m[(0, 1)],
                m[(1, 2)],
                m[(2, 0)],
            ]);
        }
    }
    let v = sums.total();
    let area = v[0];
    if area.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Err(MeshError::ZeroArea);
    }
    let mass = sigma * area;
    let com_local = Vector3::new(v[1], v[2], v[3]) / area;
    let second = Matrix3::new(v[4], v[7], v[9], v[7], v[5], v[8], v[9], v[8], v[6]) * sigma;
    let about_reference = Matrix3::identity() * second.trace() - second;
    let inertia = about_reference - parallel_axis_term(mass, &com_local);
    Ok((
        MassProperties::new(mass, reference + com_local, inertia),
        area,
    ))
}
