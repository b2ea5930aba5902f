//! `inertia-lab`: exact mass properties and rigid-body dynamics of any mesh.
//!
//! Command-line entry points of the Inertia Lab binary: `props` (mass properties of a mesh,
//! `massprops`), `simulate` (headless rigid-body simulation, `rbcore`) and `export` (mass
//! properties for engines and robot formats).

mod error;
mod export;
mod export_cmd;
mod props;
mod report;
mod simulate;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Inertia Lab: exact mass properties of any mesh, and how they shape its rotation.
#[derive(Parser, Debug)]
#[command(name = "inertia-lab", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Mass properties of a mesh (OBJ or STL): volume, mass, centre of mass, inertia tensor,
    /// principal moments and axes, the bounding-box and point-mass approximations, diagnostics.
    Props(props::PropsArgs),
    /// Headless rigid-body simulation of a free body (CSV on stdout or --csv FILE); --compare
    /// prints the integrator accuracy-for-cost table.
    Simulate(simulate::SimulateArgs),
    /// Mass properties for an engine or robot format (json, urdf, mjcf, sdf, unity, godot,
    /// unreal, rapier, gltf), with the mesh's units and up axis, and each target's frame,
    /// handedness, units and sign conventions handled.
    Export(export_cmd::ExportArgs),
}

fn main() -> ExitCode {
    // Until the desktop app exists, running the binary bare explains the commands.
    if std::env::args_os().len() == 1 {
        use clap::CommandFactory;
        let _ = Cli::command().print_help();
        return ExitCode::SUCCESS;
    }
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Props(args) => props::run(args),
        Command::Simulate(args) => simulate::run(args),
        Command::Export(args) => export_cmd::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}
