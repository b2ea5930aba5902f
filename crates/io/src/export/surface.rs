//! The body's surface, for the formats that are whole files (`glb`, `usd`, `sdf-model`): its
//! triangles in the body's coordinates (the mesh's, or a body file's in metres), and the file it
//! was read from.

use std::path::{Path, PathBuf};

use massprops::PolyMesh;
use nalgebra::{Isometry3, Point3};

use crate::input::{Parts, Resolved};

/// The triangles of a body's surface and where they came from.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Surface {
    /// Corners, in the body's coordinates and length unit.
    pub points: Vec<Point3<f64>>,
    /// Triangles as indices into `points`, wound outward as the mesh was (polygons as fans).
    pub triangles: Vec<[u32; 3]>,
    /// The file the surface was read from: a mesh, or a body file's meshes (a format that names
    /// meshes by file, SDFormat, names these).
    pub files: Vec<SurfaceFile>,
}

/// One mesh file of a [`Surface`], as a format that refers to it places it.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceFile {
    /// The mesh file.
    pub path: PathBuf,
    /// Its coordinates → the body's: a body file's part placement; identity for a mesh file.
    pub placement: Isometry3<f64>,
    /// Metres per unit of the file's coordinates within the body (a body file's unit; 1 for a
    /// mesh file, whose unit is the body's).
    pub scale: f64,
}

impl SurfaceFile {
    /// The file's path as a file written to `folder` names it: relative to `folder` when it lies
    /// under it, else absolute (as given when it cannot be resolved).
    pub fn named_from(&self, folder: Option<&Path>) -> String {
        let absolute = std::fs::canonicalize(&self.path).unwrap_or_else(|_| self.path.clone());
        let relative = folder
            .and_then(|f| std::fs::canonicalize(f).ok())
            .and_then(|f| absolute.strip_prefix(&f).ok().map(PathBuf::from));
        relative.unwrap_or(absolute).to_string_lossy().into_owned()
    }
}

impl Surface {
    /// The surface of what a file resolved to: its mesh, or each part's placed in the body.
    pub fn of(resolved: &Resolved, path: &Path) -> Self {
        match resolved {
            Resolved::Mesh { file, .. } => Self::of_mesh(&file.mesh, path),
            Resolved::Parts(parts) => Self::of_parts(parts, path),
        }
    }

    /// The surface of one mesh read from `path`, in its own coordinates.
    pub fn of_mesh(mesh: &PolyMesh, path: &Path) -> Self {
        let mut surface = Self::default();
        surface.add(mesh, &Isometry3::identity());
        surface.files.push(SurfaceFile {
            path: path.to_path_buf(),
            placement: Isometry3::identity(),
            scale: 1.0,
        });
        surface
    }

    fn of_parts(parts: &Parts, path: &Path) -> Self {
        let mut surface = Self::default();
        let unit = parts.body_file_units.map_or(1.0, |u| u.metres());
        let folder = path.parent().unwrap_or(Path::new(""));
        for part in &parts.parts {
            // A body file's entries are in metres (its parts' placements included).
            let placement = part.entry.placement(1.0);
            surface.add(&part.mesh, &placement);
            // A body file places each part's mesh: a file placed twice is named twice, and once
            // where its parts (objects of one file) lie alike; a mesh file split into parts is
            // the one file, as it lies.
            if parts.body_file_units.is_some() {
                let file = SurfaceFile {
                    path: folder.join(&part.entry.mesh),
                    placement,
                    scale: unit,
                };
                if !surface.files.contains(&file) {
                    surface.files.push(file);
                }
            } else if surface.files.is_empty() {
                surface.files.push(SurfaceFile {
                    path: path.to_path_buf(),
                    placement: Isometry3::identity(),
                    scale: unit,
                });
            }
        }
        surface
    }

    /// Adds `mesh`'s faces (as fans) moved by `placement`.
    fn add(&mut self, mesh: &PolyMesh, placement: &Isometry3<f64>) {
        let base = self.points.len() as u32;
        self.points
            .extend(mesh.positions().iter().map(|p| placement * p));
        for face in mesh.faces() {
            for k in 1..face.len().saturating_sub(1) {
                self.triangles
                    .push([base + face[0], base + face[k], base + face[k + 1]]);
            }
        }
    }
}
