//! `godot`: Godot 4 `RigidBody3D` properties in `.tscn` text form.
//!
//! Godot class reference, `RigidBody3D`: `inertia` (Vector3) is "the body's moment of inertia
//! … on each axis", a diagonal in the body's own axes, about the centre of mass; there is no
//! inertia rotation (GodotBody3D resets its principal-axes basis to identity for a custom
//! inertia). `center_of_mass` is "the body's custom center of mass, relative to the body's
//! origin position, when center_of_mass_mode is set to CENTER_OF_MASS_MODE_CUSTOM" (= 1).
//! Godot is right-handed, +Y up, metres; `.tscn` comments start with `;`, `Quaternion(x, y, z, w)`.
//!
//! Frames: `origin` keeps the mesh's axes as the body's and writes the body-axes diagonal of
//! the tensor, exact only when the products of inertia vanish (a warning says when they do
//! not); `com-principal` makes the body's axes the principal axes and adds a `MeshFrame` child
//! rotated by the inverse rotation, under which the mesh and collision shapes go: exact.

use std::fmt::Write as _;

use super::Frame;
use super::frames::{AXIS_ALIGNED_TOLERANCE, Converted, num, quaternion_wxyz};

fn vector(v: &nalgebra::Vector3<f64>) -> String {
    format!("Vector3({}, {}, {})", num(v.x), num(v.y), num(v.z))
}

/// The `.tscn` fragment; pushes a warning when body-axes inertia drops products of inertia.
pub fn render(body: &Converted, frame: Frame, warnings: &mut Vec<String>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "; {}", super::provenance(body));
    let _ = writeln!(
        s,
        "; Godot 4 RigidBody3D: lengths m, mass kg, inertia kg*m^2 = moments about the centre of \
         mass along the body's own x, y, z (Godot has no inertia rotation); center_of_mass_mode \
         1 = custom."
    );
    let (com, inertia) = match frame {
        Frame::Origin => {
            let ratio = body.off_diagonal_ratio();
            if ratio > AXIS_ALIGNED_TOLERANCE {
                let text = format!(
                    "godot: the principal axes are not the body axes (largest product of inertia \
                     {ratio:.3e} of the largest moment) and Godot has no inertia rotation, so the \
                     products of inertia are dropped and the body will turn wrongly; export with \
                     --frame com-principal and put the mesh and collision shapes under its \
                     MeshFrame node, or rotate the mesh so its principal axes are x, y, z"
                );
                let _ = writeln!(s, "; WARNING: {text}");
                warnings.push(text);
            }
            let i = &body.inertia;
            (
                body.center_of_mass,
                nalgebra::Vector3::new(i[(0, 0)], i[(1, 1)], i[(2, 2)]),
            )
        }
        Frame::ComPrincipal => (body.principal.inverse() * body.center_of_mass, body.moments),
    };
    let _ = writeln!(s, "[node name=\"Body\" type=\"RigidBody3D\"]");
    let _ = writeln!(s, "mass = {}", num(body.mass));
    let _ = writeln!(s, "center_of_mass_mode = 1");
    let _ = writeln!(s, "center_of_mass = {}", vector(&com));
    let _ = writeln!(s, "inertia = {}", vector(&inertia));
    if frame == Frame::ComPrincipal {
        let [w, x, y, z] = quaternion_wxyz(&body.principal.inverse());
        let _ = writeln!(
            s,
            "\n; The body's axes are the principal axes; MeshFrame holds the mesh's own axes. \
             Put the MeshInstance3D and CollisionShape3D nodes under it."
        );
        let _ = writeln!(s, "[node name=\"MeshFrame\" type=\"Node3D\" parent=\".\"]");
        let _ = writeln!(
            s,
            "quaternion = Quaternion({}, {}, {}, {})",
            num(x),
            num(y),
            num(z),
            num(w)
        );
    }
    s
}
