//! Inertia Lab in a browser: the entry point of the WebAssembly module that `web/build.sh`
//! builds. The app itself is `inertia-lab`'s, the same code as the desktop's; what differs is
//! its `gui/platform/web.rs`. On other targets this crate is empty.

/// Called by wasm-bindgen's glue when the module is loaded: starts the app on the page's
/// canvas.
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen(start)]
pub fn start() {
    inertia_lab::gui::platform::start();
}
