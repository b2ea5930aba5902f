//! Helpers shared by the integration tests: running the real binary, temporary files, and the
//! one rule for tests that need an optional tool ([`skip`]).

// Each test binary includes this module and uses a different part of it.
#![allow(dead_code)]

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

use serde_json::Value;

/// The puppeteer-core the browser tests drive Chromium with (24: the last line that runs on
/// Node.js 20).
pub const PUPPETEER: &str = "puppeteer-core@24.43.1";

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

/// libsdformat's reader (`tests/consumers/sdf_bodies.cc`), compiled once per run against
/// Debian's libsdformat 12; `None` (the skip reported) where the headers or g++ are missing.
pub fn sdf_bodies(test: &str) -> Option<PathBuf> {
    static BUILT: std::sync::OnceLock<Result<PathBuf, String>> = std::sync::OnceLock::new();
    let has = |program: &str, args: &[&str]| {
        Command::new(program)
            .args(args)
            .output()
            .is_ok_and(|o| o.status.success())
    };
    if !has("g++", &["--version"]) || !has("pkg-config", &["--exists", "sdformat12"]) {
        skip(
            test,
            "libsdformat 12's headers, pkg-config or g++ are missing",
            "apt install libsdformat-dev pkg-config g++",
        );
        return None;
    }
    let built = BUILT.get_or_init(|| {
        let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("sdf_bodies");
        let flags = Command::new("pkg-config")
            .args(["--cflags", "--libs", "sdformat12"])
            .output()
            .map_err(|e| e.to_string())?;
        let flags = String::from_utf8_lossy(&flags.stdout).into_owned();
        let compiled = Command::new("g++")
            .args(["-std=c++17", "-O1"])
            .arg(root().join("tests/consumers/sdf_bodies.cc"))
            .args(flags.split_whitespace())
            .arg("-o")
            .arg(&out)
            .output()
            .map_err(|e| e.to_string())?;
        if compiled.status.success() {
            Ok(out)
        } else {
            Err(String::from_utf8_lossy(&compiled.stderr).into_owned())
        }
    });
    Some(built.clone().expect("sdf_bodies.cc compiles"))
}

/// What libsdformat reads of every link of `file` (model://NAME found in `models`).
pub fn sdformat_bodies(reader: &Path, file: &Path, models: &Path) -> Value {
    let out = Command::new(reader)
        .arg(file)
        .arg(models)
        .output()
        .expect("sdf_bodies runs");
    assert!(
        out.status.success(),
        "libsdformat on {}:\n{}",
        file.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}
