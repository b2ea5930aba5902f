//! What differs between the desktop and the browser below the GUI, in one place: the clock,
//! work off the UI thread (a [`Job`]: a thread, or the page's worker), files written (a browser downloads them), lines printed (a browser's
//! console), and what the system tells about the process (its memory). One side is compiled:
//! `native.rs` (threads, the file system, Linux's `/proc`) or `web.rs` (wasm32: one thread,
//! downloads, no process figures). The GUI's own differences (starting the app, files coming
//! in) are `gui/platform`.

#[cfg_attr(target_arch = "wasm32", path = "web.rs")]
#[cfg_attr(not(target_arch = "wasm32"), path = "native.rs")]
mod side;

mod job;

pub use job::{Job, JobEvent, decode, encode, event_of, serve};
pub use side::{
    memory, prepare_jobs, print, print_error, run_spawned, spawn, start_job, write_file,
};
/// The clock: std's on the desktop, the browser's `performance.now()` on the web, where
/// `std::time::Instant::now` panics (wasm32-unknown-unknown has no clock of its own).
pub use web_time::{Instant, SystemTime, UNIX_EPOCH};

/// Resident memory of this process, in KiB: now and at its peak.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Memory {
    /// Resident now (`VmRSS`).
    pub resident_kib: u64,
    /// The most resident so far (`VmHWM`).
    pub peak_kib: u64,
}
