//! A link's geometry made ready to weigh: each mesh read once and integrated once at unit
//! density through massprops' defect pass (the same as `inertia-lab props`), each primitive in
//! closed form; and the extent of every geometry (its support function and its farthest point
//! from a line), which the impossibility bound and the hull test need.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use nalgebra::{Isometry3, Point3, Vector3};
use rayon::prelude::*;

use massprops::{Fill, IntegratedPart, MassProperties, MeshError, Repairs, Warning};

use crate::model::{Geometry, Shape};
use crate::primitives;

/// A mesh file as read, scaled, and integrated.
#[derive(Debug)]
pub struct LoadedMesh {
    /// Its points (those the faces use), scaled, in the mesh's frame.
    pub points: Vec<Point3<f64>>,
    /// Its solid at density 1, or why it has none; `None` when only its points were wanted.
    pub unit: Option<Result<MassProperties, MeshError>>,
    /// What the mesh has wrong (the reader's and the defect pass's warnings).
    pub warnings: Vec<Warning>,
}

/// The meshes of a robot, read once each: file and scale → the mesh, or why it cannot be read.
pub type Meshes = HashMap<(PathBuf, [u64; 3]), Arc<Result<LoadedMesh, MeshError>>>;

fn key(file: &std::path::Path, scale: &Vector3<f64>) -> (PathBuf, [u64; 3]) {
    (
        file.to_owned(),
        [scale.x.to_bits(), scale.y.to_bits(), scale.z.to_bits()],
    )
}

/// What [`load_meshes`] reads of one mesh: its points always, its integrals when `weigh`.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshUse {
    /// The file.
    pub file: PathBuf,
    /// Its per-axis scale.
    pub scale: Vector3<f64>,
    /// Whether it is weighed (integrated, its defects found), or only its points are needed.
    pub weigh: bool,
}

/// Reads every mesh of `uses` once, in parallel; integrates those that are weighed.
pub fn load_meshes(uses: &[MeshUse], repairs: &Repairs) -> Meshes {
    let mut wanted: Vec<MeshUse> = Vec::new();
    for u in uses {
        match wanted
            .iter_mut()
            .find(|w| w.file == u.file && w.scale == u.scale)
        {
            Some(w) => w.weigh |= u.weigh,
            None => wanted.push(u.clone()),
        }
    }
    wanted
        .par_iter()
        .map(|u| (key(&u.file, &u.scale), Arc::new(load(u, repairs))))
        .collect()
}

fn load(u: &MeshUse, repairs: &Repairs) -> Result<LoadedMesh, MeshError> {
    let read = massprops::load_mesh(&u.file)?;
    let scale = u.scale;
    let mesh = if scale == Vector3::repeat(1.0) {
        read.mesh
    } else {
        read.mesh
            .map_positions(|p| Point3::from(p.coords.component_mul(&scale)))?
    };
    let points = mesh.used_positions().collect();
    if !u.weigh {
        return Ok(LoadedMesh {
            points,
            unit: None,
            warnings: Vec::new(),
        });
    }
    let integrated = IntegratedPart::new(&mesh, repairs);
    let unit = integrated
        .properties("mesh", Fill::Solid { density: 1.0 }, &Isometry3::identity())
        .map(|p| MassProperties::new(p.mass, p.center_of_mass, p.inertia_com));
    let mut warnings = read.warnings;
    warnings.extend(
        integrated
            .warnings(Fill::Solid { density: 1.0 })
            .iter()
            .cloned(),
    );
    Ok(LoadedMesh {
        points,
        unit: Some(unit),
        warnings,
    })
}

/// One geometry ready to weigh: its unit-density solid in the link's frame, or why it has none,
/// and its extent.
#[derive(Debug, Clone)]
pub struct Ready<'a> {
    /// The geometry.
    pub geometry: &'a Geometry,
    /// Its solid at density 1 in the link's frame (mass = volume), or why there is none.
    pub unit: Result<MassProperties, Problem>,
    /// Its extent, when its points are known (a mesh that encloses no volume still has them).
    pub extent: Option<Extent<'a>>,
    /// What its mesh has wrong.
    pub warnings: Vec<Warning>,
}

/// Why a geometry cannot be weighed.
#[derive(Debug, Clone)]
pub enum Problem {
    /// Its mesh file is not where the description says.
    Missing {
        /// As written.
        written: String,
        /// Every path tried.
        tried: Vec<PathBuf>,
    },
    /// Its mesh cannot be read or encloses no volume.
    Mesh {
        /// The file.
        file: PathBuf,
        /// Why.
        error: MeshError,
    },
    /// It is a shape the audit does not integrate.
    Unsupported {
        /// What it is.
        what: String,
    },
}

/// The region a geometry occupies, in its link's frame.
#[derive(Debug, Clone)]
pub enum Extent<'a> {
    /// A primitive, placed.
    Primitive {
        /// Its shape.
        shape: &'a Shape,
        /// Shape frame → link frame.
        pose: Isometry3<f64>,
    },
    /// A mesh's points, placed.
    Points {
        /// In the mesh's frame.
        points: &'a [Point3<f64>],
        /// Mesh frame → link frame.
        pose: Isometry3<f64>,
    },
}

impl Extent<'_> {
    /// max over the region of n·x (link frame).
    pub fn support(&self, n: &Vector3<f64>) -> f64 {
        match self {
            Extent::Primitive { shape, pose } => {
                let local = pose.rotation.inverse() * n;
                primitives::support(shape, &local).unwrap_or(f64::NAN)
                    + n.dot(&pose.translation.vector)
            }
            Extent::Points { points, pose } => {
                let local = pose.rotation.inverse() * n;
                points
                    .iter()
                    .map(|p| local.dot(&p.coords))
                    .fold(f64::NEG_INFINITY, f64::max)
                    + n.dot(&pose.translation.vector)
            }
        }
    }

    /// Points (link frame) whose convex hull contains the region.
    pub fn hull_points(&self) -> Vec<Point3<f64>> {
        match self {
            Extent::Primitive { shape, pose } => primitives::hull_points(shape)
                .unwrap_or_default()
                .iter()
                .map(|p| pose * p)
                .collect(),
            Extent::Points { points, pose } => points.iter().map(|p| pose * p).collect(),
        }
    }

    /// An upper bound (exact for points, boxes, spheres, capsules) of the distance of the
    /// region's farthest point from the line through `point` along unit `direction`.
    pub fn farthest_from_line(&self, point: &Point3<f64>, direction: &Vector3<f64>) -> f64 {
        match self {
            Extent::Primitive { shape, pose } => {
                let local_point = pose.inverse_transform_point(point);
                let local_direction = pose.rotation.inverse() * direction;
                primitives::farthest_from_line(shape, &local_point, &local_direction)
                    .unwrap_or(f64::NAN)
            }
            Extent::Points { points, pose } => {
                let local_point = pose.inverse_transform_point(point);
                let d = pose.rotation.inverse() * direction;
                points
                    .iter()
                    .map(|p| {
                        let v = p - local_point;
                        (v - d * d.dot(&v)).norm_squared()
                    })
                    .fold(0.0, f64::max)
                    .sqrt()
            }
        }
    }
}

/// `geometry` made ready with the meshes read.
pub fn ready<'a>(geometry: &'a Geometry, meshes: &'a Meshes) -> Ready<'a> {
    let pose = geometry.pose;
    match &geometry.shape {
        Shape::Mesh { file, scale } => match meshes.get(&key(file, scale)).map(|m| m.as_ref()) {
            Some(Ok(mesh)) => Ready {
                geometry,
                unit: match &mesh.unit {
                    Some(Ok(u)) => Ok(u.transformed(&pose)),
                    Some(Err(e)) => Err(Problem::Mesh {
                        file: file.clone(),
                        error: e.clone(),
                    }),
                    None => Err(Problem::Unsupported {
                        what: format!("mesh {} was not weighed", file.display()),
                    }),
                },
                extent: Some(Extent::Points {
                    points: &mesh.points,
                    pose,
                }),
                warnings: mesh.warnings.clone(),
            },
            Some(Err(error)) => Ready {
                geometry,
                unit: Err(Problem::Mesh {
                    file: file.clone(),
                    error: error.clone(),
                }),
                extent: None,
                warnings: Vec::new(),
            },
            None => Ready {
                geometry,
                unit: Err(Problem::Unsupported {
                    what: format!("mesh {} was not loaded", file.display()),
                }),
                extent: None,
                warnings: Vec::new(),
            },
        },
        Shape::MissingMesh { written, tried } => Ready {
            geometry,
            unit: Err(Problem::Missing {
                written: written.clone(),
                tried: tried.clone(),
            }),
            extent: None,
            warnings: Vec::new(),
        },
        Shape::Unsupported { what } => Ready {
            geometry,
            unit: Err(Problem::Unsupported { what: what.clone() }),
            extent: None,
            warnings: Vec::new(),
        },
        shape => Ready {
            geometry,
            unit: primitives::unit_properties(shape)
                .map(|u| u.transformed(&pose))
                .ok_or_else(|| Problem::Unsupported {
                    what: shape.label(),
                }),
            extent: Some(Extent::Primitive { shape, pose }),
            warnings: Vec::new(),
        },
    }
}
