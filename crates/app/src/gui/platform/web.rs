//! The browser's side of the GUI's [`platform`](super) (wasm32): the app starts on the page's
//! canvas with eframe's web runner and the scene its address names ([`crate::gui::link`]);
//! files come in through the browser's file picker (several at once, so that a body file
//! arrives with its meshes) with their bytes; a save "dialog" answers at once with the name to
//! download; the page's title names the body, and the canvas carries the figures scripts read
//! ([`publish`]: docs/web.md lists them).

use std::cell::{Cell, RefCell};
use std::path::PathBuf;
use std::rc::Rc;

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use super::{Chosen, DialogPurpose, Figures};
use crate::gui::bench::Bench;
use crate::gui::start::Start;
use crate::gui::{SETTINGS_KEY, link};
use crate::i18n::tr;
use crate::lab::loader::LoadSource;
use crate::lab::settings::AppSettings;
use crate::lab::{Command, Message};
use inertia_io::input::FileSet;
use inertia_io::kind::{Openable, part_extensions, part_label};

/// What the page opens: meshes and bodies (not robot descriptions, whose meshes it cannot
/// fetch).
const OPENABLE: Openable = Openable { robots: false };

/// What the side panel says may be dropped.
pub fn drop_hint() -> String {
    tr!("drop-hint-page")
}

/// What a closed picker that chose nothing says (or a drop of files the browser could not read,
/// which the console names).
pub fn no_file_chosen() -> String {
    tr!("no-file-chosen-page")
}

/// The page has no accessibility tree (eframe's web runner exposes none): egui's own screen
/// reader, speaking through the browser, is offered.
pub const SELF_VOICING: bool = true;

/// A page has no paths to type: files come from the picker or a drop.
pub const READS_PATHS: bool = false;

/// A recording's hundreds of pictures would be as many downloads: the page puts them in one
/// archive, downloaded when the recording ends.
pub const RECORD_TO_ARCHIVE: bool = true;

/// What the Record button does, for its tooltip.
pub fn record_hint() -> String {
    tr!("record-hint-page")
}

/// The id of the canvas the app draws on (`web/index.html`).
pub const CANVAS_ID: &str = "inertia-lab";

/// The id of the page's live region (`aria-live="polite"`, web/index.html) that holds what is
/// happening in words.
const LIVE_ID: &str = "live";
/// The region that names the widget with the keyboard's focus (a screen reader says it at once).
const FOCUS_ID: &str = "focus";

/// Starts the app on the page's canvas with the scene its address names; an error is shown in
/// the page (the element `#error`) and the console.
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        crate::platform::print_error(&format!("inertia-lab panicked: {info}"));
        show_error(&format!("Inertia Lab stopped: {info}"));
    }));
    // The same module runs in the page's worker, which has no page to start on: it only runs
    // the jobs the page sends it (platform/web.rs).
    if web_sys::window().is_none() {
        return;
    }
    wasm_bindgen_futures::spawn_local(async {
        if let Err(e) = run().await {
            let text = e.as_string().unwrap_or_else(|| format!("{e:?}"));
            crate::platform::print_error(&format!("inertia-lab: {text}"));
            show_error(&format!("Inertia Lab could not start: {text}"));
        }
    });
}

async fn run() -> Result<(), JsValue> {
    let document = document().ok_or("no document")?;
    let canvas: web_sys::HtmlCanvasElement = document
        .get_element_by_id(CANVAS_ID)
        .ok_or_else(|| format!("the page has no canvas with id {CANVAS_ID:?}"))?
        .dyn_into()?;
    let query = web_sys::window().ok_or("no window")?.location().search()?;
    let scene = link::parse(&query);
    let fetch_lesson = scene.lesson_address.clone();
    let options = eframe::WebOptions {
        // Without a depth buffer the 3D occlusion is wrong (stack notes).
        depth_buffer: 24,
        ..Default::default()
    };
    eframe::WebRunner::new()
        .start(
            canvas,
            options,
            Box::new(move |cc| {
                // A measured run uses default settings and must not replace the user's.
                let settings = match (scene.bench_frames, cc.storage) {
                    (None, Some(storage)) => {
                        eframe::get_value(storage, SETTINGS_KEY).unwrap_or_default()
                    }
                    _ => AppSettings::default(),
                };
                let settings = scene.settings.apply(settings);
                // The link's words (its problems, a lesson's) in the language it and the saved
                // settings give: read again once that language is the thread's.
                crate::i18n::set_language(
                    settings
                        .display
                        .language
                        .unwrap_or_else(crate::i18n::Language::of_system),
                );
                let scene = link::parse(&query);
                let mut commands = scene.commands;
                if !scene.problems.is_empty() {
                    commands.push(Command::Notify(Message {
                        text: tr!("link-problems", problems = scene.problems.join("; ")),
                        error: true,
                    }));
                }
                let start = Start {
                    commands,
                    bench: scene.bench_frames.map(|n| Bench::new(n, false)),
                    embed: scene.embed,
                    tweaks: scene.settings,
                    ..Start::default()
                };
                let mut app = start.app(settings, cc.gl.clone(), &cc.egui_ctx)?;
                app.lab
                    .restore_lesson_progress(crate::gui::kept_progress(cc.storage));
                if let Some((address, step)) = fetch_lesson {
                    let ctx = cc.egui_ctx.clone();
                    wasm_bindgen_futures::spawn_local(async move {
                        let commands = match fetch_text(&address).await {
                            Ok(text) => link::fetched_lesson(&address, text, step),
                            Err(why) => vec![Command::Notify(Message {
                                text: tr!("link-lesson-not-fetched", address = &address, why = why),
                                error: true,
                            })],
                        };
                        ARRIVED.with_borrow_mut(|arrived| arrived.extend(commands));
                        ctx.request_repaint();
                    });
                }
                Ok(Box::new(app))
            }),
        )
        .await?;
    // Ready before a file arrives: loading a dropped file waits for no worker.
    crate::platform::prepare_jobs();
    Ok(())
}

thread_local! {
    /// Commands from the page's own work between frames (a lesson a link named, fetched).
    static ARRIVED: RefCell<Vec<Command>> = const { RefCell::new(Vec::new()) };
}

/// The commands that arrived since the last frame: a lesson file a link named, once fetched.
pub fn arrived() -> Vec<Command> {
    ARRIVED.with_borrow_mut(std::mem::take)
}

/// The text at `address` (relative to the page, or absolute where its server allows it).
async fn fetch_text(address: &str) -> Result<String, String> {
    let words = |e: JsValue| e.as_string().unwrap_or_else(|| format!("{e:?}"));
    let window = web_sys::window().ok_or("no window")?;
    let response: web_sys::Response =
        wasm_bindgen_futures::JsFuture::from(window.fetch_with_str(address))
            .await
            .map_err(words)?
            .dyn_into()
            .map_err(words)?;
    if !response.ok() {
        return Err(format!(
            "HTTP {} {}",
            response.status(),
            response.status_text()
        ));
    }
    let text = wasm_bindgen_futures::JsFuture::from(response.text().map_err(words)?)
        .await
        .map_err(words)?;
    text.as_string().ok_or_else(|| "not text".to_owned())
}

fn document() -> Option<web_sys::Document> {
    web_sys::window()?.document()
}

/// The link to share for a scene's `query`: this page's address with it.
pub fn share_address(query: &str) -> String {
    let location = web_sys::window().map(|w| w.location());
    let base = location
        .and_then(|l| Some(format!("{}{}", l.origin().ok()?, l.pathname().ok()?)))
        .unwrap_or_default();
    format!("{base}{query}")
}

/// What a shared link is, for the message that it was copied.
pub fn share_hint() -> String {
    tr!("share-hint-page")
}

/// Shows `text` in the page's `#error` element (the canvas may be what failed).
fn show_error(text: &str) {
    if let Some(element) = document().and_then(|d| d.get_element_by_id("error")) {
        element.set_text_content(Some(text));
        let _ = element.set_attribute("style", "display:block");
    }
}

/// The page's title.
pub fn set_title(_: &egui::Context, title: &str) {
    if let Some(document) = document() {
        document.set_title(title);
    }
}

thread_local! {
    /// Frames built so far (published as `data-frames`).
    static FRAMES: Cell<u64> = const { Cell::new(0) };
}

/// Puts `figures` on the canvas's data attributes, with the number of frames built; the first
/// frame also records when it was built (`data-first-frame-ms`, milliseconds since navigation).
pub fn publish(figures: &Figures) {
    let frames = FRAMES.get() + 1;
    FRAMES.set(frames);
    let Some(canvas) = document().and_then(|d| d.get_element_by_id(CANVAS_ID)) else {
        return;
    };
    if frames == 1
        && let Some(performance) = web_sys::window().and_then(|w| w.performance())
    {
        let _ = canvas.set_attribute("data-first-frame-ms", &format!("{:.1}", performance.now()));
    }
    let [left, top, width, height] = figures.view;
    for (name, value) in [
        ("data-mass", format!("{:e}", figures.mass)),
        ("data-volume", format!("{:e}", figures.volume)),
        ("data-omega", format!("{:e}", figures.omega)),
        ("data-momentum", format!("{:e}", figures.momentum)),
        ("data-time", format!("{:e}", figures.time)),
        (
            "data-orientation",
            figures.orientation.map(|c| format!("{c:e}")).join(" "),
        ),
        ("data-specimens", figures.specimens.to_string()),
        ("data-loading", figures.loading.is_some().to_string()),
        ("data-stage", figures.loading.clone().unwrap_or_default()),
        ("data-view", format!("{left} {top} {width} {height}")),
        ("data-focus", figures.focus.clone()),
        ("data-lesson", figures.lesson.clone()),
        ("data-lesson-step", figures.lesson_step.clone()),
        ("data-lessons", figures.lessons.to_string()),
        ("data-lang", figures.language.to_owned()),
        ("data-frames", frames.to_string()),
    ] {
        let _ = canvas.set_attribute(name, &value);
    }
    // A screen reader pronounces the page, its live regions included, in the document's language.
    if let Some(root) = document().and_then(|d| d.document_element())
        && root.get_attribute("lang").as_deref() != Some(figures.language)
    {
        let _ = root.set_attribute("lang", figures.language);
    }
    // The live region beside the canvas (eframe's web runner exposes no accessibility tree): a
    // screen reader reads it again whenever it changes, so it is written only then.
    for (id, text) in [(LIVE_ID, &figures.description), (FOCUS_ID, &figures.focus)] {
        if let Some(region) = document().and_then(|d| d.get_element_by_id(id))
            && region.text_content().as_deref() != Some(text.as_str())
        {
            region.set_text_content(Some(text));
        }
    }
}

/// A browser's file picker (for opening) or the name of the download (for saving). The picker
/// runs as a future on the page's event loop; the GUI polls for its answer.
#[derive(Debug)]
pub struct Dialog {
    /// What the chosen files are for.
    pub purpose: DialogPurpose,
    answer: Rc<RefCell<Option<Option<Chosen>>>>,
}

impl Dialog {
    /// Opens the picker for `purpose`, or answers at once with the name to download.
    pub fn open(purpose: DialogPurpose, wake: impl Fn() + 'static) -> Self {
        let answer = Rc::new(RefCell::new(None));
        let download = |name: &str| Some(Some(Chosen::Path(PathBuf::from(name))));
        match purpose {
            DialogPurpose::SaveCsv => *answer.borrow_mut() = download("inertia-lab.csv"),
            DialogPurpose::SaveBody => *answer.borrow_mut() = download("body.toml"),
            DialogPurpose::SaveMotion => *answer.borrow_mut() = download("motion.glb"),
            DialogPurpose::OpenMesh | DialogPurpose::AddPart => {
                let slot = Rc::clone(&answer);
                let dialog = rfd::AsyncFileDialog::new();
                let dialog = if purpose == DialogPurpose::OpenMesh {
                    dialog.add_filter(OPENABLE.label(), &OPENABLE.extensions())
                } else {
                    dialog.add_filter(part_label(), &part_extensions())
                };
                wasm_bindgen_futures::spawn_local(async move {
                    let picked = dialog.pick_files().await;
                    let mut files = FileSet::default();
                    for handle in picked.unwrap_or_default() {
                        let file = handle.inner();
                        match read(file).await {
                            Ok(bytes) => files.add(file.name(), bytes),
                            Err(e) => cannot_read(&file.name(), &e),
                        }
                    }
                    let chosen = files.main().is_some().then_some(Chosen::Files(files));
                    *slot.borrow_mut() = Some(chosen);
                    wake();
                });
            }
        }
        Self { purpose, answer }
    }

    /// `Some(answer)` once closed (`None` inside: cancelled).
    pub fn poll(&self) -> Option<Option<Chosen>> {
        self.answer.borrow_mut().take()
    }
}

/// Files dropped on the page, as the lab will read them: all of them (a body file with its
/// meshes) with their bytes, once the browser has read them.
#[derive(Debug)]
pub struct DroppedFiles(Rc<RefCell<Option<Option<LoadSource>>>>);

impl DroppedFiles {
    /// Starts reading the dropped files' bytes; `wake` is called when they are read.
    pub fn read(dropped: &[egui::DroppedFileHandle], wake: impl Fn() + 'static) -> Self {
        let answer = Rc::new(RefCell::new(None));
        let slot = Rc::clone(&answer);
        let dropped = dropped.to_vec();
        wasm_bindgen_futures::spawn_local(async move {
            let mut files = FileSet::default();
            for file in &dropped {
                match file.bytes_async().await {
                    Ok(bytes) => files.add(file.path(), bytes),
                    Err(e) => cannot_read(&file.path().display().to_string(), &e),
                }
            }
            *slot.borrow_mut() = Some(files.main().is_some().then_some(LoadSource::Files(files)));
            wake();
        });
        Self(answer)
    }

    /// `Some(files)` once read (`None` inside: the browser could read none of them).
    pub fn poll(&mut self) -> Option<Option<LoadSource>> {
        self.0.borrow_mut().take()
    }
}

/// The bytes of a file the user gave the page (the browser reads it; an error is its words).
async fn read(file: &web_sys::File) -> Result<Vec<u8>, String> {
    let buffer = wasm_bindgen_futures::JsFuture::from(file.array_buffer())
        .await
        .map_err(|e| e.as_string().unwrap_or_else(|| format!("{e:?}")))?;
    Ok(js_sys::Uint8Array::new(&buffer).to_vec())
}

/// A file the browser could not read, said in the console (the dialog then answers with the
/// files it could read, or that none was chosen).
fn cannot_read(name: &str, error: &str) {
    crate::platform::print_error(&format!("inertia-lab: cannot read {name}: {error}"));
}
