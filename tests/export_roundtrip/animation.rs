//! The baked motion (`simulate --animation`): usd-core, Blender, three.js and the GLB's own
//! keys against the lab's states.

use super::*;

const USD_ANIMATION: Consumer = Consumer {
    test: "usd_core_plays_the_baked_tumble_as_the_lab_simulates_it",
    script: "usd_animation.py",
    module: "pxr",
    install: "python3 -m venv .venv && .venv/bin/pip install usd-core==26.11, then put .venv/bin first on PATH",
};

/// The canonical tennis racket's ω₀ (rad/s, principal frame).
const RACKET_OMEGA: Vector3<f64> = Vector3::new(0.001, 10.0, 0.001);

/// The lab's own states of a body of `exact` mass properties spun at the racket's ω₀ from rest
/// where its mesh lies: each frame's mesh → world isometry (world = the mesh's frame), at 30
/// frames a second from the default integrator at 1/240 s.
fn lab_frames(exact: &MassProperties, seconds: f64) -> Vec<Isometry3<f64>> {
    let p = &exact.principal;
    let com = exact.center_of_mass;
    let mut body = rbcore::Body::from_principal(exact.mass, p.moments, p.rotation).expect("a body");
    body.set_position(com).expect("finite");
    body.set_orientation(UnitQuaternion::from_rotation_matrix(&body.principal_axes()))
        .expect("finite");
    body.set_omega_principal(RACKET_OMEGA).expect("finite");
    let settings = rbcore::Settings {
        dt: 1.0 / 240.0,
        ..rbcore::Settings::default()
    };
    let mut sim = rbcore::Simulation::new(body, settings).expect("settings");
    let frames = (seconds * 30.0).round() as usize;
    let mut out = Vec::with_capacity(frames + 1);
    for k in 0..=frames {
        if k > 0 {
            for _ in 0..8 {
                sim.step().expect("steps");
            }
        }
        let r = sim.body().body_orientation();
        let x = sim.body().position();
        out.push(Isometry3::from_parts(
            Translation3::from(x.coords - r * com.coords),
            r,
        ));
    }
    out
}

/// An asset baked by `simulate --animation` with the racket's spin (and `args`), beside the
/// lab's own states of it.
struct BakedAsset {
    /// The baked file.
    file: TempFile,
    /// The asset's mesh.
    mesh: massprops::PolyMesh,
    /// Its exact mass properties at density 1 (what `simulate --mesh` weighs it at).
    exact: MassProperties,
    /// The lab's frames ([`lab_frames`]).
    lab: Vec<Isometry3<f64>>,
}

fn bake_asset(asset: &str, name: &str, seconds: f64, args: &[&str]) -> BakedAsset {
    let path = root().join("assets").join(asset);
    let duration = seconds.to_string();
    let mut all = vec![
        "--mesh",
        path.to_str().expect("utf-8"),
        "--duration",
        &duration,
    ];
    all.extend_from_slice(args);
    let file = bake(name, &all);
    let mesh = massprops::load_mesh(&path).expect("the asset").mesh;
    let exact = mass_properties(&mesh, 1.0).expect("closed");
    let lab = lab_frames(&exact, seconds);
    BakedAsset {
        file,
        mesh,
        exact,
        lab,
    }
}

/// `simulate --animation` into a temporary file named `name`.
fn bake(name: &str, args: &[&str]) -> TempFile {
    let out = TempFile::new(name, b"");
    let mut all = vec![
        "simulate",
        "--omega",
        "0.001,10,0.001",
        "--animation",
        out.path(),
    ];
    all.extend_from_slice(args);
    let ran = run(&all);
    assert!(
        ran.status.success(),
        "simulate {args:?}: {}",
        String::from_utf8_lossy(&ran.stderr)
    );
    out
}

/// The T-handle (its centre of mass off its mesh's origin), baked to USD for 24 s and opened by
/// usd-core: at every time code USD's own local-to-world transform is the lab's state (turned
/// from the mesh's +Y up into the stage's +Z up) to 1e-12, and it shows the flip: the
/// intermediate axis points backwards half a period (4K(k)/λ) after the start and forwards
/// again a period after it.
#[test]
fn usd_core_plays_the_baked_tumble_as_the_lab_simulates_it() {
    if !USD_ANIMATION.available() {
        return;
    }
    let BakedAsset {
        file, exact, lab, ..
    } = bake_asset("t_handle.obj", "t_handle.usda", 24.0, &[]);
    let v = USD_ANIMATION.read(file.path());
    assert_eq!(
        (f(&v["time_codes_per_second"]), &v["start"], &v["end"]),
        (30.0, &Value::from(0), &Value::from(720))
    );
    assert_eq!(v["up_axis"], "Z");
    assert_eq!(v["kinematic"], true);
    assert_eq!(
        v["op_order"],
        serde_json::json!(["xformOp:translate", "xformOp:orient"])
    );
    let a = target_to_mesh("rh-z", "y").transpose();
    let intermediate = a * exact.principal.rotation.matrix().column(1);
    let matrices = v["matrices"].as_array().expect("matrices");
    assert_eq!(matrices.len(), lab.len());
    let mut intermediate_axis = Vec::new();
    for (k, (m, frame)) in matrices.iter().zip(&lab).enumerate() {
        let rows: Vec<Vec<f64>> = m.as_array().expect("rows").iter().map(floats).collect();
        // USD's row-vector matrix: the rotation's transpose above the translation row.
        let turn = Matrix3::from_fn(|r, c| rows[c][r]);
        let moved = Vector3::new(rows[3][0], rows[3][1], rows[3][2]);
        let expected = a * frame.rotation.to_rotation_matrix().matrix() * a.transpose();
        assert!(
            (turn - expected).amax() < 1e-12,
            "time code {k}: {turn} vs {expected}"
        );
        assert!(
            (moved - a * frame.translation.vector).amax() < 1e-12,
            "time code {k}: {moved}"
        );
        // The intermediate principal axis against where it started.
        intermediate_axis.push((turn * intermediate).dot(&intermediate));
    }
    let moments = exact.principal.moments;
    let period = rbcore::torque_free_period(&moments, &moments.component_mul(&RACKET_OMEGA))
        .expect("a flip");
    assert!(period < 24.0, "{period}");
    let at = |t: f64| intermediate_axis[(t * 30.0).round() as usize];
    assert!(
        at(period / 2.0) < -0.999 && at(period) > 0.999,
        "{} s: {}, {} s: {}",
        period / 2.0,
        at(period / 2.0),
        period,
        at(period)
    );
}

/// A GLB accessor's floats, read from the file's BIN chunk.
fn accessor(doc: &Value, bin: &[u8], index: usize) -> Vec<f32> {
    let a = &doc["accessors"][index];
    let view = &doc["bufferViews"][a["bufferView"].as_u64().expect("view") as usize];
    let offset = view["byteOffset"].as_u64().unwrap_or(0) as usize;
    let length = view["byteLength"].as_u64().expect("length") as usize;
    bin[offset..offset + length]
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes(b.try_into().expect("4 bytes")))
        .collect()
}

/// The T-handle (its centre of mass off its mesh's origin) baked to GLB for 6 s: valid under
/// Khronos' validator, one animation of rotation and translation on the mesh's node, keyed at
/// k/30 s, each keyframe the lab's state (turned from the mesh's +Z up to glTF's +Y) to single
/// precision; the mesh read back by massprops is the T-handle.
#[test]
fn the_baked_glb_keys_the_lab_states_on_the_mesh_node() {
    let BakedAsset {
        file, exact, lab, ..
    } = bake_asset(
        "t_handle.obj",
        "t_handle.glb",
        6.0,
        &["--up", "z", "--units", "m"],
    );
    let bytes = std::fs::read(file.path()).expect("written");
    let json_length = u32::from_le_bytes(bytes[12..16].try_into().expect("4 bytes")) as usize;
    let doc: Value = serde_json::from_slice(&bytes[20..20 + json_length]).expect("JSON chunk");
    let bin = &bytes[20 + json_length + 8..];
    let animation = &doc["animations"][0];
    assert_eq!(doc["animations"].as_array().map(Vec::len), Some(1));
    let channel = |path: &str| {
        let c = animation["channels"]
            .as_array()
            .expect("channels")
            .iter()
            .find(|c| c["target"]["path"] == path)
            .expect("a channel");
        assert_eq!(c["target"]["node"], 0);
        let sampler = &animation["samplers"][c["sampler"].as_u64().expect("sampler") as usize];
        assert_eq!(sampler["interpolation"], "LINEAR");
        let at = |key: &str| sampler[key].as_u64().expect("accessor") as usize;
        (
            accessor(&doc, bin, at("input")),
            accessor(&doc, bin, at("output")),
        )
    };
    let (times, rotations) = channel("rotation");
    let (_, translations) = channel("translation");
    assert_eq!(times.len(), lab.len());
    let a = target_to_mesh("rh-y", "z").transpose();
    let size = (exact.inertia_com.trace() / exact.mass).sqrt();
    for (k, frame) in lab.iter().enumerate() {
        assert!((f64::from(times[k]) - k as f64 / 30.0).abs() < 1e-6);
        let r = &rotations[4 * k..4 * k + 4];
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
            f64::from(r[3]),
            f64::from(r[0]),
            f64::from(r[1]),
            f64::from(r[2]),
        ));
        let expected = a * frame.rotation.to_rotation_matrix().matrix() * a.transpose();
        let turn = q.to_rotation_matrix().into_inner();
        assert!(
            (turn - expected).amax() < 1e-6,
            "frame {k}: {turn} vs {expected}"
        );
        let t = &translations[3 * k..3 * k + 3];
        let t = Vector3::new(f64::from(t[0]), f64::from(t[1]), f64::from(t[2]));
        assert!(
            (t - a * frame.translation.vector).amax() < 1e-6 * size.max(1.0),
            "frame {k}: {t}"
        );
    }
    let read = massprops::load_mesh(std::path::Path::new(file.path())).expect("reads");
    let solid = mass_properties(&read.mesh, 1.0).expect("closed");
    assert!((solid.mass - exact.mass).abs() < 1e-6 * exact.mass);
    validate_gltf(
        "the_baked_glb_keys_the_lab_states_on_the_mesh_node",
        &[file],
    );
}

/// What `simulate --animation` refuses, each named.
#[test]
fn an_animation_of_another_kind_or_with_a_csv_is_refused() {
    let said = |args: &[&str]| {
        let mut all = vec!["simulate"];
        all.extend_from_slice(args);
        let out = run(&all);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    assert!(said(&["--animation", "out.fbx"]).contains(".glb (glTF) or .usda (USD)"));
    assert!(said(&["--animation", "out.glb", "--csv", "out.csv"]).contains("--csv"));
    assert!(said(&["--animation", "out.glb", "--fps", "0"]).contains("fps"));
}

const BLENDER: Consumer = Consumer {
    test: "blender_imports_the_baked_glb_as_the_lab_simulates_it",
    script: "blender_glb.py",
    module: "bpy",
    install: "python3 -m venv .venv && .venv/bin/pip install bpy==5.0.1, then put .venv/bin first on PATH",
};

/// The hammer (its centre of mass 0.2 m from its mesh's origin, +Y up) baked to GLB for 4 s at
/// 30 fps and imported by Blender (`bpy`): at frame 0 the mesh's world bounding box is the
/// hammer's (turned to Blender's +Z up) to 1e-6 m, and at every frame the object's world
/// rotation is the lab's to 1e-6 rad and its translation to 1e-6 m.
#[test]
fn blender_imports_the_baked_glb_as_the_lab_simulates_it() {
    if !BLENDER.available() {
        return;
    }
    let BakedAsset {
        file, mesh, lab, ..
    } = bake_asset("hammer.obj", "hammer.glb", 4.0, &[]);
    let v = BLENDER.read_with(file.path(), &["30"]);
    assert_eq!(v["meshes"].as_array().map(Vec::len), Some(1), "{v}");
    assert_eq!(v["rotation_mode"], "QUATERNION");
    // glTF's +Y up (the mesh's here) into Blender's +Z up.
    let c = target_to_mesh("rh-z", "y").transpose();
    let (lo, hi) = mesh.positions().iter().fold(
        (
            Vector3::repeat(f64::INFINITY),
            Vector3::repeat(f64::NEG_INFINITY),
        ),
        |(lo, hi), p| {
            let q = c * p.coords;
            (lo.inf(&q), hi.sup(&q))
        },
    );
    let (box_min, box_max) = (floats(&v["box_min"]), floats(&v["box_max"]));
    for i in 0..3 {
        assert!((box_min[i] - lo[i]).abs() < 1e-6, "{box_min:?} vs {lo}");
        assert!((box_max[i] - hi[i]).abs() < 1e-6, "{box_max:?} vs {hi}");
    }
    let frames = floats(&v["frames"]);
    let matrices = v["matrices"].as_array().expect("matrices");
    assert_eq!((frames[0], matrices.len()), (0.0, lab.len()), "{frames:?}");
    let mut worst = 0.0_f64;
    for (k, (m, frame)) in matrices.iter().zip(&lab).enumerate() {
        let rows: Vec<Vec<f64>> = m.as_array().expect("rows").iter().map(floats).collect();
        let turn = Matrix3::from_fn(|r, col| rows[r][col]);
        let moved = Vector3::new(rows[0][3], rows[1][3], rows[2][3]);
        let expected = c * frame.rotation.to_rotation_matrix().matrix() * c.transpose();
        let blender = UnitQuaternion::from_matrix(&turn);
        let angle = blender.angle_to(&UnitQuaternion::from_matrix(&expected));
        worst = worst.max(angle);
        assert!(angle < 1e-6, "frame {k}: {angle} rad");
        assert!(
            (moved - c * frame.translation.vector).amax() < 1e-6,
            "frame {k}: {moved}"
        );
    }
    eprintln!("Blender {}: worst rotation {worst:e} rad", v["version"]);
}

/// The three.js three_animation.mjs loads the GLB with.
const THREE_JS: &str = "three@0.187.0";

/// The driver of `tests/web/three_animation.mjs` with puppeteer-core and three.js beside it
/// (installed once from the npm registry); `None` (the skip said) without Chromium, Node.js or
/// the registry.
fn three_driver(test: &str) -> Option<std::path::PathBuf> {
    if !std::path::Path::new("/usr/bin/chromium").is_file() {
        skip(
            test,
            "Chromium is not installed",
            "apt-get install chromium",
        );
        return None;
    }
    if !common::on_path("node") || !common::on_path("npm") {
        skip(
            test,
            "Node.js is not installed",
            "apt-get install nodejs npm",
        );
        return None;
    }
    let driver = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("three");
    let installed = ["puppeteer-core", "three"]
        .iter()
        .all(|m| driver.join("node_modules").join(m).is_dir());
    if !installed {
        let npm = Command::new("npm")
            .args(["install", "--no-audit", "--no-fund", "--prefix"])
            .arg(&driver)
            .args([PUPPETEER, THREE_JS])
            .output()
            .expect("npm runs");
        if !npm.status.success() {
            skip(
                test,
                &format!(
                    "npm could not install {PUPPETEER} and {THREE_JS}: {}",
                    String::from_utf8_lossy(&npm.stderr).trim()
                ),
                "network access to the npm registry",
            );
            return None;
        }
    }
    std::fs::copy(
        root().join("tests/web/three_animation.mjs"),
        driver.join("three_animation.mjs"),
    )
    .expect("the driver copied");
    Some(driver)
}

/// The T-handle baked to GLB for 2 s and played by three.js (GLTFLoader and AnimationMixer) in
/// headless Chromium: one clip of 2 s with a quaternion and a position track, the node's
/// KHR_physics_rigid_bodies mass the body's, and at every keyframe time the node posed as the
/// lab's state, halfway between two keyframes as their slerp, each to single precision.
#[test]
fn three_js_plays_the_baked_glb_as_the_lab_simulates_it() {
    let test = "three_js_plays_the_baked_glb_as_the_lab_simulates_it";
    let Some(driver) = three_driver(test) else {
        return;
    };
    let BakedAsset {
        file, exact, lab, ..
    } = bake_asset("t_handle.obj", "t_handle_three.glb", 2.0, &["--up", "z"]);
    // Each keyframe's time, and halfway to the next.
    let times: Vec<String> = (0..lab.len())
        .flat_map(|k| [k as f64 / 30.0, (k as f64 + 0.5) / 30.0])
        .filter(|t| *t <= 2.0)
        .map(|t| t.to_string())
        .collect();
    let out = Command::new("node")
        .arg(driver.join("three_animation.mjs"))
        .arg(file.path())
        .args(&times)
        .current_dir(&driver)
        .output()
        .expect("node runs");
    assert!(
        out.status.success(),
        "the three.js driver failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).expect("the driver prints JSON");
    assert_eq!(v["errors"], serde_json::json!([]), "{v}");
    assert_eq!(v["clips"], 1);
    assert!((f(&v["duration"]) - 2.0).abs() < 1e-6);
    let tracks: Vec<&str> = v["tracks"]
        .as_array()
        .expect("tracks")
        .iter()
        .filter_map(Value::as_str)
        .collect();
    assert!(
        tracks.iter().any(|t| t.ends_with(".quaternion"))
            && tracks.iter().any(|t| t.ends_with(".position")),
        "{tracks:?}"
    );
    assert!((f(&v["motion"]["mass"]) - exact.mass).abs() < 1e-12 * exact.mass);
    let a = target_to_mesh("rh-y", "z").transpose();
    let in_gltf = |frame: &Isometry3<f64>| {
        let r = UnitQuaternion::from_matrix(
            &(a * frame.rotation.to_rotation_matrix().matrix() * a.transpose()),
        );
        (r, a * frame.translation.vector)
    };
    let poses = v["poses"].as_array().expect("poses");
    assert_eq!(poses.len(), times.len());
    for (n, pose) in poses.iter().enumerate() {
        let q = floats(&pose["quaternion"]);
        let seen =
            UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(q[3], q[0], q[1], q[2]));
        let p = floats(&pose["position"]);
        let at = Vector3::new(p[0], p[1], p[2]);
        let k = n / 2;
        let (r, t) = if n % 2 == 0 {
            in_gltf(&lab[k])
        } else {
            let ((r0, t0), (r1, t1)) = (in_gltf(&lab[k]), in_gltf(&lab[k + 1]));
            (r0.slerp(&r1, 0.5), (t0 + t1) / 2.0)
        };
        let time = f(&pose["time"]);
        assert!(seen.angle_to(&r) < 1e-6, "{time} s: {}", seen.angle_to(&r));
        assert!((at - t).amax() < 1e-6, "{time} s: {at} vs {t}");
    }
}
