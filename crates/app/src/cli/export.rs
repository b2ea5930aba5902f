//! `inertia-lab export FILE --format F`: mass properties written for an engine or robot format.

use std::path::PathBuf;

use clap::Args;
use massprops::{MassProperties, MassSpec, Material, Method};

use super::choice::choice;
use super::error::{CliError, positive};
use super::parts::PartArgs;
use super::repair::RepairArgs;
use inertia_io::export::{
    ExportError, ExportOptions, Format, Frame, Geometry, LengthUnit, Surface, UpAxis,
    density_per_cubic_unit, export_file,
};
use inertia_io::input::{Request, Resolved, Source, resolve};
use inertia_io::kind::mesh_extension_words;

/// The default density, water's (kg/m³).
const WATER: f64 = 1000.0;

/// Arguments of `export`.
#[derive(Args, Debug)]
pub struct ExportArgs {
    /// Mesh file: .obj or .stl (binary or ASCII), all its parts one body unless parts get their
    /// own material (--density-of, --material-of, --mass-of); or a body file (.toml) of parts
    /// with their materials, placements and units.
    #[arg(help = format!("Mesh file: {} (STL binary or ASCII), all its parts one body unless \
        parts get their own material (--density-of, --material-of, --mass-of); or a body file \
        (.toml) of parts with their materials, placements and units", mesh_extension_words()))]
    pub file: PathBuf,
    /// Output format.
    #[arg(long, value_parser = choice::<Format>())]
    pub format: Format,
    /// Length unit of the mesh's coordinates (OBJ and STL carry none): m, cm, mm, in or ft.
    /// Default m; a body file gives its own.
    #[arg(long, value_parser = parse_unit)]
    pub units: Option<LengthUnit>,
    /// Which mesh axis points up.
    #[arg(long, value_parser = choice::<UpAxis>(), default_value = "y")]
    pub up: UpAxis,
    /// Density in kg/m³ (default 1000, water).
    #[arg(long, conflicts_with_all = ["mass", "material"], allow_negative_numbers = true)]
    pub density: Option<f64>,
    /// Total mass in kg instead of a density.
    #[arg(long, conflicts_with = "material", allow_negative_numbers = true)]
    pub mass: Option<f64>,
    /// A named density: foam 30, wood 600, water 1000, pla 1240, rubber 1500, aluminium 2700,
    /// steel 7850, brass 8500, lead 11340 kg/m³.
    #[arg(long, value_parser = parse_material)]
    pub material: Option<Material>,
    /// Axes the target reads the inertia in (about the centre of mass either way):
    /// com-principal (diagonal + rotation) or origin (the mesh's own axes). Default: origin for
    /// json, urdf, sdf, mjcf and godot; com-principal, the only choice, for the others.
    #[arg(long, value_parser = choice::<Frame>())]
    pub frame: Option<Frame>,
    /// Write to FILE instead of standard output.
    #[arg(long, short)]
    pub output: Option<PathBuf>,
    /// How cracks and holes in the mesh are handled.
    #[command(flatten)]
    pub repair: RepairArgs,
    /// Materials of single parts.
    #[command(flatten)]
    pub parts: PartArgs,
}

fn parse_unit(symbol: &str) -> Result<LengthUnit, String> {
    symbol
        .parse()
        .map_err(|e: massprops::UnknownUnit| e.to_string())
}

fn parse_material(name: &str) -> Result<Material, String> {
    super::parts::preset(name)
}

/// Runs `export`.
pub fn run(args: &ExportArgs) -> Result<(), CliError> {
    let units = args.units.unwrap_or(LengthUnit::M);
    let per_unit = |rho: f64| density_per_cubic_unit(rho, units);
    let spec = match (args.density, args.mass, args.material) {
        (_, Some(m), _) => MassSpec::Mass(positive("--mass", m)?),
        (Some(d), None, _) => MassSpec::Density(per_unit(positive("--density", d)?)),
        (None, None, Some(material)) => MassSpec::Density(per_unit(material.density)),
        (None, None, None) => MassSpec::Density(per_unit(WATER)),
    };
    if massprops::io::is_body_file(&args.file) {
        let given = args.density.is_some() || args.mass.is_some() || args.material.is_some();
        if given || args.units.is_some() || args.parts.any() {
            return Err(CliError::Usage(
                "a body file gives each part's material, its units and placements: --density, \
                 --mass, --material, --units and the per-part options do not apply"
                    .to_owned(),
            ));
        }
    }
    let request = Request {
        method: Method::Volume,
        spec,
        scale: 1.0,
        repairs: args.repair.repairs(1.0)?,
        parts: args.parts.materials()?,
        by_part: false,
        density_factor: density_per_cubic_unit(1.0, units),
    };
    let resolved = resolve(Source::Path(&args.file), &request)?;
    let file = args.file.display();
    let (properties, units) = match &resolved {
        Resolved::Mesh { analysis, .. } => {
            // Mass given: make it exact (density = m / V, then m = ρV, can miss by an ulp).
            let properties = match spec {
                MassSpec::Mass(m) => analysis
                    .properties
                    .with_mass(m)
                    .map_err(|e| CliError::Input(format!("{file}: {e}")))?,
                MassSpec::Density(_) => analysis.properties,
            };
            (properties, units)
        }
        Resolved::Parts(parts) => {
            // A body file's parts are in metres.
            let units = if parts.body_file_units.is_some() {
                LengthUnit::M
            } else {
                units
            };
            (parts.composite.properties, units)
        }
    };
    for line in inertia_io::report::words::warning_lines(&file.to_string(), &resolved) {
        eprintln!("{line}");
    }
    let surface = Surface::of(&resolved, &args.file);
    write(args, &properties, &surface, units)
}

/// Exports `properties` (lengths in `units`) as the arguments say.
fn write(
    args: &ExportArgs,
    properties: &MassProperties,
    surface: &Surface,
    units: LengthUnit,
) -> Result<(), CliError> {
    let file = args.file.display();
    if args.format == Format::Glb && args.output.is_none() {
        return Err(CliError::Usage(
            "glb is a binary file: name it with --output FILE.glb".to_owned(),
        ));
    }
    // Unity names a component's class after its file: the script's class is the output's name.
    let named = match (&args.output, args.format) {
        (Some(output), Format::UnityScript) => output.as_path(),
        _ => args.file.as_path(),
    };
    let name = named
        .file_stem()
        .map_or_else(|| "body".to_owned(), |s| s.to_string_lossy().into_owned());
    let geometry = Geometry {
        surface,
        name: &name,
        folder: args.output.as_deref().map(|o| {
            o.parent()
                .filter(|p| !p.as_os_str().is_empty())
                .unwrap_or(std::path::Path::new("."))
        }),
        motion: None,
    };
    let options = ExportOptions {
        format: args.format,
        units,
        up: args.up,
        frame: args.frame,
    };
    let out = export_file(properties, &geometry, &options).map_err(|e: ExportError| {
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
        Some(path) => std::fs::write(path, &out.bytes)
            .map_err(|e| CliError::Runtime(format!("cannot write {}: {e}", path.display()))),
        None => std::io::Write::write_all(&mut std::io::stdout(), &out.bytes)
            .map_err(|e| CliError::Runtime(format!("cannot write the output: {e}"))),
    }
}
