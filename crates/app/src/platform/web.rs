//! The browser's side of [`platform`](super) (wasm32-unknown-unknown): there is one thread, so
//! [`spawn`]ed work waits in a queue that [`run_spawned`] empties between frames; a file written
//! is a download named after it; lines go to the browser's console; and the page has no figures
//! of its process's memory.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::path::Path;

use wasm_bindgen::JsCast;

use super::Memory;

type Job = Box<dyn FnOnce()>;

thread_local! {
    /// Jobs queued since the last [`run_spawned`], and those it will run next time.
    static JOBS: RefCell<(VecDeque<Job>, VecDeque<Job>)> = RefCell::default();
}

/// Queues `job` for the call of [`run_spawned`] after next: the frame that says "loading" is
/// painted before the page is busy with the work.
pub fn spawn(job: impl FnOnce() + Send + 'static) {
    JOBS.with_borrow_mut(|(queued, _)| queued.push_back(Box::new(job)));
}

/// Runs the jobs that were queued before the previous call, then makes those queued since
/// ready for the next one. The lab calls it whenever it asks a job for news.
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
    web_sys::Url::revoke_object_url(&url)
}

/// A line in the browser's console (a benchmark's table).
pub fn print(line: &str) {
    web_sys::console::log_1(&line.into());
}

/// A line in the browser's console, as an error.
pub fn print_error(line: &str) {
    web_sys::console::error_1(&line.into());
}
