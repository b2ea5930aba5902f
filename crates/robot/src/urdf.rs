//! The URDF reader: `<link>`s with `<inertial>`, `<visual>` and `<collision>` geometry, and the
//! `<joint>`s only as far as the zero pose needs (parent, child, origin, type).
//!
//! ROS URDF specification (wiki.ros.org/urdf/XML): `<origin xyz rpy>` places a frame in its
//! link's (rpy fixed-axis roll, pitch, yaw, R = Rz(yaw)·Ry(pitch)·Rx(roll)); the inertial's
//! origin is the centre of mass and its axes are those of `<inertia ixx ixy ixz iyy iyz izz>`,
//! the entries of the inertia matrix (ixy = −∑m·x·y); `<box size>` gives full sides,
//! `<cylinder radius length>` lies along z, `<mesh filename scale>`; a joint's origin places
//! the child link's frame in the parent's. `<capsule radius length>` is an extension that
//! Bullet and Gazebo read. Mesh paths: `package://NAME/…` (a folder NAME given, or found by
//! searching upwards from the URDF), `file://…`, or relative to the URDF.

use std::collections::HashMap;
use std::path::Path;

use nalgebra::{Isometry3, Matrix3, Point3, Translation3, UnitQuaternion, Vector3};

use crate::ReadOptions;
use crate::error::RobotError;
use crate::model::{
    DescriptionFormat, Geometry, GeometryMass, IncompleteInertial, Inertial, Link, Robot, Shape,
    Span, Unsupported,
};
use crate::paths::resolve_mesh;
use crate::xml::{Element, SourceFile};

/// Builds the robot of a parsed `<robot>` element.
pub fn read(
    root: &Element,
    sources: Vec<SourceFile>,
    options: &ReadOptions,
) -> Result<Robot, RobotError> {
    let dir = sources[0]
        .path
        .parent()
        .map(Path::to_owned)
        .unwrap_or_default();
    let mut names: HashMap<&str, usize> = HashMap::new();
    let mut links = Vec::new();
    // What yourdfpy and MuJoCo load and the audit has nothing of, or reads as they read it:
    // named, never skipped silently.
    let mut unsupported = Vec::new();
    for (i, e) in root.children_named("link").enumerate() {
        let name = e
            .get("name")
            .ok_or_else(|| e.wrong("a link needs a name"))?;
        if names.insert(name, i).is_some() {
            return Err(e.wrong(format!("a second link named \"{name}\"")));
        }
        links.push(link(e, name, &dir, options, &mut unsupported)?);
    }
    if links.is_empty() {
        unsupported.push(Unsupported {
            at: root.at.clone(),
            element: "robot".to_owned(),
            what: "the robot has no <link>: nothing to audit".to_owned(),
        });
    }
    for d in root.children_named("deformable") {
        unsupported.push(Unsupported {
            at: d.at.clone(),
            element: "deformable".to_owned(),
            what: "a soft body (pybullet's extension): not audited".to_owned(),
        });
    }
    // Each child's joint: its parent, its origin, whether it moves.
    let mut joint_of: Vec<Option<(usize, Isometry3<f64>, bool)>> = vec![None; links.len()];
    for j in root.children_named("joint") {
        let end = |which: &str| -> Result<Result<usize, &str>, RobotError> {
            let e = j
                .child(which)
                .ok_or_else(|| j.wrong(format!("a joint needs a <{which}> link")))?;
            let name = e
                .get("link")
                .ok_or_else(|| e.wrong("the attribute link is missing"))?;
            Ok(names.get(name).copied().ok_or(name))
        };
        let (parent, child) = match (end("parent")?, end("child")?) {
            (Ok(p), Ok(c)) => (p, c),
            (Err(missing), _) | (_, Err(missing)) => {
                // yourdfpy loads such a file (a stage without its base link): the joint is
                // left out, and said so.
                unsupported.push(Unsupported {
                    at: j.at.clone(),
                    element: "joint".to_owned(),
                    what: format!(
                        "joint \"{}\" names link \"{missing}\", which the file does not have: \
                         the joint is left out",
                        j.get("name").unwrap_or_default()
                    ),
                });
                continue;
            }
        };
        if joint_of[child].is_some() {
            return Err(j.wrong(format!(
                "link \"{}\" is the child of a second joint",
                links[child].name
            )));
        }
        let moving = j.get("type").is_some_and(|t| t != "fixed");
        joint_of[child] = Some((parent, origin(j.child("origin"), &mut unsupported)?, moving));
    }
    for (i, joint) in joint_of.iter().enumerate() {
        if let Some((parent, _, moving)) = joint {
            links[i].parent = Some(*parent);
            links[i].moving = *moving;
        }
    }
    let links = in_tree_order(links, &joint_of, root)?;
    Ok(Robot {
        name: root
            .get("name")
            .map_or_else(|| file_stem(&sources[0].path), str::to_owned),
        format: DescriptionFormat::Urdf,
        sources,
        links,
        unsupported,
        inertia_from_geoms: false,
        xacro: None,
    })
}

/// The links reordered parents first, with their zero poses; refuses a cycle.
fn in_tree_order(
    links: Vec<Link>,
    joint_of: &[Option<(usize, Isometry3<f64>, bool)>],
    root: &Element,
) -> Result<Vec<Link>, RobotError> {
    let n = links.len();
    let mut order: Vec<usize> = (0..n).filter(|&i| joint_of[i].is_none()).collect();
    let mut k = 0;
    while k < order.len() {
        let p = order[k];
        order.extend((0..n).filter(|&c| joint_of[c].is_some_and(|(parent, ..)| parent == p)));
        k += 1;
    }
    if order.len() < n {
        let stuck = (0..n).find(|i| !order.contains(i)).unwrap_or(0);
        return Err(root.wrong(format!(
            "the joints make a loop through link \"{}\": a URDF is a tree",
            links[stuck].name
        )));
    }
    let mut new_index = vec![0; n];
    for (new, &old) in order.iter().enumerate() {
        new_index[old] = new;
    }
    let mut slots: Vec<Option<Link>> = links.into_iter().map(Some).collect();
    let mut sorted: Vec<Link> = Vec::with_capacity(n);
    for &old in &order {
        let Some(mut link) = slots[old].take() else {
            continue;
        };
        if let Some((parent, origin, _)) = joint_of[old] {
            link.parent = Some(new_index[parent]);
            link.pose = sorted[new_index[parent]].pose * origin;
        }
        sorted.push(link);
    }
    Ok(sorted)
}

fn link(
    e: &Element,
    name: &str,
    dir: &Path,
    options: &ReadOptions,
    notes: &mut Vec<Unsupported>,
) -> Result<Link, RobotError> {
    let (stated, incomplete_inertial) = match e.child("inertial") {
        None => (None, None),
        Some(i) => match inertial(i, notes)? {
            Ok(s) => (Some(s), None),
            Err(missing) => (
                None,
                Some(IncompleteInertial {
                    missing,
                    span: span(i),
                }),
            ),
        },
    };
    let mut geometries = |kind: &str| -> Result<Vec<Geometry>, RobotError> {
        let mut all = Vec::new();
        for g in e.children_named(kind) {
            all.extend(geometry(g, dir, options, notes)?);
        }
        Ok(all)
    };
    Ok(Link {
        name: name.to_owned(),
        parent: None,
        pose: Isometry3::identity(),
        moving: false,
        stated,
        auto_inertial: None,
        incomplete_inertial,
        element: span(e),
        collision: geometries("collision")?,
        visual: geometries("visual")?,
    })
}

/// The span of an element.
pub fn span(e: &Element) -> Span {
    Span {
        file: e.file,
        range: e.range.clone(),
        at: e.at.clone(),
    }
}

/// A stated `<inertial>`, or which of its elements it lacks (urdfdom refuses such a file,
/// yourdfpy reads it).
fn inertial(
    e: &Element,
    notes: &mut Vec<Unsupported>,
) -> Result<Result<Inertial, &'static str>, RobotError> {
    let frame = origin(e.child("origin"), notes)?;
    let Some(mass_element) = e.child("mass") else {
        return Ok(Err("mass"));
    };
    let mass = mass_element.required_number("value")?;
    let Some(i) = e.child("inertia") else {
        return Ok(Err("inertia"));
    };
    let names = ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"];
    let mut v = [0.0; 6];
    let mut written = Vec::with_capacity(6);
    for (k, name) in names.iter().enumerate() {
        v[k] = i.required_number(name)?;
        written.push(i.get(name).unwrap_or_default().trim().to_owned());
    }
    let local = Matrix3::new(v[0], v[1], v[2], v[1], v[3], v[4], v[2], v[4], v[5]);
    let r = frame.rotation.to_rotation_matrix();
    Ok(Ok(Inertial {
        mass,
        center_of_mass: Point3::from(frame.translation.vector),
        inertia: r.matrix() * local * r.matrix().transpose(),
        written,
        span: span(e),
    }))
}

/// `<origin xyz rpy>` as a rigid motion; the identity when absent. More than three numbers are
/// read as yourdfpy reads them, the first three (pybullet's microtaur writes `rpy` with four),
/// and named in `notes`.
pub fn origin(
    e: Option<&Element>,
    notes: &mut Vec<Unsupported>,
) -> Result<Isometry3<f64>, RobotError> {
    let Some(e) = e else {
        return Ok(Isometry3::identity());
    };
    let mut three = |name: &str| -> Result<[f64; 3], RobotError> {
        let Some(v) = e.number_list(name)? else {
            return Ok([0.0; 3]);
        };
        if v.len() > 3 {
            notes.push(Unsupported {
                at: e.at.clone(),
                element: "origin".to_owned(),
                what: format!(
                    "{name} has {} numbers: read as its first three, as yourdfpy reads it \
                     (urdfdom refuses it)",
                    v.len()
                ),
            });
        }
        <[f64; 3]>::try_from(&v[..3.min(v.len())]).map_err(|_| {
            e.bad(
                name,
                e.get(name).unwrap_or_default(),
                format!("expected 3 number(s), found {}", v.len()),
            )
        })
    };
    let [x, y, z] = three("xyz")?;
    let [roll, pitch, yaw] = three("rpy")?;
    Ok(Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(roll, pitch, yaw),
    ))
}

/// A `<visual>` or `<collision>`; `None` for one without `<geometry>` (urdfdom allows it).
fn geometry(
    e: &Element,
    dir: &Path,
    options: &ReadOptions,
    notes: &mut Vec<Unsupported>,
) -> Result<Option<Geometry>, RobotError> {
    let Some(g) = e.child("geometry") else {
        return Ok(None);
    };
    let Some(s) = g.children.first() else {
        return Err(g.wrong("a <geometry> needs a box, cylinder, sphere or mesh"));
    };
    // A geometry that cannot be used is the link's problem, not the whole file's.
    let shape = shape(s, dir, options).unwrap_or_else(|e| Shape::Unsupported {
        what: e.to_string(),
    });
    Ok(Some(Geometry {
        shape,
        pose: origin(e.child("origin"), notes)?,
        mass: GeometryMass::Unstated,
        at: s.at.clone(),
    }))
}

/// The shape element of a `<geometry>`.
fn shape(s: &Element, dir: &Path, options: &ReadOptions) -> Result<Shape, RobotError> {
    let positive = |name: &str| -> Result<f64, RobotError> {
        let v = s.required_number(name)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(s.bad(name, s.get(name).unwrap_or_default(), "must be positive"))
        }
    };
    Ok(match s.name.as_str() {
        "box" => {
            let size = s
                .numbers::<3>("size")?
                .ok_or_else(|| s.wrong("the attribute size is missing"))?;
            if size.iter().any(|&x| x <= 0.0) {
                return Err(s.bad(
                    "size",
                    s.get("size").unwrap_or_default(),
                    "sides must be positive",
                ));
            }
            Shape::Box {
                half_extents: Vector3::from(size) / 2.0,
            }
        }
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
        "mesh" => {
            let written = s
                .get("filename")
                .ok_or_else(|| s.wrong("the attribute filename is missing"))?;
            let scale = match s.number_list("scale")?.as_deref() {
                None => Vector3::repeat(1.0),
                Some([k]) => Vector3::repeat(*k),
                Some([x, y, z]) => Vector3::new(*x, *y, *z),
                Some(_) => {
                    return Err(s.bad(
                        "scale",
                        s.get("scale").unwrap_or_default(),
                        "expected 3 numbers",
                    ));
                }
            };
            match resolve_mesh(written, dir, options) {
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

/// A file's stem, for a model without a name.
pub fn file_stem(path: &Path) -> String {
    path.file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned())
}
