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
use std::path::Path;

use nalgebra::{Rotation3, UnitQuaternion};

use super::Frame;
use super::frames::{AXIS_ALIGNED_TOLERANCE, Converted, num, quaternion_wxyz};
use super::surface::Surface;

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

/// A whole Godot 4 scene (`.tscn`, format 3): the `RigidBody3D` of [`render`] as its root, each
/// mesh file the surface came from as an external resource on a `MeshInstance3D` (its path
/// relative to `folder`, the scene's, which Godot resolves from the scene's own folder; the
/// node placed, turned and scaled into the body's axes and metres), and a `CollisionShape3D`
/// whose `ConvexPolygonShape3D` is the hull of the surface's points. In the `com-principal`
/// frame they go under `MeshFrame`, which holds the mesh's axes.
pub fn scene(
    body: &Converted,
    frame: Frame,
    surface: &Surface,
    name: &str,
    folder: Option<&Path>,
    warnings: &mut Vec<String>,
) -> String {
    let s = body.conversion.source_unit.metres() / body.conversion.target_unit.metres();
    let mut out = String::new();
    let meshes = surface.files.len();
    let _ = writeln!(out, "[gd_scene load_steps={} format=3]", meshes + 2);
    let _ = writeln!(out);
    let kinds: Vec<Option<Imported>> = surface.files.iter().map(|f| imported(&f.path)).collect();
    for (k, (file, kind)) in surface.files.iter().zip(&kinds).enumerate() {
        let Some(kind) = kind else {
            warnings.push(format!(
                "godot-scene: Godot 4 does not import {} (it imports .obj as a mesh, and glTF, \
                 .glb and COLLADA as scenes): convert it to one of them, or the body has its \
                 collision hull and mass but is not drawn",
                file.path.display()
            ));
            continue;
        };
        let path = file.named_from(folder);
        if Path::new(&path).is_absolute() {
            warnings.push(format!(
                "godot-scene: {} is not under the scene's folder, so the scene names it by its \
                 absolute path, which Godot does not load from outside its project: write the \
                 scene beside the mesh, or move the mesh under the scene's folder",
                file.path.display()
            ));
        }
        let _ = writeln!(
            out,
            "[ext_resource type=\"{}\" path=\"{}\" id=\"mesh_{k}\"]",
            match kind {
                Imported::Mesh => "ArrayMesh",
                Imported::Scene => "PackedScene",
            },
            text(&path)
        );
    }
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "[sub_resource type=\"ConvexPolygonShape3D\" id=\"hull\"]"
    );
    let points: Vec<String> = surface
        .points
        .iter()
        .map(|p| {
            let q = body.map * p.coords * s;
            format!("{}, {}, {}", num(q.x), num(q.y), num(q.z))
        })
        .collect();
    let _ = writeln!(out, "points = PackedVector3Array({})", points.join(", "));
    let _ = writeln!(out);
    let node = render(body, frame, warnings).replacen(
        "[node name=\"Body\" type=\"RigidBody3D\"]",
        &format!("[node name=\"{}\" type=\"RigidBody3D\"]", text(name)),
        1,
    );
    out.push_str(&node);
    let parent = match frame {
        Frame::ComPrincipal => "MeshFrame",
        Frame::Origin => ".",
    };
    // The mesh's axes → the body's: the same turn for every file (Godot is right-handed, so
    // the map is a rotation), each file's placement within the body before it.
    let turn = Rotation3::from_matrix_unchecked(body.map);
    for (k, (file, kind)) in surface.files.iter().zip(&kinds).enumerate() {
        let Some(kind) = kind else { continue };
        let rotation = UnitQuaternion::from_rotation_matrix(&turn) * file.placement.rotation;
        let position = body.map * file.placement.translation.vector * s;
        let scale = file.scale * s;
        let _ = writeln!(out);
        let _ = match kind {
            Imported::Mesh => writeln!(
                out,
                "[node name=\"Mesh{k}\" type=\"MeshInstance3D\" parent=\"{parent}\"]"
            ),
            Imported::Scene => writeln!(
                out,
                "[node name=\"Mesh{k}\" parent=\"{parent}\" instance=ExtResource(\"mesh_{k}\")]"
            ),
        };
        let _ = writeln!(out, "position = {}", vector(&position));
        let _ = writeln!(
            out,
            "quaternion = Quaternion({}, {}, {}, {})",
            num(rotation.i),
            num(rotation.j),
            num(rotation.k),
            num(rotation.w)
        );
        let _ = writeln!(out, "scale = Vector3({0}, {0}, {0})", num(scale));
        if *kind == Imported::Mesh {
            let _ = writeln!(out, "mesh = ExtResource(\"mesh_{k}\")");
        }
    }
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "[node name=\"Collision\" type=\"CollisionShape3D\" parent=\"{parent}\"]"
    );
    let _ = writeln!(out, "shape = SubResource(\"hull\")");
    out
}

/// What Godot 4 imports a mesh file as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Imported {
    /// A mesh resource (Wavefront OBJ), drawn by a `MeshInstance3D`.
    Mesh,
    /// A scene (glTF, GLB, COLLADA), instanced as a node.
    Scene,
}

/// What Godot 4 imports `path` as, by its extension; `None` for a format it does not import.
fn imported(path: &Path) -> Option<Imported> {
    let extension = path.extension()?.to_string_lossy().to_ascii_lowercase();
    match extension.as_str() {
        "obj" => Some(Imported::Mesh),
        "gltf" | "glb" | "dae" => Some(Imported::Scene),
        _ => None,
    }
}

/// Text for a double-quoted `.tscn` string.
fn text(s: &str) -> String {
    s.replace('\\', "\\\\").replace('"', "\\\"")
}
