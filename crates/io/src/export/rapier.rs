//! `rapier`: a Rust snippet building rapier's `MassProperties`, for rapier3d and bevy_rapier3d.
//!
//! rapier3d 0.36 (parry3d 0.31, glam types through `rapier3d::math`)
//! `MassProperties::with_principal_inertia_frame(local_com: Vector, mass: Real, principal_inertia:
//! AngVector, principal_inertia_local_frame: Rotation)`: "the center-of-mass is specified in the
//! local-space of the rigid-body", the principal inertia is along the axes of
//! `principal_inertia_local_frame`, a unit quaternion rotating principal-axes coordinates into the
//! body's local space. `Vector`/`AngVector` are glam's `Vec3` (`DVec3` in rapier3d-f64) and
//! `Rotation` is glam's `Quat` (`DQuat`), so `Rotation::from_xyzw(x, y, z, w)` is scalar last.
//! bevy_rapier3d's `MassProperties` has the same four fields as glam types (`Vec3`,
//! `Quat::from_xyzw(x, y, z, w)`). rapier has no fixed up axis; Bevy is right-handed +Y up, so
//! that is the target here. Units m, kg, kg·m². tests/export_roundtrip/fragments.rs builds the rapier3d-f64
//! value with this constructor and reads back rapier's own mass, centre of mass and tensor.

use super::frames::{Converted, num};

/// The Rust snippet.
pub fn render(body: &Converted) -> String {
    let c = &body.center_of_mass;
    let m = &body.moments;
    let [w, x, y, z] = body.principal_quaternion();
    let (cx, cy, cz) = (num(c.x), num(c.y), num(c.z));
    let (mx, my, mz) = (num(m.x), num(m.y), num(m.z));
    let (qw, qx, qy, qz) = (num(w), num(x), num(y), num(z));
    let mass = num(body.mass);
    format!(
        "// {}\n\
         // rapier / bevy_rapier3d: lengths m, mass kg, inertia kg*m^2; local_com in body space;\n\
         // principal_inertia along the axes of the rotation principal frame -> body frame.\n\
         // rapier3d 0.36 (glam types; with rapier3d-f64, write rapier3d_f64 for rapier3d):\n\
         let rapier_mass = rapier3d::dynamics::MassProperties::with_principal_inertia_frame(\n\
         \x20   rapier3d::math::Vector::new({cx}, {cy}, {cz}),\n\
         \x20   {mass},\n\
         \x20   rapier3d::math::AngVector::new({mx}, {my}, {mz}),\n\
         \x20   rapier3d::math::Rotation::from_xyzw({qx}, {qy}, {qz}, {qw}),\n\
         );\n\
         // bevy_rapier3d (glam types), e.g. in ColliderMassProperties::MassProperties(..):\n\
         let bevy_mass = bevy_rapier3d::prelude::MassProperties {{\n\
         \x20   local_center_of_mass: Vec3::new({cx}, {cy}, {cz}),\n\
         \x20   mass: {mass},\n\
         \x20   principal_inertia_local_frame: Quat::from_xyzw({qx}, {qy}, {qz}, {qw}),\n\
         \x20   principal_inertia: Vec3::new({mx}, {my}, {mz}),\n\
         }};\n",
        super::provenance(body),
    )
}
