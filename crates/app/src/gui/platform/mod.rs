//! What differs between the desktop app and the page in a browser, for the GUI, in one place:
//! how the app starts (a window with the command line's arguments; a canvas with the link's),
//! how files come in (a native dialog or a path; a file picker or a drop, with their bytes), and
//! what the page shows beyond the canvas (its title, the figures scripts read). One side is
//! compiled: `native.rs` or `web.rs` (wasm32). Files going out need nothing here: the lab writes
//! them through [`crate::platform::write_file`], which a browser turns into downloads.

use std::path::PathBuf;

use inertia_io::input::FileSet;

#[cfg_attr(target_arch = "wasm32", path = "web.rs")]
#[cfg_attr(not(target_arch = "wasm32"), path = "native.rs")]
mod side;

pub use side::*;

/// Why a file dialog was opened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DialogPurpose {
    /// Pick a mesh or body file to load.
    OpenMesh,
    /// Choose where to write the plot CSV.
    SaveCsv,
    /// Pick a mesh to add as a part.
    AddPart,
    /// Choose where to write the body file.
    SaveBody,
    /// Choose where to write the baked motion (`.glb` or `.usda`).
    SaveMotion,
}

/// What a closed dialog gives.
#[derive(Debug, Clone, PartialEq)]
pub enum Chosen {
    /// A path (the desktop's dialogs; a browser's save, named by the file to download).
    Path(PathBuf),
    /// Files with their bytes (a browser's picker).
    Files(FileSet),
}

/// The figures a page publishes for scripts each frame: the primary specimen's, and where the
/// 3D view is.
#[derive(Debug, Clone, PartialEq)]
pub struct Figures {
    /// Its exact mass (kg).
    pub mass: f64,
    /// Its volume (m³).
    pub volume: f64,
    /// |ω| (rad/s).
    pub omega: f64,
    /// |L| about the centre of mass (kg m²/s): constant until a poke or the string acts.
    pub momentum: f64,
    /// Simulated time since the last start (s).
    pub time: f64,
    /// The body's orientation, a unit quaternion (w, x, y, z), body to world.
    pub orientation: [f64; 4],
    /// How many specimens run (the body and its copies).
    pub specimens: usize,
    /// What is happening, in words ([`crate::lab::describe`]): the page's live region.
    pub description: String,
    /// The widget that has the keyboard's focus, in words.
    pub focus: String,
    /// The open lesson's id (empty when none is open).
    pub lesson: String,
    /// Its step, `k/N`, or `done` (empty when none is open).
    pub lesson_step: String,
    /// How many built-in lessons there are.
    pub lessons: usize,
    /// The language the lab speaks (its code: `en`, `de`, `es`).
    pub language: &'static str,
    /// The stage of the file loading, when one is.
    pub loading: Option<String>,
    /// The 3D view's rectangle (left, top, width, height), in points: CSS pixels in a page.
    pub view: [f32; 4],
}
