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
//!
//! [`script`] does it in the editor instead, for a static mesh: Unreal computes mass properties
//! from simple collision shapes at uniform density, so the script gives the mesh the solid box
//! with the body's mass, centre, principal axes and moments (collision off, contributing to
//! mass) and takes the mesh's other shapes out of the mass. Chaos sums the shapes whose
//! `FKShapeElem::GetContributeToMass()` holds (`BodyUtils::ComputeMassProperties`), a shape
//! with collision off included, and a mass override scales that inertia to the mass.

use std::fmt::Write as _;

use super::frames::{Converted, num};
use super::surface::Surface;

/// The editor script's code; its `#@BODY@` line becomes the body's numbers.
const EDITOR_SCRIPT: &str = include_str!("unreal_editor.py");

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

/// A Python literal of three numbers.
fn triple(v: &nalgebra::Vector3<f64>) -> String {
    format!("({}, {}, {})", num(v.x), num(v.y), num(v.z))
}

/// A whole Unreal editor Python script that gives the static mesh `name` (placed in the level)
/// the body's exact mass properties through its equivalent box; it refuses a mesh imported at
/// another size or turn, which it tells by the bounds of `surface`.
pub fn script(
    body: &Converted,
    surface: &Surface,
    name: &str,
    warnings: &mut Vec<String>,
) -> String {
    let s = body.conversion.source_unit.metres() / body.conversion.target_unit.metres();
    let mut lo = nalgebra::Vector3::repeat(f64::INFINITY);
    let mut hi = -lo;
    for p in &surface.points {
        let q = body.map * p.coords * s;
        lo = lo.inf(&q);
        hi = hi.sup(&q);
    }
    if surface.files.len() > 1 {
        warnings.push(format!(
            "unreal-script: the body is {} mesh files, and Unreal simulates one static mesh: \
             import them as one (Combine Meshes) named {name}, which the script changes",
            surface.files.len()
        ));
    }
    // Unreal names an imported mesh after its file.
    let mesh_name = match surface.files.as_slice() {
        [one] => one
            .path
            .file_stem()
            .map_or_else(|| name.to_owned(), |s| s.to_string_lossy().into_owned()),
        _ => name.to_owned(),
    };
    let [w, x, y, z] = body.principal_quaternion();
    let mut data = String::new();
    let _ = writeln!(data, "MESH_NAME = {}", python_string(&mesh_name));
    let _ = writeln!(data, "MASS_KG = {}", num(body.mass));
    let _ = writeln!(data, "CENTER_OF_MASS_CM = {}", triple(&body.center_of_mass));
    let _ = writeln!(data, "PRINCIPAL_MOMENTS_KG_CM2 = {}", triple(&body.moments));
    let _ = writeln!(
        data,
        "PRINCIPAL_AXES_XYZW = ({}, {}, {}, {})",
        num(x),
        num(y),
        num(z),
        num(w)
    );
    let _ = writeln!(data, "BOUNDS_CM = ({}, {})", triple(&lo), triple(&hi));
    format!(
        "# {}\n{}",
        super::provenance(body),
        EDITOR_SCRIPT.replacen("#@BODY@\n", &data, 1)
    )
}

/// `text` as a Python string literal.
fn python_string(text: &str) -> String {
    let mut out = String::from("\"");
    for c in text.chars() {
        match c {
            '\\' | '"' => {
                out.push('\\');
                out.push(c);
            }
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04x}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::python_string;

    #[test]
    fn names_become_python_strings() {
        assert_eq!(python_string("t_handle"), "\"t_handle\"");
        assert_eq!(python_string("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
    }
}
