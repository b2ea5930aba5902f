//! A robot description in the lab: the audited robot ([`robot::audit`]), the link shown, and how
//! a link, or the whole robot at its zero pose, becomes a body made of parts (one part per
//! geometry, each at its link's uniform density). Primitives are drawn as tessellations; the mass
//! properties of a link shown alone are the audit's, in closed form.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use massprops::{MassProperties, MaterialEntry, PartEntry, PolyMesh};
use nalgebra::{Isometry3, Point3, Vector3};
use robot::{Audit, AuditOptions, Geometry, GeometryKind, ReadOptions, Robot, Shape};

use super::body::{LinkMark, LoadedBody};
use super::error::LabError;
use super::parts::PartModel;

/// Segments around a tessellated primitive (its drawing only).
const SEGMENTS: usize = 48;

/// A robot as the lab holds it.
#[derive(Debug, Clone)]
pub struct RobotModel {
    /// The description as read.
    pub robot: Arc<Robot>,
    /// Every link audited (collision geometry, stated masses).
    pub audit: Arc<Audit>,
    /// The link that is the body, or `None` for the whole robot at its zero pose.
    pub shown: Option<usize>,
}

/// Reads and audits the description at `path`, and the body of the whole robot.
///
/// # Errors
/// The description cannot be read (the message names file, line and element), or no link has
/// geometry that can be drawn.
pub fn load(path: &Path) -> Result<(RobotModel, LoadedBody), LabError> {
    // Gazebo's model folders, as the command line finds them; a xacro file is expanded with
    // its arguments' defaults.
    let options = ReadOptions {
        resource_paths: robot::resource_paths_from_env(),
        ..ReadOptions::default()
    };
    let robot = robot::read(path, &options).map_err(|e| LabError::Robot(e.to_string()))?;
    let audit = robot::audit(&robot, &AuditOptions::default());
    let model = RobotModel {
        robot: Arc::new(robot),
        audit: Arc::new(audit),
        shown: None,
    };
    let body = whole_body(&model)?;
    Ok((model, body))
}

/// The whole robot at its zero pose: every link's collision geometry placed by its link's pose,
/// each link at its computed density, with each link's stated and computed inertia as marks.
///
/// # Errors
/// No link has geometry that can be drawn.
pub fn whole_body(model: &RobotModel) -> Result<LoadedBody, LabError> {
    let mut parts = Vec::new();
    let mut marks = Vec::new();
    for (l, a) in model.robot.links.iter().zip(&model.audit.links) {
        let density = a.computed.as_ref().map_or(1000.0, |c| c.density);
        for (k, g) in l.geometry(GeometryKind::Collision).iter().enumerate() {
            if let Ok(part) = part(
                &format!("{} {}", l.name, k + 1),
                g,
                &(l.pose * g.pose),
                density,
            ) {
                parts.push(part);
            }
        }
        let place = |p: &MassProperties| p.transformed(&l.pose);
        marks.push(LinkMark {
            name: l.name.clone(),
            stated: a.stated.as_ref().map(place),
            computed: a.computed.as_ref().ok().map(|c| place(&c.properties)),
        });
    }
    if parts.is_empty() {
        return Err(LabError::Robot(format!(
            "{}: no link has collision geometry that can be drawn",
            model.robot.name
        )));
    }
    let mut body = LoadedBody::from_parts(&model.robot.name, parts)?;
    body.links = marks;
    Ok(body)
}

/// Link `index` alone: its collision geometry as parts in the link's frame, its mass
/// properties the audit's (closed forms for primitives), and its stated inertial as the
/// "stated" source.
///
/// # Errors
/// The link has no geometry that can be weighed (the message says why).
pub fn link_body(model: &RobotModel, index: usize) -> Result<LoadedBody, LabError> {
    let link = model
        .robot
        .links
        .get(index)
        .ok_or(LabError::NoLink(index))?;
    let audit = &model.audit.links[index];
    let computed = audit.computed.as_ref().map_err(|why| {
        LabError::Robot(format!(
            "link {}: {}",
            link.name,
            inertia_io::report::findings::unweighed_text(why, "collision")
        ))
    })?;
    let parts = link
        .geometry(GeometryKind::Collision)
        .iter()
        .enumerate()
        .map(|(k, g)| {
            part(
                &format!("{} {}", link.name, k + 1),
                g,
                &g.pose,
                computed.density,
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut body = LoadedBody::from_parts(&link.name, parts)?;
    if let Some(c) = &mut body.composition {
        c.whole = computed.properties;
    }
    body.stated = audit.stated;
    Ok(body)
}

/// One geometry as a part: its mesh placed by `pose`, at `density`.
fn part(
    name: &str,
    g: &Geometry,
    pose: &Isometry3<f64>,
    density: f64,
) -> Result<PartModel, LabError> {
    let (mesh, file) = geometry_mesh(g)?;
    let placed = mesh.map_positions(|p| pose * p)?;
    let entry = PartEntry::unplaced(name, &file, None, MaterialEntry::Density(density));
    PartModel::new(entry, placed)
}

/// The mesh of a geometry in its own frame (a primitive tessellated), and the file it names.
fn geometry_mesh(g: &Geometry) -> Result<(PolyMesh, PathBuf), LabError> {
    let label = PathBuf::from(g.shape.label());
    let mesh = match &g.shape {
        Shape::Mesh { file, scale } => {
            let read = massprops::load_mesh(file)?;
            let mesh = read
                .mesh
                .map_positions(|p| Point3::from(p.coords.component_mul(scale)))?;
            return Ok((mesh, file.clone()));
        }
        Shape::Box { half_extents } => {
            massprops::shapes::cuboid(half_extents * 2.0, Point3::origin()).build()
        }
        Shape::Cylinder {
            radius,
            half_length,
        } => massprops::shapes::cylinder(*radius, -half_length, *half_length, SEGMENTS).build(),
        Shape::Sphere { radius } => round(Vector3::repeat(*radius), 0.0),
        Shape::Ellipsoid { radii } => round(*radii, 0.0),
        Shape::Capsule {
            radius,
            half_length,
        } => round(Vector3::repeat(*radius), *half_length),
        Shape::MissingMesh { .. } | Shape::Unsupported { .. } => {
            return Err(LabError::Robot(format!(
                "{} cannot be drawn",
                g.shape.label()
            )));
        }
    };
    Ok((mesh, label))
}

/// An ellipsoid of semi-axes `radii`, its two halves `half_length` apart along z (a capsule when
/// that is not zero), as rings of latitude wound outward.
fn round(radii: Vector3<f64>, half_length: f64) -> PolyMesh {
    let rings = SEGMENTS / 2;
    let mut positions = vec![Point3::new(0.0, 0.0, half_length + radii.z)];
    // Each ring: its polar angle, and which half it belongs to (the equator twice for a capsule).
    let mut ring_angles: Vec<(f64, f64)> = Vec::new();
    for i in 1..rings {
        let theta = std::f64::consts::PI * i as f64 / rings as f64;
        match (2 * i).cmp(&rings) {
            std::cmp::Ordering::Less => ring_angles.push((theta, half_length)),
            std::cmp::Ordering::Greater => ring_angles.push((theta, -half_length)),
            // The equator: once for an ellipsoid, at both ends of a capsule's cylinder.
            std::cmp::Ordering::Equal => {
                ring_angles.push((theta, half_length));
                if half_length > 0.0 {
                    ring_angles.push((theta, -half_length));
                }
            }
        }
    }
    for &(theta, shift) in &ring_angles {
        for j in 0..SEGMENTS {
            let phi = std::f64::consts::TAU * j as f64 / SEGMENTS as f64;
            positions.push(Point3::new(
                radii.x * theta.sin() * phi.cos(),
                radii.y * theta.sin() * phi.sin(),
                shift + radii.z * theta.cos(),
            ));
        }
    }
    positions.push(Point3::new(0.0, 0.0, -half_length - radii.z));
    let bottom = positions.len() - 1;
    let at = |ring: usize, j: usize| 1 + ring * SEGMENTS + j % SEGMENTS;
    let mut faces: Vec<Vec<usize>> = Vec::new();
    for j in 0..SEGMENTS {
        faces.push(vec![0, at(0, j), at(0, j + 1)]);
        let last = ring_angles.len() - 1;
        faces.push(vec![bottom, at(last, j + 1), at(last, j)]);
        for r in 0..last {
            faces.push(vec![at(r, j), at(r + 1, j), at(r + 1, j + 1), at(r, j + 1)]);
        }
    }
    PolyMesh::new(positions, &faces).unwrap_or_else(|_| massprops::shapes::cube().build())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tessellated_round_primitives_enclose_their_volume_wound_outward() {
        for (radii, h, volume) in [
            (
                Vector3::new(0.1, 0.2, 0.3),
                0.0,
                4.0 / 3.0 * std::f64::consts::PI * 0.006,
            ),
            (
                Vector3::repeat(0.1),
                0.25,
                std::f64::consts::PI * 0.01 * 0.5 + 4.0 / 3.0 * std::f64::consts::PI * 0.001,
            ),
        ] {
            let mesh = round(radii, h);
            let a = massprops::analyze(
                &mesh,
                massprops::Method::Volume,
                massprops::MassSpec::Density(1.0),
            )
            .expect("closed");
            assert!(!a.flipped && a.warnings.is_empty(), "{:?}", a.warnings);
            let v = a.volume.expect("volume");
            assert!((v / volume - 1.0).abs() < 0.01, "{v} vs {volume}");
        }
    }
}
