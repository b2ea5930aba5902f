//! `inertia-lab simulate`: headless rigid-body simulation of a free body, written as CSV, with
//! conservation drifts and flip count on stderr; `--compare` prints the integrator table instead,
//! `--summary` one JSON object (predicted and measured flip period, drifts, the polhode's axis).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;
use nalgebra::{Rotation3, Vector3};
use rbcore::{
    Body, Diagnostics, DriftTracker, FlipCounter, Integrator, Polhode, RotationModel, Settings,
    Simulation,
};

use massprops::MassSpec;

use super::animation::{self, AnimationArgs};
use super::error::{CliError, positive};
use super::repair::RepairArgs;
use crate::timeseries::{CSV_HEADER, QuaternionSign, Sample};
use inertia_io::bake::{BakeError, Shape, Spin};
use inertia_io::input::{Request, Resolved, Source, resolve};
use inertia_io::kind::mesh_extension_words;

/// Arguments of `simulate`. Without `--mesh` or `--inertia` it runs the canonical
/// tennis-racket case I = (1, 2, 3), ω₀ = (0.001, 10, 0.001).
#[derive(Args, Debug)]
pub struct SimulateArgs {
    /// Mesh file (.obj or .stl), or a body file of parts (.toml); its exact mass properties give
    /// the body.
    #[arg(long, conflicts_with = "inertia", help = format!("Mesh file ({}), or a body file of \
        parts (.toml); its exact mass properties give the body", mesh_extension_words()))]
    pub mesh: Option<PathBuf>,
    /// Density of the mesh's solid (default 1). Only with --mesh.
    #[arg(
        long,
        requires = "mesh",
        conflicts_with = "mass",
        allow_negative_numbers = true
    )]
    pub density: Option<f64>,
    /// Total mass (default 1 with --inertia; with --mesh the inertia scales with it).
    #[arg(long, allow_negative_numbers = true)]
    pub mass: Option<f64>,
    /// Principal moments I1,I2,I3 in ascending order (default 1,2,3).
    #[arg(long, allow_hyphen_values = true)]
    pub inertia: Option<String>,
    /// Initial angular velocity w1,w2,w3 (rad/s) in the principal body frame, moments ascending.
    #[arg(long, default_value = "0.001,10,0.001", allow_hyphen_values = true)]
    pub omega: String,
    /// Time step (s), 0 < dt <= 1.
    #[arg(long, default_value_t = 1.0 / 240.0, allow_negative_numbers = true)]
    pub dt: f64,
    /// Simulated time (s).
    #[arg(long, default_value_t = 60.0, allow_negative_numbers = true)]
    pub duration: f64,
    /// Integrator: midpoint-cayley (default), splitting, rk4, euler, midpoint, exact,
    /// engine-style, implicit-euler.
    #[arg(long, default_value_t = Integrator::MidpointCayley)]
    pub integrator: Integrator,
    /// Rotation model: full (Euler's equations) or textbook (no gyroscopic term; wrong).
    #[arg(long, default_value_t = RotationModel::Full)]
    pub model: RotationModel,
    /// Write every N-th step (the drifts and flips still use every step).
    #[arg(long, default_value_t = 1)]
    pub every: u64,
    /// Write the CSV to FILE instead of stdout.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Run every integrator on this case and print an accuracy-for-cost table instead of CSV.
    #[arg(long, conflicts_with_all = ["csv", "every", "integrator"])]
    pub compare: bool,
    /// Print one JSON object instead of the CSV: the flip period predicted from E and |L|
    /// (4K(k)/λ) and the one measured, the flips, the drifts, and the axis the polhode circles.
    #[arg(long, conflicts_with_all = ["csv", "every", "compare"])]
    pub summary: bool,
    /// How cracks and holes in the mesh are handled (with --mesh).
    #[command(flatten)]
    pub repair: RepairArgs,
    /// The motion baked into a glTF or USD file.
    #[command(flatten)]
    pub animation: AnimationArgs,
}

/// Version of the JSON object of `simulate --summary`; bumped on any incompatible change.
pub const SUMMARY_SCHEMA_VERSION: u32 = 1;

/// Parses `a,b,c` into three finite numbers.
fn triple(name: &str, s: &str) -> Result<Vector3<f64>, CliError> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let bad = || {
        CliError::Usage(format!(
            "{name} needs three comma-separated finite numbers, got '{s}'"
        ))
    };
    if parts.len() != 3 {
        return Err(bad());
    }
    let mut v = Vector3::zeros();
    for (i, p) in parts.iter().enumerate() {
        v[i] = p.parse::<f64>().map_err(|_| bad())?;
        if !v[i].is_finite() {
            return Err(bad());
        }
    }
    Ok(v)
}

/// The body at rest, from `--mesh` or `--inertia`, and with `--animation` the shape its file
/// shows.
fn build_body(args: &SimulateArgs) -> Result<(Body, Option<Shape>), CliError> {
    if let Some(m) = args.mass {
        positive("--mass", m)?;
    }
    if let Some(path) = &args.mesh {
        let density = positive("--density", args.density.unwrap_or(1.0))?;
        if massprops::io::is_body_file(path) && args.density.is_some() {
            return Err(CliError::Usage(
                "a body file gives each part's material: --density does not apply".to_owned(),
            ));
        }
        // The body `props` reports for the same file, through the same input path.
        let request = Request {
            spec: MassSpec::Density(density),
            repairs: args.repair.repairs(1.0)?,
            ..Request::default()
        };
        let resolved = resolve(Source::Path(path), &request)?;
        for line in inertia_io::report::words::warning_lines(&path.display().to_string(), &resolved)
        {
            eprintln!("{line}");
        }
        let mut props = match &resolved {
            Resolved::Mesh { analysis, .. } => analysis.properties,
            Resolved::Parts(parts) => parts.composite.properties,
        };
        let input = |e: massprops::MeshError| CliError::Input(format!("{}: {e}", path.display()));
        if let Some(m) = args.mass {
            props = props.with_mass(m).map_err(input)?;
        }
        let body = Body::from_principal(
            props.mass,
            props.principal.moments,
            props.principal.rotation,
        )
        .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
        let shape = args
            .animation
            .animation
            .is_some()
            .then(|| Shape::of(&resolved, path, props));
        return Ok((body, shape));
    }
    let moments = match &args.inertia {
        Some(s) => triple("--inertia", s)?,
        None => Vector3::new(1.0, 2.0, 3.0),
    };
    if !(moments.x <= moments.y && moments.y <= moments.z) {
        return Err(CliError::Usage(format!(
            "--inertia takes the principal moments in ascending order, got {},{},{}",
            moments.x, moments.y, moments.z
        )));
    }
    let body = Body::from_principal(args.mass.unwrap_or(1.0), moments, Rotation3::identity())
        .map_err(|e| CliError::Usage(format!("--inertia: {e}")))?;
    let shape = args
        .animation
        .animation
        .is_some()
        .then(|| Shape::principal_box(body.mass(), &body.moments()));
    Ok((body, shape))
}

/// Number of steps for `--duration`.
fn step_count(args: &SimulateArgs) -> Result<u64, CliError> {
    if !(args.dt > 0.0 && args.dt <= rbcore::MAX_DT) {
        return Err(CliError::Usage(format!(
            "--dt must be greater than 0 and at most {} s, got {}",
            rbcore::MAX_DT,
            args.dt
        )));
    }
    if !(args.duration.is_finite() && args.duration >= 0.0) {
        return Err(CliError::Usage(format!(
            "--duration must be a finite number >= 0, got {}",
            args.duration
        )));
    }
    let n = (args.duration / args.dt).round();
    if n > 1e9 {
        return Err(CliError::Usage(format!(
            "--duration/--dt asks for {n} steps; the limit is 1e9"
        )));
    }
    Ok(n as u64)
}

fn simulation(
    args: &SimulateArgs,
    body: Body,
    integrator: Integrator,
) -> Result<Simulation, CliError> {
    let settings = Settings {
        dt: args.dt,
        integrator,
        model: args.model,
        ..Settings::default()
    };
    Simulation::new(body, settings).map_err(|e| CliError::Usage(format!("--dt: {e}")))
}

fn diverged(e: rbcore::SimError) -> CliError {
    CliError::Runtime(e.to_string())
}

/// Runs `simulate`.
pub fn run(args: &SimulateArgs) -> Result<(), CliError> {
    args.animation.format()?;
    let (mut body, shape) = build_body(args)?;
    let omega = triple("--omega", &args.omega)?;
    body.set_omega_principal(omega)
        .map_err(|e| CliError::Usage(format!("--omega: {e}")))?;
    if args.every == 0 {
        return Err(CliError::Usage("--every must be at least 1".to_owned()));
    }
    let steps = step_count(args)?;
    if args.compare {
        return compare(args, body, steps);
    }
    if let Some(shape) = &shape {
        return bake(args, omega, shape);
    }
    let mut sim = simulation(args, body, args.integrator)?;
    if args.summary {
        return summary(args, &mut sim, steps);
    }
    let write_err = |e: std::io::Error| CliError::Runtime(format!("cannot write the CSV: {e}"));
    let mut out: Box<dyn Write> = match &args.csv {
        Some(path) => Box::new(BufWriter::new(File::create(path).map_err(|e| {
            CliError::Runtime(format!("cannot create {}: {e}", path.display()))
        })?)),
        None => Box::new(BufWriter::new(std::io::stdout().lock())),
    };
    writeln!(out, "{CSV_HEADER}").map_err(write_err)?;
    let mut sign = QuaternionSign::default();
    let mut write_row = |out: &mut dyn Write, d: &Diagnostics| {
        let mut s = Sample::new(d);
        sign.apply(&mut s);
        s.write_csv_row(out)
    };
    let d0 = sim.diagnostics();
    let mut drift = DriftTracker::new(&d0);
    let mut flips = FlipCounter::new();
    flips.observe(d0.time, d0.omega_principal.y);
    write_row(&mut out, &d0).map_err(write_err)?;
    for i in 1..=steps {
        sim.step().map_err(diverged)?;
        let d = sim.diagnostics();
        drift.observe(&d);
        flips.observe(d.time, d.omega_principal.y);
        if i % args.every == 0 {
            write_row(&mut out, &d).map_err(write_err)?;
        }
    }
    out.flush().map_err(write_err)?;
    eprintln!(
        "integrator {} ({} model), dt {} s, {} steps",
        args.integrator, args.model, args.dt, steps
    );
    eprintln!(
        "max relative drift of |L|:          {:.3e}",
        drift.max_l_norm()
    );
    eprintln!(
        "max relative drift of world L:      {:.3e}",
        drift.max_l_vector()
    );
    eprintln!(
        "max relative drift of E:            {:.3e}",
        drift.max_energy()
    );
    eprintln!("flips (reversals of w2):            {}", flips.flips());
    Ok(())
}

/// `simulate --animation`: the keyframes written with the shape, the drifts on stderr.
fn bake(args: &SimulateArgs, omega: Vector3<f64>, shape: &Shape) -> Result<(), CliError> {
    let spin = Spin {
        omega,
        duration: args.duration,
        fps: args.animation.fps,
        settings: Settings {
            dt: args.dt,
            integrator: args.integrator,
            model: args.model,
            ..Settings::default()
        },
    };
    let baked = inertia_io::bake::bake(shape, &spin).map_err(|e| match e {
        BakeError::Setting(e) => CliError::Usage(format!("--fps, --duration, --dt: {e}")),
        BakeError::Body(e) => CliError::Input(e.to_string()),
        BakeError::Diverged(e) => diverged(e),
    })?;
    let name = args
        .mesh
        .as_deref()
        .and_then(|p| p.file_stem())
        .map_or_else(|| "box".to_owned(), |s| s.to_string_lossy().into_owned());
    animation::write(&args.animation, &name, shape, &baked)?;
    let k = &baked.keyframes;
    eprintln!(
        "integrator {} ({} model), dt {} s, {} keyframes at {} fps over {} s",
        args.integrator,
        args.model,
        k.dt,
        k.poses.len(),
        k.fps,
        k.poses.last().map_or(0.0, |p| p.time)
    );
    eprintln!(
        "relative change of |L| and E from start to end: {:.3e}, {:.3e}",
        baked.l_change, baked.energy_change
    );
    Ok(())
}

/// `simulate --summary`: runs every step without writing the CSV and prints one JSON object.
fn summary(args: &SimulateArgs, sim: &mut Simulation, steps: u64) -> Result<(), CliError> {
    let d0 = sim.diagnostics();
    let moments = sim.body().moments();
    let l0 = sim.body().angular_momentum_principal();
    let mut drift = DriftTracker::new(&d0);
    let mut flips = FlipCounter::new();
    flips.observe(d0.time, d0.omega_principal.y);
    for _ in 0..steps {
        sim.step().map_err(diverged)?;
        let d = sim.diagnostics();
        drift.observe(&d);
        flips.observe(d.time, d.omega_principal.y);
    }
    let (axis, period) = match rbcore::polhode(&moments, &l0) {
        Polhode::Circles { axis, period, .. } => (Some(axis + 1), Some(period)),
        Polhode::Steady { axis } => (Some(axis + 1), None),
        Polhode::AtRest | Polhode::Spherical | Polhode::Separatrix => (None, None),
    };
    let object = serde_json::json!({
        "schema_version": SUMMARY_SCHEMA_VERSION,
        "integrator": args.integrator.to_string(),
        "model": args.model.to_string(),
        "dt": args.dt,
        "duration": sim.time(),
        "steps": steps,
        "moments": [moments.x, moments.y, moments.z],
        "flip_period_predicted": period,
        "flip_period_measured": flips.mean_period(),
        "flips": flips.flips(),
        "energy_drift_max_rel": drift.max_energy(),
        "L_drift_max_rel": drift.max_l_vector(),
        "L_norm_drift_max_rel": drift.max_l_norm(),
        "polhode_circles_axis": axis,
    });
    let text = serde_json::to_string_pretty(&object)
        .map_err(|e| CliError::Runtime(format!("cannot write the summary: {e}")))?;
    println!("{text}");
    Ok(())
}

/// One integrator's row of the comparison.
struct Row {
    integrator: Integrator,
    ns_per_step: f64,
    flips: usize,
    period_error: Option<f64>,
    energy_error: f64,
    omega_error: f64,
}

/// Principal-frame ω after every step (index 0 = start) plus flip and energy statistics.
fn trajectory(
    args: &SimulateArgs,
    body: Body,
    integrator: Integrator,
    steps: u64,
) -> Result<(Vec<Vector3<f64>>, FlipCounter, f64), CliError> {
    let mut sim = simulation(args, body, integrator)?;
    let d0 = sim.diagnostics();
    let mut drift = DriftTracker::new(&d0);
    let mut flips = FlipCounter::new();
    flips.observe(0.0, d0.omega_principal.y);
    let mut omegas = Vec::with_capacity(steps as usize + 1);
    omegas.push(d0.omega_principal);
    for _ in 0..steps {
        sim.step().map_err(diverged)?;
        let d = sim.diagnostics();
        drift.observe(&d);
        flips.observe(d.time, d.omega_principal.y);
        omegas.push(d.omega_principal);
    }
    Ok((omegas, flips, drift.max_energy()))
}

/// Times `steps` steps alone (no diagnostics), in ns per step.
fn time_steps(
    args: &SimulateArgs,
    body: Body,
    integrator: Integrator,
    steps: u64,
) -> Result<f64, CliError> {
    let mut sim = simulation(args, body, integrator)?;
    let start = Instant::now();
    for _ in 0..steps {
        sim.step().map_err(diverged)?;
    }
    Ok(start.elapsed().as_nanos() as f64 / steps.max(1) as f64)
}

fn compare(args: &SimulateArgs, body: Body, steps: u64) -> Result<(), CliError> {
    let l0 = body.angular_momentum_principal();
    let reference_period = rbcore::torque_free_period(&body.moments(), &l0);
    let (exact, _, _) = trajectory(args, body, Integrator::Exact, steps)?;
    let mut rows = Vec::new();
    for integrator in Integrator::ALL {
        let ns_per_step = time_steps(args, body, integrator, steps)?;
        let (omegas, flips, energy_error) = trajectory(args, body, integrator, steps)?;
        let omega_error = omegas
            .iter()
            .zip(&exact)
            .map(|(a, b)| (a - b).norm())
            .fold(0.0, f64::max);
        let period_error = flips
            .mean_period()
            .zip(reference_period)
            .map(|(p, r)| (p - r) / r);
        rows.push(Row {
            integrator,
            ns_per_step,
            flips: flips.flips(),
            period_error,
            energy_error,
            omega_error,
        });
    }
    let m = body.moments();
    println!(
        "I = ({}, {}, {}), w0 = {}, dt = {} s, {} s ({} steps), {} model",
        m.x, m.y, m.z, args.omega, args.dt, args.duration, steps, args.model
    );
    match reference_period {
        Some(p) => println!("flip period 4K(k)/lambda = {p:.9} s"),
        None => println!("flip period: none (steady rotation or separatrix)"),
    }
    println!(
        "{:<16} {:>9} {:>6} {:>13} {:>13} {:>16}",
        "integrator", "ns/step", "flips", "period err", "max |dE|/E", "max |dw| (rad/s)"
    );
    for r in &rows {
        let period = r
            .period_error
            .map_or_else(|| "n/a".to_owned(), |e| format!("{e:+.2e}"));
        println!(
            "{:<16} {:>9.1} {:>6} {:>13} {:>13.2e} {:>16.2e}",
            r.integrator.name(),
            r.ns_per_step,
            r.flips,
            period,
            r.energy_error,
            r.omega_error
        );
    }
    println!(
        "(period err: mean period from the w2 reversals vs 4K/lambda; dw vs the exact flow at the same times)"
    );
    Ok(())
}
