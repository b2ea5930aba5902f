//! The glTF reader against closed forms placed through node trees (rotation, non-uniform scale,
//! mirroring, quantization, instancing, sparse accessors, strips and fans), the same scene as
//! GLB, as `.gltf` with a data URI and with a `.bin` beside it, bad files refused by name, and the
//! files written here checked by Khronos' validator.

use std::path::Path;

use nalgebra::{Matrix3, Rotation3, Vector3};
use serde_json::{Value, json};

use super::super::tests::{
    assert_close, placed_box, properties, signed_volume, two_unit_cubes_four_apart,
};
use super::*;
use crate::MassProperties;

/// The unit cube centred on the origin: corner `i` has coordinate `bit − ½` on each axis (x is
/// bit 0, y bit 1, z bit 2).
fn cube_corners() -> Vec<[f64; 3]> {
    (0..8)
        .map(|i| [0, 1, 2].map(|a| f64::from((i >> a) & 1) - 0.5))
        .collect()
}

/// The cube's twelve triangles, wound outward.
const CUBE_TRIANGLES: [u32; 36] = [
    0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3,
    7, 1, 7, 5,
];

/// A glTF document being written: the JSON and its one binary buffer.
struct Writer {
    json: Value,
    bin: Vec<u8>,
}

impl Writer {
    fn new() -> Self {
        Self {
            json: json!({
                "asset": {"version": "2.0", "generator": "Inertia Lab's tests"},
                "scene": 0, "scenes": [{"nodes": []}],
                "nodes": [], "meshes": [], "accessors": [], "bufferViews": [], "buffers": []
            }),
            bin: Vec::new(),
        }
    }

    fn push(&mut self, key: &str, value: Value) -> usize {
        let list = self.json[key].as_array_mut().expect("a list");
        list.push(value);
        list.len() - 1
    }

    /// A buffer view of `bytes` (4-byte aligned), with a stride if given.
    fn view(&mut self, bytes: &[u8], stride: Option<usize>, target: Option<u32>) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let mut view =
            json!({"buffer": 0, "byteOffset": self.bin.len(), "byteLength": bytes.len()});
        if let Some(s) = stride {
            view["byteStride"] = json!(s);
        }
        if let Some(t) = target {
            view["target"] = json!(t);
        }
        self.bin.extend_from_slice(bytes);
        self.push("bufferViews", view)
    }

    /// Float positions, with their bounds (the specification asks for them).
    fn positions(&mut self, points: &[[f64; 3]]) -> usize {
        let bytes: Vec<u8> = points
            .iter()
            .flatten()
            .flat_map(|&c| (c as f32).to_le_bytes())
            .collect();
        let view = self.view(&bytes, None, Some(34962));
        let (min, max) = bounds(points);
        self.push(
            "accessors",
            json!({"bufferView": view, "componentType": 5126, "count": points.len(),
                   "type": "VEC3", "min": min, "max": max}),
        )
    }

    /// Corner indices as unsigned bytes, shorts or ints (5121, 5123, 5125).
    fn indices(&mut self, indices: &[u32], component: u32) -> usize {
        let bytes: Vec<u8> = indices
            .iter()
            .flat_map(|&i| match component {
                5121 => vec![i as u8],
                5123 => (i as u16).to_le_bytes().to_vec(),
                _ => i.to_le_bytes().to_vec(),
            })
            .collect();
        let view = self.view(&bytes, None, Some(34963));
        self.push(
            "accessors",
            json!({"bufferView": view, "componentType": component, "count": indices.len(),
                   "type": "SCALAR"}),
        )
    }

    fn mesh(&mut self, name: &str, primitives: Value) -> usize {
        self.push("meshes", json!({"name": name, "primitives": primitives}))
    }

    /// The cube as one indexed triangle list.
    fn cube(&mut self) -> usize {
        let p = self.positions(&cube_corners());
        let i = self.indices(&CUBE_TRIANGLES, 5123);
        self.mesh(
            "cube",
            json!([{"attributes": {"POSITION": p}, "indices": i}]),
        )
    }

    fn node(&mut self, node: Value) -> usize {
        self.push("nodes", node)
    }

    fn root(&mut self, node: usize) {
        self.json["scenes"][0]["nodes"]
            .as_array_mut()
            .expect("a list")
            .push(json!(node));
    }

    fn require(&mut self, extension: &str) {
        for key in ["extensionsUsed", "extensionsRequired"] {
            self.json[key] = json!([extension]);
        }
    }

    /// The JSON with its buffer described as `buffer` says.
    fn json_with(&self, buffer: Value) -> Value {
        let mut json = self.json.clone();
        json["buffers"] = json!([buffer]);
        json
    }

    fn glb(&self) -> Vec<u8> {
        let mut text = serde_json::to_vec(&self.json_with(json!({"byteLength": self.bin.len()})))
            .expect("JSON");
        while !text.len().is_multiple_of(4) {
            text.push(b' ');
        }
        let mut bin = self.bin.clone();
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        let mut out = Vec::new();
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&((12 + 8 + text.len() + 8 + bin.len()) as u32).to_le_bytes());
        for (kind, data) in [(JSON_CHUNK, &text), (BIN_CHUNK, &bin)] {
            out.extend_from_slice(&(data.len() as u32).to_le_bytes());
            out.extend_from_slice(&kind.to_le_bytes());
            out.extend_from_slice(data);
        }
        out
    }

    fn gltf_with_data_uri(&self) -> Vec<u8> {
        let uri = format!(
            "data:application/octet-stream;base64,{}",
            base64_of(&self.bin)
        );
        serde_json::to_vec(&self.json_with(json!({"byteLength": self.bin.len(), "uri": uri})))
            .expect("JSON")
    }

    fn gltf_beside(&self, bin_name: &str) -> Vec<u8> {
        serde_json::to_vec(&self.json_with(json!({"byteLength": self.bin.len(), "uri": bin_name})))
            .expect("JSON")
    }
}

fn bounds(points: &[[f64; 3]]) -> (Vec<f64>, Vec<f64>) {
    let fold = |f: fn(f64, f64) -> f64, start: f64| {
        (0..3)
            .map(|a| points.iter().map(|p| p[a]).fold(start, f))
            .collect::<Vec<_>>()
    };
    (
        fold(f64::min, f64::INFINITY),
        fold(f64::max, f64::NEG_INFINITY),
    )
}

/// Base64 written the plain way (the test's own, to check the reader's decoder against).
fn base64_of(bytes: &[u8]) -> String {
    const DIGITS: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::new();
    for chunk in bytes.chunks(3) {
        let mut n = 0u32;
        for (k, &b) in chunk.iter().enumerate() {
            n |= u32::from(b) << (16 - 8 * k);
        }
        for k in 0..4 {
            out.push(if k <= chunk.len() {
                DIGITS[((n >> (18 - 6 * k)) & 63) as usize] as char
            } else {
                '='
            });
        }
    }
    out
}

fn read(bytes: &[u8]) -> MeshFile {
    parse_gltf(bytes, Path::new("scene.glb")).expect("reads")
}

/// The cube under a parent that turns it 30° about z and moves it, and a child that scales it
/// to 2 × 3 × 4: the box's closed form, turned and moved.
fn nested_scene() -> Writer {
    let mut w = Writer::new();
    let cube = w.cube();
    let child = w.node(json!({"name": "brick", "mesh": cube, "scale": [2.0, 3.0, 4.0]}));
    let half = 15f64.to_radians();
    let parent = w.node(json!({
        "name": "arm", "children": [child],
        "rotation": [0.0, 0.0, half.sin(), half.cos()], "translation": [1.0, 2.0, 3.0]
    }));
    w.root(parent);
    w
}

fn nested_expected() -> MassProperties {
    let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), 30f64.to_radians());
    placed_box([2.0, 3.0, 4.0], *turn.matrix(), [1.0, 2.0, 3.0])
}

#[test]
fn a_node_tree_places_the_box_by_its_closed_form() {
    let file = read(&nested_scene().glb());
    assert_close(
        &properties(&file),
        &nested_expected(),
        "turned, scaled, moved",
    );
    assert_eq!(file.part_names, ["brick"]);
    assert_eq!(file.face_parts, vec![0; 12]);
}

/// The tetrahedron as GLB, with no node placement, is the OBJ's mesh corner for corner and its
/// mass properties bit for bit.
#[test]
fn the_tetrahedron_is_the_objs() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    let obj = super::super::parse_obj(obj.as_bytes(), Path::new("t.obj")).expect("obj");
    let mut w = Writer::new();
    let p = w.positions(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    let i = w.indices(&[0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3], 5125);
    let mesh = w.mesh(
        "tetra",
        json!([{"attributes": {"POSITION": p}, "indices": i}]),
    );
    let node = w.node(json!({"mesh": mesh}));
    w.root(node);
    let file = read(&w.glb());
    assert_eq!(
        super::super::tests::face_points(&file.mesh),
        super::super::tests::face_points(&obj.mesh)
    );
    assert_eq!(properties(&file), properties(&obj));
}

/// A matrix says the same as translation, rotation and scale.
#[test]
fn a_matrix_places_as_its_trs_does() {
    let mut w = Writer::new();
    let cube = w.cube();
    let (c, s) = (0.6, 0.8);
    // Column-major: a turn about x by (cos, sin) = (0.6, 0.8), then scaled 2 along x, moved (0, 0, 5).
    let node = w.node(json!({"mesh": cube, "matrix": [
        2.0, 0.0, 0.0, 0.0,  0.0, c, s, 0.0,  0.0, -s, c, 0.0,  0.0, 0.0, 5.0, 1.0
    ]}));
    w.root(node);
    let turn = Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c);
    let file = read(&w.glb());
    assert_close(
        &properties(&file),
        &placed_box([2.0, 1.0, 1.0], turn, [0.0, 0.0, 5.0]),
        "matrix",
    );
    assert_eq!(
        file.part_names,
        ["cube"],
        "the mesh's name when the node has none"
    );
}

/// A mirroring scale turns the winding back: the volume is +1, not −1.
#[test]
fn a_mirrored_node_stays_outward() {
    for scale in [[-1.0, 1.0, 1.0], [-1.0, -1.0, -1.0], [1.0, -2.0, 1.0]] {
        let mut w = Writer::new();
        let cube = w.cube();
        let node = w.node(json!({"mesh": cube, "scale": scale}));
        w.root(node);
        let sides = scale.map(f64::abs);
        let file = read(&w.glb());
        let volume = signed_volume(&file.mesh);
        assert!(
            (volume - sides.iter().product::<f64>()).abs() < 1e-12,
            "{scale:?}: {volume}"
        );
        assert_close(
            &properties(&file),
            &placed_box(sides, Matrix3::identity(), [0.0; 3]),
            &format!("scale {scale:?}"),
        );
    }
}

/// One mesh in two nodes is two parts, each placed: the pair's closed form.
#[test]
fn instances_are_parts() {
    let mut w = Writer::new();
    let cube = w.cube();
    for x in [0.0, 4.0] {
        let node = w.node(json!({"name": "wheel", "mesh": cube, "translation": [x, 0.0, 0.0]}));
        w.root(node);
    }
    let file = read(&w.glb());
    assert_eq!(file.part_names, ["wheel", "wheel 2"]);
    assert_eq!(
        file.parts().iter().map(|p| p.1.len()).collect::<Vec<_>>(),
        [12, 12]
    );
    assert_close(
        &properties(&file),
        &two_unit_cubes_four_apart(),
        "two instances",
    );
}

/// The unit cube quantized: corners stored as `low` or `high` in `component`s (with a stride
/// that keeps each element 4-byte aligned, as the specification asks), placed by a node that
/// scales by `scale`.
fn quantized_cube(component: u32, normalized: bool, low: i32, high: i32, scale: f64) -> Writer {
    let mut w = Writer::new();
    w.require("KHR_mesh_quantization");
    let size: usize = if matches!(component, 5120 | 5121) {
        1
    } else {
        2
    };
    let stride = 4 * (3 * size).div_ceil(4);
    let mut bytes = Vec::new();
    for corner in cube_corners() {
        for c in corner {
            let q = if c < 0.0 { low } else { high };
            bytes.extend_from_slice(&q.to_le_bytes()[..size]);
        }
        bytes.resize(bytes.len() + stride - 3 * size, 0);
    }
    let view = w.view(&bytes, Some(stride), Some(34962));
    let p = w.push(
        "accessors",
        json!({"bufferView": view, "componentType": component, "normalized": normalized,
               "count": 8, "type": "VEC3", "min": vec![low; 3], "max": vec![high; 3]}),
    );
    let i = w.indices(&CUBE_TRIANGLES, 5121);
    let mesh = w.mesh("q", json!([{"attributes": {"POSITION": p}, "indices": i}]));
    let node = w.node(json!({"mesh": mesh, "scale": vec![scale; 3]}));
    w.root(node);
    w
}

/// Quantized positions give the unit cube: signed shorts normalized (±32767 is ±1, −32768
/// clamps to −1), signed bytes and unsigned shorts normalized, unsigned bytes not (0 or 2).
#[test]
fn quantized_positions_are_dequantized() {
    for (component, normalized, low, high, scale, center) in [
        (5122u32, true, -32768i32, 32767i32, 0.5, 0.0),
        (5122, true, -32767, 32767, 0.5, 0.0),
        (5121, false, 0, 2, 0.5, 0.5),
        (5123, true, 0, 65535, 1.0, 0.5),
        (5120, true, -127, 127, 0.5, 0.0),
    ] {
        let w = quantized_cube(component, normalized, low, high, scale);
        assert_close(
            &properties(&read(&w.glb())),
            &placed_box([1.0; 3], Matrix3::identity(), [center; 3]),
            &format!("component {component}, normalized {normalized}, from {low}"),
        );
    }
}

/// A sparse accessor with no buffer view: zeros, with the cube's eight corners put in place.
#[test]
fn a_sparse_accessor_replaces_its_elements() {
    let mut w = Writer::new();
    let targets: Vec<u8> = (0u8..8).rev().collect();
    let values: Vec<u8> = targets
        .iter()
        .flat_map(|&t| cube_corners()[t as usize])
        .flat_map(|c| (c as f32).to_le_bytes())
        .collect();
    let index_view = w.view(&targets, None, None);
    let value_view = w.view(&values, None, None);
    let (min, max) = bounds(&cube_corners());
    let p = w.push(
        "accessors",
        json!({"componentType": 5126, "count": 8, "type": "VEC3", "min": min, "max": max,
               "sparse": {"count": 8,
                          "indices": {"bufferView": index_view, "componentType": 5121},
                          "values": {"bufferView": value_view}}}),
    );
    let i = w.indices(&CUBE_TRIANGLES, 5125);
    let mesh = w.mesh(
        "sparse",
        json!([{"attributes": {"POSITION": p}, "indices": i}]),
    );
    let node = w.node(json!({"mesh": mesh}));
    w.root(node);
    assert_close(
        &properties(&read(&w.glb())),
        &placed_box([1.0; 3], Matrix3::identity(), [0.0; 3]),
        "sparse",
    );
}

/// The unit tetrahedron (volume 1/6) three ways, each its own part away from the origin: its
/// sides as a fan about the origin with the base as a list; the whole as one strip (whose odd
/// triangles turn), with a repeated corner where a second strip joins; and as a list without
/// indices. Each part encloses +1/6, wound outward.
#[test]
fn strips_fans_and_unindexed_lists_make_the_same_faces() {
    let corners = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    let mut w = Writer::new();
    let p = w.positions(&corners);
    // The outward faces are 0-2-1, 0-1-3, 0-3-2 and 1-2-3. A fan from 0 over 2, 1, 3, 2 gives
    // the first three as (2,1,0), (1,3,0), (3,2,0).
    let fan = w.indices(&[0, 2, 1, 3, 2], 5123);
    let base = w.indices(&[1, 2, 3], 5123);
    // The strip 0 2 1 3 0 2 gives (0,2,1), (1,2,3) turned, (1,3,0), (0,3,2) turned; the 2 2 2
    // after it repeat corners, as strips are joined: no faces.
    let strip = w.indices(&[0, 2, 1, 3, 0, 2, 2, 2, 2], 5121);
    let flat: Vec<[f64; 3]> = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
        .iter()
        .flatten()
        .map(|&k| corners[k])
        .collect();
    let unindexed = w.positions(&flat);
    let fan_base = w.mesh(
        "fan",
        json!([{"attributes": {"POSITION": p}, "indices": fan, "mode": 6},
               {"attributes": {"POSITION": p}, "indices": base},
               {"attributes": {"POSITION": p}, "mode": 1}]),
    );
    let strip = w.mesh(
        "strip",
        json!([{"attributes": {"POSITION": p}, "indices": strip, "mode": 5}]),
    );
    let list = w.mesh("list", json!([{"attributes": {"POSITION": unindexed}}]));
    for (k, mesh) in [fan_base, strip, list].into_iter().enumerate() {
        let node = w.node(json!({"mesh": mesh, "translation": [3.0 * k as f64 + 1.0, 2.0, 1.0]}));
        w.root(node);
    }
    let file = read(&w.glb());
    let parts = file.parts();
    assert_eq!(
        parts
            .iter()
            .map(|(n, f)| (n.as_str(), f.len()))
            .collect::<Vec<_>>(),
        [("fan", 4), ("strip", 4), ("list", 4)],
        "the strip's joins are no faces"
    );
    for (name, faces) in &parts {
        let volume = signed_volume(&file.mesh.subset(faces).expect("a part"));
        assert!((volume - 1.0 / 6.0).abs() < 1e-15, "{name}: {volume}");
    }
}

/// The same scene as GLB, as `.gltf` with a data URI and with a `.bin` beside it: the same mesh.
#[test]
fn every_container_gives_the_same_mesh() {
    let w = nested_scene();
    let glb = read(&w.glb());
    let data_uri = parse_gltf(&w.gltf_with_data_uri(), Path::new("s.gltf")).expect("data URI");
    let dir = std::env::temp_dir().join(format!("gltf-beside-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(dir.join("the mesh.bin"), &w.bin).expect("writes");
    let gltf = w.gltf_beside("the%20mesh.bin");
    std::fs::write(dir.join("s.gltf"), &gltf).expect("writes");
    let beside = super::super::load_mesh(&dir.join("s.gltf")).expect("beside");
    assert_eq!(data_uri, glb);
    assert_eq!(beside, glb);
    let in_memory = parse_gltf_with(&gltf, Path::new("s.gltf"), &|uri| {
        (uri == "the mesh.bin")
            .then(|| w.bin.clone())
            .ok_or_else(|| "not given".to_owned())
    });
    assert_eq!(in_memory.expect("given"), glb);
    std::fs::remove_dir_all(dir).ok();
}

/// Bad files are refused by name: the element and what is wrong.
#[test]
fn bad_files_are_refused_by_name() {
    let said = |json: Value| {
        let mut w = nested_scene();
        w.json = json;
        parse_gltf(&w.glb(), Path::new("bad.glb"))
            .map(|_| ())
            .map_err(|e| e.to_string())
    };
    let base = nested_scene().json;
    let with = |pointer: &str, value: Value| {
        let mut json = base.clone();
        *json.pointer_mut(pointer).expect(pointer) = value;
        json
    };
    for (json, expected) in [
        (
            {
                let mut j = base.clone();
                j["extensionsRequired"] = json!(["KHR_draco_mesh_compression"]);
                j
            },
            "the file requires the extension KHR_draco_mesh_compression: its geometry is \
             compressed; decompress it first (for example with gltf-transform's `copy`)",
        ),
        (
            with("/asset/version", json!("1.0")),
            "glTF 1.0: only glTF 2.0 is read",
        ),
        (
            with("/accessors/0/count", json!(9)),
            "accessor 0: 9 elements of 12 bytes every 12 bytes need more than the 96 bytes \
             buffer view 0 has from its offset",
        ),
        (
            with("/bufferViews/1/byteLength", json!(1000)),
            "buffer view 1 spans bytes 96 to 96+1000, past the 168 bytes of buffer 0",
        ),
        (
            with(
                "/nodes/0",
                json!({"mesh": 0, "scale": [2.0, 3.0, 4.0], "children": [1]}),
            ),
            "node 1 is reached twice in the scene (a node has one parent)",
        ),
        (
            with("/nodes/1/rotation", json!([0, 0, 0])),
            "node 1: \"rotation\" must be 4 finite numbers, not [0,0,0]",
        ),
        (
            // A count without a view asks for zeros; a few bytes must not ask for gigabytes.
            with(
                "/accessors/0",
                json!({"componentType": 5126, "count": 100_000_000, "type": "VEC3"}),
            ),
            "accessor 0: 100000000 elements of zeros is more than a file whose buffers hold \
             168 bytes can mean",
        ),
        (
            with("/meshes/0/primitives/0/attributes/POSITION", json!(7)),
            "accessor 7 does not exist (the file has 2)",
        ),
    ] {
        assert_eq!(said(json), Err(format!("bad.glb: {expected}")));
    }
    // An index past the vertices, written into the buffer.
    let mut w = nested_scene();
    let at = w.json["bufferViews"][1]["byteOffset"]
        .as_u64()
        .expect("JSON") as usize;
    w.bin[at] = 8;
    assert_eq!(
        parse_gltf(&w.glb(), Path::new("bad.glb"))
            .map(|_| ())
            .map_err(|e| e.to_string()),
        Err(
            "bad.glb: accessor 1 (indices of mesh 0, primitive 0) names vertex 8, but the \
             primitive has 8"
                .to_owned()
        )
    );
    // A GLB cut short, and one of another version.
    let glb = nested_scene().glb();
    let short = parse_gltf(&glb[..glb.len() - 10], Path::new("bad.glb")).map(|_| ());
    assert!(
        matches!(&short, Err(e) if e.to_string().contains("gives a length of")),
        "{short:?}"
    );
    let mut v1 = glb.clone();
    v1[4] = 1;
    assert_eq!(
        parse_gltf(&v1, Path::new("bad.glb"))
            .map(|_| ())
            .map_err(|e| e.to_string()),
        Err("bad.glb: GLB version 1: only glTF 2.0 is read".to_owned())
    );
    let missing = parse_gltf(
        &nested_scene().gltf_beside("gone.bin"),
        Path::new("/nowhere/s.gltf"),
    )
    .map(|_| ())
    .map_err(|e| e.to_string());
    assert!(
        matches!(&missing, Err(e) if e.starts_with("/nowhere/s.gltf: buffer 0: cannot read gone.bin: ")),
        "{missing:?}"
    );
}

/// The decoder against the test's encoder, every length mod 3.
#[test]
fn base64_round_trips() {
    let bytes: Vec<u8> = (0..=255).collect();
    for n in [0, 1, 2, 3, 4, 5, 255, 256] {
        assert_eq!(base64(&base64_of(&bytes[..n])).as_deref(), Ok(&bytes[..n]));
    }
    assert!(base64("ab!c").is_err());
}

/// The files these tests write pass Khronos' validator (npm `gltf-validator`) without an error.
#[test]
fn the_test_files_are_valid_gltf() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../target/gltf-validator");
    let module = root.join("node_modules/gltf-validator");
    let node = std::process::Command::new("node").arg("--version").output();
    if !module.is_dir() || node.is_err() {
        let message = "SKIPPED the_test_files_are_valid_gltf: Node.js and Khronos' glTF validator \
                       are missing (apt install nodejs npm; npm install --prefix \
                       target/gltf-validator gltf-validator@2.0.0-dev.3.10)";
        assert!(std::env::var("CI").as_deref() != Ok("true"), "{message}");
        println!("{message}");
        return;
    }
    let dir = std::env::temp_dir().join(format!("gltf-valid-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let mut mirrored = Writer::new();
    let cube = mirrored.cube();
    let n = mirrored.node(json!({"mesh": cube, "scale": [-1.0, 1.0, 1.0]}));
    mirrored.root(n);
    let scene = nested_scene();
    let files = [
        ("nested.glb", scene.glb()),
        ("nested.gltf", scene.gltf_with_data_uri()),
        ("mirrored.glb", mirrored.glb()),
        (
            "quantized.glb",
            quantized_cube(5122, true, -32767, 32767, 0.5).glb(),
        ),
    ];
    for (name, bytes) in &files {
        std::fs::write(dir.join(name), bytes).expect("writes");
    }
    let script = "const v = require(process.argv[2]); const fs = require('fs');
        (async () => { for (const f of process.argv.slice(3)) {
          const r = await v.validateBytes(new Uint8Array(fs.readFileSync(f)));
          console.log(f, r.issues.numErrors, JSON.stringify(r.issues.messages.filter(m => m.severity === 0)));
        } })();";
    std::fs::write(dir.join("validate.js"), script).expect("writes");
    let output = std::process::Command::new("node")
        .arg(dir.join("validate.js"))
        .arg(&module)
        .args(files.iter().map(|(name, _)| dir.join(name)))
        .output()
        .expect("node runs");
    let said = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{said}{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let lines: Vec<&str> = said.lines().collect();
    assert_eq!(lines.len(), files.len(), "{said}");
    for line in lines {
        assert!(line.split(' ').nth(1) == Some("0"), "errors: {line}");
    }
    std::fs::remove_dir_all(dir).ok();
}
