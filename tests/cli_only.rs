//! The command-line build: `--no-default-features` leaves the desktop app out, and with it every
//! GUI crate, so servers, CI images and batch jobs build the CLI without a windowing stack.

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
