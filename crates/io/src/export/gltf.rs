//! `gltf`: a glTF node fragment with the `KHR_physics_rigid_bodies` motion.
//!
//! Khronos `KHR_physics_rigid_bodies` (draft): `motion.mass` in kg, `centerOfMass` "in node
//! space", `inertiaDiagonal` "the principal moments of inertia" in kg·m², `inertiaOrientation`
//! "the quaternion rotating from inertia major axis space to node space"; "the 3x3 inertia
//! tensor can be calculated as the product of the inertiaOrientation (in matrix form) and the
//! matrix whose diagonal is inertiaDiagonal" (R·D·Rᵀ). glTF quaternions are `[x, y, z, w]`;
//! glTF is right-handed, +Y up, metres (glTF 2.0 §3.4). JSON has no comments, so the
//! conventions go in the node's `extras`. The file must also list the extension in
//! `extensionsUsed`.

use serde_json::{Value, json};

use super::frames::Converted;

/// The node fragment.
pub fn render(body: &Converted) -> String {
    format!("{:#}\n", node(body))
}

/// The node with its motion and, in `extras`, the conventions (also the `glb` file's node).
pub fn node(body: &Converted) -> Value {
    let c = &body.center_of_mass;
    let m = &body.moments;
    let [w, x, y, z] = body.principal_quaternion();
    json!({
        "extras": {
            "inertia_lab_conventions": format!(
                "{} KHR_physics_rigid_bodies motion: mass kg, centerOfMass m in node space, \
                 inertiaDiagonal = principal moments kg*m^2 about the centre of mass, \
                 inertiaOrientation = [x, y, z, w] rotating inertia axes to node space \
                 (tensor = R diag R^T). Add \"KHR_physics_rigid_bodies\" to extensionsUsed.",
                super::provenance(body)
            ),
        },
        "extensions": {
            "KHR_physics_rigid_bodies": {
                "motion": {
                    "mass": body.mass,
                    "centerOfMass": [c.x, c.y, c.z],
                    "inertiaDiagonal": [m.x, m.y, m.z],
                    "inertiaOrientation": [x, y, z, w],
                }
            }
        }
    })
}
