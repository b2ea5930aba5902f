//! Helpers shared by the integration tests that run the real binary.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The workspace root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Runs `inertia-lab` with `args` in the workspace root.
pub fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_inertia-lab"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("the binary runs")
}

/// A temporary file with given contents, removed on drop; names are unique per process and call.
pub struct TempFile(PathBuf);

static NEXT_FILE: AtomicUsize = AtomicUsize::new(0);

impl TempFile {
    /// Writes `contents` to a fresh temporary file whose name ends with `name`.
    pub fn new(name: &str, contents: &[u8]) -> Self {
        let n = NEXT_FILE.fetch_add(1, Ordering::Relaxed);
        let path =
            std::env::temp_dir().join(format!("inertia-lab-{}-{n}-{name}", std::process::id()));
        std::fs::write(&path, contents).expect("temp file written");
        Self(path)
    }

    /// The file's path as text, for command lines.
    pub fn path(&self) -> &str {
        self.0.to_str().expect("utf-8 temp path")
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}
