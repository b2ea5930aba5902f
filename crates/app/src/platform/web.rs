//! The browser's side of [`platform`](super) (wasm32-unknown-unknown): the page has one thread,
//! so a [`Job`] runs in the page's worker (`web/worker.js`: the same wasm module loaded on
//! another thread of the browser's), started on the first job and kept; [`spawn`]ed work (what
//! is not a job) waits in a queue that [`run_spawned`] empties between frames; a file written
//! is a download named after it; lines go to the browser's console; and the page has no figures
//! of its process's memory.

use std::cell::RefCell;
use std::collections::{HashMap, VecDeque};
use std::path::Path;
use std::rc::Rc;

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::{Closure, JsValue};

use super::{Job, JobEvent, Memory, encode, event_of};

/// The worker's script, beside the page (web/build.sh puts it there).
const WORKER_SCRIPT: &str = "./worker.js";
/// Where a page with nothing beside it (`web/build.sh --single-file`, opened from the disk)
/// names the worker's script it made itself, a `blob:` address of a classic script (Chromium
/// starts no module worker from a blob of a page opened from the disk).
const WORKER_SCRIPT_GLOBAL: &str = "INERTIA_LAB_WORKER";

/// The worker's script and its kind: the classic one the page made itself, else the module
/// beside the page.
fn worker_script() -> (String, web_sys::WorkerType) {
    web_sys::window()
        .and_then(|w| js_sys::Reflect::get(&w, &WORKER_SCRIPT_GLOBAL.into()).ok())
        .and_then(|v| v.as_string())
        .map_or_else(
            || (WORKER_SCRIPT.to_owned(), web_sys::WorkerType::Module),
            |blob| (blob, web_sys::WorkerType::Classic),
        )
}

type Queued = Box<dyn FnOnce()>;

thread_local! {
    /// Jobs queued since the last [`run_spawned`], and those it will run next time.
    static JOBS: RefCell<(VecDeque<Queued>, VecDeque<Queued>)> = RefCell::default();
}

/// Queues `job` for the call of [`run_spawned`] after next: the frame that says "loading" is
/// painted before the page is busy with the work.
pub fn spawn(job: impl FnOnce() + Send + 'static) {
    JOBS.with_borrow_mut(|(queued, _)| queued.push_back(Box::new(job)));
}

/// Runs the jobs that were queued before the previous call, then makes those queued since
/// ready for the next one. The app calls it once a frame.
pub fn run_spawned() {
    let ready = JOBS.with_borrow_mut(|(queued, ready)| {
        let run = std::mem::take(ready);
        *ready = std::mem::take(queued);
        run
    });
    // Outside the borrow: a job may queue another.
    for job in ready {
        job();
    }
}

/// What the worker said of a job: a report or the output (`done`), as bytes; or that it failed.
enum Reply {
    Posted { done: bool, bytes: Vec<u8> },
    Failed(String),
}

/// The page's worker and the jobs sent to it that have not ended.
struct PageWorker {
    worker: web_sys::Worker,
    waiting: HashMap<u32, Rc<dyn Fn(Reply)>>,
    next_id: u32,
    /// Set when the worker failed: the next job starts a new one (a job that failed may have
    /// left the module's memory as it was mid-way).
    broken: bool,
    _on_message: Closure<dyn FnMut(web_sys::MessageEvent)>,
    _on_error: Closure<dyn FnMut(web_sys::Event)>,
}

thread_local! {
    static WORKER: RefCell<Option<PageWorker>> = const { RefCell::new(None) };
}

/// Starts the page's worker ahead of the first job, so that a file dropped soon after the page
/// opened waits for no instantiation. A failure is said in the console; the first job tries
/// again.
pub fn prepare_jobs() {
    let started = WORKER.with_borrow_mut(|slot| {
        if slot.is_none() {
            *slot = Some(start_worker()?);
        }
        Ok::<_, JsValue>(())
    });
    if let Err(e) = started {
        super::print_error(&format!("the page's worker did not start: {e:?}"));
    }
}

/// Sends job `J` to the page's worker; `on_event` hears its reports and its output when the
/// worker posts them (between the page's frames: the page goes on drawing meanwhile).
pub fn start_job<J: Job>(input: J::Input, on_event: impl Fn(JobEvent<J>) + Send + 'static) {
    let on_event = Rc::new(on_event);
    let hear = {
        let on_event = on_event.clone();
        move |reply: Reply| {
            on_event(match reply {
                Reply::Posted { done, bytes } => event_of::<J>(done, &bytes),
                Reply::Failed(words) => JobEvent::Lost(words),
            })
        }
    };
    let sent = encode(&input).and_then(|bytes| send(J::NAME, &bytes, Rc::new(hear)));
    if let Err(words) = sent {
        on_event(JobEvent::Lost(format!("{}: {words}", J::NAME)));
    }
}

/// Posts `input` for the job `name` to the worker (started if there is none, or a new one if it
/// failed), with `hear` waiting for its replies.
fn send(name: &str, input: &[u8], hear: Rc<dyn Fn(Reply)>) -> Result<(), String> {
    let words = |e: JsValue| e.as_string().unwrap_or_else(|| format!("{e:?}"));
    WORKER.with_borrow_mut(|slot| {
        if slot.as_ref().is_none_or(|w| w.broken) {
            if let Some(old) = slot.take() {
                old.worker.terminate();
            }
            *slot = Some(start_worker().map_err(words)?);
        }
        let page_worker = slot.as_mut().expect("started above");
        let id = page_worker.next_id;
        page_worker.next_id += 1;
        let bytes = js_sys::Uint8Array::from(input);
        let message = js_sys::Object::new();
        for (key, value) in [
            ("id", JsValue::from(id)),
            ("name", JsValue::from(name)),
            ("input", bytes.clone().into()),
        ] {
            js_sys::Reflect::set(&message, &key.into(), &value).map_err(words)?;
        }
        let transfer = js_sys::Array::of1(&bytes.buffer());
        page_worker
            .worker
            .post_message_with_transfer(&message, &transfer)
            .map_err(words)?;
        page_worker.waiting.insert(id, hear);
        Ok(())
    })
}

fn start_worker() -> Result<PageWorker, JsValue> {
    let (script, kind) = worker_script();
    let options = web_sys::WorkerOptions::new();
    options.set_type(kind);
    let worker = web_sys::Worker::new_with_options(&script, &options)?;
    let on_message =
        Closure::<dyn FnMut(web_sys::MessageEvent)>::new(|e: web_sys::MessageEvent| {
            let data = e.data();
            let field = |key: &str| js_sys::Reflect::get(&data, &key.into()).unwrap_or_default();
            let Some(id) = field("id").as_f64() else {
                return;
            };
            let reply = match field("kind").as_string().as_deref() {
                Some("failed") => Reply::Failed(field("message").as_string().unwrap_or_default()),
                kind => Reply::Posted {
                    done: kind == Some("done"),
                    bytes: js_sys::Uint8Array::new(&field("bytes")).to_vec(),
                },
            };
            hear(id as u32, reply);
        });
    // A plain Event, not an ErrorEvent, when the worker's script could not be loaded at all: its
    // message is read only where there is one (a missing one once panicked the page).
    let on_error = Closure::<dyn FnMut(web_sys::Event)>::new(|e: web_sys::Event| {
        let message = js_sys::Reflect::get(&e, &"message".into())
            .ok()
            .and_then(|m| m.as_string())
            .unwrap_or_else(|| "its script could not be loaded".to_owned());
        let words = format!("the page's worker stopped: {message}");
        super::print_error(&words);
        let waiting = WORKER.with_borrow_mut(|slot| {
            slot.as_mut().map_or_else(HashMap::new, |w| {
                w.broken = true;
                std::mem::take(&mut w.waiting)
            })
        });
        for hear in waiting.into_values() {
            hear(Reply::Failed(words.clone()));
        }
    });
    worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
    worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
    // The page's own compiled module: the worker instantiates it without fetching or compiling
    // the wasm again.
    let module = js_sys::Object::new();
    js_sys::Reflect::set(&module, &"module".into(), &wasm_bindgen::module())?;
    worker.post_message(&module)?;
    Ok(PageWorker {
        worker,
        waiting: HashMap::new(),
        next_id: 0,
        broken: false,
        _on_message: on_message,
        _on_error: on_error,
    })
}

/// Hands `reply` to the job `id` waits with (outside the worker's borrow: hearing may start
/// another job); a job that ended stops waiting, and one that failed leaves the worker broken.
fn hear(id: u32, reply: Reply) {
    let ended = !matches!(reply, Reply::Posted { done: false, .. });
    let hear = WORKER.with_borrow_mut(|slot| {
        let w = slot.as_mut()?;
        if matches!(reply, Reply::Failed(_)) {
            w.broken = true;
        }
        if ended {
            w.waiting.remove(&id)
        } else {
            w.waiting.get(&id).cloned()
        }
    });
    if let Some(hear) = hear {
        hear(reply);
    }
}

/// The page cannot tell its memory.
pub fn memory() -> Option<Memory> {
    None
}

/// Hands `bytes` to the browser as a download named after `path`'s file name (a page cannot
/// choose a folder: the browser puts it in the user's downloads).
///
/// # Errors
/// The browser refused to make the file or the link that downloads it.
pub fn write_file(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let name = path.file_name().map_or_else(
        || "download".to_owned(),
        |n| n.to_string_lossy().into_owned(),
    );
    download(&name, bytes).map_err(|e| std::io::Error::other(format!("{e:?}")))
}

fn download(name: &str, bytes: &[u8]) -> Result<(), wasm_bindgen::JsValue> {
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type("application/octet-stream");
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob)?;
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let link: web_sys::HtmlAnchorElement = document.create_element("a")?.dyn_into()?;
    link.set_href(&url);
    link.set_download(name);
    link.click();
    // Not at once: the browser reads the blob after the click returns, and a large one revoked
    // now is downloaded as an empty, never-finished file (seen with a recording's archive).
    let revoke = Closure::once_into_js(move || {
        let _ = web_sys::Url::revoke_object_url(&url);
    });
    web_sys::window()
        .ok_or("no window")?
        .set_timeout_with_callback_and_timeout_and_arguments_0(revoke.unchecked_ref(), 60_000)?;
    Ok(())
}

/// A line in the browser's console (a benchmark's table).
pub fn print(line: &str) {
    web_sys::console::log_1(&line.into());
}

/// A line in the browser's console, as an error.
pub fn print_error(line: &str) {
    web_sys::console::error_1(&line.into());
}
