//! The findings vocabulary: what can be wrong with a link's stated inertia or its geometry
//! ([`Finding`]), each with its evidence and a stable code, apart from the audit that finds
//! them (`audit.rs`). Every front end words each variant (inertia-io's `report::findings`).

use massprops::{MeshError, Warning};
use nalgebra::{Point3, Vector3};

use crate::model::GeometryKind;

/// Why a stated tensor looks like a placeholder.
#[derive(Debug, Clone, PartialEq)]
pub enum PlaceholderReason {
    /// All three moments equal (and no products), on a link whose geometry is not round, or
    /// that has none to compare with.
    EqualMoments {
        /// The moment.
        moment: f64,
        /// Whether the link's geometry was weighed (and found not round).
        weighed: bool,
    },
    /// Every non-zero entry is a power of ten as written (1, 0.1, 1e-3…).
    RoundNumbers {
        /// The entries as written.
        written: Vec<String>,
    },
    /// The same tensor on other links whose geometry differs.
    SharedTensor {
        /// Those links.
        links: Vec<String>,
    },
}

/// The geometry a proof takes the link's mass to lie in: the larger, the weaker its premise.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Region {
    /// The collision and the visual geometry together (when both are known).
    Both,
    /// Only the kind audited (the other is missing or cannot be read).
    Only(GeometryKind),
}

/// One stated principal moment above its bound m·r².
#[derive(Debug, Clone, PartialEq)]
pub struct ImpossibleAxis {
    /// Which moment (0, 1, 2: ascending).
    pub rank: usize,
    /// The stated moment.
    pub moment: f64,
    /// m·r².
    pub bound: f64,
    /// r: the geometry's farthest distance from that principal axis through the stated centre
    /// of mass.
    pub radius: f64,
    /// The principal axis, link frame.
    pub axis: Vector3<f64>,
}

/// Something wrong with a link's stated inertia or its geometry, with its evidence. Every front
/// end matches it without a wildcard arm, so a new variant does not compile until each has its
/// words and JSON data.
#[derive(Debug, Clone)]
pub enum Finding {
    /// No `<inertial>` (URDF, SDFormat), on a link that has geometry or moves, or one without
    /// its `<mass>` or `<inertia>`.
    MissingInertial {
        /// Whether the link has a degree of freedom.
        moving: bool,
        /// The element an `<inertial>` written without it lacks (`mass`, `inertia`).
        incomplete: Option<&'static str>,
    },
    /// A negative mass, or zero on a moving link.
    NonpositiveMass {
        /// The stated mass.
        mass: f64,
    },
    /// A principal moment ≤ 0.
    NotPositiveDefinite {
        /// The stated principal moments, ascending.
        moments: [f64; 3],
    },
    /// I₁ + I₂ < I₃.
    TriangleInequality {
        /// The stated principal moments, ascending.
        moments: [f64; 3],
    },
    /// Stated principal moments above m·r², which no distribution of the stated mass within
    /// the geometry reaches.
    ImpossibleMoment {
        /// The geometry the mass is taken to lie in.
        region: Region,
        /// The stated mass.
        mass: f64,
        /// Each moment above its bound.
        axes: Vec<ImpossibleAxis>,
    },
    /// The stated centre of mass outside the geometry's hull.
    ComOutsideGeometry {
        /// The geometry the mass is taken to lie in.
        region: Region,
        /// The stated centre, link frame.
        center_of_mass: Point3<f64>,
        /// How far outside the 26-sided polytope around the hull, at least, m.
        distance: f64,
    },
    /// A stated value off from the geometry's by a power of ten that a unit slip explains: the
    /// value it would have, once the slip is undone, is plausible.
    LikelyUnitError {
        /// Which slip.
        slip: UnitSlip,
        /// The stated value (kg for the mass, kg·m² for the largest moment), or for a mesh in
        /// millimetres the density it gives, kg/m³.
        stated: f64,
        /// The value with the slip undone, in the same unit.
        would_be: f64,
    },
    /// The stated centre of mass is the geometry's centre written in a geometry's own frame
    /// (its mesh's origin, say) rather than in the link's: placed by that geometry's origin,
    /// it would be the geometry's centre.
    CenterInGeometryFrame {
        /// The geometry, as [`crate::Shape::label`] names it.
        geometry: String,
        /// The stated centre, link frame.
        stated: Point3<f64>,
        /// The stated centre placed by the geometry's origin: the centre it likely means.
        would_be: Point3<f64>,
    },
    /// The stated tensor looks like a placeholder.
    Placeholder {
        /// Why.
        reasons: Vec<PlaceholderReason>,
    },
    /// The stated mass over the geometry's volume is outside [`PLAUSIBLE_DENSITY`](crate::audit::PLAUSIBLE_DENSITY).
    ImplausibleDensity {
        /// kg/m³.
        density: f64,
        /// The geometry's volume, m³.
        volume: f64,
        /// The stated mass.
        mass: f64,
    },
    /// The stated mass or centre differs from the measured one (more than 1 % of the mass,
    /// or of the link's size).
    DiffersFromMeasured {
        /// The stated mass, kg.
        stated_mass: f64,
        /// The measured mass, kg, when it differs.
        measured_mass: Option<f64>,
        /// The measured centre (link frame) and its distance from the stated one, m, when
        /// they differ.
        measured_center: Option<(Point3<f64>, f64)>,
    },
    /// The stated tensor is farther from the uniform-density one than the threshold.
    MomentsFar {
        /// The relative error.
        error: f64,
        /// The threshold given.
        threshold: f64,
    },
    /// The stated centre of mass is farther from the uniform-density one than the threshold.
    ComFar {
        /// The offset as a fraction of the link's size.
        fraction: f64,
        /// The threshold given.
        threshold: f64,
    },
    /// A mesh file that is not there.
    MeshMissing {
        /// As written.
        written: String,
        /// Every path tried.
        tried: Vec<std::path::PathBuf>,
    },
    /// A mesh that cannot be read, or encloses no volume.
    MeshUnreadable {
        /// The file.
        file: std::path::PathBuf,
        /// Why.
        error: MeshError,
    },
    /// A geometry the audit does not integrate.
    GeometryUnsupported {
        /// What it is.
        what: String,
    },
    /// A defect of one of the link's meshes, as `props` reports it.
    MeshDefect {
        /// The geometry, as [`crate::Shape::label`] names it.
        geometry: String,
        /// The warning.
        warning: Warning,
    },
}

impl Finding {
    /// Its stable code, as in JSON: the codes of this module, or the mesh warning's own.
    pub fn code(&self) -> &'static str {
        match self {
            Finding::MissingInertial { .. } => "missing_inertial",
            Finding::NonpositiveMass { .. } => "nonpositive_mass",
            Finding::NotPositiveDefinite { .. } => "not_positive_definite",
            Finding::TriangleInequality { .. } => "triangle_inequality",
            Finding::ImpossibleMoment { .. } => "impossible_moment",
            Finding::ComOutsideGeometry { .. } => "com_outside_geometry",
            Finding::Placeholder { .. } => "placeholder",
            Finding::LikelyUnitError { .. } => "likely_unit_error",
            Finding::CenterInGeometryFrame { .. } => "center_in_geometry_frame",
            Finding::ImplausibleDensity { .. } => "implausible_density",
            Finding::DiffersFromMeasured { .. } => "differs_from_measured",
            Finding::MomentsFar { .. } => "moments_far",
            Finding::ComFar { .. } => "com_far",
            Finding::MeshMissing { .. } => "mesh_missing",
            Finding::MeshUnreadable { .. } => "mesh_unreadable",
            Finding::GeometryUnsupported { .. } => "geometry_unsupported",
            Finding::MeshDefect { warning, .. } => warning.code(),
        }
    }

    /// How bad it is: 0 (a proof that the stated inertia is impossible) to 8 (a mesh defect).
    pub fn severity(&self) -> u8 {
        match self {
            Finding::ImpossibleMoment { .. } | Finding::ComOutsideGeometry { .. } => 0,
            Finding::NotPositiveDefinite { .. } | Finding::TriangleInequality { .. } => 1,
            Finding::NonpositiveMass { .. } => 2,
            Finding::MissingInertial { .. } => 3,
            Finding::Placeholder { .. }
            | Finding::LikelyUnitError { .. }
            | Finding::CenterInGeometryFrame { .. } => 4,
            Finding::ImplausibleDensity { .. } | Finding::DiffersFromMeasured { .. } => 5,
            Finding::MomentsFar { .. } | Finding::ComFar { .. } => 6,
            Finding::MeshMissing { .. }
            | Finding::MeshUnreadable { .. }
            | Finding::GeometryUnsupported { .. } => 7,
            Finding::MeshDefect { .. } => 8,
        }
    }

    /// Whether it says the stated inertial is wrong (the links `--fix-links flagged` changes),
    /// rather than something about the geometry.
    pub fn flags_inertial(&self) -> bool {
        self.severity() <= 6
    }
}

/// A unit or typing slip that puts a stated value a power of ten from the geometry's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnitSlip {
    /// The mass written in grams (1000 × the kilograms).
    MassInGrams,
    /// The mass with its decimal point one or two places to the right (`power`: the stated
    /// mass is 10^power × the plausible one; 1 or 2).
    MassDecimalPoint {
        /// The power of ten.
        power: i32,
    },
    /// The mesh's coordinates in millimetres, read as metres: a volume 10⁹ too large.
    MeshInMillimetres,
    /// The moments in kg·mm² (10⁶ × kg·m²).
    MomentsInKgMm2,
    /// The moments in g·mm² (10⁹ × kg·m²).
    MomentsInGMm2,
}
