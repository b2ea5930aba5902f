//! The app, on the desktop and in a browser: eframe glue around the model ([`Lab`]), the
//! panels and the 3D view. Each frame: gather input (shortcuts, dropped files) and the panels'
//! intents as [`Command`]s, apply them in one place, advance the simulation by the frame clock,
//! repaint only while something moves. Settings persist through eframe's storage; GPU resources
//! live only in the 3D scene. What differs between the two targets is [`platform`].

use std::path::PathBuf;
use std::sync::Arc;

use egui::Key;

use crate::i18n::tr;

mod archive;
mod bench;
pub mod capture;
pub mod link;
pub mod panels;
pub mod platform;
mod start;
pub mod view3d;
pub mod warnings;

use crate::lab::lessons::LessonRun;
use crate::lab::settings::InertiaSource;
use crate::lab::{Command, Lab, Message};
use crate::platform::Instant;
use bench::Bench;
use panels::{Frame, Panel, PanelState, Panels};
use platform::{Chosen, Dialog, DialogPurpose, DroppedFiles};
use view3d::View3d;
use view3d::scene::{Scene, SceneSlot};

/// Default width of the side panel (points): the mass-properties table fits, and at 1280×800
/// the 3D toolbar and the plot controls still fit in one row beside it.
const SIDE_PANEL_WIDTH: f32 = 340.0;

/// Default width of the momentum-sphere panel beside the 3D view (points).
const SPHERE_PANEL_WIDTH: f32 = 250.0;

/// Key under which the settings are stored (eframe's storage: a file on the desktop, the page's
/// local storage in a browser).
const SETTINGS_KEY: &str = "inertia-lab-settings";
/// The Lessons panel's width at first (points).
const LESSON_PANEL_WIDTH: f32 = 300.0;
/// Where the lessons' progress is kept (each lesson's id and the most steps done).
const PROGRESS_KEY: &str = "inertia-lab-lesson-progress";

/// The app.
pub struct LabApp {
    lab: Lab,
    view: View3d,
    /// What the panels share with each other and the app.
    shared: PanelState,
    /// Every panel, each with its own state.
    panels: Panels,
    scene: Option<SceneSlot>,
    dialog: Option<Dialog>,
    /// Files dropped and being read (a browser reads their bytes first).
    dropping: Option<DroppedFiles>,
    /// The title last given to the window or page.
    title: String,
    bench: Option<Bench>,
    capture: Option<capture::Capture>,
    recording: Option<capture::Recording>,
    /// The widget that last took the keyboard's focus, in words (egui's description).
    focus: String,
    /// The language "the system's" stands for (the desktop's locale, the browser's language).
    system_language: crate::i18n::Language,
    /// The display settings last applied to the context (its zoom, animations and voice).
    display: Option<crate::lab::settings::DisplaySettings>,
}

impl std::fmt::Debug for LabApp {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LabApp")
            .field("lab", &self.lab)
            .finish_non_exhaustive()
    }
}

impl LabApp {
    /// The app on the default T-handle; `gl` is eframe's GL context (absent in UI tests, where
    /// the 3D view shows a placeholder).
    ///
    /// # Errors
    /// The built-in body cannot be set up (a bug).
    pub fn new(
        settings: crate::lab::settings::AppSettings,
        gl: Option<Arc<three_d::context::Context>>,
        ctx: &egui::Context,
    ) -> Result<Self, crate::lab::LabError> {
        // In the user's language from the start: the first commands (a file, a lesson) speak.
        let system_language = crate::i18n::Language::of_system();
        crate::i18n::set_language(settings.display.language.unwrap_or(system_language));
        let mut lab = Lab::new(settings)?;
        let repaint = ctx.clone();
        lab.set_waker(move || repaint.request_repaint());
        let scene = match gl.map(Scene::new) {
            Some(Ok(scene)) => Some(SceneSlot::install(scene)),
            Some(Err(e)) => {
                crate::platform::print_error(&format!("inertia-lab: {e}; the 3D view is disabled"));
                None
            }
            None => None,
        };
        Ok(Self {
            lab,
            view: View3d::default(),
            shared: PanelState::default(),
            panels: Panels::default(),
            scene,
            dialog: None,
            dropping: None,
            title: String::new(),
            bench: None,
            capture: None,
            recording: None,
            focus: String::new(),
            system_language,
            display: None,
        })
    }

    /// The model (read-only; the UI tests inspect it).
    pub fn lab(&self) -> &Lab {
        &self.lab
    }

    /// The mesh warning whose faces the 3D view highlights, if one is selected.
    pub fn selected_warning(&self) -> Option<usize> {
        self.shared.selected_warning
    }

    /// Applies a command at once (the startup file given on the command line).
    pub fn command(&mut self, c: Command) {
        self.lab.apply(c);
    }

    /// One frame of the whole UI.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let display = &self.lab.settings().display;
        crate::i18n::set_language(display.language.unwrap_or(self.system_language));
        if self.display.as_ref() != Some(display) {
            panels::display::apply(&ctx, display);
            self.display = Some(display.clone());
        }
        let mut commands = Vec::new();
        self.shortcuts(&ctx, &mut commands);
        self.take_dropped(&ctx, &mut commands);
        commands.extend(platform::arrived());
        self.poll_dialog(&mut commands);
        self.shared.dialog_open = self.dialog.is_some();
        self.lab.frame(Instant::now());
        // Every panel edits this one draft; it becomes one command, so no edit undoes another.
        let mut draft = self.lab.settings().clone();

        egui::Panel::top("message").show(ui, |ui| {
            ui.horizontal(|ui| {
                // First, so that a long message cannot push it off the window.
                if ui
                    .small_button(tr!("top-help"))
                    .on_hover_text(tr!("top-help-hover"))
                    .clicked()
                {
                    self.shared.help_open = !self.shared.help_open;
                }
                if ui
                    .small_button(tr!("top-lessons"))
                    .on_hover_text(tr!("top-lessons-hover"))
                    .clicked()
                {
                    self.shared.lessons_open = !self.shared.lessons_open;
                }
                if ui
                    .small_button(tr!("top-share"))
                    .on_hover_text(tr!("top-share-hover"))
                    .clicked()
                {
                    commands.push(Command::Notify(match link::share(&self.lab) {
                        Ok(query) => {
                            let address = platform::share_address(&query);
                            ctx.copy_text(address.clone());
                            Message {
                                text: tr!(
                                    "top-share-copied",
                                    address = address,
                                    hint = platform::share_hint()
                                ),
                                error: false,
                            }
                        }
                        Err(why) => Message {
                            text: why,
                            error: true,
                        },
                    }));
                }
                panels::display::show(ui, &mut draft.display, self.system_language);
                ui.separator();
                message_text(ui, self.lab.message(), &mut commands);
            });
        });
        // A fixed width the user can drag; content wraps or truncates to it (a long file name or
        // diagnostics line must not widen the panel over the 3D view).
        // Embedded in another page (`?embed=1`): the view, the plots and the lesson only.
        if !self.shared.embed {
            egui::Panel::left("side")
                .resizable(true)
                .default_size(SIDE_PANEL_WIDTH)
                .min_size(260.0)
                .max_size(640.0)
                .show(ui, |ui| {
                    let mut frame = Frame {
                        lab: &self.lab,
                        settings: &mut draft,
                        commands: &mut commands,
                        shared: &mut self.shared,
                    };
                    self.panels.side.show(ui, &mut frame);
                });
        }
        let mut frame = Frame {
            lab: &self.lab,
            settings: &mut draft,
            commands: &mut commands,
            shared: &mut self.shared,
        };
        let hide_plots = self.bench.as_ref().is_some_and(Bench::hides_plots);
        if !hide_plots {
            egui::Panel::bottom("plots")
                .resizable(true)
                .default_size(260.0)
                .min_size(200.0)
                .show(ui, |ui| self.panels.plots.show(ui, &mut frame));
        }
        if frame.shared.lessons_open || self.lab.lesson().is_some() {
            egui::Panel::right("lessons")
                .resizable(true)
                .default_size(LESSON_PANEL_WIDTH)
                .min_size(220.0)
                .show(ui, |ui| self.panels.lessons.show(ui, &mut frame));
        }
        egui::CentralPanel::default().show(ui, |ui| {
            // The toolbar spans the whole width; the sphere and the 3D view share the rest.
            self.panels.toolbar.show(ui, &mut frame);
            if std::mem::take(&mut frame.shared.frame_request) {
                self.view.frame_body(&self.lab);
            }
            if frame.settings.view.momentum_sphere {
                egui::Panel::right("sphere")
                    .resizable(true)
                    .default_size(SPHERE_PANEL_WIDTH)
                    .min_size(180.0)
                    .show(ui, |ui| self.panels.sphere.show(ui, &mut frame));
            }
            self.view.show(
                ui,
                &self.lab,
                self.scene,
                view3d::overlay::Selection {
                    warning: frame.shared.selected_warning,
                    part: frame.shared.selected_part,
                },
                frame.commands,
            );
        });
        if ctx.input(|i| !i.raw.hovered_files.is_empty()) {
            ctx.debug_painter().text(
                ctx.content_rect().center(),
                egui::Align2::CENTER_CENTER,
                if self.lab.drop_may_add_parts() {
                    tr!("drop-adds-part")
                } else {
                    tr!("drop-loads")
                },
                egui::FontId::proportional(32.0),
                egui::Color32::WHITE,
            );
        }
        self.panels.help.show(ui, &mut frame);
        if let Some(purpose) = self.shared.dialog_request.take()
            && self.dialog.is_none()
        {
            let repaint = ctx.clone();
            self.dialog = Some(Dialog::open(purpose, move || repaint.request_repaint()));
        }
        self.show_status(&ctx);
        // Work queued off the UI thread where there is no other thread (a page's pictures).
        crate::platform::run_spawned();
        self.record(&ctx, &mut commands);
        if draft != *self.lab.settings() {
            // Before the panels' commands, so that "Reset settings" in the same frame wins.
            commands.insert(0, Command::Settings(Box::new(draft)));
        }
        self.lab.apply_all(commands);
        if self.lab.is_animating()
            || self.dialog.is_some()
            || self.dropping.is_some()
            || self.recording.is_some()
            || self.view.is_dragging()
            || self.bench.is_some()
        {
            ctx.request_repaint();
        }
    }

    /// Files dropped on the window or page become [`Command::Drop`] once the platform has them
    /// (in a browser their bytes are read first, which takes a moment); the lab decides whether
    /// they open a body or join this one.
    fn take_dropped(&mut self, ctx: &egui::Context, commands: &mut Vec<Command>) {
        if let Some(ready) = self.dropping.as_mut().and_then(DroppedFiles::poll) {
            self.dropping = None;
            commands.push(match ready {
                Some(source) => Command::Drop(source),
                None => Command::Notify(Message {
                    text: platform::no_file_chosen(),
                    error: false,
                }),
            });
        }
        let dropped = ctx.input(|i| i.raw.dropped_files.clone());
        if dropped.is_empty() || self.dropping.is_some() {
            return;
        }
        let repaint = ctx.clone();
        self.dropping = Some(DroppedFiles::read(&dropped, move || {
            repaint.request_repaint();
        }));
    }

    /// The window's or page's title names the body; the page also publishes its figures.
    fn show_status(&mut self, ctx: &egui::Context) {
        let primary = self.lab.primary();
        let title = tr!("window-title", body = &primary.body().name);
        if title != self.title {
            platform::set_title(ctx, &title);
            self.title = title;
        }
        // What the keyboard's focus moved to: the page tells a screen reader (its runner exposes no
        // tree), and the keyboard-only test finds its way by it.
        for event in ctx.output(|o| o.events.clone()) {
            if let egui::output::OutputEvent::FocusGained(info) = event {
                self.focus = info.description();
            }
        }
        let exact = primary.properties(InertiaSource::Exact);
        let body = primary.sim().body();
        let view = self.view.rect().unwrap_or(egui::Rect::NOTHING);
        let lesson = self.lab.lesson();
        platform::publish(&platform::Figures {
            mass: exact.mass,
            volume: primary.volume(),
            omega: body.omega_world().norm(),
            momentum: body.angular_momentum().norm(),
            time: primary.sim().time(),
            orientation: {
                let q = body.orientation();
                [q.w, q.i, q.j, q.k]
            },
            specimens: self.lab.specimens().len(),
            description: match crate::lab::describe::lesson(&self.lab) {
                Some(lesson) => {
                    format!("{} {lesson}", crate::lab::describe::description(&self.lab))
                }
                None => crate::lab::describe::description(&self.lab),
            },
            focus: self.focus.clone(),
            lesson: lesson.map(|r| r.lesson.id.clone()).unwrap_or_default(),
            lesson_step: lesson.map(LessonRun::progress).unwrap_or_default(),
            lessons: crate::lab::lessons::built_in().len(),
            language: crate::i18n::language().code(),
            loading: self.lab.loading().map(|l| l.stage.to_string()),
            view: [view.left(), view.top(), view.width(), view.height()],
        });
    }

    /// Starts, advances and ends the Record button's recording; its outcome becomes a message.
    fn record(&mut self, ctx: &egui::Context, commands: &mut Vec<Command>) {
        let now = Instant::now();
        if std::mem::take(&mut self.shared.record_request) && self.recording.is_none() {
            let stamp = crate::platform::SystemTime::now()
                .duration_since(crate::platform::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs());
            let name = format!("inertia-lab-recording-{stamp}");
            let seconds = self.shared.record_seconds;
            let started = if platform::RECORD_TO_ARCHIVE {
                let archive = PathBuf::from(format!("{name}.zip"));
                Ok(capture::Recording::start_archive(archive, seconds, now))
            } else {
                capture::Recording::start(PathBuf::from(name), seconds, now)
            };
            match started {
                Ok(r) => self.recording = Some(r),
                Err(text) => commands.push(Command::Notify(Message { text, error: true })),
            }
        }
        if let Some(r) = &mut self.recording {
            if std::mem::take(&mut self.shared.record_stop) {
                r.stop(now);
            }
            if let Some((text, error)) = r.frame(ctx, now) {
                commands.push(Command::Notify(Message { text, error }));
                self.recording = None;
            }
        }
        self.shared.recording = self.recording.as_ref().map(|r| r.remaining(now));
    }

    /// Turns a closed dialog's answer into a command.
    fn poll_dialog(&mut self, commands: &mut Vec<Command>) {
        let Some(answer) = self.dialog.as_ref().and_then(Dialog::poll) else {
            return;
        };
        let purpose = self.dialog.take().map(|d| d.purpose);
        commands.push(match (purpose, answer) {
            (Some(DialogPurpose::OpenMesh), Some(Chosen::Path(path))) => Command::LoadFile(path),
            (Some(DialogPurpose::OpenMesh), Some(Chosen::Files(files))) => {
                Command::LoadFiles(files)
            }
            (Some(DialogPurpose::SaveCsv), Some(Chosen::Path(path))) => Command::ExportCsv {
                specimen: crate::lab::PRIMARY,
                path,
            },
            (Some(DialogPurpose::AddPart), Some(Chosen::Path(path))) => Command::AddPart(path),
            (Some(DialogPurpose::AddPart), Some(Chosen::Files(files))) => {
                Command::AddPartFiles(files)
            }
            (Some(DialogPurpose::SaveBody), Some(Chosen::Path(path))) => Command::SaveBody(path),
            (Some(DialogPurpose::SaveMotion), Some(Chosen::Path(path))) => Command::ExportMotion {
                specimen: crate::lab::PRIMARY,
                path,
                seconds: self.shared.motion_seconds,
                fps: self.shared.motion_fps,
            },
            _ => Command::Notify(Message {
                text: platform::no_file_chosen(),
                error: false,
            }),
        });
    }

    fn shortcuts(&mut self, ctx: &egui::Context, commands: &mut Vec<Command>) {
        if ctx.input(|i| i.key_pressed(Key::F1)) {
            self.shared.help_open = !self.shared.help_open;
        }
        // Keys go to a text or number field being edited; otherwise they are the lab's, whatever
        // widget has focus (a focused button would take Space as a click).
        if ctx.text_edit_focused() {
            return;
        }
        if ctx.input(|i| i.key_pressed(Key::Escape))
            && let Some(id) = ctx.memory(|m| m.focused())
        {
            ctx.memory_mut(|m| m.surrender_focus(id));
        }
        if ctx.input_mut(|i| i.consume_key(egui::Modifiers::NONE, Key::Space)) {
            commands.push(Command::TogglePause);
        }
        ctx.input(|i| {
            if i.key_pressed(Key::S) {
                commands.push(Command::Step);
            }
            if i.key_pressed(Key::R) {
                commands.push(Command::Reset);
            }
            for (k, axis) in [(Key::Num1, 0), (Key::Num2, 1), (Key::Num3, 2)] {
                if i.key_pressed(k) {
                    commands.push(Command::Preset(axis));
                }
            }
        });
        if ctx.input(|i| i.key_pressed(Key::F)) {
            self.view.frame_body(&self.lab);
        }
        if ctx.input(|i| i.key_pressed(Key::L)) {
            self.shared.lessons_open = !self.shared.lessons_open;
        }
    }
}

impl eframe::App for LabApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let start = Instant::now();
        self.show(ui);
        let ctx = ui.ctx().clone();
        if let Some(b) = &mut self.bench {
            b.record_work(start.elapsed(), frame.info().cpu_usage);
            if b.frame(&self.lab, &mut self.view) {
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            }
        }
        if let Some(c) = &mut self.capture {
            c.frame(&ctx);
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        // Measuring and capturing runs use default settings and must not replace the user's.
        if self.bench.is_none() && self.capture.is_none() {
            eframe::set_value(storage, SETTINGS_KEY, self.lab.settings());
            eframe::set_value(storage, PROGRESS_KEY, self.lab.lesson_progress());
        }
    }
}

/// The lessons' progress kept in `storage` (none for a scripted run, which has no storage).
fn kept_progress(
    storage: Option<&dyn eframe::Storage>,
) -> std::collections::BTreeMap<String, usize> {
    storage
        .and_then(|s| eframe::get_value(s, PROGRESS_KEY))
        .unwrap_or_default()
}

/// The message line's text: the lab's last message with its dismiss button, or what the lab is.
fn message_text(ui: &mut egui::Ui, message: Option<&Message>, commands: &mut Vec<Command>) {
    match message {
        Some(m) => {
            let color = if m.error {
                egui::Color32::from_rgb(255, 110, 100)
            } else {
                ui.visuals().text_color()
            };
            ui.colored_label(color, &m.text);
            if ui
                .small_button("x")
                .on_hover_text(tr!("message-dismiss"))
                .clicked()
            {
                commands.push(Command::DismissMessage);
            }
        }
        None => {
            ui.label(tr!("message-none"));
        }
    }
}
