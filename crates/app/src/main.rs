//! `inertia-lab`: exact mass properties and rigid-body dynamics of any mesh.
//!
//! Argument parsing and dispatch only; the work is in the libraries (`inertia_lab`'s `cli` over
//! `inertia_io`, massprops, rbcore and robot). The subcommands `props`, `simulate`, `export` and
//! `audit` are the command-line tools; without one the binary opens the desktop app on the
//! flipping T-handle, or on the mesh, body or robot given as the argument.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use inertia_lab::cli::{self, CliError};

/// Inertia Lab: exact mass properties of any mesh, and how they shape its rotation.
#[derive(Parser, Debug)]
#[command(
    name = "inertia-lab",
    version,
    about,
    args_conflicts_with_subcommands = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[cfg(feature = "gui")]
    #[command(flatten)]
    gui: inertia_lab::gui::platform::GuiArgs,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Mass properties of a mesh (OBJ or STL): volume, mass, centre of mass, inertia tensor,
    /// principal moments and axes, the bounding-box and point-mass approximations, diagnostics.
    #[command(about = format!("Mass properties of a mesh ({}): volume, mass, centre of mass, \
        inertia tensor, principal moments and axes, the bounding-box and point-mass \
        approximations, diagnostics", inertia_io::kind::mesh_format_words()))]
    Props(cli::props::PropsArgs),
    /// Headless rigid-body simulation of a free body (CSV on stdout or --csv FILE); --compare
    /// prints the integrator accuracy-for-cost table.
    Simulate(cli::simulate::SimulateArgs),
    /// Mass properties for an engine or robot format (json, urdf, mjcf, sdf, unity, godot,
    /// unreal, rapier, gltf), with the mesh's units and up axis, and each target's frame,
    /// handedness, units and sign conventions handled.
    Export(cli::export::ExportArgs),
    /// Audit a robot description (URDF, MJCF or SDFormat): every link's stated inertia against the one
    /// its geometry gives, with findings (impossible, placeholder, implausible…), and --fix -o
    /// FIXED to write it back with the inertials replaced.
    Audit(cli::audit::AuditArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Some(Command::Props(args)) => cli::props::run(args),
        Some(Command::Simulate(args)) => cli::simulate::run(args),
        Some(Command::Export(args)) => cli::export::run(args),
        Some(Command::Audit(args)) => cli::audit::run(args),
        None => app(&cli),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}

#[cfg(feature = "gui")]
fn app(cli: &Cli) -> Result<(), CliError> {
    use inertia_lab::gui::platform::RunError;
    inertia_lab::gui::platform::run(&cli.gui).map_err(|e| match e {
        RunError::Usage(text) => CliError::Usage(text),
        other => CliError::Runtime(other.to_string()),
    })
}

#[cfg(not(feature = "gui"))]
fn app(_: &Cli) -> Result<(), CliError> {
    Err(CliError::Usage(
        "this inertia-lab was built without the desktop app (the `gui` feature): use a \
         subcommand (props, simulate, export; see --help), or get the app with \
         `cargo install --path crates/app` or `cargo run --release` (the feature is on by default)"
            .to_owned(),
    ))
}
