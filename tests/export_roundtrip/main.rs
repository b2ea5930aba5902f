//! Round trips of `inertia-lab export`: every format's output is parsed with a real parser (or,
//! for the C#, C++ and Rust snippets, a small number reader), the full inertia tensor is rebuilt
//! in the mesh's own frame from what the target would read (its quaternion or roll-pitch-yaw
//! convention, handedness and units, written out independently here), and compared with
//! `massprops` on the mesh scaled to metres, to [`TOLERANCE`] relative (rapier3d's own
//! reconstruction to [`RAPIER_TOLERANCE`]). Bodies are rotated, off-centre and asymmetric. MuJoCo and yourdfpy (Python) load the MJCF and URDF outputs themselves;
//! rapier3d-f64 (a dev-dependency) builds the rapier snippet's `MassProperties` itself. The
//! whole files are opened by their consumers too: the USD stage by Pixar's usd-core, the GLB by
//! Khronos' validator (and massprops' reader), the SDFormat model by libsdformat.

#[path = "../common/mod.rs"]
mod common;

mod animation;
mod fragments;
mod whole_files;

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

    /// [`Read::principal`] of a JSON reader's fields: `mass` a number, `com` and `diagonal`
    /// three numbers, `quaternion` four in `order` (the indices of w, x, y and z in it).
    fn principal_json(
        mass: &Value,
        com: &Value,
        diagonal: &Value,
        quaternion: &Value,
        order: [usize; 4],
    ) -> Self {
        let (c, d, q) = (floats(com), floats(diagonal), floats(quaternion));
        Read::principal(
            f(mass),
            Vector3::new(c[0], c[1], c[2]),
            quat(q[order[0]], q[order[1]], q[order[2]], q[order[3]]),
            [d[0], d[1], d[2]],
        )
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

/// A Python consumer: its script, the module it imports and the one command that installs it
/// (the versions `.ci/run` installs).
struct Consumer {
    test: &'static str,
    script: &'static str,
    module: &'static str,
    install: &'static str,
}

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
