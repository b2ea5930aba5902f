//! STL: binary files by our own reader (50-byte records, read in blocks from a path, corners
//! welded on their f32 bits), ASCII through `stl_io`; vertices are welded exactly.

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
        let announced = header_count(bytes);
        let count = binary_count(bytes.len() as u64, announced).map_err(malformed)?;
        let mut corners = Vec::with_capacity(3 * count as usize);
        let end = 84 + 50 * count as usize;
        binary_records(&bytes[84..end], 0, &mut corners).map_err(malformed)?;
        return binary_mesh(&corners, announced, count, path);
    }
    match ascii_fast(bytes) {
        Some(ascii) => {
            let mut file = binary_mesh(&ascii.corners, 0, 0, path)?;
            file.face_lines = ascii.facet_lines;
            file.part_names = ascii.part_names;
            file.face_parts = ascii.face_parts;
            Ok(file)
        }
        None => ascii_general(bytes, path),
    }
}

/// An ASCII STL through `stl_io`, block by block.
fn ascii_general(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let malformed = |message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line: None,
        message,
    };
    let mut corners = Vec::new();
    let mut part_names = Vec::new();
    let mut face_parts = Vec::new();
    // stl_io reads the first `solid … endsolid` block and silently stops there: each block is
    // read on its own, and its name names a part.
    for (name, block) in solid_blocks(bytes) {
        let patched = patch_for_stl_io(block);
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
    let (positions, remap) = weld_exact(&corners);
    Ok(MeshFile {
        mesh: triangle_mesh(positions, &remap, path)?,
        face_lines: facet_lines(bytes),
        warnings: Vec::new(),
        part_names,
        face_parts,
    })
}

/// The mesh of welded `positions` whose corners, three a triangle, are `remap`.
fn triangle_mesh(
    positions: Vec<Point3<f64>>,
    remap: &[u32],
    path: &Path,
) -> Result<PolyMesh, MeshError> {
    let triangles: Vec<[u32; 3]> = remap.as_chunks::<3>().0.to_vec();
    PolyMesh::from_triangles(positions, &triangles).map_err(|e| MeshError::InFile {
        path: path.to_path_buf(),
        line: None,
        source: Box::new(e),
    })
}

/// What the ASCII fast path read: the corners, the parts and the `facet` lines.
struct AsciiParsed {
    corners: Vec<[f32; 3]>,
    part_names: Vec<String>,
    face_parts: Vec<u32>,
    facet_lines: Vec<u32>,
}

/// The fast path for ASCII STL: one pass over the lines for files made only of well-formed
/// `solid NAME` … `facet normal` / `outer loop` / three `vertex` / `endloop` / `endfacet` …
/// `endsolid` blocks, numbers through the standard library's f32 parser as `stl_io` reads them;
/// `None` for anything else (a missing or non-finite number, an indented `solid`, a block left
/// open, a keyword out of place), which then goes through `stl_io` as before, with its message.
fn ascii_fast(bytes: &[u8]) -> Option<AsciiParsed> {
    let text = std::str::from_utf8(bytes).ok()?;
    let mut out = AsciiParsed {
        corners: Vec::with_capacity(bytes.len() / 80),
        part_names: Vec::new(),
        face_parts: Vec::new(),
        facet_lines: Vec::with_capacity(bytes.len() / 250),
    };
    // Inside a block: the part, and how far into the current facet (0: between facets).
    let mut block: Option<u32> = None;
    let mut step = 0;
    for (i, line) in text.split('\n').enumerate() {
        let mut words = line.split_ascii_whitespace();
        let Some(first) = words.next() else {
            continue;
        };
        let Some(part) = block else {
            // Between blocks only a block's start: other text there would shift the lines.
            if !line.trim_ascii_start().starts_with("solid") {
                return None;
            }
            {
                // `solid`, then a space, a tab or the line's end (`stl_io` is given its space by
                // `patch_for_stl_io`); not an indented `solid`, nor `solids`.
                if !line
                    .strip_prefix("solid")
                    .is_some_and(|rest| rest.is_empty() || rest.starts_with(char::is_whitespace))
                {
                    return None;
                }
                let name = line.trim_ascii()[5..].trim_ascii();
                let k = match out.part_names.iter().position(|n| n == name) {
                    Some(k) => k,
                    None => {
                        out.part_names.push(name.to_owned());
                        out.part_names.len() - 1
                    }
                };
                block = Some(k as u32);
            }
            continue;
        };
        let numbers = |words: &mut std::str::SplitAsciiWhitespace<'_>| -> Option<[f32; 3]> {
            let mut p = [0.0f32; 3];
            for c in &mut p {
                *c = words.next()?.parse().ok().filter(|x: &f32| x.is_finite())?;
            }
            words.next().is_none().then_some(p)
        };
        match (step, first) {
            (0, "endsolid") => block = None,
            (0, "facet") => {
                (words.next()? == "normal").then_some(())?;
                // The normal is never used (the corners give each face its orientation), so a
                // NaN there (some exporters write one for a degenerate facet) refuses nothing.
                let mut normal = [0.0f32; 3];
                for c in &mut normal {
                    *c = words.next()?.parse().ok()?;
                }
                words.next().is_none().then_some(())?;
                out.facet_lines.push((i + 1) as u32);
                out.face_parts.push(part);
                step = 1;
            }
            (1, "outer") => {
                (words.next()? == "loop" && words.next().is_none()).then_some(())?;
                step = 2;
            }
            (2..=4, "vertex") => {
                out.corners.push(numbers(&mut words)?);
                step += 1;
            }
            (5, "endloop") | (6, "endfacet") if words.next().is_none() => {
                step = if step == 6 { 0 } else { 6 };
            }
            _ => return None,
        }
    }
    block.is_none().then_some(out)
}

/// [`parse_stl`] on a file: a binary one is read in blocks of records, never whole; an ASCII
/// one is read whole.
pub(super) fn load_stl(path: &Path, progress: &dyn Fn(f32)) -> Result<MeshFile, MeshError> {
    use std::io::Read as _;
    let io = |source: std::io::Error| MeshError::Io {
        path: path.to_path_buf(),
        source: source.into(),
    };
    let malformed = |message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line: None,
        message,
    };
    let mut file = std::fs::File::open(path).map_err(io)?;
    let len = file.metadata().map_err(io)?.len();
    let mut head = vec![0u8; len.min(1024) as usize];
    file.read_exact(&mut head).map_err(io)?;
    if is_ascii(&head) || len < 84 {
        let bytes = std::fs::read(path).map_err(io)?;
        return parse_stl(&bytes, path);
    }
    let announced = header_count(&head);
    let count = binary_count(len, announced).map_err(malformed)?;
    let mut corners = Vec::with_capacity(3 * count as usize);
    // The records after the header in the bytes already read, then block by block.
    let mut pending = head.split_off(84);
    let mut block = vec![0u8; 50 * 8192];
    let mut read = 0u64;
    while read < count {
        let n = super::obj::read_full(&mut file, &mut block).map_err(io)?;
        pending.extend_from_slice(&block[..n]);
        let whole = (pending.len() / 50).min((count - read) as usize) * 50;
        binary_records(&pending[..whole], read, &mut corners).map_err(malformed)?;
        read += (whole / 50) as u64;
        progress(read as f32 / count.max(1) as f32);
        pending.drain(..whole);
        if n == 0 {
            break;
        }
    }
    binary_mesh(&corners, announced, count, path)
}

/// The triangles a binary STL of `len` bytes holds, given its header's count: by its size when
/// the header counts fewer than the whole records that follow (warned about), else the header's.
fn binary_count(len: u64, announced: u64) -> Result<u64, String> {
    Ok(check_binary_length(len, announced)?.unwrap_or(announced))
}

/// Appends the corners of whole 50-byte binary records (normal, three corners, attribute),
/// numbered on from `first`; a non-finite coordinate is an error naming its triangle.
fn binary_records(records: &[u8], first: u64, corners: &mut Vec<[f32; 3]>) -> Result<(), String> {
    for (k, record) in records.as_chunks::<50>().0.iter().enumerate() {
        for corner in 0..3 {
            let at = 12 + 12 * corner;
            let c = |i: usize| {
                let b = &record[at + 4 * i..at + 4 * i + 4];
                f32::from_le_bytes([b[0], b[1], b[2], b[3]])
            };
            let p = [c(0), c(1), c(2)];
            if let Some(value) = p.into_iter().find(|x| !x.is_finite()) {
                return Err(format!(
                    "triangle {} (counting from 0), corner {corner}: non-finite coordinate {value}",
                    first + k as u64
                ));
            }
            corners.push(p);
        }
    }
    Ok(())
}

/// The welded mesh of a binary STL's corners (f32, as the format stores them, welded on their
/// bits: a third of the memory of f64 points, converted exactly once welded).
fn binary_mesh(
    corners: &[[f32; 3]],
    announced: u64,
    count: u64,
    path: &Path,
) -> Result<MeshFile, MeshError> {
    let key = |i: usize| corners[i].map(|c| (c + 0.0).to_bits());
    let (firsts, remap) = crate::mesh::weld_by_key(corners.len(), key, |k| {
        crate::mesh::weld_hash(k.map(u64::from))
    });
    let positions = firsts
        .iter()
        .map(|&i| corners[i as usize].map(f64::from).into())
        .collect();
    let mesh = triangle_mesh(positions, &remap, path)?;
    let warnings = if count > announced {
        vec![count_warning(announced, count)]
    } else {
        Vec::new()
    };
    Ok(MeshFile {
        mesh,
        face_lines: Vec::new(),
        warnings,
        part_names: Vec::new(),
        face_parts: Vec::new(),
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
fn check_binary_length(len: u64, announced: u64) -> Result<Option<u64>, String> {
    if len < 84 {
        return Err(format!(
            "the file is cut short: {len} bytes, less than a binary STL's 84-byte header (and it \
             is not ASCII STL text, which starts with \"solid\")"
        ));
    }
    let expected = 84 + 50 * announced;
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
fn count_warning(header: u64, records: u64) -> crate::Warning {
    crate::Warning {
        defect: crate::Defect::StlTriangleCount { header, records },
        count: 1,
        faces: Vec::new(),
        effect_on_mass: None,
    }
}

/// A copy of an ASCII block that `stl_io` reads as the fast path does, or `None` when the
/// block needs none: `stl_io` takes a block for ASCII only when its first line starts with
/// `"solid "`, so a bare `solid` line (no name), or `solid` and a tab before the name (assimp's
/// `sphereWithHole.stl`), gets the space; and it refuses a non-finite facet normal, which mass
/// properties never use, so such a normal is written as `0 0 0`.
fn patch_for_stl_io(block: &[u8]) -> Option<Vec<u8>> {
    let first = match block.strip_prefix(b"solid")?.first() {
        Some(b'\t') => Some(6),
        None | Some(b'\r' | b'\n') => Some(5),
        _ => None,
    };
    let bad_normal = |line: &[u8]| {
        let text = std::str::from_utf8(line).unwrap_or_default();
        let mut words = text.split_ascii_whitespace();
        words.next() == Some("facet")
            && words.next() == Some("normal")
            && words.any(|w| w.parse::<f32>().is_ok_and(|x| !x.is_finite()))
    };
    let lines = || block.split_inclusive(|&b| b == b'\n');
    if first.is_none() && !lines().any(bad_normal) {
        return None;
    }
    let mut copy = Vec::with_capacity(block.len() + 1);
    for (k, line) in lines().enumerate() {
        match (k, first) {
            (0, Some(from)) => {
                copy.extend_from_slice(b"solid ");
                copy.extend_from_slice(&line[from..]);
            }
            _ if bad_normal(line) => {
                let end = &line[line.trim_ascii_end().len()..];
                copy.extend_from_slice(b"facet normal 0 0 0");
                copy.extend_from_slice(end);
            }
            _ => copy.extend_from_slice(line),
        }
    }
    Some(copy)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A binary STL of `triangles` records whose corners repeat (a grid, so most are shared),
    /// with the header's count `announced`.
    fn binary(triangles: usize, announced: u32) -> Vec<u8> {
        let mut bytes = b"solid binary header that opens with solid".to_vec();
        bytes.resize(80, b' ');
        bytes.extend_from_slice(&announced.to_le_bytes());
        for t in 0..triangles {
            bytes.extend_from_slice(&[0; 12]);
            let (x, y) = ((t % 97) as f32, (t / 97) as f32);
            for [dx, dy] in [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]] {
                for c in [x + dx, y + dy, (x * 0.37 - y).sin()] {
                    bytes.extend_from_slice(&c.to_le_bytes());
                }
            }
            bytes.extend_from_slice(&[0, 0]);
        }
        bytes
    }

    /// The same bytes through `stl_io`, as the reader did before it had its own: the corners,
    /// welded.
    fn through_stl_io(bytes: &[u8]) -> (Vec<Point3<f64>>, Vec<u32>) {
        let mut copy = bytes.to_vec();
        copy[0] = b'_';
        let records = ((copy.len() - 84) / 50) as u32;
        copy[80..84].copy_from_slice(&records.to_le_bytes());
        let mut corners = Vec::new();
        read_triangles(&copy, &mut corners, &|m: String| -> MeshError {
            panic!("{m}")
        })
        .expect("stl_io reads it");
        weld_exact(&corners)
    }

    fn bits(p: &[Point3<f64>]) -> Vec<[u64; 3]> {
        p.iter()
            .map(|q| q.coords.map(f64::to_bits).into())
            .collect()
    }

    #[test]
    fn the_binary_reader_gives_stl_ios_mesh_bit_for_bit_from_memory_and_from_a_file() {
        let bytes = binary(30_000, 30_000);
        let (positions, remap) = through_stl_io(&bytes);
        let parsed = parse_stl(&bytes, Path::new("t.stl")).expect("reads");
        assert_eq!(bits(parsed.mesh.positions()), bits(&positions));
        let indices: Vec<u32> = parsed.mesh.faces().flatten().copied().collect();
        assert_eq!(indices, remap);
        // From a path, in blocks (30 000 records are more than three blocks).
        let path = std::env::temp_dir().join(format!("massprops-stl-{}.stl", std::process::id()));
        std::fs::write(&path, &bytes).expect("writable");
        let loaded = load_stl(&path, &|_| {}).expect("reads");
        std::fs::remove_file(&path).ok();
        assert_eq!(loaded, parsed);
    }

    /// Every ASCII STL of the workspace, and of the folders in `MASSPROPS_STL_DIRS`, reads on the
    /// fast path as through `stl_io`, or the fast path declines it.
    #[test]
    fn every_ascii_stl_file_reads_as_stl_io_reads_it_or_is_declined() {
        let files = super::super::test_files("stl", "MASSPROPS_STL_DIRS");
        let (mut equal, mut declined) = (0, 0);
        for file in &files {
            let bytes = std::fs::read(file).expect("readable");
            if !is_ascii(&bytes) {
                continue;
            }
            let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&bytes);
            let general = ascii_general(bytes, file);
            match (ascii_fast(bytes), general) {
                (Some(_), Ok(general)) => {
                    let fast = parse_stl(bytes, file).expect("reads");
                    assert_eq!(bits(fast.mesh.positions()), bits(general.mesh.positions()));
                    assert_eq!(fast, general, "{}", file.display());
                    equal += 1;
                }
                (Some(_), Err(e)) => panic!("{}: stl_io refuses ({e})", file.display()),
                (None, _) => declined += 1,
            }
        }
        eprintln!("ASCII STL files: {equal} equal on both paths, {declined} declined");
        assert!(equal >= 1);
    }

    /// A two-block ASCII file with `\r\n`, blank lines and numbers written every way reads as
    /// through `stl_io`; each departure from the plain grammar is declined and still reads (or
    /// fails) as before.
    #[test]
    fn ascii_fast_path_matches_stl_io_and_declines_the_rest() {
        let facet = |x: &str| {
            format!(
                "  facet normal 0 0 1\r\n    outer loop\r\n      vertex {x} 0 0\r\n      vertex 1 \
                 1e0 0\r\n\r\n      vertex 0 1 -0.0\r\n    endloop\r\n  endfacet\r\n"
            )
        };
        let text = format!(
            "solid a\r\n{}{}endsolid a\r\nsolid\r\n{}endsolid\r\n",
            facet("0"),
            facet("2.5"),
            facet(".25")
        );
        let path = Path::new("t.stl");
        assert!(ascii_fast(text.as_bytes()).is_some());
        let fast = parse_stl(text.as_bytes(), path).expect("reads");
        assert_eq!(fast, ascii_general(text.as_bytes(), path).expect("reads"));
        assert_eq!(fast.part_names, ["a", ""]);
        assert_eq!(fast.face_lines, [2, 10, 20]);
        for (what, from, to) in [
            ("a missing normal", "facet normal 0 0 1", "facet normal 0 0"),
            (
                "a non-finite vertex",
                "vertex 1 \
                 1e0",
                "vertex inf 1e0",
            ),
            ("an indented solid", "a\r\nsolid\r\n", "a\r\n  solid\r\n"),
            ("a block left open", "endsolid\r\n", ""),
            ("text between blocks", "solid\r\n", "note\r\nsolid\r\n"),
            ("a word after endloop", "endloop", "endloop x"),
        ] {
            let changed = text.replacen(from, to, 1);
            assert_ne!(changed, text, "{what}");
            assert!(ascii_fast(changed.as_bytes()).is_none(), "{what}");
            let (a, b) = (
                parse_stl(changed.as_bytes(), path),
                ascii_general(changed.as_bytes(), path),
            );
            assert_eq!(format!("{a:?}"), format!("{b:?}"), "{what}");
        }
    }

    /// Two defects of real files: a `solid` line with a tab before its name (assimp's
    /// `sphereWithHole.stl`) was taken for binary and refused ("failed to fill whole buffer"),
    /// and a NaN facet normal, which mass properties never use, refused the whole file. Both read
    /// now, on the fast path and through `stl_io`, as the plain file does.
    #[test]
    fn a_tab_after_solid_and_a_nan_normal_read_as_the_plain_file() {
        let facet = |normal: &str, [a, b, c]: [&str; 3]| {
            format!(
                "facet normal {normal}\nouter loop\nvertex {a}\nvertex {b}\nvertex {c}\nendloop\n\
                 endfacet\n"
            )
        };
        let (o, x, y, z) = ("0 0 0", "1 0 0", "0 1 0", "0 0 1");
        let plain = format!(
            "solid t\n{}{}{}{}endsolid t\n",
            facet("0 0 -1", [o, y, x]),
            facet("0 -1 0", [o, x, z]),
            facet("-1 0 0", [o, z, y]),
            facet("1 1 1", [x, y, z])
        );
        let path = Path::new("t.stl");
        let expected = parse_stl(plain.as_bytes(), path).expect("the plain file");
        let volume = crate::mass_properties(&expected.mesh, 1.0).map(|p| p.mass);
        assert!(
            matches!(volume, Ok(v) if (v - 1.0 / 6.0).abs() < 1e-15),
            "{volume:?}"
        );
        for (what, changed) in [
            (
                "a tab after solid",
                plain.replacen("solid t", "solid\tt", 1),
            ),
            ("a NaN normal", plain.replacen("0 0 -1", "nan NaN -nan", 1)),
        ] {
            assert!(is_ascii(changed.as_bytes()), "{what}");
            let fast = parse_stl(changed.as_bytes(), path).map_err(|e| e.to_string());
            assert_eq!(fast.as_ref().map(|f| &f.mesh), Ok(&expected.mesh), "{what}");
            assert_eq!(
                fast.map(|f| f.part_names),
                Ok(vec!["t".to_owned()]),
                "{what}"
            );
            let general = ascii_general(changed.as_bytes(), path).map_err(|e| e.to_string());
            let general = general.map(|f| f.mesh);
            assert_eq!(
                general.as_ref(),
                Ok(&expected.mesh),
                "{what} through stl_io"
            );
        }
    }

    /// Every binary STL of the workspace, and of the folders in `MASSPROPS_STL_DIRS`, reads as
    /// `stl_io` reads it.
    #[test]
    fn every_binary_stl_file_reads_as_stl_io_reads_it() {
        let files = super::super::test_files("stl", "MASSPROPS_STL_DIRS");
        let mut compared = 0;
        for file in &files {
            let bytes = std::fs::read(file).expect("readable");
            if is_ascii(&bytes) || bytes.len() < 84 {
                continue;
            }
            let Ok(parsed) = parse_stl(&bytes, file) else {
                continue;
            };
            let (positions, remap) = through_stl_io(&bytes[..84 + 50 * parsed.mesh.face_count()]);
            assert_eq!(
                bits(parsed.mesh.positions()),
                bits(&positions),
                "{}",
                file.display()
            );
            let indices: Vec<u32> = parsed.mesh.faces().flatten().copied().collect();
            assert_eq!(indices, remap, "{}", file.display());
            compared += 1;
        }
        eprintln!("{compared} binary STL files read as stl_io reads them");
        assert!(compared >= 2, "{files:?}");
    }

    #[test]
    fn a_header_counting_zero_is_read_by_the_size_and_warned_about() {
        let bytes = binary(1_938, 0);
        let parsed = parse_stl(&bytes, Path::new("t.stl")).expect("reads");
        assert_eq!(parsed.mesh.face_count(), 1_938);
        assert!(matches!(
            parsed.warnings[..],
            [crate::Warning {
                defect: crate::Defect::StlTriangleCount {
                    header: 0,
                    records: 1_938
                },
                ..
            }]
        ));
    }

    #[test]
    fn a_non_finite_corner_in_a_later_block_names_its_triangle() {
        let mut bytes = binary(20_000, 20_000);
        let at = 84 + 50 * 17_001 + 12 + 12 + 4;
        bytes[at..at + 4].copy_from_slice(&f32::NAN.to_le_bytes());
        let path = std::env::temp_dir().join(format!("massprops-nan-{}.stl", std::process::id()));
        std::fs::write(&path, &bytes).expect("writable");
        let loaded = load_stl(&path, &|_| {}).map(|_| ()).expect_err("refused");
        std::fs::remove_file(&path).ok();
        let parsed = parse_stl(&bytes, Path::new("t.stl"))
            .map(|_| ())
            .expect_err("refused");
        assert!(
            loaded
                .to_string()
                .contains("triangle 17001 (counting from 0), corner 1: non-finite coordinate NaN"),
            "{loaded}"
        );
        assert_eq!(
            loaded
                .to_string()
                .replace(&path.display().to_string(), "t.stl"),
            parsed.to_string()
        );
    }
}
