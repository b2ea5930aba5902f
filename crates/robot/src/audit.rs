//! The audit: each link's mass properties from its geometry, beside what the file states, and
//! the findings that compare them.
//!
//! The computed body is the link's geometries as parts of one body (massprops' sums: masses
//! add, tensors move to the common centre by Steiner's theorem) at uniform density: at the
//! stated mass when there is one (the density follows), else at the file's geom masses and
//! densities (MJCF), else at a density given or assumed. Uniform density is only an estimate
//! for a link full of motors, so distance from it is a finding only past thresholds the user
//! sets.
//!
//! Two findings are proofs, not heuristics, given that the link's mass lies within its
//! geometry: a principal moment I about an axis through the stated centre of mass is ∫d² dm
//! with d each mass element's distance from the axis, so I ≤ m·r² where r is the largest
//! distance of the geometry from that axis (`impossible_moment`); and the centre of mass is a
//! weighted mean of the mass's points, so it lies in their convex hull, judged here by the
//! 26-sided polytope of 13 directions that contains the hull (`com_outside_geometry`).

use std::collections::HashMap;

use nalgebra::{Matrix3, Point3, Vector3};
use rayon::prelude::*;

use massprops::composite::{PartMass, combine};
use massprops::principal::Degeneracy;
use massprops::{MassProperties, MeshError, Repairs};

use crate::findings::{Finding, ImpossibleAxis, PlaceholderReason, Region, UnitSlip};
use crate::geometry::{self, Extent, Meshes, Problem, Ready};
use crate::masses::{Measured, MeasuredMasses};
use crate::model::{DescriptionFormat, GeometryKind, GeometryMass, Link, Robot, Shape};
use crate::nearest::{self, Nearest, NearestError};

/// Relative slack for round-off in the laws and the bounds.
const SLACK: f64 = 1e-9;

/// Moments within this ratio (largest / smallest) count as "nearly equal" for a body whose
/// stated moments are all equal.
const ISOTROPIC_RATIO: f64 = 1.1;

/// Densities outside this range, kg/m³, are implausible for a link (aerogel foam is ~50,
/// osmium ~22 600).
pub const PLAUSIBLE_DENSITY: (f64, f64) = (50.0, 25_000.0);

/// What the audit weighs and how strict it is.
#[derive(Debug, Clone)]
pub struct AuditOptions {
    /// Which geometry stands for a link's shape.
    pub geometry: GeometryKind,
    /// A density for every link, kg/m³, instead of the stated masses.
    pub density: Option<f64>,
    /// The density of a link with neither a stated mass nor geom masses, kg/m³.
    pub assumed_density: f64,
    /// Flag a tensor whose relative (Frobenius) error against the computed one exceeds this.
    pub max_moment_error: Option<f64>,
    /// Flag a centre of mass farther than this fraction of the link's size from the computed one.
    pub max_com_offset: Option<f64>,
    /// How each mesh's defects are handled (as `props`).
    pub repairs: Repairs,
    /// Also find each stated inertial's nearest valid one ([`crate::nearest`]).
    pub nearest: bool,
    /// Links' masses (and centres) as measured: their geometry is weighed at the measured mass,
    /// a stated inertial that differs is a finding, and both fixes keep them.
    pub measured: MeasuredMasses,
}

impl Default for AuditOptions {
    fn default() -> Self {
        Self {
            geometry: GeometryKind::Collision,
            density: None,
            assumed_density: 1000.0,
            max_moment_error: None,
            max_com_offset: None,
            repairs: Repairs::default(),
            nearest: false,
            measured: MeasuredMasses::new(),
        }
    }
}

/// Where a computed link's mass comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassBasis {
    /// The stated mass, spread uniformly over the geometry.
    StatedMass,
    /// The measured mass (`AuditOptions::measured`), spread uniformly over the geometry.
    MeasuredMass,
    /// The file's own geom masses and densities (MJCF).
    FileMasses,
    /// The density the user gave.
    GivenDensity(f64),
    /// No mass anywhere: this density was assumed.
    AssumedDensity(f64),
    /// SDFormat's `<inertial auto="true">`, as Gazebo computes it: the collisions' densities,
    /// scaled to the `<mass>` where one is written.
    AutoInertial,
}

/// A link's mass properties from its geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct Computed {
    /// Link frame, kg, m, kg·m², about the centre of mass in the link's axes.
    pub properties: MassProperties,
    /// The geometry's volume, m³.
    pub volume: f64,
    /// Mass / volume, kg/m³.
    pub density: f64,
    /// Where the mass comes from.
    pub basis: MassBasis,
}

/// Why a link has no computed mass properties.
#[derive(Debug, Clone)]
pub enum Unweighed {
    /// It has no geometry of the kind audited.
    NoGeometry,
    /// Some of its geometry cannot be weighed (its findings say which).
    Incomplete,
    /// Its geoms have no mass (MJCF `density="0"` or `mass="0"`).
    Massless,
    /// The parts sum to no body (voids larger than solids: not possible here, but named).
    Sum(MeshError),
}

/// The stated inertial beside the computed one.
#[derive(Debug, Clone, PartialEq)]
pub struct InertialComparison {
    /// Distance between the two centres of mass, m.
    pub com_offset: f64,
    /// That distance as a fraction of the link's size (its geometry's bounding-box diagonal).
    pub com_offset_fraction: f64,
    /// ‖I_stated − I_computed‖ / ‖I_computed‖ (Frobenius norms, about each one's centre of mass,
    /// link axes).
    pub tensor_error: f64,
    /// The angle between each stated principal axis and the computed one of the same rank,
    /// radians in [0, π/2]; `None` where equal moments leave an axis free.
    pub axis_angles: [Option<f64>; 3],
}

/// One link's audit.
#[derive(Debug, Clone)]
pub struct LinkAudit {
    /// The link's index in [`Robot::links`].
    pub link: usize,
    /// The stated inertial's mass properties (`None` without one).
    pub stated: Option<MassProperties>,
    /// From the geometry, or why not.
    pub computed: Result<Computed, Unweighed>,
    /// The geometry's bounding-box diagonal, m, when its extent is known.
    pub size: Option<f64>,
    /// Stated beside computed, when both are there.
    pub comparison: Option<InertialComparison>,
    /// What is wrong, worst first.
    pub findings: Vec<Finding>,
    /// The valid inertial nearest to the stated one, when asked for and there is one stated
    /// and geometry to hold it.
    pub nearest: Option<Result<Nearest, NearestError>>,
}

impl LinkAudit {
    /// The worst finding's severity (9 with none).
    pub fn worst(&self) -> u8 {
        self.findings
            .iter()
            .map(Finding::severity)
            .min()
            .unwrap_or(9)
    }

    /// Whether a finding says the stated inertial is wrong.
    pub fn flagged(&self) -> bool {
        self.findings.iter().any(Finding::flags_inertial)
    }
}

/// The whole robot's audit.
#[derive(Debug, Clone)]
pub struct Audit {
    /// Every link, in the robot's order.
    pub links: Vec<LinkAudit>,
    /// The options used.
    pub options: AuditOptions,
}

impl Audit {
    /// The links worst first (then by tensor error, largest first; then in file order).
    pub fn worst_first(&self) -> Vec<&LinkAudit> {
        let mut v: Vec<&LinkAudit> = self.links.iter().collect();
        let error = |l: &LinkAudit| l.comparison.as_ref().map_or(-1.0, |c| c.tensor_error);
        v.sort_by(|a, b| {
            a.worst()
                .cmp(&b.worst())
                .then(error(b).total_cmp(&error(a)))
                .then(a.link.cmp(&b.link))
        });
        v
    }
}

/// Audits every link of `robot`.
pub fn audit(robot: &Robot, options: &AuditOptions) -> Audit {
    let meshes = geometry::load_meshes(&mesh_uses(robot, options.geometry), &options.repairs);
    let mut links: Vec<LinkAudit> = robot
        .links
        .par_iter()
        .enumerate()
        .map(|(i, link)| audit_link(robot, i, link, &meshes, options))
        .collect();
    shared_tensors(robot, &mut links);
    for l in &mut links {
        l.findings.sort_by_key(Finding::severity);
    }
    Audit {
        links,
        options: options.clone(),
    }
}

/// The meshes an audit reads: the kind audited, weighed; the other kind's points, for the
/// proofs (which take the mass to lie in all of a link's geometry), except for an MJCF body
/// that states no inertia, whose every geom is weighed as MuJoCo weighs it.
pub fn mesh_uses(robot: &Robot, kind: GeometryKind) -> Vec<geometry::MeshUse> {
    let other = other_kind(kind);
    let mut uses = Vec::new();
    for link in &robot.links {
        let all_geoms = robot.format == DescriptionFormat::Mjcf && link.stated.is_none();
        for (k, weigh) in [(kind, true), (other, all_geoms)] {
            if k == other && !all_geoms && link.geometry(kind).is_empty() {
                continue;
            }
            for g in link.geometry(k) {
                if let Shape::Mesh { file, scale } = &g.shape {
                    uses.push(geometry::MeshUse {
                        file: file.clone(),
                        scale: *scale,
                        weigh,
                    });
                }
            }
        }
    }
    uses
}

fn other_kind(kind: GeometryKind) -> GeometryKind {
    match kind {
        GeometryKind::Collision => GeometryKind::Visual,
        GeometryKind::Visual => GeometryKind::Collision,
    }
}

fn audit_link(
    robot: &Robot,
    i: usize,
    link: &Link,
    meshes: &Meshes,
    options: &AuditOptions,
) -> LinkAudit {
    let ready: Vec<Ready<'_>> = link
        .geometry(options.geometry)
        .iter()
        .map(|g| geometry::ready(g, meshes))
        .collect();
    let mut findings = Vec::new();
    for r in &ready {
        if let Err(problem) = &r.unit {
            findings.push(match problem.clone() {
                Problem::Missing { written, tried } => Finding::MeshMissing { written, tried },
                Problem::Mesh { file, error } => Finding::MeshUnreadable { file, error },
                Problem::Unsupported { what } => Finding::GeometryUnsupported { what },
            });
        }
        for w in &r.warnings {
            findings.push(Finding::MeshDefect {
                geometry: r.geometry.shape.label(),
                warning: w.clone(),
            });
        }
    }
    let extents: Option<Vec<&Extent<'_>>> = ready.iter().map(|r| r.extent.as_ref()).collect();
    let extents = extents.filter(|e| !e.is_empty());
    let size = extents.as_deref().map(box_diagonal);
    let other: Vec<Ready<'_>> = link
        .geometry(other_kind(options.geometry))
        .iter()
        .map(|g| geometry::ready(g, meshes))
        .collect();
    let other_extents: Option<Vec<&Extent<'_>>> = other.iter().map(|r| r.extent.as_ref()).collect();
    let region = match (&extents, other_extents) {
        (Some(e), Some(o)) if !o.is_empty() => {
            Some((Region::Both, e.iter().copied().chain(o).collect::<Vec<_>>()))
        }
        (Some(e), _) => Some((Region::Only(options.geometry), e.clone())),
        (None, _) => None,
    };
    // MuJoCo weighs every geom of a body that states no inertia, visual ones too.
    let all_geoms: Vec<Ready<'_>>;
    let weighed = if robot.format == DescriptionFormat::Mjcf && link.stated.is_none() {
        all_geoms = ready.iter().chain(&other).cloned().collect();
        &all_geoms
    } else {
        &ready
    };
    let computed = computed(link, weighed, robot.format, options);
    let stated = link
        .stated
        .as_ref()
        .map(|s| MassProperties::new(s.mass, s.center_of_mass, s.inertia));

    if link.stated.is_none()
        && link.auto_inertial.is_none()
        && robot.format != DescriptionFormat::Mjcf
        && (link.moving || !ready.is_empty() || link.incomplete_inertial.is_some())
    {
        findings.push(Finding::MissingInertial {
            moving: link.moving,
            incomplete: link.incomplete_inertial.as_ref().map(|i| i.missing),
        });
    }
    let mut comparison = None;
    if let Some(s) = &stated {
        stated_laws(s, link.moving, &mut findings);
        if s.mass > 0.0
            && let Some((region, extents)) = &region
        {
            bounds(s, *region, extents, &mut findings);
        }
        if let (Ok(c), Some(size)) = (&computed, size) {
            if s.mass > 0.0 {
                let cmp = compare(s, &c.properties, size);
                if let Some(t) = options.max_moment_error
                    && cmp.tensor_error > t
                {
                    findings.push(Finding::MomentsFar {
                        error: cmp.tensor_error,
                        threshold: t,
                    });
                }
                if let Some(t) = options.max_com_offset
                    && cmp.com_offset_fraction > t
                {
                    findings.push(Finding::ComFar {
                        fraction: cmp.com_offset_fraction,
                        threshold: t,
                    });
                }
                comparison = Some(cmp);
            }
            let density = s.mass / c.volume;
            if s.mass > 0.0 && !(PLAUSIBLE_DENSITY.0..=PLAUSIBLE_DENSITY.1).contains(&density) {
                findings.push(Finding::ImplausibleDensity {
                    density,
                    volume: c.volume,
                    mass: s.mass,
                });
                findings.extend(mass_slip(s, &c.properties, density));
            }
            if s.mass > 0.0 {
                findings.extend(moment_slip(s, &c.properties));
                findings.extend(frame_slip(s, &c.properties, &ready, size));
            }
        }
        let written = &link
            .stated
            .as_ref()
            .map(|s| s.written.clone())
            .unwrap_or_default();
        let mut reasons = Vec::new();
        let m = s.principal.moments;
        let products = s.inertia_com[(0, 1)]
            .abs()
            .max(s.inertia_com[(0, 2)].abs())
            .max(s.inertia_com[(1, 2)].abs());
        let round_shape = computed.as_ref().is_ok_and(|c| {
            let cm = c.properties.principal.moments;
            cm.z <= ISOTROPIC_RATIO * cm.x
        });
        if m.z > 0.0 && m.z - m.x <= SLACK * m.z && products <= SLACK * m.z && !round_shape {
            reasons.push(PlaceholderReason::EqualMoments {
                moment: m.z,
                weighed: computed.is_ok(),
            });
        }
        if round_numbers(written) {
            reasons.push(PlaceholderReason::RoundNumbers {
                written: written.clone(),
            });
        }
        if !reasons.is_empty() {
            findings.push(Finding::Placeholder { reasons });
        }
    }
    let measured = options.measured.get(&link.name);
    if let (Some(s), Some(m)) = (&stated, measured) {
        findings.extend(measured_differs(s, m, size));
    }
    let nearest = match (&stated, &region) {
        (Some(s), Some((_, extents))) if options.nearest => Some(nearest_inertial(
            &with_measured(s, measured),
            extents,
            computed.as_ref().ok(),
        )),
        _ => None,
    };
    LinkAudit {
        link: i,
        stated,
        computed,
        size,
        comparison,
        findings,
        nearest,
    }
}

/// The laws every stated inertia must obey on its own.
fn stated_laws(s: &MassProperties, moving: bool, findings: &mut Vec<Finding>) {
    if s.mass < 0.0 || (s.mass == 0.0 && moving) || !s.mass.is_finite() {
        findings.push(Finding::NonpositiveMass { mass: s.mass });
    }
    let m = s.principal.moments;
    let moments = [m.x, m.y, m.z];
    let massless = s.mass == 0.0 && m.amax() == 0.0;
    if massless {
        return;
    }
    // A point mass (no moments) is a body; a moving one is refused by simulators.
    if m.x < 0.0 || (m.x <= 0.0 && moving) {
        findings.push(Finding::NotPositiveDefinite { moments });
    } else if m.x + m.y < m.z * (1.0 - SLACK) {
        findings.push(Finding::TriangleInequality { moments });
    }
}

/// The two proofs: each principal moment against m·r², and the centre against the hull.
fn bounds(
    s: &MassProperties,
    region: Region,
    extents: &[&Extent<'_>],
    findings: &mut Vec<Finding>,
) {
    let rotation = s.principal.rotation.matrix();
    let mut axes = Vec::new();
    for rank in 0..3 {
        let axis: Vector3<f64> = rotation.column(rank).into();
        let radius = extents
            .iter()
            .map(|e| e.farthest_from_line(&s.center_of_mass, &axis))
            .fold(0.0, f64::max);
        let bound = s.mass * radius * radius;
        let moment = s.principal.moments[rank];
        if moment > bound * (1.0 + SLACK) {
            axes.push(ImpossibleAxis {
                rank,
                moment,
                bound,
                radius,
                axis,
            });
        }
    }
    if !axes.is_empty() {
        findings.push(Finding::ImpossibleMoment {
            region,
            mass: s.mass,
            axes,
        });
    }
    let outside = outside_hull(extents, &s.center_of_mass);
    if outside > SLACK * box_diagonal(extents) {
        findings.push(Finding::ComOutsideGeometry {
            region,
            center_of_mass: s.center_of_mass,
            distance: outside,
        });
    }
}

/// How far `point` lies outside the 26-sided polytope about the geometry (negative inside).
fn outside_hull(extents: &[&Extent<'_>], point: &Point3<f64>) -> f64 {
    directions()
        .iter()
        .map(|d| {
            let hi = extents
                .iter()
                .map(|e| e.support(d))
                .fold(f64::NEG_INFINITY, f64::max);
            let lo = -extents
                .iter()
                .map(|e| e.support(&-d))
                .fold(f64::NEG_INFINITY, f64::max);
            let t = d.dot(&point.coords);
            (t - hi).max(lo - t)
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

/// A stated centre within this fraction of the link's size of the geometry's centre counts as
/// it; farther than `FRAME_SLIP_FAR` from it, as not.
const FRAME_SLIP_NEAR: f64 = 0.02;
const FRAME_SLIP_FAR: f64 = 0.1;

/// A stated centre that is the geometry's centre in one geometry's own frame rather than the
/// link's: far from the computed centre and from the link's origin, but placed by that
/// geometry's origin (the transform the author left out), on it.
fn frame_slip(
    s: &MassProperties,
    computed: &MassProperties,
    ready: &[Ready<'_>],
    size: f64,
) -> Option<Finding> {
    let c = computed.center_of_mass;
    // A centre at the link's origin is the value left by default, not one computed in another
    // frame: a primitive's own centre is its origin, so every offset primitive would match.
    if (s.center_of_mass - c).norm() <= FRAME_SLIP_FAR * size
        || s.center_of_mass.coords.norm() <= FRAME_SLIP_NEAR * size
    {
        return None;
    }
    ready.iter().find_map(|r| {
        let would_be = r.geometry.pose * s.center_of_mass;
        ((would_be - c).norm() <= FRAME_SLIP_NEAR * size).then(|| Finding::CenterInGeometryFrame {
            geometry: r.geometry.shape.label(),
            stated: s.center_of_mass,
            would_be,
        })
    })
}

/// How far a measured mass may be from the stated one, and a measured centre from the stated
/// one (as a fraction of the link's size), before it is a finding.
const MEASURED_TOLERANCE: f64 = 0.01;

/// The finding when the stated inertial differs from what was measured.
fn measured_differs(s: &MassProperties, m: &Measured, size: Option<f64>) -> Option<Finding> {
    let mass = ((s.mass - m.mass).abs() > MEASURED_TOLERANCE * m.mass).then_some(m.mass);
    let center = m.center_of_mass.and_then(|c| {
        let offset = (s.center_of_mass - c).norm();
        (offset > MEASURED_TOLERANCE * size.unwrap_or(0.0)).then_some((c, offset))
    });
    (mass.is_some() || center.is_some()).then_some(Finding::DiffersFromMeasured {
        stated_mass: s.mass,
        measured_mass: mass,
        measured_center: center,
    })
}

/// The stated inertial as the nearest fix starts from it: the measured mass (the stated
/// tensor scaled with it: the same distribution per kilogram) and the measured centre.
fn with_measured(s: &MassProperties, measured: Option<&Measured>) -> MassProperties {
    match measured {
        None => *s,
        Some(m) => {
            let scale = if s.mass > 0.0 { m.mass / s.mass } else { 1.0 };
            MassProperties::new(
                m.mass,
                m.center_of_mass.unwrap_or(s.center_of_mass),
                s.inertia_com * scale,
            )
        }
    }
}

/// The stated inertial's nearest valid one within the link's geometry (all of it: the region
/// the proofs use), centred at the computed centre where the stated one is outside.
fn nearest_inertial(
    stated: &MassProperties,
    extents: &[&Extent<'_>],
    computed: Option<&Computed>,
) -> Result<Nearest, NearestError> {
    let hull: Vec<Point3<f64>> = extents.iter().flat_map(|e| e.hull_points()).collect();
    let center = computed.map_or_else(
        || {
            Point3::from(
                hull.iter().map(|p| p.coords).sum::<Vector3<f64>>() / hull.len().max(1) as f64,
            )
        },
        |c| c.properties.center_of_mass,
    );
    let size = box_diagonal(extents);
    let farthest = |c: &Point3<f64>, u: &Vector3<f64>| {
        extents
            .iter()
            .map(|e| e.farthest_from_line(c, u))
            .fold(0.0, f64::max)
    };
    let contains = |c: &Point3<f64>| outside_hull(extents, c) <= SLACK * size;
    nearest::nearest(
        stated,
        &nearest::Region {
            hull: &hull,
            farthest_from_line: &farthest,
            contains: &contains,
            center,
        },
    )
}

/// The 13 unit directions of a 26-sided discrete oriented polytope: the axes, the face
/// diagonals and the body diagonals of a cube.
pub(crate) fn directions() -> Vec<Vector3<f64>> {
    let raw = [
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 0.0, 1.0],
        [1.0, 0.0, -1.0],
        [0.0, 1.0, 1.0],
        [0.0, 1.0, -1.0],
        [1.0, 1.0, 1.0],
        [1.0, 1.0, -1.0],
        [1.0, -1.0, 1.0],
        [-1.0, 1.0, 1.0],
    ];
    raw.iter().map(|v| Vector3::from(*v).normalize()).collect()
}

/// The diagonal of the geometry's bounding box in the link's axes.
fn box_diagonal(extents: &[&Extent<'_>]) -> f64 {
    let side = |axis: Vector3<f64>| {
        let hi = extents
            .iter()
            .map(|e| e.support(&axis))
            .fold(f64::NEG_INFINITY, f64::max);
        let lo = -extents
            .iter()
            .map(|e| e.support(&-axis))
            .fold(f64::NEG_INFINITY, f64::max);
        hi - lo
    };
    Vector3::new(side(Vector3::x()), side(Vector3::y()), side(Vector3::z())).norm()
}

/// Whether every non-zero number written is a power of ten (1, 0.1, 1e-3…), and one is.
fn round_numbers(written: &[String]) -> bool {
    let values: Option<Vec<f64>> = written.iter().map(|w| w.parse().ok()).collect();
    let Some(values) = values else {
        return false;
    };
    let nonzero: Vec<f64> = values.into_iter().filter(|v| *v != 0.0).collect();
    !nonzero.is_empty()
        && nonzero.iter().all(|v| {
            let k = v.abs().log10().round();
            (-12.0..=3.0).contains(&k) && format!("1e{k}").parse::<f64>().ok() == Some(v.abs())
        })
}

/// The link's geometry as one body, at the mass the options and the file give.
fn computed(
    link: &Link,
    ready: &[Ready<'_>],
    format: DescriptionFormat,
    options: &AuditOptions,
) -> Result<Computed, Unweighed> {
    if ready.is_empty() {
        return Err(Unweighed::NoGeometry);
    }
    let units: Option<Vec<&MassProperties>> = ready.iter().map(|r| r.unit.as_ref().ok()).collect();
    let units = units.ok_or(Unweighed::Incomplete)?;
    let volume: f64 = units.iter().map(|u| u.mass).sum();
    let measured = options.measured.get(&link.name).map(|m| m.mass);
    let stated_mass =
        measured.or_else(|| link.stated.as_ref().map(|s| s.mass).filter(|m| *m > 0.0));
    let auto_mass = link.auto_inertial.as_ref().and_then(|a| a.mass);
    let basis = match (options.density, stated_mass, format) {
        (Some(d), ..) => MassBasis::GivenDensity(d),
        (None, None, _) if link.auto_inertial.is_some() => MassBasis::AutoInertial,
        (None, Some(_), _) if measured.is_some() => MassBasis::MeasuredMass,
        (None, Some(_), _) => MassBasis::StatedMass,
        (None, None, DescriptionFormat::Mjcf) => MassBasis::FileMasses,
        (None, None, DescriptionFormat::Urdf | DescriptionFormat::Sdf) => {
            MassBasis::AssumedDensity(options.assumed_density)
        }
    };
    let masses: Vec<f64> = ready
        .iter()
        .zip(&units)
        .map(|(r, u)| match basis {
            MassBasis::StatedMass | MassBasis::MeasuredMass => {
                stated_mass.unwrap_or(0.0) * u.mass / volume
            }
            MassBasis::GivenDensity(d) | MassBasis::AssumedDensity(d) => d * u.mass,
            MassBasis::FileMasses | MassBasis::AutoInertial => match r.geometry.mass {
                GeometryMass::Mass(m) => m,
                GeometryMass::Density(d) => d * u.mass,
                GeometryMass::Unstated => options.assumed_density * u.mass,
            },
        })
        .collect();
    let parts: Vec<PartMass> = units
        .iter()
        .zip(&masses)
        .filter(|(_, m)| **m > 0.0)
        .map(|(u, m)| PartMass {
            mass: *m,
            center_of_mass: u.center_of_mass,
            inertia_com: u.inertia_com * (m / u.mass),
        })
        .collect();
    if parts.is_empty() {
        return Err(Unweighed::Massless);
    }
    let (mut properties, _) = combine(&parts).map_err(Unweighed::Sum)?;
    if matches!(basis, MassBasis::StatedMass | MassBasis::MeasuredMass) {
        // Exactly the stated (measured) mass, not its sum of rounded parts.
        properties = properties
            .with_mass(stated_mass.unwrap_or(properties.mass))
            .map_err(Unweighed::Sum)?;
    }
    if let (MassBasis::AutoInertial, Some(m)) = (basis, auto_mass) {
        properties = properties.with_mass(m).map_err(Unweighed::Sum)?;
    }
    Ok(Computed {
        density: properties.mass / volume,
        properties,
        volume,
        basis,
    })
}

fn compare(s: &MassProperties, c: &MassProperties, size: f64) -> InertialComparison {
    let com_offset = (s.center_of_mass - c.center_of_mass).norm();
    let difference: Matrix3<f64> = s.inertia_com - c.inertia_com;
    let unique = |d: Degeneracy| match d {
        Degeneracy::Distinct => [true; 3],
        Degeneracy::Moments12 => [false, false, true],
        Degeneracy::Moments23 => [true, false, false],
        Degeneracy::Spherical => [false; 3],
    };
    let (us, uc) = (
        unique(s.principal.degeneracy),
        unique(c.principal.degeneracy),
    );
    let (rs, rc) = (s.principal.rotation.matrix(), c.principal.rotation.matrix());
    let axis_angles = std::array::from_fn(|k| {
        (us[k] && uc[k]).then(|| rs.column(k).dot(&rc.column(k)).abs().min(1.0).acos())
    });
    InertialComparison {
        com_offset,
        com_offset_fraction: if size > 0.0 {
            com_offset / size
        } else {
            f64::INFINITY
        },
        tensor_error: difference.norm() / c.inertia_com.norm(),
        axis_angles,
    }
}

/// Marks the links that share one stated tensor while their geometries differ.
fn shared_tensors(robot: &Robot, links: &mut [LinkAudit]) {
    let mut groups: HashMap<[u64; 6], Vec<usize>> = HashMap::new();
    for (i, l) in links.iter().enumerate() {
        if let Some(s) = &l.stated {
            let t = &s.inertia_com;
            if t.amax() > 0.0 {
                let key = [
                    t[(0, 0)],
                    t[(1, 1)],
                    t[(2, 2)],
                    t[(0, 1)],
                    t[(0, 2)],
                    t[(1, 2)],
                ]
                .map(f64::to_bits);
                groups.entry(key).or_default().push(i);
            }
        }
    }
    for members in groups.values().filter(|m| m.len() > 1) {
        for &i in members {
            let others: Vec<String> = members
                .iter()
                .filter(|&&j| j != i && differ(&links[i], &links[j], robot))
                .map(|&j| robot.links[links[j].link].name.clone())
                .collect();
            if others.is_empty() {
                continue;
            }
            let reason = PlaceholderReason::SharedTensor { links: others };
            match links[i].findings.iter_mut().find_map(|f| match f {
                Finding::Placeholder { reasons } => Some(reasons),
                _ => None,
            }) {
                Some(reasons) => reasons.push(reason),
                None => links[i].findings.push(Finding::Placeholder {
                    reasons: vec![reason],
                }),
            }
        }
    }
}

/// Whether two links' geometries differ: by their computed principal moments per unit mass
/// (more than 10 %), or, without them, by their shapes.
fn differ(a: &LinkAudit, b: &LinkAudit, robot: &Robot) -> bool {
    match (&a.computed, &b.computed) {
        (Ok(x), Ok(y)) => {
            let mx = x.properties.principal.moments / x.properties.mass;
            let my = y.properties.principal.moments / y.properties.mass;
            (0..3).any(|k| (mx[k] - my[k]).abs() > 0.1 * mx[k].max(my[k]))
        }
        _ => {
            let shapes = |l: &LinkAudit| -> Vec<String> {
                robot.links[l.link]
                    .collision
                    .iter()
                    .map(|g| g.shape.label())
                    .collect()
            };
            // A link without geometry differs from nothing that can be seen.
            let (sa, sb) = (shapes(a), shapes(b));
            !sa.is_empty() && !sb.is_empty() && sa != sb
        }
    }
}

/// The densities a unit slip is judged against: those of real parts (foams to tungsten), the
/// plausible range's core, so that a slip is named only when undoing it lands well inside.
const SLIP_DENSITY: (f64, f64) = (300.0, 20_000.0);

/// Whether the stated tensor agrees, within 50 %, with `expected` (the geometry's, for the
/// value the slip would give): the second, independent witness a slip is named on.
fn agrees(stated: &MassProperties, expected: &Matrix3<f64>) -> bool {
    (stated.inertia_com - expected).norm() < 0.5 * expected.norm()
}

/// Whether the stated moments look made up (all three equal), so that they witness nothing.
fn made_up(stated: &MassProperties) -> bool {
    let m = stated.principal.moments;
    m.z - m.x <= 1e-3 * m.z
}

/// The slip of the stated mass, or of the mesh's unit, that an implausible `density` points to,
/// named only when two witnesses agree: undoing it lands the density among real parts
/// ([`SLIP_DENSITY`]), and the stated moments are the geometry's for the value it gives (the
/// tensor worked out right, the mass or the mesh scale typed wrong; for grams, also the whole
/// inertial in grams). A decimal slip of 10 or 100 needs the first kind: a tensor that agrees
/// only in shape fits an undersized collision geometry as well.
fn mass_slip(stated: &MassProperties, computed: &MassProperties, density: f64) -> Option<Finding> {
    let real = |d: f64| (SLIP_DENSITY.0..=SLIP_DENSITY.1).contains(&d);
    if made_up(stated) {
        return None;
    }
    // The computed tensor is at the stated mass: linear in the mass, quadratic in lengths.
    let at_mass = |mass: f64| computed.inertia_com * (mass / stated.mass);
    // The mesh in millimetres makes the volume 10⁹ too large (the density 10⁹ too small) and
    // every moment 10⁶ too large.
    if real(density * 1e9) && agrees(stated, &(computed.inertia_com * 1e-6)) {
        return Some(Finding::LikelyUnitError {
            slip: UnitSlip::MeshInMillimetres,
            stated: density,
            would_be: density * 1e9,
        });
    }
    let mass = stated.mass;
    // Grams: the tensor right for the mass in kilograms, or the whole inertial in grams (the
    // tensor the geometry's at the stated mass: the shape right, the unit of mass wrong).
    let grams_witnessed =
        agrees(stated, &at_mass(mass / 1e3)) || agrees(stated, &computed.inertia_com);
    if real(density / 1e3) && grams_witnessed {
        return Some(Finding::LikelyUnitError {
            slip: UnitSlip::MassInGrams,
            stated: mass,
            would_be: mass / 1e3,
        });
    }
    // Only a mass too large: a density too small is as often an enclosed hollow part.
    [1, 2].into_iter().find_map(|power: i32| {
        let factor = 10f64.powi(power);
        (real(density / factor) && agrees(stated, &at_mass(mass / factor))).then(|| {
            Finding::LikelyUnitError {
                slip: UnitSlip::MassDecimalPoint { power },
                stated: mass,
                would_be: mass / factor,
            }
        })
    })
}

/// Moments stated in kg·mm² or g·mm²: the stated tensor 10⁶ or 10⁹ × the geometry's (at the
/// stated mass), within 50 % once divided; never for moments that look made up (all equal).
fn moment_slip(stated: &MassProperties, computed: &MassProperties) -> Option<Finding> {
    if made_up(stated) || computed.inertia_com.norm() <= 0.0 {
        return None;
    }
    [
        (1e6, UnitSlip::MomentsInKgMm2),
        (1e9, UnitSlip::MomentsInGMm2),
    ]
    .into_iter()
    .find_map(|(factor, slip)| {
        agrees(stated, &(computed.inertia_com * factor)).then(|| Finding::LikelyUnitError {
            slip,
            stated: stated.principal.moments.z,
            would_be: stated.principal.moments.z / factor,
        })
    })
}
