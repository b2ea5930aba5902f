//! `rapier`: a Rust snippet building rapier's `MassProperties`, for rapier3d and bevy_rapier3d.
//!
//! rapier `MassProperties::with_principal_inertia_frame(local_com, mass, principal_inertia,
//! principal_inertia_local_frame)`: "the center-of-mass is specified in the local-space of the
//! rigid-body", the principal inertia is along the axes of `principal_inertia_local_frame`, a
//! unit quaternion rotating principal-axes coordinates into the body's local space; nalgebra's
//! `Quaternion::new(w, i, j, k)` is scalar first. bevy_rapier3d's `MassProperties` has the same
//! four fields as glam types (`Vec3`, `Quat::from_xyzw(x, y, z, w)`). rapier has no fixed up
//! axis; Bevy is right-handed +Y up, so that is the target here. Units m, kg, kg·m².

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
         // rapier3d (nalgebra types; rapier3d-f64 for f64):\n\
         let rapier_mass = rapier3d::dynamics::MassProperties::with_principal_inertia_frame(\n\
         \x20   nalgebra::point![{cx}, {cy}, {cz}],\n\
         \x20   {mass},\n\
         \x20   nalgebra::vector![{mx}, {my}, {mz}],\n\
         \x20   nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new({qw}, {qx}, {qy}, {qz})),\n\
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
