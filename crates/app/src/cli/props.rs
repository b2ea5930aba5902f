//! `inertia-lab props FILE`: mass properties of a mesh as a readable table or one JSON object.

use std::path::PathBuf;
use std::time::Instant;

use clap::{Args, ValueEnum};
use massprops::{Fill, MassSpec, Method, Repairs};

use super::error::{CliError, positive};
use super::parts::{PartArgs, body_parts, mesh_parts};
use super::repair::RepairArgs;
use super::report;

/// Mass-distribution method, as named on the command line.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum MethodArg {
    /// Solid of uniform density bounded by a closed mesh (exact, Mirtich 1996).
    Volume,
    /// Thin wall of uniform surface density on the faces (open meshes, sheets); density in kg/m².
    Shell,
    /// Equal point masses at the vertices (approximation).
    Points,
    /// Solid cuboid filling the axis-aligned bounding box (approximation).
    Bbox,
}

impl From<MethodArg> for Method {
    fn from(m: MethodArg) -> Self {
        match m {
            MethodArg::Volume => Method::Volume,
            MethodArg::Shell => Method::Shell,
            MethodArg::Points => Method::Points,
            MethodArg::Bbox => Method::BoundingBox,
        }
    }
}

/// Arguments of `props`.
#[derive(Args, Debug)]
pub struct PropsArgs {
    /// Mesh file: .obj or .stl (binary or ASCII), all its parts one body unless parts get their
    /// own material (--density-of, --material-of, --mass-of) or --parts is given; or a body
    /// file (.toml) of parts with their materials and placements.
    pub file: PathBuf,
    /// Density: mass per volume (per area for --method shell). Default 1.
    #[arg(long, conflicts_with = "mass", allow_negative_numbers = true)]
    pub density: Option<f64>,
    /// Total mass instead of a density.
    #[arg(long, allow_negative_numbers = true)]
    pub mass: Option<f64>,
    /// Multiply every coordinate by S before computing (e.g. 0.001 for a file in millimetres).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub scale: f64,
    /// How the mass is distributed.
    #[arg(long, value_enum, default_value_t = MethodArg::Volume)]
    pub method: MethodArg,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Print the time spent reading and computing to stderr.
    #[arg(long)]
    pub timings: bool,
    /// How cracks and holes in the mesh are handled.
    #[command(flatten)]
    pub repair: RepairArgs,
    /// Materials of single parts.
    #[command(flatten)]
    pub parts: PartArgs,
    /// Report the body part by part (a mesh file's parts at --density unless given their own).
    #[arg(long = "parts")]
    pub by_part: bool,
}

/// Runs `props`.
pub fn run(args: &PropsArgs) -> Result<(), CliError> {
    positive("--scale", args.scale)?;
    let spec = match (args.density, args.mass) {
        (_, Some(m)) => MassSpec::Mass(positive("--mass", m)?),
        (Some(d), None) => MassSpec::Density(positive("--density", d)?),
        (None, None) => MassSpec::Density(1.0),
    };
    let repairs = args.repair.repairs(args.scale)?;
    if massprops::is_body_file(&args.file) || args.parts.any() || args.by_part {
        return run_composite(args, spec, &repairs);
    }
    let start = Instant::now();
    let mut loaded =
        massprops::load_mesh(&args.file).map_err(|e| CliError::Input(e.to_string()))?;
    let parsed = Instant::now();
    if args.scale != 1.0 {
        loaded.mesh = loaded
            .mesh
            .map_positions(|p| p * args.scale)
            .map_err(|e| CliError::Input(format!("{}: {e}", args.file.display())))?;
    }
    let mesh = &loaded.mesh;
    let scaled = Instant::now();
    // Timed alone only on request: `analyze` integrates again below, with the diagnostics.
    let integration = args.timings.then(|| {
        let _ = massprops::solid_properties(mesh, massprops::IntegrationPath::Auto);
        scaled.elapsed()
    });
    let analyzed = Instant::now();
    let analysis = loaded
        .analyze(args.method.into(), spec, &repairs)
        .map_err(|e| CliError::Input(format!("{}: {e}", args.file.display())))?;
    let computed = Instant::now();
    let file = args.file.display().to_string();
    let lines = &loaded.face_lines;
    if args.json {
        println!("{}", report::json(&file, args.scale, &analysis, lines));
    } else {
        print!("{}", report::table(&file, args.scale, &analysis, lines));
    }
    if let Some(integration) = integration {
        let ms = |d: std::time::Duration| d.as_secs_f64() * 1e3;
        eprintln!(
            "timings ({} triangles): read+parse+weld {:.1} ms, volume integration {:.1} ms, \
             full analysis (integration, diagnostics, defects, approximations) {:.1} ms",
            mesh.triangle_count(),
            ms(parsed - start),
            ms(integration),
            ms(computed - analyzed),
        );
    }
    Ok(())
}

/// `props` of a body made of parts: a body file, or a mesh file's parts.
fn run_composite(args: &PropsArgs, spec: MassSpec, repairs: &Repairs) -> Result<(), CliError> {
    let file = args.file.display().to_string();
    let (units, parts) = if massprops::is_body_file(&args.file) {
        if args.density.is_some() || args.mass.is_some() || args.scale != 1.0 || args.parts.any() {
            return Err(CliError::Usage(
                "a body file gives each part's material, units and placement: --density, \
                 --mass, --scale and the per-part options do not apply"
                    .to_owned(),
            ));
        }
        let (body, parts) = body_parts(&args.file)?;
        (format!("metres, from a body file in {}", body.units), parts)
    } else {
        let MassSpec::Density(density) = spec else {
            return Err(CliError::Usage(
                "with parts, give each part's mass with --mass-of NAME=M (--mass is the whole \
                 body's)"
                    .to_owned(),
            ));
        };
        let mut loaded =
            massprops::load_mesh(&args.file).map_err(|e| CliError::Input(e.to_string()))?;
        if args.scale != 1.0 {
            loaded.mesh = loaded
                .mesh
                .map_positions(|p| p * args.scale)
                .map_err(|e| CliError::Input(format!("{file}: {e}")))?;
        }
        let parts = mesh_parts(&loaded, &args.parts, Fill::Solid { density }, &|d| d)?;
        ("the mesh's units times --scale".to_owned(), parts)
    };
    let body = massprops::composite(&parts, repairs)
        .map_err(|e| CliError::Input(format!("{file}: {e}")))?;
    if args.json {
        println!("{}", report::composite_json(&file, &units, &body));
    } else {
        print!("{}", report::composite_table(&file, &units, &body));
    }
    Ok(())
}
