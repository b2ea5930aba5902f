//! The desktop's side of the GUI's [`platform`](super): a window of its own (`run`, with the
//! command line's arguments), and native file dialogs through the XDG desktop portal (`rfd`),
//! which block until closed, so each runs on its own thread; the GUI polls for the answer and
//! turns it into a lab command.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::thread;

use clap::Args;
use inertia_io::kind::{Openable, mesh_extension_words, part_extensions, part_label};

use super::{Chosen, DialogPurpose, Figures};
use crate::gui::bench::Bench;
use crate::gui::start::Start;
use crate::gui::{SETTINGS_KEY, capture};
use crate::i18n::{Language, tr};
use crate::lab::lessons::LessonSource;
use crate::lab::loader::LoadSource;
use crate::lab::settings::{AppSettings, InertiaSource};
use crate::lab::{Command, Variant};

/// What the window opens: meshes, bodies and robot descriptions.
const OPENABLE: Openable = Openable { robots: true };

/// What the side panel says may be dropped.
pub fn drop_hint() -> String {
    tr!("drop-hint-window")
}

/// What a closed dialog that chose nothing says: rfd reports a cancel and a missing XDG desktop
/// portal alike.
pub fn no_file_chosen() -> String {
    tr!("no-file-chosen-window")
}

/// The desktop leaves speech to real screen readers, through AccessKit.
pub const SELF_VOICING: bool = false;

/// Paths may be typed: the side panel's Path field reads the file named there.
pub const READS_PATHS: bool = true;

/// The Record button's numbered PNG files are written in a folder of their own.
pub const RECORD_TO_ARCHIVE: bool = false;

/// What the Record button does, for its tooltip.
pub fn record_hint() -> String {
    tr!("record-hint-window")
}

/// The window's title.
pub fn set_title(ctx: &egui::Context, title: &str) {
    ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.to_owned()));
}

/// Nothing arrives between frames on the desktop but what the window's own input brings (a page
/// fetches a lesson a link named).
pub fn arrived() -> Vec<Command> {
    Vec::new()
}

/// Nothing: a window shows its figures in its panels alone. (A page also gives them to scripts.)
pub fn publish(_: &Figures) {}

/// The link to share for a scene's `query`: the desktop has no page address of its own, so the
/// query alone, to put after the lab page's address.
pub fn share_address(query: &str) -> String {
    query.to_owned()
}

/// What a shared link is, for the message that it was copied.
pub fn share_hint() -> String {
    tr!("share-hint-window")
}

/// A native file dialog running on its own thread (they block until closed).
#[derive(Debug)]
pub struct Dialog {
    /// What the chosen file is for.
    pub purpose: DialogPurpose,
    answer: Receiver<Option<Chosen>>,
}

impl Dialog {
    /// Opens the dialog for `purpose`.
    pub fn open(purpose: DialogPurpose, wake: impl Fn() + Send + 'static) -> Self {
        let (tx, rx) = channel();
        thread::spawn(move || {
            let dialog = rfd::FileDialog::new();
            let path = match purpose {
                DialogPurpose::OpenMesh => dialog
                    .add_filter(OPENABLE.label(), &any_case(&OPENABLE.extensions()))
                    .pick_file(),
                DialogPurpose::AddPart => dialog
                    .add_filter(part_label(), &any_case(&part_extensions()))
                    .pick_file(),
                DialogPurpose::SaveBody => dialog
                    .add_filter(tr!("dialog-body-files"), &["toml"])
                    .set_file_name("body.toml")
                    .save_file(),
                DialogPurpose::SaveCsv => dialog
                    .add_filter("CSV", &["csv"])
                    .set_file_name("inertia-lab.csv")
                    .save_file(),
                DialogPurpose::SaveMotion => dialog
                    .add_filter(tr!("dialog-gltf-binary"), &["glb"])
                    .add_filter("USD", &["usda"])
                    .set_file_name("motion.glb")
                    .save_file(),
            };
            let _ = tx.send(path.map(Chosen::Path));
            wake();
        });
        Self {
            purpose,
            answer: rx,
        }
    }

    /// `Some(answer)` once closed (`None` inside: cancelled, or no dialog service available).
    pub fn poll(&self) -> Option<Option<Chosen>> {
        match self.answer.try_recv() {
            Ok(answer) => Some(answer),
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => Some(None),
        }
    }
}

/// Files dropped on the window, as the lab will read them: the first one's path, at once (the
/// lab reads the files a body file names from beside it).
#[derive(Debug)]
pub struct DroppedFiles(Option<Option<LoadSource>>);

impl DroppedFiles {
    /// Takes the dropped files (`wake` is for a platform that reads them first).
    pub fn read(files: &[egui::DroppedFileHandle], _wake: impl Fn() + 'static) -> Self {
        Self(Some(
            files
                .first()
                .map(|f| LoadSource::Path(f.path().to_path_buf())),
        ))
    }

    /// `Some(files)` once ready (`None` inside: nothing could be read).
    pub fn poll(&mut self) -> Option<Option<LoadSource>> {
        self.0.take()
    }
}

/// Arguments of the app (no subcommand).
#[derive(Args, Debug, Default)]
pub struct GuiArgs {
    /// Mesh to open (.obj or .stl), a body file or a robot description; the built-in T-handle
    /// when absent.
    #[arg(help = format!("Mesh to open ({}), a body file (.toml) or a robot description \
        (.urdf, .xml); the built-in T-handle when absent", mesh_extension_words()))]
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
    /// With a robot description (URDF, MJCF or SDFormat): show this link as the body.
    #[arg(long, value_name = "NAME", requires = "file")]
    pub link: Option<String>,
    /// Open a lesson: its number from 1, its id, or a lesson file (….lesson.toml).
    #[arg(long, value_name = "LESSON")]
    pub lesson: Option<String>,
    /// The language of the window: en, de or es (the system's when absent).
    #[arg(long, value_name = "CODE", value_parser = language)]
    pub lang: Option<Language>,
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

/// Opens the window and runs the app until it is closed (what it does first: `gui::start`).
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
    let outcome = capture::Outcome::default();
    let start = Start {
        file: args.file.clone(),
        link: args.link.clone(),
        commands: args
            .lesson
            .iter()
            .map(|key| {
                let path = PathBuf::from(key);
                Command::OpenLesson(if crate::lab::lessons::is_lesson_file(&path) {
                    LessonSource::Path(path)
                } else {
                    LessonSource::BuiltIn(key.clone())
                })
            })
            .collect(),
        bench: args
            .bench_frames
            .map(|frames| Bench::new(frames, args.bench_no_plots)),
        ghosts: [
            Variant::Source(InertiaSource::BoundingBox),
            Variant::Source(InertiaSource::PointMasses),
            Variant::Model(rbcore::RotationModel::Textbook),
        ]
        .into_iter()
        .take(args.bench_ghosts.map_or(0, usize::from))
        .collect(),
        history: args.bench_history,
        capture: args
            .screenshot
            .clone()
            .map(|path| capture::Capture::new(path, Arc::clone(&outcome))),
        after: args.after,
        embed: false,
        tweaks: crate::gui::link::Tweaks::default(),
        language: args.lang,
    };
    let scripted = start.scripted();
    let options = eframe::NativeOptions {
        renderer: eframe::Renderer::Glow,
        // Without a depth buffer the 3D occlusion is wrong (stack notes).
        depth_buffer: 24,
        // MSAA more than doubles frame time on software GL (llvmpipe).
        multisampling: 0,
        glow_options: egui_glow::GlowConfiguration {
            vsync: start.bench.is_none(),
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
            let mut app = start.app(settings, cc.gl.clone(), &cc.egui_ctx)?;
            if !scripted {
                app.lab
                    .restore_lesson_progress(crate::gui::kept_progress(cc.storage));
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

/// A language from `--lang`'s code.
fn language(code: &str) -> Result<Language, String> {
    Language::from_tag(code).ok_or_else(|| {
        let codes: Vec<&str> = Language::ALL.iter().map(|l| l.code()).collect();
        format!("no language '{code}': the lab speaks {}", codes.join(", "))
    })
}

/// Each extension in lower and upper case: the portal's filters match case-sensitively, and
/// files from Windows tools are often named `PART.STL`.
fn any_case(extensions: &[&str]) -> Vec<String> {
    extensions
        .iter()
        .flat_map(|e| [e.to_string(), e.to_ascii_uppercase()])
        .collect()
}
