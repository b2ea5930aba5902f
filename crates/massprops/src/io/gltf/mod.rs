//! glTF 2.0 (Khronos; `.gltf` JSON with its buffers in `.bin` files or data URIs, or one binary
//! `.glb`): the default scene's node tree is walked, each node's matrix or translation, rotation
//! and scale composed in f64 with its parents', and every node that references a mesh placed as
//! one part (named after the node, else its mesh). Positions are read from their accessor as
//! stored: floats, or the integers of `KHR_mesh_quantization` (signed or unsigned bytes and
//! shorts), turned into numbers by the specification's rule when the accessor is `normalized`
//! (`max(c / 32767, −1)` for a signed short; trimesh and the `gltf` crate get this wrong), with
//! `byteStride` and sparse accessors. Triangles, strips and fans make faces; points and lines
//! carry no volume and are passed over. A node whose placement mirrors (negative determinant)
//! has its triangles' winding turned, so its outward normals stay outward, as the specification
//! requires of renderers. Units are metres and +Y is up, as the specification says; nothing is
//! turned. Geometry compressed by an extension (Draco, meshopt) is refused by the extension's
//! name. Reference: the glTF 2.0 specification, sections 3.5–3.7 (Khronos, 2021).

use std::borrow::Cow;
use std::path::Path;

use nalgebra::{Matrix3, Matrix4, Point3, Quaternion, UnitQuaternion, Vector3};
use serde_json::Value;

use super::MeshFile;
use crate::MeshError;

/// What a binary glTF file starts with.
pub(super) const GLB_MAGIC: &[u8] = b"glTF";
const JSON_CHUNK: u32 = 0x4E4F_534A;
const BIN_CHUNK: u32 = 0x004E_4942;
/// How many zero values an accessor without a buffer view may have beyond its file's buffer
/// bytes: enough for any small file's placeholder, far from a hostile count's gigabytes.
const ZEROS_SLACK: usize = 1 << 16;

/// Extensions a file may require that change nothing of its geometry (materials, textures,
/// lights), or whose geometry this reader reads (quantization). Any other required extension is
/// refused by name, since reading past it could give wrong numbers.
const HARMLESS_PREFIXES: [&str; 5] = [
    "KHR_mesh_quantization",
    "KHR_materials_",
    "KHR_texture_",
    "EXT_texture_",
    "KHR_lights_",
];

/// Whether `bytes` are a glTF JSON document: an object (after any byte-order mark and blanks)
/// whose text has the `"asset"` key every glTF file must have.
pub(super) fn is_gltf_json(bytes: &[u8]) -> bool {
    let text = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    text.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{')
        && text.windows(7).any(|w| w == b"\"asset\"")
}

/// Reads a glTF or GLB file already in memory; `path` names it in messages, and a buffer in a
/// file of its own (`"uri": "mesh.bin"`) is read from beside it.
///
/// # Errors
/// The file does not follow the specification (the message names the accessor, buffer view,
/// buffer, node or primitive), needs an extension that changes its geometry (Draco, meshopt), a
/// buffer cannot be read, or the scene has no triangles.
pub fn parse_gltf(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let folder = path.parent().unwrap_or(Path::new(""));
    parse_gltf_with(bytes, path, &|uri| {
        std::fs::read(folder.join(uri)).map_err(|e| e.to_string())
    })
}

/// [`parse_gltf`] with the buffers in files of their own given by `external` (the file's URI,
/// percent-decoded, to its bytes or why not): the page passes the files dropped together.
///
/// # Errors
/// As [`parse_gltf`].
pub fn parse_gltf_with(
    bytes: &[u8],
    path: &Path,
    external: super::Beside,
) -> Result<MeshFile, MeshError> {
    let bad = |message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line: None,
        message,
    };
    let (json, bin) = if bytes.starts_with(GLB_MAGIC) {
        split_glb(bytes).map_err(bad)?
    } else {
        (bytes, None)
    };
    let json: Value = serde_json::from_slice(json).map_err(|e| MeshError::Malformed {
        path: path.to_path_buf(),
        line: (e.line() > 0 && !bytes.starts_with(GLB_MAGIC)).then_some(e.line()),
        message: format!("not glTF JSON: {e}"),
    })?;
    let document = Document::new(&json, bin, external).map_err(bad)?;
    let placed = document.placed_triangles().map_err(bad)?;
    if placed.triangles.is_empty() {
        return Err(bad(
            "the scene has no triangles (only points or lines, or no meshes), so it encloses no \
             volume"
                .to_owned(),
        ));
    }
    let corners = placed.triangles.iter().flatten().map(|&i| i as usize);
    let mesh = super::welded_mesh(
        path,
        &placed.positions,
        corners,
        &vec![3; placed.triangles.len()],
    )?;
    Ok(MeshFile {
        mesh,
        face_lines: Vec::new(),
        warnings: Vec::new(),
        part_names: placed.part_names,
        face_parts: placed.face_parts,
    })
}

/// A GLB's JSON chunk and its binary chunk, if it has one.
fn split_glb(bytes: &[u8]) -> Result<(&[u8], Option<&[u8]>), String> {
    let word = |at: usize| -> Option<u32> {
        bytes
            .get(at..at + 4)
            .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
    };
    let version = word(4).ok_or("a GLB header needs 12 bytes")?;
    if version != 2 {
        return Err(format!("GLB version {version}: only glTF 2.0 is read"));
    }
    let length = word(8).ok_or("a GLB header needs 12 bytes")? as usize;
    let bytes = bytes.get(..length).ok_or_else(|| {
        format!(
            "the GLB header gives a length of {length} bytes, but the file has {}",
            bytes.len()
        )
    })?;
    let mut chunks = Vec::new();
    let mut at = 12;
    while at < bytes.len() {
        let (Some(size), Some(kind)) = (word(at), word(at + 4)) else {
            return Err(format!("a chunk header at byte {at} is cut short"));
        };
        let start = at + 8;
        let data = start
            .checked_add(size as usize)
            .and_then(|end| bytes.get(start..end))
            .ok_or_else(|| {
                format!("the chunk at byte {at} claims {size} bytes, past the end of the file")
            })?;
        chunks.push((kind, data));
        at = start + size as usize;
    }
    match chunks.as_slice() {
        [(JSON_CHUNK, json), rest @ ..] => {
            let bin = rest.first().filter(|(k, _)| *k == BIN_CHUNK).map(|c| c.1);
            Ok((json, bin))
        }
        _ => Err("the first chunk of a GLB must be its JSON".to_owned()),
    }
}

/// The JSON with its buffers read.
struct Document<'a> {
    json: &'a Value,
    buffers: Vec<Cow<'a, [u8]>>,
}

/// Triangles in the file's frame, with the part each belongs to.
struct Placed {
    positions: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
    part_names: Vec<String>,
    face_parts: Vec<u32>,
}

/// `json[key]` as an array, empty when absent.
fn array<'v>(json: &'v Value, key: &str) -> &'v [Value] {
    json.get(key)
        .and_then(Value::as_array)
        .map_or(&[], Vec::as_slice)
}

/// A whole number ≥ 0 at `json[key]`: `Ok(None)` when absent, an error naming `what` when it is
/// not one.
fn index(json: &Value, key: &str, what: &str) -> Result<Option<usize>, String> {
    match json.get(key) {
        None => Ok(None),
        Some(v) => v
            .as_u64()
            .and_then(|n| usize::try_from(n).ok())
            .map(Some)
            .ok_or_else(|| format!("{what}: \"{key}\" must be a whole number ≥ 0, not {v}")),
    }
}

/// `count` finite numbers at `json[key]`, `None` when absent.
fn numbers<const N: usize>(
    json: &Value,
    key: &str,
    what: &str,
) -> Result<Option<[f64; N]>, String> {
    let Some(v) = json.get(key) else {
        return Ok(None);
    };
    let wrong = || format!("{what}: \"{key}\" must be {N} finite numbers, not {v}");
    let list = v.as_array().filter(|l| l.len() == N).ok_or_else(wrong)?;
    let mut out = [0.0; N];
    for (o, x) in out.iter_mut().zip(list) {
        *o = x.as_f64().filter(|x| x.is_finite()).ok_or_else(wrong)?;
    }
    Ok(Some(out))
}

impl<'a> Document<'a> {
    fn new(
        json: &'a Value,
        bin: Option<&'a [u8]>,
        external: &dyn Fn(&str) -> Result<Vec<u8>, String>,
    ) -> Result<Self, String> {
        let version = json
            .pointer("/asset/version")
            .and_then(Value::as_str)
            .ok_or("no \"asset\": {\"version\"}: not a glTF file")?;
        if !version.starts_with("2.") {
            return Err(format!("glTF {version}: only glTF 2.0 is read"));
        }
        for extension in array(json, "extensionsRequired") {
            let name = extension.as_str().unwrap_or_default();
            if !HARMLESS_PREFIXES.iter().any(|p| name.starts_with(p)) {
                let hint = if name.contains("draco") || name.contains("meshopt") {
                    ": its geometry is compressed; decompress it first (for example with \
                     gltf-transform's `copy`)"
                } else {
                    ", which this reader does not read"
                };
                return Err(format!("the file requires the extension {name}{hint}"));
            }
        }
        let mut buffers = Vec::new();
        for (b, buffer) in array(json, "buffers").iter().enumerate() {
            let what = format!("buffer {b}");
            let data: Cow<'a, [u8]> = match buffer.get("uri").and_then(Value::as_str) {
                None if b == 0 => Cow::Borrowed(
                    bin.ok_or("buffer 0 has no \"uri\" and the file has no binary chunk")?,
                ),
                None => return Err(format!("{what} has no \"uri\"")),
                Some(uri) if uri.starts_with("data:") => {
                    let (_, data) = uri
                        .split_once(";base64,")
                        .ok_or_else(|| format!("{what}: a data URI that is not base64"))?;
                    Cow::Owned(base64(data).map_err(|e| format!("{what}: {e}"))?)
                }
                Some(uri) if uri.starts_with('/') || uri.contains("://") => {
                    return Err(format!(
                        "{what}: {uri} is not a path relative to the file, which is all a \
                         buffer is read from"
                    ));
                }
                Some(uri) => {
                    let name = percent_decoded(uri);
                    Cow::Owned(
                        external(&name).map_err(|e| format!("{what}: cannot read {name}: {e}"))?,
                    )
                }
            };
            let length = index(buffer, "byteLength", &what)?
                .ok_or_else(|| format!("{what} has no \"byteLength\""))?;
            if data.len() < length {
                return Err(format!(
                    "{what} should hold {length} bytes, but has {}",
                    data.len()
                ));
            }
            buffers.push(data);
        }
        Ok(Self { json, buffers })
    }

    /// The `i`th element of the top-level array `key`, named `what i` in messages.
    fn item(&self, key: &str, i: usize, what: &str) -> Result<&'a Value, String> {
        array(self.json, key).get(i).ok_or_else(|| {
            format!(
                "{what} {i} does not exist (the file has {})",
                array(self.json, key).len()
            )
        })
    }

    /// Every triangle of the default scene, placed.
    fn placed_triangles(&self) -> Result<Placed, String> {
        let nodes = array(self.json, "nodes");
        let roots: Vec<usize> = match index(self.json, "scene", "the file")? {
            Some(s) => self.scene_roots(s)?,
            None if !array(self.json, "scenes").is_empty() => self.scene_roots(0)?,
            // No scene: every node that is no node's child is a root (as viewers do).
            None => {
                let mut child = vec![false; nodes.len()];
                for node in nodes {
                    for c in array(node, "children") {
                        if let Some(c) = c.as_u64().and_then(|c| child.get_mut(c as usize)) {
                            *c = true;
                        }
                    }
                }
                (0..nodes.len()).filter(|&n| !child[n]).collect()
            }
        };
        let mut placed = Placed {
            positions: Vec::new(),
            triangles: Vec::new(),
            part_names: Vec::new(),
            face_parts: Vec::new(),
        };
        let mut visited = vec![false; nodes.len()];
        let mut stack: Vec<(usize, Matrix4<f64>)> = roots
            .into_iter()
            .rev()
            .map(|n| (n, Matrix4::identity()))
            .collect();
        while let Some((n, parent)) = stack.pop() {
            let node = self.item("nodes", n, "node")?;
            if std::mem::replace(&mut visited[n], true) {
                return Err(format!(
                    "node {n} is reached twice in the scene (a node has one parent)"
                ));
            }
            let placement = parent * local_matrix(node, n)?;
            if let Some(m) = index(node, "mesh", &format!("node {n}"))? {
                self.place_mesh(n, m, &placement, &mut placed)?;
            }
            for c in array(node, "children").iter().rev() {
                let c = c
                    .as_u64()
                    .and_then(|c| usize::try_from(c).ok())
                    .ok_or_else(|| format!("node {n}: a child that is not a node index: {c}"))?;
                stack.push((c, placement));
            }
        }
        Ok(placed)
    }

    /// The root nodes of scene `s`.
    fn scene_roots(&self, s: usize) -> Result<Vec<usize>, String> {
        let scene = self.item("scenes", s, "scene")?;
        array(scene, "nodes")
            .iter()
            .map(|n| {
                n.as_u64()
                    .and_then(|n| usize::try_from(n).ok())
                    .ok_or_else(|| format!("scene {s}: a node that is not an index: {n}"))
            })
            .collect()
    }

    /// Mesh `m`'s triangles, placed by node `n`'s `placement`, as one part.
    fn place_mesh(
        &self,
        n: usize,
        m: usize,
        placement: &Matrix4<f64>,
        placed: &mut Placed,
    ) -> Result<(), String> {
        let mesh = self.item("meshes", m, "mesh")?;
        let node = self.item("nodes", n, "node")?;
        let linear: Matrix3<f64> = placement.fixed_view::<3, 3>(0, 0).into_owned();
        let offset: Vector3<f64> = placement.fixed_view::<3, 1>(0, 3).into_owned();
        let mirrored = linear.determinant() < 0.0;
        let part = placed.part_names.len() as u32;
        let name = [node, mesh]
            .iter()
            .find_map(|v| v.get("name").and_then(Value::as_str))
            .map_or_else(|| format!("node {n}"), str::to_owned);
        placed
            .part_names
            .push(super::unique_name(name, &placed.part_names));
        for (p, primitive) in array(mesh, "primitives").iter().enumerate() {
            let what = format!("mesh {m}, primitive {p}");
            let mode = index(primitive, "mode", &what)?.unwrap_or(4);
            if mode < 4 {
                continue;
            }
            if mode > 6 {
                return Err(format!("{what}: mode {mode} is not a glTF primitive mode"));
            }
            let a = primitive
                .pointer("/attributes/POSITION")
                .ok_or_else(|| format!("{what} has no POSITION attribute"))?
                .as_u64()
                .ok_or_else(|| format!("{what}: POSITION is not an accessor index"))?
                as usize;
            let (coords, width) = self.accessor(a)?;
            if width != 3 {
                return Err(format!("accessor {a} (POSITION of {what}) is not a VEC3"));
            }
            let first = placed.positions.len();
            let vertices = coords.len() / 3;
            placed.positions.extend(
                coords
                    .chunks_exact(3)
                    .map(|c| Point3::from(linear * Vector3::new(c[0], c[1], c[2]) + offset)),
            );
            let corners: Vec<usize> = match index(primitive, "indices", &what)? {
                None => (0..vertices).collect(),
                Some(i) => {
                    let (values, width) = self.accessor(i)?;
                    if width != 1 {
                        return Err(format!("accessor {i} (indices of {what}) is not a SCALAR"));
                    }
                    values
                        .iter()
                        .map(|&v| {
                            let v = v as usize;
                            (v < vertices).then_some(v).ok_or_else(|| {
                                format!(
                                    "accessor {i} (indices of {what}) names vertex {v}, but the \
                                     primitive has {vertices}"
                                )
                            })
                        })
                        .collect::<Result<_, _>>()?
                }
            };
            for [a, b, c] in triangles(mode, &corners) {
                let t = [a, b, c].map(|k| (first + k) as u32);
                placed
                    .triangles
                    .push(if mirrored { [t[0], t[2], t[1]] } else { t });
                placed.face_parts.push(part);
            }
        }
        Ok(())
    }

    /// Accessor `a`'s values as numbers (flat) and how many make one element; normalized
    /// integers are turned into numbers by the specification's rule, sparse values applied.
    fn accessor(&self, a: usize) -> Result<(Vec<f64>, usize), String> {
        let accessor = self.item("accessors", a, "accessor")?;
        let what = format!("accessor {a}");
        let width = match accessor.get("type").and_then(Value::as_str) {
            Some("SCALAR") => 1,
            Some("VEC2") => 2,
            Some("VEC3") => 3,
            Some("VEC4") => 4,
            other => return Err(format!("{what}: a \"type\" of {other:?} is not read here")),
        };
        let component = component_type(accessor, &what)?;
        let normalized = accessor
            .get("normalized")
            .and_then(Value::as_bool)
            .unwrap_or(false);
        let count =
            index(accessor, "count", &what)?.ok_or_else(|| format!("{what} has no \"count\""))?;
        let element = width * component.size;
        let mut values = match index(accessor, "bufferView", &what)? {
            // No view: zeros, which a sparse part may replace (the specification's rule). A
            // count is only a number in the JSON, so zeros are capped by what the file's
            // buffers could index (plus a little for small files) lest a few bytes ask for
            // gigabytes.
            None => {
                let cap = self.buffers.iter().map(|b| b.len()).sum::<usize>() + ZEROS_SLACK;
                let n = count
                    .checked_mul(width)
                    .filter(|&n| n <= cap)
                    .ok_or_else(|| {
                        format!(
                            "{what}: {count} elements of zeros is more than a file whose buffers \
                             hold {} bytes can mean",
                            cap - ZEROS_SLACK
                        )
                    })?;
                vec![0.0; n]
            }
            Some(v) => {
                let offset = index(accessor, "byteOffset", &what)?.unwrap_or(0);
                let (data, stride) = self.view(v, offset, element)?;
                if count > 0
                    && (count - 1).saturating_mul(stride).saturating_add(element) > data.len()
                {
                    return Err(format!(
                        "{what}: {count} elements of {element} bytes every {stride} bytes need \
                         more than the {} bytes buffer view {v} has from its offset",
                        data.len()
                    ));
                }
                let mut values = Vec::with_capacity(count * width);
                for e in 0..count {
                    let at = e * stride;
                    for k in 0..width {
                        values.push(component.read(&data[at + k * component.size..]));
                    }
                }
                values
            }
        };
        if let Some(sparse) = accessor.get("sparse") {
            self.apply_sparse(sparse, &what, count, width, component, &mut values)?;
        }
        if normalized {
            for v in &mut values {
                *v = component.normalize(*v);
            }
        }
        if let Some(v) = values.iter().find(|v| !v.is_finite()) {
            return Err(format!("{what} holds a value that is not finite: {v}"));
        }
        Ok((values, width))
    }

    /// Replaces the values a sparse accessor names.
    fn apply_sparse(
        &self,
        sparse: &Value,
        what: &str,
        count: usize,
        width: usize,
        component: Component,
        values: &mut [f64],
    ) -> Result<(), String> {
        let what = format!("{what}, sparse");
        let n = index(sparse, "count", &what)?.ok_or_else(|| format!("{what}: no \"count\""))?;
        let part = |key: &str| {
            sparse
                .get(key)
                .ok_or_else(|| format!("{what}: no \"{key}\""))
        };
        let (indices, places) = (part("indices")?, part("values")?);
        let index_type = component_type(indices, &format!("{what} indices"))?;
        let (index_data, _) = self.view(
            index(indices, "bufferView", &what)?.ok_or_else(|| format!("{what}: no index view"))?,
            index(indices, "byteOffset", &what)?.unwrap_or(0),
            index_type.size,
        )?;
        let (value_data, _) = self.view(
            index(places, "bufferView", &what)?.ok_or_else(|| format!("{what}: no value view"))?,
            index(places, "byteOffset", &what)?.unwrap_or(0),
            width * component.size,
        )?;
        if n.saturating_mul(index_type.size) > index_data.len()
            || n.saturating_mul(width * component.size) > value_data.len()
        {
            return Err(format!("{what}: {n} entries do not fit their buffer views"));
        }
        for s in 0..n {
            let target = index_type.read(&index_data[s * index_type.size..]) as usize;
            if target >= count {
                return Err(format!(
                    "{what}: entry {s} replaces element {target}, but there are {count}"
                ));
            }
            for k in 0..width {
                values[target * width + k] =
                    component.read(&value_data[(s * width + k) * component.size..]);
            }
        }
        Ok(())
    }

    /// Buffer view `v`'s bytes from `offset` on, and its stride for elements of `element` bytes.
    fn view(&self, v: usize, offset: usize, element: usize) -> Result<(&[u8], usize), String> {
        let view = self.item("bufferViews", v, "buffer view")?;
        let what = format!("buffer view {v}");
        let b = index(view, "buffer", &what)?.ok_or_else(|| format!("{what} has no \"buffer\""))?;
        let buffer = self
            .buffers
            .get(b)
            .ok_or_else(|| format!("{what} names buffer {b}, which does not exist"))?;
        let start = index(view, "byteOffset", &what)?.unwrap_or(0);
        let length = index(view, "byteLength", &what)?
            .ok_or_else(|| format!("{what} has no \"byteLength\""))?;
        let bytes = start
            .checked_add(length)
            .and_then(|end| buffer.get(start..end))
            .ok_or_else(|| {
                format!(
                    "{what} spans bytes {start} to {start}+{length}, past the {} bytes of buffer \
                     {b}",
                    buffer.len()
                )
            })?;
        let stride = index(view, "byteStride", &what)?.unwrap_or(element);
        if stride < element {
            return Err(format!(
                "{what}: a byteStride of {stride} is less than an element's {element} bytes"
            ));
        }
        let bytes = bytes.get(offset..).ok_or_else(|| {
            format!("an accessor's byteOffset {offset} is past the end of {what}")
        })?;
        Ok((bytes, stride))
    }
}

/// A node's own placement: its matrix, or translation · rotation · scale.
fn local_matrix(node: &Value, n: usize) -> Result<Matrix4<f64>, String> {
    let what = format!("node {n}");
    if let Some(m) = numbers::<16>(node, "matrix", &what)? {
        return Ok(Matrix4::from_column_slice(&m));
    }
    let t = numbers::<3>(node, "translation", &what)?.unwrap_or([0.0; 3]);
    let [x, y, z, w] = numbers::<4>(node, "rotation", &what)?.unwrap_or([0.0, 0.0, 0.0, 1.0]);
    let s = numbers::<3>(node, "scale", &what)?.unwrap_or([1.0; 3]);
    let q = Quaternion::new(w, x, y, z);
    if q.norm() == 0.0 {
        return Err(format!("{what}: the rotation quaternion is zero"));
    }
    let rotation = UnitQuaternion::from_quaternion(q).to_rotation_matrix();
    let linear = rotation.matrix() * Matrix3::from_diagonal(&Vector3::from(s));
    let mut m = linear.to_homogeneous();
    m.fixed_view_mut::<3, 1>(0, 3).copy_from(&Vector3::from(t));
    Ok(m)
}

/// The triangles of a primitive of mode 4 (list), 5 (strip) or 6 (fan), as corners' positions
/// in `corners`. A strip's triangles alternate winding so that all face the same way, and those
/// that repeat a corner (how strips are joined) are left out: they have no area.
fn triangles(mode: usize, corners: &[usize]) -> Vec<[usize; 3]> {
    match mode {
        4 => corners
            .chunks_exact(3)
            .map(|t| [t[0], t[1], t[2]])
            .collect(),
        5 => (0..corners.len().saturating_sub(2))
            .map(|i| {
                let t = [corners[i], corners[i + 1], corners[i + 2]];
                if i % 2 == 0 { t } else { [t[1], t[0], t[2]] }
            })
            .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
            .collect(),
        _ => (1..corners.len().saturating_sub(1))
            .map(|i| [corners[i], corners[i + 1], corners[0]])
            .collect(),
    }
}

/// An accessor's component type: its size and how to read one.
#[derive(Clone, Copy)]
struct Component {
    code: u64,
    size: usize,
}

fn component_type(accessor: &Value, what: &str) -> Result<Component, String> {
    let code = accessor
        .get("componentType")
        .and_then(Value::as_u64)
        .ok_or_else(|| format!("{what} has no \"componentType\""))?;
    let size = match code {
        5120 | 5121 => 1,
        5122 | 5123 => 2,
        5125 | 5126 => 4,
        _ => return Err(format!("{what}: componentType {code} is not a glTF type")),
    };
    Ok(Component { code, size })
}

impl Component {
    /// The component at the start of `bytes` (little-endian), as stored.
    fn read(self, bytes: &[u8]) -> f64 {
        let b = |k: usize| bytes[k];
        match self.code {
            5120 => f64::from(b(0) as i8),
            5121 => f64::from(b(0)),
            5122 => f64::from(i16::from_le_bytes([b(0), b(1)])),
            5123 => f64::from(u16::from_le_bytes([b(0), b(1)])),
            5125 => f64::from(u32::from_le_bytes([b(0), b(1), b(2), b(3)])),
            _ => f64::from(f32::from_le_bytes([b(0), b(1), b(2), b(3)])),
        }
    }

    /// A normalized integer as the number it stands for (glTF 2.0, section 3.11).
    fn normalize(self, c: f64) -> f64 {
        match self.code {
            5120 => (c / 127.0).max(-1.0),
            5121 => c / 255.0,
            5122 => (c / 32767.0).max(-1.0),
            5123 => c / 65535.0,
            _ => c,
        }
    }
}

/// A URI's `%XX` escapes decoded (`my%20mesh.bin` is the file `my mesh.bin`).
fn percent_decoded(uri: &str) -> String {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = bytes
            .get(i + 1..i + 3)
            .and_then(|h| std::str::from_utf8(h).ok())
            .and_then(|h| u8::from_str_radix(h, 16).ok());
        match (bytes[i], hex) {
            (b'%', Some(h)) => {
                out.push(h);
                i += 3;
            }
            (c, _) => {
                out.push(c);
                i += 1;
            }
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Standard base64 (RFC 4648, section 4) decoded; padding optional, whitespace refused.
fn base64(text: &str) -> Result<Vec<u8>, String> {
    let digit = |c: u8| -> Result<u32, String> {
        Ok(match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return Err(format!("{:?} is not a base64 digit", c as char)),
        }
        .into())
    };
    let text = text.trim_end_matches('=').as_bytes();
    let mut out = Vec::with_capacity(text.len() * 3 / 4);
    for group in text.chunks(4) {
        let mut bits = 0u32;
        for (k, &c) in group.iter().enumerate() {
            bits |= digit(c)? << (18 - 6 * k);
        }
        let bytes = bits.to_be_bytes();
        match group.len() {
            4 => out.extend_from_slice(&bytes[1..4]),
            3 => out.extend_from_slice(&bytes[1..3]),
            2 => out.push(bytes[1]),
            _ => return Err("base64 text cut one digit short".to_owned()),
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests;
