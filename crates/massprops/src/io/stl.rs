//! STL, binary or ASCII, through `stl_io`; vertices (f32 in the format) are welded exactly.

use std::io::Cursor;
use std::path::Path;

use nalgebra::Point3;

use super::MeshFile;
use crate::mesh::weld_exact;
use crate::{MeshError, PolyMesh};

/// Parses STL bytes into a welded triangle mesh. Face `t` is the file's triangle `t`; for ASCII
/// files, each face's line is that of its `facet`.
pub fn parse_stl(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let malformed = |message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line: None,
        message,
    };
    let ascii = is_ascii(bytes);
    // A byte-order mark before `solid` (Windows editors) would hide the ASCII keyword.
    let bytes = match bytes.strip_prefix(b"\xEF\xBB\xBF") {
        Some(rest) if ascii => rest,
        _ => bytes,
    };
    if !ascii {
        check_binary_length(bytes).map_err(malformed)?;
    }
    let patched = patch_for_detection(bytes);
    let mut cursor = Cursor::new(patched.as_deref().unwrap_or(bytes));
    let reader = stl_io::create_stl_reader(&mut cursor)
        .map_err(|e| malformed(format!("not a readable STL file: {e}")))?;
    let mut corners = Vec::new();
    for (t, triangle) in reader.enumerate() {
        let triangle = triangle.map_err(|e| {
            malformed(format!(
                "triangle {t} (counting from 0) cannot be read: {e}"
            ))
        })?;
        // Checked here, where the triangle is still known: after welding only an index is.
        if let Some((corner, value)) = triangle
            .vertices
            .iter()
            .enumerate()
            .find_map(|(c, v)| v.0.into_iter().find(|x| !x.is_finite()).map(|x| (c, x)))
        {
            return Err(malformed(format!(
                "triangle {t} (counting from 0), corner {corner}: non-finite coordinate {value}"
            )));
        }
        corners.extend(
            triangle
                .vertices
                .iter()
                .map(|v| Point3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]))),
        );
    }
    let (positions, remap) = weld_exact(&corners);
    let triangles: Vec<[u32; 3]> = remap.as_chunks::<3>().0.to_vec();
    let mesh = PolyMesh::from_triangles(positions, &triangles).map_err(|e| MeshError::InFile {
        path: path.to_path_buf(),
        line: None,
        source: Box::new(e),
    })?;
    let face_lines = if ascii {
        facet_lines(bytes)
    } else {
        Vec::new()
    };
    Ok(MeshFile {
        mesh,
        face_lines,
        warnings: Vec::new(),
    })
}

/// Whether the bytes are an ASCII STL: they open with `solid` (after an optional byte-order
/// mark) and their first kilobyte holds no NUL byte. A binary STL's 80-byte header may also
/// open with `solid` (many CAD exporters write one), but its triangle count and attribute bytes
/// are all but certain to hold a zero byte.
fn is_ascii(bytes: &[u8]) -> bool {
    let text = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    text.starts_with(b"solid") && !text[..text.len().min(1024)].contains(&0)
}

/// The one-based line of each `facet` keyword, in order.
fn facet_lines(bytes: &[u8]) -> Vec<u32> {
    bytes
        .split(|&b| b == b'\n')
        .enumerate()
        .filter(|(_, line)| line.trim_ascii_start().starts_with(b"facet"))
        .map(|(i, _)| (i + 1) as u32)
        .collect()
}

/// A binary STL is an 84-byte header, whose last four bytes
/// count the triangles, then 50 bytes a triangle. A file cut short (an interrupted download or
/// copy) is named as such, with how much is missing, rather than as an I/O error mid-triangle.
fn check_binary_length(bytes: &[u8]) -> Result<(), String> {
    let Some(count) = bytes.get(80..84) else {
        return Err(format!(
            "the file is cut short: {} bytes, less than a binary STL's 84-byte header (and it is \
             not ASCII STL text, which starts with \"solid\")",
            bytes.len()
        ));
    };
    let announced = u64::from(u32::from_le_bytes([count[0], count[1], count[2], count[3]]));
    let expected = 84 + 50 * announced;
    let len = bytes.len() as u64;
    if len < expected {
        let complete = (len - 84) / 50;
        return Err(format!(
            "the file is cut short: its header announces {announced} triangles ({expected} \
             bytes) but it has {len} bytes; triangles {complete} to {} (counting from 0) are \
             missing or incomplete",
            announced - 1
        ));
    }
    Ok(())
}

/// `stl_io` takes a file for ASCII exactly when its first line starts with `"solid "`. Two common
/// kinds of file defeat that test, and get a patched copy:
/// - binary files whose free-form 80-byte header starts with `"solid "` (many CAD exporters write
///   one): recognised by their size, 84 + 50 × the triangle count, and the header's first byte
///   changed (the header carries no data);
/// - ASCII files that open with a bare `solid` line (no name): a space is added after `solid`.
fn patch_for_detection(bytes: &[u8]) -> Option<Vec<u8>> {
    let binary_size = bytes
        .get(80..84)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .is_some_and(|n| 84 + 50 * n as u64 == bytes.len() as u64);
    if binary_size && bytes.starts_with(b"solid") {
        let mut copy = bytes.to_vec();
        copy[0] = b'_';
        return Some(copy);
    }
    let first_line = bytes.split(|&b| b == b'\n').next().unwrap_or_default();
    if !binary_size && first_line.trim_ascii_end() == b"solid" {
        let mut copy = Vec::with_capacity(bytes.len() + 1);
        copy.extend_from_slice(b"solid ");
        copy.extend_from_slice(&bytes[5..]);
        return Some(copy);
    }
    None
}
