//! `inertia-lab audit` end to end: the pybullet Panda's placeholder inertias proved impossible,
//! the fix loaded by yourdfpy and compiled by MuJoCo with our values, MuJoCo's own inertia of
//! geoms against our closed forms, an SDFormat arm and its fix read by libsdformat, and the errors
//! a user sees.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use common::{root, run, sdf_bodies, sdformat_bodies, skip};
use serde_json::Value;

/// The description's JSON report, which must exit 0.
fn audit_json(args: &[&str]) -> Value {
    let mut all = vec!["audit"];
    all.extend_from_slice(args);
    all.push("--json");
    let out = run(&all);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

fn link<'a>(report: &'a Value, name: &str) -> &'a Value {
    report["links"]
        .as_array()
        .expect("present")
        .iter()
        .find(|l| l["name"] == name)
        .unwrap_or_else(|| panic!("no link {name}"))
}

fn finding<'a>(l: &'a Value, code: &str) -> Option<&'a Value> {
    l["findings"]
        .as_array()
        .expect("present")
        .iter()
        .find(|f| f["code"] == code)
}

fn f64s(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(f64s).collect(),
        other => vec![other.as_f64().expect("a number")],
    }
}

/// Largest |a − b| over the largest |b|.
fn relative(a: &Value, b: &Value) -> f64 {
    let (a, b) = (f64s(a), f64s(b));
    assert_eq!(a.len(), b.len());
    let scale = b
        .iter()
        .fold(0.0f64, |m, x| m.max(x.abs()))
        .max(f64::MIN_POSITIVE);
    a.iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
        / scale
}

const PANDA: &str = "tests/data/robots/franka_panda/panda.urdf";

#[test]
fn the_pybullet_panda_placeholders_are_proved_impossible_with_the_bound() {
    let report = audit_json(&[PANDA]);
    assert_eq!(report["schema_version"], 1);
    for name in ["panda_leftfinger", "panda_rightfinger", "panda_hand"] {
        let l = link(&report, name);
        let f = finding(l, "impossible_moment").unwrap_or_else(|| panic!("{name}: {l}"));
        assert_eq!(f["proof"], true);
        let mass = f["mass"].as_f64().expect("present");
        let moments = f["moments"].as_array().expect("present");
        assert_eq!(moments.len(), 3, "{name}: all three moments exceed m r^2");
        for m in moments {
            let (moment, bound, r) = (
                m["moment"].as_f64().expect("present"),
                m["bound"].as_f64().expect("present"),
                m["radius"].as_f64().expect("present"),
            );
            assert_eq!(moment, 0.1);
            assert!((bound - mass * r * r).abs() <= 1e-15 * bound);
            // A finger is a few centimetres long; the hand about 20 cm across.
            assert!(r < 0.12, "{name}: r = {r}");
            assert!(moment > 8.0 * bound, "{name}: {moment} vs {bound}");
        }
        assert!(finding(l, "placeholder").is_some());
        let message = f["message"].as_str().expect("present");
        assert!(message.contains("proof"), "{message}");
    }
    // The table names the angles between the principal axes both ways (free where the stated
    // moments are equal, as all the Panda's are).
    let table = run(&["audit", PANDA]);
    let text = String::from_utf8_lossy(&table.stdout);
    assert!(
        text.contains("between their principal axes 1, 2, 3: free, free, free"),
        "{text}"
    );
    // The fingers' uniform-density moments: 7e-6 … 2.6e-5 kg·m² (over 3 800× less than 0.1).
    let finger = &link(&report, "panda_leftfinger")["computed"];
    let moments = f64s(&finger["principal_moments"]);
    assert!(moments[0] > 6e-6 && moments[2] < 2.7e-5, "{moments:?}");
}

/// A copy of the Panda's folder in the test's own scratch space (the fix is written beside it,
/// where its package paths resolve).
fn panda_copy(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    let source = root().join("tests/data/robots/franka_panda");
    for entry in walk(&source) {
        let to = dir.join(entry.strip_prefix(&source).expect("present"));
        std::fs::create_dir_all(to.parent().expect("present")).expect("present");
        std::fs::copy(&entry, &to).expect("present");
    }
    dir
}

fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    for e in std::fs::read_dir(dir).expect("present") {
        let p = e.expect("present").path();
        if p.is_dir() {
            files.extend(walk(&p));
        } else {
            files.push(p);
        }
    }
    files
}

/// Whether python3 can import `module`; reports the skip otherwise.
fn python_has(test: &str, module: &str, version: &str) -> bool {
    let ok = Command::new("python3")
        .args(["-c", &format!("import {module}")])
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        skip(
            test,
            &format!("the Python package {module} is not installed"),
            &format!(
                "python3 -m venv .venv && .venv/bin/pip install {module}=={version}, then put .venv/bin first on PATH"
            ),
        );
    }
    ok
}

fn bodies(loader: &str, file: &Path) -> Value {
    let out = Command::new("python3")
        .arg(root().join("tests/python/robot_bodies.py"))
        .arg(loader)
        .arg(file)
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "{loader} on {}:\n{}",
        file.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

/// Text without the inertials and the fix's comments: what the fix must leave unchanged.
fn without_inertials(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(start) = rest.find("<inertial") {
        let mut head = &rest[..start];
        if let Some(c) = head.rfind("<!-- inertia-lab audit, fixed:") {
            head = head[..c].trim_end_matches([' ', '\t']);
        }
        out.push_str(head.trim_end());
        let end = rest[start..]
            .find("</inertial>")
            .map(|e| start + e + "</inertial>".len())
            .or_else(|| rest[start..].find("/>").map(|e| start + e + 2))
            .expect("present");
        out.push('\u{1}');
        rest = &rest[end..];
    }
    out + rest
}

/// The fixed description as yourdfpy and MuJoCo load it: each changed link's mass, centre and
/// tensor those of `ours` (yourdfpy keeps the written numbers exactly; MuJoCo diagonalises and
/// recomposes the tensor, to 1e-9).
fn read_back(test: &str, fixed: &Path, changed: &[&str], ours: impl Fn(&str) -> Value) {
    if python_has(test, "yourdfpy", "0.0.60") {
        let read = bodies("yourdfpy", fixed);
        for name in changed {
            let (b, c) = (&read["bodies"][name], ours(name));
            assert_eq!(b["mass"], c["mass"], "{name}");
            assert!(relative(&b["com"], &c["center_of_mass"]) < 1e-15, "{name}");
            assert!(relative(&b["tensor"], &c["inertia"]) < 1e-15, "{name}");
        }
    }
    if python_has(test, "mujoco", "4.0.0") {
        let read = bodies("mujoco", fixed);
        for name in changed {
            let (b, c) = (&read["bodies"][name], ours(name));
            assert!(relative(&b["mass"], &c["mass"]) < 1e-12, "{name}");
            assert!(relative(&b["com"], &c["center_of_mass"]) < 1e-9, "{name}");
            assert!(
                relative(&b["tensor"], &c["inertia"]) < 1e-9,
                "{name}: {} vs {}",
                b["tensor"],
                c["inertia"]
            );
        }
    }
}

#[test]
fn the_fixed_panda_loads_in_yourdfpy_and_mujoco_with_our_values() {
    let test = "the_fixed_panda_loads_in_yourdfpy_and_mujoco_with_our_values";
    let dir = panda_copy("panda_fix");
    let original = dir.join("panda.urdf");
    let fixed = dir.join("panda_fixed.urdf");
    let report = audit_json(&[
        original.to_str().expect("present"),
        "--fix",
        "-o",
        fixed.to_str().expect("present"),
    ]);
    let changed: Vec<&str> = report["fixed"]["links"]
        .as_array()
        .expect("present")
        .iter()
        .map(|v| v.as_str().expect("present"))
        .collect();
    assert_eq!(changed.len(), 11, "every link with geometry: {changed:?}");

    let before = std::fs::read_to_string(&original).expect("present");
    let after = std::fs::read_to_string(&fixed).expect("present");
    assert_eq!(
        without_inertials(&before),
        without_inertials(&after),
        "only inertials change"
    );
    assert_eq!(after.matches("inertia-lab audit, fixed").count(), 11);

    let ours = |name: &str| link(&report, name)["computed"].clone();
    read_back(test, &fixed, &changed, ours);
}

/// The findings that prove a stated inertial impossible (what the nearest fix must remove).
const IMPOSSIBLE: [&str; 4] = [
    "impossible_moment",
    "triangle_inequality",
    "not_positive_definite",
    "com_outside_geometry",
];

/// `--fix-mode nearest` on the Panda: every link proved impossible gets the valid inertial
/// nearest to its stated one (stated mass kept), which the audit of the fixed file then finds
/// nothing impossible in, and which yourdfpy and MuJoCo read back as written.
#[test]
fn the_nearest_fix_lands_inside_and_loads_as_written() {
    let test = "the_nearest_fix_lands_inside_and_loads_as_written";
    let dir = panda_copy("panda_nearest");
    let original = dir.join("panda.urdf");
    let fixed = dir.join("panda_nearest.urdf");
    let report = audit_json(&[
        original.to_str().expect("present"),
        "--fix",
        "--fix-mode",
        "nearest",
        "-o",
        fixed.to_str().expect("present"),
    ]);
    let impossible: Vec<&Value> = report["links"]
        .as_array()
        .expect("present")
        .iter()
        .filter(|l| IMPOSSIBLE.iter().any(|c| finding(l, c).is_some()))
        .collect();
    assert!(impossible.len() >= 5, "{}", impossible.len());
    let changed: Vec<&str> = report["fixed"]["links"]
        .as_array()
        .expect("present")
        .iter()
        .map(|v| v.as_str().expect("present"))
        .collect();
    for l in &impossible {
        let name = l["name"].as_str().expect("a name");
        assert!(changed.contains(&name), "{name} not fixed: {changed:?}");
        let n = &l["nearest"];
        assert_eq!(n["mass"], l["stated"]["mass"], "{name}");
        assert!(n["moved"].as_f64().expect("moved") > 0.0, "{name}");
        assert!(
            !n["held_by"].as_array().expect("held_by").is_empty(),
            "{name}"
        );
    }

    let before = std::fs::read_to_string(&original).expect("present");
    let after = std::fs::read_to_string(&fixed).expect("present");
    assert_eq!(
        without_inertials(&before),
        // The comment's head as the geometry fix writes it, which without_inertials knows.
        without_inertials(&after.replace("fixed (nearest):", "fixed:")),
        "only inertials change"
    );
    let again = audit_json(&[fixed.to_str().expect("present")]);
    for name in &changed {
        let l = link(&again, name);
        for code in IMPOSSIBLE {
            assert!(finding(l, code).is_none(), "{name}: still {code}");
        }
        let n = &link(&report, name)["nearest"];
        assert!(
            relative(&l["stated"]["inertia"], &n["inertia"]) < 1e-15,
            "{name}"
        );
        assert!(
            relative(&l["stated"]["center_of_mass"], &n["center_of_mass"]) < 1e-15,
            "{name}"
        );
    }
    read_back(test, &fixed, &changed, |name| {
        link(&report, name)["nearest"].clone()
    });
}

/// `--masses`: a link weighed at its measured mass, the stated one that differs named, and
/// both fixes writing the measured mass (and centre); a name the robot lacks is refused.
#[test]
fn measured_masses_are_weighed_at_named_and_kept_by_both_fixes() {
    let dir = panda_copy("panda_masses");
    let original = dir.join("panda.urdf");
    let masses = dir.join("masses.csv");
    std::fs::write(
        &masses,
        "link,mass,x,y,z\npanda_link1,3.1,0.0,-0.035,-0.06\npanda_hand,0.9\n",
    )
    .expect("written");
    let path = |p: &Path| p.to_str().expect("UTF-8").to_owned();
    let report = audit_json(&[&path(&original), "--masses", &path(&masses)]);
    let link1 = link(&report, "panda_link1");
    assert_eq!(link1["computed"]["mass"], 3.1);
    assert_eq!(link1["computed"]["basis"], "measured_mass");
    assert_eq!(
        link1["measured"]["center_of_mass"],
        serde_json::json!([0.0, -0.035, -0.06])
    );
    let differs = finding(link1, "differs_from_measured").expect("named");
    assert_eq!(differs["stated_mass"], 2.7);
    assert_eq!(differs["measured_mass"], 3.1);
    let offset = differs["center_offset"].as_f64().expect("an offset");
    assert!(
        (offset - (0.005f64.powi(2) + 0.01f64.powi(2)).sqrt()).abs() < 1e-12,
        "{offset}"
    );
    // The hand states 0.81 kg, weighed 0.9: named too, its centre not measured.
    let hand = finding(link(&report, "panda_hand"), "differs_from_measured").expect("named");
    assert_eq!(hand["measured_center_of_mass"], Value::Null);

    for mode in ["geometry", "nearest"] {
        let fixed = dir.join(format!("fixed_{mode}.urdf"));
        let out = audit_json(&[
            &path(&original),
            "--masses",
            &path(&masses),
            "--fix",
            "--fix-mode",
            mode,
            "-o",
            &path(&fixed),
        ]);
        assert!(
            out["fixed"]["links"]
                .as_array()
                .expect("links")
                .iter()
                .any(|l| l == "panda_link1"),
            "{mode}"
        );
        // Well-formed as written: no "--" inside the fix's comments (strict XML refuses it).
        let text = std::fs::read_to_string(&fixed).expect("written");
        if let Err(e) = roxmltree::Document::parse(&text) {
            panic!("{mode}: the fixed file is not well-formed XML: {e}");
        }
        let again = audit_json(&[&path(&fixed)]);
        let link1 = link(&again, "panda_link1");
        assert_eq!(link1["stated"]["mass"], 3.1, "{mode}");
        assert!(
            relative(
                &link1["stated"]["center_of_mass"],
                &serde_json::json!([0.0, -0.035, -0.06])
            ) < 1e-15,
            "{mode}: {}",
            link1["stated"]["center_of_mass"]
        );
        assert_eq!(link(&again, "panda_hand")["stated"]["mass"], 0.9, "{mode}");
    }

    std::fs::write(&masses, "panda_link1,3.1\nwrist,1\n").expect("written");
    let out = run(&["audit", &path(&original), "--masses", &path(&masses)]);
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        said.contains("the robot has no link named \"wrist\" (its links: panda_link0, "),
        "{said}"
    );
}

/// Bodies whose inertia MuJoCo infers from primitive geoms, one fixed from a placeholder, and
/// one with a rotated, offset inertial.
const MJCF: &str = r#"<mujoco model="shapes">
  <compiler angle="degree"/>
  <default>
    <geom density="700"/>
    <default class="arm"><geom type="capsule" size="0.04"/></default>
  </default>
  <worldbody>
    <body name="capsule" pos="0 0 1" childclass="arm">
      <freejoint/>
      <geom fromto="0 0 0 0.3 0.1 0.05"/>
    </body>
    <body name="mixed" pos="1 0 0" euler="10 20 30">
      <freejoint/>
      <geom type="box" size="0.1 0.2 0.05" pos="0.05 0 0" euler="0 0 40"/>
      <geom type="cylinder" size="0.05 0.1" pos="0 0.3 0" zaxis="1 1 0" density="2000"/>
      <geom type="sphere" size="0.07" pos="-0.2 0 0" mass="1.5"/>
      <geom type="ellipsoid" size="0.05 0.08 0.12" pos="0 -0.2 0.1" quat="0.9 0.1 0.3 0.2"/>
      <geom type="capsule" size="0.02" fromto="0 0 0.2 0.1 0.1 0.3" contype="0" conaffinity="0"/>
      <geom type="sphere" size="0.05" pos="0 0 -0.3" group="6"/>
    </body>
    <body name="placeholder" pos="2 0 0">
      <freejoint/>
      <inertial pos="0 0 0" mass="2" diaginertia="1 1 1"/>
      <geom type="box" size="0.1 0.1 0.3"/>
    </body>
  </worldbody>
</mujoco>
"#;

#[test]
fn mujoco_infers_the_same_inertia_from_geoms_and_compiles_the_fix_to_our_values() {
    let test = "mujoco_infers_the_same_inertia_from_geoms_and_compiles_the_fix_to_our_values";
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("mjcf_fix");
    std::fs::create_dir_all(&dir).expect("present");
    let original = dir.join("shapes.xml");
    std::fs::write(&original, MJCF).expect("present");
    let fixed = dir.join("shapes_fixed.xml");
    let report = audit_json(&[
        original.to_str().expect("present"),
        "--fix",
        "-o",
        fixed.to_str().expect("present"),
        "--fix-links",
        "all",
    ]);
    let placeholder = link(&report, "placeholder");
    assert!(
        finding(placeholder, "impossible_moment").is_some()
            && finding(placeholder, "placeholder").is_some()
    );
    if !python_has(test, "mujoco", "4.0.0") {
        return;
    }
    // MuJoCo's own inertia of the primitives (the original file: no inertial on two bodies).
    let theirs = bodies("mujoco", &original);
    for name in ["capsule", "mixed"] {
        let (b, c) = (&theirs["bodies"][name], &link(&report, name)["computed"]);
        assert!(
            relative(&b["mass"], &c["mass"]) < 1e-12,
            "{name}: {} vs {}",
            b["mass"],
            c["mass"]
        );
        assert!(relative(&b["com"], &c["center_of_mass"]) < 1e-12, "{name}");
        assert!(
            relative(&b["tensor"], &c["inertia"]) < 1e-9,
            "{name}: {} vs {}",
            b["tensor"],
            c["inertia"]
        );
    }
    // The fix: every body now states our numbers, and MuJoCo keeps them.
    let compiled = bodies("mujoco", &fixed);
    for name in ["capsule", "mixed", "placeholder"] {
        let (b, c) = (&compiled["bodies"][name], &link(&report, name)["computed"]);
        assert!(relative(&b["mass"], &c["mass"]) < 1e-12, "{name}");
        assert!(relative(&b["com"], &c["center_of_mass"]) < 1e-9, "{name}");
        assert!(relative(&b["tensor"], &c["inertia"]) < 1e-9, "{name}");
        assert!(
            relative(&b["inertia"], &c["principal_moments"]) < 1e-9,
            "{name}: body_inertia as written"
        );
    }
}

#[test]
fn a_description_that_cannot_be_read_exits_3_naming_the_place() {
    let bad = common::TempFile::new(
        "bad.urdf",
        b"<robot name=\"r\">\n  <link name=\"a\">\n</robot>\n",
    );
    let out = run(&["audit", bad.path()]);
    assert_eq!(out.status.code(), Some(3));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("bad.urdf:3:"), "{stderr}");

    let out = run(&["audit", PANDA, "--fix"]);
    assert_eq!(out.status.code(), Some(2), "--fix needs -o");
    let out = run(&["audit", PANDA, "--fix", "-o", PANDA]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "never over the description itself"
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("is the description itself"));
}

/// `audit --json` of an SDFormat file, with `models` on GZ_SIM_RESOURCE_PATH.
fn audit_sdf(args: &[&str], models: &Path) -> (Value, String) {
    let mut all = vec!["audit"];
    all.extend_from_slice(args);
    all.push("--json");
    let out = Command::new(env!("CARGO_BIN_EXE_inertia-lab"))
        .args(&all)
        .env("GZ_SIM_RESOURCE_PATH", models)
        .output()
        .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{stderr}");
    (serde_json::from_slice(&out.stdout).expect("JSON"), stderr)
}

/// An SDFormat arm (frames relative_to others, a nested model, a model:// include) read as
/// libsdformat reads it, link by link; its impossible inertial fixed in place, and the fixed
/// file read by libsdformat with our values. The included file's link is named, not fixed.
#[test]
fn an_sdformat_arm_reads_as_libsdformat_reads_it_and_its_fix_too() {
    let test = "an_sdformat_arm_reads_as_libsdformat_reads_it_and_its_fix_too";
    let source = root().join("tests/data/robots/sdf_arm");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("sdf_arm");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("made");
    std::fs::copy(source.join("arm.sdf"), dir.join("arm.sdf")).expect("copied");
    let models = source.join("models");
    let (original, fixed) = (dir.join("arm.sdf"), dir.join("arm_fixed.sdf"));
    let (report, stderr) = audit_sdf(
        &[
            original.to_str().expect("utf-8"),
            "--fix",
            "-o",
            fixed.to_str().expect("utf-8"),
        ],
        &models,
    );
    assert_eq!(report["format"], "sdf");
    assert_eq!(report["fixed"]["links"], serde_json::json!(["upper"]));
    assert!(
        stderr.contains("\"hand::finger\" is not fixed") && stderr.contains("gripper"),
        "{stderr}"
    );
    assert!(finding(link(&report, "hand::finger"), "impossible_moment").is_some());
    let before = std::fs::read_to_string(&original).expect("present");
    let after = std::fs::read_to_string(&fixed).expect("present");
    assert_eq!(without_inertials(&before), without_inertials(&after));

    let Some(reader) = sdf_bodies(test) else {
        return;
    };
    // Every link as stated, where libsdformat places it.
    let theirs = sdformat_bodies(&reader, &original, &models);
    for name in ["base", "upper", "forearm_model::forearm", "hand::finger"] {
        let (b, ours) = (&theirs["bodies"][name], link(&report, name));
        assert!(
            relative(&b["mass"], &ours["stated"]["mass"]) == 0.0,
            "{name}"
        );
        assert!(
            relative(&b["com"], &ours["stated"]["center_of_mass"]) < 1e-15,
            "{name}"
        );
        assert!(
            relative(&b["tensor"], &ours["stated"]["inertia"]) < 1e-15,
            "{name}"
        );
        assert!(
            relative(&b["position"], &ours["pose"]["position"]) < 1e-15,
            "{name}"
        );
        assert!(
            relative(&b["rotation"], &ours["pose"]["rotation"]) < 1e-15,
            "{name}"
        );
    }
    // The fix as libsdformat reads it: our computed inertial, to the digits written.
    let read = sdformat_bodies(&reader, &fixed, &models);
    let (b, c) = (
        &read["bodies"]["upper"],
        &link(&report, "upper")["computed"],
    );
    assert!(relative(&b["mass"], &c["mass"]) < 1e-15);
    assert!(relative(&b["com"], &c["center_of_mass"]) < 1e-15);
    assert!(
        relative(&b["tensor"], &c["inertia"]) < 1e-15,
        "{} vs {}",
        b["tensor"],
        c["inertia"]
    );
}

/// A xacro gripper (a macro in a file found through `$(find …)` makes both fingers, their mass an
/// argument) audited through the xacro tool; the fix is a note naming the macro's `<inertial>`
/// in its source file, and the install line is given when the tool is missing.
#[test]
fn a_xacro_description_is_audited_through_xacro_and_fixed_as_a_note() {
    let test = "a_xacro_description_is_audited_through_xacro_and_fixed_as_a_note";
    let file = root().join("tests/data/robots/xacro_gripper/gripper.urdf.xacro");
    let file = file.to_str().expect("utf-8");

    // Without the tool: the one line that installs it.
    let empty = Path::new(env!("CARGO_TARGET_TMPDIR")).join("no_tools");
    std::fs::create_dir_all(&empty).expect("made");
    let out = Command::new(env!("CARGO_BIN_EXE_inertia-lab"))
        .args(["audit", file])
        .env("PATH", &empty)
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{stderr}");
    assert!(stderr.contains("pip install xacro==2.1.1"), "{stderr}");
    let out = run(&["audit", file, "--xacro-arg", "finger_mass=0.05"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("NAME:=VALUE"));

    if !common::on_path("xacro") {
        skip(
            test,
            "the xacro tool is not on PATH",
            "python3 -m venv .venv && .venv/bin/pip install xacro==2.1.1, then put .venv/bin first on PATH",
        );
        return;
    }
    // What xacro refuses is named with xacro's own words.
    let wrong = common::TempFile::new(
        "arm.urdf.xacro",
        b"<robot xmlns:xacro=\"http://ros.org/wiki/xacro\" name=\"a\">\n<link name=\"${no_such_property}\"/>\n</robot>\n",
    );
    let out = run(&["audit", wrong.path()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{stderr}");
    assert!(
        stderr.contains("xacro cannot expand it") && stderr.contains("no_such_property"),
        "{stderr}"
    );
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("xacro_fix");
    std::fs::create_dir_all(&dir).expect("made");
    let note = dir.join("gripper_fix.txt");
    let report = audit_json(&[
        file,
        "--xacro-arg",
        "finger_mass:=0.05",
        "--fix",
        "-o",
        note.to_str().expect("utf-8"),
    ]);
    assert_eq!(report["format"], "urdf");
    // The argument reached the macro: both fingers state 0.05 kg, and 0.1 kg·m² on them is
    // impossible within a 6 cm finger.
    for name in ["left_finger", "right_finger"] {
        let l = link(&report, name);
        assert_eq!(l["stated"]["mass"], 0.05, "{name}");
        assert!(finding(l, "impossible_moment").is_some(), "{name}");
    }
    assert!(finding(link(&report, "palm"), "impossible_moment").is_none());
    assert_eq!(report["fixed"]["xacro_note"], true);
    assert_eq!(
        report["fixed"]["links"],
        serde_json::json!(["left_finger", "right_finger"])
    );
    let text = std::fs::read_to_string(&note).expect("written");
    // The macro's <inertial> is line 5 of parts.xacro, and it writes both fingers.
    assert!(text.contains("parts.xacro:5:7"), "{text}");
    assert!(
        text.contains("which writes 2 links: left_finger, right_finger"),
        "{text}"
    );
    assert!(text.contains("finger_mass:=0.05"), "{text}");
    // The box 0.01 × 0.02 × 0.06 m at 0.05 kg: ixx = m(b² + c²)/12.
    let ixx = 0.05 * (0.02f64.powi(2) + 0.06f64.powi(2)) / 12.0;
    let computed = &link(&report, "left_finger")["computed"]["inertia"][0][0];
    assert!((computed.as_f64().expect("number") - ixx).abs() < 1e-15 * ixx.max(1.0));
    assert_eq!(text.matches("<mass value=\"0.05\"/>").count(), 2, "{text}");
}
