//! Where a specimen's mesh is in the world: the one mesh → world transform, used by rendering
//! (as a matrix), picking (its inverse) and every overlay (points and vectors), so that what is
//! drawn and what is picked cannot disagree.
//!
//! `x_world = R (s·x_mesh − c) + r`: the mesh is scaled by `s` about its origin, shifted so that
//! the centre of mass `c` (in scaled mesh coordinates, of the inertia source in use) is at the
//! body's origin, turned by the body's mesh-frame orientation `R` and placed at its position `r`.

use nalgebra::{Matrix4, Point3, UnitQuaternion, Vector3};

/// The mesh → world transform of one specimen at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Uniform scale `s` of the mesh.
    pub scale: f64,
    /// Centre of mass `c` in scaled mesh coordinates.
    pub center: Point3<f64>,
    /// Mesh frame → world, `R` (rbcore's `Body::body_orientation`).
    pub rotation: UnitQuaternion<f64>,
    /// World position `r` of the centre of mass.
    pub position: Point3<f64>,
}

impl Placement {
    /// Mesh point → world.
    pub fn to_world(&self, x: &Point3<f64>) -> Point3<f64> {
        self.position + self.rotation * (x.coords * self.scale - self.center.coords)
    }

    /// World point → mesh coordinates (the inverse of [`Placement::to_world`]).
    pub fn to_mesh(&self, x: &Point3<f64>) -> Point3<f64> {
        let body = self.rotation.inverse_transform_vector(&(x - self.position));
        Point3::from((body + self.center.coords) / self.scale)
    }

    /// World vector → mesh coordinates (rotation and scale; a ray direction keeps its parameter).
    pub fn vector_to_mesh(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.rotation.inverse_transform_vector(v) / self.scale
    }

    /// The transform as a homogeneous matrix, for the renderer.
    pub fn matrix(&self) -> Matrix4<f64> {
        Matrix4::new_translation(&self.position.coords)
            * self.rotation.to_homogeneous()
            * Matrix4::new_translation(&(-self.center.coords))
            * Matrix4::new_scaling(self.scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn placement() -> Placement {
        Placement {
            scale: 2.5,
            center: Point3::new(0.3, -1.0, 2.0),
            rotation: UnitQuaternion::from_euler_angles(0.4, -0.9, 2.2),
            position: Point3::new(10.0, -3.0, 0.5),
        }
    }

    #[test]
    fn matrix_inverse_and_points_agree() {
        let p = placement();
        let m = p.matrix();
        for x in [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 2.0, -3.0),
            Point3::new(-7.5, 0.25, 4.0),
        ] {
            let w = p.to_world(&x);
            let h = m * x.to_homogeneous();
            let by_matrix = Point3::new(h.x, h.y, h.z) / h.w;
            assert!((by_matrix - w).norm() < 1e-12, "{by_matrix} {w}");
            assert!((p.to_mesh(&w) - x).norm() < 1e-12);
        }
        // The centre of mass lands on the body's position.
        let c = Point3::from(p.center.coords / p.scale);
        assert!((p.to_world(&c) - p.position).norm() < 1e-12);
    }

    #[test]
    fn a_mesh_ray_maps_to_the_same_points() {
        let p = placement();
        let (o, d) = (Point3::new(5.0, 5.0, 5.0), Vector3::new(-1.0, 0.5, 0.25));
        let (om, dm) = (p.to_mesh(&o), p.vector_to_mesh(&d));
        for t in [0.0, 0.7, 3.0] {
            assert!((p.to_world(&(om + dm * t)) - (o + d * t)).norm() < 1e-12);
        }
    }
}
