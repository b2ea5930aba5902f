//! The two approximations the tool teaches with, each given the body's mass:
//! - point masses: every vertex carries m/N (what a particle system or a naive script computes);
//! - the bounding-box cuboid: I = m/12·diag(b²+c², a²+c², a²+b²) about the box centre, mesh axes
//!   (what Bullet's `btBoxShape`, Blender and older Godot use by default).
//!
//! And the other way round: the uniform box or ellipsoid that has a body's mass and principal
//! moments ([`equivalent_half_extents`]), which the app draws beside the mesh.

use nalgebra::{Matrix3, Point3, Vector3};

use crate::integrals::CompensatedSum;
use crate::properties::{MassProperties, parallel_axis_term, positive};
use crate::{MeshError, PolyMesh};

/// Mass properties of `mass` split equally over the vertices the faces use.
pub fn point_mass_properties(mesh: &PolyMesh, mass: f64) -> Result<MassProperties, MeshError> {
    let mass = positive("mass", mass)?;
    let (lo, hi) = mesh.bounding_box();
    let reference = Point3::from(lo.coords * 0.5 + hi.coords * 0.5);
    let mut sums = CompensatedSum::<9>::new();
    let mut count = 0usize;
    for p in mesh.used_positions() {
        let d = p - reference;
        sums.add(&[
            d.x,
            d.y,
            d.z,
            d.x * d.x,
            d.y * d.y,
            d.z * d.z,
            d.x * d.y,
            d.y * d.z,
            d.z * d.x,
        ]);
        count += 1;
    }
    let s = sums.total();
    let n = count as f64;
    let mean = Vector3::new(s[0], s[1], s[2]) / n;
    let second = Matrix3::new(s[3], s[6], s[8], s[6], s[4], s[7], s[8], s[7], s[5]) * (mass / n);
    let about_reference = Matrix3::identity() * second.trace() - second;
    let inertia = about_reference - parallel_axis_term(mass, &mean);
    Ok(MassProperties::new(mass, reference + mean, inertia))
}

/// Mass properties of a solid cuboid filling the mesh's axis-aligned bounding box, with `mass`.
pub fn bounding_box_properties(mesh: &PolyMesh, mass: f64) -> Result<MassProperties, MeshError> {
    let mass = positive("mass", mass)?;
    let (lo, hi) = mesh.bounding_box();
    let e = hi - lo;
    let (a2, b2, c2) = (e.x * e.x, e.y * e.y, e.z * e.z);
    let inertia = Matrix3::from_diagonal(&Vector3::new(b2 + c2, a2 + c2, a2 + b2)) * (mass / 12.0);
    Ok(MassProperties::new(
        mass,
        Point3::from(lo.coords * 0.5 + hi.coords * 0.5),
        inertia,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_of_a_square_and_box_of_a_tetrahedron() {
        let pts = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(0.0, 4.0, 0.0),
            Point3::new(0.0, 0.0, 6.0),
        ];
        let tet = PolyMesh::new(pts, &[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]).expect("valid");
        let p = point_mass_properties(&tet, 4.0).expect("valid");
        assert_eq!(p.center_of_mass, Point3::new(0.5, 1.0, 1.5));
        // Σ m_i x_i² about the centre: 1·(0.25·3 + 2.25) = 3, y: 1·(1·3 + 9) = 12, z: 27.
        let expected = Matrix3::new(39.0, 2.0, 3.0, 2.0, 30.0, 6.0, 3.0, 6.0, 15.0);
        assert!(
            (p.inertia_com - expected).amax() < 1e-13,
            "{}",
            p.inertia_com
        );
        let b = bounding_box_properties(&tet, 12.0).expect("valid");
        assert_eq!(b.center_of_mass, Point3::new(1.0, 2.0, 3.0));
        assert_eq!(
            b.inertia_com,
            Matrix3::from_diagonal(&Vector3::new(52.0, 40.0, 20.0))
        );
    }
}

/// A simple uniform shape that can stand for a body with the same mass and principal moments.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EquivalentShape {
    /// A box: I₁ = m(b² + c²)/3 for half-extents a, b, c.
    Box,
    /// An ellipsoid: I₁ = m(b² + c²)/5 for semi-axes a, b, c.
    Ellipsoid,
}

/// The half-extents (a box) or semi-axes (an ellipsoid), along the principal axes, of the uniform
/// `shape` with mass `mass` and principal `moments`. Solving I₁ = m(b² + c²)/q and its turns
/// gives a² = q(I₂ + I₃ − I₁)/(2m), with q = 3 for a box and 5 for an ellipsoid; an axis where the
/// moments break the triangle inequality (no body has them) gets 0.
pub fn equivalent_half_extents(
    shape: EquivalentShape,
    mass: f64,
    moments: &Vector3<f64>,
) -> Vector3<f64> {
    let q = match shape {
        EquivalentShape::Box => 3.0,
        EquivalentShape::Ellipsoid => 5.0,
    };
    Vector3::from_fn(|a, _| {
        let (j, l) = ((a + 1) % 3, (a + 2) % 3);
        (q * (moments[j] + moments[l] - moments[a]) / (2.0 * mass))
            .max(0.0)
            .sqrt()
    })
}

#[cfg(test)]
mod equivalent_tests {
    use super::*;

    /// The equivalent of a box (an ellipsoid) is that box (ellipsoid): its moments from the
    /// closed forms give back its half-extents (semi-axes).
    #[test]
    fn the_equivalent_of_a_shape_is_that_shape() {
        let (m, [a, b, c]) = (6.0, [1.0, 2.0, 3.0]);
        for (shape, q) in [
            (EquivalentShape::Box, 3.0),
            (EquivalentShape::Ellipsoid, 5.0),
        ] {
            let moments = Vector3::new(
                m * (b * b + c * c) / q,
                m * (a * a + c * c) / q,
                m * (a * a + b * b) / q,
            );
            let half = equivalent_half_extents(shape, m, &moments);
            assert!(
                (half - Vector3::new(a, b, c)).norm() < 1e-14,
                "{shape:?}: {half}"
            );
        }
        // Moments no body has (I₁ > I₂ + I₃) leave that axis at 0, not NaN.
        let bad = equivalent_half_extents(EquivalentShape::Box, 1.0, &Vector3::new(5.0, 1.0, 1.0));
        assert_eq!(bad[0], 0.0);
        assert!(bad.iter().all(|x| x.is_finite()));
    }
}
