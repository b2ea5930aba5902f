//! The motion baked into a file that plays it back: a body (what the input path resolved a file
//! to, or a box of given principal moments) spun from rest where its mesh lies, run by rbcore's
//! own integrator, its keyframes written as a glTF animation or USD time samples. The command
//! line's `simulate --animation`, the app's Export motion and Python's `inertialab.simulate`
//! all bake through here.
//!
//! World is the mesh's frame: at frame 0 the mesh is where its file puts it, its centre of mass
//! at rest there, and the spin is given in the principal frame (moments ascending), as
//! `simulate --omega` takes it. The keyframes are [`rbcore::keyframes`]' states; the export
//! maps them into the format's axes and unit (+Y up for glTF, +Z for USD) as it does the mass
//! properties ([`crate::export::Motion`]).

use std::path::Path;

use massprops::MassProperties;
use nalgebra::{UnitQuaternion, Vector3};
use rbcore::{Body, Keyframes, Settings, Simulation};

use crate::export::{
    ExportError, ExportOptions, ExportOutput, Format, Geometry, LengthUnit, Motion, Surface,
    UpAxis, export_file, principal_box,
};
use crate::input::Resolved;

/// A body as a baked file shows it: its mass properties and its surface, in the mesh's
/// coordinates.
#[derive(Debug, Clone)]
pub struct Shape {
    /// Mass properties in the mesh's coordinates.
    pub properties: MassProperties,
    /// Its surface.
    pub surface: Surface,
}

impl Shape {
    /// The body a file resolved to (`properties` as the caller settled them: a mass given, say).
    pub fn of(resolved: &Resolved, path: &Path, properties: MassProperties) -> Self {
        Self {
            properties,
            surface: Surface::of(resolved, path),
        }
    }

    /// A body known by its mass and principal moments: the box of those moments
    /// ([`principal_box`]).
    pub fn principal_box(mass: f64, moments: &Vector3<f64>) -> Self {
        let (properties, surface) = principal_box(mass, moments);
        Self {
            properties,
            surface,
        }
    }
}

/// How the body is set going and sampled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spin {
    /// Angular velocity at the start (rad/s), in the principal frame, moments ascending.
    pub omega: Vector3<f64>,
    /// Seconds simulated.
    pub duration: f64,
    /// Keyframes a second.
    pub fps: f64,
    /// The simulation's settings: its step (shortened to divide a frame where it does not),
    /// integrator and model.
    pub settings: Settings,
}

/// The keyframes and the node motion they make.
#[derive(Debug, Clone, PartialEq)]
pub struct Baked {
    /// The simulation's poses, one a frame.
    pub keyframes: Keyframes,
    /// The mesh's node transform at each frame (mesh coordinates → world).
    pub motion: Motion,
    /// Relative change of |L| from the first frame to the last.
    pub l_change: f64,
    /// Relative change of the energy from the first frame to the last.
    pub energy_change: f64,
}

/// What stops a bake.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BakeError {
    /// The body cannot be simulated (its moments, or a non-finite spin).
    #[error("the body cannot be simulated: {0}")]
    Body(#[from] rbcore::BodyError),
    /// A setting, the frame rate or the duration is out of range.
    #[error("{0}")]
    Setting(rbcore::BodyError),
    /// The simulation diverged.
    #[error("{0}")]
    Diverged(rbcore::SimError),
}

impl From<rbcore::SimError> for BakeError {
    fn from(e: rbcore::SimError) -> Self {
        match e {
            rbcore::SimError::InvalidSetting(e) => BakeError::Setting(e),
            e => BakeError::Diverged(e),
        }
    }
}

/// Spins `shape` as `spin` says and samples its motion.
///
/// # Errors
/// [`BakeError`].
pub fn bake(shape: &Shape, spin: &Spin) -> Result<Baked, BakeError> {
    let p = &shape.properties;
    let mut body = Body::from_principal(p.mass, p.principal.moments, p.principal.rotation)?;
    body.set_position(p.center_of_mass)?;
    body.set_body_orientation(UnitQuaternion::identity())?;
    body.set_omega_principal(spin.omega)?;
    let mut sim = Simulation::new(body, spin.settings)?;
    sample(shape, &mut sim, spin.duration, spin.fps)
}

/// Samples `sim`, a simulation of `shape` already going (the app's, as it stands: its forces,
/// string and settings), for `duration` seconds at `fps`, frame 0 its present state. World is
/// the simulation's: the node transform puts `shape`'s mesh where the body is.
///
/// # Errors
/// [`BakeError`].
pub fn sample(
    shape: &Shape,
    sim: &mut Simulation,
    duration: f64,
    fps: f64,
) -> Result<Baked, BakeError> {
    let start = sim.diagnostics();
    let keyframes = rbcore::keyframes(sim, duration, fps)?;
    let end = sim.diagnostics();
    let change = |a: f64, b: f64| rbcore::relative_change(a, b).unwrap_or(0.0);
    let motion = Motion::from_poses(
        keyframes.fps,
        &shape.properties.center_of_mass,
        keyframes.poses.iter().map(|k| (k.position, k.orientation)),
    );
    Ok(Baked {
        l_change: change(end.angular_momentum_norm, start.angular_momentum_norm),
        energy_change: change(end.energy, start.energy),
        keyframes,
        motion,
    })
}

/// The file format a baked motion's path names by its extension: `.glb` or `.usda`.
pub fn format_of(path: &Path) -> Option<Format> {
    let extension = path.extension()?.to_string_lossy().to_ascii_lowercase();
    match extension.as_str() {
        "glb" => Some(Format::Glb),
        "usda" => Some(Format::Usd),
        _ => None,
    }
}

/// `baked` of `shape` as a `format` file (`glb` or `usd`), the body named `name`, the mesh's
/// coordinates in `units` with `up` up.
///
/// # Errors
/// A format that carries no motion, or a body no format can hold (as [`export_file`]).
pub fn write(
    shape: &Shape,
    baked: &Baked,
    name: &str,
    format: Format,
    units: LengthUnit,
    up: UpAxis,
) -> Result<ExportOutput, ExportError> {
    let geometry = Geometry {
        surface: &shape.surface,
        name,
        folder: None,
        motion: Some(&baked.motion),
    };
    let options = ExportOptions {
        format,
        units,
        up,
        frame: None,
    };
    export_file(&shape.properties, &geometry, &options)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A box spun about its major axis turns steadily: frame k is turned k·ω/fps about the
    /// stage's axis, and the exact flow keeps |L| and E to round-off.
    #[test]
    fn a_steady_spin_bakes_to_a_steady_turn() {
        let shape = Shape::principal_box(2.0, &Vector3::new(1.0, 2.0, 3.0));
        let spin = Spin {
            omega: Vector3::new(0.0, 0.0, 3.0),
            duration: 1.0,
            fps: 10.0,
            settings: Settings {
                integrator: rbcore::Integrator::Exact,
                ..Settings::default()
            },
        };
        let baked = bake(&shape, &spin).expect("bakes");
        assert_eq!(baked.motion.frames.len(), 11);
        for (k, frame) in baked.motion.frames.iter().enumerate() {
            let expected =
                UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 3.0 * k as f64 / 10.0);
            assert!(frame.rotation.angle_to(&expected) < 1e-12, "frame {k}");
            assert!(frame.translation.vector.norm() < 1e-15);
        }
        assert!(baked.l_change.abs() < 1e-14 && baked.energy_change.abs() < 1e-14);
        let out =
            write(&shape, &baked, "box", Format::Usd, LengthUnit::M, UpAxis::Z).expect("writes");
        let text = String::from_utf8(out.bytes).expect("text");
        assert!(text.contains("endTimeCode = 10"), "{text}");
        assert!(
            write(
                &shape,
                &baked,
                "box",
                Format::Urdf,
                LengthUnit::M,
                UpAxis::Z
            )
            .is_err()
        );
    }

    #[test]
    fn a_bad_rate_or_spin_is_named() {
        let shape = Shape::principal_box(1.0, &Vector3::new(1.0, 2.0, 3.0));
        let spin = Spin {
            omega: Vector3::new(0.0, 1.0, 0.0),
            duration: 1.0,
            fps: 0.0,
            settings: Settings::default(),
        };
        assert!(matches!(bake(&shape, &spin), Err(BakeError::Setting(_))));
        let spin = Spin {
            omega: Vector3::new(f64::NAN, 1.0, 0.0),
            fps: 30.0,
            ..spin
        };
        assert!(matches!(bake(&shape, &spin), Err(BakeError::Body(_))));
    }

    #[test]
    fn the_format_is_named_by_the_extension() {
        assert_eq!(format_of(Path::new("a/spin.GLB")), Some(Format::Glb));
        assert_eq!(format_of(Path::new("spin.usda")), Some(Format::Usd));
        assert_eq!(format_of(Path::new("spin.fbx")), None);
        assert_eq!(format_of(Path::new("spin")), None);
    }
}
