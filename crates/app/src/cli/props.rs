//! `inertia-lab props FILE`: mass properties of a mesh as a readable table or one JSON object.

use std::path::PathBuf;
use std::time::Instant;

use clap::{Args, ValueEnum};
use massprops::{MassSpec, Method};

use super::error::{CliError, positive};
use super::parts::PartArgs;
use super::repair::RepairArgs;
use inertia_io::input::{Request, Resolved, Source, resolve};
use inertia_io::kind::mesh_extension_words;
use inertia_io::report::{json, table};

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
    #[arg(help = format!("Mesh file: {} (STL binary or ASCII), all its parts one body unless \
        parts get their own material (--density-of, --material-of, --mass-of) or --parts is \
        given; or a body file (.toml) of parts with their materials and placements",
        mesh_extension_words()))]
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
    let body_file = massprops::io::is_body_file(&args.file);
    if body_file
        && (args.density.is_some() || args.mass.is_some() || args.scale != 1.0 || args.parts.any())
    {
        return Err(CliError::Usage(
            "a body file gives each part's material, units and placement: --density, --mass, \
             --scale and the per-part options do not apply"
                .to_owned(),
        ));
    }
    let request = Request {
        method: args.method.into(),
        spec,
        scale: args.scale,
        repairs: args.repair.repairs(args.scale)?,
        parts: args.parts.materials()?,
        by_part: args.by_part,
        density_factor: 1.0,
    };
    let resolved = resolve(Source::Path(&args.file), &request)?;
    let file = args.file.display().to_string();
    match &resolved {
        Resolved::Mesh {
            file: read,
            analysis,
        } => {
            let lines = &read.face_lines;
            if args.json {
                println!("{}", json::single(&file, args.scale, analysis, lines));
            } else {
                print!("{}", table::single(&file, args.scale, analysis, lines));
            }
            if args.timings {
                timings(args, &request)?;
            }
        }
        Resolved::Parts(parts) => {
            let units = match parts.body_file_units {
                Some(unit) => format!("metres, from a body file in {unit}"),
                None => "the mesh's units times --scale".to_owned(),
            };
            if args.json {
                println!("{}", json::composite(&file, &units, &parts.composite));
            } else {
                print!("{}", table::composite(&file, &units, &parts.composite));
            }
        }
    }
    Ok(())
}

/// `--timings`: each stage of the report timed alone on stderr (read, parse and weld; the volume
/// integration; the full analysis), run again so that the report itself is never slowed.
fn timings(args: &PropsArgs, request: &Request) -> Result<(), CliError> {
    let ms = |d: std::time::Duration| d.as_secs_f64() * 1e3;
    let start = Instant::now();
    let file = massprops::load_mesh(&args.file).map_err(|e| CliError::Input(e.to_string()))?;
    let parsed = start.elapsed();
    let mesh = &file.mesh;
    let start = Instant::now();
    let _ = massprops::solid::solid_properties(mesh, massprops::integrals::IntegrationPath::Auto);
    let integration = start.elapsed();
    let start = Instant::now();
    let _ = file.analyze(request.method, request.spec, &request.repairs);
    let analysis = start.elapsed();
    let peak = crate::platform::memory()
        .map(|m| {
            format!(
                ", peak resident memory {:.1} MB",
                m.peak_kib as f64 / 1024.0
            )
        })
        .unwrap_or_default();
    eprintln!(
        "timings ({} triangles): read+parse+weld {:.1} ms, volume integration {:.1} ms, \
         full analysis (integration, diagnostics, defects, approximations) {:.1} ms{peak}",
        mesh.triangle_count(),
        ms(parsed),
        ms(integration),
        ms(analysis),
    );
    Ok(())
}
