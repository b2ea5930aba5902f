//! # robot — robot descriptions audited against their geometry
//!
//! Reads a URDF, an MJCF or an SDFormat description into plain data ([`Robot`]: links with their stated
//! `<inertial>` and their geometries, placed at the zero pose), weighs every link's geometry
//! exactly (meshes by massprops' integrals and defect pass, primitives in closed form,
//! [`primitives`]), compares the two and names what is wrong ([`audit()`]: findings with their
//! evidence, two of them proofs of impossibility), and writes the description back with chosen
//! `<inertial>`s replaced and every other byte kept ([`fix::splice`]).
//!
//! Conventions: SI units (m, kg, kg·m²), tensors about the centre of mass in the link's axes,
//! off-diagonals −∑m·x·y (URDF's ixy and MJCF's fullinertia M12 are these entries).
//!
//! ```
//! use robot::{AuditOptions, ReadOptions, audit, read_str};
//! let urdf = r#"<robot name="r"><link name="finger">
//!   <inertial><mass value="0.1"/>
//!     <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
//!   <collision><geometry><box size="0.02 0.02 0.05"/></geometry></collision>
//! </link></robot>"#;
//! let robot = read_str(urdf, "finger.urdf".as_ref(), &ReadOptions::default()).unwrap();
//! let report = audit(&robot, &AuditOptions::default());
//! let codes: Vec<&str> = report.links[0].findings.iter().map(|f| f.code()).collect();
//! // 0.1 kg·m² on 0.1 kg needs mass 1 m from the axis; the box reaches 3 cm.
//! assert!(codes.contains(&"impossible_moment"));
//! assert!(codes.contains(&"placeholder"));
//! ```

mod audit;
mod error;
mod findings;
pub mod fix;
pub mod geometry;
mod masses;
mod mjcf;
mod model;
pub mod nearest;
mod paths;
pub mod primitives;
mod sdf;
mod urdf;
pub mod xacro;
mod xml;

use std::path::{Path, PathBuf};

pub use audit::{
    Audit, AuditOptions, Computed, InertialComparison, LinkAudit, MassBasis, PLAUSIBLE_DENSITY,
    Unweighed, audit,
};
pub use error::{Location, RobotError};
pub use findings::{Finding, ImpossibleAxis, PlaceholderReason, Region, UnitSlip};
pub use masses::{MassesError, Measured, MeasuredMasses, parse_csv, parse_toml, read_masses};
pub use model::{
    AutoInertial, DescriptionFormat, Geometry, GeometryKind, GeometryMass, Inertial, Link, Robot,
    Shape, Span, Unsupported,
};
pub use xml::{Leniency, SourceFile, unexpanded_substitution};

/// How to find what a description refers to.
#[derive(Debug, Clone, Default)]
pub struct ReadOptions {
    /// `package://NAME/…` (and SDFormat's `model://NAME/…`) → a folder, tried before the
    /// resource path and before searching upwards from the file.
    pub packages: Vec<(String, PathBuf)>,
    /// Folders holding model folders, searched for `model://NAME` and `package://NAME` (what
    /// Gazebo reads from `GZ_SIM_RESOURCE_PATH` and `SDF_PATH`).
    pub resource_paths: Vec<PathBuf>,
    /// Arguments for xacro (`NAME:=VALUE`), when a description is a xacro file.
    pub xacro_args: Vec<(String, String)>,
}

/// The environment variables whose folders Gazebo searches for `model://NAME`, newest first.
pub const RESOURCE_PATH_VARIABLES: &[&str] = &[
    "GZ_SIM_RESOURCE_PATH",
    "SDF_PATH",
    "IGN_GAZEBO_RESOURCE_PATH",
    "GAZEBO_MODEL_PATH",
];

/// The folders that [`RESOURCE_PATH_VARIABLES`] name in this process's environment, in order
/// (for [`ReadOptions::resource_paths`]).
pub fn resource_paths_from_env() -> Vec<PathBuf> {
    RESOURCE_PATH_VARIABLES
        .iter()
        .filter_map(std::env::var_os)
        .flat_map(|v| std::env::split_paths(&v).collect::<Vec<_>>())
        .filter(|p| !p.as_os_str().is_empty())
        .collect()
}

/// Reads the URDF, MJCF or SDFormat description at `path`.
/// A xacro file (an element in xacro's namespace, or a `${…}`/`$(…)` substitution) is
/// expanded by the `xacro` tool first ([`xacro::expand`]); [`Robot::xacro`] then says from what.
pub fn read(path: &Path, options: &ReadOptions) -> Result<Robot, RobotError> {
    let text = xml::read_file(path)?;
    match read_str(&text, path, options) {
        Err(RobotError::Xacro { .. }) => {
            let expanded = xacro::expand(path, options)?;
            let mut robot = read_str(&expanded.text, path, options)?;
            robot.xacro = Some(expanded.xacro);
            Ok(robot)
        }
        other => other,
    }
}

/// Reads a description from its text, as if from `path` (relative files are found beside it).
pub fn read_str(text: &str, path: &Path, options: &ReadOptions) -> Result<Robot, RobotError> {
    let (root, read_leniently) = xml::parse(text, path, 0)?;
    if let Some((e, what)) = root.xacro() {
        return Err(RobotError::Xacro {
            file: path.to_owned(),
            line: e.at.line,
            what,
        });
    }
    let sources = vec![SourceFile {
        path: path.to_owned(),
        text: text.to_owned(),
        read_leniently,
    }];
    match root.name.as_str() {
        "robot" => urdf::read(&root, sources, options),
        "mujoco" | "mujocoinclude" => mjcf::read(&root, sources),
        "sdf" => sdf::read(&root, sources, options),
        other => Err(RobotError::UnknownFormat {
            file: path.to_owned(),
            root: other.to_owned(),
        }),
    }
}
