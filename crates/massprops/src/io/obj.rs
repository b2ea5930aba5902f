//! Wavefront OBJ through `tobj`, with our own error locations.
//!
//! `tobj` reports what went wrong but not where; on the (rare) error path we scan the text once
//! more to find the offending line, so a user is told "file, line N: …".

use std::io::Cursor;
use std::path::Path;

use nalgebra::Point3;

use super::MeshFile;
use super::obj_fast::FastObj;
use super::obj_parsed::{Parsed, Record, Records, extend_runs, parts};
use crate::diagnostics::EXAMPLES;
use crate::mesh::weld_exact;
use crate::{Defect, MeshError, PolyMesh, Warning};

/// Parses OBJ text: all objects and groups form one body; `l` and `p` elements are skipped, and
/// so are `f` records of fewer than three corners (reported as [`Defect::TwoCornerFaces`]);
/// positions are welded exactly. A UTF-8 byte-order mark at the start is ignored.
///
/// The records nearly every file is made of take a fast path of our own
/// (`io/obj_fast.rs`); any other file goes through `tobj`, with the same result.
pub fn parse_obj(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let text = utf8(bytes, path)?;
    let parsed = match fast(text) {
        Some(parsed) => parsed,
        None => general(text, path)?,
    };
    finish(parsed, without_mark(text), path)
}

/// The text without a byte-order mark at its start (Windows exporters write one; tobj would
/// read it as part of the first keyword, losing the first vertex and shifting every face index).
fn without_mark(text: &str) -> &str {
    text.strip_prefix('\u{FEFF}').unwrap_or(text)
}

/// The fast path over the whole text; `None` when it declines.
fn fast(text: &str) -> Option<Parsed> {
    let mut fast = FastObj::new(text.len());
    fast.feed(text).ok()?;
    Some(fast.finish())
}

/// For the fuzzer (`--cfg fuzzing`): whether the fast path, where it reads `bytes` at all,
/// reads them as tobj does (the same positions bit for bit, faces, lines and parts).
#[cfg(fuzzing)]
#[doc(hidden)]
pub fn fast_path_agrees(bytes: &[u8]) -> bool {
    let Ok(text) = std::str::from_utf8(bytes) else {
        return true;
    };
    let Some(f) = fast(text) else {
        return true;
    };
    let Ok(g) = general(text, Path::new("fuzz.obj")) else {
        return false;
    };
    let bits = |p: &Parsed| -> Vec<[u64; 3]> {
        p.positions
            .iter()
            .map(|q| [q.x.to_bits(), q.y.to_bits(), q.z.to_bits()])
            .collect()
    };
    bits(&f) == bits(&g)
        && (f.indices, f.arities, f.face_lines, f.runs, f.two_corner)
            == (g.indices, g.arities, g.face_lines, g.runs, g.two_corner)
        && (f.records.objects, f.records.groups) == (g.records.objects, g.records.groups)
}

/// The general path alone, on bytes the fast path declined.
fn parse_general(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let text = utf8(bytes, path)?;
    finish(general(text, path)?, without_mark(text), path)
}

/// [`parse_obj`] on a file read block by block: the fast path never holds the whole file; only
/// a file it declines (or one with an error to locate) is read again whole.
pub(super) fn load_obj(path: &Path, progress: &dyn Fn(f32)) -> Result<MeshFile, MeshError> {
    let io = |source: std::io::Error| MeshError::Io {
        path: path.to_path_buf(),
        source: source.into(),
    };
    let mut file = std::fs::File::open(path).map_err(io)?;
    let size = file.metadata().map_or(0, |m| m.len() as usize);
    let mut fast = FastObj::new(size);
    let mut block = Vec::with_capacity(BLOCK + 4096);
    let mut done = false;
    let mut readable = true;
    let mut read = 0;
    while !done && readable {
        let filled = block.len();
        block.resize(filled + BLOCK, 0);
        let n = read_full(&mut file, &mut block[filled..]).map_err(io)?;
        block.truncate(filled + n);
        done = n == 0;
        read += n;
        if n > 0 {
            progress(read as f32 / size.max(1) as f32);
        }
        // Whole lines only, but the last line at the end of the file.
        let cut = if done {
            block.len()
        } else {
            block.iter().rposition(|&b| b == b'\n').map_or(0, |k| k + 1)
        };
        readable = match std::str::from_utf8(&block[..cut]) {
            Ok(text) => fast.feed(text).is_ok(),
            Err(_) => false,
        };
        block.drain(..cut);
    }
    if !readable {
        let bytes = std::fs::read(path).map_err(io)?;
        return parse_general(&bytes, path);
    }
    let parsed = fast.finish();
    // The text is needed again only to name the line of a non-finite vertex.
    let mesh_ok = parsed
        .positions
        .iter()
        .all(|p| p.iter().all(|c| c.is_finite()));
    if !mesh_ok {
        let bytes = std::fs::read(path).map_err(io)?;
        return parse_obj(&bytes, path);
    }
    finish(parsed, "", path)
}

/// Bytes read at a time by [`load_obj`]: large enough that each read is a fraction of the
/// parse, small enough to stay in the cache's neighbourhood.
const BLOCK: usize = 1 << 20;

/// Fills `buf` as far as the file goes; fewer bytes only at its end.
pub(super) fn read_full(file: &mut std::fs::File, buf: &mut [u8]) -> std::io::Result<usize> {
    use std::io::Read as _;
    let mut filled = 0;
    while filled < buf.len() {
        match file.read(&mut buf[filled..]) {
            Ok(0) => break,
            Ok(n) => filled += n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(filled)
}

/// The text, or an error naming the first line that is not UTF-8.
fn utf8<'a>(bytes: &'a [u8], path: &Path) -> Result<&'a str, MeshError> {
    std::str::from_utf8(bytes).map_err(|e| MeshError::Malformed {
        path: path.to_path_buf(),
        line: Some(line_of_offset(bytes, e.valid_up_to())),
        message: "the file is not UTF-8 text (is it a binary file?)".into(),
    })
}

/// The general path, through `tobj`.
fn general(text: &str, path: &Path) -> Result<Parsed, MeshError> {
    let text = without_mark(text);
    let options = tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ignore_points: false,
        ignore_lines: false,
    };
    let (models, _materials) =
        tobj::load_obj_buf(&mut Cursor::new(text.as_bytes()), &options, |_| {
            Err(tobj::LoadError::OpenFileFailed)
        })
        .map_err(|e| MeshError::Malformed {
            path: path.to_path_buf(),
            line: locate_tobj_error(text, &e),
            message: describe(&e).into(),
        })?;

    let mut positions = Vec::new();
    let mut indices = Vec::new();
    let mut arities = Vec::new();
    // tobj returns `f` and `l` lines alike as elements (an `l` of three or more points looks like
    // a face), in file order; `p` lines it drops.
    let records = element_lines(text);
    let mut runs = Vec::new();
    let mut face_lines = Vec::new();
    let mut two_corner = Vec::new();
    let mut element = 0usize;
    for model in &models {
        let m = &model.mesh;
        let base = positions.len() as u32;
        positions.extend(
            m.positions
                .as_chunks::<3>()
                .0
                .iter()
                .map(|&[x, y, z]| Point3::new(x, y, z)),
        );
        let model_arities: Vec<usize> = if m.face_arities.is_empty() {
            vec![3; m.indices.len() / 3]
        } else {
            m.face_arities.iter().map(|&a| a as usize).collect()
        };
        let mut start = 0;
        for arity in model_arities {
            let face = &m.indices[start..start + arity];
            start += arity;
            let record = records.elements.get(element).copied().unwrap_or(Record {
                line: 0,
                polyline: false,
                object: 0,
                group: 0,
            });
            let (line, polyline) = (record.line, record.polyline);
            element += 1;
            // Polylines bound no volume: not part of the body.
            if polyline {
                continue;
            }
            // Segments written as faces (`f 1 2`): no area, skipped and reported.
            if arity < 3 {
                two_corner.push(line);
                continue;
            }
            indices.extend(face.iter().map(|&i| i + base));
            extend_runs(&mut runs, arities.len(), record.object, record.group);
            arities.push(arity);
            face_lines.push(line as u32);
        }
    }
    let (welded, remap) = weld_exact(&positions);
    let indices = indices.into_iter().map(|i| remap[i as usize]).collect();
    Ok(Parsed {
        positions: welded,
        indices,
        arities,
        face_lines,
        records,
        runs,
        two_corner,
    })
}

/// The mesh file from what a path read; `text` (the file, when a vertex is not finite) names
/// the line of a bad vertex.
fn finish(parsed: Parsed, text: &str, path: &Path) -> Result<MeshFile, MeshError> {
    let Parsed {
        positions,
        indices,
        arities,
        face_lines,
        records,
        runs,
        two_corner,
    } = parsed;
    let mut warnings = Vec::new();
    if !two_corner.is_empty() {
        warnings.push(Warning {
            count: two_corner.len(),
            defect: Defect::TwoCornerFaces {
                lines: two_corner.iter().copied().take(EXAMPLES).collect(),
            },
            faces: Vec::new(),
            effect_on_mass: Some(0.0),
        });
    }
    let mesh = PolyMesh::from_flat(positions, indices, &arities).map_err(|e| {
        let (line, source) = match e {
            // The welded index means nothing to the user: name the file's vertex and its line.
            MeshError::NonFiniteVertex { value, .. } => {
                let mut vertex = 0;
                let line = first_line(text, |kw, rest| {
                    let bad = kw == "v"
                        && rest
                            .split_whitespace()
                            .take(3)
                            .any(|t| t.parse::<f64>().is_ok_and(|v| !v.is_finite()));
                    vertex += usize::from(kw == "v" && !bad);
                    bad
                });
                (line, MeshError::NonFiniteVertex { vertex, value })
            }
            e => (None, e),
        };
        MeshError::InFile {
            path: path.to_path_buf(),
            line,
            source: Box::new(source),
        }
    })?;
    let (part_names, face_parts) = parts(&records, &runs, face_lines.len());
    Ok(MeshFile {
        mesh,
        face_lines,
        warnings,
        part_names,
        face_parts,
    })
}

fn describe(e: &tobj::LoadError) -> &'static str {
    use tobj::LoadError as E;
    match e {
        E::PositionParseError => "malformed vertex position: `v` needs three numbers",
        E::ColorParseError => "malformed vertex: `v` takes x y z, x y z w or x y z r g b",
        E::ScalingByZeroError => "a vertex has a weight w of zero",
        E::NormalParseError => "malformed normal: `vn` needs three numbers",
        E::TexcoordParseError => "malformed texture coordinate",
        E::FaceParseError => {
            "malformed face: `f` takes vertex indices like `f 1 2 3` or `f 1/1/1 2/2/2 3/3/3`"
        }
        E::FaceVertexOutOfBounds => "a face refers to a vertex that the file does not define",
        E::FaceTexCoordOutOfBounds => {
            "a face refers to a texture coordinate that the file does not define"
        }
        E::FaceNormalOutOfBounds => "a face refers to a normal that the file does not define",
        E::ReadError => "the file cannot be read as text",
        E::InvalidPolygon => "invalid polygon",
        _ => "the file is not valid OBJ",
    }
}

/// One-based line of byte `offset`.
fn line_of_offset(bytes: &[u8], offset: usize) -> usize {
    1 + bytes[..offset].iter().filter(|&&b| b == b'\n').count()
}

/// The first line whose keyword and remainder satisfy `bad`, one-based.
fn first_line(text: &str, mut bad: impl FnMut(&str, &str) -> bool) -> Option<usize> {
    text.lines().enumerate().find_map(|(i, line)| {
        let line = line.trim_start();
        let (kw, rest) = line.split_once(char::is_whitespace).unwrap_or((line, ""));
        bad(kw, rest).then_some(i + 1)
    })
}

/// The first word of each line, with its one-based line number.
fn keywords(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .filter_map(|(i, line)| line.split_whitespace().next().map(|kw| (i + 1, kw)))
}

fn element_lines(text: &str) -> Records {
    // Bytes, not `str::lines` and `split_whitespace`: this runs on every file, and a scan of
    // bytes takes a fraction of the time on a million-face file.
    let mut records = Records::new();
    let (mut object, mut group) = (0u32, 0u32);
    for (i, line) in text.as_bytes().split(|&b| b == b'\n').enumerate() {
        // tobj splits on Unicode whitespace (vertical tab, no-break space…): so does this, on the
        // rare line that starts with some other than ASCII spaces and tabs.
        let line = match line.first() {
            Some(&b) if b >= 0x80 || b == 0x0B || b == 0x0C => {
                std::str::from_utf8(line).map_or(line, |l| l.trim_start().as_bytes())
            }
            _ => line.trim_ascii_start(),
        };
        let keyword_ends = match line.get(1) {
            None => true,
            Some(&b) if b < 0x80 => (b as char).is_whitespace(),
            Some(_) => std::str::from_utf8(&line[1..])
                .ok()
                .and_then(|rest| rest.chars().next())
                .is_some_and(char::is_whitespace),
        };
        if !keyword_ends {
            continue;
        }
        let name = || String::from_utf8_lossy(line[1..].trim_ascii()).into_owned();
        match line.first() {
            Some(b'f') | Some(b'l') => records.elements.push(Record {
                line: i + 1,
                polyline: line[0] == b'l',
                object,
                group,
            }),
            Some(b'o') => {
                records.objects.push(name());
                object = (records.objects.len() - 1) as u32;
            }
            Some(b'g') => {
                records.groups.push(name());
                group = (records.groups.len() - 1) as u32;
            }
            _ => {}
        }
    }
    records
}

/// Finds the line `tobj` rejected, by re-checking the lines of the kind its error names.
fn locate_tobj_error(text: &str, e: &tobj::LoadError) -> Option<usize> {
    use tobj::LoadError as E;
    let numbers_ok = |rest: &str, n: usize| {
        let t: Vec<&str> = rest.split_whitespace().collect();
        t.len() >= n && t.iter().all(|x| x.parse::<f64>().is_ok())
    };
    match e {
        E::PositionParseError | E::ColorParseError | E::ScalingByZeroError => {
            // What tobj accepts: x y z; x y z w with w ≠ 0; x y z r g b.
            first_line(text, |kw, rest| {
                let t: Vec<&str> = rest.split_whitespace().collect();
                let number = |s: &str| s.parse::<f64>().ok();
                let xyz = t.len() >= 3 && t[..3].iter().all(|x| number(x).is_some());
                kw == "v"
                    && !(xyz
                        && match t.len() {
                            3 | 6 => true,
                            4 => number(t[3]).is_some_and(|w| w != 0.0),
                            _ => false,
                        })
            })
        }
        E::NormalParseError => first_line(text, |kw, rest| kw == "vn" && !numbers_ok(rest, 3)),
        E::TexcoordParseError => first_line(text, |kw, rest| kw == "vt" && !numbers_ok(rest, 1)),
        E::FaceParseError => first_line(text, |kw, rest| {
            (kw == "f" || kw == "l")
                && rest.split_whitespace().any(|t| {
                    t.split('/')
                        .next()
                        .is_none_or(|i| i.parse::<i64>().map_or(true, |i| i == 0))
                })
        }),
        E::FaceVertexOutOfBounds => {
            let count = keywords(text).filter(|&(_, kw)| kw == "v").count() as i64;
            let mut seen = 0i64;
            first_line(text, |kw, rest| {
                if kw == "v" {
                    seen += 1;
                }
                (kw == "f" || kw == "l")
                    && rest.split_whitespace().any(|t| {
                        let i = t.split('/').next().and_then(|i| i.parse::<i64>().ok());
                        match i {
                            Some(i) if i > 0 => i > count,
                            // OBJ indices start at 1; tobj reads 0 as out of range.
                            Some(0) => true,
                            Some(i) => -i > seen,
                            None => false,
                        }
                    })
            })
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both paths on the same text: the fast one (`None` when it declines) and `tobj`'s.
    fn both(text: &str) -> (Option<Parsed>, Result<Parsed, MeshError>) {
        (fast(text), general(text, Path::new("t.obj")))
    }

    /// The two results are the same, positions compared bit for bit.
    fn same(a: &Parsed, b: &Parsed) -> bool {
        let bits = |p: &Parsed| -> Vec<[u64; 3]> {
            p.positions
                .iter()
                .map(|q| [q.x.to_bits(), q.y.to_bits(), q.z.to_bits()])
                .collect()
        };
        bits(a) == bits(b)
            && a.indices == b.indices
            && a.arities == b.arities
            && a.face_lines == b.face_lines
            && (&a.records.objects, &a.records.groups) == (&b.records.objects, &b.records.groups)
            && a.runs == b.runs
            && a.two_corner == b.two_corner
    }

    /// The cross-check on real files: every OBJ of the workspace, and of the folders in
    /// `MASSPROPS_OBJ_DIRS` (colon-separated: the real-mesh survey's unpacked wheels), gives the
    /// same mesh on both paths, or the fast path declines it.
    #[test]
    fn the_fast_path_gives_tobjs_mesh_bit_for_bit_or_declines_on_every_obj_file() {
        let files = super::super::test_files("obj", "MASSPROPS_OBJ_DIRS");
        assert!(files.len() >= 20, "found only {files:?}");
        let (mut equal, mut declined, mut refused) = (0, 0, 0);
        // The first word of each declined file's first line the fast path does not read.
        let mut reasons = std::collections::BTreeMap::new();
        for file in &files {
            let bytes = std::fs::read(file).expect("readable");
            let Ok(text) = std::str::from_utf8(&bytes) else {
                continue;
            };
            match both(text) {
                (Some(f), Ok(g)) => {
                    assert!(same(&f, &g), "{} differs", file.display());
                    equal += 1;
                }
                (Some(_), Err(e)) => panic!(
                    "{}: tobj refuses ({e}) what the fast path read",
                    file.display()
                ),
                (None, Ok(_)) => {
                    declined += 1;
                    let mut pass = FastObj::new(text.len());
                    if let Err(d) = pass.feed(text) {
                        let line = text.lines().nth(d.line - 1).unwrap_or("");
                        let word = line.split_whitespace().next().unwrap_or("(blank)");
                        *reasons
                            .entry(word.chars().take(8).collect::<String>())
                            .or_insert(0) += 1;
                    }
                }
                (None, Err(_)) => refused += 1,
            }
        }
        eprintln!(
            "{} OBJ files: {equal} equal on both paths, {declined} declined by the fast path, \
             {refused} refused by tobj; declined at lines starting {reasons:?}",
            files.len()
        );
        assert!(equal > declined, "the fast path should read most files");
    }

    /// One line of a generated OBJ file, given the counts of `v`, `vt`, `vn` so far.
    fn generated_line(kind: u8, pick: &[u32], counts: &mut [usize; 3], text: &mut String) {
        let number = |k: u32| -> String {
            let x = (f64::from(k % 2000) - 1000.0) / 7.0;
            match k % 5 {
                0 => format!("{x}"),
                1 => format!("{x:e}"),
                2 => format!("{x:.3}"),
                3 => format!("{}", (k % 7) as f64 - 3.0),
                _ => format!("{x:.17}"),
            }
        };
        let reference = |k: u32, count: usize| -> String {
            let i = k as usize % count;
            if k.is_multiple_of(3) {
                format!("-{}", count - i)
            } else {
                format!("{}", i + 1)
            }
        };
        // A record of `n` numbers, counted as element `kind` (v, vt, vn).
        let mut numbers = |keyword: &str, n: usize, kind: usize| {
            text.push_str(keyword);
            for &k in &pick[..n] {
                text.push(' ');
                text.push_str(&number(k));
            }
            counts[kind] += 1;
        };
        match kind {
            0..=3 => numbers("v", 3, 0),
            4 => numbers("vt", 2, 1),
            5 => numbers("vn", 3, 2),
            6 => text.push_str(
                [
                    "o part",
                    "g side",
                    "s 1",
                    "usemtl red",
                    "mtllib m.mtl",
                    "# note",
                ][pick[0] as usize % 6],
            ),
            _ if counts[0] > 0 => {
                text.push('f');
                let corners = 3 + pick[3] as usize % 4;
                for c in 0..corners {
                    let k = pick[c % 4].wrapping_mul(2654435761).wrapping_add(c as u32);
                    text.push(' ');
                    text.push_str(&reference(k, counts[0]));
                    match (k % 4, counts[1] > 0, counts[2] > 0) {
                        (1, true, _) => text.push_str(&format!("/{}", reference(k / 4, counts[1]))),
                        (2, _, true) => {
                            text.push_str(&format!("//{}", reference(k / 4, counts[2])))
                        }
                        (3, true, true) => text.push_str(&format!(
                            "/{}/{}",
                            reference(k / 4, counts[1]),
                            reference(k / 8, counts[2])
                        )),
                        _ => {}
                    }
                }
            }
            _ => {}
        }
    }

    proptest::proptest! {
        /// Generated files mixing every record the fast path reads (numbers written every way,
        /// all index forms, objects, groups, materials, `\r\n`) read as tobj reads them; with a
        /// line it does not read added anywhere, it declines or still agrees.
        #[test]
        fn generated_obj_text_reads_as_tobj_reads_it(
            lines in proptest::collection::vec((0u8..10, proptest::collection::vec(0u32..100_000, 4)), 1..60),
            crlf in proptest::bool::ANY,
            trigger in proptest::option::of((0usize..60, 0usize..5)),
        ) {
            let mut text = String::new();
            let mut counts = [0usize; 3];
            for (n, (kind, pick)) in lines.iter().enumerate() {
                if let Some((at, which)) = trigger && at == n {
                    text.push_str(["l 1 2", "v 1 2 3 4", "vt 1", "f 1 2 # c", "p 1"][which]);
                    text.push('\n');
                }
                generated_line(*kind, pick, &mut counts, &mut text);
                text.push_str(if crlf { "\r\n" } else { "\n" });
            }
            let (f, g) = both(&text);
            match (f, g) {
                (Some(f), Ok(g)) => proptest::prop_assert!(same(&f, &g), "{}", text),
                (Some(_), Err(e)) => proptest::prop_assert!(false, "tobj refuses ({}) what the fast path read: {}", e, text),
                (None, _) => proptest::prop_assert!(trigger.is_some(), "declined without a trigger: {}", text),
            }
        }
    }

    /// A whole mesh: two objects and groups, `\r\n` endings, numbers written every way, faces
    /// with texture and normal references, negative indices, polygons, repeated positions.
    const MIXED: &str = "# exported\r\nmtllib a.mtl\r\no first\r\nv 0 0 0\r\nv 1.0 0 0\r\n\
        v 0 1e0 0\r\nv 0 0 +1.\r\nv -0.0 0 0\r\nvt 0 0\r\nvt 1 0 0\r\nvn 0 0 1\r\n\
        usemtl red\r\ns 1\r\nf 1/1/1 2/2/1 3/1/1\r\nf 5//1 3//1 2//1\r\ng side\r\n\
        f -4/-1 -3/-2 -1/-1\r\no second\r\nv 2 0 0\r\nv .5 .5 .5\r\ns off\r\nf 2 6 7 3\r\n\
        \tf  1 3  4 \r\n";

    /// Vertex colours on every vertex (MeshLab's export) and a material named in any script.
    #[test]
    fn coloured_vertices_and_unicode_names_take_the_fast_path() {
        let text = "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 0 0 1 1 1 1\n\
                    usemtl 材质.001\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        let (f, g) = both(text);
        assert!(same(
            &f.expect("fast path reads it"),
            &g.expect("tobj reads it")
        ));
    }

    #[test]
    fn a_mixed_file_is_read_by_the_fast_path_as_tobj_reads_it() {
        let (f, g) = both(MIXED);
        let (f, g) = (f.expect("fast path reads it"), g.expect("tobj reads it"));
        assert!(same(&f, &g));
        // -0.0 and 0.0 are one vertex, the first one's coordinates kept.
        assert_eq!(f.positions.len(), 6);
        assert_eq!(f.arities, [3, 3, 3, 4, 3]);
        assert_eq!(f.face_lines, [14, 15, 17, 22, 23]);
        assert_eq!(f.records.objects, ["unnamed", "first", "second"]);
    }

    /// Each thing the fast path leaves to tobj, on a file that is otherwise [`MIXED`]: the fast
    /// path declines, and the file reads (or fails) exactly as before.
    #[test]
    fn each_fallback_trigger_is_declined_and_read_by_tobj() {
        let triggers: [(&str, &str); 11] = [
            ("trailing comment", "v 1 1 1 # corner\n"),
            ("one-number vt", "vt 0.5\n"),
            ("polyline", "l 1 2 3\n"),
            ("line continuation", "f 1 2 \\\n3\n"),
            ("four-number v", "v 1 1 1 1\n"),
            ("usemtl without a name", "usemtl\n"),
            ("lone carriage return", "v 1 1 1\rv 2 2 2\n"),
            ("two-corner face", "f 1 2\n"),
            ("hexadecimal number", "v 0x10 0 0\n"),
            ("point", "p 1\n"),
            ("colours on one vertex only", "v 1 1 1 0.5 0.5 0.5\n"),
        ];
        for (what, line) in triggers {
            let text = format!("{MIXED}{line}");
            assert!(
                fast(&text).is_none(),
                "{what}: the fast path should decline"
            );
            let path = Path::new("t.obj");
            match (
                parse_obj(text.as_bytes(), path),
                parse_general(text.as_bytes(), path),
            ) {
                (Ok(a), Ok(b)) => assert_eq!(a, b, "{what}"),
                (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{what}"),
                (a, b) => panic!("{what}: {a:?} vs {b:?}"),
            }
        }
        // A non-finite vertex on a marked file's first line is named with its line.
        let bad = parse_obj(
            "\u{FEFF}v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".as_bytes(),
            Path::new("t.obj"),
        )
        .map(|_| ())
        .expect_err("refused");
        assert!(bad.to_string().contains("line 1"), "{bad}");
        let bom = format!("\u{FEFF}{MIXED}");
        assert!(fast(&bom).is_none(), "byte-order mark");
        let read = parse_obj(bom.as_bytes(), Path::new("t.obj")).expect("tobj reads it");
        let plain = parse_obj(MIXED.as_bytes(), Path::new("t.obj")).expect("fast");
        assert_eq!(read, plain, "the mark changes nothing");
    }
}
