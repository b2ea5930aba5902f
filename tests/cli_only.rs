//! The command-line build: `--no-default-features` leaves the desktop app out, and with it every
//! GUI crate, so servers, CI images and batch jobs build the CLI without a windowing stack.

use std::process::Command;

#[test]
fn cli_only_build_has_no_gui_crate_in_its_tree() {
    let out = Command::new(env!("CARGO"))
        .args([
            "tree",
            "-p",
            "inertia-lab",
            "--no-default-features",
            "-e",
            "normal",
            "--prefix",
            "none",
            "--offline",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let tree = String::from_utf8_lossy(&out.stdout);
    let names: Vec<&str> = tree.lines().filter_map(|l| l.split(' ').next()).collect();
    assert!(
        names.contains(&"massprops") && names.contains(&"rbcore"),
        "{tree}"
    );
    for gui in [
        "eframe",
        "egui",
        "egui_glow",
        "egui_plot",
        "three-d",
        "rfd",
        "winit",
        "glow",
    ] {
        assert!(
            !names.contains(&gui),
            "{gui} is in the CLI-only tree:\n{tree}"
        );
    }
    // And the app's build has them: the check above looks at the right tree.
    let full = Command::new(env!("CARGO"))
        .args([
            "tree",
            "-p",
            "inertia-lab",
            "-e",
            "normal",
            "--prefix",
            "none",
            "--offline",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo runs");
    assert!(
        String::from_utf8_lossy(&full.stdout)
            .lines()
            .any(|l| l.starts_with("eframe "))
    );
}
