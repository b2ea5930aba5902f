//! The SDFormat reader (Gazebo's `.sdf`, versions 1.4 to 1.11): a `<model>` (or a `<world>`'s
//! models), its nested and `<include>`d models, their links with `<inertial>` (also
//! `auto="true"`), `<collision>` and `<visual>` geometry, and the frames that place them.
//!
//! SDFormat specification (sdformat.org/spec, and "Pose frame semantics" for 1.7+): values are
//! element text; `<pose>x y z roll pitch yaw</pose>` in radians with R = Rz(yaw)·Ry(pitch)·Rx(roll)
//! as URDF's rpy (`degrees="true"` for degrees; `rotation_format="quat_xyzw"` and seven numbers
//! since 1.9); `relative_to` (1.7+; `frame` in 1.5–1.6) names the frame a pose is written in.
//! Unnamed, a link's, a nested model's and a `<frame>`'s pose is in the model's frame, a joint's
//! in its child link's, a collision's, a visual's and an inertial's in their link's. Names inside
//! a nested model are scoped `outer::inner`. An `<inertial>` without `<mass>` has 1 kg and a
//! missing moment `ixx`/`iyy`/`izz` is 1 kg·m² (libsdformat's defaults). `<inertial auto="true">`
//! (1.11) asks the simulator to compute the inertia from the collisions, each of its own
//! `<density>`, else the inertial's, else 1000 kg/m³, scaled to the `<mass>` where one is
//! written (libsdformat 15.2, `Link::ResolveAutoInertials`).
//! `<include><uri>model://NAME</uri>` is the folder NAME on the resource path
//! (`GZ_SIM_RESOURCE_PATH`, `SDF_PATH`: [`ReadOptions::resource_paths`]) whose `model.config`
//! names the model's file (the newest `<sdf version>`; `model.sdf` without one).

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use nalgebra::{Isometry3, Matrix3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};

use crate::ReadOptions;
use crate::error::RobotError;
use crate::model::{
    AutoInertial, DescriptionFormat, Geometry, GeometryMass, Inertial, Link, Robot, Shape,
    Unsupported,
};
use crate::paths::{model_folders, resolve_mesh};
use crate::urdf::{file_stem, span};
use crate::xml::{self, Element, SourceFile};

/// How deep includes may nest before a file is taken to include itself.
const MAX_INCLUDE_DEPTH: usize = 16;

/// The density of a collision that does not write one (`<density>`'s default), kg/m³.
const DEFAULT_DENSITY: f64 = 1000.0;

/// Builds the robot of a parsed `<sdf>` element.
pub fn read(
    root: &Element,
    sources: Vec<SourceFile>,
    options: &ReadOptions,
) -> Result<Robot, RobotError> {
    let mut reader = Reader {
        sources,
        options,
        frames: HashMap::new(),
        links: Vec::new(),
        joints: Vec::new(),
        unsupported: Vec::new(),
    };
    let dir = folder_of(&reader.sources[0].path);
    reader.frames.insert(
        MODEL_FRAME.to_owned(),
        FrameDef {
            pose: Isometry3::identity(),
            relative_to: None,
        },
    );
    let name = match (root.child("model"), root.child("world")) {
        // One model: its frame is the robot's.
        (Some(model), _) => {
            reader.model_contents(model, "", &dir, 0)?;
            model.get("name").map(str::to_owned)
        }
        // A world: each of its models placed in the world's frame.
        (None, Some(world)) => {
            for c in &world.children {
                match c.name.as_str() {
                    "model" => reader.nested_model(c, "", &dir, 0)?,
                    "include" => reader.include(c, "", &dir, 0)?,
                    _ => {}
                }
            }
            world.get("name").map(str::to_owned)
        }
        (None, None) => return Err(root.wrong("an SDFormat file needs a <model> or a <world>")),
    };
    reader.finish(name)
}

/// The model frame's own name in every scope.
const MODEL_FRAME: &str = "__model__";

/// A frame: its pose in another frame (a scoped name; `None` for the robot's own frame).
struct FrameDef {
    pose: Isometry3<f64>,
    relative_to: Option<String>,
}

/// A pose as written: a rigid motion in a frame (a scoped name).
#[derive(Clone)]
struct Placed {
    pose: Isometry3<f64>,
    relative_to: String,
}

struct LinkDef {
    link: Link,
    key: String,
    /// Each geometry's pose as written, resolved into the link's frame at the end.
    collision: Vec<Placed>,
    visual: Vec<Placed>,
    inertial: Option<Placed>,
}

struct JointDef {
    parent: Option<String>,
    child: String,
    moving: bool,
    element: Element,
}

struct Reader<'a> {
    sources: Vec<SourceFile>,
    options: &'a ReadOptions,
    frames: HashMap<String, FrameDef>,
    links: Vec<LinkDef>,
    joints: Vec<JointDef>,
    unsupported: Vec<Unsupported>,
}

/// `name` scoped in `scope`.
fn scoped(scope: &str, name: &str) -> String {
    if scope.is_empty() {
        name.to_owned()
    } else {
        format!("{scope}::{name}")
    }
}

fn folder_of(path: &Path) -> PathBuf {
    path.parent().map(Path::to_owned).unwrap_or_default()
}

impl Reader<'_> {
    /// The key of frame `name` as written in `scope` (`world` is the robot's frame).
    fn frame_key(&self, scope: &str, name: &str) -> String {
        match name {
            "" | MODEL_FRAME => scoped(scope, MODEL_FRAME),
            "world" => MODEL_FRAME.to_owned(),
            _ => scoped(scope, name),
        }
    }

    /// A child `<pose>` of `e`: the rigid motion and the frame it is in (`default` if it names
    /// none).
    fn placed(&self, e: &Element, scope: &str, default: &str) -> Result<Placed, RobotError> {
        let Some(p) = e.child("pose") else {
            return Ok(Placed {
                pose: Isometry3::identity(),
                relative_to: default.to_owned(),
            });
        };
        let relative_to = p
            .get("relative_to")
            .or_else(|| p.get("frame"))
            .filter(|r| !r.is_empty())
            .map_or_else(|| default.to_owned(), |r| self.frame_key(scope, r));
        Ok(Placed {
            pose: pose(p)?,
            relative_to,
        })
    }

    fn add_frame(&mut self, e: &Element, key: String, placed: Placed) -> Result<(), RobotError> {
        if self.frames.contains_key(&key) {
            return Err(e.wrong(format!(
                "a second <{}> (or other frame) named \"{key}\"",
                e.name
            )));
        }
        self.frames.insert(
            key,
            FrameDef {
                pose: placed.pose,
                relative_to: Some(placed.relative_to),
            },
        );
        Ok(())
    }

    /// A nested `<model>` of the model at `scope`.
    fn nested_model(
        &mut self,
        e: &Element,
        scope: &str,
        dir: &Path,
        depth: usize,
    ) -> Result<(), RobotError> {
        let name = e
            .get("name")
            .ok_or_else(|| e.wrong("a model needs a name"))?;
        let placed = self.placed(e, scope, &scoped(scope, MODEL_FRAME))?;
        self.place_model(e, scope, name, placed)?;
        self.model_contents(e, &scoped(scope, name), dir, depth)
    }

    /// Registers model `name` of `scope` placed at `placed`, and its name as a frame.
    fn place_model(
        &mut self,
        e: &Element,
        scope: &str,
        name: &str,
        placed: Placed,
    ) -> Result<(), RobotError> {
        let inner = scoped(scope, name);
        if self.frames.contains_key(&inner) {
            return Err(e.wrong(format!("a second model (or frame) named \"{inner}\"")));
        }
        self.add_frame(e, scoped(&inner, MODEL_FRAME), placed)?;
        self.add_frame(
            e,
            inner.clone(),
            Placed {
                pose: Isometry3::identity(),
                relative_to: scoped(&inner, MODEL_FRAME),
            },
        )
    }

    /// The links, joints, frames and models of a model whose names are scoped `scope`.
    fn model_contents(
        &mut self,
        model: &Element,
        scope: &str,
        dir: &Path,
        depth: usize,
    ) -> Result<(), RobotError> {
        let model_frame = scoped(scope, MODEL_FRAME);
        for c in &model.children {
            match c.name.as_str() {
                "link" => self.link(c, scope, dir)?,
                "joint" => {
                    let name = c
                        .get("name")
                        .ok_or_else(|| c.wrong("a joint needs a name"))?;
                    let end = |which: &str| {
                        c.child_text(which)
                            .filter(|t| !t.is_empty())
                            .map(str::to_owned)
                            .ok_or_else(|| c.wrong(format!("a joint needs a <{which}> link")))
                    };
                    let (parent, child) = (end("parent")?, end("child")?);
                    let child = self.frame_key(scope, &child);
                    let placed = self.placed(c, scope, &child)?;
                    self.add_frame(c, scoped(scope, name), placed)?;
                    self.joints.push(JointDef {
                        parent: (parent != "world").then(|| self.frame_key(scope, &parent)),
                        child,
                        moving: c.get("type").is_some_and(|t| t != "fixed"),
                        element: c.clone(),
                    });
                }
                "frame" => {
                    let name = c
                        .get("name")
                        .ok_or_else(|| c.wrong("a frame needs a name"))?;
                    let attached = c
                        .get("attached_to")
                        .filter(|a| !a.is_empty())
                        .map_or_else(|| model_frame.clone(), |a| self.frame_key(scope, a));
                    let placed = self.placed(c, scope, &attached)?;
                    self.add_frame(c, scoped(scope, name), placed)?;
                }
                "model" => self.nested_model(c, scope, dir, depth)?,
                "include" => self.include(c, scope, dir, depth)?,
                _ => {}
            }
        }
        Ok(())
    }

    /// An `<include>`: the model its `<uri>` names, as a nested model.
    fn include(
        &mut self,
        e: &Element,
        scope: &str,
        dir: &Path,
        depth: usize,
    ) -> Result<(), RobotError> {
        if depth >= MAX_INCLUDE_DEPTH {
            return Err(e.wrong(format!(
                "includes nest deeper than {MAX_INCLUDE_DEPTH}: a model includes itself"
            )));
        }
        let uri = e
            .child_text("uri")
            .filter(|u| !u.is_empty())
            .ok_or_else(|| e.wrong("an include needs a <uri>"))?;
        let path = self.model_file(uri, dir).map_err(|tried| {
            e.wrong(format!(
                "<uri>{uri}</uri>: no model found (tried {}); give its folder with --package \
                 NAME=DIR or GZ_SIM_RESOURCE_PATH",
                tried
                    .iter()
                    .map(|p| p.display().to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            ))
        })?;
        let text = xml::read_file(&path)?;
        let index = self.sources.len();
        let (root, read_leniently) = xml::parse(&text, &path, index)?;
        self.sources.push(SourceFile {
            path: path.clone(),
            text,
            read_leniently,
        });
        let model = root
            .child("model")
            .ok_or_else(|| root.wrong("an included file needs a <model>"))?;
        let name = e
            .child_text("name")
            .filter(|n| !n.is_empty())
            .or_else(|| model.get("name"))
            .ok_or_else(|| model.wrong("a model needs a name"))?
            .to_owned();
        if let Some(p) = e.child("placement_frame") {
            self.unsupported.push(Unsupported {
                at: p.at.clone(),
                element: "placement_frame".to_owned(),
                what: "the included model is placed by its <pose> alone: where its links sit \
                       in the robot may differ, their masses do not"
                    .to_owned(),
            });
        }
        // The include's pose replaces the model's own.
        let placed = if e.child("pose").is_some() {
            self.placed(e, scope, &scoped(scope, MODEL_FRAME))?
        } else {
            self.placed(model, scope, &scoped(scope, MODEL_FRAME))?
        };
        self.place_model(e, scope, &name, placed)?;
        self.model_contents(model, &scoped(scope, &name), &folder_of(&path), depth + 1)
    }

    /// The SDFormat file of the model a `<uri>` names, or every path tried.
    fn model_file(&self, uri: &str, dir: &Path) -> Result<PathBuf, Vec<PathBuf>> {
        let folders: Vec<PathBuf> = if let Some(rest) = uri
            .strip_prefix("model://")
            .or_else(|| uri.strip_prefix("package://"))
        {
            let (name, inner) = rest.split_once('/').unwrap_or((rest, ""));
            model_folders(name, dir, self.options)
                .into_iter()
                .map(|f| f.join(inner))
                .collect()
        } else if let Some(path) = uri.strip_prefix("file://") {
            vec![dir.join(path)]
        } else {
            vec![dir.join(uri)]
        };
        for f in &folders {
            if f.is_file() {
                return Ok(f.clone());
            }
            if f.is_dir() {
                let file = f.join(model_config_file(&f.join("model.config")));
                if file.is_file() {
                    return Ok(file);
                }
            }
        }
        Err(folders)
    }

    fn link(&mut self, e: &Element, scope: &str, dir: &Path) -> Result<(), RobotError> {
        let name = e
            .get("name")
            .ok_or_else(|| e.wrong("a link needs a name"))?;
        let key = scoped(scope, name);
        let placed = self.placed(e, scope, &scoped(scope, MODEL_FRAME))?;
        self.add_frame(e, key.clone(), placed)?;
        let inertial_element = e.child("inertial");
        let auto = inertial_element.is_some_and(|i| matches!(i.get("auto"), Some("true" | "1")));
        let (stated, inertial) = match inertial_element {
            Some(i) if !auto => {
                let (stated, placed) = self.inertial(i, scope, &key)?;
                (Some(stated), Some(placed))
            }
            _ => (None, None),
        };
        let auto_inertial = match inertial_element {
            Some(i) if auto => Some(AutoInertial {
                mass: i.child_number("mass")?,
                at: i.at.clone(),
            }),
            _ => None,
        };
        // A collision's own density, else the inertial's, else water's (libsdformat's Link.cc).
        let link_density = match inertial_element {
            Some(i) if auto => i.child_number("density")?.unwrap_or(DEFAULT_DENSITY),
            _ => DEFAULT_DENSITY,
        };
        let geometries = |kind: &str| -> Result<(Vec<Geometry>, Vec<Placed>), RobotError> {
            let mut shapes = Vec::new();
            let mut placements = Vec::new();
            for g in e.children_named(kind) {
                let Some(shape_element) = g.child("geometry").and_then(|x| x.children.first())
                else {
                    continue;
                };
                if shape_element.name == "empty" {
                    continue;
                }
                let shape = self
                    .shape(shape_element, dir)
                    .unwrap_or_else(|e| Shape::Unsupported {
                        what: e.to_string(),
                    });
                let mass = if auto && kind == "collision" {
                    GeometryMass::Density(g.child_number("density")?.unwrap_or(link_density))
                } else {
                    GeometryMass::Unstated
                };
                placements.push(self.placed(g, scope, &key)?);
                shapes.push(Geometry {
                    shape,
                    pose: Isometry3::identity(),
                    mass,
                    at: shape_element.at.clone(),
                });
            }
            Ok((shapes, placements))
        };
        let (collision, collision_placed) = geometries("collision")?;
        let (visual, visual_placed) = geometries("visual")?;
        self.links.push(LinkDef {
            link: Link {
                name: key.clone(),
                parent: None,
                pose: Isometry3::identity(),
                moving: false,
                stated,
                auto_inertial,
                incomplete_inertial: None,
                element: span(e),
                collision,
                visual,
            },
            key,
            collision: collision_placed,
            visual: visual_placed,
            inertial,
        });
        Ok(())
    }

    /// An `<inertial>` in its own frame (placed in the link's at the end).
    fn inertial(
        &self,
        e: &Element,
        scope: &str,
        link: &str,
    ) -> Result<(Inertial, Placed), RobotError> {
        let mass = e.child_number("mass")?.unwrap_or(1.0);
        let names = ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"];
        let defaults = [1.0, 0.0, 0.0, 1.0, 0.0, 1.0];
        let mut v = defaults;
        let mut written = Vec::with_capacity(6);
        let inertia = e.child("inertia");
        for (k, name) in names.iter().enumerate() {
            match inertia.map(|i| i.child_number(name)).transpose()?.flatten() {
                Some(x) => {
                    v[k] = x;
                    written.push(
                        inertia
                            .and_then(|i| i.child_text(name))
                            .unwrap_or_default()
                            .to_owned(),
                    );
                }
                None => written.push(defaults[k].to_string()),
            }
        }
        let placed = self.placed(e, scope, link)?;
        Ok((
            Inertial {
                mass,
                center_of_mass: Point3::origin(),
                inertia: Matrix3::new(v[0], v[1], v[2], v[1], v[3], v[4], v[2], v[4], v[5]),
                written,
                span: span(e),
            },
            placed,
        ))
    }

    /// The shape element of a `<geometry>`.
    fn shape(&self, s: &Element, dir: &Path) -> Result<Shape, RobotError> {
        let positive = |name: &str| -> Result<f64, RobotError> {
            match s.child_number(name)? {
                Some(v) if v > 0.0 => Ok(v),
                Some(_) => Err(s.wrong(format!(
                    "<{name}>{}</{name}> must be positive",
                    s.child_text(name).unwrap_or_default()
                ))),
                None => Err(s.wrong(format!("a <{}> needs a <{name}>", s.name))),
            }
        };
        let positive3 = |name: &str| -> Result<Vector3<f64>, RobotError> {
            match s.child_numbers::<3>(name)? {
                Some(v) if v.iter().all(|&x| x > 0.0) => Ok(Vector3::from(v)),
                Some(_) => Err(s.wrong(format!(
                    "<{name}>{}</{name}>: each must be positive",
                    s.child_text(name).unwrap_or_default()
                ))),
                None => Err(s.wrong(format!("a <{}> needs a <{name}>", s.name))),
            }
        };
        Ok(match s.name.as_str() {
            "box" => Shape::Box {
                half_extents: positive3("size")? / 2.0,
            },
            "sphere" => Shape::Sphere {
                radius: positive("radius")?,
            },
            "cylinder" => Shape::Cylinder {
                radius: positive("radius")?,
                half_length: positive("length")? / 2.0,
            },
            "capsule" => Shape::Capsule {
                radius: positive("radius")?,
                half_length: positive("length")? / 2.0,
            },
            "ellipsoid" => Shape::Ellipsoid {
                radii: positive3("radii")?,
            },
            "mesh" => {
                if s.child("submesh").is_some() {
                    return Ok(Shape::Unsupported {
                        what: "a <mesh> with a <submesh> (one part of the file)".to_owned(),
                    });
                }
                let written = s
                    .child_text("uri")
                    .filter(|u| !u.is_empty())
                    .ok_or_else(|| s.wrong("a <mesh> needs a <uri>"))?;
                let scale = s
                    .child_numbers::<3>("scale")?
                    .map_or_else(|| Vector3::repeat(1.0), Vector3::from);
                match resolve_mesh(written, dir, self.options) {
                    Ok(file) => Shape::Mesh { file, scale },
                    Err(tried) => Shape::MissingMesh {
                        written: written.to_owned(),
                        tried,
                    },
                }
            }
            other => Shape::Unsupported {
                what: format!("<{other}> geometry"),
            },
        })
    }

    /// Frame `key` in the robot's frame; refuses a frame that is not there or a loop.
    fn resolve(
        &self,
        key: &str,
        memo: &mut HashMap<String, Isometry3<f64>>,
        path: &mut Vec<String>,
    ) -> Result<Isometry3<f64>, String> {
        if let Some(p) = memo.get(key) {
            return Ok(*p);
        }
        if path.iter().any(|k| k == key) {
            return Err(format!(
                "the poses make a loop of frames: {} -> {key}",
                path.join(" -> ")
            ));
        }
        let def = self
            .frames
            .get(key)
            .ok_or_else(|| format!("no frame is named \"{key}\""))?;
        path.push(key.to_owned());
        let pose = match &def.relative_to {
            Some(r) => self.resolve(r, memo, path)? * def.pose,
            None => def.pose,
        };
        path.pop();
        memo.insert(key.to_owned(), pose);
        Ok(pose)
    }

    /// The robot: every pose resolved, links parents first.
    fn finish(self, name: Option<String>) -> Result<Robot, RobotError> {
        if self.links.is_empty() {
            return Err(RobotError::Element {
                at: Box::new(crate::error::Location {
                    file: self.sources[0].path.clone(),
                    line: 1,
                    column: 1,
                }),
                element: "model".to_owned(),
                problem: "the model has no <link>".to_owned(),
            });
        }
        let mut memo = HashMap::new();
        let mut links: Vec<Link> = Vec::with_capacity(self.links.len());
        for def in &self.links {
            let at = |problem: String| RobotError::Element {
                at: Box::new(def.link.element.at.clone()),
                element: "link".to_owned(),
                problem,
            };
            let pose = self
                .resolve(&def.key, &mut memo, &mut Vec::new())
                .map_err(at)?;
            let inverse = pose.inverse();
            let mut in_link = |p: &Placed| -> Result<Isometry3<f64>, RobotError> {
                Ok(inverse
                    * self
                        .resolve(&p.relative_to, &mut memo, &mut Vec::new())
                        .map_err(at)?
                    * p.pose)
            };
            let mut link = def.link.clone();
            link.pose = pose;
            for (g, p) in link.collision.iter_mut().zip(&def.collision) {
                g.pose = in_link(p)?;
            }
            for (g, p) in link.visual.iter_mut().zip(&def.visual) {
                g.pose = in_link(p)?;
            }
            if let (Some(s), Some(p)) = (&mut link.stated, &def.inertial) {
                let frame = in_link(p)?;
                let r = frame.rotation.to_rotation_matrix();
                s.center_of_mass = Point3::from(frame.translation.vector);
                s.inertia = r.matrix() * s.inertia * r.matrix().transpose();
            }
            links.push(link);
        }
        let index: HashMap<&str, usize> = self
            .links
            .iter()
            .enumerate()
            .map(|(i, d)| (d.key.as_str(), i))
            .collect();
        for j in &self.joints {
            // Since 1.8 a joint may name any frame; one not a link's leaves the tree as it is.
            let link_of = |key: &str, which: &str| match index.get(key) {
                Some(&i) => Ok(Some(i)),
                None if self.frames.contains_key(key) => Ok(None),
                None => Err(j
                    .element
                    .wrong(format!("<{which}>: no link or frame is named \"{key}\""))),
            };
            let child = link_of(&j.child, "child")?;
            let parent = match &j.parent {
                Some(p) => link_of(p, "parent")?,
                None => None,
            };
            let Some(child) = child else {
                continue;
            };
            // A link that is the child of two joints closes a loop (SDFormat allows them): the
            // first joint makes the tree.
            if links[child].parent.is_none() && parent != Some(child) {
                links[child].parent = parent;
            }
            links[child].moving |= j.moving;
        }
        let links = parents_first(links);
        Ok(Robot {
            name: name.unwrap_or_else(|| file_stem(&self.sources[0].path)),
            format: DescriptionFormat::Sdf,
            sources: self.sources,
            links,
            unsupported: self.unsupported,
            inertia_from_geoms: false,
            xacro: None,
        })
    }
}

/// The links reordered parents first (each tree depth first in file order), parents renumbered.
fn parents_first(links: Vec<Link>) -> Vec<Link> {
    let n = links.len();
    let mut order = Vec::with_capacity(n);
    let mut seen = vec![false; n];
    // Roots first; a loop of parents has none, so its links follow in file order.
    let mut starts: Vec<usize> = (0..n).filter(|&i| links[i].parent.is_none()).collect();
    starts.extend(0..n);
    for s in starts {
        let mut stack = vec![s];
        while let Some(i) = stack.pop() {
            if seen[i] {
                continue;
            }
            seen[i] = true;
            order.push(i);
            stack.extend(
                (0..n)
                    .rev()
                    .filter(|&c| links[c].parent == Some(i) && !seen[c]),
            );
        }
    }
    let mut new_index = vec![0; n];
    for (new, &old) in order.iter().enumerate() {
        new_index[old] = new;
    }
    let mut slots: Vec<Option<Link>> = links.into_iter().map(Some).collect();
    order
        .iter()
        .filter_map(|&old| slots[old].take())
        .map(|mut l| {
            l.parent = l.parent.map(|p| new_index[p]);
            l
        })
        .collect()
}

/// The model file a `model.config` names: its `<sdf>` of the newest version, else `model.sdf`.
fn model_config_file(config: &Path) -> String {
    let fallback = "model.sdf".to_owned();
    let Ok(text) = std::fs::read_to_string(config) else {
        return fallback;
    };
    let Ok(doc) = roxmltree::Document::parse(&text) else {
        return fallback;
    };
    let version = |n: &roxmltree::Node<'_, '_>| -> Vec<u32> {
        n.attribute("version")
            .unwrap_or("0")
            .split('.')
            .map(|p| p.parse().unwrap_or(0))
            .collect()
    };
    doc.descendants()
        .filter(|n| n.has_tag_name("sdf"))
        .max_by_key(version)
        .and_then(|n| n.text())
        .map(|t| t.trim().to_owned())
        .filter(|t| !t.is_empty())
        .unwrap_or(fallback)
}

/// A `<pose>` element as a rigid motion.
fn pose(p: &Element) -> Result<Isometry3<f64>, RobotError> {
    let text = p.text.trim();
    let values: Vec<f64> = if text.is_empty() {
        vec![0.0; 6]
    } else {
        text.split_whitespace()
            .map(|t| t.parse::<f64>().ok().filter(|x| x.is_finite()))
            .collect::<Option<Vec<f64>>>()
            .ok_or_else(|| p.wrong(format!("\"{text}\": not numbers")))?
    };
    let degrees = matches!(p.get("degrees"), Some("true" | "1"));
    let quaternion = p.get("rotation_format") == Some("quat_xyzw");
    let rotation = match (values.as_slice(), quaternion) {
        ([_, _, _, x, y, z, w], true) => {
            let q = Quaternion::new(*w, *x, *y, *z);
            if q.norm() == 0.0 {
                return Err(p.wrong(format!("\"{text}\": a zero quaternion")));
            }
            UnitQuaternion::from_quaternion(q)
        }
        ([_, _, _, r, pitch, y], false) => {
            let k = if degrees {
                std::f64::consts::PI / 180.0
            } else {
                1.0
            };
            UnitQuaternion::from_euler_angles(r * k, pitch * k, y * k)
        }
        _ => {
            return Err(p.wrong(format!(
                "\"{text}\": expected x y z roll pitch yaw{}",
                if quaternion {
                    " (x y z qx qy qz qw)"
                } else {
                    ""
                }
            )));
        }
    };
    Ok(Isometry3::from_parts(
        Translation3::new(values[0], values[1], values[2]),
        rotation,
    ))
}
