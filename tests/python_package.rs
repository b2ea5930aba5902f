//! The Python package (`crates/py`), built and installed as a user installs it
//! (`pip install ./crates/py`) into a virtual environment of its own, then tested by its pytest
//! suite (`crates/py/tests/`) against the `inertia-lab` binary of this same build.
//!
//! The environment lives in Cargo's target folder (`tmp/py/venv`) with what the tests need
//! (`crates/py/tests/requirements.txt`: pyarrow, trimesh, Dask, Ray, …), installed once and again
//! only when that list changes; the package is rebuilt every run (Cargo's incremental build, in
//! `tmp/py/build`, apart from this test's own target folder, which Cargo holds locked). Without
//! python3's venv module or the package registry the test prints a SKIPPED line (a failure under
//! `CI`).

mod common;

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use common::{in_ci, root, skip};

const TEST: &str = "python_package";

fn tail(out: &Output) -> String {
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<&str> = text.lines().collect();
    lines[lines.len().saturating_sub(40)..].join("\n")
}

/// The environment's folder and its python, made (and its requirements installed) when
/// missing or out of date; `None` after reporting a skip.
fn environment(work: &Path) -> Option<PathBuf> {
    let venv = work.join("venv");
    let python = venv.join("bin").join("python");
    if !python.is_file() {
        let made = Command::new("python3")
            .args(["-m", "venv"])
            .arg(&venv)
            .output();
        match made {
            Ok(out) if out.status.success() => {}
            Ok(out) => {
                skip(
                    TEST,
                    &format!("python3 cannot make a virtual environment: {}", tail(&out)),
                    "apt-get install python3-venv",
                );
                return None;
            }
            Err(_) => {
                skip(
                    TEST,
                    "python3 is not installed",
                    "apt-get install python3 python3-venv",
                );
                return None;
            }
        }
    }
    let requirements = root().join("crates/py/tests/requirements.txt");
    let wanted = std::fs::read_to_string(&requirements).expect("requirements.txt is readable");
    let stamp = work.join("installed-requirements.txt");
    if std::fs::read_to_string(&stamp).ok().as_deref() != Some(wanted.as_str()) {
        let out = Command::new(&python)
            .args([
                "-m",
                "pip",
                "install",
                "--disable-pip-version-check",
                "-q",
                "-r",
            ])
            .arg(&requirements)
            .output()
            .expect("pip runs");
        if !out.status.success() {
            skip(
                TEST,
                &format!(
                    "pip could not install the test requirements (is the package registry \
                     reachable?): {}",
                    tail(&out)
                ),
                "network access to pypi.org, or a mirror in PIP_INDEX_URL",
            );
            return None;
        }
        std::fs::write(&stamp, &wanted).expect("stamp written");
    }
    Some(venv)
}

#[test]
fn the_package_builds_installs_and_passes_its_tests() {
    let work = Path::new(env!("CARGO_TARGET_TMPDIR")).join("py");
    std::fs::create_dir_all(&work).expect("work folder");
    let Some(venv) = environment(&work) else {
        return;
    };
    let bin = venv.join("bin");
    let path = std::env::join_paths(std::iter::once(bin.clone()).chain(std::env::split_paths(
        &std::env::var_os("PATH").unwrap_or_default(),
    )))
    .expect("PATH");
    // Exactly what a user types in a fresh checkout, with the environment's pip.
    let install = Command::new(bin.join("python"))
        .args([
            "-m",
            "pip",
            "install",
            "--disable-pip-version-check",
            "-q",
            "--force-reinstall",
            "--no-deps",
            "./crates/py",
        ])
        .current_dir(root())
        .env("PATH", &path)
        .env("CARGO_TARGET_DIR", work.join("build"))
        .output()
        .expect("pip runs");
    assert!(
        install.status.success(),
        "pip install ./crates/py failed:\n{}",
        tail(&install)
    );
    let pytest = Command::new(bin.join("python"))
        .args([
            "-m",
            "pytest",
            "crates/py/tests",
            "-q",
            "-rs",
            "-p",
            "no:cacheprovider",
        ])
        .current_dir(root())
        .env("PATH", &path)
        .env("INERTIA_LAB_BIN", env!("CARGO_BIN_EXE_inertia-lab"))
        .env("CI", if in_ci() { "true" } else { "" })
        .output()
        .expect("pytest runs");
    let report = tail(&pytest);
    // The Python tests' own skips, in the form every skip of this workspace has.
    // Straight to stderr, past the harness's capture, as `common::skip` writes.
    for line in report.lines().filter(|l| l.contains("SKIPPED")) {
        let _ = writeln!(std::io::stderr(), "{line}");
    }
    assert!(
        pytest.status.success(),
        "the Python tests failed:\n{report}"
    );
    let summary = report.lines().last().unwrap_or_default();
    let _ = writeln!(std::io::stderr(), "{TEST}: pytest {summary}");
}
