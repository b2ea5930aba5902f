//! `simulate … --animation OUT.glb|OUT.usda`: the simulated motion baked into a file that plays
//! it back, with the body's mesh (or, for `--inertia`, a box of those principal moments).
//!
//! World is the mesh's frame: at frame 0 the mesh is where its file puts it, its centre of mass
//! at rest there, and the principal-frame `--omega` is turned into that frame. The keyframes are
//! `rbcore::keyframes`' states of the lab's own integrator; `inertia_io::export` maps them into
//! the format's axes and unit (+Y up for glTF, +Z for USD) as it does the mass properties.

use std::path::PathBuf;

use clap::Args;
use massprops::MassProperties;
use nalgebra::UnitQuaternion;
use rbcore::{Body, Keyframes};

use super::choice::choice;
use super::error::CliError;
use inertia_io::export::{
    ExportOptions, Format, Geometry, LengthUnit, Motion, Surface, UpAxis, export_file,
    principal_box,
};

/// What the animation is written to and how.
#[derive(Args, Debug)]
pub struct AnimationArgs {
    /// Bake the motion into FILE: .glb (glTF animation channels) or .usda (USD time samples),
    /// with the mesh, or a box of the principal moments for --inertia.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["csv", "compare", "summary", "every"])]
    pub animation: Option<PathBuf>,
    /// Keyframes a second in the animation (the step is shortened to divide a frame if needed).
    #[arg(long, default_value_t = 30.0, requires = "animation")]
    pub fps: f64,
    /// Length unit of the mesh's coordinates, for the animation's file: m, cm, mm, in or ft.
    #[arg(long, requires = "animation", value_parser = parse_unit)]
    pub units: Option<LengthUnit>,
    /// Which mesh axis points up, for the animation's file.
    #[arg(long, value_parser = choice::<UpAxis>(), default_value = "y", requires = "animation")]
    pub up: UpAxis,
}

fn parse_unit(symbol: &str) -> Result<LengthUnit, String> {
    symbol
        .parse()
        .map_err(|e: massprops::UnknownUnit| e.to_string())
}

/// The body's mass properties and surface, as the animation's file shows it.
pub struct Shape {
    /// Mass properties in the mesh's coordinates.
    pub properties: MassProperties,
    /// Its surface.
    pub surface: Surface,
}

impl Shape {
    /// The box of `body`'s principal moments ([`principal_box`]).
    pub fn principal_box(body: &Body) -> Self {
        let (properties, surface) = principal_box(body.mass(), &body.moments());
        Self {
            properties,
            surface,
        }
    }
}

impl AnimationArgs {
    /// The format the output's extension names.
    pub fn format(&self) -> Result<Option<Format>, CliError> {
        let Some(path) = &self.animation else {
            return Ok(None);
        };
        let extension = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        match extension.as_deref() {
            Some("glb") => Ok(Some(Format::Glb)),
            Some("usda") => Ok(Some(Format::Usd)),
            _ => Err(CliError::Usage(format!(
                "--animation writes .glb (glTF) or .usda (USD), not {}",
                path.display()
            ))),
        }
    }
}

/// Places `body` as its mesh lies in its file: centre of mass at `shape`'s, body axes = world.
pub fn place(body: &mut Body, shape: &Shape) -> Result<(), CliError> {
    let at = |e: rbcore::BodyError| CliError::Input(e.to_string());
    body.set_position(shape.properties.center_of_mass)
        .map_err(at)?;
    body.set_body_orientation(UnitQuaternion::identity())
        .map_err(at)
}

/// Writes `keyframes` of `shape` as `args` say.
pub fn write(
    args: &AnimationArgs,
    name: &str,
    shape: &Shape,
    keyframes: &Keyframes,
) -> Result<(), CliError> {
    let (Some(path), Some(format)) = (&args.animation, args.format()?) else {
        return Ok(());
    };
    let motion = Motion::from_poses(
        keyframes.fps,
        &shape.properties.center_of_mass,
        keyframes.poses.iter().map(|p| (p.position, p.orientation)),
    );
    let geometry = Geometry {
        surface: &shape.surface,
        name,
        folder: None,
        motion: Some(&motion),
    };
    let options = ExportOptions {
        format,
        units: args.units.unwrap_or(LengthUnit::M),
        up: args.up,
        frame: None,
    };
    let out = export_file(&shape.properties, &geometry, &options)
        .map_err(|e| CliError::Input(e.to_string()))?;
    for w in &out.warnings {
        eprintln!("warning: {w}");
    }
    std::fs::write(path, &out.bytes)
        .map_err(|e| CliError::Runtime(format!("cannot write {}: {e}", path.display())))
}
