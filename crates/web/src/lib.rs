//! Inertia Lab in a browser: the entry points of the WebAssembly module that `web/build.sh`
//! builds. The app itself is `inertia-lab`'s, the same code as the desktop's; what differs is
//! its `platform/web.rs` and `gui/platform/web.rs`. The module runs twice: on the page (the
//! app) and in the page's worker (`web/worker.js`), which runs the jobs listed here so the page
//! goes on drawing. On other targets this crate is empty.

/// Called by wasm-bindgen's glue when the module is loaded: starts the app on the page's canvas
/// (in the worker, where there is no page, nothing).
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen(start)]
pub fn start() {
    inertia_lab::gui::platform::start();
}

/// Runs the job called `name` on its encoded `input` in the page's worker; its reports and then
/// its output go back through `post(done, bytes)`. `web/worker.js` calls it.
///
/// # Errors
/// No job has that name, or its input or output could not be read or written.
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn run_job(
    name: &str,
    input: &[u8],
    post: &js_sys::Function,
) -> Result<(), wasm_bindgen::JsValue> {
    use inertia_lab::lab::loader::LoadFiles;
    use inertia_lab::platform::{Job, serve};

    let post = |done: bool, bytes: Vec<u8>| {
        let bytes = js_sys::Uint8Array::from(&bytes[..]);
        // A post fails only when the page is gone.
        let _ = post.call2(&wasm_bindgen::JsValue::NULL, &done.into(), &bytes);
    };
    let served = match name {
        LoadFiles::NAME => serve::<LoadFiles>(input, &post),
        other => Err(format!("no job is called {other:?}")),
    };
    served.map_err(|words| format!("{name}: {words}").into())
}
