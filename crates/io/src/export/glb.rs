//! `glb`: a whole binary glTF file: the body's surface as a mesh on one node, the node carrying
//! `KHR_physics_rigid_bodies`' motion (as the `gltf` fragment writes it), the extension listed
//! in `extensionsUsed`.
//!
//! glTF 2.0 (Khronos, §4.4 binary glTF): a 12-byte header (`glTF`, version 2, length), a JSON
//! chunk padded with spaces and a BIN chunk padded with zeros, each to four bytes. Positions
//! are `FLOAT` `VEC3` with their `min` and `max` (required for POSITION, §3.7.2.1), indices
//! `UNSIGNED_INT`; glTF is right-handed, +Y up, metres, counter-clockwise front faces.
//! Positions are single precision, as glTF stores them: the motion's numbers are the exact
//! body's in double precision, not recomputed from the rounded corners.
//!
//! With a baked [`Motion`], the file also has one animation (§3.11) of two `LINEAR` samplers on
//! the node: `rotation` (`VEC4` x, y, z, w) and `translation` (`VEC3`), keyed at each frame's
//! time in seconds, single precision as glTF requires of animation data. A player interpolates
//! between keyframes (slerp for the rotation); the keyframes themselves are the simulation's
//! states.

use serde_json::{Value, json};

use super::frames::Converted;
use super::motion::Motion;
use super::surface::Surface;

/// The GLB file's bytes.
pub fn render(
    body: &Converted,
    surface: &Surface,
    name: &str,
    animation: Option<&Motion>,
) -> Vec<u8> {
    let s = body.conversion.source_unit.metres() / body.conversion.target_unit.metres();
    let points: Vec<[f32; 3]> = surface
        .points
        .iter()
        .map(|p| {
            let q = body.map * p.coords * s;
            [q.x as f32, q.y as f32, q.z as f32]
        })
        .collect();
    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    for p in &points {
        for k in 0..3 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    let mut bin = Vec::with_capacity(points.len() * 12 + surface.triangles.len() * 12);
    for p in &points {
        for c in p {
            bin.extend_from_slice(&c.to_le_bytes());
        }
    }
    let positions_length = bin.len();
    for t in &surface.triangles {
        for i in t {
            bin.extend_from_slice(&i.to_le_bytes());
        }
    }
    let indices_length = bin.len() - positions_length;
    let frames = animation.map(|a| (a.fps, a.in_target(body)));
    let mut node = super::gltf::node(body);
    // The fragment's note on extensionsUsed is done here.
    if let Some(Value::String(text)) = node.pointer_mut("/extras/inertia_lab_conventions") {
        *text = text.replace(
            " Add \"KHR_physics_rigid_bodies\" to extensionsUsed.",
            " The mesh is in the same node space.",
        );
    }
    node["name"] = json!(name);
    node["mesh"] = json!(0);
    let mut doc = json!({
        "asset": {"version": "2.0", "generator": "Inertia Lab"},
        "extensionsUsed": ["KHR_physics_rigid_bodies"],
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [node],
        "meshes": [{
            "name": name,
            "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]
        }],
        "accessors": [
            {
                "bufferView": 0, "componentType": 5126, "count": points.len(),
                "type": "VEC3", "min": min, "max": max
            },
            {
                "bufferView": 1, "componentType": 5125,
                "count": surface.triangles.len() * 3, "type": "SCALAR"
            }
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": positions_length, "target": 34962},
            {
                "buffer": 0, "byteOffset": positions_length, "byteLength": indices_length,
                "target": 34963
            }
        ],
        "buffers": [{"byteLength": 0}]
    });
    if let Some((fps, frames)) = &frames {
        add_animation(&mut doc, &mut bin, *fps, frames);
    }
    doc["buffers"][0]["byteLength"] = json!(bin.len());
    glb(&doc, bin)
}

/// Appends the keyframes' times, rotations and translations to `bin` and the animation that
/// plays them on node 0 to `doc`.
fn add_animation(
    doc: &mut Value,
    bin: &mut Vec<u8>,
    fps: f64,
    frames: &[(nalgebra::UnitQuaternion<f64>, nalgebra::Vector3<f64>)],
) {
    let times: Vec<f32> = (0..frames.len()).map(|k| (k as f64 / fps) as f32).collect();
    let rotations: Vec<f32> = frames
        .iter()
        .flat_map(|(q, _)| [q.i, q.j, q.k, q.w].map(|c| c as f32))
        .collect();
    let translations: Vec<f32> = frames
        .iter()
        .flat_map(|(_, t)| [t.x, t.y, t.z].map(|c| c as f32))
        .collect();
    let mut view = |values: &[f32]| {
        let offset = bin.len();
        for v in values {
            bin.extend_from_slice(&v.to_le_bytes());
        }
        let views = doc["bufferViews"].as_array_mut().expect("bufferViews");
        views.push(json!({"buffer": 0, "byteOffset": offset, "byteLength": bin.len() - offset}));
        views.len() - 1
    };
    let [t, r, p] = [view(&times), view(&rotations), view(&translations)];
    let count = frames.len();
    let last = times.last().copied().unwrap_or(0.0);
    let accessors = doc["accessors"].as_array_mut().expect("accessors");
    let first = accessors.len();
    accessors.extend([
        json!({
            "bufferView": t, "componentType": 5126, "count": count, "type": "SCALAR",
            "min": [0.0], "max": [last]
        }),
        json!({"bufferView": r, "componentType": 5126, "count": count, "type": "VEC4"}),
        json!({"bufferView": p, "componentType": 5126, "count": count, "type": "VEC3"}),
    ]);
    doc["animations"] = json!([{
        "name": "tumble",
        "samplers": [
            {"input": first, "output": first + 1, "interpolation": "LINEAR"},
            {"input": first, "output": first + 2, "interpolation": "LINEAR"}
        ],
        "channels": [
            {"sampler": 0, "target": {"node": 0, "path": "rotation"}},
            {"sampler": 1, "target": {"node": 0, "path": "translation"}}
        ]
    }]);
    if let Some((q, t)) = frames.first() {
        doc["nodes"][0]["rotation"] = json!([q.i, q.j, q.k, q.w]);
        doc["nodes"][0]["translation"] = json!([t.x, t.y, t.z]);
    }
}

/// The GLB container of a JSON document and its binary buffer.
fn glb(doc: &Value, mut bin: Vec<u8>) -> Vec<u8> {
    let mut json = doc.to_string().into_bytes();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let length = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(length);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(length as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}
