//! The desktop app: eframe glue around the model ([`Lab`]), the panels and the 3D view. Each
//! frame: gather input (shortcuts, dropped files) and the panels' intents as [`Command`]s, apply
//! them in one place, advance the simulation by the frame clock, repaint only while something
//! moves. Settings persist through eframe's storage; GPU resources live only in the 3D scene.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use clap::Args;
use egui::Key;

mod bench;
pub mod capture;
pub mod dialogs;
pub mod panels;
pub mod view3d;
pub mod warnings;

use crate::lab::settings::{AppSettings, InertiaSource};
use crate::lab::{Command, Lab, Message, Variant};
use bench::Bench;
use dialogs::{Dialog, DialogPurpose};
use panels::PanelState;
use view3d::View3d;
use view3d::scene::Scene;

/// Default width of the side panel (points): the mass-properties table fits, and at 1280×800
/// the 3D toolbar and the plot controls still fit in one row beside it.
const SIDE_PANEL_WIDTH: f32 = 340.0;

/// Default width of the momentum-sphere panel beside the 3D view (points).
const SPHERE_PANEL_WIDTH: f32 = 250.0;

/// Key under which the settings are stored.
const SETTINGS_KEY: &str = "inertia-lab-settings";

/// Arguments of the app (no subcommand).
#[derive(Args, Debug, Default)]
pub struct GuiArgs {
    /// Mesh to open (.obj or .stl); the built-in T-handle when absent.
    pub file: Option<PathBuf>,
    /// Render N frames continuously with default settings, print frame-time percentiles, exit.
    #[arg(long, value_name = "N")]
    pub bench_frames: Option<usize>,
    /// With --bench-frames: simulate this many seconds first so the plots hold that much history.
    #[arg(
        long,
        value_name = "SECONDS",
        default_value_t = 0.0,
        requires = "bench_frames"
    )]
    pub bench_history: f64,
    /// With --bench-frames: collapse the plot panel (to measure what the plots cost).
    #[arg(long, requires = "bench_frames")]
    pub bench_no_plots: bool,
    /// With --bench-frames: compare N copies (1 to 3: bounding-box inertia, point-mass inertia,
    /// textbook model), drawn as ghosts with their plot curves (to measure what they cost).
    #[arg(long, value_name = "N", requires = "bench_frames", value_parser = clap::value_parser!(u8).range(1..=3))]
    pub bench_ghosts: Option<u8>,
    /// With a robot description (URDF or MJCF): show this link as the body.
    #[arg(long, value_name = "NAME", requires = "file")]
    pub link: Option<String>,
    /// Save the app's own pixels (3D view, panels, plots) as this PNG, then exit: default
    /// settings, after --after simulated seconds, paused there.
    #[arg(long, value_name = "OUT.png", conflicts_with = "bench_frames")]
    pub screenshot: Option<PathBuf>,
    /// With --screenshot: simulated seconds to run first.
    #[arg(
        long,
        value_name = "SECONDS",
        default_value_t = 0.0,
        requires = "screenshot",
        allow_negative_numbers = true
    )]
    pub after: f64,
}

/// Why the app could not run.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The arguments are out of range.
    #[error("{0}")]
    Usage(String),
    /// No window or GL context could be created (no display, no OpenGL 3).
    #[error("cannot start the app: {0}")]
    Start(#[from] eframe::Error),
    /// `--screenshot` could not be taken or written.
    #[error("{0}")]
    Screenshot(String),
}

/// The app.
pub struct LabApp {
    lab: Lab,
    view: View3d,
    panels: PanelState,
    scene: Option<Arc<Mutex<Scene>>>,
    dialog: Option<Dialog>,
    bench: Option<Bench>,
    capture: Option<capture::Capture>,
    recording: Option<capture::Recording>,
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
        settings: AppSettings,
        gl: Option<Arc<three_d::context::Context>>,
        ctx: &egui::Context,
    ) -> Result<Self, crate::lab::LabError> {
        let mut lab = Lab::new(settings)?;
        let repaint = ctx.clone();
        lab.set_waker(move || repaint.request_repaint());
        let scene = match gl.map(Scene::new) {
            Some(Ok(scene)) => Some(Arc::new(Mutex::new(scene))),
            Some(Err(e)) => {
                eprintln!("inertia-lab: {e}; the 3D view is disabled");
                None
            }
            None => None,
        };
        Ok(Self {
            lab,
            view: View3d::default(),
            panels: PanelState::default(),
            scene,
            dialog: None,
            bench: None,
            capture: None,
            recording: None,
        })
    }

    /// The model (read-only; the UI tests inspect it).
    pub fn lab(&self) -> &Lab {
        &self.lab
    }

    /// The mesh warning whose faces the 3D view highlights, if one is selected.
    pub fn selected_warning(&self) -> Option<usize> {
        self.panels.selected_warning
    }

    /// Applies a command at once (the startup file given on the command line).
    pub fn command(&mut self, c: Command) {
        self.lab.apply(c);
    }

    /// One frame of the whole UI.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let mut commands = Vec::new();
        self.shortcuts(&ctx, &mut commands);
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .collect()
        });
        // A mesh dropped on a body made of parts joins it as a part; anything else (a mesh on a
        // single mesh, a body file) replaces the body.
        let parts = self.lab.primary().body().composition.is_some();
        commands.extend(dropped.into_iter().take(1).map(|path| {
            if parts && !massprops::io::is_body_file(&path) {
                Command::AddPart(path)
            } else {
                Command::LoadFile(path)
            }
        }));
        self.poll_dialog(&mut commands);
        self.panels.dialog_open = self.dialog.is_some();
        self.lab.frame(Instant::now());
        // Every panel edits this one draft; it becomes one command, so no edit undoes another.
        let mut draft = self.lab.settings().clone();

        egui::Panel::top("message").show(ui, |ui| {
            ui.horizontal(|ui| match self.lab.message() {
                Some(m) => {
                    let color = if m.error {
                        egui::Color32::from_rgb(255, 110, 100)
                    } else {
                        ui.visuals().text_color()
                    };
                    ui.colored_label(color, &m.text);
                    if ui.small_button("x").on_hover_text("dismiss").clicked() {
                        commands.push(Command::DismissMessage);
                    }
                }
                None => {
                    ui.label(
                        "Inertia Lab — exact inertia vs the bounding-box guess. Press F1 for help.",
                    );
                }
            });
        });
        // A fixed width the user can drag; content wraps or truncates to it (a long file name or
        // diagnostics line must not widen the panel over the 3D view).
        egui::Panel::left("side")
            .resizable(true)
            .default_size(SIDE_PANEL_WIDTH)
            .min_size(260.0)
            .max_size(640.0)
            .show(ui, |ui| {
                panels::side::show(ui, &self.lab, &mut draft, &mut self.panels, &mut commands);
            });
        let hide_plots = self.bench.as_ref().is_some_and(Bench::hides_plots);
        if !hide_plots {
            egui::Panel::bottom("plots")
                .resizable(true)
                .default_size(260.0)
                .min_size(200.0)
                .show(ui, |ui| {
                    panels::plots::show(ui, &self.lab, &mut draft, &mut self.panels, &mut commands);
                });
        }
        egui::CentralPanel::default().show(ui, |ui| {
            // The toolbar spans the whole width; the sphere and the 3D view share the rest.
            if panels::toolbar::show(ui, &mut draft) {
                self.view.frame_body(&self.lab);
            }
            if draft.view.momentum_sphere {
                egui::Panel::right("sphere")
                    .resizable(true)
                    .default_size(SPHERE_PANEL_WIDTH)
                    .min_size(180.0)
                    .show(ui, |ui| {
                        panels::sphere::show(ui, &self.lab, &mut self.panels);
                    });
            }
            self.view.show(
                ui,
                &self.lab,
                self.scene.as_ref(),
                view3d::overlay::Selection {
                    warning: self.panels.selected_warning,
                    part: self.panels.selected_part,
                },
                &mut commands,
            );
        });
        if ctx.input(|i| !i.raw.hovered_files.is_empty()) {
            ctx.debug_painter().text(
                ctx.content_rect().center(),
                egui::Align2::CENTER_CENTER,
                if self.lab.primary().body().composition.is_some() {
                    "Drop a mesh to add it as a part (a body file to open it)"
                } else {
                    "Drop to load"
                },
                egui::FontId::proportional(32.0),
                egui::Color32::WHITE,
            );
        }
        panels::help::show(&ctx, &mut self.panels.help_open);
        if let Some(purpose) = self.panels.dialog_request.take()
            && self.dialog.is_none()
        {
            let repaint = ctx.clone();
            self.dialog = Some(Dialog::open(purpose, move || repaint.request_repaint()));
        }
        self.record(&ctx, &mut commands);
        if draft != *self.lab.settings() {
            // Before the panels' commands, so that "Reset settings" in the same frame wins.
            commands.insert(0, Command::Settings(Box::new(draft)));
        }
        self.lab.apply_all(commands);
        if self.lab.is_animating()
            || self.dialog.is_some()
            || self.recording.is_some()
            || self.view.is_dragging()
            || self.bench.is_some()
        {
            ctx.request_repaint();
        }
    }

    /// Starts, advances and ends the Record button's recording; its outcome becomes a message.
    fn record(&mut self, ctx: &egui::Context, commands: &mut Vec<Command>) {
        let now = Instant::now();
        if std::mem::take(&mut self.panels.record_request) && self.recording.is_none() {
            let stamp = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs());
            let dir = PathBuf::from(format!("inertia-lab-recording-{stamp}"));
            match capture::Recording::start(dir, self.panels.record_seconds, now) {
                Ok(r) => self.recording = Some(r),
                Err(text) => commands.push(Command::Notify(Message { text, error: true })),
            }
        }
        if let Some(r) = &mut self.recording {
            if std::mem::take(&mut self.panels.record_stop) {
                r.stop(now);
            }
            if let Some((text, error)) = r.frame(ctx, now) {
                commands.push(Command::Notify(Message { text, error }));
                self.recording = None;
            }
        }
        self.panels.recording = self.recording.as_ref().map(|r| r.remaining(now));
    }

    /// Turns a closed dialog's answer into a command.
    fn poll_dialog(&mut self, commands: &mut Vec<Command>) {
        let Some(answer) = self.dialog.as_ref().and_then(Dialog::poll) else {
            return;
        };
        let purpose = self.dialog.take().map(|d| d.purpose);
        commands.push(match (purpose, answer) {
            (Some(DialogPurpose::OpenMesh), Some(path)) => Command::LoadFile(path),
            (Some(DialogPurpose::SaveCsv), Some(path)) => Command::ExportCsv {
                specimen: crate::lab::PRIMARY,
                path,
            },
            (Some(DialogPurpose::AddPart), Some(path)) => Command::AddPart(path),
            (Some(DialogPurpose::SaveBody), Some(path)) => Command::SaveBody(path),
            // rfd reports a cancel and a missing XDG desktop portal alike.
            _ => Command::Notify(Message {
                text: "no file chosen (if no dialog appeared, this desktop has no file-dialog \
                       portal: type a path or drop the file on the window)"
                    .to_owned(),
                error: false,
            }),
        });
    }

    fn shortcuts(&mut self, ctx: &egui::Context, commands: &mut Vec<Command>) {
        if ctx.input(|i| i.key_pressed(Key::F1)) {
            self.panels.help_open = !self.panels.help_open;
        }
        // Letters go to a text field when one has focus.
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        ctx.input(|i| {
            if i.key_pressed(Key::Space) {
                commands.push(Command::TogglePause);
            }
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
        }
    }
}

/// Opens the window and runs the app until it is closed.
///
/// # Errors
/// No window or GL context could be created (no display, no OpenGL 3); `--after` is not a
/// finite number ≥ 0; the screenshot could not be written.
pub fn run(args: &GuiArgs) -> Result<(), RunError> {
    if !(args.after.is_finite() && args.after >= 0.0) {
        return Err(RunError::Usage(format!(
            "--after must be a finite number of seconds ≥ 0, got {}",
            args.after
        )));
    }
    let bench = args
        .bench_frames
        .map(|frames| Bench::new(frames, args.bench_no_plots));
    let outcome = capture::Outcome::default();
    let capture = args
        .screenshot
        .clone()
        .map(|path| capture::Capture::new(path, Arc::clone(&outcome)));
    let scripted = bench.is_some() || capture.is_some();
    let options = eframe::NativeOptions {
        renderer: eframe::Renderer::Glow,
        // Without a depth buffer the 3D occlusion is wrong (stack notes).
        depth_buffer: 24,
        // MSAA more than doubles frame time on software GL (llvmpipe).
        multisampling: 0,
        glow_options: egui_glow::GlowConfiguration {
            vsync: bench.is_none(),
            ..Default::default()
        },
        viewport: egui::ViewportBuilder::default()
            .with_title("Inertia Lab")
            .with_inner_size([1280.0, 800.0])
            .with_min_inner_size([640.0, 480.0])
            .with_drag_and_drop(true),
        persist_window: !scripted,
        ..Default::default()
    };
    let file = args.file.clone();
    let link = args.link.clone();
    let (history, after) = (args.bench_history, args.after);
    let capture_outcome = Arc::clone(&outcome);
    let ghosts = [
        Variant::Source(InertiaSource::BoundingBox),
        Variant::Source(InertiaSource::PointMasses),
        Variant::Model(rbcore::RotationModel::Textbook),
    ]
    .into_iter()
    .take(args.bench_ghosts.map_or(0, usize::from))
    .collect::<Vec<_>>();
    eframe::run_native(
        "inertia-lab",
        options,
        Box::new(move |cc| {
            let settings = match (scripted, cc.storage) {
                (false, Some(storage)) => {
                    eframe::get_value(storage, SETTINGS_KEY).unwrap_or_default()
                }
                _ => AppSettings::default(),
            };
            let mut app = LabApp::new(settings, cc.gl.clone(), &cc.egui_ctx)?;
            if let Some(path) = file {
                app.command(Command::LoadFile(path));
                if scripted || link.is_some() {
                    // Every measured frame, and the picture, must show the mesh.
                    app.lab.wait_for_load();
                }
                if let Some(name) = &link {
                    app.command(app.lab.link_named(name));
                }
            }
            if bench.is_some() {
                if !ghosts.is_empty() {
                    app.command(Command::Compare(ghosts));
                }
                if history > 0.0 {
                    app.lab.advance_for(history);
                }
                app.bench = bench;
            }
            if capture.is_some() {
                // A file that did not load must not give a picture of the default body.
                if let Some(m) = app.lab.message().filter(|m| m.error) {
                    if let Ok(mut slot) = capture_outcome.lock() {
                        *slot = Some(Err(m.text.clone()));
                    }
                    cc.egui_ctx.send_viewport_cmd(egui::ViewportCommand::Close);
                    return Ok(Box::new(app));
                }
                app.lab.advance_for(after);
                // The picture shows the state at exactly `after` seconds.
                app.command(Command::TogglePause);
                app.capture = capture;
            }
            Ok(Box::new(app))
        }),
    )?;
    if args.screenshot.is_some() {
        let result = outcome.lock().ok().and_then(|mut slot| slot.take());
        return match result {
            Some(Ok(())) => Ok(()),
            Some(Err(e)) => Err(RunError::Screenshot(e)),
            None => Err(RunError::Screenshot(
                "the window closed before the screenshot was taken".to_owned(),
            )),
        };
    }
    Ok(())
}
