//! A robot description as plain data: links (URDF and SDFormat links, MJCF bodies) with their stated
//! inertials and their geometries, each placed in its link's frame, and each link placed in the
//! robot's frame at the zero pose. Both readers build this; the audit and the fix read only it.

use std::ops::Range;
use std::path::PathBuf;

use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

use crate::error::Location;
use crate::xml::SourceFile;

/// Which format a description is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DescriptionFormat {
    /// ROS URDF (`<robot>`).
    Urdf,
    /// MuJoCo MJCF (`<mujoco>`).
    Mjcf,
    /// Gazebo's SDFormat (`<sdf>`).
    Sdf,
}

impl DescriptionFormat {
    /// Its name, as in reports.
    pub fn name(self) -> &'static str {
        match self {
            DescriptionFormat::Urdf => "urdf",
            DescriptionFormat::Mjcf => "mjcf",
            DescriptionFormat::Sdf => "sdf",
        }
    }
}

/// A robot: its links, and the files it was read from.
#[derive(Debug, Clone)]
pub struct Robot {
    /// The model's name (`<robot name>`, `<mujoco model>`), or the file's stem.
    pub name: String,
    /// The format read.
    pub format: DescriptionFormat,
    /// The files read: the description first, then each file it includes.
    pub sources: Vec<SourceFile>,
    /// The links, parents before children, in file order otherwise.
    pub links: Vec<Link>,
    /// What the file holds that this reader does not model and that can change masses or
    /// geometry (MJCF): named, never skipped silently.
    pub unsupported: Vec<Unsupported>,
    /// MJCF: the compiler computes every body's inertia from its geoms
    /// (`inertiafromgeom="true"`), ignoring the `<inertial>` elements.
    pub inertia_from_geoms: bool,
    /// A xacro description: the files and arguments xacro expanded it from; `sources[0]` then
    /// holds the expansion (its lines are the expansion's), not a file of the user's.
    pub xacro: Option<crate::xacro::Xacro>,
}

/// Something in a description that the reader does not model.
#[derive(Debug, Clone, PartialEq)]
pub struct Unsupported {
    /// Where it is.
    pub at: Location,
    /// The element (`geom`, `compiler`, `flexcomp`…).
    pub element: String,
    /// What is not supported, and what that means for the audit.
    pub what: String,
}

/// The part of a file an element spans: its file and bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Span {
    /// An index into [`Robot::sources`].
    pub file: usize,
    /// The element's bytes, start tag to end tag.
    pub range: Range<usize>,
    /// Where it starts, for messages.
    pub at: Location,
}

/// One rigid link (URDF `<link>`, MJCF `<body>`).
#[derive(Debug, Clone)]
pub struct Link {
    /// Its name (MJCF bodies without one are named by their place, `body 3`).
    pub name: String,
    /// Its parent link, if any.
    pub parent: Option<usize>,
    /// Link frame → robot frame at the zero pose (every joint at zero).
    pub pose: Isometry3<f64>,
    /// Whether it has a degree of freedom of its own (a URDF joint that is not `fixed`, an MJCF
    /// body with a joint).
    pub moving: bool,
    /// The `<inertial>` as the file states it, if it has one.
    pub stated: Option<Inertial>,
    /// SDFormat's `<inertial auto="true">`: the simulator computes the inertial from the
    /// collisions (their densities in [`Geometry::mass`]); `stated` is then `None`.
    pub auto_inertial: Option<AutoInertial>,
    /// A URDF `<inertial>` without its `<mass>` or `<inertia>` (yourdfpy reads the file, urdfdom
    /// refuses it); `stated` is then `None`, and the fix replaces this element.
    pub incomplete_inertial: Option<IncompleteInertial>,
    /// The `<link>`/`<body>` element, where the fix inserts a missing `<inertial>`.
    pub element: Span,
    /// Collision geometry (URDF `<collision>`; MJCF geoms that can collide).
    pub collision: Vec<Geometry>,
    /// Visual geometry (URDF `<visual>`; MJCF geoms with `contype` and `conaffinity` zero).
    pub visual: Vec<Geometry>,
}

/// An `<inertial auto="true">` (SDFormat 1.11): computed by the simulator from the collisions.
#[derive(Debug, Clone, PartialEq)]
pub struct AutoInertial {
    /// The `<mass>` written, which the computed inertial is scaled to (libsdformat 15.2).
    pub mass: Option<f64>,
    /// Where it is written.
    pub at: Location,
}

/// An `<inertial>` that lacks an element the format requires.
#[derive(Debug, Clone, PartialEq)]
pub struct IncompleteInertial {
    /// The element it lacks: `mass` or `inertia`.
    pub missing: &'static str,
    /// The `<inertial>`, for the fix.
    pub span: Span,
}

/// A stated `<inertial>`, converted to one convention: the tensor about the centre of mass in
/// the link's axes, off-diagonals −∑m·x·y, SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct Inertial {
    /// kg.
    pub mass: f64,
    /// Centre of mass, link frame, m.
    pub center_of_mass: Point3<f64>,
    /// Tensor about the centre of mass, link axes, kg·m².
    pub inertia: Matrix3<f64>,
    /// The tensor's numbers as the file writes them (for spotting placeholders such as `0.1`).
    pub written: Vec<String>,
    /// The element, for the fix.
    pub span: Span,
}

/// One geometry of a link, placed in the link's frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    /// Its shape, in its own frame.
    pub shape: Shape,
    /// Geometry frame → link frame.
    pub pose: Isometry3<f64>,
    /// What the file says of its mass (MJCF geoms only).
    pub mass: GeometryMass,
    /// Where it is written.
    pub at: Location,
}

/// How a geometry's mass is given in the file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GeometryMass {
    /// Not at all (URDF): the link's mass or the audit's density decides.
    Unstated,
    /// A density, kg/m³ (MJCF `density`, 1000 when not written).
    Density(f64),
    /// A mass, kg (MJCF `mass`).
    Mass(f64),
}

/// A geometry's shape, in its own frame; primitives centred on the origin, their axis along z.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A box of these half-sides.
    Box {
        /// Half the side along each axis, m.
        half_extents: Vector3<f64>,
    },
    /// A ball.
    Sphere {
        /// m.
        radius: f64,
    },
    /// A circular cylinder along z.
    Cylinder {
        /// m.
        radius: f64,
        /// Half its length, m.
        half_length: f64,
    },
    /// A cylinder along z with a hemisphere on each end.
    Capsule {
        /// m.
        radius: f64,
        /// Half the length of its cylindrical part, m.
        half_length: f64,
    },
    /// An ellipsoid with these semi-axes.
    Ellipsoid {
        /// Semi-axes along x, y, z, m.
        radii: Vector3<f64>,
    },
    /// A mesh file, its coordinates multiplied by `scale` per axis.
    Mesh {
        /// The file found.
        file: PathBuf,
        /// Per-axis scale.
        scale: Vector3<f64>,
    },
    /// A mesh file that is not where the description says.
    MissingMesh {
        /// The file name as written.
        written: String,
        /// Every path tried, in order.
        tried: Vec<PathBuf>,
    },
    /// A geometry the audit cannot integrate (a height field, a plane…).
    Unsupported {
        /// What it is.
        what: String,
    },
}

impl Shape {
    /// A short description: "box 0.1 × 0.2 × 0.3 m", "mesh finger.obj".
    pub fn label(&self) -> String {
        match self {
            Shape::Box { half_extents: h } => {
                format!("box {} x {} x {} m", 2.0 * h.x, 2.0 * h.y, 2.0 * h.z)
            }
            Shape::Sphere { radius } => format!("sphere r {radius} m"),
            Shape::Cylinder {
                radius,
                half_length,
            } => format!("cylinder r {radius} m, length {} m", 2.0 * half_length),
            Shape::Capsule {
                radius,
                half_length,
            } => format!("capsule r {radius} m, length {} m", 2.0 * half_length),
            Shape::Ellipsoid { radii: r } => format!("ellipsoid {} x {} x {} m", r.x, r.y, r.z),
            Shape::Mesh { file, .. } => format!(
                "mesh {}",
                file.file_name().map_or_else(
                    || file.display().to_string(),
                    |n| n.to_string_lossy().into_owned()
                )
            ),
            Shape::MissingMesh { written, .. } => format!("mesh {written} (missing)"),
            Shape::Unsupported { what } => what.clone(),
        }
    }
}

/// Which geometry of a link stands for its shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GeometryKind {
    /// Collision geometry (the default: usually closed, often simplified).
    #[default]
    Collision,
    /// Visual geometry (detailed; often open or made of several shells).
    Visual,
}

impl GeometryKind {
    /// Its name, as in reports.
    pub fn name(self) -> &'static str {
        match self {
            GeometryKind::Collision => "collision",
            GeometryKind::Visual => "visual",
        }
    }
}

impl Link {
    /// The geometries of `kind`.
    pub fn geometry(&self, kind: GeometryKind) -> &[Geometry] {
        match kind {
            GeometryKind::Collision => &self.collision,
            GeometryKind::Visual => &self.visual,
        }
    }
}
