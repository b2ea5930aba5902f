//! The MJCF reader: the `<body>` tree of `<worldbody>` with each body's `<inertial>` and
//! `<geom>`s, `<frame>`s, `<compiler>`, `<asset><mesh>`, `<default>` classes (`class`,
//! `childclass`) and `<include>`.
//!
//! MuJoCo XML reference (mujoco.readthedocs.io, XML Reference, 3.x/4.0): positions `pos`;
//! orientations by one of `quat` (w x y z), `axisangle` (x y z angle), `euler` (in the order of
//! `compiler/eulerseq`, default `xyz`, lowercase axes rotating with the frame, uppercase fixed),
//! `xyaxes`, `zaxis`; angles in degrees unless `compiler/angle="radian"`; `inertial/diaginertia`
//! in the inertial frame, `fullinertia` = M11 M22 M33 M12 M13 M23 in the body frame; geom `size`
//! (box half-sides, sphere radius, capsule and cylinder radius and half-length, ellipsoid
//! radii) and `fromto` (the axis from one point to another); `mass` overrides `density`
//! (default 1000); mesh files relative to `compiler/meshdir` (else `assetdir`) beside the model;
//! a default class inherits from its parent, and an element takes `class`, else the nearest
//! `childclass` above it, else `main`; a body without `<inertial>` is weighed from the geoms of
//! `compiler/inertiagrouprange` (default groups 0 to 5) only. What can change masses and is not
//! modelled here (height fields, planes, primitives fitted to meshes, shell inertia, flexes,
//! composites, replicate and attach, the compiler's mass-changing options) is listed in
//! [`Robot::unsupported`].

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use nalgebra::{
    Isometry3, Matrix3, Point3, Rotation3, Translation3, Unit, UnitQuaternion, Vector3,
};

use crate::error::RobotError;
use crate::model::{
    DescriptionFormat, Geometry, GeometryMass, Inertial, Link, Robot, Shape, Unsupported,
};
use crate::urdf::{file_stem, span};
use crate::xml::{self, Element, SourceFile};

/// How deep `<include>`s may nest before the reader calls it a loop.
const MAX_INCLUDE_DEPTH: usize = 16;

/// Builds the robot of a parsed `<mujoco>` element; `sources` holds the model file, and every
/// included file is appended to it.
pub fn read(root: &Element, mut sources: Vec<SourceFile>) -> Result<Robot, RobotError> {
    let dir = sources[0]
        .path
        .parent()
        .map(Path::to_owned)
        .unwrap_or_default();
    let root = expand_includes(root, &dir, &dir, &mut sources, 0)?;
    let source_dirs = sources
        .iter()
        .map(|s| s.path.parent().map(Path::to_owned).unwrap_or_default())
        .collect();
    let mut reader = Reader {
        compiler: Compiler::default(),
        defaults: HashMap::new(),
        meshes: HashMap::new(),
        dir,
        source_dirs,
        links: Vec::new(),
        unsupported: Vec::new(),
    };
    for c in root.children_named("compiler") {
        reader.compiler(c)?;
    }
    for d in root.children_named("default") {
        reader.default_class(d, None)?;
    }
    for a in root.children_named("asset") {
        for m in a.children_named("mesh") {
            reader.mesh_asset(m)?;
        }
    }
    for w in root.children_named("worldbody") {
        reader.children(
            w,
            None,
            &Isometry3::identity(),
            &Isometry3::identity(),
            "main",
        )?;
    }
    for other in ["deformable", "skin"] {
        for e in root.children_named(other) {
            reader.unsupported(e, "deformable bodies are not audited");
        }
    }
    Ok(Robot {
        name: root
            .get("model")
            .map_or_else(|| file_stem(&sources[0].path), str::to_owned),
        format: DescriptionFormat::Mjcf,
        sources,
        links: reader.links,
        unsupported: reader.unsupported,
        inertia_from_geoms: reader.compiler.inertia_from_geoms,
        xacro: None,
    })
}

/// `root` with every `<include file>` replaced by the children of the file's `<mujoco>`. An
/// include's path is taken, as MuJoCo 4.0 takes it, beside the model file (`dir`) or else beside
/// the file that writes it (`here`).
fn expand_includes(
    e: &Element,
    dir: &Path,
    here: &Path,
    sources: &mut Vec<SourceFile>,
    depth: usize,
) -> Result<Element, RobotError> {
    let mut out = e.clone();
    out.children.clear();
    for c in &e.children {
        if c.name != "include" {
            out.children
                .push(expand_includes(c, dir, here, sources, depth)?);
            continue;
        }
        if depth >= MAX_INCLUDE_DEPTH {
            return Err(c.wrong(format!(
                "includes nest deeper than {MAX_INCLUDE_DEPTH}: a file includes itself"
            )));
        }
        let written = c
            .get("file")
            .ok_or_else(|| c.wrong("the attribute file is missing"))?;
        let beside_model = dir.join(written);
        let path = if beside_model.is_file() {
            beside_model
        } else {
            here.join(written)
        };
        let text = xml::read_file(&path).map_err(|e| match e {
            RobotError::Io { source, .. } => c.bad(
                "file",
                written,
                format!("{} cannot be read: {source}", path.display()),
            ),
            other => other,
        })?;
        let index = sources.len();
        let (included, read_leniently) = xml::parse(&text, &path, index)?;
        let included_dir = path.parent().map(Path::to_owned).unwrap_or_default();
        sources.push(SourceFile {
            path,
            text,
            read_leniently,
        });
        // MuJoCo takes either root for an included file.
        if included.name != "mujoco" && included.name != "mujocoinclude" {
            return Err(included
                .wrong("an included file's root element must be <mujoco> or <mujocoinclude>"));
        }
        let expanded = expand_includes(&included, dir, &included_dir, sources, depth + 1)?;
        out.children.extend(expanded.children);
    }
    Ok(out)
}

/// What `<compiler>` says that the reader uses.
#[derive(Debug, Clone)]
struct Compiler {
    radians: bool,
    meshdir: Option<String>,
    assetdir: Option<String>,
    eulerseq: [u8; 3],
    inertia_from_geoms: bool,
    /// Geoms of groups outside this range give a body no mass (`inertiagrouprange`).
    inertia_groups: (f64, f64),
}

impl Default for Compiler {
    fn default() -> Self {
        Self {
            radians: false,
            meshdir: None,
            assetdir: None,
            eulerseq: *b"xyz",
            inertia_from_geoms: false,
            inertia_groups: (0.0, 5.0),
        }
    }
}

/// A default class: its parent, and for each element kind the attributes it sets.
#[derive(Debug, Clone, Default)]
struct DefaultClass {
    parent: Option<String>,
    kinds: HashMap<String, Vec<(String, String)>>,
}

/// A `<mesh>` asset.
#[derive(Debug, Clone)]
enum MeshAsset {
    File {
        file: Result<PathBuf, Vec<PathBuf>>,
        written: String,
        scale: Vector3<f64>,
    },
    Other(String),
}

struct Reader {
    compiler: Compiler,
    defaults: HashMap<String, DefaultClass>,
    meshes: HashMap<String, MeshAsset>,
    dir: PathBuf,
    /// The folder of each source file (the model's first, then each included file's).
    source_dirs: Vec<PathBuf>,
    links: Vec<Link>,
    unsupported: Vec<Unsupported>,
}

impl Reader {
    fn unsupported(&mut self, e: &Element, what: impl Into<String>) {
        self.unsupported.push(Unsupported {
            at: e.at.clone(),
            element: e.name.clone(),
            what: what.into(),
        });
    }

    fn compiler(&mut self, e: &Element) -> Result<(), RobotError> {
        if let Some(a) = e.get("angle") {
            self.compiler.radians = match a {
                "radian" => true,
                "degree" => false,
                _ => return Err(e.bad("angle", a, "must be degree or radian")),
            };
        }
        if let Some(d) = e.get("meshdir") {
            self.compiler.meshdir = Some(d.to_owned());
        }
        if let Some(d) = e.get("assetdir") {
            self.compiler.assetdir = Some(d.to_owned());
        }
        if let Some(s) = e.get("eulerseq") {
            let bytes = s.as_bytes();
            if bytes.len() != 3 || !bytes.iter().all(|b| b"xyzXYZ".contains(b)) {
                return Err(e.bad("eulerseq", s, "must be three of x y z X Y Z"));
            }
            self.compiler.eulerseq = [bytes[0], bytes[1], bytes[2]];
        }
        if let Some([lo, hi]) = e.numbers::<2>("inertiagrouprange")? {
            self.compiler.inertia_groups = (lo, hi);
        }
        if let Some(v) = e.get("inertiafromgeom") {
            self.compiler.inertia_from_geoms = v == "true";
        }
        for (name, what) in [
            (
                "boundmass",
                "MuJoCo raises every body's mass to at least this",
            ),
            (
                "boundinertia",
                "MuJoCo raises every body's moments to at least this",
            ),
            (
                "balanceinertia",
                "MuJoCo changes moments that break the triangle inequality",
            ),
            (
                "settotalmass",
                "MuJoCo scales every mass so that they add up to this",
            ),
        ] {
            if let Some(v) = e.get(name)
                && (name != "balanceinertia" || v == "true")
            {
                self.unsupported(
                    e,
                    format!(
                        "{name}=\"{v}\": {what}; the audit reads the file's numbers as written"
                    ),
                );
            }
        }
        Ok(())
    }

    fn default_class(&mut self, e: &Element, parent: Option<&str>) -> Result<(), RobotError> {
        let name = match (e.get("class"), parent) {
            (Some(c), _) => c.to_owned(),
            (None, None) => "main".to_owned(),
            (None, Some(_)) => return Err(e.wrong("a nested <default> needs a class")),
        };
        let mut class = DefaultClass {
            parent: parent.map(str::to_owned),
            kinds: HashMap::new(),
        };
        for c in e.children.iter().filter(|c| c.name != "default") {
            class
                .kinds
                .entry(c.name.clone())
                .or_default()
                .extend(c.attributes.iter().cloned());
        }
        self.defaults.insert(name.clone(), class);
        for c in e.children_named("default") {
            self.default_class(c, Some(&name))?;
        }
        Ok(())
    }

    /// `e` with the attributes its class chain sets and it does not.
    fn resolved(&self, e: &Element, childclass: &str) -> Result<Element, RobotError> {
        let mut class = e.get("class").unwrap_or(childclass).to_owned();
        if !self.defaults.contains_key(&class) && class != "main" {
            return Err(e.bad("class", &class, "no <default> class has this name"));
        }
        let mut out = e.clone();
        out.children.clear();
        let mut hops = 0;
        while let Some(c) = self.defaults.get(&class) {
            if let Some(attributes) = c.kinds.get(&e.name) {
                for (k, v) in attributes {
                    if out.get(k).is_none() {
                        out.attributes.push((k.clone(), v.clone()));
                    }
                }
            }
            match &c.parent {
                Some(p) if hops < 64 => {
                    class = p.clone();
                    hops += 1;
                }
                _ => break,
            }
        }
        Ok(out)
    }

    fn mesh_asset(&mut self, m: &Element) -> Result<(), RobotError> {
        let m = self.resolved(m, "main")?;
        let Some(written) = m.get("file") else {
            let name = m
                .get("name")
                .ok_or_else(|| m.wrong("a mesh without a file needs a name"))?;
            self.meshes.insert(
                name.to_owned(),
                MeshAsset::Other("a mesh given by its vertices in the XML".to_owned()),
            );
            self.unsupported(&m, "a mesh given inline (vertex, face) is not audited");
            return Ok(());
        };
        let name = m.get("name").map_or_else(
            || {
                Path::new(written)
                    .file_stem()
                    .map_or_else(String::new, |s| s.to_string_lossy().into_owned())
            },
            str::to_owned,
        );
        let scale = m
            .numbers::<3>("scale")?
            .map_or(Vector3::repeat(1.0), Vector3::from);
        if let Some(inertia) = m.get("inertia")
            && inertia == "shell"
        {
            self.unsupported(&m, "inertia=\"shell\": MuJoCo takes this mesh as a thin shell; the audit integrates it as a solid");
        }
        let base = self
            .compiler
            .meshdir
            .as_deref()
            .or(self.compiler.assetdir.as_deref())
            .unwrap_or("");
        // As MuJoCo 4.0 looks: beside the model (in meshdir), then, for a mesh written in an
        // included file, beside that file (without meshdir).
        let path = Path::new(written);
        let mut tried = vec![if path.is_absolute() {
            path.to_owned()
        } else {
            self.dir.join(base).join(path)
        }];
        if m.file != 0
            && !path.is_absolute()
            && let Some(here) = self.source_dirs.get(m.file)
        {
            tried.push(here.join(path));
        }
        let file = match tried.iter().find(|p| p.is_file()) {
            Some(found) => Ok(found.clone()),
            None => Err(tried),
        };
        self.meshes.insert(
            name,
            MeshAsset::File {
                file,
                written: written.to_owned(),
                scale,
            },
        );
        Ok(())
    }

    /// The bodies, geoms and frames under `e` (a worldbody, body or frame); `parent` is the
    /// body they belong to, `parent_pose` its zero pose, `frame` where `e` sits in it.
    fn children(
        &mut self,
        e: &Element,
        parent: Option<usize>,
        parent_pose: &Isometry3<f64>,
        frame: &Isometry3<f64>,
        childclass: &str,
    ) -> Result<(), RobotError> {
        for c in &e.children {
            match c.name.as_str() {
                "body" => self.body(c, parent, parent_pose, frame, childclass)?,
                "frame" => {
                    let resolved = self.resolved(c, childclass)?;
                    let inner = frame * self.pose(&resolved)?;
                    let class = c.get("childclass").unwrap_or(childclass).to_owned();
                    self.children(c, parent, parent_pose, &inner, &class)?;
                }
                "geom" => {
                    if let Some(body) = parent {
                        let g = self.geom(c, frame, childclass)?;
                        let link = &mut self.links[body];
                        if g.1 {
                            link.visual.push(g.0);
                        } else {
                            link.collision.push(g.0);
                        }
                    }
                }
                "joint" | "freejoint" => {
                    if let Some(body) = parent {
                        self.links[body].moving = true;
                    }
                }
                "composite" | "flexcomp" | "replicate" | "attach" => {
                    self.unsupported(
                        c,
                        format!(
                            "<{}> is not expanded: the bodies and geoms it makes are not audited",
                            c.name
                        ),
                    );
                }
                _ => {}
            }
        }
        Ok(())
    }

    fn body(
        &mut self,
        e: &Element,
        parent: Option<usize>,
        parent_pose: &Isometry3<f64>,
        frame: &Isometry3<f64>,
        childclass: &str,
    ) -> Result<(), RobotError> {
        let class = e.get("childclass").unwrap_or(childclass).to_owned();
        let pose = parent_pose * frame * self.pose(e)?;
        let index = self.links.len();
        let name = e
            .get("name")
            .map_or_else(|| format!("body {index}"), str::to_owned);
        let stated = e.child("inertial").map(|i| self.inertial(i)).transpose()?;
        self.links.push(Link {
            name,
            parent,
            pose,
            moving: false,
            stated,
            auto_inertial: None,
            incomplete_inertial: None,
            element: span(e),
            collision: Vec::new(),
            visual: Vec::new(),
        });
        self.children(e, Some(index), &pose, &Isometry3::identity(), &class)
    }

    fn inertial(&self, e: &Element) -> Result<Inertial, RobotError> {
        let frame = self.pose(e)?;
        let mass = e.required_number("mass")?;
        let (inertia, attribute) = match (
            e.numbers::<3>("diaginertia")?,
            e.numbers::<6>("fullinertia")?,
        ) {
            (Some(d), None) => {
                let r = frame.rotation.to_rotation_matrix();
                let m = Matrix3::from_diagonal(&Vector3::from(d));
                (r.matrix() * m * r.matrix().transpose(), "diaginertia")
            }
            (None, Some(f)) => (
                Matrix3::new(f[0], f[3], f[4], f[3], f[1], f[5], f[4], f[5], f[2]),
                "fullinertia",
            ),
            (Some(_), Some(_)) => return Err(e.wrong("give diaginertia or fullinertia, not both")),
            (None, None) => return Err(e.wrong("an inertial needs diaginertia or fullinertia")),
        };
        Ok(Inertial {
            mass,
            center_of_mass: Point3::from(frame.translation.vector),
            inertia,
            written: e
                .get(attribute)
                .unwrap_or_default()
                .split_whitespace()
                .map(str::to_owned)
                .collect(),
            span: span(e),
        })
    }

    /// A geom, in the frame of the body it belongs to, and whether it is visual only.
    fn geom(
        &mut self,
        raw: &Element,
        frame: &Isometry3<f64>,
        childclass: &str,
    ) -> Result<(Geometry, bool), RobotError> {
        let e = self.resolved(raw, childclass)?;
        let kind = e.get("type").unwrap_or("sphere").to_owned();
        let size = e.number_list("size")?.unwrap_or_default();
        let size_at = |k: usize| size.get(k).copied().unwrap_or(0.0);
        let fromto = e.numbers::<6>("fromto")?;
        let mut pose = frame * self.pose(&e)?;
        let mut half_length = size_at(1);
        if let Some(ft) = fromto
            && matches!(kind.as_str(), "capsule" | "cylinder" | "box" | "ellipsoid")
        {
            let a = Vector3::new(ft[0], ft[1], ft[2]);
            let b = Vector3::new(ft[3], ft[4], ft[5]);
            let axis = b - a;
            if axis.norm() == 0.0 {
                return Err(e.bad(
                    "fromto",
                    e.get("fromto").unwrap_or_default(),
                    "the two ends are the same point",
                ));
            }
            let rotation =
                UnitQuaternion::rotation_between(&Vector3::z(), &axis).unwrap_or_else(|| {
                    UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
                });
            pose = frame * Isometry3::from_parts(Translation3::from((a + b) / 2.0), rotation);
            half_length = axis.norm() / 2.0;
        }
        let need = |n: usize, what: &str| -> Result<(), RobotError> {
            if (0..n).all(|k| size_at(k) > 0.0) {
                Ok(())
            } else {
                Err(e.bad(
                    "size",
                    e.get("size").unwrap_or_default(),
                    format!("a {kind} needs {what}, positive"),
                ))
            }
        };
        let mut shape = match kind.as_str() {
            "sphere" => {
                need(1, "a radius")?;
                Shape::Sphere { radius: size_at(0) }
            }
            "capsule" | "cylinder" => {
                if fromto.is_none() {
                    need(2, "a radius and a half-length")?;
                } else {
                    need(1, "a radius")?;
                }
                if kind == "capsule" {
                    Shape::Capsule {
                        radius: size_at(0),
                        half_length,
                    }
                } else {
                    Shape::Cylinder {
                        radius: size_at(0),
                        half_length,
                    }
                }
            }
            "box" | "ellipsoid" => {
                let z = if fromto.is_some() {
                    half_length
                } else {
                    size_at(2)
                };
                let half = Vector3::new(size_at(0), size_at(1), z);
                if half.iter().any(|&x| x <= 0.0) {
                    return Err(e.bad(
                        "size",
                        e.get("size").unwrap_or_default(),
                        format!("a {kind} needs three positive sizes"),
                    ));
                }
                if kind == "box" {
                    Shape::Box { half_extents: half }
                } else {
                    Shape::Ellipsoid { radii: half }
                }
            }
            "mesh" => {
                let name = e
                    .get("mesh")
                    .ok_or_else(|| e.wrong("a mesh geom needs mesh=\"…\""))?;
                match self.meshes.get(name) {
                    Some(MeshAsset::File {
                        file: Ok(file),
                        scale,
                        ..
                    }) => Shape::Mesh {
                        file: file.clone(),
                        scale: *scale,
                    },
                    Some(MeshAsset::File {
                        file: Err(tried),
                        written,
                        ..
                    }) => Shape::MissingMesh {
                        written: written.clone(),
                        tried: tried.clone(),
                    },
                    Some(MeshAsset::Other(what)) => Shape::Unsupported { what: what.clone() },
                    None => return Err(e.bad("mesh", name, "no <mesh> asset has this name")),
                }
            }
            other => Shape::Unsupported {
                what: format!("a {other} geom"),
            },
        };
        if kind != "mesh"
            && let Some(mesh) = e.get("mesh")
        {
            shape = Shape::Unsupported {
                what: format!("a {kind} fitted to mesh {mesh}"),
            };
        }
        if e.get("shellinertia") == Some("true") {
            self.unsupported(raw, "shellinertia=\"true\": MuJoCo takes this geom as a thin shell; the audit integrates it as a solid");
        }
        if let Shape::Unsupported { what } = &shape {
            let what = format!("{what} — not integrated: its body's computed mass leaves it out");
            self.unsupported(raw, what);
        }
        let mass = match (e.number("mass")?, e.number("density")?) {
            (Some(m), _) => GeometryMass::Mass(m),
            (None, Some(d)) => GeometryMass::Density(d),
            (None, None) => GeometryMass::Density(1000.0),
        };
        // MuJoCo weighs only the geoms of `inertiagrouprange` when it infers a body's inertia.
        let group = e.number("group")?.unwrap_or(0.0);
        let (lo, hi) = self.compiler.inertia_groups;
        let mass = if (lo..=hi).contains(&group) {
            mass
        } else {
            GeometryMass::Mass(0.0)
        };
        let contype = e.number("contype")?.unwrap_or(1.0);
        let conaffinity = e.number("conaffinity")?.unwrap_or(1.0);
        Ok((
            Geometry {
                shape,
                pose,
                mass,
                at: raw.at.clone(),
            },
            contype == 0.0 && conaffinity == 0.0,
        ))
    }

    /// `pos` and the orientation of `e` as a rigid motion.
    fn pose(&self, e: &Element) -> Result<Isometry3<f64>, RobotError> {
        let pos = e.numbers::<3>("pos")?.unwrap_or([0.0; 3]);
        Ok(Isometry3::from_parts(
            Translation3::new(pos[0], pos[1], pos[2]),
            self.orientation(e)?,
        ))
    }

    /// The one orientation attribute of `e` (identity when none).
    fn orientation(&self, e: &Element) -> Result<UnitQuaternion<f64>, RobotError> {
        let given: Vec<&str> = ["quat", "axisangle", "euler", "xyaxes", "zaxis"]
            .into_iter()
            .filter(|k| e.get(k).is_some())
            .collect();
        if given.len() > 1 {
            return Err(e.wrong(format!("give one orientation, not {}", given.join(" and "))));
        }
        let angle = |a: f64| {
            if self.compiler.radians {
                a
            } else {
                a.to_radians()
            }
        };
        let invalid =
            |name: &str, problem: &str| e.bad(name, e.get(name).unwrap_or_default(), problem);
        if let Some([w, x, y, z]) = e.numbers::<4>("quat")? {
            let q = nalgebra::Quaternion::new(w, x, y, z);
            if q.norm() == 0.0 {
                return Err(invalid("quat", "a zero quaternion is no rotation"));
            }
            return Ok(UnitQuaternion::from_quaternion(q));
        }
        if let Some([x, y, z, a]) = e.numbers::<4>("axisangle")? {
            let axis = Unit::try_new(Vector3::new(x, y, z), 0.0)
                .ok_or_else(|| invalid("axisangle", "the axis is zero"))?;
            return Ok(UnitQuaternion::from_axis_angle(&axis, angle(a)));
        }
        if let Some(angles) = e.numbers::<3>("euler")? {
            let mut q = UnitQuaternion::identity();
            for (k, &axis) in self.compiler.eulerseq.iter().enumerate() {
                let unit = match axis.to_ascii_lowercase() {
                    b'x' => Vector3::x_axis(),
                    b'y' => Vector3::y_axis(),
                    _ => Vector3::z_axis(),
                };
                let turn = UnitQuaternion::from_axis_angle(&unit, angle(angles[k]));
                // Lowercase: about the axes as they have turned (intrinsic), post-multiplied.
                q = if axis.is_ascii_lowercase() {
                    q * turn
                } else {
                    turn * q
                };
            }
            return Ok(q);
        }
        if let Some(v) = e.numbers::<6>("xyaxes")? {
            let x = Vector3::new(v[0], v[1], v[2]);
            let y = Vector3::new(v[3], v[4], v[5]);
            let x = x
                .try_normalize(0.0)
                .ok_or_else(|| invalid("xyaxes", "the x axis is zero"))?;
            let y = (y - x * x.dot(&y))
                .try_normalize(1e-12)
                .ok_or_else(|| invalid("xyaxes", "the y axis is parallel to the x axis"))?;
            let r = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[x, y, x.cross(&y)]));
            return Ok(UnitQuaternion::from_rotation_matrix(&r));
        }
        if let Some(z) = e.numbers::<3>("zaxis")? {
            let z = Vector3::from(z);
            if z.norm() == 0.0 {
                return Err(invalid("zaxis", "the axis is zero"));
            }
            return Ok(
                UnitQuaternion::rotation_between(&Vector3::z(), &z).unwrap_or_else(|| {
                    UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
                }),
            );
        }
        Ok(UnitQuaternion::identity())
    }
}
