//! 3D Manufacturing Format (`.3mf`, the 3MF Consortium's core specification 1.3): a ZIP package
//! whose relationships (`_rels/.rels`) name the model part, an XML file of `<object>`s (a
//! `<mesh>` of vertices and triangles, or `<components>` that place other objects) and a
//! `<build>` of items to make. Every build item is one part (named after its object), with its
//! objects' components followed recursively, each `transform` composed in f64. A transform is
//! twelve numbers, a 3 × 4 matrix applied to points as row vectors (`p' = p · M`, section 3.3).
//! The root model's `unit` (micron to foot; millimetre when absent) is converted to metres, so
//! results are in metres. A placement that mirrors turns its triangles' winding. Components in other
//! model parts of the package (the production extension's `p:path`) are followed; a build item
//! of another part, or anything else the reader cannot follow, is refused by name.

use std::collections::HashMap;
use std::path::Path;

use nalgebra::{Matrix3, Matrix4, Point3, Vector3};
use roxmltree::Node;

use super::MeshFile;
use super::zip::Archive;
use crate::MeshError;

/// What a 3MF package starts with: a ZIP local file header.
pub(super) const ZIP_MAGIC: &[u8] = b"PK\x03\x04";

/// The production extension's namespace, whose `path` attribute names another model part.
const PRODUCTION: &str = "http://schemas.microsoft.com/3dmanufacturing/production/2015/06";

/// How many objects a build may place, all components counted: more than any real print, few
/// enough that components within components cannot multiply without end.
const MAX_PLACEMENTS: usize = 1 << 20;

/// Reads a 3MF package already in memory; `path` names it in messages.
///
/// # Errors
/// The package is not a ZIP archive or is damaged, has no 3D model part, the model is not XML or
/// does not follow the specification (the message names the part, the element and its line),
/// a reference names no object, or the build has no triangles.
pub fn parse_3mf(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let bad = |message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line: None,
        message,
    };
    let archive = Archive::new(bytes).map_err(bad)?;
    let root_part = model_part(&archive).map_err(bad)?;
    let mut package = Package {
        archive: &archive,
        texts: HashMap::new(),
    };
    let mut placed = Placed::default();
    package
        .place_build(&root_part, &mut placed)
        .map_err(|(line, message)| MeshError::Malformed {
            path: path.to_path_buf(),
            line,
            message,
        })?;
    if placed.triangles.is_empty() {
        return Err(bad(
            "the build has no triangles, so it encloses no volume".to_owned()
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
        face_lines: placed.face_lines,
        warnings: Vec::new(),
        part_names: placed.part_names,
        face_parts: placed.face_parts,
    })
}

/// The package's 3D model part: the target of the root relationship of the 3D model type, else
/// the usual `3D/3dmodel.model`.
fn model_part(archive: &Archive) -> Result<String, String> {
    const MODEL_TYPE: &str = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";
    if let Some(rels) = archive.read("_rels/.rels") {
        let rels = rels?;
        let text = std::str::from_utf8(&rels).map_err(|e| format!("_rels/.rels: {e}"))?;
        let document =
            roxmltree::Document::parse(text).map_err(|e| format!("_rels/.rels: not XML: {e}"))?;
        if let Some(target) = document
            .descendants()
            .filter(|n| n.tag_name().name() == "Relationship")
            .find(|n| n.attribute("Type") == Some(MODEL_TYPE))
            .and_then(|n| n.attribute("Target"))
        {
            return Ok(target.trim_start_matches('/').to_owned());
        }
    }
    Ok("3D/3dmodel.model".to_owned())
}

/// Triangles placed so far, with their parts and source lines.
#[derive(Default)]
struct Placed {
    positions: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
    face_lines: Vec<u32>,
    part_names: Vec<String>,
    face_parts: Vec<u32>,
}

/// An error: the line of the model part it is about, if known, and what is wrong.
type Failure = (Option<usize>, String);

/// The package with the model parts read so far (their text), by name.
struct Package<'a> {
    archive: &'a Archive<'a>,
    texts: HashMap<String, String>,
}

/// A model part's unit, in metres (section 3.4.1).
fn metres_per(unit: &str) -> Option<f64> {
    Some(match unit {
        "micron" => 1e-6,
        "millimeter" => 1e-3,
        "centimeter" => 1e-2,
        "inch" => 0.0254,
        "foot" => 0.3048,
        "meter" => 1.0,
        _ => return None,
    })
}

/// The placement a `transform` attribute gives (identity when absent).
fn transform(node: Node, part: &str) -> Result<Matrix4<f64>, Failure> {
    let Some(text) = node.attribute("transform") else {
        return Ok(Matrix4::identity());
    };
    let m: Vec<f64> = text
        .split_ascii_whitespace()
        .map(str::parse)
        .collect::<Result<_, _>>()
        .unwrap_or_default();
    if m.len() != 12 || m.iter().any(|x: &f64| !x.is_finite()) {
        return Err((
            Some(line(node)),
            format!("{part}: transform=\"{text}\" is not twelve finite numbers"),
        ));
    }
    // p' = [x y z 1] · M with M's rows (m00 m01 m02) … (m30 m31 m32): as a column-vector map,
    // the transposed 3 × 3 block and the last row as the offset.
    Ok(Matrix4::new(
        m[0], m[3], m[6], m[9], m[1], m[4], m[7], m[10], m[2], m[5], m[8], m[11], 0.0, 0.0, 0.0,
        1.0,
    ))
}

fn line(node: Node) -> usize {
    node.document().text_pos_at(node.range().start).row as usize
}

impl Package<'_> {
    /// The text of model part `part`, read once.
    fn text(&mut self, part: &str) -> Result<(), Failure> {
        if self.texts.contains_key(part) {
            return Ok(());
        }
        let bytes = self
            .archive
            .read(part)
            .ok_or_else(|| (None, format!("the package has no model part {part}")))?
            .map_err(|e| (None, e))?;
        let text =
            String::from_utf8(bytes).map_err(|e| (None, format!("{part}: not UTF-8 text: {e}")))?;
        self.texts.insert(part.to_owned(), text);
        Ok(())
    }

    /// Places the build of the root model part: each item one part.
    fn place_build(&mut self, root: &str, placed: &mut Placed) -> Result<(), Failure> {
        self.text(root)?;
        // Every part the build can reach is read first, so that the documents below can borrow
        // all the texts at once.
        let mut pending = vec![root.to_owned()];
        while let Some(part) = pending.pop() {
            self.text(&part)?;
            let document = roxmltree::Document::parse(&self.texts[&part])
                .map_err(|e| (Some(e.pos().row as usize), format!("{part}: not XML: {e}")))?;
            for node in document.descendants() {
                if let Some(other) = node.attribute((PRODUCTION, "path")) {
                    let other = other.trim_start_matches('/').to_owned();
                    if !self.texts.contains_key(&other) && !pending.contains(&other) {
                        pending.push(other);
                    }
                }
            }
        }
        let mut models = HashMap::new();
        for (part, text) in &self.texts {
            let document = roxmltree::Document::parse(text)
                .map_err(|e| (Some(e.pos().row as usize), format!("{part}: not XML: {e}")))?;
            models.insert(part.clone(), document);
        }
        let models = Models { models: &models };
        let model = models.models[root].root_element();
        if model.tag_name().name() != "model" {
            return Err((
                Some(line(model)),
                format!(
                    "{root}: the root element is <{}>, not <model>",
                    model.tag_name().name()
                ),
            ));
        }
        let build = model
            .children()
            .find(|c| c.tag_name().name() == "build")
            .ok_or_else(|| (None, format!("{root}: the model has no <build>")))?;
        // Every model part is taken in the root model's unit: the whole build is scaled to
        // metres once.
        let unit = model.attribute("unit").unwrap_or("millimeter");
        let units = Matrix4::new_scaling(metres_per(unit).ok_or_else(|| {
            (
                Some(line(model)),
                format!("{root}: unit=\"{unit}\" is not one of 3MF's units"),
            )
        })?);
        let mut budget = MAX_PLACEMENTS;
        for item in build.children().filter(|c| c.tag_name().name() == "item") {
            if item
                .attribute((PRODUCTION, "path"))
                .is_some_and(|p| p.trim_start_matches('/') != root)
            {
                return Err((
                    Some(line(item)),
                    format!("{root}: a build item of another model part is not followed"),
                ));
            }
            let placement = transform(item, root)?;
            let object = models.object(root, item)?;
            let name = object.attribute("name").map_or_else(
                || format!("object {}", object.attribute("id").unwrap_or("?")),
                str::to_owned,
            );
            let part = placed.part_names.len() as u32;
            placed
                .part_names
                .push(super::unique_name(name, &placed.part_names));
            models.place_object(
                object,
                &(units * placement),
                part,
                &mut Vec::new(),
                &mut budget,
                placed,
            )?;
        }
        Ok(())
    }
}

/// Every model part of the package, parsed.
struct Models<'d, 'i> {
    models: &'d HashMap<String, roxmltree::Document<'i>>,
}

impl<'d, 'i> Models<'d, 'i> {
    /// The object a build item or component names (`objectid`, in its own part or `p:path`'s).
    fn object(&self, part: &str, reference: Node<'d, 'i>) -> Result<Node<'d, 'i>, Failure> {
        let id = reference.attribute("objectid").ok_or_else(|| {
            (
                Some(line(reference)),
                format!("{part}: <{}> has no objectid", reference.tag_name().name()),
            )
        })?;
        let target = reference
            .attribute((PRODUCTION, "path"))
            .map_or(part, |p| p.trim_start_matches('/'));
        self.models[target]
            .descendants()
            .find(|n| n.tag_name().name() == "object" && n.attribute("id") == Some(id))
            .ok_or_else(|| {
                (
                    Some(line(reference)),
                    format!("{part}: objectid {id} names no object of {target}"),
                )
            })
    }

    /// The part (file name) an object's document is.
    fn part_of(&self, object: Node) -> &'d str {
        self.models
            .iter()
            .find(|(_, d)| std::ptr::eq(*d, object.document()))
            .map_or("", |(name, _)| name.as_str())
    }

    /// Places an object (its mesh, or its components) under `placement` in the build part
    /// `part`; `path` holds the objects it is within, so that one that contains itself is refused.
    fn place_object(
        &self,
        object: Node<'d, 'i>,
        placement: &Matrix4<f64>,
        part: u32,
        path: &mut Vec<Node<'d, 'i>>,
        budget: &mut usize,
        placed: &mut Placed,
    ) -> Result<(), Failure> {
        let file = self.part_of(object);
        if path.contains(&object) {
            return Err((
                Some(line(object)),
                format!(
                    "{file}: object {} contains itself",
                    object.attribute("id").unwrap_or("?")
                ),
            ));
        }
        *budget = budget.checked_sub(1).ok_or_else(|| {
            (
                None,
                format!("the build places more than {MAX_PLACEMENTS} objects"),
            )
        })?;
        path.push(object);
        for content in object.children().filter(Node::is_element) {
            match content.tag_name().name() {
                "mesh" => self.place_mesh(file, content, placement, part, placed)?,
                "components" => {
                    for component in content
                        .children()
                        .filter(|c| c.tag_name().name() == "component")
                    {
                        let inner = self.object(file, component)?;
                        let local = transform(component, file)?;
                        self.place_object(inner, &(placement * local), part, path, budget, placed)?;
                    }
                }
                _ => {}
            }
        }
        path.pop();
        Ok(())
    }

    /// A `<mesh>`'s triangles, placed by `placement`.
    fn place_mesh(
        &self,
        file: &str,
        mesh: Node<'d, 'i>,
        placement: &Matrix4<f64>,
        part: u32,
        placed: &mut Placed,
    ) -> Result<(), Failure> {
        let linear: Matrix3<f64> = placement.fixed_view::<3, 3>(0, 0).into_owned();
        let offset: Vector3<f64> = placement.fixed_view::<3, 1>(0, 3).into_owned();
        let mirrored = linear.determinant() < 0.0;
        let first = placed.positions.len();
        let element = |name: &str| mesh.children().find(|c| c.tag_name().name() == name);
        let coordinate = |v: Node, key: &str| -> Result<f64, Failure> {
            v.attribute(key)
                .and_then(|x| x.trim().parse::<f64>().ok())
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    (
                        Some(line(v)),
                        format!("{file}: a <vertex> needs a finite {key}"),
                    )
                })
        };
        if let Some(vertices) = element("vertices") {
            for v in vertices
                .children()
                .filter(|c| c.tag_name().name() == "vertex")
            {
                let p = Vector3::new(
                    coordinate(v, "x")?,
                    coordinate(v, "y")?,
                    coordinate(v, "z")?,
                );
                placed.positions.push(Point3::from(linear * p + offset));
            }
        }
        let count = placed.positions.len() - first;
        if let Some(triangles) = element("triangles") {
            for t in triangles
                .children()
                .filter(|c| c.tag_name().name() == "triangle")
            {
                let mut corners = [0u32; 3];
                for (c, key) in corners.iter_mut().zip(["v1", "v2", "v3"]) {
                    let i = t
                        .attribute(key)
                        .and_then(|i| i.trim().parse::<usize>().ok())
                        .filter(|&i| i < count)
                        .ok_or_else(|| {
                            (
                                Some(line(t)),
                                format!(
                                    "{file}: a <triangle>'s {key} is not one of the mesh's {count} vertices"
                                ),
                            )
                        })?;
                    *c = (first + i) as u32;
                }
                if mirrored {
                    corners.swap(1, 2);
                }
                placed.triangles.push(corners);
                placed.face_lines.push(line(t) as u32);
                placed.face_parts.push(part);
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
