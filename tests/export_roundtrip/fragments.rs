//! The fragment formats (json, urdf, sdf, mjcf, unity, godot, unreal, rapier, gltf, and the
//! Godot, Unity and Unreal whole files' numbers): parsed and rebuilt in the mesh frame; rapier, MuJoCo
//! and yourdfpy build them themselves.

use super::*;

fn parse(format: &str, text: &str) -> Read {
    match format {
        "json" => {
            let v: Value = serde_json::from_str(text).expect("JSON");
            let i: Vec<Vec<f64>> = v["inertia_com"]
                .as_array()
                .expect("rows")
                .iter()
                .map(floats)
                .collect();
            let inertia = Matrix3::from_fn(|r, c| i[r][c]);
            // The principal decomposition must say the same.
            let q = floats(&v["principal_quaternion_xyzw"]);
            let m = floats(&v["principal_moments"]);
            let r = quat(q[3], q[0], q[1], q[2]);
            let rebuilt =
                r * Matrix3::from_diagonal(&Vector3::new(m[0], m[1], m[2])) * r.transpose();
            assert!((rebuilt - inertia).amax() <= 1e-12 * inertia.amax());
            let c = floats(&v["center_of_mass"]);
            Read {
                mass: f(&v["mass"]),
                com: Vector3::new(c[0], c[1], c[2]),
                inertia,
            }
        }
        "urdf" => {
            let doc = roxmltree::Document::parse(text).expect("XML");
            let inertial = doc.root_element();
            assert!(inertial.has_tag_name("inertial"));
            let origin = child(inertial, "origin");
            let xyz = attr_floats(origin, "xyz");
            let a = attr_floats(origin, "rpy");
            let i = child(inertial, "inertia");
            let g = |n: &str| attr_floats(i, n)[0];
            let r = rpy(a[0], a[1], a[2]);
            let local = symmetric(g("ixx"), g("iyy"), g("izz"), g("ixy"), g("ixz"), g("iyz"));
            Read {
                mass: attr_floats(child(inertial, "mass"), "value")[0],
                com: Vector3::new(xyz[0], xyz[1], xyz[2]),
                inertia: r * local * r.transpose(),
            }
        }
        "sdf" => {
            let doc = roxmltree::Document::parse(text).expect("XML");
            let inertial = doc.root_element();
            let pose = text_floats(child(inertial, "pose"));
            let i = child(inertial, "inertia");
            let g = |n: &str| text_floats(child(i, n))[0];
            let r = rpy(pose[3], pose[4], pose[5]);
            let local = symmetric(g("ixx"), g("iyy"), g("izz"), g("ixy"), g("ixz"), g("iyz"));
            Read {
                mass: text_floats(child(inertial, "mass"))[0],
                com: Vector3::new(pose[0], pose[1], pose[2]),
                inertia: r * local * r.transpose(),
            }
        }
        "mjcf" => {
            let doc = roxmltree::Document::parse(text).expect("XML");
            let e = doc.root_element();
            let pos = attr_floats(e, "pos");
            let mass = attr_floats(e, "mass")[0];
            let com = Vector3::new(pos[0], pos[1], pos[2]);
            if e.has_attribute("fullinertia") {
                assert!(
                    !e.has_attribute("quat"),
                    "MuJoCo forbids quat with fullinertia"
                );
                let m = attr_floats(e, "fullinertia");
                Read {
                    mass,
                    com,
                    inertia: symmetric(m[0], m[1], m[2], m[3], m[4], m[5]),
                }
            } else {
                let q = attr_floats(e, "quat");
                let d = attr_floats(e, "diaginertia");
                Read::principal(mass, com, quat(q[0], q[1], q[2], q[3]), [d[0], d[1], d[2]])
            }
        }
        "unity" => {
            let q = numbers_after(text, "new Quaternion(");
            let c = numbers_after(text, "centerOfMass = new Vector3(");
            let d = numbers_after(text, "inertiaTensor = new Vector3(");
            let m = line_number(text, "body.mass = ");
            let read = Read::principal(
                m,
                Vector3::new(c[0], c[1], c[2]),
                quat(q[3], q[0], q[1], q[2]),
                [d[0], d[1], d[2]],
            );
            // The JSON line carries the same values.
            let line = text
                .lines()
                .find(|l| l.starts_with("// {"))
                .expect("JSON comment line");
            let v: Value = serde_json::from_str(&line[3..]).expect("JSON");
            assert!(same(f(&v["mass"]), m));
            assert!(same(f(&v["inertiaTensorRotation"]["w"]), q[3]));
            assert!(same(f(&v["centerOfMass"]["z"]), c[2]));
            assert!(same(f(&v["inertiaTensor"]["y"]), d[1]));
            read
        }
        "unity-script" => {
            let q = numbers_after(text, "new Quaternion(");
            let c = numbers_after(text, "centerOfMass = new Vector3(");
            let d = numbers_after(text, "inertiaTensor = new Vector3(");
            let m = line_number(text, "public float mass = ");
            assert!(text.contains("body.inertiaTensor = inertiaTensor;"));
            Read::principal(
                m,
                Vector3::new(c[0], c[1], c[2]),
                quat(q[3], q[0], q[1], q[2]),
                [d[0], d[1], d[2]],
            )
        }
        // The scene's RigidBody3D is the fragment's (its mesh and hull are checked apart).
        "godot" | "godot-scene" => {
            let m = line_number(text, "mass = ");
            let c = numbers_after(text, "center_of_mass = Vector3(");
            let d = numbers_after(text, "inertia = Vector3(");
            // Body axes; with a MeshFrame child, the mesh sits rotated by its quaternion.
            let child = if text.contains("[node name=\"MeshFrame\"") {
                let q = numbers_after(text, "quaternion = Quaternion(");
                quat(q[3], q[0], q[1], q[2])
            } else {
                Matrix3::identity()
            };
            // child maps mesh-frame coordinates to body coordinates.
            let com = child.transpose() * Vector3::new(c[0], c[1], c[2]);
            Read::principal(m, com, child.transpose(), [d[0], d[1], d[2]])
        }
        "unreal" => {
            let m = numbers_after(text, "SetMass_AssumesLocked(Actor, ")[0];
            let pose = &text[text
                .find("SetComLocalPose_AssumesLocked")
                .expect("COM pose")..];
            let q = numbers_after(pose, "FQuat(");
            let c = numbers_after(pose, "FVector(");
            let d = numbers_after(
                text,
                "SetMassSpaceInertiaTensor_AssumesLocked(Actor, FVector(",
            );
            Read::principal(
                m,
                Vector3::new(c[0], c[1], c[2]),
                quat(q[3], q[0], q[1], q[2]),
                [d[0], d[1], d[2]],
            )
        }
        "unreal-script" => {
            let q = numbers_after(text, "PRINCIPAL_AXES_XYZW = (");
            let c = numbers_after(text, "CENTER_OF_MASS_CM = (");
            let d = numbers_after(text, "PRINCIPAL_MOMENTS_KG_CM2 = (");
            Read::principal(
                line_number(text, "MASS_KG = "),
                Vector3::new(c[0], c[1], c[2]),
                quat(q[3], q[0], q[1], q[2]),
                [d[0], d[1], d[2]],
            )
        }
        "rapier" => {
            let r = rapier_args(text);
            // The bevy_rapier3d literal carries the same values.
            assert_eq!(numbers_after(text, "Quat::from_xyzw("), r.xyzw.to_vec());
            assert_eq!(
                numbers_after(text, "local_center_of_mass: Vec3::new("),
                r.com.to_vec()
            );
            assert_eq!(line_number(text, "mass: "), r.mass);
            assert_eq!(
                numbers_after(text, "principal_inertia: Vec3::new("),
                r.inertia.to_vec()
            );
            let [x, y, z, w] = r.xyzw;
            Read::principal(r.mass, Vector3::from(r.com), quat(w, x, y, z), r.inertia)
        }
        "gltf" => {
            let v: Value = serde_json::from_str(text).expect("JSON");
            let motion = &v["extensions"]["KHR_physics_rigid_bodies"]["motion"];
            Read::principal_json(
                &motion["mass"],
                &motion["centerOfMass"],
                &motion["inertiaDiagonal"],
                &motion["inertiaOrientation"],
                [3, 0, 1, 2],
            )
        }
        other => panic!("unknown format {other}"),
    }
}

/// (format, target frame name in [`target_to_mesh`], length unit of the target in metres).
const FORMATS: [(&str, &str, f64); 12] = [
    ("json", "mesh", 1.0),
    ("urdf", "rh-z", 1.0),
    ("sdf", "rh-z", 1.0),
    ("mjcf", "rh-z", 1.0),
    ("unity", "unity", 1.0),
    ("godot", "rh-y", 1.0),
    ("unreal", "unreal", 0.01),
    ("rapier", "rh-y", 1.0),
    ("gltf", "rh-y", 1.0),
    ("godot-scene", "rh-y", 1.0),
    ("unity-script", "unity", 1.0),
    ("unreal-script", "unreal", 0.01),
];

#[test]
fn every_format_rebuilds_the_tensor_in_the_mesh_frame() {
    let mut worst: f64 = 0.0;
    for b in bodies() {
        for (units, metres) in [("mm", 0.001), ("in", 0.0254), ("m", 1.0)] {
            for up in ["y", "z"] {
                let exact = reference(&b.mesh, metres, 2700.0);
                for (format, target, target_metres) in FORMATS {
                    for frame in ["com-principal", "origin"] {
                        let refused = matches!(
                            format,
                            "unity"
                                | "unity-script"
                                | "unreal"
                                | "unreal-script"
                                | "rapier"
                                | "gltf"
                        ) && frame == "origin";
                        // Godot's body-axes diagonal drops products: checked separately.
                        let godot = matches!(format, "godot" | "godot-scene");
                        if refused || (godot && frame == "origin") {
                            continue;
                        }
                        let text = export(
                            b.file.path(),
                            &[
                                "--format",
                                format,
                                "--units",
                                units,
                                "--up",
                                up,
                                "--material",
                                "aluminium",
                                "--frame",
                                frame,
                            ],
                        );
                        let read = parse(format, &text);
                        let e = errors(&read, target, up, target_metres, &exact);
                        let label = format!("{} {format} {frame} units {units} up {up}", b.name);
                        worst = worst.max(check(&label, e));
                    }
                }
            }
        }
    }
    eprintln!("worst tensor error over all formats: {worst:.2e}");
}

/// rapier itself (rapier3d-f64 from crates.io) builds the exported `MassProperties` through the
/// very constructor the snippet calls; its own mass, `local_com` and reconstructed body-axes
/// tensor are the mesh's, so it reads the quaternion order and frames as intended.
#[test]
fn rapier3d_builds_the_exported_mass_properties_as_the_same_body() {
    use rapier3d_f64::dynamics::MassProperties as RapierMassProperties;
    use rapier3d_f64::math::{AngVector, Rotation, Vector};

    let mut worst: f64 = 0.0;
    for b in bodies() {
        for (units, metres) in [("mm", 0.001), ("in", 0.0254), ("m", 1.0)] {
            for up in ["y", "z"] {
                let exact = reference(&b.mesh, metres, 2700.0);
                let text = export(
                    b.file.path(),
                    &[
                        "--format",
                        "rapier",
                        "--units",
                        units,
                        "--up",
                        up,
                        "--material",
                        "aluminium",
                        "--frame",
                        "com-principal",
                    ],
                );
                let a = rapier_args(&text);
                let [x, y, z, w] = a.xyzw;
                let props = RapierMassProperties::with_principal_inertia_frame(
                    Vector::new(a.com[0], a.com[1], a.com[2]),
                    a.mass,
                    AngVector::new(a.inertia[0], a.inertia[1], a.inertia[2]),
                    Rotation::from_xyzw(x, y, z, w),
                );
                let com = props.local_com;
                let inertia = props.reconstruct_inertia_matrix();
                let read = Read {
                    mass: props.mass(),
                    com: Vector3::new(com.x, com.y, com.z),
                    // glam matrices are column-major: col(c)[r] is row r, column c.
                    inertia: Matrix3::from_fn(|r, c| inertia.col(c)[r]),
                };
                let e = errors(&read, "rh-y", up, 1.0, &exact);
                check_within(
                    &format!("{} rapier3d-f64 units {units} up {up}", b.name),
                    e,
                    RAPIER_TOLERANCE,
                );
                worst = worst.max(e[0]).max(e[1]).max(e[2]);
            }
        }
    }
    eprintln!("rapier3d-f64: worst relative error (mass, com, tensor): {worst:.2e}");
}

#[test]
fn the_hammer_in_millimetres_weighs_half_a_kilo_and_is_a_thousand_times_smaller() {
    let out = export(
        "assets/hammer.obj",
        &["--format", "urdf", "--units", "mm", "--mass", "0.5"],
    );
    assert!(out.contains("<inertial>"));
    let read = parse("urdf", &out);
    // Independently: the hammer's numbers as millimetres, at whatever density gives 0.5 kg.
    let exact = reference(&shapes::hammer(), 0.001, 1.0)
        .with_mass(0.5)
        .expect("valid");
    assert_eq!(read.mass, 0.5);
    check(
        "hammer urdf mm 0.5 kg",
        errors(&read, "rh-z", "y", 1.0, &exact),
    );
    // Scale law: the same hammer in metres at 0.5 kg has 10⁶ times the inertia.
    let metres = reference(&shapes::hammer(), 1.0, 1.0)
        .with_mass(0.5)
        .expect("valid");
    assert!(
        (metres.inertia_com / 1e6 - exact.inertia_com).amax() <= 1e-12 * exact.inertia_com.amax()
    );
    // Handle along the mesh's y (up) becomes URDF's z: the smallest moment is about z.
    let i = read.inertia;
    assert!(i[(2, 2)] < i[(0, 0)] && i[(2, 2)] < i[(1, 1)]);
    // Density presets: 1 kg/m³ × volume, in kg.
    let out = export(
        "assets/cube.obj",
        &["--format", "json", "--units", "cm", "--material", "steel"],
    );
    let v: Value = serde_json::from_str(&out).expect("JSON");
    assert!(
        (f(&v["mass"]) - 7850.0 * 1e-6).abs() < 1e-15,
        "a 1 cm steel cube weighs 7.85 g"
    );
}

#[test]
fn godot_warns_when_it_must_drop_products_of_inertia() {
    // A T-handle moved off-centre but not rotated: principal axes = body axes, exact.
    let t = body(
        "tee",
        shapes::t_handle().transformed(&motion([0.2, -0.1, 0.05], [0.0; 3])),
        "m",
        1.0,
    );
    let exact = reference(&t.mesh, 1.0, 1000.0);
    let out = run(&["export", t.file.path(), "--format", "godot"]);
    assert!(out.status.success());
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let read = parse("godot", &String::from_utf8(out.stdout).expect("utf-8"));
    check("tee godot origin", errors(&read, "rh-y", "y", 1.0, &exact));

    // Rotated: a warning, and the body-axes diagonal is exactly the tensor's diagonal.
    let b = &bodies()[1];
    let exact = reference(&b.mesh, 1.0, 1000.0);
    let out = run(&["export", b.file.path(), "--format", "godot"]);
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("principal axes are not the body axes"),
        "{stderr}"
    );
    let read = parse("godot", &String::from_utf8(out.stdout).expect("utf-8"));
    let diag = Vector3::from_fn(|i, _| exact.inertia_com[(i, i)]);
    assert!((read.inertia.diagonal() - diag).amax() <= TOLERANCE * diag.amax());
}

#[test]
fn output_file_frames_and_repaired_bodies() {
    let b = &bodies()[0];
    let out_file = TempFile::new("out.xml", b"");
    let out = run(&[
        "export",
        b.file.path(),
        "--format",
        "sdf",
        "--output",
        out_file.path(),
    ]);
    assert!(out.status.success() && out.stdout.is_empty());
    let written = std::fs::read_to_string(out_file.path()).expect("written");
    assert!(roxmltree::Document::parse(&written).is_ok());

    // A format without a frame choice refuses --frame origin as a usage error.
    let out = run(&[
        "export",
        b.file.path(),
        "--format",
        "unity",
        "--frame",
        "origin",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let out = run(&["export", b.file.path(), "--format", "urdf", "--mass", "-1"]);
    assert_eq!(out.status.code(), Some(2));

    // A unit cube plus a small inside-out cube far away: once negative mass out there (two
    // moments negative); now the separate inward cube is turned outward, with a warning.
    let mut mesh = shapes::cube();
    let mut hole = shapes::cuboid(Vector3::repeat(0.5), Point3::new(3.0, 0.0, 0.0));
    for f in &mut hole.faces {
        f.reverse();
    }
    mesh.append(&hole);
    let turned = TempFile::new(
        "turned.obj",
        shapes::to_obj("turned", "turned", &mesh).as_bytes(),
    );
    let out = run(&[
        "export",
        turned.path(),
        "--format",
        "mjcf",
        "--density",
        "1",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("turned outward"), "{stderr}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("mass=\"1.125\""), "{stdout}");

    // A 1 × 0.2 × 0.2 bar whose two end faces are wound the wrong way within the one shell
    // (taken literally, a negative principal moment; this was refused): the faces are turned to
    // agree with their neighbours and the bar is exported, with the warning on stderr.
    let mut bar = shapes::cuboid(Vector3::new(1.0, 0.2, 0.2), Point3::origin());
    for f in &mut bar.faces {
        let x: Vec<f64> = f.iter().map(|&i| bar.positions[i].x).collect();
        if x.iter().all(|&v| v == x[0]) {
            f.reverse();
        }
    }
    let bad = TempFile::new("bad.obj", shapes::to_obj("bad", "bad", &bar).as_bytes());
    let out = run(&["export", bad.path(), "--format", "mjcf"]);
    assert_eq!(out.status.code(), Some(0));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("2 face(s) wound against their neighbours"),
        "{stderr}"
    );
    // 0.04 m³ of water.
    let stdout = String::from_utf8_lossy(&out.stdout);
    let mass: f64 = stdout
        .split("mass=\"")
        .nth(1)
        .and_then(|rest| rest.split('"').next())
        .and_then(|m| m.parse().ok())
        .expect("a mass");
    assert!((mass - 40.0).abs() < 1e-12, "{stdout}");

    // The hammer (modelled in metres) read as millimetres at PLA density is far below
    // MuJoCo's mjMINVAL: exported, with a warning.
    let out = run(&[
        "export",
        "assets/hammer.obj",
        "--format",
        "mjcf",
        "--units",
        "mm",
        "--material",
        "pla",
    ]);
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("mjMINVAL") && stderr.contains("--units"),
        "{stderr}"
    );
}

const MUJOCO: Consumer = Consumer {
    test: "mujoco_compiles_the_mjcf_to_the_same_body",
    script: "mujoco_inertial.py",
    module: "mujoco",
    install: "python3 -m venv .venv && .venv/bin/pip install mujoco==4.0.0, then put .venv/bin first on PATH",
};

const YOURDFPY: Consumer = Consumer {
    test: "yourdfpy_reads_the_urdf_as_the_same_body",
    script: "urdf_inertial.py",
    module: "yourdfpy",
    install: "python3 -m venv .venv && .venv/bin/pip install yourdfpy==0.0.60, then put .venv/bin first on PATH",
};

#[test]
fn mujoco_compiles_the_mjcf_to_the_same_body() {
    if !MUJOCO.available() {
        return;
    }
    for b in bodies() {
        for frame in ["origin", "com-principal"] {
            let exact = reference(&b.mesh, b.metres, 1240.0);
            let text = export(
                b.file.path(),
                &[
                    "--format",
                    "mjcf",
                    "--units",
                    b.units,
                    "--material",
                    "pla",
                    "--frame",
                    frame,
                ],
            );
            let file = TempFile::new(&format!("{}-{frame}.mjcf", b.name), text.as_bytes());
            let v = MUJOCO.read(file.path());
            let read = Read::principal_json(
                &v["mass"],
                &v["ipos"],
                &v["inertia"],
                &v["iquat"],
                [0, 1, 2, 3],
            );
            let label = format!("mujoco {} {} {frame}", v["version"], b.name);
            check(&label, errors(&read, "rh-z", "y", 1.0, &exact));
        }
    }
}

#[test]
fn yourdfpy_reads_the_urdf_as_the_same_body() {
    if !YOURDFPY.available() {
        return;
    }
    for b in bodies() {
        for frame in ["origin", "com-principal"] {
            let exact = reference(&b.mesh, 0.0254, 7850.0);
            let text = export(
                b.file.path(),
                &[
                    "--format",
                    "urdf",
                    "--units",
                    "in",
                    "--up",
                    "z",
                    "--density",
                    "7850",
                    "--frame",
                    frame,
                ],
            );
            let file = TempFile::new(&format!("{}-{frame}.urdf", b.name), text.as_bytes());
            let v = YOURDFPY.read(file.path());
            let o: Vec<Vec<f64>> = v["origin"]
                .as_array()
                .expect("rows")
                .iter()
                .map(floats)
                .collect();
            let i: Vec<Vec<f64>> = v["inertia"]
                .as_array()
                .expect("rows")
                .iter()
                .map(floats)
                .collect();
            let r = Matrix3::from_fn(|row, col| o[row][col]);
            let local = Matrix3::from_fn(|row, col| i[row][col]);
            let read = Read {
                mass: f(&v["mass"]),
                com: Vector3::new(o[0][3], o[1][3], o[2][3]),
                inertia: r * local * r.transpose(),
            };
            let label = format!("yourdfpy {} {} {frame}", v["version"], b.name);
            check(&label, errors(&read, "rh-z", "z", 1.0, &exact));
        }
    }
}
