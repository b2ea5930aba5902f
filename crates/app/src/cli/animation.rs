//! `simulate … --animation OUT.glb|OUT.usda`: the simulated motion baked into a file that plays
//! it back ([`inertia_io::bake`]), with the body's mesh (or, for `--inertia`, a box of those
//! principal moments).

use std::path::PathBuf;

use clap::Args;
use inertia_io::bake::{self, Baked, Shape};
use inertia_io::export::{Format, LengthUnit, UpAxis};

use super::choice::choice;
use super::error::CliError;

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

impl AnimationArgs {
    /// The format the output's extension names.
    pub fn format(&self) -> Result<Option<Format>, CliError> {
        self.animation
            .as_deref()
            .map(|path| {
                bake::format_of(path).ok_or_else(|| {
                    CliError::Usage(format!(
                        "--animation writes .glb (glTF) or .usda (USD), not {}",
                        path.display()
                    ))
                })
            })
            .transpose()
    }
}

/// Writes `baked` of `shape` as `args` say.
pub fn write(
    args: &AnimationArgs,
    name: &str,
    shape: &Shape,
    baked: &Baked,
) -> Result<(), CliError> {
    let (Some(path), Some(format)) = (&args.animation, args.format()?) else {
        return Ok(());
    };
    let units = args.units.unwrap_or(LengthUnit::M);
    let out = bake::write(shape, baked, name, format, units, args.up)
        .map_err(|e| CliError::Input(e.to_string()))?;
    for w in &out.warnings {
        eprintln!("warning: {w}");
    }
    std::fs::write(path, &out.bytes)
        .map_err(|e| CliError::Runtime(format!("cannot write {}: {e}", path.display())))
}
