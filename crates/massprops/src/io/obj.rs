//! Wavefront OBJ through `tobj`, with our own error locations.
//!
//! `tobj` reports what went wrong but not where; on the (rare) error path we scan the text once
//! more to find the offending line, so a user is told "file, line N: …".

use std::io::Cursor;
use std::path::Path;

use nalgebra::Point3;

use super::MeshFile;
use crate::diagnostics::EXAMPLES;
use crate::mesh::weld_exact;
use crate::{Defect, MeshError, PolyMesh, Warning};

/// Parses OBJ text: all objects and groups form one body; `l` and `p` elements are skipped, and
/// so are `f` records of fewer than three corners (reported as [`Defect::TwoCornerFaces`]);
/// positions are welded exactly. A UTF-8 byte-order mark at the start is ignored.
pub fn parse_obj(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    // Windows exporters often start with a byte-order mark, which tobj would read as part of the
    // first keyword, losing the first vertex and shifting every face index by one.
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let text = std::str::from_utf8(bytes).map_err(|e| MeshError::Malformed {
        path: path.to_path_buf(),
        line: Some(line_of_offset(bytes, e.valid_up_to())),
        message: "the file is not UTF-8 text (is it a binary file?)".into(),
    })?;
    let options = tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ignore_points: false,
        ignore_lines: false,
    };
    let (models, _materials) = tobj::load_obj_buf(&mut Cursor::new(bytes), &options, |_| {
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
    let mut kept: Vec<Record> = Vec::new();
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
            arities.push(arity);
            face_lines.push(line as u32);
            kept.push(record);
        }
    }
    let (welded, remap) = weld_exact(&positions);
    let indices = indices.into_iter().map(|i| remap[i as usize]).collect();
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
    let mesh = PolyMesh::from_flat(welded, indices, &arities).map_err(|e| {
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
    let (part_names, face_parts) = parts(&records, &kept);
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

/// One `f` or `l` record: its one-based line, whether it is a polyline, and the object and group
/// (indices into [`Records::objects`] and [`Records::groups`]) in force there.
#[derive(Clone, Copy)]
struct Record {
    line: usize,
    polyline: bool,
    object: u32,
    group: u32,
}

/// The elements tobj returns (each `f` or `l` record, in order) and the object and group names.
struct Records {
    elements: Vec<Record>,
    /// Names of `o` statements; index 0 is the unnamed part before the first.
    objects: Vec<String>,
    /// Names of `g` statements, likewise.
    groups: Vec<String>,
}

fn element_lines(text: &str) -> Records {
    // Bytes, not `str::lines` and `split_whitespace`: this runs on every file, and a scan of
    // bytes takes a fraction of the time on a million-face file.
    let mut records = Records {
        elements: Vec::new(),
        objects: vec![UNNAMED.to_owned()],
        groups: vec![UNNAMED.to_owned()],
    };
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

/// The name of the faces before a file's first `o` (or `g`).
const UNNAMED: &str = "unnamed";

/// The parts of the kept faces (objects, or groups when the file has no `o`): the names, and
/// for each face its part; both empty when the file names neither. Parts of the same name are
/// one part, and names without faces are dropped.
fn parts(records: &Records, kept: &[Record]) -> (Vec<String>, Vec<u32>) {
    let by_object = records.objects.len() > 1;
    if !by_object && records.groups.len() <= 1 {
        return (Vec::new(), Vec::new());
    }
    let mut names: Vec<String> = Vec::new();
    let faces = kept
        .iter()
        .map(|r| {
            let name = if by_object {
                &records.objects[r.object as usize]
            } else {
                &records.groups[r.group as usize]
            };
            match names.iter().position(|n| n == name) {
                Some(i) => i as u32,
                None => {
                    names.push(name.clone());
                    (names.len() - 1) as u32
                }
            }
        })
        .collect();
    (names, faces)
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
