//! `unreal`: a C++ snippet setting a body's mass properties through Unreal's physics interface.
//!
//! Unreal Engine is left-handed, +Z up, centimetres; its FBX/OBJ importer makes right-handed
//! files left-handed by negating y (`FFbxDataConverter::ConvertPos`), so the body is mirrored
//! in y here (frames.rs) after any Y-up → Z-up rotation, lengths are ×100 from metres and
//! inertia is in kg·cm². The editor only offers a mass override, a centre-of-mass *offset* and an
//! inertia *scale*, so the exact values go through `FPhysicsInterface` (Chaos):
//! `SetComLocalPose_AssumesLocked(actor, FTransform(rotation, com))` sets the mass frame (centre
//! of mass and principal axes, as PhysX's `cMassLocalPose`), `SetMassSpaceInertiaTensor_
//! AssumesLocked(actor, FVector)` the principal moments in that frame. `FQuat(X, Y, Z, W)`.

use super::frames::{Converted, num};

/// The C++ snippet.
pub fn render(body: &Converted) -> String {
    let c = &body.center_of_mass;
    let m = &body.moments;
    let [w, x, y, z] = body.principal_quaternion();
    format!(
        "// {}\n\
         // Unreal Engine (Chaos): lengths cm, mass kg, inertia kg*cm^2 (principal moments about the\n\
         // centre of mass, in the mass frame FTransform(FQuat(X, Y, Z, W), centre of mass) local to\n\
         // the body). Import the mesh at its real size. Run after the body's physics state exists,\n\
         // e.g. with FBodyInstance* Body = Component->GetBodyInstance():\n\
         FPhysicsCommand::ExecuteWrite(Body->GetPhysicsActorHandle(), [](FPhysicsActorHandle& Actor)\n\
         {{\n\
         \x20   FPhysicsInterface::SetMass_AssumesLocked(Actor, {});\n\
         \x20   FPhysicsInterface::SetComLocalPose_AssumesLocked(Actor, FTransform(FQuat({}, {}, {}, {}), FVector({}, {}, {})));\n\
         \x20   FPhysicsInterface::SetMassSpaceInertiaTensor_AssumesLocked(Actor, FVector({}, {}, {}));\n\
         }});\n",
        super::provenance(body),
        num(body.mass),
        num(x),
        num(y),
        num(z),
        num(w),
        num(c.x),
        num(c.y),
        num(c.z),
        num(m.x),
        num(m.y),
        num(m.z),
    )
}
