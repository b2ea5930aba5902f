//! The whole files (usd, glb, sdf-model, godot-scene, unity-script, unreal-script), opened by
//! usd-core, Khronos' validator and libsdformat, checked for the places they name, or (the
//! Unreal editor script) run against a stand-in of Unreal's Python module.

use serde_json::json;

use super::*;

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
            Read::principal_json(
                &m["mass"],
                &m["center_of_mass"],
                &m["diagonal_inertia"],
                &m["principal_axes"],
                [0, 1, 2, 3],
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
        let read = Read::principal_json(
            &motion["mass"],
            &motion["centerOfMass"],
            &motion["inertiaDiagonal"],
            &motion["inertiaOrientation"],
            [3, 0, 1, 2],
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
    // The test's meshes and scenes share the temporary folder: named relatively, no word; a
    // mesh elsewhere is named by its absolute path, which Godot does not load, and said so.
    let near = TempFile::new("near.tscn", b"");
    let out = run(&[
        "export",
        b.file.path(),
        "--format",
        "godot-scene",
        "-o",
        near.path(),
    ]);
    let warned = String::from_utf8_lossy(&out.stderr);
    assert!(!warned.contains("not under the scene's folder"), "{warned}");
    let away = TempFile::new("away.tscn", b"");
    let elsewhere = root().join("assets/t_handle.obj");
    let out = run(&[
        "export",
        elsewhere.to_str().expect("utf-8"),
        "--format",
        "godot-scene",
        "-o",
        away.path(),
    ]);
    let warned = String::from_utf8_lossy(&out.stderr);
    assert!(warned.contains("not under the scene's folder"), "{warned}");
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

const UNREAL_STUB: Consumer = Consumer {
    test: "the_unreal_script_gives_the_placed_mesh_its_equivalent_box",
    script: "unreal_editor.py",
    module: "json",
    install: "apt-get install python3",
};

/// The name of the box the Unreal script adds.
const EQUIVALENT_BOX: &str = "InertiaLab equivalent box";

/// The Unreal editor script, run in a level of the stand-in `unreal` module (Unreal itself does
/// not run here): on every placed component of its mesh (twice over) it leaves one box, out of
/// collision, whose solid has the body's mass, centre and tensor in Unreal's frame; the mesh's
/// own shapes still collide but no longer count; each component's mass is overridden and
/// nothing else scales the inertia; another mesh's component is left alone. A mesh imported at
/// another size (metres read as centimetres) or simulated as its complex collision is refused
/// with the fix named and nothing changed; with actors selected, only theirs change.
#[test]
fn the_unreal_script_gives_the_placed_mesh_its_equivalent_box() {
    if !UNREAL_STUB.available() {
        return;
    }
    for Exported {
        name,
        up,
        exact,
        file,
        bytes,
    } in exported("unreal-script", "py")
    {
        let b = bodies()
            .into_iter()
            .find(|b| b.name == name)
            .expect("a body");
        let text = String::from_utf8(bytes).expect("text");
        // Unreal names the imported mesh after its file: the exported OBJ's stem.
        let mesh = text
            .lines()
            .find_map(|l| l.strip_prefix("MESH_NAME = \""))
            .and_then(|l| l.strip_suffix('"'))
            .expect("the mesh's name")
            .to_owned();
        assert!(mesh.ends_with(&format!("-{name}")), "{mesh}");
        // The mesh as Unreal imports it: in its axes, in centimetres.
        let to_unreal = target_to_mesh("unreal", up).transpose();
        let (mut lo, mut hi) = (
            Vector3::repeat(f64::INFINITY),
            Vector3::repeat(-f64::INFINITY),
        );
        for p in &b.mesh.positions {
            let q = to_unreal * p.coords * (b.metres * 100.0);
            lo = lo.inf(&q);
            hi = hi.sup(&q);
        }
        let bounds = |s: f64| json!([(lo * s).as_slice(), (hi * s).as_slice()]);
        let run = |meshes: Value, actors: Value| {
            let level = TempFile::new(
                "level.json",
                json!({"meshes": meshes, "actors": actors, "runs": 2})
                    .to_string()
                    .as_bytes(),
            );
            UNREAL_STUB.read_with(file.path(), &[level.path()])
        };
        let errors_in = |v: &Value| -> Vec<String> {
            v["log"]
                .as_array()
                .expect("a log")
                .iter()
                .filter(|l| l[0] == "error")
                .map(|l| l[1].as_str().expect("text").to_owned())
                .collect()
        };
        let v = run(
            json!([{"name": mesh, "bounds": bounds(1.0)}, {"name": "other", "bounds": bounds(1.0)}]),
            json!([
                {"name": "A", "mesh": mesh},
                {"name": "B", "mesh": mesh, "scale": [2.0, 2.0, 2.0]},
                {"name": "C", "mesh": "other"},
            ]),
        );
        assert!(errors_in(&v).is_empty(), "{v}");
        let shapes = &v["meshes"][mesh.as_str()];
        let boxes = shapes["boxes"].as_array().expect("boxes");
        assert_eq!(boxes.len(), 1, "one box after two runs: {v}");
        let a = &boxes[0];
        assert_eq!(a["name"], EQUIVALENT_BOX);
        assert_eq!(a["collision"], "NO_COLLISION");
        assert_eq!(a["contribute_to_mass"], true);
        for hull in shapes["convex"].as_array().expect("hulls") {
            assert_eq!(hull["collision"], "QUERY_AND_PHYSICS", "{v}");
            assert_eq!(hull["contribute_to_mass"], false, "{v}");
        }
        // A solid box: moments m(b² + c²)/12 about its centre, along its turned axes.
        let m = f(&v["bodies"]["A"]["mass_in_kg_override"]);
        let e = floats(&a["edges"]);
        let moments = [
            m * (e[1] * e[1] + e[2] * e[2]) / 12.0,
            m * (e[0] * e[0] + e[2] * e[2]) / 12.0,
            m * (e[0] * e[0] + e[1] * e[1]) / 12.0,
        ];
        let q = floats(&a["xyzw"]);
        let c = floats(&a["center"]);
        let read = Read::principal(
            m,
            Vector3::new(c[0], c[1], c[2]),
            quat(q[3], q[0], q[1], q[2]),
            moments,
        );
        let label = format!("{name} up {up} unreal-script's equivalent box");
        check(&label, errors(&read, "unreal", up, 0.01, &exact));
        for actor in ["A", "B"] {
            let body = &v["bodies"][actor];
            assert_eq!(body["override_mass"], true);
            assert_eq!(f(&body["mass_in_kg_override"]), m);
            assert_eq!(body["inertia_conditioning"], false);
            assert_eq!(floats(&body["com_nudge"]), [0.0; 3]);
            assert_eq!(floats(&body["inertia_tensor_scale"]), [1.0; 3]);
        }
        assert_eq!(v["bodies"]["C"]["override_mass"], false);
        assert!(
            v["meshes"]["other"]["boxes"]
                .as_array()
                .expect("boxes")
                .is_empty()
        );

        // Imported in metres as if centimetres: refused, and how to reimport said.
        let v = run(
            json!([{"name": mesh, "bounds": bounds(0.01)}]),
            json!([{"name": "A", "mesh": mesh}]),
        );
        let said = errors_in(&v);
        assert!(said.iter().any(|e| e.contains("Uniform Scale 100")), "{v}");
        assert!(
            v["meshes"][mesh.as_str()]["boxes"]
                .as_array()
                .expect("boxes")
                .is_empty()
        );
        assert_eq!(v["bodies"]["A"]["override_mass"], false);
        // Complex collision as simple: refused.
        let v = run(
            json!([{"name": mesh, "bounds": bounds(1.0), "trace": "CTF_USE_COMPLEX_AS_SIMPLE"}]),
            json!([{"name": "A", "mesh": mesh}]),
        );
        let said = errors_in(&v);
        assert!(
            said.iter()
                .any(|e| e.contains("Use Complex Collision As Simple")),
            "{v}"
        );
        assert_eq!(v["bodies"]["A"]["override_mass"], false);
        // With actors selected, only theirs.
        let v = run(
            json!([{"name": mesh, "bounds": bounds(1.0)}]),
            json!([{"name": "A", "mesh": mesh, "selected": true}, {"name": "B", "mesh": mesh}]),
        );
        assert_eq!(v["bodies"]["A"]["override_mass"], true, "{v}");
        assert_eq!(v["bodies"]["B"]["override_mass"], false, "{v}");
    }
}
