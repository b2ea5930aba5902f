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
    let mut warnings = Vec::new();
    let recounted;
    let bytes = if ascii {
        bytes
    } else {
        match check_binary_length(bytes).map_err(malformed)? {
            Some(records) => {
                warnings.push(count_warning(bytes, records));
                recounted = with_count(bytes, records);
                &recounted
            }
            None => bytes,
        }
    };
    let mut corners = Vec::new();
    let mut part_names = Vec::new();
    let mut face_parts = Vec::new();
    if ascii {
        // stl_io reads the first `solid … endsolid` block and silently stops there: each block
        // is read on its own, and its name names a part.
        for (name, block) in solid_blocks(bytes) {
            let patched = patch_bare_solid(block);
            read_triangles(
                patched.as_deref().unwrap_or(block),
                &mut corners,
                &malformed,
            )?;
            // Blocks of the same name are one part (as OBJ objects are).
            let part = match part_names.iter().position(|n| *n == name) {
                Some(k) => k,
                None => {
                    part_names.push(name);
                    part_names.len() - 1
                }
            };
            face_parts.resize(corners.len() / 3, part as u32);
        }
    } else {
        let patched = patch_binary_header(bytes);
        read_triangles(
            patched.as_deref().unwrap_or(bytes),
            &mut corners,
            &malformed,
        )?;
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
        warnings,
        part_names,
        face_parts,
    })
}

/// Reads every triangle of one STL (binary, or one ASCII `solid` block), appending its corners;
/// triangles are numbered on from those already read.
fn read_triangles(
    bytes: &[u8],
    corners: &mut Vec<Point3<f64>>,
    malformed: &dyn Fn(String) -> MeshError,
) -> Result<(), MeshError> {
    let first = corners.len() / 3;
    let mut cursor = Cursor::new(bytes);
    let reader = stl_io::create_stl_reader(&mut cursor)
        .map_err(|e| malformed(format!("not a readable STL file: {e}")))?;
    for (k, triangle) in reader.enumerate() {
        let t = first + k;
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
    Ok(())
}

/// The `solid NAME … endsolid` blocks of an ASCII STL: each block's name (empty when it has
/// none) and its bytes. Text after the last `endsolid` that opens no block is ignored, as
/// readers do with trailing blank lines.
fn solid_blocks(bytes: &[u8]) -> Vec<(String, &[u8])> {
    let mut blocks = Vec::new();
    let mut start: Option<(usize, String)> = None;
    let mut offset = 0;
    for line in bytes.split_inclusive(|&b| b == b'\n') {
        let text = line.trim_ascii();
        if start.is_none() && text.starts_with(b"solid") {
            let name = String::from_utf8_lossy(text[5..].trim_ascii()).into_owned();
            start = Some((offset, name));
        } else if text.starts_with(b"endsolid")
            && let Some((from, name)) = start.take()
        {
            blocks.push((name, &bytes[from..offset + line.len()]));
        }
        offset += line.len();
    }
    if let Some((from, name)) = start {
        blocks.push((name, &bytes[from..]));
    }
    blocks
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
/// A header that counts fewer triangles than the whole records that follow (an exporter that
/// leaves the count 0) gives `Some(records)`: the file is read by its size.
fn check_binary_length(bytes: &[u8]) -> Result<Option<u64>, String> {
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
    let body = len - 84;
    if body.is_multiple_of(50) && body / 50 > announced {
        return Ok(Some(body / 50));
    }
    Ok(None)
}

/// The header's count, as read.
fn header_count(bytes: &[u8]) -> u64 {
    bytes.get(80..84).map_or(0, |c| {
        u64::from(u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
    })
}

/// The warning for a header that counts fewer triangles than the file holds.
fn count_warning(bytes: &[u8], records: u64) -> crate::Warning {
    crate::Warning {
        defect: crate::Defect::StlTriangleCount {
            header: header_count(bytes),
            records,
        },
        count: 1,
        faces: Vec::new(),
        effect_on_mass: None,
    }
}

/// A copy of a binary STL with its header's count set to `records` (so the reader reads them
/// all); a count beyond `u32` cannot be written and leaves the file as it is.
fn with_count(bytes: &[u8], records: u64) -> Vec<u8> {
    let mut copy = bytes.to_vec();
    if let Ok(n) = u32::try_from(records) {
        copy[80..84].copy_from_slice(&n.to_le_bytes());
    }
    copy
}

/// A binary STL whose free-form 80-byte header starts with `"solid "` (many CAD exporters write
/// one) would be read as ASCII by `stl_io`: its first byte is changed in a copy (the header
/// carries no data).
fn patch_binary_header(bytes: &[u8]) -> Option<Vec<u8>> {
    if !bytes.starts_with(b"solid") {
        return None;
    }
    let mut copy = bytes.to_vec();
    copy[0] = b'_';
    Some(copy)
}

/// `stl_io` takes a file for ASCII only when its first line starts with `"solid "`: a block
/// that opens with a bare `solid` line (no name) gets the space in a copy.
fn patch_bare_solid(block: &[u8]) -> Option<Vec<u8>> {
    let first_line = block.split(|&b| b == b'\n').next().unwrap_or_default();
    if first_line.trim_ascii_end() != b"solid" {
        return None;
    }
    let mut copy = Vec::with_capacity(block.len() + 1);
    copy.extend_from_slice(b"solid ");
    copy.extend_from_slice(&block[5..]);
    Some(copy)
}
