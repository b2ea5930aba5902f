//! The command-line build: `--no-default-features` leaves the desktop app out, and with it every
//! GUI crate, so servers, CI images and batch jobs build the CLI without a windowing stack. And
//! the builds that the workspace's own test run never makes (features are unified there) still
//! compile: the CLI alone, massprops without `io` and `parallel`, rbcore as it depends on it.

use std::process::Command;

/// The crate names in `cargo tree` of the app's normal dependencies, with `extra` arguments.
fn tree(extra: &[&str]) -> Vec<String> {
    let out = Command::new(env!("CARGO"))
        .args([
            "tree",
            "-p",
            "inertia-lab",
            "-e",
            "normal",
            "--prefix",
            "none",
        ])
        .arg("--offline")
        .args(extra)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| l.split(' ').next())
        .map(str::to_owned)
        .collect()
}

#[test]
fn cli_only_build_has_no_gui_crate_in_its_tree() {
    let gui_crates = [
        "eframe",
        "egui",
        "egui_glow",
        "egui_plot",
        "three-d",
        "rfd",
        "winit",
        "glow",
    ];
    let cli = tree(&["--no-default-features"]);
    assert!(cli.iter().any(|n| n == "rbcore"), "{cli:?}");
    for gui in gui_crates {
        assert!(
            !cli.iter().any(|n| n == gui),
            "{gui} is in the CLI-only tree"
        );
    }
    // The app's own build has them: the check above reads the right tree.
    let app = tree(&[]);
    assert!(app.iter().any(|n| n == "eframe"), "{app:?}");
}

/// `cargo check` of `args`, in the workspace's own target folder: Cargo releases it once the
/// test binaries are built, and the dependencies' check artifacts that `cargo clippy` left there
/// serve these feature sets too (a folder of its own cost CI three minutes to fill).
fn check(args: &[&str]) {
    let out = Command::new(env!("CARGO"))
        .args(["check", "--offline", "--quiet"])
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo runs");
    assert!(
        out.status.success(),
        "cargo check {}:\n{}",
        args.join(" "),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn builds_without_default_features_compile() {
    check(&["-p", "inertia-lab", "--no-default-features"]);
    check(&["-p", "massprops", "--no-default-features"]);
    check(&["-p", "rbcore"]);
}
