//! Export of mass properties to the engines and robot formats people paste them into.
//!
//! [`export`] is pure: mass properties (mesh units, kg) and [`ExportOptions`] in, text and
//! warnings out. All frame, handedness, unit and sign work happens in `frames`; each format
//! module only writes the numbers `frames::convert` gives it, in its target's field order.
//!
//! | format | frame read by the target | units | rotation written as | source |
//! |---|---|---|---|---|
//! | `json` | mesh axes | SI | principal axes as rows + quaternion `[x, y, z, w]` | ours |
//! | `urdf` | right-handed Z-up link frame | m, kg, kg·m² | `<origin xyz rpy>`, fixed-axis RPY | ROS URDF `<inertial>` spec |
//! | `mjcf` | right-handed Z-up body frame | m, kg, kg·m² | `quat="w x y z"` + `diaginertia`, or `fullinertia` (xx yy zz xy xz yz) | MuJoCo XML reference, `inertial` |
//! | `sdf` | right-handed Z-up link frame | m, kg, kg·m² | `<pose>x y z roll pitch yaw</pose>` | SDFormat `<inertial>` spec |
//! | `unity` | left-handed Y-up (x mirrored) | m, kg, kg·m² | `inertiaTensorRotation = new Quaternion(x, y, z, w)` | Unity `Rigidbody` scripting API |
//! | `godot` | right-handed Y-up | m, kg, kg·m² | none: `inertia` is a body-axes diagonal | Godot `RigidBody3D` class reference |
//! | `unreal` | left-handed Z-up (y mirrored) | cm, kg, kg·cm² | `FQuat(X, Y, Z, W)` in the COM local pose | Unreal `FPhysicsInterface` (Chaos) |
//! | `rapier` | right-handed Y-up (Bevy) | m, kg, kg·m² | `Rotation::from_xyzw(x, y, z, w)` / `Quat::from_xyzw` (glam) | rapier3d 0.36 `MassProperties` docs |
//! | `gltf` | right-handed Y-up node space | m, kg, kg·m² | `inertiaOrientation: [x, y, z, w]` | Khronos `KHR_physics_rigid_bodies` |
//! | `glb` | as `gltf`: a whole file, the mesh on the node | m, kg, kg·m² | as `gltf` | glTF 2.0 §4.4 (GLB) |
//! | `usd` | right-handed Z-up prim space (`upAxis`) | m, kg, kg·m² (`metersPerUnit`, `kilogramsPerUnit`) | `principalAxes = (w, x, y, z)` | UsdPhysics `MassAPI` |
//! | `sdf-model` | as `sdf`: a whole `<model>`, meshes by `<uri>` | m, kg, kg·m² | as `sdf` | SDFormat 1.9 |
//! | `godot-scene` | as `godot`: a whole `.tscn`, meshes by path, a convex hull | m, kg, kg·m² | as `godot` | Godot 4 text scene format 3 |
//! | `unity-script` | as `unity`: a whole `MonoBehaviour` | m, kg, kg·m² | as `unity` | Unity `Rigidbody` |
//! | `unreal-script` | as `unreal`: a whole editor Python script | cm, kg, kg·cm² | `unreal.Quat(x, y, z, w)` of the equivalent box | Unreal Python API, Chaos mass properties |
//!
//! Every target takes the inertia about the centre of mass; "frame" only chooses its axes:
//! [`Frame::ComPrincipal`] writes the principal moments and the rotation to the principal axes,
//! [`Frame::Origin`] the full tensor in the mesh's own axes (URDF, SDF, MJCF), or for Godot,
//! which has no inertia rotation, the diagonal in body axes.
//!
//! `glb`, `usd`, `sdf-model`, `godot-scene` and `unreal-script` are whole files, which carry
//! the body's [`Surface`] too (`unity-script` is a whole file that needs none):
//! [`export_file`] writes them (and every other format); [`export`] the fragments alone.

mod frames;
mod glb;
mod gltf;
mod godot;
mod json;
mod mjcf;
mod motion;
mod rapier;
mod sdf;
mod surface;
mod unity;
mod unreal;
mod urdf;
mod usd;

use massprops::MassProperties;

use crate::choice::Choice;

use frames::{Axes, Conversion};
pub use frames::{UpAxis, density_per_cubic_unit, quaternion_wxyz};
pub use massprops::LengthUnit;
pub use motion::{Motion, principal_box};
pub use surface::{Surface, SurfaceFile};

/// An output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Our JSON schema, every number in SI, mesh axes.
    Json,
    /// URDF `<inertial>` (ROS).
    Urdf,
    /// MuJoCo MJCF `<inertial>`.
    Mjcf,
    /// SDFormat `<inertial>` (Gazebo).
    Sdf,
    /// Unity `Rigidbody` C# snippet with the same values as JSON.
    Unity,
    /// Godot 4 `RigidBody3D` scene (.tscn) properties.
    Godot,
    /// Unreal Engine C++ snippet (cm, kg·cm², left-handed Z-up).
    Unreal,
    /// rapier3d / bevy_rapier3d Rust snippet building `MassProperties`.
    Rapier,
    /// glTF `KHR_physics_rigid_bodies` node extension with its motion.
    Gltf,
    /// A whole binary glTF file: the mesh on a node with its `KHR_physics_rigid_bodies` motion.
    Glb,
    /// A whole USD stage (.usda): the mesh on a prim with UsdPhysics' `RigidBodyAPI` and `MassAPI`.
    Usd,
    /// A whole SDFormat file: a `<model>` whose link has the `<inertial>` and the meshes.
    SdfModel,
    /// A whole Godot 4 scene (.tscn): the `RigidBody3D` with its mesh and collision hull.
    GodotScene,
    /// A whole Unity C# script: a component that sets its object's `Rigidbody`.
    UnityScript,
    /// A whole Unreal editor Python script: gives a placed static mesh the body's mass
    /// properties through its equivalent box.
    UnrealScript,
}

impl Choice for Format {
    const OPTION: &'static str = "format";
    const ALL: &'static [Self] = &[
        Format::Json,
        Format::Urdf,
        Format::Mjcf,
        Format::Sdf,
        Format::Unity,
        Format::Godot,
        Format::Unreal,
        Format::Rapier,
        Format::Gltf,
        Format::Glb,
        Format::Usd,
        Format::SdfModel,
        Format::GodotScene,
        Format::UnityScript,
        Format::UnrealScript,
    ];

    fn name(self) -> &'static str {
        match self {
            Format::Json => "json",
            Format::Urdf => "urdf",
            Format::Mjcf => "mjcf",
            Format::Sdf => "sdf",
            Format::Unity => "unity",
            Format::Godot => "godot",
            Format::Unreal => "unreal",
            Format::Rapier => "rapier",
            Format::Gltf => "gltf",
            Format::Glb => "glb",
            Format::Usd => "usd",
            Format::SdfModel => "sdf-model",
            Format::GodotScene => "godot-scene",
            Format::UnityScript => "unity-script",
            Format::UnrealScript => "unreal-script",
        }
    }

    fn help(self) -> &'static str {
        match self {
            Format::Json => "Our JSON schema, every number in SI, mesh axes",
            Format::Urdf => "URDF `<inertial>` (ROS)",
            Format::Mjcf => "MuJoCo MJCF `<inertial>`",
            Format::Sdf => "SDFormat `<inertial>` (Gazebo)",
            Format::Unity => "Unity `Rigidbody` C# snippet with the same values as JSON",
            Format::Godot => "Godot 4 `RigidBody3D` scene (.tscn) properties",
            Format::Unreal => "Unreal Engine C++ snippet (cm, kg·cm², left-handed Z-up)",
            Format::Rapier => "rapier3d / bevy_rapier3d Rust snippet building `MassProperties`",
            Format::Gltf => "glTF `KHR_physics_rigid_bodies` node extension with its motion",
            Format::Glb => {
                "A whole binary glTF file: the mesh on a node with its \
                 `KHR_physics_rigid_bodies` motion"
            }
            Format::Usd => {
                "A whole USD stage (.usda): the mesh on a prim with UsdPhysics' `RigidBodyAPI` \
                 and `MassAPI`"
            }
            Format::SdfModel => {
                "A whole SDFormat file: a `<model>` whose link has the `<inertial>` and the meshes"
            }
            Format::GodotScene => {
                "A whole Godot 4 scene (.tscn): the `RigidBody3D` with its mesh and collision hull"
            }
            Format::UnityScript => {
                "A whole Unity C# script (.cs): a component that sets its object's `Rigidbody`"
            }
            Format::UnrealScript => {
                "A whole Unreal editor Python script (.py): gives the placed static mesh the \
                 body's mass properties"
            }
        }
    }
}

impl Format {
    /// The axes and length unit the target reads.
    fn target(self) -> (Axes, LengthUnit) {
        match self {
            Format::Json => (Axes::Mesh, LengthUnit::M),
            Format::Urdf | Format::Mjcf | Format::Sdf | Format::SdfModel | Format::Usd => {
                (Axes::RightZUp, LengthUnit::M)
            }
            Format::Unity | Format::UnityScript => (Axes::UnityLeftYUp, LengthUnit::M),
            Format::Godot | Format::GodotScene | Format::Rapier | Format::Gltf | Format::Glb => {
                (Axes::RightYUp, LengthUnit::M)
            }
            Format::Unreal | Format::UnrealScript => (Axes::UnrealLeftZUp, LengthUnit::Cm),
        }
    }

    /// The frame written when none is asked for, and whether the other one is possible.
    fn frames(self) -> (Frame, bool) {
        match self {
            // JSON always carries both frames.
            Format::Json
            | Format::Urdf
            | Format::Sdf
            | Format::SdfModel
            | Format::Mjcf
            | Format::Godot
            | Format::GodotScene => (Frame::Origin, true),
            Format::Unity
            | Format::UnityScript
            | Format::Unreal
            | Format::UnrealScript
            | Format::Rapier
            | Format::Gltf
            | Format::Glb
            | Format::Usd => (Frame::ComPrincipal, false),
        }
    }

    /// Whether the format is a whole file, which carries the body's surface
    /// ([`export_file`]).
    pub fn is_whole_file(self) -> bool {
        matches!(
            self,
            Format::Glb
                | Format::Usd
                | Format::SdfModel
                | Format::GodotScene
                | Format::UnrealScript
        )
    }
}

/// Which axes the inertia is written in (always about the centre of mass).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// Centre of mass and principal axes: a diagonal plus a rotation.
    ComPrincipal,
    /// The mesh's own axes (the link/body frame at the mesh origin): the full tensor.
    Origin,
}

impl Choice for Frame {
    const OPTION: &'static str = "frame";
    const ALL: &'static [Self] = &[Frame::ComPrincipal, Frame::Origin];

    fn name(self) -> &'static str {
        match self {
            Frame::ComPrincipal => "com-principal",
            Frame::Origin => "origin",
        }
    }

    fn help(self) -> &'static str {
        match self {
            Frame::ComPrincipal => "Centre of mass and principal axes: a diagonal plus a rotation",
            Frame::Origin => {
                "The mesh's own axes (the link/body frame at the mesh origin): the full tensor"
            }
        }
    }
}

/// What to write and how the mesh is to be read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ExportOptions {
    /// Output format.
    pub format: Format,
    /// The mesh's length unit.
    pub units: LengthUnit,
    /// The mesh's up axis.
    pub up: UpAxis,
    /// The frame the target should read; `None` for the format's default.
    pub frame: Option<Frame>,
}

/// What a whole file carries beside the numbers.
#[derive(Debug, Clone, Copy)]
pub struct Geometry<'a> {
    /// The body's surface, in the mesh's coordinates and unit.
    pub surface: &'a Surface,
    /// The body's name (the file's stem).
    pub name: &'a str,
    /// The folder the file is written to: a format that names meshes by file (SDFormat) names
    /// them relative to it where it can.
    pub folder: Option<&'a std::path::Path>,
    /// The body's motion, baked into the file (`glb` and `usd` only).
    pub motion: Option<&'a Motion>,
}

/// The exported file and what the user should know about it.
#[derive(Debug, Clone, PartialEq)]
pub struct ExportOutput {
    /// The file's bytes: text ending with a newline, or a binary file (`glb`).
    pub bytes: Vec<u8>,
    /// Caveats (for stderr or a status line).
    pub warnings: Vec<String>,
}

/// Why mass properties cannot be exported.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExportError {
    /// The mass or a coordinate is not a finite number, or the mass is not positive.
    #[error(
        "the mass ({mass}) or the centre of mass or inertia is not a finite positive value; \
         check the density or mass and that the mesh has finite coordinates"
    )]
    NotFinite {
        /// The mass given.
        mass: f64,
    },
    /// A principal moment is zero or negative.
    #[error(
        "the inertia tensor is not positive definite (principal moments {moments:?}): every \
         real body has three positive moments and every engine rejects or explodes on this. \
         Check the mesh for flipped faces (parts counted as negative volume), overlapping or \
         self-intersecting parts, holes, and flat or degenerate parts; `inertia-lab props` \
         lists open, non-manifold and inconsistently wound edges"
    )]
    NotPositiveDefinite {
        /// Principal moments, ascending.
        moments: [f64; 3],
    },
    /// The largest principal moment exceeds the sum of the other two.
    #[error(
        "the principal moments {moments:?} break the triangle inequality I1 + I2 >= I3 \
         (I3 exceeds I1 + I2 by {:.3e} of I3): no distribution of positive mass has them, and \
         MuJoCo, PhysX and Bullet refuse or misbehave. Check the mesh for inconsistent winding \
         (some faces or parts counted as negative volume) and overlapping parts; \
         `inertia-lab props` reports both",
        excess
    )]
    TriangleInequality {
        /// Principal moments, ascending.
        moments: [f64; 3],
        /// (I3 − I1 − I2) / I3.
        excess: f64,
    },
    /// A whole file needs the body's surface, which only [`export_file`] is given.
    #[error("{format} is a whole file with the body's mesh: it is written from the mesh file")]
    NeedsSurface {
        /// Format name.
        format: &'static str,
    },
    /// Only `glb` and `usd` carry a baked motion.
    #[error("{format} cannot carry a motion: write it as glb or usd")]
    MotionNotSupported {
        /// Format name.
        format: &'static str,
    },
    /// The format cannot express the requested frame.
    #[error("{format} cannot write the {frame} frame: {reason}")]
    FrameNotSupported {
        /// Format name.
        format: &'static str,
        /// Frame name.
        frame: &'static str,
        /// Why.
        reason: &'static str,
    },
}

impl ExportError {
    /// Whether the options, not the body, are at fault.
    pub fn is_usage(&self) -> bool {
        matches!(
            self,
            ExportError::FrameNotSupported { .. }
                | ExportError::NeedsSurface { .. }
                | ExportError::MotionNotSupported { .. }
        )
    }
}

/// Writes `props` (mesh coordinates in `options.units`, mass in kg) in `options.format`, a
/// fragment format (a whole file's is refused: [`export_file`]).
pub fn export(
    props: &MassProperties,
    options: &ExportOptions,
) -> Result<ExportOutput, ExportError> {
    write(props, None, options)
}

/// Writes `props` with the body's `geometry` in any format, whole files included.
pub fn export_file(
    props: &MassProperties,
    geometry: &Geometry<'_>,
    options: &ExportOptions,
) -> Result<ExportOutput, ExportError> {
    write(props, Some(geometry), options)
}

fn write(
    props: &MassProperties,
    geometry: Option<&Geometry<'_>>,
    options: &ExportOptions,
) -> Result<ExportOutput, ExportError> {
    let (default_frame, choice) = options.format.frames();
    let frame = options.frame.unwrap_or(default_frame);
    if frame != default_frame && !choice {
        return Err(ExportError::FrameNotSupported {
            format: options.format.name(),
            frame: "origin",
            reason: "the target takes only principal moments and a rotation (com-principal)",
        });
    }
    let (target, target_unit) = options.format.target();
    let body = frames::convert(
        props,
        Conversion {
            source_unit: options.units,
            source_up: options.up,
            target,
            target_unit,
        },
    )?;
    if geometry.is_some_and(|g| g.motion.is_some())
        && !matches!(options.format, Format::Glb | Format::Usd)
    {
        return Err(ExportError::MotionNotSupported {
            format: options.format.name(),
        });
    }
    let whole = |format: Format| {
        geometry.ok_or(ExportError::NeedsSurface {
            format: format.name(),
        })
    };
    let mut warnings = Vec::new();
    let text = match options.format {
        Format::Json => json::render(&body),
        Format::Urdf => urdf::render(&body, frame),
        Format::Mjcf => mjcf::render(&body, frame, &mut warnings),
        Format::Sdf => sdf::render(&body, frame),
        Format::Unity => unity::render(&body),
        Format::Godot => godot::render(&body, frame, &mut warnings),
        Format::Unreal => unreal::render(&body),
        Format::Rapier => rapier::render(&body),
        Format::Gltf => gltf::render(&body),
        Format::Glb => {
            let g = whole(Format::Glb)?;
            return Ok(ExportOutput {
                bytes: glb::render(&body, g.surface, g.name, g.motion),
                warnings,
            });
        }
        Format::Usd => {
            let g = whole(Format::Usd)?;
            usd::render(&body, g.surface, g.name, g.motion)
        }
        Format::SdfModel => {
            let g = whole(Format::SdfModel)?;
            sdf::model(&body, frame, g.surface, g.name, g.folder)
        }
        Format::GodotScene => {
            let g = whole(Format::GodotScene)?;
            godot::scene(&body, frame, g.surface, g.name, g.folder, &mut warnings)
        }
        // C# class names are identifiers.
        Format::UnityScript => {
            unity::script(&body, &identifier(geometry.map_or("Body", |g| g.name)))
        }
        Format::UnrealScript => {
            let g = whole(Format::UnrealScript)?;
            unreal::script(&body, g.surface, g.name, &mut warnings)
        }
    };
    Ok(ExportOutput {
        bytes: text.into_bytes(),
        warnings,
    })
}

/// A robot description's `<inertial>` element alone, for a body already in the description's
/// frame and units (metres, Z-up link axes): URDF in link axes (the full tensor, `rpy` zero),
/// MJCF in principal axes (`quat` and `diaginertia`, which MuJoCo keeps as written), SDFormat
/// as URDF. What the
/// audit's `--fix` writes in place of a link's inertial.
pub fn inertial_element(props: &MassProperties, format: Format) -> Result<String, ExportError> {
    let body = frames::convert(
        props,
        Conversion {
            source_unit: LengthUnit::M,
            source_up: UpAxis::Z,
            target: Axes::RightZUp,
            target_unit: LengthUnit::M,
        },
    )?;
    Ok(match format {
        Format::Mjcf => mjcf::element(&body, Frame::ComPrincipal),
        Format::Sdf => sdf::element(&body, Frame::Origin),
        _ => urdf::element(&body, Frame::Origin),
    })
}

/// The source line every output's comment starts with.
/// `name` as an identifier of USD's and C#'s kind: a letter or `_`, then letters, digits and
/// `_` (every other character `_`).
fn identifier(name: &str) -> String {
    let mut out: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if !out.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
        out.insert(0, '_');
    }
    out
}

fn provenance(body: &frames::Converted) -> String {
    let c = body.conversion;
    format!(
        "Inertia Lab export. Mesh read in {}, +{} up; target axes {}: target (x, y, z) = mesh {}.",
        c.source_unit.symbol(),
        match c.source_up {
            UpAxis::Y => "Y",
            UpAxis::Z => "Z",
        },
        c.target.describe(),
        frames::describe_map(&body.map),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use massprops::shapes;
    use nalgebra::{Isometry3, Translation3, UnitQuaternion};

    pub(super) fn rotated_hammer() -> MassProperties {
        massprops::mass_properties(&rotated_hammer_mesh(), 7850.0).expect("closed mesh")
    }

    fn rotated_hammer_mesh() -> massprops::PolyMesh {
        let motion = Isometry3::from_parts(
            Translation3::new(0.11, 0.05, -0.3),
            UnitQuaternion::from_euler_angles(0.7, 0.2, -1.3),
        );
        shapes::hammer().transformed(&motion).build()
    }

    #[test]
    fn names_become_identifiers() {
        assert_eq!(identifier("t_handle"), "t_handle");
        assert_eq!(identifier("3 part-body"), "_3_part_body");
        assert_eq!(identifier(""), "_");
    }

    #[test]
    fn every_format_exports_and_frames_are_checked() {
        let p = rotated_hammer();
        for &format in Format::ALL {
            let options = ExportOptions {
                format,
                units: LengthUnit::M,
                up: UpAxis::Y,
                frame: None,
            };
            let surface = Surface::of_mesh(&rotated_hammer_mesh(), std::path::Path::new("h.obj"));
            let geometry = Geometry {
                surface: &surface,
                name: "hammer",
                folder: None,
                motion: None,
            };
            let export = |p: &MassProperties, o: &ExportOptions| export_file(p, &geometry, o);
            let out = export(&p, &options).expect("exports");
            let motion = Motion {
                fps: 30.0,
                frames: vec![Isometry3::identity(); 3],
            };
            let animated = Geometry {
                motion: Some(&motion),
                ..geometry
            };
            let baked = export_file(&p, &animated, &options);
            if matches!(format, Format::Glb | Format::Usd) {
                assert!(baked.expect("a motion").bytes.len() > out.bytes.len());
            } else {
                assert!(baked.expect_err("no motion").is_usage(), "{format:?}");
            }
            if format == Format::Glb {
                assert!(out.bytes.starts_with(b"glTF"));
            } else {
                assert!(out.bytes.ends_with(b"\n"), "{format:?}");
            }
            assert_eq!(
                super::export(&p, &options).is_err(),
                format.is_whole_file(),
                "{format:?}"
            );
            let (_, choice) = format.frames();
            let origin = export(
                &p,
                &ExportOptions {
                    frame: Some(Frame::Origin),
                    ..options
                },
            );
            if choice {
                assert!(origin.is_ok());
            } else {
                assert!(origin.expect_err("refused").is_usage());
            }
            assert!(
                export(
                    &p,
                    &ExportOptions {
                        frame: Some(Frame::ComPrincipal),
                        ..options
                    }
                )
                .is_ok()
            );
        }
    }
}
