//! `unity`: a C# snippet setting a `Rigidbody`, with the same values as one JSON line.
//!
//! Unity scripting API: `Rigidbody.centerOfMass` is "the center of mass relative to the
//! transform's origin"; `inertiaTensor` is "the diagonal inertia tensor of mass relative to the
//! center of mass", and "the inertia tensor is rotated by the inertiaTensorRotation"
//! (a `Quaternion`, constructor order x, y, z, w), i.e. the rotation from the principal frame to
//! the body frame (PhysX's mass-frame pose). Units m, kg, kg·m². Unity is left-handed, +Y up;
//! its model importer turns right-handed files left-handed by negating x, so the body is
//! mirrored in x here too (frames.rs), after any Z-up → Y-up rotation. The mirrored tensor is
//! `A I Aᵀ`, and the quaternion is that of the mirrored principal axes made a proper rotation.
//! Setting `inertiaTensor` and `centerOfMass` from a script turns Unity's automatic computation
//! off for them (`automaticInertiaTensor`, `automaticCenterOfMass` in Unity 2022.2+).

use serde_json::json;

use super::frames::{Converted, num};

/// A C# float literal.
fn f(v: f64) -> String {
    format!("{}f", num(v))
}

/// The C# snippet.
pub fn render(body: &Converted) -> String {
    let c = &body.center_of_mass;
    let m = &body.moments;
    let [w, x, y, z] = body.principal_quaternion();
    let data = json!({
        "mass": body.mass,
        "centerOfMass": {"x": c.x, "y": c.y, "z": c.z},
        "inertiaTensor": {"x": m.x, "y": m.y, "z": m.z},
        "inertiaTensorRotation": {"x": x, "y": y, "z": z, "w": w},
    });
    format!(
        "// {}\n\
         // Unity Rigidbody: lengths m, mass kg, inertia kg*m^2. centerOfMass in the body's local\n\
         // space; inertiaTensor = principal moments about the centre of mass, in the frame that\n\
         // inertiaTensorRotation (Quaternion(x, y, z, w)) rotates into the body's local axes.\n\
         // Same values as JSON (JsonUtility layout of Vector3/Quaternion):\n\
         // {data}\n\
         var body = GetComponent<Rigidbody>();\n\
         body.mass = {};\n\
         body.centerOfMass = new Vector3({}, {}, {});\n\
         body.inertiaTensorRotation = new Quaternion({}, {}, {}, {});\n\
         body.inertiaTensor = new Vector3({}, {}, {});\n",
        super::provenance(body),
        f(body.mass),
        f(c.x),
        f(c.y),
        f(c.z),
        f(x),
        f(y),
        f(z),
        f(w),
        f(m.x),
        f(m.y),
        f(m.z),
    )
}

/// A whole C# file: a `MonoBehaviour` named `class` (Unity wants the file named `class.cs`) that
/// gives its object's `Rigidbody` the body's mass properties in `Awake`, its values as
/// serialized fields (shown in the Inspector).
pub fn script(body: &Converted, class: &str) -> String {
    let c = &body.center_of_mass;
    let m = &body.moments;
    let [w, x, y, z] = body.principal_quaternion();
    format!(
        "// {}\n\
         // Unity Rigidbody: lengths m, mass kg, inertia kg*m^2. centerOfMass in the body's local\n\
         // space; inertiaTensor = principal moments about the centre of mass, in the frame that\n\
         // inertiaTensorRotation (Quaternion(x, y, z, w)) rotates into the body's local axes.\n\
         // Save as {class}.cs in Assets and add it to the object with the Rigidbody.\n\
         using UnityEngine;\n\
         \n\
         [RequireComponent(typeof(Rigidbody))]\n\
         public class {class} : MonoBehaviour\n\
         {{\n\
         \x20   public float mass = {};\n\
         \x20   public Vector3 centerOfMass = new Vector3({}, {}, {});\n\
         \x20   public Vector3 inertiaTensor = new Vector3({}, {}, {});\n\
         \x20   public Quaternion inertiaTensorRotation = new Quaternion({}, {}, {}, {});\n\
         \n\
         \x20   void Awake()\n\
         \x20   {{\n\
         \x20       var body = GetComponent<Rigidbody>();\n\
         \x20       body.mass = mass;\n\
         \x20       body.centerOfMass = centerOfMass;\n\
         \x20       body.inertiaTensorRotation = inertiaTensorRotation;\n\
         \x20       body.inertiaTensor = inertiaTensor;\n\
         \x20   }}\n\
         }}\n",
        super::provenance(body),
        f(body.mass),
        f(c.x),
        f(c.y),
        f(c.z),
        f(m.x),
        f(m.y),
        f(m.z),
        f(x),
        f(y),
        f(z),
        f(w),
    )
}
