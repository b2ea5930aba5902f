//! Reading meshes from files: Wavefront OBJ (through `tobj`) and STL, binary or ASCII (through
//! `stl_io`). Positions with identical coordinates are welded so per-corner splitting in a file
//! never changes the topology; every object and group of a file forms one body.

mod obj;
mod stl;

use std::path::Path;

pub use obj::parse_obj;
pub use stl::parse_stl;

use crate::{MeshError, PolyMesh};

/// Loads an `.obj` or `.stl` file (chosen by extension, case-insensitive) as one body.
pub fn load_mesh(path: &Path) -> Result<PolyMesh, MeshError> {
    let bytes = std::fs::read(path).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse_mesh(&bytes, path)
}

/// Parses a file already in memory; `path` names it in messages and gives the format.
pub fn parse_mesh(bytes: &[u8], path: &Path) -> Result<PolyMesh, MeshError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("obj") => parse_obj(bytes, path),
        Some("stl") => parse_stl(bytes, path),
        _ => Err(MeshError::UnsupportedFormat {
            path: path.to_path_buf(),
        }),
    }
}
