//! Object File Format (OFF, Geomview's; as Princeton's shape benchmark and ModelNet ship it): a
//! keyword line (`OFF`, or `COFF`, `NOFF`, `STOFF`… for the extra numbers each vertex carries),
//! the vertex, face and edge counts, the vertices, then each face as its corner count and
//! corners, optionally followed by its colour. `#` starts a comment anywhere. Only the first three
//! numbers of a vertex and the corners of a face make the mesh; the rest (colours, normals,
//! texture coordinates) is read past. Polygons stay polygons; positions are welded exactly, as
//! the other readers do. Four-dimensional (`4OFF`, `nOFF`) and binary OFF are refused by name.

use std::path::Path;

use nalgebra::Point3;

use super::MeshFile;
use crate::MeshError;

/// Reads an OFF file already in memory; `path` names it in messages.
///
/// # Errors
/// The file does not follow the format (the message names the line), an index names no vertex,
/// a coordinate is not finite, or the file has no faces.
pub fn parse_off(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let bad = |line: Option<usize>, message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line,
        message,
    };
    let text = std::str::from_utf8(bytes).map_err(|e| {
        bad(
            None,
            format!("not a text file (binary OFF is not read): {e}"),
        )
    })?;
    // Each line without its comment, numbered from 1, blank ones left out.
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.split('#').next().unwrap_or_default().trim()))
        .filter(|(_, l)| !l.is_empty());
    let Some((first, keyword_line)) = lines.next() else {
        return Err(bad(None, "an empty file".to_owned()));
    };
    let mut words = keyword_line.split_ascii_whitespace();
    let keyword = words.next().unwrap_or_default();
    let prefix = keyword.strip_suffix("OFF").ok_or_else(|| {
        bad(
            Some(first),
            format!("not an OFF file: it starts with {keyword:?}, not OFF"),
        )
    })?;
    if prefix.contains('4') || prefix.contains('n') {
        return Err(bad(
            Some(first),
            format!("{keyword}: only three-dimensional OFF is read"),
        ));
    }
    // The counts follow the keyword on its line, or come on the next.
    let mut counts: Vec<&str> = words.collect();
    let mut counts_line = first;
    if counts.first() == Some(&"BINARY") {
        return Err(bad(Some(first), "binary OFF is not read".to_owned()));
    }
    if counts.is_empty() {
        let (line, text) = lines
            .next()
            .ok_or_else(|| bad(None, "the file ends before its counts".to_owned()))?;
        counts = text.split_ascii_whitespace().collect();
        counts_line = line;
    }
    let count = |k: usize, what: &str| -> Result<usize, MeshError> {
        counts.get(k).and_then(|c| c.parse().ok()).ok_or_else(|| {
            bad(
                Some(counts_line),
                format!("the {what} count is missing or not a whole number"),
            )
        })
    };
    let (vertices, faces) = (count(0, "vertex")?, count(1, "face")?);
    // The count is the file's word: room for what its bytes can hold, no more.
    let mut positions = Vec::with_capacity(vertices.min(bytes.len()));
    for v in 0..vertices {
        let (line, text) = lines.next().ok_or_else(|| {
            bad(
                None,
                format!("the file ends before vertex {v} (counting from 0)"),
            )
        })?;
        let mut point = [0.0; 3];
        let mut numbers = text.split_ascii_whitespace();
        for c in &mut point {
            *c = numbers
                .next()
                .and_then(|w| w.parse::<f64>().ok())
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    bad(
                        Some(line),
                        format!("vertex {v} (counting from 0) needs three finite numbers"),
                    )
                })?;
        }
        positions.push(Point3::from(point));
    }
    let (mut indices, mut arities, mut face_lines) = (Vec::new(), Vec::new(), Vec::new());
    for f in 0..faces {
        let (line, text) = lines.next().ok_or_else(|| {
            bad(
                None,
                format!("the file ends before face {f} (counting from 0)"),
            )
        })?;
        let face =
            |message: String| bad(Some(line), format!("face {f} (counting from 0) {message}"));
        let mut numbers = text.split_ascii_whitespace();
        let n: usize = numbers
            .next()
            .and_then(|w| w.parse().ok())
            .ok_or_else(|| face("does not start with its corner count".to_owned()))?;
        if n < 3 {
            return Err(face(format!("has {n} corners: a face needs three or more")));
        }
        for _ in 0..n {
            let i: usize = numbers
                .next()
                .and_then(|w| w.parse().ok())
                .ok_or_else(|| face(format!("has fewer than its {n} corners")))?;
            if i >= vertices {
                return Err(face(format!(
                    "names vertex {i}, but there are {vertices} vertices"
                )));
            }
            indices.push(i);
        }
        // What follows the corners is the face's colour, if anything: not the mesh's.
        arities.push(n);
        face_lines.push(line as u32);
    }
    if arities.is_empty() {
        return Err(bad(
            None,
            format!(
                "a point cloud of {vertices} points: it has no faces, so it encloses no volume"
            ),
        ));
    }
    let mesh = super::welded_mesh(path, &positions, indices, &arities)?;
    Ok(MeshFile {
        mesh,
        face_lines,
        warnings: Vec::new(),
        part_names: Vec::new(),
        face_parts: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::super::tests::face_points;
    use super::*;

    /// The unit cube: its corners and outward quads (as OBJ writes them, from 1).
    const CUBE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\n\
                            v 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n\
                            f 4 1 5 8\n";

    /// The cube as Geomview writes it, and as ModelNet does (counts on the keyword's line), with
    /// comments, vertex colours (COFF) and face colours.
    const SPELLINGS: [&str; 2] = [
        "OFF\n# the unit cube\n8 6 12\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
         4 0 3 2 1\n4 4 5 6 7 255 0 0\n4 0 1 5 4\n4 1 2 6 5  # a comment\n4 2 3 7 6\n4 3 0 4 7\n",
        "COFF 8 6 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n1 1 0 1 0 0 1\n0 1 0 1 0 0 1\n0 0 1 1 0 0 1\n\
         1 0 1 1 0 0 1\n1 1 1 1 0 0 1\n0 1 1 1 0 0 1\n4 0 3 2 1 0.5 0.5 0.5 1\n4 4 5 6 7\n\
         4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n",
    ];

    /// Each spelling has the OBJ's faces, corner for corner, and its mass properties bit for
    /// bit (volume 1); faces know their lines.
    #[test]
    fn every_spelling_of_the_cube_is_the_objs_mesh() {
        let obj = super::super::parse_obj(CUBE_OBJ.as_bytes(), Path::new("c.obj")).expect("obj");
        let exact = crate::mass_properties(&obj.mesh, 1.0).expect("the OBJ's");
        assert!((exact.mass - 1.0).abs() < 1e-15);
        for text in SPELLINGS {
            let file = parse_off(text.as_bytes(), Path::new("c.off")).expect(text);
            assert_eq!(face_points(&file.mesh), face_points(&obj.mesh), "{text}");
            assert_eq!(crate::mass_properties(&file.mesh, 1.0).expect(text), exact);
        }
        let file = parse_off(SPELLINGS[0].as_bytes(), Path::new("c.off")).expect("reads");
        assert_eq!(file.face_lines, [12, 13, 14, 15, 16, 17]);
    }

    /// Bad files are refused by name, with the line.
    #[test]
    fn bad_files_are_refused_by_name() {
        let said = |text: &str| {
            parse_off(text.as_bytes(), Path::new("bad.off"))
                .map(|_| ())
                .map_err(|e| e.to_string())
        };
        let off = SPELLINGS[0];
        assert_eq!(
            said(&off.replacen("4 0 3 2 1", "4 0 3 2 9", 1)),
            Err(
                "bad.off, line 12: face 0 (counting from 0) names vertex 9, but there are 8 \
                 vertices"
                    .to_owned()
            )
        );
        assert_eq!(
            said(&off.replacen("1 1 1\n", "1 x 1\n", 1)),
            Err(
                "bad.off, line 10: vertex 6 (counting from 0) needs three finite numbers"
                    .to_owned()
            )
        );
        assert_eq!(
            said("4OFF\n1 0 0\n"),
            Err("bad.off, line 1: 4OFF: only three-dimensional OFF is read".to_owned())
        );
        assert_eq!(
            said("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
            Err(
                "bad.off: a point cloud of 3 points: it has no faces, so it encloses no volume"
                    .to_owned()
            )
        );
        assert_eq!(
            said("ply\n"),
            Err("bad.off, line 1: not an OFF file: it starts with \"ply\", not OFF".to_owned())
        );
        // A count no file could hold reserves nothing for it.
        assert_eq!(
            said("OFF\n1000000000000000 1 0\n"),
            Err("bad.off: the file ends before vertex 0 (counting from 0)".to_owned())
        );
        assert_eq!(
            said(&off.replacen("4 3 0 4 7\n", "", 1)),
            Err("bad.off: the file ends before face 5 (counting from 0)".to_owned())
        );
    }
}
