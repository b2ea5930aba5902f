//! STL, binary or ASCII, through `stl_io`; vertices (f32 in the format) are welded exactly.

use std::io::Cursor;
use std::path::Path;

use nalgebra::Point3;

use crate::mesh::weld_exact;
use crate::{MeshError, PolyMesh};

/// Parses STL bytes into a welded triangle mesh.
pub fn parse_stl(bytes: &[u8], path: &Path) -> Result<PolyMesh, MeshError> {
    let malformed = |message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line: None,
        message,
    };
    let mut cursor = Cursor::new(bytes);
    let reader = stl_io::create_stl_reader(&mut cursor)
        .map_err(|e| malformed(format!("not a readable STL file: {e}")))?;
    let mut corners = Vec::new();
    for (t, triangle) in reader.enumerate() {
        let triangle =
            triangle.map_err(|e| malformed(format!("triangle {t} cannot be read: {e}")))?;
        corners.extend(
            triangle
                .vertices
                .iter()
                .map(|v| Point3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]))),
        );
    }
    let (positions, remap) = weld_exact(&corners);
    let triangles: Vec<[u32; 3]> = remap
        .as_chunks::<3>()
        .0
        .to_vec();
    PolyMesh::from_triangles(positions, &triangles).map_err(|e| MeshError::InFile {
        path: path.to_path_buf(),
        line: None,
        source: Box::new(e),
    })
}
