//! `inertia-lab export FILE --format F`: mass properties written for an engine or robot format.

use std::path::PathBuf;

use clap::Args;
use massprops::{MassSpec, Method};

use super::error::{CliError, positive};
use super::repair::RepairArgs;
use crate::export::{
    ExportError, ExportOptions, Format, Frame, LengthUnit, Material, UpAxis,
    density_per_cubic_unit, export,
};

/// Arguments of `export`.
#[derive(Args, Debug)]
pub struct ExportArgs {
    /// Mesh file: .obj or .stl (binary or ASCII). All objects and groups form one body.
    pub file: PathBuf,
    /// Output format.
    #[arg(long, value_enum)]
    pub format: Format,
    /// Length unit of the mesh's coordinates (OBJ and STL carry none).
    #[arg(long, value_enum, default_value = "m")]
    pub units: LengthUnit,
    /// Which mesh axis points up.
    #[arg(long, value_enum, default_value = "y")]
    pub up: UpAxis,
    /// Density in kg/m³ (default 1000, water).
    #[arg(long, conflicts_with_all = ["mass", "material"], allow_negative_numbers = true)]
    pub density: Option<f64>,
    /// Total mass in kg instead of a density.
    #[arg(long, conflicts_with = "material", allow_negative_numbers = true)]
    pub mass: Option<f64>,
    /// A named density: water 1000, pla 1240, aluminium 2700, steel 7850, wood 600 kg/m³.
    #[arg(long, value_enum)]
    pub material: Option<Material>,
    /// Axes the target reads the inertia in (about the centre of mass either way):
    /// com-principal (diagonal + rotation) or origin (the mesh's own axes). Default: origin for
    /// json, urdf, sdf, mjcf and godot; com-principal, the only choice, for the others.
    #[arg(long, value_enum)]
    pub frame: Option<Frame>,
    /// Write to FILE instead of standard output.
    #[arg(long, short)]
    pub output: Option<PathBuf>,
    /// How cracks and holes in the mesh are handled.
    #[command(flatten)]
    pub repair: RepairArgs,
}

/// Runs `export`.
pub fn run(args: &ExportArgs) -> Result<(), CliError> {
    let spec = match (args.density, args.mass, args.material) {
        (_, Some(m), _) => MassSpec::Mass(positive("--mass", m)?),
        (Some(d), None, _) => MassSpec::Density(density_per_cubic_unit(
            positive("--density", d)?,
            args.units,
        )),
        (None, None, Some(material)) => {
            MassSpec::Density(density_per_cubic_unit(material.density(), args.units))
        }
        (None, None, None) => MassSpec::Density(density_per_cubic_unit(
            Material::Water.density(),
            args.units,
        )),
    };
    let file = args.file.display();
    let repairs = args.repair.repairs(1.0)?;
    let loaded = massprops::load_mesh(&args.file).map_err(|e| CliError::Input(e.to_string()))?;
    let analysis = loaded
        .analyze(Method::Volume, spec, &repairs)
        .map_err(|e| CliError::Input(format!("{file}: {e}")))?;
    // Mass given: make it exact (density = m / V, then m = ρV, can miss by an ulp).
    let properties = match spec {
        MassSpec::Mass(m) => analysis
            .properties
            .with_mass(m)
            .map_err(|e| CliError::Input(format!("{file}: {e}")))?,
        MassSpec::Density(_) => analysis.properties,
    };
    for w in &analysis.warnings {
        eprintln!(
            "warning: {file}: {}",
            super::report::warning_text(w, &loaded.face_lines)
        );
    }
    let options = ExportOptions {
        format: args.format,
        units: args.units,
        up: args.up,
        frame: args.frame,
    };
    let out = export(&properties, &options).map_err(|e: ExportError| {
        if e.is_usage() {
            CliError::Usage(e.to_string())
        } else {
            CliError::Input(format!("{file}: {e}"))
        }
    })?;
    for w in &out.warnings {
        eprintln!("warning: {w}");
    }
    match &args.output {
        Some(path) => std::fs::write(path, &out.text)
            .map_err(|e| CliError::Runtime(format!("cannot write {}: {e}", path.display()))),
        None => {
            print!("{}", out.text);
            Ok(())
        }
    }
}
