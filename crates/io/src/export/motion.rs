//! A body's motion as a file plays it back: the node transform (mesh coordinates → world) at
//! evenly spaced times, which the `glb` (animation channels) and `usd` (time samples) writers
//! turn into the format's axes and unit.
//!
//! World is the mesh's own frame: axes as the mesh's, lengths in its unit, so that frame 0 of a
//! body simulated from rest in its file's placement is the identity. A mesh point `p` is at
//! `R(t)·p + t(t)` with `R` the body's orientation and `t = x(t) − R(t)·c`, `x` the centre of mass
//! in world and `c` in the mesh. In a target whose axes are `A·mesh` the node turns by
//! `A·R·Aᵀ` and moves by `A·t` (scaled to the target's unit).

use std::path::Path;

use massprops::MassProperties;
use nalgebra::{Isometry3, Matrix3, Point3, Rotation3, Translation3, UnitQuaternion, Vector3};

use super::frames::Converted;
use super::surface::Surface;

/// A body known only by its mass and principal moments, shown as the box that has them about its
/// axes (sides from I₁ = m(b² + c²)/12 and the two like it), centred at the origin: its mass
/// properties and surface.
pub fn principal_box(mass: f64, moments: &Vector3<f64>) -> (MassProperties, Surface) {
    let i = moments;
    let side = |a: f64, b: f64, c: f64| (6.0 * (b + c - a) / mass).max(0.0).sqrt();
    let size = Vector3::new(
        side(i.x, i.y, i.z),
        side(i.y, i.z, i.x),
        side(i.z, i.x, i.y),
    );
    let mesh = massprops::shapes::cuboid(size, Point3::origin()).build();
    (
        MassProperties::new(mass, Point3::origin(), Matrix3::from_diagonal(i)),
        Surface::of_mesh(&mesh, Path::new("box")),
    )
}

/// The node transform at each keyframe.
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    /// Frames a second: keyframe k is at time k / fps.
    pub fps: f64,
    /// The mesh's coordinates → world at each frame (world: the mesh's axes and unit).
    pub frames: Vec<Isometry3<f64>>,
}

impl Motion {
    /// The motion of a body whose centre of mass is `center_of_mass` in its mesh, from its
    /// centre of mass in world and its orientation (mesh axes → world) at each frame.
    pub fn from_poses(
        fps: f64,
        center_of_mass: &Point3<f64>,
        poses: impl IntoIterator<Item = (Point3<f64>, UnitQuaternion<f64>)>,
    ) -> Self {
        let frames = poses
            .into_iter()
            .map(|(x, r)| {
                Isometry3::from_parts(Translation3::from(x.coords - r * center_of_mass.coords), r)
            })
            .collect();
        Self { fps, frames }
    }

    /// Each frame's rotation and translation in `body`'s target axes and unit. `body.map` must
    /// be a proper rotation (the right-handed targets): the turn is conjugated as a quaternion,
    /// so consecutive frames keep the hemisphere they had.
    pub(crate) fn in_target(&self, body: &Converted) -> Vec<(UnitQuaternion<f64>, Vector3<f64>)> {
        let s = body.conversion.source_unit.metres() / body.conversion.target_unit.metres();
        let a = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(body.map));
        self.frames
            .iter()
            .map(|f| {
                (
                    a * f.rotation * a.inverse(),
                    body.map * f.translation.vector * s,
                )
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::frames::{Axes, Conversion, convert};
    use crate::export::{LengthUnit, UpAxis};
    use massprops::MassProperties;
    use nalgebra::Matrix3;

    fn converted(source_unit: LengthUnit, source_up: UpAxis, target: Axes) -> Converted {
        let props = MassProperties::new(
            2.0,
            Point3::new(0.1, 0.2, 0.3),
            Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
        );
        let conversion = Conversion {
            source_unit,
            source_up,
            target,
            target_unit: LengthUnit::M,
        };
        convert(&props, conversion).expect("physical")
    }

    /// The box's own mass properties, integrated from its surface, are the moments it stands
    /// for.
    #[test]
    fn the_principal_box_has_the_moments() {
        let moments = Vector3::new(0.5, 2.0, 2.25);
        let (stated, surface) = principal_box(3.0, &moments);
        let faces: Vec<Vec<usize>> = surface
            .triangles
            .iter()
            .map(|t| t.iter().map(|&i| i as usize).collect())
            .collect();
        let mesh = massprops::PolyMesh::new(surface.points.clone(), &faces).expect("a mesh");
        let volume = massprops::mass_properties(&mesh, 1.0).expect("closed").mass;
        let weighed = massprops::mass_properties(&mesh, 3.0 / volume).expect("closed");
        assert!((weighed.inertia_com - stated.inertia_com).amax() < 1e-14);
        assert!(weighed.center_of_mass.coords.norm() < 1e-15);
    }

    /// A frame's node transform puts the centre of mass where the pose says and turns the mesh
    /// about it.
    #[test]
    fn a_pose_moves_the_centre_of_mass_to_its_position() {
        let c = Point3::new(1.0, 2.0, 3.0);
        let r = UnitQuaternion::from_euler_angles(0.3, -0.2, 1.1);
        let x = Point3::new(-4.0, 0.5, 7.0);
        let motion = Motion::from_poses(24.0, &c, [(x, r)]);
        let f = motion.frames[0];
        assert!((f * c - x).norm() < 1e-14);
        let p = Point3::new(2.0, -1.0, 0.0);
        assert!((f * p - (x + r * (p - c))).norm() < 1e-14);
    }

    /// A Z-up mesh turning about its up axis turns about glTF's up axis (+Y) in the target, its
    /// translation mapped and scaled from millimetres to metres; in USD (+Z up) it stays about z.
    #[test]
    fn a_turn_about_up_stays_a_turn_about_up_in_the_target() {
        let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.8);
        let motion = Motion {
            fps: 30.0,
            frames: vec![Isometry3::from_parts(
                Translation3::new(10.0, 20.0, 30.0),
                turn,
            )],
        };
        let gltf = motion.in_target(&converted(LengthUnit::Mm, UpAxis::Z, Axes::RightYUp));
        let (q, t) = gltf[0];
        let (axis, angle) = q.axis_angle().expect("a turn");
        assert!(
            (angle - 0.8).abs() < 1e-14 && (axis.y - 1.0).abs() < 1e-14,
            "{q:?}"
        );
        assert!((t - Vector3::new(0.01, 0.03, -0.02)).norm() < 1e-15, "{t}");
        let usd = motion.in_target(&converted(LengthUnit::Mm, UpAxis::Z, Axes::RightZUp));
        assert!(usd[0].0.angle_to(&turn) < 1e-14);
    }
}
