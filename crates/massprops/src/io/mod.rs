//! Reading meshes from files: Wavefront OBJ and STL, binary or ASCII, by fast paths of our own
//! for the records nearly every file is made of (`obj_fast.rs`, `stl.rs`), and through `tobj`
//! and `stl_io` for every file they decline, with the same result bit for bit. Positions with
//! identical coordinates are welded so per-corner splitting in a file never changes the
//! topology; every object and group of a file forms one body.

mod body;
mod obj;
mod obj_fast;
mod obj_parsed;
mod stl;

use std::path::Path;

pub use body::{BODY_FILE_VERSION, BodyFile, PartEntry, is_body_file};
#[cfg(fuzzing)]
pub use obj::fast_path_agrees;
pub use obj::parse_obj;
pub use stl::parse_stl;

use crate::{Analysis, MassSpec, MeshError, Method, PolyMesh, Repairs, Warning, analyze_with};

/// A mesh read from a file, with what a report needs to name its faces.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MeshFile {
    /// The mesh, positions welded where identical.
    pub mesh: PolyMesh,
    /// The one-based file line of each face (OBJ: its `f` record; ASCII STL: its `facet`); empty
    /// for binary STL, whose face `t` is simply the file's triangle `t`.
    pub face_lines: Vec<u32>,
    /// What the reader skipped (OBJ records of fewer than three corners).
    pub warnings: Vec<Warning>,
    /// The names of the file's parts: OBJ objects (`o`), or groups (`g`) when it has no
    /// objects; ASCII STL `solid` blocks. Empty when the file names none.
    pub part_names: Vec<String>,
    /// For each face, its part (an index into `part_names`); empty when that is.
    pub face_parts: Vec<u32>,
}

impl MeshFile {
    /// [`analyze_with`] on the mesh, with the reader's warnings added in their place.
    pub fn analyze(
        &self,
        method: Method,
        spec: MassSpec,
        repairs: &Repairs,
    ) -> Result<Analysis, MeshError> {
        let mut analysis = analyze_with(&self.mesh, method, spec, repairs)?;
        analysis.add_warnings(self.warnings.iter().cloned());
        Ok(analysis)
    }

    /// The file's parts, each a name and its faces: the named parts (objects, groups, STL
    /// solids), or else the connected shells, named "shell 1", "shell 2", ….
    pub fn parts(&self) -> Vec<(String, Vec<u32>)> {
        if self.face_parts.is_empty() {
            return crate::defects::shell_faces(&self.mesh)
                .into_iter()
                .enumerate()
                .map(|(i, faces)| (format!("shell {}", i + 1), faces))
                .collect();
        }
        let mut parts: Vec<(String, Vec<u32>)> = self
            .part_names
            .iter()
            .map(|n| (n.clone(), Vec::new()))
            .collect();
        for (f, &p) in self.face_parts.iter().enumerate() {
            parts[p as usize].1.push(f as u32);
        }
        parts.retain(|p| !p.1.is_empty());
        parts
    }

    /// The file line of face `f`, when the format has lines.
    pub fn line_of(&self, f: usize) -> Option<usize> {
        self.face_lines.get(f).map(|&l| l as usize)
    }
}

/// Loads an `.obj` or `.stl` file (chosen by extension, case-insensitive) as one body.
///
/// OBJ and binary STL files are read in blocks: the whole file is never in memory at once
/// (unless the OBJ fast path declines it; see [`parse_obj`]).
pub fn load_mesh(path: &Path) -> Result<MeshFile, MeshError> {
    load_mesh_reporting(path, &|_| {})
}

/// [`load_mesh`], calling `progress` with the fraction of the file read so far (0 to 1) after
/// each block.
pub fn load_mesh_reporting(path: &Path, progress: &dyn Fn(f32)) -> Result<MeshFile, MeshError> {
    match extension(path).as_deref() {
        Some("obj") => return obj::load_obj(path, progress),
        Some("stl") => return stl::load_stl(path, progress),
        _ => {}
    }
    let bytes = std::fs::read(path).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source: source.into(),
    })?;
    parse_mesh(&bytes, path)
}

/// Parses a file already in memory; `path` names it in messages and gives the format.
pub fn parse_mesh(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    match extension(path).as_deref() {
        Some("obj") => parse_obj(bytes, path),
        Some("stl") => parse_stl(bytes, path),
        _ => Err(MeshError::UnsupportedFormat {
            path: path.to_path_buf(),
        }),
    }
}

/// The file's extension, lower case.
fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// Every file of extension `ext` (any case) in the workspace and under the folders listed in the
/// environment variable `dirs` (colon-separated: the real-mesh survey's unpacked wheels), for the
/// readers' cross-checks.
#[cfg(test)]
fn test_files(ext: &str, dirs: &str) -> Vec<std::path::PathBuf> {
    fn walk(dir: &Path, ext: &str, out: &mut Vec<std::path::PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() && !path.ends_with("target") {
                walk(&path, ext, out);
            } else if path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case(ext))
            {
                out.push(path);
            }
        }
    }
    let mut files = Vec::new();
    walk(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."),
        ext,
        &mut files,
    );
    for dir in std::env::var(dirs).unwrap_or_default().split(':') {
        if !dir.is_empty() {
            walk(Path::new(dir), ext, &mut files);
        }
    }
    files
}
