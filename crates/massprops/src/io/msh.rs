//! MuJoCo's binary mesh (`.msh`, the XML reference's `mesh/@file`): four little-endian 32-bit
//! counts (vertices, normals, texture coordinates, faces), then the vertices as 3 floats each,
//! the normals (3 floats), the texture coordinates (2 floats) and the faces as 3 integers each.
//! The file is exactly that long; MuJoCo refuses any other length, and so does this reader. A
//! file with no faces stands, for MuJoCo, for its points' convex hull, which this reader does not
//! build: it is refused by name.

use std::path::Path;

use nalgebra::Point3;

use super::MeshFile;
use crate::MeshError;

/// Whether `bytes` are a `.msh` file: four counts, none negative, with faces, that give exactly
/// the file's length (MuJoCo's own test).
pub(super) fn is_msh(bytes: &[u8]) -> bool {
    let count = |k: usize| {
        bytes
            .get(4 * k..4 * k + 4)
            .and_then(|w| u64::try_from(i32::from_le_bytes([w[0], w[1], w[2], w[3]])).ok())
    };
    match [count(0), count(1), count(2), count(3)] {
        [Some(v), Some(n), Some(t), Some(f)] => {
            f > 0 && 4 * (4 + 3 * (v + n + f) + 2 * t) == bytes.len() as u64
        }
        _ => false,
    }
}

/// Reads a `.msh` file already in memory; `path` names it in messages.
///
/// # Errors
/// The header's counts are negative or do not give the file's length, a face names no vertex, a
/// coordinate is not finite, or the file has no faces.
pub fn parse_msh(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let bad = |message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line: None,
        message,
    };
    let word = |k: usize| -> [u8; 4] {
        let at = 4 * k;
        [bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]
    };
    if bytes.len() < 16 {
        return Err(bad(format!(
            "{} bytes: a .msh file starts with four 4-byte counts",
            bytes.len()
        )));
    }
    let mut counts = [0usize; 4];
    for (k, name) in ["vertex", "normal", "texture coordinate", "face"]
        .iter()
        .enumerate()
    {
        let n = i32::from_le_bytes(word(k));
        counts[k] = usize::try_from(n).map_err(|_| bad(format!("a {name} count of {n}")))?;
    }
    let [vertices, normals, texcoords, faces] = counts;
    // In u64: the counts are i32s, so this cannot overflow, even where usize has 32 bits.
    let words = 4 + 3 * (vertices + normals + faces) as u64 + 2 * texcoords as u64;
    if 4 * words != bytes.len() as u64 {
        return Err(bad(format!(
            "{vertices} vertices, {normals} normals, {texcoords} texture coordinates and {faces} \
             faces need {} bytes, but the file has {}",
            4 * words,
            bytes.len()
        )));
    }
    if faces == 0 {
        return Err(bad(format!(
            "no faces: MuJoCo takes the convex hull of its {vertices} points, which is not read \
             here"
        )));
    }
    let mut positions = Vec::with_capacity(vertices);
    for v in 0..vertices {
        let mut p = [0.0; 3];
        for (c, x) in p.iter_mut().enumerate() {
            *x = f64::from(f32::from_le_bytes(word(4 + 3 * v + c)));
            if !x.is_finite() {
                return Err(bad(format!(
                    "vertex {v} (counting from 0) has a coordinate that is not finite: {x}"
                )));
            }
        }
        positions.push(Point3::from(p));
    }
    let first_face = 4 + 3 * vertices + 3 * normals + 2 * texcoords;
    let mut indices = Vec::with_capacity(3 * faces);
    for f in 0..faces {
        for c in 0..3 {
            let i = i32::from_le_bytes(word(first_face + 3 * f + c));
            let i = usize::try_from(i)
                .ok()
                .filter(|&i| i < vertices)
                .ok_or_else(|| {
                    bad(format!(
                        "face {f} (counting from 0) names vertex {i}, but there are {vertices} \
                     vertices"
                    ))
                })?;
            indices.push(i);
        }
    }
    let mesh = super::welded_mesh(path, &positions, indices, &vec![3; faces])?;
    Ok(MeshFile {
        mesh,
        face_lines: Vec::new(),
        warnings: Vec::new(),
        part_names: Vec::new(),
        face_parts: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::super::tests::face_points;
    use super::*;

    /// A `.msh` file of these counts and arrays, as MuJoCo lays it out.
    fn msh(
        positions: &[[f32; 3]],
        normals: usize,
        texcoords: usize,
        faces: &[[i32; 3]],
    ) -> Vec<u8> {
        let counts = [positions.len(), normals, texcoords, faces.len()].map(|n| n as i32);
        let mut out: Vec<u8> = counts.iter().flat_map(|n| n.to_le_bytes()).collect();
        out.extend(positions.iter().flatten().flat_map(|x| x.to_le_bytes()));
        out.extend(std::iter::repeat_n(0u8, 4 * (3 * normals + 2 * texcoords)));
        out.extend(faces.iter().flatten().flat_map(|i| i.to_le_bytes()));
        out
    }

    const TETRA: [[f32; 3]; 4] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    const TETRA_FACES: [[i32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];

    /// The tetrahedron with normals and texture coordinates to read past is the OBJ's mesh.
    #[test]
    fn the_tetrahedron_is_the_objs() {
        let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        let obj = super::super::parse_obj(obj.as_bytes(), Path::new("t.obj")).expect("obj");
        for (normals, texcoords) in [(0, 0), (4, 4), (12, 0)] {
            let file = parse_msh(
                &msh(&TETRA, normals, texcoords, &TETRA_FACES),
                Path::new("t.msh"),
            )
            .expect("reads");
            assert_eq!(face_points(&file.mesh), face_points(&obj.mesh));
            assert_eq!(
                crate::mass_properties(&file.mesh, 1.0).expect("integrates"),
                crate::mass_properties(&obj.mesh, 1.0).expect("integrates")
            );
        }
    }

    /// Bad files are refused by name.
    #[test]
    fn bad_files_are_refused_by_name() {
        let said = |bytes: &[u8]| {
            parse_msh(bytes, Path::new("bad.msh"))
                .map(|_| ())
                .map_err(|e| e.to_string())
        };
        let good = msh(&TETRA, 0, 0, &TETRA_FACES);
        assert_eq!(
            said(&good[..good.len() - 1]),
            Err(
                "bad.msh: 4 vertices, 0 normals, 0 texture coordinates and 4 faces need 112 \
                 bytes, but the file has 111"
                    .to_owned()
            )
        );
        assert_eq!(
            said(&msh(
                &TETRA,
                0,
                0,
                &[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 4]]
            )),
            Err(
                "bad.msh: face 3 (counting from 0) names vertex 4, but there are 4 vertices"
                    .to_owned()
            )
        );
        assert_eq!(
            said(&msh(&TETRA, 0, 0, &[])),
            Err(
                "bad.msh: no faces: MuJoCo takes the convex hull of its 4 points, which is not \
                 read here"
                    .to_owned()
            )
        );
        assert_eq!(
            said(&msh(&[[0.0, f32::NAN, 0.0]; 4], 0, 0, &TETRA_FACES)),
            Err(
                "bad.msh: vertex 0 (counting from 0) has a coordinate that is not finite: NaN"
                    .to_owned()
            )
        );
        let mut negative = good.clone();
        negative[4..8].copy_from_slice(&(-1i32).to_le_bytes());
        assert_eq!(
            said(&negative),
            Err("bad.msh: a normal count of -1".to_owned())
        );
        assert_eq!(
            said(b"short"),
            Err("bad.msh: 5 bytes: a .msh file starts with four 4-byte counts".to_owned())
        );
        // Counts that overflow the length are a length that does not match, not a panic.
        let mut huge = good;
        huge[0..4].copy_from_slice(&i32::MAX.to_le_bytes());
        assert!(said(&huge).is_err());
    }
}
