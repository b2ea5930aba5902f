//! `inertia-lab`: exact mass properties and rigid-body dynamics of any mesh.
//!
//! Without a subcommand the binary opens the desktop app (`gui`) on the flipping T-handle, or on
//! a mesh given as the argument. Command-line entry points: `props` (mass properties of a mesh,
//! `massprops`), `simulate` (headless rigid-body simulation, `rbcore`) and `export` (mass
//! properties for engines and robot formats).

mod camera;
mod clock;
mod error;
mod export;
mod export_cmd;
mod geometry;
mod gui;
mod history;
mod loader;
mod model;
mod panels;
mod picking;
mod props;
mod report;
mod settings;
mod simulate;
#[cfg(test)]
mod ui_tests;
mod view3d;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

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
    #[command(flatten)]
    gui: gui::GuiArgs,
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
    let cli = Cli::parse();
    let result = match &cli.command {
        Some(Command::Props(args)) => props::run(args),
        Some(Command::Simulate(args)) => simulate::run(args),
        Some(Command::Export(args)) => export_cmd::run(args),
        None => gui::run(&cli.gui),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}
