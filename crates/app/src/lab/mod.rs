//! The headless model of the app: a [`Lab`] of one or more simulated [`Specimen`]s and the user's
//! settings they share, changed only by [`Command`]s that [`Lab::apply`] carries out in one place
//! (as MuJoCo's `simulate` viewer does). Nothing here draws or imports a GUI crate: the GUI reads
//! the lab and records commands, the tests drive it directly. The commands come in groups, one
//! file each beside `apply`: the part commands (`editing.rs`), the robot-link commands
//! (`links.rs`), and loading (`loader.rs`, the one load path).
//!
//! Also here, because the GUI and the tests both need them without a window: the frame clock,
//! the loader (off the UI thread), the body as loaded ([`body`]) and a body made of parts
//! ([`parts`]), the render/picking mesh, picking and the one mesh → world transform
//! ([`placement`]).

pub mod body;
pub mod clock;
mod command;
pub mod describe;
mod editing;
mod error;
pub mod geometry;
pub mod history;
pub mod lessons;
mod links;
pub mod loader;
pub mod parts;
pub mod picking;
pub mod placement;
pub mod robot;
pub mod samples;
pub mod settings;
pub mod specimen;
mod teaching;
#[cfg(test)]
mod tests;

use std::sync::Arc;
use std::time::Duration;

use crate::i18n::tr;
use crate::platform::Instant;

use body::LoadedBody;
use clock::FrameClock;
pub use command::{Command, Message};
pub use error::LabError;
use loader::{LoadSource, Loaded, Loading, Purpose};
use robot::RobotModel;
use settings::{AppSettings, InertiaSource};
pub use specimen::{PokeFlash, Specimen, SpecimenId, StringView, Variant};

/// The specimen every lab has: the one the user loads, pokes and plots.
pub const PRIMARY: SpecimenId = SpecimenId(0);

/// Most copies compared with the primary (each costs a simulation, a history and a ghost).
pub const MAX_COPIES: usize = 3;

/// Whether time runs: held once, here, for every specimen (they run or pause together).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RunMode {
    /// Every frame advances every specimen by the scaled wall-clock time.
    #[default]
    Running,
    /// Time stands still; [`Command::Step`] advances one fixed step at a time.
    Paused,
}

/// The model of the whole app.
#[derive(Debug)]
pub struct Lab {
    settings: AppSettings,
    /// The primary first; never empty.
    specimens: Vec<Specimen>,
    next_id: u32,
    preset_axis: usize,
    run_mode: RunMode,
    clock: FrameClock,
    loading: Option<Loading>,
    /// The robot description loaded last, while its links are what is shown.
    robot: Option<RobotModel>,
    message: Option<Message>,
    /// The lesson open, if any.
    lesson: Option<lessons::LessonRun>,
    /// For each lesson (by id), how many of its steps were done, the most ever.
    lesson_progress: std::collections::BTreeMap<String, usize>,
    /// Bumped whenever what is drawn of the body changes (a new body, a part moved, shown or
    /// hidden), so the 3D view uploads it again; an edit of masses alone leaves it.
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

/// How a body just opened starts: spinning, or waiting for Run where the user asked for reduced
/// motion (nothing on the screen moves unless they start it).
fn first_run_mode(settings: &AppSettings) -> RunMode {
    if settings.display.reduced_motion {
        RunMode::Paused
    } else {
        RunMode::Running
    }
}

impl Lab {
    /// The lab on the default T-handle with `settings` (falls back to defaults if they cannot
    /// build a simulation).
    ///
    /// # Errors
    /// Only if the built-in T-handle cannot be analysed (a bug).
    pub fn new(settings: AppSettings) -> Result<Self, LabError> {
        let body = Arc::new(LoadedBody::t_handle()?);
        let axis = 1;
        let same = Variant::Same;
        let (settings, primary) =
            match Specimen::start(PRIMARY, same, body.clone(), &settings, axis) {
                Ok(s) => (settings, s),
                Err(_) => {
                    let defaults = AppSettings::default();
                    let s = Specimen::start(PRIMARY, same, body, &defaults, axis)?;
                    (defaults, s)
                }
            };
        Ok(Self {
            run_mode: first_run_mode(&settings),
            settings,
            specimens: vec![primary],
            next_id: 1,
            preset_axis: axis,
            clock: FrameClock::new(),
            loading: None,
            robot: None,
            message: None,
            lesson: None,
            lesson_progress: std::collections::BTreeMap::new(),
            generation: 0,
            waker: Waker(Arc::new(|| {})),
        })
    }

    /// Sets what worker threads call when they have news.
    pub fn set_waker(&mut self, waker: impl Fn() + Send + Sync + 'static) {
        self.waker = Waker(Arc::new(waker));
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
            self.message = Some(Message::error(&e));
        }
        self.update_lesson();
    }

    /// Carries out one command, or says why it could not (nothing changed then).
    ///
    /// # Errors
    /// The command's own failure: a file that does not load, a part the body does not have, a
    /// setting the simulation refuses, ….
    pub fn try_apply(&mut self, command: Command) -> Result<(), LabError> {
        match teaching::lesson_opened(command) {
            Command::TogglePause => {
                self.run_mode = match self.run_mode {
                    RunMode::Running => RunMode::Paused,
                    RunMode::Paused => RunMode::Running,
                };
                self.clock.stop();
            }
            Command::Step => {
                self.run_mode = RunMode::Paused;
                self.clock.stop();
                for s in &mut self.specimens {
                    s.step().map_err(LabError::Stopped)?;
                }
            }
            Command::Reset => self.restart(self.preset_axis)?,
            Command::Preset(axis) => self.restart(axis.min(2))?,
            Command::Settings(s) => self.set_settings(*s)?,
            Command::ResetSettings => self.set_settings(AppSettings {
                display: self.settings.display.clone(),
                ..AppSettings::default()
            })?,
            Command::LoadFile(path) => self.start_load(LoadSource::Path(path), Purpose::Open),
            Command::LoadFiles(files) => self.start_load(LoadSource::Files(files), Purpose::Open),
            Command::AddPart(path) => {
                let purpose = self.adding_parts()?;
                self.start_load(LoadSource::Path(path), purpose);
            }
            Command::AddPartFiles(files) => {
                let purpose = self.adding_parts()?;
                self.start_load(LoadSource::Files(files), purpose);
            }
            Command::Drop(source) => {
                let purpose = if self.drop_adds_parts(&source.names()) {
                    self.adding_parts()?
                } else {
                    Purpose::Open
                };
                self.start_load(source, purpose);
            }
            Command::LoadSample(label) => {
                let body = LoadedBody::sample(&label)?;
                self.install(body)?;
            }
            Command::ExportCsv { specimen, path } => {
                let (csv, n) = self.csv(specimen)?;
                crate::platform::write_file(&path, &csv).map_err(|e| LabError::Write {
                    path: path.clone(),
                    message: e.to_string(),
                })?;
                self.info(tr!(
                    "lab-wrote-samples",
                    samples = n,
                    path = path.display().to_string()
                ));
            }
            Command::ExportMotion {
                specimen,
                path,
                seconds,
                fps,
            } => {
                let (bytes, frames) = self.motion_file(specimen, &path, seconds, fps)?;
                crate::platform::write_file(&path, &bytes).map_err(|e| LabError::Write {
                    path: path.clone(),
                    message: e.to_string(),
                })?;
                self.info(tr!(
                    "lab-wrote-keyframes",
                    frames = frames,
                    seconds = crate::i18n::localize(seconds.to_string()),
                    fps = crate::i18n::localize(fps.to_string()),
                    path = path.display().to_string()
                ));
            }
            Command::Poke {
                specimen,
                point,
                direction,
            } => {
                let magnitude = self.specimen(specimen)?.poke_impulse(&self.settings);
                self.specimen_mut(specimen)?
                    .poke(point, direction, magnitude, Instant::now())?;
            }
            Command::Grab { specimen, point } => {
                let settings = self.settings.clone();
                self.specimen_mut(specimen)?.grab(point, &settings)?;
            }
            Command::Drag { specimen, target } => self.specimen_mut(specimen)?.drag(target)?,
            Command::Release { specimen } => self.specimen_mut(specimen)?.release(),
            Command::Compare(variants) => {
                if variants.len() > MAX_COPIES {
                    return Err(LabError::TooManyCopies {
                        max: MAX_COPIES,
                        asked: variants.len(),
                    });
                }
                if variants.is_empty() {
                    // The body goes on where it is; only the copies go.
                    self.specimens.truncate(1);
                    return Ok(());
                }
                let mut plan = vec![(PRIMARY, Variant::Same)];
                for (k, variant) in variants.into_iter().enumerate() {
                    plan.push((SpecimenId(self.next_id + k as u32), variant));
                }
                self.next_id += plan.len() as u32;
                let body = self.primary().body_arc().clone();
                self.start_all(&plan, &body, self.preset_axis)?;
            }
            Command::Notify(message) => self.message = Some(message),
            Command::DismissMessage => self.message = None,
            Command::SplitIntoParts => self.split_into_parts()?,
            Command::EditPart {
                index,
                entry,
                visible,
            } => self.edit_part(index, *entry, visible)?,
            Command::RemovePart(index) => self.remove_part(index)?,
            Command::SaveBody(path) => self.save_body(&path)?,
            Command::ShowLink(link) => self.show_link(link)?,
            Command::OpenLesson(source) => self.open_lesson(&source)?,
            Command::Predict(choice) => self.predict(choice)?,
            Command::NextStep => self.next_step()?,
            Command::PreviousStep => self.previous_step()?,
            Command::GoToStep(step) => self.go_to_step(step)?,
            Command::CloseLesson => self.lesson = None,
        }
        Ok(())
    }

    /// Every specimen goes on with `body`, p and L kept; `redraw`: what is drawn changed.
    /// Nothing changes if one specimen cannot take it.
    fn set_body(&mut self, body: Arc<LoadedBody>, redraw: bool) -> Result<(), LabError> {
        let old = self.primary().body_arc().clone();
        for i in 0..self.specimens.len() {
            if let Err(e) = self.specimens[i].set_body(body.clone(), &self.settings) {
                for s in &mut self.specimens[..i] {
                    // These held `old` before, so going back cannot fail.
                    let _ = s.set_body(old.clone(), &self.settings);
                }
                return Err(e);
            }
        }
        if redraw {
            self.generation += 1;
        }
        Ok(())
    }

    /// Every specimen starts again on the current body, spinning about `axis`.
    fn restart(&mut self, axis: usize) -> Result<(), LabError> {
        let body = self.primary().body_arc().clone();
        self.start_all(&self.plan(), &body, axis)?;
        self.preset_axis = axis;
        Ok(())
    }

    /// The specimens there are, as a plan to start them again.
    fn plan(&self) -> Vec<(SpecimenId, Variant)> {
        self.specimens
            .iter()
            .map(|s| (s.id(), s.variant()))
            .collect()
    }

    /// Replaces every specimen by `plan`'s, all starting on `body` spinning about `axis`; the
    /// run mode is kept. Nothing changes if one cannot start (the message names its variant).
    fn start_all(
        &mut self,
        plan: &[(SpecimenId, Variant)],
        body: &Arc<LoadedBody>,
        axis: usize,
    ) -> Result<(), LabError> {
        let fresh = plan
            .iter()
            .map(|&(id, variant)| {
                Specimen::start(id, variant, body.clone(), &self.settings, axis).map_err(|e| {
                    if variant == Variant::Same {
                        e
                    } else {
                        LabError::Copy {
                            variant: variant.label(),
                            source: Box::new(e),
                        }
                    }
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        self.specimens = fresh;
        self.clock.stop();
        Ok(())
    }

    /// New settings for every specimen; if one rejects them, the ones already changed are put
    /// back so that all keep the same settings.
    fn set_settings(&mut self, new: AppSettings) -> Result<(), LabError> {
        let old = self.settings.clone();
        for i in 0..self.specimens.len() {
            if let Err(e) = self.specimens[i].set_settings(&old, &new) {
                for s in &mut self.specimens[..i] {
                    // These accepted `old` before, so going back cannot fail.
                    let _ = s.set_settings(&new, &old);
                }
                return Err(e);
            }
        }
        let switched = new.body.source != old.body.source || new.physics.model != old.physics.model;
        self.settings = new;
        if switched && self.settings.physics.restart_on_switch {
            self.restart(self.preset_axis)?;
            self.info(tr!(
                "lab-started-again",
                axis = self.preset_axis + 1,
                source = self.settings.body.source.label(),
                model = settings::model_words(self.settings.physics.model),
            ));
        }
        Ok(())
    }

    /// Makes `body` every specimen's body, keeping the old one if the new one cannot be
    /// simulated.
    fn install(&mut self, body: LoadedBody) -> Result<(), LabError> {
        let body = Arc::new(body);
        // The stated source exists only for a link whose description states an inertia.
        let stated_copy = Variant::Source(InertiaSource::Stated);
        if body.stated.is_none() && self.settings.body.source == InertiaSource::Stated {
            self.settings.body.source = InertiaSource::Exact;
        }
        let plan: Vec<(SpecimenId, Variant)> = self
            .plan()
            .into_iter()
            .filter(|(_, v)| body.stated.is_some() || *v != stated_copy)
            .collect();
        self.start_all(&plan, &body, self.preset_axis)?;
        self.generation += 1;
        if self.settings.display.reduced_motion {
            self.run_mode = RunMode::Paused;
            self.clock.stop();
        }
        // The diagnostics sit low in the side panel: the message line says whether to look.
        self.info(tr!(
            "lab-loaded",
            body = &body.name,
            triangles = body.mesh.triangles.len(),
            warnings = body.analysis.warnings.len()
        ));
        Ok(())
    }

    fn info(&mut self, text: String) {
        self.message = Some(Message { text, error: false });
    }

    /// Runs one frame: installs a finished load, then advances every specimen by the scaled
    /// wall-clock time since the last frame (every step recorded in its history).
    pub fn frame(&mut self, now: Instant) {
        if let Some(result) = self.loading.as_mut().and_then(Loading::poll) {
            let joins = self.loading.take().and_then(|l| l.joins);
            self.finish_load(result, joins);
        }
        for s in &mut self.specimens {
            s.expire_flash(now);
        }
        if self.is_paused() {
            self.clock.stop();
            return;
        }
        let frame_dt = self.clock.tick(now, self.settings.physics.time_scale);
        self.advance(frame_dt);
    }

    /// Advances every specimen by `frame_dt` simulated seconds (at most rbcore's catch-up cap of
    /// steps each; the rest is counted in [`Specimen::dropped`]), unless paused. A diverging
    /// specimen pauses the lab and says so on the message line.
    pub fn advance(&mut self, frame_dt: f64) {
        if self.is_paused() {
            return;
        }
        let mut failure = None;
        for s in &mut self.specimens {
            if let Err(e) = s.advance(frame_dt) {
                failure = Some(LabError::Stopped(e));
            }
        }
        if let Some(e) = failure {
            self.run_mode = RunMode::Paused;
            self.message = Some(Message::error(&e));
        }
        self.update_lesson();
    }

    /// Runs `seconds` of simulated time at once (every step recorded), in pieces of the
    /// catch-up cap, e.g. to fill the plots before a benchmark.
    pub fn advance_for(&mut self, seconds: f64) {
        let s = self.primary().sim().settings();
        let chunk = f64::from(s.max_catch_up_steps) * s.dt;
        let mut left = seconds;
        while left > 0.0 && !self.is_paused() {
            self.advance(left.min(chunk));
            left -= chunk;
        }
    }

    /// Blocks until a running load has finished (benchmarks and tests), then installs it.
    pub fn wait_for_load(&mut self) {
        while let Some(loading) = &mut self.loading {
            if let Some(result) = loading.poll() {
                let joins = self.loading.take().and_then(|l| l.joins);
                self.finish_load(result, joins);
            } else {
                std::thread::sleep(Duration::from_millis(2));
            }
        }
    }

    /// Starts the one load path for `source`; new parts remember the body they join, which
    /// must still be the one shown when they arrive.
    fn start_load(&mut self, source: LoadSource, purpose: Purpose) {
        let joins =
            matches!(purpose, Purpose::AddParts { .. }).then(|| self.primary().body_arc().clone());
        let waker = self.waker.clone();
        let mut loading = Loading::begin(source, purpose, move || (waker.0)());
        loading.joins = joins;
        self.loading = Some(loading);
    }

    /// `joins`: for new parts, the body they were read to join.
    fn finish_load(&mut self, result: Result<Loaded, LabError>, joins: Option<Arc<LoadedBody>>) {
        let outcome = result.and_then(|loaded| match loaded {
            Loaded::Joined(body, added) => {
                // An edit while the parts were read made another body: adding to the old one
                // would undo it.
                let current = self.primary().body_arc();
                if !joins.is_some_and(|j| Arc::ptr_eq(&j, current)) {
                    return Err(LabError::ChangedWhileAdding(added));
                }
                self.set_body(Arc::new(body), true)?;
                self.info(tr!("lab-added", parts = &added));
                Ok(())
            }
            Loaded::Body(body) => {
                self.install(body)?;
                self.robot = None;
                Ok(())
            }
            Loaded::Robot(model, body) => {
                self.install(body)?;
                let flagged = model.audit.links.iter().filter(|l| l.flagged()).count();
                self.info(tr!(
                    "lab-loaded-robot",
                    robot = &model.robot.name,
                    links = model.robot.links.len(),
                    flagged = flagged
                ));
                self.robot = Some(*model);
                // The whole robot is shown at its zero pose, still; Run spins it as one body.
                self.run_mode = RunMode::Paused;
                Ok(())
            }
        });
        if let Err(e) = outcome {
            self.message = Some(Message {
                text: tr!("lab-load-failed", error = e.to_string()),
                error: true,
            });
        }
    }

    /// The user's settings (change them with [`Command::Settings`]).
    pub fn settings(&self) -> &AppSettings {
        &self.settings
    }
    /// The specimens, the primary first.
    pub fn specimens(&self) -> &[Specimen] {
        &self.specimens
    }
    /// The primary specimen.
    pub fn primary(&self) -> &Specimen {
        &self.specimens[0]
    }
    /// A specimen by id.
    ///
    /// # Errors
    /// No specimen has that id (it was removed).
    pub fn specimen(&self, id: SpecimenId) -> Result<&Specimen, LabError> {
        self.specimens
            .iter()
            .find(|s| s.id() == id)
            .ok_or(LabError::NoSpecimen(id.0))
    }
    fn specimen_mut(&mut self, id: SpecimenId) -> Result<&mut Specimen, LabError> {
        self.specimens
            .iter_mut()
            .find(|s| s.id() == id)
            .ok_or(LabError::NoSpecimen(id.0))
    }
    /// The principal axis (0, 1, 2; moments ascending) the body was last spun about.
    pub fn preset_axis(&self) -> usize {
        self.preset_axis
    }
    /// Whether time runs or stands still (for every specimen).
    pub fn run_mode(&self) -> RunMode {
        self.run_mode
    }
    /// Whether the simulation is paused.
    pub fn is_paused(&self) -> bool {
        self.run_mode == RunMode::Paused
    }
    /// Drawing generation (changes when what is drawn of the body changes).
    pub fn generation(&self) -> u64 {
        self.generation
    }
    /// The message line.
    pub fn message(&self) -> Option<&Message> {
        self.message.as_ref()
    }
    /// The robot whose links are shown, if a description was loaded.
    pub fn robot(&self) -> Option<&RobotModel> {
        self.robot.as_ref()
    }

    /// The running load, if any.
    pub fn loading(&self) -> Option<&Loading> {
        self.loading.as_ref()
    }

    /// A specimen's plot history as CSV ([`crate::timeseries`]'s columns), and its number of
    /// samples: what [`Command::ExportCsv`] writes.
    ///
    /// # Errors
    /// No such specimen.
    pub fn csv(&self, specimen: SpecimenId) -> Result<(Vec<u8>, usize), LabError> {
        let history = self.specimen(specimen)?.history();
        let mut csv = Vec::new();
        history
            .write_csv(&mut csv)
            .expect("writing to memory cannot fail");
        Ok((csv, history.samples().len()))
    }

    /// A specimen's motion from its present state, `seconds` at `fps`, as the bytes of the file
    /// `path` names (`.glb` or `.usda`: [`inertia_io::bake`]) with its mesh at its size, and the
    /// number of keyframes: what [`Command::ExportMotion`] writes. The specimen itself goes on
    /// untouched (a copy of its simulation is run).
    ///
    /// # Errors
    /// No such specimen, another extension, a rate or duration out of range, or divergence.
    pub fn motion_file(
        &self,
        specimen: SpecimenId,
        path: &std::path::Path,
        seconds: f64,
        fps: f64,
    ) -> Result<(Vec<u8>, usize), LabError> {
        let s = self.specimen(specimen)?;
        let format = inertia_io::bake::format_of(path).ok_or_else(|| LabError::MotionFormat {
            path: path.to_path_buf(),
        })?;
        let shape = s.shape();
        let mut sim = s.sim().clone();
        let baked = inertia_io::bake::sample(&shape, &mut sim, seconds, fps)?;
        let out = inertia_io::bake::write(
            &shape,
            &baked,
            &s.body().name,
            format,
            inertia_io::export::LengthUnit::M,
            inertia_io::export::UpAxis::Y,
        )
        .map_err(|e| LabError::Relayed(e.to_string()))?;
        Ok((out.bytes, baked.keyframes.poses.len()))
    }

    /// Whether anything moves without input (the app repaints continuously only then).
    pub fn is_animating(&self) -> bool {
        !self.is_paused()
            || self.loading.is_some()
            || self.specimens.iter().any(|s| s.poke_flash().is_some())
    }
}
