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
    blender_addon(&venv, &work);
}

/// The Blender add-on (`crates/py/blender/inertia_lab`) under Blender as a Python module (bpy
/// 5.0.1, from `python3` on PATH: CI's consumer environment), with this package importable
/// beside it (the package alone: bpy keeps its own numpy). `tests/python/blender_addon.py`
/// imports the T-handle and a cube with a hole; here: the mass, centre and moments are
/// `props`' (to Blender's single-precision vertices), the hole is named as `props` names it,
/// the rigid body has the mass, the principal-axes empty sits at the centre of mass on the
/// principal axes, and the baked keys are `inertialab.simulate`'s motion put where the object
/// is, turning the intermediate axis over at half the flip period 4K(k)/λ and back at one.
fn blender_addon(venv: &Path, work: &Path) {
    const ADDON: &str = "python_package (the Blender add-on)";
    let has_bpy = Command::new("python3")
        .args(["-c", "import bpy"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !has_bpy {
        skip(
            ADDON,
            "Blender's Python module bpy is not installed for python3",
            "python3 -m venv .venv && .venv/bin/pip install bpy==5.0.1, then put .venv/bin \
             first on PATH",
        );
        return;
    }
    let site = Command::new(venv.join("bin/python"))
        .args([
            "-c",
            "import inertialab, os; print(os.path.dirname(inertialab.__file__))",
        ])
        .output()
        .expect("the environment's python runs");
    let package = PathBuf::from(String::from_utf8_lossy(&site.stdout).trim());
    let only = work.join("blender-path");
    std::fs::create_dir_all(&only).expect("a folder");
    let link = only.join("inertialab");
    let _ = std::fs::remove_file(&link);
    std::os::unix::fs::symlink(&package, &link).expect("the package linked");
    let open = work.join("open_cube.obj");
    std::fs::write(
        &open,
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
         f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n",
    )
    .expect("the open cube written");
    let body = root().join("assets/t_handle.obj");
    let path = std::env::join_paths([only, root().join("crates/py/blender")]).expect("a path");
    let out = Command::new("python3")
        .arg(root().join("tests/python/blender_addon.py"))
        .arg(&body)
        .arg(&open)
        .env("PYTHONPATH", path)
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "the add-on's script failed:\n{}",
        tail(&out)
    );
    let said = String::from_utf8_lossy(&out.stdout);
    let v: serde_json::Value =
        serde_json::from_str(said.lines().last().unwrap_or_default()).expect("the script's JSON");
    let f = |v: &serde_json::Value| v.as_f64().expect("a number");
    let floats = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array().expect("numbers").iter().map(f).collect()
    };
    let props = |file: &Path| -> serde_json::Value {
        let out = Command::new(env!("CARGO_BIN_EXE_inertia-lab"))
            .arg("props")
            .arg(file)
            .args(["--json", "--density", "1000"])
            .output()
            .expect("props runs");
        serde_json::from_slice(&out.stdout).expect("props' JSON")
    };
    // Blender keeps vertices in single precision: the numbers agree to its rounding.
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * b.abs().max(1e-12);
    let theirs = props(&body);
    let b = &v["body"];
    assert!(close(f(&b["mass"]), f(&theirs["mass"])), "{b}");
    for (m, t) in floats(&b["moments"])
        .iter()
        .zip(floats(&theirs["principal_moments"]))
    {
        assert!(close(*m, t), "{m} vs {t}");
    }
    assert_eq!(b["warnings"], serde_json::json!([]));
    assert!(close(f(&b["rigid_body_mass"]), f(&b["mass"])));
    // The empty: at the centre of mass, on the principal axes, in world (object matrix × local).
    let rows = |m: &serde_json::Value| -> Vec<Vec<f64>> {
        m.as_array().expect("rows").iter().map(floats).collect()
    };
    let (world, empty) = (rows(&b["matrix_world"]), rows(&b["empty"]));
    let c = floats(&b["centre"]);
    let axes = floats(&b["axes"]);
    for i in 0..3 {
        let at: f64 = (0..3).map(|k| world[i][k] * c[k]).sum::<f64>() + world[i][3];
        assert!((empty[i][3] - at).abs() < 1e-6, "{empty:?} vs centre {c:?}");
        for j in 0..3 {
            // Column j of the empty's rotation: principal axis j (row j of `axes`) in world.
            let axis: f64 = (0..3).map(|k| world[i][k] * axes[3 * j + k]).sum();
            assert!((empty[i][j] - axis).abs() < 1e-6, "{empty:?}");
        }
    }
    assert_eq!(v["kinematic"], true);
    // The keys: Blender's world rotation at frame k is the object's own R0 times the motion's.
    let quat = |q: &[f64]| {
        nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(q[0], q[1], q[2], q[3]))
    };
    let frames = v["frames"].as_array().expect("frames");
    let motion = v["motion"]["orientation"].as_array().expect("motion");
    let moved = v["motion"]["translation"].as_array().expect("motion");
    assert_eq!((frames.len(), motion.len()), (12 * 24 + 1, 12 * 24 + 1));
    let r0 = quat(&floats(&frames[0]["rotation"]));
    let intermediate = nalgebra::Vector3::from_column_slice(&axes[3..6]);
    let moments = nalgebra::Vector3::from_column_slice(&floats(&b["moments"]));
    // The spin the add-on gave (axis 2 at 10 rad/s, 0.1 of it about the others) and L from it,
    // fixed in world.
    let omega = nalgebra::Vector3::new(1.0, 10.0, 1.0);
    let l_principal = moments.component_mul(&omega);
    let l_world = r0
        * (0..3)
            .map(|i| nalgebra::Vector3::from_column_slice(&axes[3 * i..3 * i + 3]) * l_principal[i])
            .sum::<nalgebra::Vector3<f64>>()
            .normalize();
    let mut along = Vec::new();
    for (k, frame) in frames.iter().enumerate() {
        let seen = quat(&floats(&frame["rotation"]));
        let expected = r0 * quat(&floats(&motion[k]));
        assert!(
            seen.angle_to(&expected) < 1e-5,
            "frame {k}: {}",
            seen.angle_to(&expected)
        );
        let t = floats(&moved[k]);
        let at = r0 * nalgebra::Vector3::new(t[0], t[1], t[2]);
        let location = floats(&frame["location"]);
        assert!(
            (0..3).all(|i| (location[i] - at[i]).abs() < 1e-6),
            "frame {k}"
        );
        // The intermediate axis along L: L₂/|L| in the body, periodic with the flip.
        along.push((seen * intermediate).dot(&l_world));
    }
    let period = rbcore::torque_free_period(&moments, &l_principal).expect("a flip");
    let at = |t: f64| along[(t * 24.0).round() as usize];
    assert!(
        period < 12.0
            && at(0.0) > 0.9
            && (at(period / 2.0) + at(0.0)).abs() < 0.02
            && (at(period) - at(0.0)).abs() < 0.02,
        "T = {period} s: {} at 0, {} at T/2, {} at T",
        at(0.0),
        at(period / 2.0),
        at(period)
    );
    // The hole, named as props names it, and the mass with its cap.
    let open_props = props(&open);
    let o = &v["open"];
    let codes: Vec<String> = open_props["warnings"]
        .as_array()
        .expect("warnings")
        .iter()
        .map(|w| w["code"].as_str().expect("a code").to_owned())
        .collect();
    let named: Vec<&str> = o["warnings"]
        .as_array()
        .expect("lines")
        .iter()
        .filter_map(|l| l.as_str()?.split(':').next())
        .collect();
    assert_eq!(named, codes, "{o}");
    assert!(close(f(&o["mass"]), f(&open_props["mass"])), "{o}");
    let _ = writeln!(
        std::io::stderr(),
        "{ADDON}: Blender {}, T-handle flip period {period:.3} s baked, hole named {codes:?}",
        v["version"]
    );
}
