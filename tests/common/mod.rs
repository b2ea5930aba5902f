//! Helpers shared by the integration tests: running the real binary, temporary files, and the
//! one rule for tests that need an optional tool ([`skip`]).

// Each test binary includes this module and uses a different part of it.
#![allow(dead_code)]

use std::io::Write as _;
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

/// Whether this run is CI (`CI` set to anything but empty, `0` or `false`), where every test must
/// really run: `.ci/run` installs every optional tool and package first.
pub fn in_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| !matches!(v.trim(), "" | "0" | "false"))
}

/// Reports that `test` cannot run here because `missing` is absent, with the one command that
/// installs it. Under CI this fails the test instead, so CI proves nothing was skipped.
///
/// The line goes straight to the process's stderr (not through `eprintln!`, which the test
/// harness captures and hides for passing tests), so a newcomer sees it in `cargo test`'s output.
pub fn skip(test: &str, missing: &str, install: &str) {
    let line = format!("SKIPPED {test}: {missing} ({install})");
    assert!(!in_ci(), "{line}, but CI is set: CI must run every test");
    let _ = writeln!(std::io::stderr(), "{line}");
}

/// Whether `program` is an executable file on `PATH`.
pub fn on_path(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|dir| dir.join(program).is_file()))
}
