//! Round trips of `inertia-lab export`: every format's output is parsed with a real parser (or,
//! for the C#, C++ and Rust snippets, a small number reader), the full inertia tensor is rebuilt
//! in the mesh's own frame from what the target would read (its quaternion or roll-pitch-yaw
//! convention, handedness and units, written out independently here), and compared with
//! `massprops` on the mesh scaled to metres, to [`TOLERANCE`] relative (rapier3d's own
//! reconstruction to [`RAPIER_TOLERANCE`]). Bodies are rotated, off-centre and asymmetric. MuJoCo and yourdfpy (Python) load the MJCF and URDF outputs themselves;
//! rapier3d-f64 (a dev-dependency) builds the rapier snippet's `MassProperties` itself. The
//! whole files are opened by their consumers too: the USD stage by Pixar's usd-core, the GLB by
//! Khronos' validator (and massprops' reader), the SDFormat model by libsdformat.

mod common;

use std::process::Command;

use common::{PUPPETEER, TempFile, root, run, sdf_bodies, sdformat_bodies, skip};
use massprops::shapes::{self, MeshBuilder};
use massprops::{MassProperties, mass_properties};
use nalgebra::{Isometry3, Matrix3, Point3, Translation3, UnitQuaternion, Vector3};
use serde_json::Value;

/// Relative error allowed in mass, centre of mass and tensor after a round trip: ten times
/// README's worst figure (1.3e-15; measured 1.29e-15 over every format, unit, up axis and frame,
/// and at most 1.2e-15 through MuJoCo 4.0.0 and yourdfpy 0.0.60). An exporter writing 10
/// significant digits (up to 5e-11 relative) fails.
const TOLERANCE: f64 = 1.3e-14;

/// The same for rapier3d-f64's own `reconstruct_inertia_matrix`: ten times README's 1.6e-15
/// (measured 1.2e-15).
const RAPIER_TOLERANCE: f64 = 1.6e-14;

/// A body: its mesh (in its own units), the unit it is meant in, and the OBJ file holding it.
struct Body {
    name: &'static str,
    mesh: MeshBuilder,
    units: &'static str,
    metres: f64,
    file: TempFile,
}

fn body(name: &'static str, mesh: MeshBuilder, units: &'static str, metres: f64) -> Body {
    let file = TempFile::new(
        &format!("{name}.obj"),
        shapes::to_obj(name, name, &mesh).as_bytes(),
    );
    Body {
        name,
        mesh,
        units,
        metres,
        file,
    }
}

fn motion(t: [f64; 3], euler: [f64; 3]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(t[0], t[1], t[2]),
        UnitQuaternion::from_euler_angles(euler[0], euler[1], euler[2]),
    )
}

/// Rotated, off-centre, asymmetric bodies, coordinates in "mesh units".
fn bodies() -> Vec<Body> {
    vec![
        // An L-bracket with millimetre-like numbers, tilted and moved away from the origin.
        body(
            "bracket",
            scaled(&shapes::l_bracket(), 1000.0)
                .transformed(&motion([30.0, -12.0, 55.0], [0.4, -1.1, 2.3])),
            "mm",
            0.001,
        ),
        body(
            "hammer",
            shapes::hammer().transformed(&motion([0.11, 0.05, -0.3], [0.7, 0.2, -1.3])),
            "m",
            1.0,
        ),
    ]
}

fn scaled(mesh: &MeshBuilder, s: f64) -> MeshBuilder {
    let mut m = mesh.clone();
    for p in &mut m.positions {
        *p = Point3::from(p.coords * s);
    }
    m
}

/// The mesh scaled to metres, integrated at `density` kg/m³ (independent of the CLI's path).
fn reference(mesh: &MeshBuilder, metres_per_unit: f64, density: f64) -> MassProperties {
    mass_properties(&scaled(mesh, metres_per_unit).build(), density).expect("closed mesh")
}

/// Target coordinates → mesh coordinates, written out from the formats' documentation.
fn target_to_mesh(target: &str, up: &str) -> Matrix3<f64> {
    // Mesh → right-handed target of the other up axis.
    let y_to_z = Matrix3::new(1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0);
    let z_to_y = y_to_z.transpose();
    let to_rh = |target_up: &str| match (up, target_up) {
        ("y", "z") => y_to_z,
        ("z", "y") => z_to_y,
        _ => Matrix3::identity(),
    };
    let mesh_to_target = match target {
        "mesh" => Matrix3::identity(),
        "rh-y" => to_rh("y"),
        "rh-z" => to_rh("z"),
        // Unity mirrors x, Unreal mirrors y.
        "unity" => Matrix3::from_diagonal(&Vector3::new(-1.0, 1.0, 1.0)) * to_rh("y"),
        "unreal" => Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, 1.0)) * to_rh("z"),
        other => panic!("unknown target {other}"),
    };
    mesh_to_target.transpose()
}

/// Hamilton quaternion (w, x, y, z) → rotation matrix.
fn quat(w: f64, x: f64, y: f64, z: f64) -> Matrix3<f64> {
    let n = (w * w + x * x + y * y + z * z).sqrt();
    let (w, x, y, z) = (w / n, x / n, y / n, z / n);
    Matrix3::new(
        1.0 - 2.0 * (y * y + z * z),
        2.0 * (x * y - w * z),
        2.0 * (x * z + w * y),
        2.0 * (x * y + w * z),
        1.0 - 2.0 * (x * x + z * z),
        2.0 * (y * z - w * x),
        2.0 * (x * z - w * y),
        2.0 * (y * z + w * x),
        1.0 - 2.0 * (x * x + y * y),
    )
}

/// Fixed-axis roll-pitch-yaw (URDF, SDFormat): Rz(yaw)·Ry(pitch)·Rx(roll).
fn rpy(r: f64, p: f64, y: f64) -> Matrix3<f64> {
    let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, r.cos(), -r.sin(), 0.0, r.sin(), r.cos());
    let ry = Matrix3::new(p.cos(), 0.0, p.sin(), 0.0, 1.0, 0.0, -p.sin(), 0.0, p.cos());
    let rz = Matrix3::new(y.cos(), -y.sin(), 0.0, y.sin(), y.cos(), 0.0, 0.0, 0.0, 1.0);
    rz * ry * rx
}

fn symmetric(xx: f64, yy: f64, zz: f64, xy: f64, xz: f64, yz: f64) -> Matrix3<f64> {
    Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz)
}

/// What a target reads, in its own frame and units.
#[derive(Debug)]
struct Read {
    mass: f64,
    com: Vector3<f64>,
    inertia: Matrix3<f64>,
}

impl Read {
    fn principal(mass: f64, com: Vector3<f64>, rotation: Matrix3<f64>, d: [f64; 3]) -> Self {
        let diag = Matrix3::from_diagonal(&Vector3::from(d));
        Read {
            mass,
            com,
            inertia: rotation * diag * rotation.transpose(),
        }
    }
}

/// Relative errors (mass, centre of mass, tensor) of `read` against `exact`, after taking it back
/// to the mesh frame in metres.
fn errors(read: &Read, target: &str, up: &str, metres: f64, exact: &MassProperties) -> [f64; 3] {
    let a = target_to_mesh(target, up);
    let com = a * read.com * metres;
    let inertia = a * read.inertia * a.transpose() * (metres * metres);
    let scale = exact.inertia_com.amax();
    let size = (exact.inertia_com.trace() / exact.mass).sqrt();
    [
        (read.mass - exact.mass).abs() / exact.mass,
        (com - exact.center_of_mass.coords).amax() / size,
        (inertia - exact.inertia_com).amax() / scale,
    ]
}

fn check(label: &str, e: [f64; 3]) -> f64 {
    check_within(label, e, TOLERANCE)
}

/// Prints the relative errors (mass, com, tensor), asserts each is within `tolerance`, and
/// returns the tensor's.
fn check_within(label: &str, e: [f64; 3], tolerance: f64) -> f64 {
    eprintln!(
        "{label}: mass {:.1e}, com {:.1e}, tensor {:.1e}",
        e[0], e[1], e[2]
    );
    for v in e {
        assert!(v <= tolerance, "{label}: relative errors {e:?}");
    }
    e[2]
}

fn export(file: &str, args: &[&str]) -> String {
    let mut all = vec!["export", file];
    all.extend_from_slice(args);
    let out = run(&all);
    assert!(
        out.status.success(),
        "export {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

/// Equal to 1e-15 relative (serde_json's default float parser may miss by one ulp).
fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-15 * a.abs().max(b.abs())
}

fn f(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array().expect("an array").iter().map(f).collect()
}

fn attr_floats(node: roxmltree::Node, name: &str) -> Vec<f64> {
    node.attribute(name)
        .unwrap_or_else(|| panic!("attribute {name}"))
        .split_whitespace()
        .map(|s| s.parse().expect("a number"))
        .collect()
}

fn child<'a, 'i>(node: roxmltree::Node<'a, 'i>, name: &str) -> roxmltree::Node<'a, 'i> {
    node.children()
        .find(|c| c.has_tag_name(name))
        .unwrap_or_else(|| panic!("element {name}"))
}

fn text_floats(node: roxmltree::Node) -> Vec<f64> {
    node.text()
        .unwrap_or_default()
        .split_whitespace()
        .map(|s| s.parse().expect("a number"))
        .collect()
}

/// The number after `prefix` on the line that starts with it (`;`, `,` and C#'s `f` dropped).
fn line_number(text: &str, prefix: &str) -> f64 {
    let line = text
        .lines()
        .find_map(|l| l.trim_start().strip_prefix(prefix))
        .unwrap_or_else(|| panic!("a line starting with {prefix:?} in\n{text}"));
    let v = line
        .trim()
        .trim_end_matches([';', ','])
        .trim_end_matches('f');
    v.parse()
        .unwrap_or_else(|_| panic!("number {v:?} after {prefix}"))
}

/// The comma-separated numbers between `marker` and the next `)` or `]` (C#, C++, Rust, tscn).
fn numbers_after(text: &str, marker: &str) -> Vec<f64> {
    let start = text
        .find(marker)
        .unwrap_or_else(|| panic!("{marker} in\n{text}"))
        + marker.len();
    let rest = &text[start..];
    let end = rest.find([')', ']']).expect("closing bracket");
    rest[..end]
        .split(',')
        .map(|s| {
            let s = s.trim().trim_end_matches('f');
            s.parse()
                .unwrap_or_else(|_| panic!("number {s:?} after {marker}"))
        })
        .collect()
}

/// The four arguments of the rapier3d snippet's `with_principal_inertia_frame(..)` call.
struct RapierArgs {
    com: [f64; 3],
    mass: f64,
    inertia: [f64; 3],
    /// glam's `Rotation::from_xyzw` order: scalar last.
    xyzw: [f64; 4],
}

fn rapier_args(text: &str) -> RapierArgs {
    let call = "rapier3d::dynamics::MassProperties::with_principal_inertia_frame(\n";
    let start = text
        .find(call)
        .unwrap_or_else(|| panic!("{call} in\n{text}"))
        + call.len();
    let args: Vec<&str> = text[start..]
        .lines()
        .take_while(|l| l.trim() != ");")
        .collect();
    assert_eq!(args.len(), 4, "four arguments in\n{text}");
    let three = |line: &str, marker: &str| -> [f64; 3] {
        numbers_after(line, marker)
            .try_into()
            .expect("three numbers")
    };
    let mass = args[1].trim().trim_end_matches(',');
    RapierArgs {
        com: three(args[0], "rapier3d::math::Vector::new("),
        mass: mass.parse().unwrap_or_else(|_| panic!("mass {mass:?}")),
        inertia: three(args[2], "rapier3d::math::AngVector::new("),
        xyzw: numbers_after(args[3], "rapier3d::math::Rotation::from_xyzw(")
            .try_into()
            .expect("four numbers"),
    }
}

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
            let c = floats(&motion["centerOfMass"]);
            let d = floats(&motion["inertiaDiagonal"]);
            let q = floats(&motion["inertiaOrientation"]);
            Read::principal(
                f(&motion["mass"]),
                Vector3::new(c[0], c[1], c[2]),
                quat(q[3], q[0], q[1], q[2]),
                [d[0], d[1], d[2]],
            )
        }
        other => panic!("unknown format {other}"),
    }
}

/// (format, target frame name in [`target_to_mesh`], length unit of the target in metres).
const FORMATS: [(&str, &str, f64); 11] = [
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
                            "unity" | "unity-script" | "unreal" | "rapier" | "gltf"
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

/// A Python consumer: its script, the module it imports and the one command that installs it
/// (the versions `.ci/run` installs).
struct Consumer {
    test: &'static str,
    script: &'static str,
    module: &'static str,
    install: &'static str,
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

impl Consumer {
    /// Whether python3 and the module are here; reports the skip otherwise.
    fn available(&self) -> bool {
        let probe = Command::new("python3")
            .args(["-c", &format!("import {}", self.module)])
            .output();
        match probe {
            Ok(out) if out.status.success() => true,
            Ok(_) => {
                let missing = format!("the Python package {} is not installed", self.module);
                skip(self.test, &missing, self.install);
                false
            }
            Err(_) => {
                skip(
                    self.test,
                    "python3 is not installed",
                    "apt-get install python3 python3-venv",
                );
                false
            }
        }
    }

    /// Runs the script on `file` and parses what it prints.
    fn read(&self, file: &str) -> Value {
        self.read_with(file, &[])
    }

    /// Runs the script on `file` and `args` and parses the JSON line it prints last (Blender
    /// logs its importer's progress to standard output before it).
    fn read_with(&self, file: &str, args: &[&str]) -> Value {
        let out = Command::new("python3")
            .arg(root().join("tests/python").join(self.script))
            .arg(file)
            .args(args)
            .output()
            .expect("python3 runs");
        assert!(
            out.status.success(),
            "{} failed on {file}:\n{}",
            self.script,
            String::from_utf8_lossy(&out.stderr)
        );
        let said = String::from_utf8_lossy(&out.stdout);
        let last = said.lines().rfind(|l| !l.trim().is_empty()).unwrap_or("");
        serde_json::from_str(last).expect("JSON from the script")
    }
}

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
            let q = floats(&v["iquat"]);
            let p = floats(&v["ipos"]);
            let d = floats(&v["inertia"]);
            let read = Read::principal(
                f(&v["mass"]),
                Vector3::new(p[0], p[1], p[2]),
                quat(q[0], q[1], q[2], q[3]),
                [d[0], d[1], d[2]],
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

const USD_CORE: Consumer = Consumer {
    test: "usd_core_reads_the_stage_as_the_same_body",
    script: "usd_mass.py",
    module: "pxr",
    install: "python3 -m venv .venv && .venv/bin/pip install usd-core==26.11, then put .venv/bin first on PATH",
};

/// Relative error allowed of what a format stores in single precision (USD's `MassAPI`
/// attributes, glTF's corners): a few units in the last place of an f32 (6e-8).
const SINGLE: f64 = 1e-6;

/// The relative errors of a uniform solid's volume and centre of volume, read from its surface,
/// against the exact body's (its mass over the density, its centre of mass).
fn solid_errors(
    volume: f64,
    centre: Vector3<f64>,
    exact: &MassProperties,
    density: f64,
) -> [f64; 2] {
    let size = (exact.inertia_com.trace() / exact.mass).sqrt();
    [
        (volume - exact.mass / density).abs() / (exact.mass / density),
        (centre - exact.center_of_mass.coords).amax() / size,
    ]
}

/// `export` with `--output` into a temporary file named `name`; its bytes.
fn export_file(file: &str, name: &str, args: &[&str]) -> (TempFile, Vec<u8>) {
    let out = TempFile::new(name, b"");
    let mut all = args.to_vec();
    all.extend_from_slice(&["--output", out.path()]);
    let said = export(file, &all);
    assert!(said.is_empty(), "{said}");
    let bytes = std::fs::read(out.path()).expect("written");
    (out, bytes)
}

/// One test body exported as a whole file.
struct Exported {
    name: &'static str,
    up: &'static str,
    /// The body in metres, of PLA.
    exact: MassProperties,
    file: TempFile,
    bytes: Vec<u8>,
}

/// Each test body of PLA, with +Y and with +Z up, exported as `format` into a `.{extension}`
/// file.
fn exported(format: &str, extension: &str) -> Vec<Exported> {
    let mut out = Vec::new();
    for b in bodies() {
        for up in ["y", "z"] {
            let args = [
                "--format",
                format,
                "--units",
                b.units,
                "--material",
                "pla",
                "--up",
                up,
            ];
            let (file, bytes) =
                export_file(b.file.path(), &format!("{}.{extension}", b.name), &args);
            out.push(Exported {
                name: b.name,
                up,
                exact: reference(&b.mesh, b.metres, 1240.0),
                file,
                bytes,
            });
        }
    }
    out
}

/// The USD stage, opened by usd-core: its metres, kilograms and +Z up; UsdPhysics' MassAPI
/// rebuilds the tensor to single precision, its double-precision attributes to [`TOLERANCE`];
/// the mesh on its collision prim encloses the body's volume about its centre of mass.
#[test]
fn usd_core_reads_the_stage_as_the_same_body() {
    if !USD_CORE.available() {
        return;
    }
    for Exported {
        name,
        up,
        exact,
        file,
        ..
    } in exported("usd", "usda")
    {
        let v = USD_CORE.read(file.path());
        assert_eq!(
            (f(&v["meters_per_unit"]), f(&v["kilograms_per_unit"])),
            (1.0, 1.0)
        );
        assert_eq!(v["up_axis"], "Z");
        let read = |m: &Value| {
            let q = floats(&m["principal_axes"]);
            let c = floats(&m["center_of_mass"]);
            let d = floats(&m["diagonal_inertia"]);
            Read::principal(
                f(&m["mass"]),
                Vector3::new(c[0], c[1], c[2]),
                quat(q[0], q[1], q[2], q[3]),
                [d[0], d[1], d[2]],
            )
        };
        let label = format!("usd-core {} {name} +{up} up", v["version"]);
        check(&label, errors(&read(&v["double"]), "rh-z", up, 1.0, &exact));
        check_within(
            &format!("{label} MassAPI"),
            errors(&read(&v), "rh-z", up, 1.0, &exact),
            SINGLE,
        );
        let c = floats(&v["centre_of_volume"]);
        let centre = target_to_mesh("rh-z", up) * Vector3::new(c[0], c[1], c[2]);
        let [volume, centre] = solid_errors(f(&v["volume"]), centre, &exact, 1240.0);
        assert!(
            volume < SINGLE && centre < SINGLE,
            "{label}: {volume:e} {centre:e}"
        );
    }
}

/// The GLB: valid under Khronos' validator; its node's `KHR_physics_rigid_bodies` motion (read
/// here from the file's JSON chunk) is the body to [`TOLERANCE`]; its mesh, read back by
/// massprops' glTF reader, encloses the body's volume about its centre of mass.
#[test]
fn the_glb_is_valid_gltf_and_its_node_holds_the_same_body() {
    let mut files = Vec::new();
    for Exported {
        name,
        up,
        exact,
        file,
        bytes,
    } in exported("glb", "glb")
    {
        assert_eq!(&bytes[..4], b"glTF");
        let json_length = u32::from_le_bytes(bytes[12..16].try_into().expect("4 bytes")) as usize;
        let doc: Value = serde_json::from_slice(&bytes[20..20 + json_length]).expect("JSON chunk");
        assert_eq!(doc["extensionsUsed"][0], "KHR_physics_rigid_bodies");
        let motion = &doc["nodes"][0]["extensions"]["KHR_physics_rigid_bodies"]["motion"];
        let q = floats(&motion["inertiaOrientation"]);
        let c = floats(&motion["centerOfMass"]);
        let d = floats(&motion["inertiaDiagonal"]);
        let read = Read::principal(
            f(&motion["mass"]),
            Vector3::new(c[0], c[1], c[2]),
            quat(q[3], q[0], q[1], q[2]),
            [d[0], d[1], d[2]],
        );
        let label = format!("glb {name} +{up} up");
        check(&label, errors(&read, "rh-y", up, 1.0, &exact));
        let mesh = massprops::load_mesh(std::path::Path::new(file.path())).expect("reads");
        let solid = mass_properties(&mesh.mesh, 1240.0).expect("closed");
        let centre = target_to_mesh("rh-y", up) * solid.center_of_mass.coords;
        let [volume, centre] = solid_errors(solid.mass / 1240.0, centre, &exact, 1240.0);
        assert!(
            volume < SINGLE && centre < SINGLE,
            "{label}: {volume:e} {centre:e}"
        );
        files.push(file);
    }
    validate_gltf(
        "the_glb_is_valid_gltf_and_its_node_holds_the_same_body",
        &files,
    );
}

/// Khronos' glTF validator finds no error in any of `files` (skipped, and said, where Node.js or
/// the validator is missing).
fn validate_gltf(test: &str, files: &[TempFile]) {
    let validator = root().join("target/gltf-validator/node_modules/gltf-validator");
    if !(validator.is_dir() && common::on_path("node")) {
        skip(
            test,
            "Node.js and Khronos' glTF validator are missing",
            "apt install nodejs npm; npm install --prefix target/gltf-validator \
             gltf-validator@2.0.0-dev.3.10",
        );
        return;
    }
    let script = "const v = require(process.argv[1]); const fs = require('fs');
        (async () => { for (const f of process.argv.slice(2)) {
          const r = await v.validateBytes(new Uint8Array(fs.readFileSync(f)));
          console.log(r.issues.numErrors, JSON.stringify(r.issues.messages.filter(m => m.severity === 0)));
        } })();";
    let out = Command::new("node")
        .args(["-e", script])
        .arg(&validator)
        .args(files.iter().map(TempFile::path))
        .output()
        .expect("node runs");
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{said}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(said.lines().count(), files.len(), "{said}");
    for line in said.lines() {
        assert!(line.starts_with("0 "), "the validator's errors: {line}");
    }
}

/// The SDFormat model, read by libsdformat: its link's inertial is the body to [`TOLERANCE`]
/// in both frames, and its visual names the mesh file, scaled to metres and turned to +Z up.
#[test]
fn libsdformat_reads_the_sdf_model_as_the_same_body() {
    let Some(reader) = sdf_bodies("libsdformat_reads_the_sdf_model_as_the_same_body") else {
        return;
    };
    for b in bodies() {
        let exact = reference(&b.mesh, b.metres, 1240.0);
        for frame in ["origin", "com-principal"] {
            let args = [
                "--format",
                "sdf-model",
                "--units",
                b.units,
                "--material",
                "pla",
                "--frame",
                frame,
            ];
            let (file, _) = export_file(b.file.path(), &format!("{}.sdf", b.name), &args);
            let v = sdformat_bodies(&reader, std::path::Path::new(file.path()), &root());
            let link = &v["bodies"]["body"];
            let c = floats(&link["com"]);
            let t: Vec<Vec<f64>> = link["tensor"]
                .as_array()
                .expect("rows")
                .iter()
                .map(floats)
                .collect();
            let read = Read {
                mass: f(&link["mass"]),
                com: Vector3::new(c[0], c[1], c[2]),
                inertia: Matrix3::from_fn(|r, k| t[r][k]),
            };
            let label = format!("libsdformat {} {frame}", b.name);
            check(&label, errors(&read, "rh-z", "y", 1.0, &exact));
            let mesh = &link["meshes"][0];
            let uri = mesh["uri"].as_str().expect("uri");
            let named = std::path::Path::new(file.path())
                .parent()
                .expect("folder")
                .join(uri);
            assert_eq!(
                std::fs::canonicalize(named).ok(),
                std::fs::canonicalize(b.file.path()).ok(),
                "{label}: {uri}"
            );
            let r: Vec<Vec<f64>> = mesh["rotation"]
                .as_array()
                .expect("rows")
                .iter()
                .map(floats)
                .collect();
            let placed = Matrix3::from_fn(|i, k| r[i][k]) * floats(&mesh["scale"])[0];
            let expected = target_to_mesh("rh-z", "y").transpose() * b.metres;
            assert!(
                (placed - expected).amax() < 1e-15,
                "{label}: {placed} vs {expected}"
            );
            assert_eq!(floats(&mesh["position"]), [0.0; 3], "{label}");
        }
    }
}

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

/// The Godot scene: its first line Godot's text-scene header, each mesh file an external
/// resource whose path, from the scene's folder, is the file, its node's position, quaternion
/// and scale putting the file's vertices where the body has them (turned to +Y up, millimetres
/// to metres), the collision hull's points the surface's, and a mesh Godot cannot import named
/// in a warning.
#[test]
fn the_godot_scene_places_each_mesh_and_its_hull() {
    let b = &bodies()[0];
    let (file, bytes) = export_file(
        b.file.path(),
        "bracket.tscn",
        &[
            "--format",
            "godot-scene",
            "--units",
            "mm",
            "--up",
            "z",
            "--frame",
            "com-principal",
        ],
    );
    let text = String::from_utf8(bytes).expect("text");
    assert!(
        text.starts_with("[gd_scene load_steps=3 format=3]\n"),
        "{text}"
    );
    let path = text
        .lines()
        .find_map(|l| l.strip_prefix("[ext_resource type=\"ArrayMesh\" path=\""))
        .and_then(|l| l.split('"').next())
        .expect("the mesh's resource");
    let named = std::path::Path::new(file.path())
        .parent()
        .expect("folder")
        .join(path);
    assert_eq!(
        std::fs::canonicalize(named).ok(),
        std::fs::canonicalize(b.file.path()).ok()
    );
    let node = &text[text
        .find("[node name=\"Mesh0\" type=\"MeshInstance3D\" parent=\"MeshFrame\"]")
        .expect("the mesh's node")..];
    let position = numbers_after(node, "position = Vector3(");
    let q = numbers_after(node, "quaternion = Quaternion(");
    let scale = numbers_after(node, "scale = Vector3(");
    let turn = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(q[3], q[0], q[1], q[2]));
    let a = target_to_mesh("rh-y", "z").transpose();
    let hull = numbers_after(&text, "points = PackedVector3Array(");
    assert_eq!(hull.len(), 3 * b.mesh.positions.len());
    // The hull's points are the surface's as read (in the reader's order).
    let hull: Vec<Vector3<f64>> = hull.chunks(3).map(Vector3::from_column_slice).collect();
    for p in &b.mesh.positions {
        let placed = Vector3::from_column_slice(&position) + turn * (p.coords * scale[0]);
        let expected = a * p.coords * 0.001;
        assert!((placed - expected).amax() < 1e-15, "{placed} vs {expected}");
        assert!(
            hull.iter().any(|h| (h - expected).amax() < 1e-15),
            "{expected} not in the hull"
        );
    }
    let mut solid = String::from("solid bracket\n");
    for face in &b.mesh.faces {
        for k in 1..face.len() - 1 {
            solid.push_str(" facet normal 0 0 0\n  outer loop\n");
            for i in [face[0], face[k], face[k + 1]] {
                let p = b.mesh.positions[i];
                solid.push_str(&format!("   vertex {} {} {}\n", p.x, p.y, p.z));
            }
            solid.push_str("  endloop\n endfacet\n");
        }
    }
    solid.push_str("endsolid bracket\n");
    let stl = TempFile::new("bracket.stl", solid.as_bytes());
    let out = TempFile::new("stl.tscn", b"");
    let said = run(&[
        "export",
        stl.path(),
        "--format",
        "godot-scene",
        "-o",
        out.path(),
    ]);
    assert!(said.status.success());
    let warned = String::from_utf8_lossy(&said.stderr);
    assert!(
        warned.contains("Godot 4 does not import") && warned.contains("bracket.stl"),
        "{warned}"
    );
}

/// The Unity script's class is its file's name, as Unity requires of a component.
#[test]
fn the_unity_script_is_named_after_its_file() {
    let b = &bodies()[1];
    let (file, bytes) = export_file(
        b.file.path(),
        "HammerBody.cs",
        &["--format", "unity-script"],
    );
    let text = String::from_utf8(bytes).expect("text");
    let stem = std::path::Path::new(file.path())
        .file_stem()
        .and_then(|s| s.to_str())
        .expect("a name");
    assert!(stem.ends_with("HammerBody"), "{stem}");
    let class = stem.replace(|c: char| !c.is_ascii_alphanumeric(), "_");
    assert!(
        text.contains(&format!("public class {class} : MonoBehaviour")),
        "{text}"
    );
    assert!(text.contains("[RequireComponent(typeof(Rigidbody))]"));
}
