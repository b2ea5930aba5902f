//! The lab's model: the loaded body, the `rbcore` simulation, the plotted history and the user's
//! settings. Panels and the 3D view never change it directly: they record [`Command`]s, and
//! [`Lab::apply`] is the one place that carries them out (as MuJoCo's `simulate` viewer does).

use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};

use massprops::{Comparison, MassProperties};
use nalgebra::{Point3, UnitQuaternion, Vector3};
use rbcore::{Body, SimError, Simulation, SoftString};

use crate::clock::FrameClock;
use crate::history::History;
use crate::loader::{Dialog, DialogPurpose, LoadedBody, Loading};
use crate::picking::{Hit, Ray};
use crate::settings::{AppSettings, InertiaSource, MassSpec};

/// How long the ΔL arrow of a poke stays on screen.
const POKE_FLASH: Duration = Duration::from_millis(1500);

/// Relative size of the perturbation the spin presets add on the other two axes: enough for the
/// T-handle to flip within about three seconds at the default 8 rad/s.
const PERTURBATION: f64 = 0.02;

/// Most samples kept (about 58 MB): 600 s at the default step; a tiny step shortens the history
/// rather than exhausting memory.
const MAX_HISTORY: usize = 400_000;

/// An intent recorded by the UI, applied by [`Lab::apply`].
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// Pause or resume.
    TogglePause,
    /// One fixed step (pauses first).
    Step,
    /// Back to the start state of the current body and preset.
    Reset,
    /// Spin about principal axis 0, 1 or 2 (moments ascending) with a small perturbation.
    Preset(usize),
    /// New settings (the panel edits a copy); applied live.
    Settings(Box<AppSettings>),
    /// Settings back to defaults.
    ResetSettings,
    /// Load a mesh file on the worker thread.
    LoadFile(PathBuf),
    /// Load a built-in sample by label.
    LoadSample(String),
    /// Open the native file dialog to choose a mesh.
    OpenDialog,
    /// Write the plot history as CSV.
    ExportCsv(PathBuf),
    /// Open the native dialog to choose where to write the CSV.
    ExportCsvDialog,
    /// Poke: impulse of the set magnitude at a world point, along `direction` (the view ray).
    Poke {
        /// World point on the surface.
        point: Point3<f64>,
        /// Direction of the impulse (normalised here).
        direction: Vector3<f64>,
    },
    /// Attach the string at a world point on the surface.
    Grab(Point3<f64>),
    /// Move the string's free end.
    Drag(Point3<f64>),
    /// Detach the string.
    Release,
    /// Dismiss the message line.
    DismissMessage,
}

/// A line for the user: an error (red) or information.
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    /// The text.
    pub text: String,
    /// Whether something went wrong.
    pub error: bool,
}

/// The last poke, for the ΔL arrow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PokeFlash {
    /// Where the impulse was applied (world).
    pub point: Point3<f64>,
    /// The impulse J (N·s).
    pub impulse: Vector3<f64>,
    /// ΔL = r × J (world).
    pub delta_l: Vector3<f64>,
    /// When to stop drawing it.
    pub until: Instant,
}

/// The string as drawn: both ends and the force it currently applies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StringView {
    /// Attachment point on the body (world).
    pub attachment: Point3<f64>,
    /// The pointer end (world).
    pub target: Point3<f64>,
    /// Force on the body (N), the step's impulse over `dt`.
    pub force: Vector3<f64>,
}

/// The model of the whole app.
#[derive(Debug)]
pub struct Lab {
    /// The user's settings (persisted by the app).
    pub settings: AppSettings,
    body: Arc<LoadedBody>,
    /// Exact, bounding-box and point-mass properties at the current scale and mass.
    props: [MassProperties; 3],
    sim: Simulation,
    history: History,
    clock: FrameClock,
    preset_axis: usize,
    loading: Option<Loading>,
    dialog: Option<Dialog>,
    message: Option<Message>,
    poke: Option<PokeFlash>,
    /// The string as last set on the simulation (which has no read accessor for it).
    string: Option<SoftString>,
    /// Bumped whenever the body's mesh changes, so the 3D view re-uploads it.
    generation: u64,
    /// Called by worker threads when they have news (a repaint request in the app).
    waker: Waker,
}

/// A callback for worker threads.
#[derive(Clone)]
struct Waker(Arc<dyn Fn() + Send + Sync>);

impl std::fmt::Debug for Waker {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Waker")
    }
}

impl Lab {
    /// The lab on the default T-handle with `settings` (falls back to defaults if they cannot
    /// build a simulation).
    ///
    /// # Errors
    /// Only if the built-in T-handle cannot be analysed (a bug).
    pub fn new(settings: AppSettings) -> Result<Self, String> {
        let body = Arc::new(LoadedBody::t_handle()?);
        let (settings, props, sim) = match Self::start(&body, &settings, 1) {
            Ok((props, sim)) => (settings, props, sim),
            Err(_) => {
                let defaults = AppSettings::default();
                let (props, sim) = Self::start(&body, &defaults, 1)?;
                (defaults, props, sim)
            }
        };
        let history = History::new(capacity(&settings));
        Ok(Self {
            settings,
            body,
            props,
            sim,
            history,
            clock: FrameClock::new(),
            preset_axis: 1,
            loading: None,
            dialog: None,
            message: None,
            poke: None,
            string: None,
            generation: 0,
            waker: Waker(Arc::new(|| {})),
        })
    }

    /// Sets what worker threads call when they have news.
    pub fn set_waker(&mut self, waker: impl Fn() + Send + Sync + 'static) {
        self.waker = Waker(Arc::new(waker));
    }

    /// Mass properties and a simulation spinning about principal axis `axis`.
    fn start(
        body: &LoadedBody,
        settings: &AppSettings,
        axis: usize,
    ) -> Result<([MassProperties; 3], Simulation), String> {
        let props = scaled_properties(body, settings)?;
        let used = &props[source_index(settings.body.source)];
        let mut b =
            Body::from_principal(used.mass, used.principal.moments, used.principal.rotation)
                .map_err(|e| format!("{}: {e}", body.name))?;
        // Start with the mesh axes on the world axes (orientation maps principal → world).
        b.set_orientation(UnitQuaternion::from_rotation_matrix(
            &used.principal.rotation,
        ))
        .map_err(|e| e.to_string())?;
        let rate = settings.body.spin_rate;
        let mut omega = Vector3::repeat(PERTURBATION * rate);
        omega[axis.min(2)] = rate;
        b.set_omega_principal(omega)
            .map_err(|e| format!("spin rate: {e}"))?;
        let sim = Simulation::new(b, settings.physics.to_sim()).map_err(|e| e.to_string())?;
        Ok((props, sim))
    }

    /// Replaces the simulation by a fresh start (keeps the paused flag).
    fn restart(&mut self) -> Result<(), String> {
        let paused = self.sim.is_paused();
        let (props, mut sim) = Self::start(&self.body, &self.settings, self.preset_axis)?;
        if paused {
            sim.pause();
        }
        self.props = props;
        self.sim = sim;
        self.history.clear();
        self.history.push(&self.sim.diagnostics());
        self.poke = None;
        self.string = None;
        Ok(())
    }

    /// Applies every command in order.
    pub fn apply_all(&mut self, commands: impl IntoIterator<Item = Command>) {
        for c in commands {
            self.apply(c);
        }
    }

    /// Carries out one command; failures become the message line, the model stays usable.
    pub fn apply(&mut self, command: Command) {
        if let Err(e) = self.try_apply(command) {
            self.message = Some(Message {
                text: e,
                error: true,
            });
        }
    }

    fn try_apply(&mut self, command: Command) -> Result<(), String> {
        match command {
            Command::TogglePause => {
                if self.sim.is_paused() {
                    self.sim.resume();
                } else {
                    self.sim.pause();
                }
                self.clock.stop();
            }
            Command::Step => {
                self.sim.pause();
                self.clock.stop();
                let result = self.sim.step();
                self.after_steps(1, result)?;
            }
            Command::Reset => self.restart()?,
            Command::Preset(axis) => {
                self.preset_axis = axis.min(2);
                self.restart()?;
            }
            Command::Settings(s) => self.set_settings(*s)?,
            Command::ResetSettings => self.set_settings(AppSettings::default())?,
            Command::LoadFile(path) => {
                let waker = self.waker.clone();
                self.loading = Some(Loading::start(path, move || (waker.0)()));
            }
            Command::LoadSample(label) => {
                let body = LoadedBody::sample(&label)?;
                self.install(body)?;
            }
            Command::OpenDialog | Command::ExportCsvDialog => {
                let purpose = if command == Command::OpenDialog {
                    DialogPurpose::OpenMesh
                } else {
                    DialogPurpose::SaveCsv
                };
                let waker = self.waker.clone();
                self.dialog = Some(Dialog::open(purpose, move || (waker.0)()));
            }
            Command::ExportCsv(path) => {
                let write = || -> std::io::Result<()> {
                    let mut out = std::io::BufWriter::new(std::fs::File::create(&path)?);
                    self.history.write_csv(&mut out)?;
                    std::io::Write::flush(&mut out)
                };
                write().map_err(|e| format!("cannot write {}: {e}", path.display()))?;
                self.info(format!(
                    "wrote {} samples to {}",
                    self.history.samples().len(),
                    path.display()
                ));
            }
            Command::Poke { point, direction } => {
                let n = direction.norm();
                if !(n.is_finite() && n > 0.0) {
                    return Err("poke: the view ray has no direction".to_owned());
                }
                let magnitude = self.poke_impulse();
                let j = direction * (magnitude / n);
                let r = point - self.sim.body().position();
                self.sim
                    .poke(&point, &j)
                    .map_err(|e| format!("poke: {e}"))?;
                self.poke = Some(PokeFlash {
                    point,
                    impulse: j,
                    delta_l: r.cross(&j),
                    until: Instant::now() + POKE_FLASH,
                });
                self.history.mark_disturbance();
            }
            Command::Grab(point) => {
                let i = &self.settings.interaction;
                let attachment = self.sim.body().point_to_body(&point);
                let string = SoftString::new(
                    point,
                    attachment,
                    i.string_frequency,
                    i.string_damping,
                    self.string_max_force(),
                )
                .map_err(|e| format!("string: {e}"))?;
                self.string = Some(string);
                self.sim.set_string(self.string);
                self.history.mark_disturbance();
            }
            Command::Drag(target) => {
                if let Some(s) = &mut self.string {
                    s.set_target(target).map_err(|e| format!("string: {e}"))?;
                    self.sim.set_string(self.string);
                }
            }
            Command::Release => {
                if self.string.take().is_some() {
                    self.sim.set_string(None);
                    self.history.mark_disturbance();
                }
            }
            Command::DismissMessage => self.message = None,
        }
        Ok(())
    }

    /// Applies new settings: simulation settings, history bound, and (if size, mass or source
    /// changed) new mass properties with p and L kept, as an instantaneous change of mass
    /// distribution conserves them.
    fn set_settings(&mut self, new: AppSettings) -> Result<(), String> {
        let props = scaled_properties(&self.body, &new)?;
        let (old_src, new_src) = (
            source_index(self.settings.body.source),
            source_index(new.body.source),
        );
        let used = &props[new_src];
        // Checked before anything changes, so a rejected value leaves the model as it was.
        Body::from_principal(used.mass, used.principal.moments, used.principal.rotation)
            .map_err(|e| format!("mass properties rejected: {e}"))?;
        self.sim
            .set_settings(new.physics.to_sim())
            .map_err(|e| format!("setting rejected: {e}"))?;
        // The body frame's origin is the used centre of mass. A new source moves it within the
        // mesh by `shift`: the pose moves with it so the mesh stays where it is on screen (a new
        // size or mass keeps the centre of mass in place and the body grows about it).
        let shift = props[new_src].center_of_mass - props[old_src].center_of_mass;
        if new.body != self.settings.body {
            let b = self.sim.body_mut();
            let position = b.position() + b.body_orientation() * shift;
            b.set_mass_properties(used.mass, used.principal.moments, used.principal.rotation)
                .map_err(|e| format!("mass properties rejected: {e}"))?;
            b.set_position(position).map_err(|e| e.to_string())?;
            self.history.mark_disturbance();
        }
        if new.physics != self.settings.physics {
            self.history.mark_disturbance();
        }
        if let Some(string) = &mut self.string {
            let i = &new.interaction;
            *string = SoftString::new(
                string.target(),
                string.attachment() - shift,
                i.string_frequency,
                i.string_damping,
                used.mass * i.string_max_accel,
            )
            .map_err(|e| format!("string: {e}"))?;
            self.sim.set_string(self.string);
        }
        self.props = props;
        self.history.set_capacity(capacity(&new));
        self.settings = new;
        Ok(())
    }

    /// Makes `body` current, keeping the old one if the new one cannot be simulated.
    fn install(&mut self, body: LoadedBody) -> Result<(), String> {
        let body = Arc::new(body);
        let (props, sim) = Self::start(&body, &self.settings, self.preset_axis)?;
        let paused = self.sim.is_paused();
        self.body = body;
        self.props = props;
        self.sim = sim;
        if paused {
            self.sim.pause();
        }
        self.generation += 1;
        self.history.clear();
        self.history.push(&self.sim.diagnostics());
        self.poke = None;
        self.string = None;
        self.info(format!(
            "loaded {} ({} triangles)",
            self.body.name,
            self.body.mesh.triangles.len()
        ));
        Ok(())
    }

    fn info(&mut self, text: String) {
        self.message = Some(Message { text, error: false });
    }

    /// Runs one frame: collects finished loads and dialogs, then advances the simulation by the
    /// scaled wall-clock time since the last frame, sampling the history once per step.
    pub fn frame(&mut self, now: Instant) {
        if let Some(result) = self.loading.as_mut().and_then(Loading::poll) {
            self.loading = None;
            self.finish_load(result);
        }
        if let Some(answer) = self.dialog.as_ref().and_then(Dialog::poll) {
            let purpose = self.dialog.take().map(|d| d.purpose);
            match (purpose, answer) {
                (Some(DialogPurpose::OpenMesh), Some(path)) => self.apply(Command::LoadFile(path)),
                (Some(DialogPurpose::SaveCsv), Some(path)) => self.apply(Command::ExportCsv(path)),
                // rfd reports a cancel and a missing XDG desktop portal alike.
                _ => self.info(
                    "no file chosen (if no dialog appeared, this desktop has no file-dialog \
                     portal: type a path or drop the file on the window)"
                        .to_owned(),
                ),
            }
        }
        if self.poke.is_some_and(|p| now >= p.until) {
            self.poke = None;
        }
        if self.sim.is_paused() {
            self.clock.stop();
            return;
        }
        let frame_dt = self.clock.tick(now, self.settings.physics.time_scale);
        self.advance(frame_dt);
    }

    /// Advances by `frame_dt` simulated seconds through the simulation's accumulator, fed one
    /// step's worth at a time so that every step is sampled; at most the catch-up cap of steps.
    pub fn advance(&mut self, frame_dt: f64) {
        let dt = self.sim.settings().dt;
        let cap = f64::from(self.sim.settings().max_catch_up_steps) * dt;
        let mut remaining = frame_dt.min(cap);
        while remaining > 0.0 {
            let slice = remaining.min(dt);
            remaining -= slice;
            let result = self.sim.advance(slice).map(|a| a.steps);
            let steps = *result.as_ref().unwrap_or(&0);
            if self.after_steps(steps, result.map(|_| ())).is_err() {
                return;
            }
        }
    }

    /// Runs `seconds` of simulated time at once (sampled every step), e.g. to fill the plots
    /// before a benchmark.
    pub fn advance_for(&mut self, seconds: f64) {
        let chunk = f64::from(self.sim.settings().max_catch_up_steps) * self.sim.settings().dt;
        let mut left = seconds;
        while left > 0.0 && !self.sim.is_paused() {
            self.advance(left.min(chunk));
            left -= chunk;
        }
    }

    /// Blocks until a running load has finished (benchmarks and tests), then installs it.
    pub fn wait_for_load(&mut self) {
        while let Some(loading) = &mut self.loading {
            if let Some(result) = loading.poll() {
                self.loading = None;
                self.finish_load(result);
            } else {
                std::thread::sleep(Duration::from_millis(2));
            }
        }
    }

    fn finish_load(&mut self, result: Result<LoadedBody, String>) {
        let outcome = result.and_then(|body| self.install(body));
        if let Err(e) = outcome {
            self.message = Some(Message {
                text: format!("{e} (the current body is kept)"),
                error: true,
            });
        }
    }

    /// Records the state after steps ran, or reports a halt (divergence) and pauses.
    fn after_steps(&mut self, steps: u32, result: Result<(), SimError>) -> Result<(), String> {
        match result {
            Ok(()) => {
                if steps > 0 {
                    self.history.push(&self.sim.diagnostics());
                }
                Ok(())
            }
            Err(e) => {
                self.sim.pause();
                let text = format!("simulation stopped: {e}. Press Reset.");
                self.message = Some(Message {
                    text: text.clone(),
                    error: true,
                });
                Err(text)
            }
        }
    }

    /// The simulation (read-only).
    pub fn sim(&self) -> &Simulation {
        &self.sim
    }
    /// The loaded body.
    pub fn body(&self) -> &LoadedBody {
        &self.body
    }
    /// Mesh generation counter (changes when a new mesh is installed).
    pub fn generation(&self) -> u64 {
        self.generation
    }
    /// The plotted history.
    pub fn history(&self) -> &History {
        &self.history
    }
    /// The message line.
    pub fn message(&self) -> Option<&Message> {
        self.message.as_ref()
    }
    /// The running load, if any.
    pub fn loading(&self) -> Option<&Loading> {
        self.loading.as_ref()
    }
    /// Whether a dialog is open.
    pub fn dialog_open(&self) -> bool {
        self.dialog.is_some()
    }
    /// Mass properties per source (exact, bounding box, point masses) at the current scale/mass.
    pub fn properties(&self, source: InertiaSource) -> &MassProperties {
        &self.props[source_index(source)]
    }
    /// The mass properties the simulation uses.
    pub fn used_properties(&self) -> &MassProperties {
        self.properties(self.settings.body.source)
    }
    /// How an approximation compares with the exact properties.
    pub fn comparison(&self, source: InertiaSource) -> Comparison {
        self.properties(source)
            .compare_to(self.properties(InertiaSource::Exact))
    }
    /// Whether anything moves without input (the app repaints continuously only then).
    pub fn is_animating(&self) -> bool {
        !self.sim.is_paused()
            || self.loading.is_some()
            || self.dialog.is_some()
            || self.poke.is_some()
    }
    /// The current poke flash.
    pub fn poke_flash(&self) -> Option<PokeFlash> {
        self.poke
    }
    /// Poke impulse magnitude (N·s) for the current mass.
    pub fn poke_impulse(&self) -> f64 {
        self.used_properties().mass * self.settings.interaction.poke_delta_v
    }
    /// String force cap (N) for the current mass.
    pub fn string_max_force(&self) -> f64 {
        self.used_properties().mass * self.settings.interaction.string_max_accel
    }
    /// The string, if attached.
    pub fn string_view(&self) -> Option<StringView> {
        let sim = &self.sim;
        let s = self.string?;
        let dt = sim.settings().dt;
        Some(StringView {
            attachment: sim.body().point_to_world(&s.attachment()),
            target: s.target(),
            force: s.impulse(sim.body(), dt) / dt,
        })
    }
    /// Uniform scale of the mesh.
    pub fn scale(&self) -> f64 {
        self.settings.body.scale
    }
    /// Mesh coordinates → world: `x ↦ R (s·x − c) + r` with `c` the used centre of mass.
    pub fn mesh_to_world(&self, x: &Point3<f64>) -> Point3<f64> {
        let c = self.used_properties().center_of_mass;
        self.sim
            .body()
            .point_to_world(&Point3::from(x.coords * self.scale() - c.coords))
    }
    /// Ray-casts the body: the world ray is mapped into mesh coordinates (the body is rigid, so
    /// this equals intersecting the world-space mesh) and the hit mapped back.
    pub fn pick(&self, ray: &Ray) -> Option<Hit> {
        let s = self.scale();
        let c = self.used_properties().center_of_mass;
        let b = self.sim.body();
        let to_mesh = |p: &Point3<f64>| Point3::from((b.point_to_body(p).coords + c.coords) / s);
        let local = Ray {
            origin: to_mesh(&ray.origin),
            dir: b.vector_to_body(&ray.dir) / s,
        };
        let hit = self.body.bvh.pick(&self.body.mesh, &local)?;
        Some(Hit {
            point: self.mesh_to_world(&hit.point),
            ..hit
        })
    }
    /// Bounding-sphere centre (world) and radius of the scaled body.
    pub fn bounding_sphere(&self) -> (Point3<f64>, f64) {
        let (c, r) = self.body.sphere;
        (self.mesh_to_world(&c), r * self.scale())
    }
}

/// History capacity for the configured seconds at the configured step.
fn capacity(settings: &AppSettings) -> usize {
    let n = settings.plots.history / settings.physics.dt;
    if n.is_finite() && n > 0.0 {
        (n.ceil() as usize).clamp(2, MAX_HISTORY)
    } else {
        2
    }
}

fn source_index(source: InertiaSource) -> usize {
    match source {
        InertiaSource::Exact => 0,
        InertiaSource::BoundingBox => 1,
        InertiaSource::PointMasses => 2,
    }
}

/// The three sources' properties for the settings' scale and mass (the analysis is at density 1
/// and scale 1: mass ∝ s³, inertia ∝ s⁵ at fixed density).
fn scaled_properties(
    body: &LoadedBody,
    settings: &AppSettings,
) -> Result<[MassProperties; 3], String> {
    let s = settings.body.scale;
    let a = &body.analysis;
    let exact = a
        .properties
        .scaled_at_fixed_density(s)
        .map_err(|e| format!("size: {e}"))?;
    let mass = match settings.body.mass {
        MassSpec::Density(d) => exact.mass * d,
        MassSpec::Mass(m) => m,
    };
    let fit = |p: &MassProperties| -> Result<MassProperties, String> {
        p.scaled_at_fixed_density(s)
            .and_then(|p| p.with_mass(mass))
            .map_err(|e| format!("mass: {e}"))
    };
    Ok([
        fit(&a.properties)?,
        fit(&a.bounding_box)?,
        fit(&a.point_masses)?,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lab() -> Lab {
        Lab::new(AppSettings::default()).expect("lab")
    }

    #[test]
    fn switching_the_source_keeps_the_mesh_in_place_and_momenta() {
        let mut lab = lab();
        lab.advance(0.5);
        let corner = lab.body().mesh.positions[3];
        let before = lab.mesh_to_world(&corner);
        let (p, l) = (
            lab.sim().body().momentum(),
            lab.sim().body().angular_momentum(),
        );
        let mut s = lab.settings.clone();
        s.body.source = InertiaSource::BoundingBox;
        lab.apply(Command::Settings(Box::new(s)));
        assert!(lab.message().is_none(), "{:?}", lab.message());
        assert!((lab.mesh_to_world(&corner) - before).norm() < 1e-12);
        assert_eq!(lab.sim().body().momentum(), p);
        assert!((lab.sim().body().angular_momentum() - l).norm() < 1e-15);
        // The body now turns about the box centre.
        let bbox = lab.properties(InertiaSource::BoundingBox).center_of_mass;
        assert!((lab.mesh_to_world(&bbox) - lab.sim().body().position()).norm() < 1e-12);
    }

    #[test]
    fn rejected_settings_change_nothing_and_say_why() {
        let mut lab = lab();
        let before = lab.settings.clone();
        let mut s = before.clone();
        s.physics.dt = -1.0;
        lab.apply(Command::Settings(Box::new(s)));
        assert!(lab.message().is_some_and(|m| m.error));
        assert_eq!(lab.settings, before);
        let mut s = before.clone();
        s.body.mass = MassSpec::Mass(f64::NAN);
        lab.apply(Command::Settings(Box::new(s)));
        assert_eq!(lab.settings, before);
        lab.advance(0.1);
        assert!(
            lab.history()
                .samples()
                .iter()
                .all(|s| s.values().iter().all(|v| v.is_finite()))
        );
    }

    #[test]
    fn poke_string_and_csv_export() {
        let mut lab = lab();
        lab.apply(Command::TogglePause);
        let l0 = lab.sim().body().angular_momentum();
        let com = lab.sim().body().position();
        let point = com + Vector3::new(0.03, 0.0, 0.0);
        lab.apply(Command::Poke {
            point,
            direction: Vector3::new(0.0, 0.0, -2.0),
        });
        let j = Vector3::new(0.0, 0.0, -lab.poke_impulse());
        let dl = lab.sim().body().angular_momentum() - l0;
        assert!((dl - (point - com).cross(&j)).norm() < 1e-15);
        assert!(lab.poke_flash().is_some());
        lab.apply(Command::Poke {
            point,
            direction: Vector3::zeros(),
        });
        assert!(lab.message().is_some_and(|m| m.error));

        lab.apply(Command::TogglePause);
        lab.apply(Command::Grab(point));
        let target = point + Vector3::new(0.0, 0.05, 0.0);
        lab.apply(Command::Drag(target));
        let s = lab.string_view().expect("attached");
        assert_eq!(s.target, target);
        assert!(s.force.norm() <= lab.string_max_force() * (1.0 + 1e-12));
        lab.advance(0.2);
        lab.apply(Command::Release);
        assert!(lab.string_view().is_none());

        let path = std::env::temp_dir().join(format!("inertia-lab-{}.csv", std::process::id()));
        lab.apply(Command::ExportCsv(path.clone()));
        let text = std::fs::read_to_string(&path).expect("written");
        assert_eq!(text.lines().count(), lab.history().samples().len() + 1);
        std::fs::remove_file(&path).ok();
        lab.apply(Command::ExportCsv(PathBuf::from("/no/such/dir/x.csv")));
        assert!(
            lab.message()
                .is_some_and(|m| m.error && m.text.contains("/no/such/dir"))
        );
    }
}
