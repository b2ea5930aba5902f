//! COLLADA 1.4 and 1.5 (`.dae`, Khronos; ROS's mesh format): the scene's node tree is walked,
//! each node's `<matrix>`, `<translate>`, `<rotate>` and `<scale>` composed in document order in
//! f64 with its parents', `<instance_node>` followed (a node may be instanced many times), and
//! every `<instance_geometry>` placed as one part, named after its node. A geometry's
//! `<triangles>`, `<polylist>`, `<polygons>`, `<tristrips>` and `<trifans>` make faces, each
//! corner's position found through the `VERTEX` input at its own offset among the primitive's
//! index streams; lines carry no volume and are passed over. Coordinates are read as decimal text
//! straight into f64. A mirroring placement (negative determinant) turns its faces' winding.
//!
//! Units: `<asset><unit meter>` is applied, so results are in metres, as Gazebo, rviz and
//! MoveIt's `geometric_shapes` apply it to a URDF's meshes. `<up_axis>` is not applied: rviz
//! and `geometric_shapes` drop the rotation that assimp makes of it, so a robot's DAE mesh is
//! used in its own axes; the reader reports the axis ([`ColladaFile::up_axis`]) and warns
//! (`up_axis_not_applied`) when it is not Z_UP. Reference: COLLADA 1.4.1 specification (Khronos, 2008),
//! chapters 5 (`node`, transforms, `mesh`) and 8.

use std::collections::HashMap;
use std::path::Path;

use nalgebra::{Matrix3, Matrix4, Point3, Rotation3, Unit, Vector3};
use roxmltree::Node;

use super::MeshFile;
use crate::MeshError;

/// A COLLADA file's mesh and what its `<asset>` says of its axes.
#[derive(Debug, Clone, PartialEq)]
pub struct ColladaFile {
    /// The mesh, in metres.
    pub file: MeshFile,
    /// The file's `<up_axis>` ("X_UP", "Y_UP" or "Z_UP"; "Y_UP" when it gives none, as the
    /// specification says), not applied.
    pub up_axis: String,
    /// The file's `<unit meter>`, applied (1 when it gives none).
    pub metres_per_unit: f64,
}

/// Whether `bytes` are a COLLADA document: XML whose first kilobytes hold its `<COLLADA` root.
pub(super) fn is_collada(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(4096)];
    head.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'<')
        && head.windows(8).any(|w| w == b"<COLLADA")
}

/// Reads a COLLADA file already in memory as one mesh (see [`parse_collada_file`] for its axis).
///
/// # Errors
/// As [`parse_collada_file`].
pub fn parse_collada(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    parse_collada_file(bytes, path).map(|c| c.file)
}

/// Reads a COLLADA file already in memory; `path` names it in messages.
///
/// # Errors
/// The file is not XML or not COLLADA, an element does not follow the specification (the
/// message names it, with its `id` and line), a reference names nothing, a transform is one this
/// reader does not follow (`<lookat>`, `<skew>`), or the scene has no faces.
pub fn parse_collada_file(bytes: &[u8], path: &Path) -> Result<ColladaFile, MeshError> {
    let bad = |line: Option<usize>, message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line,
        message,
    };
    let text = std::str::from_utf8(bytes).map_err(|e| bad(None, format!("not UTF-8 text: {e}")))?;
    let document = roxmltree::Document::parse(text)
        .map_err(|e| bad(Some(e.pos().row as usize), format!("not XML: {e}")))?;
    let root = document.root_element();
    if root.tag_name().name() != "COLLADA" {
        return Err(bad(
            None,
            format!(
                "not a COLLADA file: its root element is <{}>",
                root.tag_name().name()
            ),
        ));
    }
    let line = |node: Node| document.text_pos_at(node.range().start).row as usize;
    let reader = Reader::new(&document);
    let asset = child(root, "asset");
    let metres_per_unit = match asset
        .and_then(|a| child(a, "unit"))
        .and_then(|u| u.attribute("meter").map(|m| (u, m)))
    {
        None => 1.0,
        Some((unit, m)) => m
            .trim()
            .parse::<f64>()
            .ok()
            .filter(|m| m.is_finite() && *m > 0.0)
            .ok_or_else(|| {
                bad(
                    Some(line(unit)),
                    format!("<unit meter=\"{m}\">: not a positive number"),
                )
            })?,
    };
    let up_axis = asset
        .and_then(|a| child(a, "up_axis"))
        .and_then(|u| u.text())
        .map_or("Y_UP", str::trim)
        .to_owned();
    let mut placed = Placed::default();
    reader
        .place_scene(root, metres_per_unit, &mut placed)
        .map_err(|(node, message)| bad(node.map(line), message))?;
    if placed.faces.is_empty() {
        return Err(bad(
            None,
            "the scene has no faces (only lines, or no geometry), so it encloses no volume"
                .to_owned(),
        ));
    }
    let arities: Vec<usize> = placed.faces.iter().map(Vec::len).collect();
    let corners = placed.faces.iter().flatten().map(|&i| i as usize);
    let mesh = super::welded_mesh(path, &placed.positions, corners, &arities)?;
    let warnings = if up_axis == "Z_UP" {
        Vec::new()
    } else {
        vec![crate::Warning {
            defect: crate::Defect::UpAxisNotApplied {
                axis: up_axis.clone(),
            },
            count: 1,
            faces: Vec::new(),
            effect_on_mass: None,
        }]
    };
    Ok(ColladaFile {
        file: MeshFile {
            mesh,
            face_lines: placed.face_lines,
            warnings,
            part_names: placed.part_names,
            face_parts: placed.face_parts,
        },
        up_axis,
        metres_per_unit,
    })
}

/// An error: the element it is about, if one, and what is wrong.
type Failure<'a, 'i> = (Option<Node<'a, 'i>>, String);

/// Faces placed so far, with their parts and source lines.
#[derive(Default)]
struct Placed {
    positions: Vec<Point3<f64>>,
    faces: Vec<Vec<u32>>,
    face_lines: Vec<u32>,
    part_names: Vec<String>,
    face_parts: Vec<u32>,
}

/// How many geometries a scene may place, all instances counted: far more than any real file,
/// few enough that nodes instanced within nodes cannot multiply without end.
const MAX_PLACEMENTS: usize = 1 << 20;

/// The document, with its elements by `id`.
struct Reader<'a, 'i> {
    by_id: HashMap<&'a str, Node<'a, 'i>>,
}

/// The first child element named `name`.
fn child<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    children(node, name).next()
}

/// The child elements named `name`.
fn children<'a: 'n, 'i: 'a, 'n>(
    node: Node<'a, 'i>,
    name: &'n str,
) -> impl Iterator<Item = Node<'a, 'i>> + 'n {
    node.children()
        .filter(move |c| c.is_element() && c.tag_name().name() == name)
}

/// How an element is named in messages: `<node id="arm">`.
fn named(node: Node) -> String {
    match node.attribute("id").or_else(|| node.attribute("name")) {
        Some(id) => format!("<{} id=\"{id}\">", node.tag_name().name()),
        None => format!("<{}>", node.tag_name().name()),
    }
}

/// The numbers of an element's text.
fn numbers<'a, 'i, T: std::str::FromStr>(node: Node<'a, 'i>) -> Result<Vec<T>, Failure<'a, 'i>> {
    node.text()
        .unwrap_or_default()
        .split_ascii_whitespace()
        .map(|w| {
            w.parse().map_err(|_| {
                (
                    Some(node),
                    format!("{}: {w:?} is not a number", named(node)),
                )
            })
        })
        .collect()
}

impl<'a, 'i> Reader<'a, 'i> {
    fn new(document: &'a roxmltree::Document<'i>) -> Self {
        let by_id = document
            .descendants()
            .filter_map(|n| n.attribute("id").map(|id| (id, n)))
            .collect();
        Self { by_id }
    }

    /// The element a `url="#id"` (or `source="#id"`) attribute of `node` names.
    fn target(&self, node: Node<'a, 'i>, attribute: &str) -> Result<Node<'a, 'i>, Failure<'a, 'i>> {
        let url = node.attribute(attribute).unwrap_or_default();
        url.strip_prefix('#')
            .and_then(|id| self.by_id.get(id).copied())
            .ok_or_else(|| {
                (
                    Some(node),
                    format!(
                        "{}: {attribute}=\"{url}\" names no element of this file",
                        named(node)
                    ),
                )
            })
    }

    /// Places the scene's geometry: the `<scene>`'s visual scene, else the first, else every
    /// geometry of the file where it stands.
    fn place_scene(
        &self,
        root: Node<'a, 'i>,
        metres_per_unit: f64,
        placed: &mut Placed,
    ) -> Result<(), Failure<'a, 'i>> {
        let units = Matrix4::new_scaling(metres_per_unit);
        let instance = child(root, "scene").and_then(|s| child(s, "instance_visual_scene"));
        let scene = match instance {
            Some(i) => Some(self.target(i, "url")?),
            None => root
                .descendants()
                .find(|n| n.tag_name().name() == "visual_scene"),
        };
        let mut budget = MAX_PLACEMENTS;
        match scene {
            Some(scene) => {
                for node in children(scene, "node") {
                    self.place_node(node, &units, &mut Vec::new(), &mut budget, placed)?;
                }
            }
            None => {
                for geometry in root
                    .descendants()
                    .filter(|n| n.tag_name().name() == "geometry")
                {
                    self.place_geometry(geometry, geometry, &units, placed)?;
                }
            }
        }
        Ok(())
    }

    /// Places a node and what it holds, under `parent`; `path` holds the nodes it is within,
    /// so that a node that instances itself is refused rather than followed for ever.
    fn place_node(
        &self,
        node: Node<'a, 'i>,
        parent: &Matrix4<f64>,
        path: &mut Vec<Node<'a, 'i>>,
        budget: &mut usize,
        placed: &mut Placed,
    ) -> Result<(), Failure<'a, 'i>> {
        if path.contains(&node) {
            return Err((Some(node), format!("{} instances itself", named(node))));
        }
        path.push(node);
        let mut placement = *parent;
        for element in node.children().filter(Node::is_element) {
            let local = match element.tag_name().name() {
                "matrix" => {
                    let m: Vec<f64> = self.finite(element, 16)?;
                    Matrix4::from_row_slice(&m)
                }
                "translate" => {
                    let t: Vec<f64> = self.finite(element, 3)?;
                    Matrix4::new_translation(&Vector3::new(t[0], t[1], t[2]))
                }
                "scale" => {
                    let s: Vec<f64> = self.finite(element, 3)?;
                    Matrix4::new_nonuniform_scaling(&Vector3::new(s[0], s[1], s[2]))
                }
                "rotate" => {
                    let r: Vec<f64> = self.finite(element, 4)?;
                    let axis = Vector3::new(r[0], r[1], r[2]);
                    if axis.norm() == 0.0 {
                        Matrix4::identity()
                    } else {
                        Rotation3::from_axis_angle(&Unit::new_normalize(axis), r[3].to_radians())
                            .to_homogeneous()
                    }
                }
                "lookat" | "skew" => {
                    return Err((
                        Some(element),
                        format!(
                            "{}: a <{}> transform is not read",
                            named(node),
                            element.tag_name().name()
                        ),
                    ));
                }
                _ => continue,
            };
            placement *= local;
        }
        for element in node.children().filter(Node::is_element) {
            match element.tag_name().name() {
                "instance_geometry" => {
                    *budget = budget.checked_sub(1).ok_or_else(|| {
                        (
                            Some(element),
                            format!("the scene places more than {MAX_PLACEMENTS} geometries"),
                        )
                    })?;
                    let geometry = self.target(element, "url")?;
                    self.place_geometry(geometry, node, &placement, placed)?;
                }
                "node" => self.place_node(element, &placement, path, budget, placed)?,
                "instance_node" => {
                    let target = self.target(element, "url")?;
                    self.place_node(target, &placement, path, budget, placed)?;
                }
                _ => {}
            }
        }
        path.pop();
        Ok(())
    }

    /// `n` finite numbers from an element's text.
    fn finite(&self, element: Node<'a, 'i>, n: usize) -> Result<Vec<f64>, Failure<'a, 'i>> {
        let values: Vec<f64> = numbers(element)?;
        if values.len() != n || values.iter().any(|v| !v.is_finite()) {
            return Err((
                Some(element),
                format!("{} needs {n} finite numbers", named(element)),
            ));
        }
        Ok(values)
    }

    /// A geometry's faces, placed, as one part named after `owner` (its node, or itself).
    fn place_geometry(
        &self,
        geometry: Node<'a, 'i>,
        owner: Node<'a, 'i>,
        placement: &Matrix4<f64>,
        placed: &mut Placed,
    ) -> Result<(), Failure<'a, 'i>> {
        let Some(mesh) = child(geometry, "mesh") else {
            // A <spline> or <convex_mesh> (by reference): no faces of its own to place.
            return Ok(());
        };
        let linear: Matrix3<f64> = placement.fixed_view::<3, 3>(0, 0).into_owned();
        let offset: Vector3<f64> = placement.fixed_view::<3, 1>(0, 3).into_owned();
        let mirrored = linear.determinant() < 0.0;
        let name = [owner, geometry]
            .iter()
            .find_map(|n| n.attribute("name").or_else(|| n.attribute("id")))
            .unwrap_or("geometry")
            .to_owned();
        let part = placed.part_names.len() as u32;
        placed
            .part_names
            .push(super::unique_name(name, &placed.part_names));
        let mut positions_of: HashMap<roxmltree::NodeId, usize> = HashMap::new();
        for primitive in mesh.children().filter(Node::is_element) {
            let kind = primitive.tag_name().name();
            if !matches!(
                kind,
                "triangles" | "polylist" | "polygons" | "tristrips" | "trifans"
            ) {
                continue;
            }
            let (vertex_offset, stride, source) = self.vertex_input(primitive)?;
            let first = match positions_of.get(&source.id()) {
                Some(&first) => first,
                None => {
                    let first = placed.positions.len();
                    let coordinates = self.positions(source)?;
                    placed.positions.extend(
                        coordinates
                            .iter()
                            .map(|p| Point3::from(linear * p.coords + offset)),
                    );
                    positions_of.insert(source.id(), first);
                    first
                }
            };
            let count = placed.positions.len() - first;
            let line = primitive
                .document()
                .text_pos_at(primitive.range().start)
                .row;
            let faces = self.faces(primitive, vertex_offset, stride)?;
            for face in faces {
                let mut corners = Vec::with_capacity(face.len());
                for i in face {
                    if i >= count {
                        return Err((
                            Some(primitive),
                            format!(
                                "{}: a corner names position {i}, but {} has {count}",
                                named(primitive),
                                named(source)
                            ),
                        ));
                    }
                    corners.push((first + i) as u32);
                }
                if mirrored {
                    corners.reverse();
                }
                placed.faces.push(corners);
                placed.face_lines.push(line);
                placed.face_parts.push(part);
            }
        }
        Ok(())
    }

    /// A primitive's `VERTEX` input: its offset, how many indices make one corner (the largest
    /// offset of its inputs, plus one), and the `<source>` of its positions.
    fn vertex_input(
        &self,
        primitive: Node<'a, 'i>,
    ) -> Result<(usize, usize, Node<'a, 'i>), Failure<'a, 'i>> {
        let mut stride = 0;
        let mut vertex = None;
        for input in children(primitive, "input") {
            let offset: usize = input
                .attribute("offset")
                .unwrap_or("0")
                .parse()
                .map_err(|_| {
                    (
                        Some(input),
                        format!("{}: an offset that is not a whole number", named(primitive)),
                    )
                })?;
            stride = stride.max(offset + 1);
            if input.attribute("semantic") == Some("VERTEX") {
                vertex = Some((offset, input));
            }
        }
        let (offset, input) = vertex.ok_or_else(|| {
            (
                Some(primitive),
                format!("{} has no VERTEX input", named(primitive)),
            )
        })?;
        let vertices = self.target(input, "source")?;
        let position = children(vertices, "input")
            .find(|i| i.attribute("semantic") == Some("POSITION"))
            .ok_or_else(|| {
                (
                    Some(vertices),
                    format!("{} has no POSITION input", named(vertices)),
                )
            })?;
        Ok((offset, stride, self.target(position, "source")?))
    }

    /// A `<source>`'s points, by its accessor's count, stride and offset (the first three
    /// values of each element are x, y and z).
    fn positions(&self, source: Node<'a, 'i>) -> Result<Vec<Point3<f64>>, Failure<'a, 'i>> {
        let accessor = child(source, "technique_common")
            .and_then(|t| child(t, "accessor"))
            .ok_or_else(|| {
                (
                    Some(source),
                    format!("{} has no <technique_common><accessor>", named(source)),
                )
            })?;
        let array = self.target(accessor, "source")?;
        let values: Vec<f64> = numbers(array)?;
        let whole = |key: &str, default: usize| -> Result<usize, Failure<'a, 'i>> {
            accessor.attribute(key).map_or(Ok(default), |v| {
                v.parse().map_err(|_| {
                    (
                        Some(accessor),
                        format!("{}: {key}=\"{v}\" is not a whole number", named(source)),
                    )
                })
            })
        };
        let (count, stride, start) = (whole("count", 0)?, whole("stride", 1)?, whole("offset", 0)?);
        if stride < 3 {
            return Err((
                Some(accessor),
                format!(
                    "{}: positions need a stride of 3 or more, not {stride}",
                    named(source)
                ),
            ));
        }
        let needed = count.checked_mul(stride).and_then(|n| n.checked_add(start));
        if count > 0 && needed.is_none_or(|n| n - stride + 3 > values.len()) {
            return Err((
                Some(accessor),
                format!(
                    "{}: {count} points every {stride} values from {start} need more than the {} \
                     values of {}",
                    named(source),
                    values.len(),
                    named(array)
                ),
            ));
        }
        let points: Vec<Point3<f64>> = (0..count)
            .map(|k| {
                let at = start + k * stride;
                Point3::new(values[at], values[at + 1], values[at + 2])
            })
            .collect();
        if points.iter().any(|p| p.iter().any(|c| !c.is_finite())) {
            return Err((
                Some(array),
                format!("{} holds a value that is not finite", named(array)),
            ));
        }
        Ok(points)
    }

    /// A primitive's faces as position indices: each corner's index at `offset` of every group
    /// of `stride` indices.
    fn faces(
        &self,
        primitive: Node<'a, 'i>,
        offset: usize,
        stride: usize,
    ) -> Result<Vec<Vec<usize>>, Failure<'a, 'i>> {
        let kind = primitive.tag_name().name();
        let corners_of = |p: Node<'a, 'i>| -> Result<Vec<usize>, Failure<'a, 'i>> {
            let indices: Vec<usize> = numbers(p)?;
            if !indices.len().is_multiple_of(stride) {
                return Err((
                    Some(p),
                    format!(
                        "{}: {} indices are not whole corners of {stride}",
                        named(primitive),
                        indices.len()
                    ),
                ));
            }
            Ok(indices.chunks_exact(stride).map(|c| c[offset]).collect())
        };
        if child(primitive, "ph").is_some() {
            return Err((
                Some(primitive),
                format!(
                    "{}: polygons with holes (<ph>) are not read",
                    named(primitive)
                ),
            ));
        }
        let mut faces = Vec::new();
        match kind {
            "triangles" | "polylist" => {
                let Some(p) = child(primitive, "p") else {
                    return Ok(faces);
                };
                let corners = corners_of(p)?;
                let arities: Vec<usize> = match child(primitive, "vcount") {
                    Some(v) if kind == "polylist" => numbers(v)?,
                    _ => vec![3; corners.len() / 3],
                };
                if arities.iter().sum::<usize>() != corners.len() {
                    return Err((
                        Some(p),
                        format!(
                            "{}: the faces' corner counts add up to {}, but <p> has {} corners",
                            named(primitive),
                            arities.iter().sum::<usize>(),
                            corners.len()
                        ),
                    ));
                }
                let mut at = 0;
                for n in arities {
                    if n >= 3 {
                        faces.push(corners[at..at + n].to_vec());
                    }
                    at += n;
                }
            }
            "polygons" => {
                for p in children(primitive, "p") {
                    let corners = corners_of(p)?;
                    if corners.len() >= 3 {
                        faces.push(corners);
                    }
                }
            }
            "tristrips" => {
                for p in children(primitive, "p") {
                    let c = corners_of(p)?;
                    for i in 0..c.len().saturating_sub(2) {
                        let t = if i % 2 == 0 {
                            [c[i], c[i + 1], c[i + 2]]
                        } else {
                            [c[i + 1], c[i], c[i + 2]]
                        };
                        if t[0] != t[1] && t[1] != t[2] && t[0] != t[2] {
                            faces.push(t.to_vec());
                        }
                    }
                }
            }
            _ => {
                for p in children(primitive, "p") {
                    let c = corners_of(p)?;
                    for i in 1..c.len().saturating_sub(1) {
                        faces.push(vec![c[0], c[i], c[i + 1]]);
                    }
                }
            }
        }
        Ok(faces)
    }
}

#[cfg(test)]
mod tests;
