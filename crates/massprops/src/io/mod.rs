//! Reading meshes from files: Wavefront OBJ, STL (binary or ASCII), PLY (`ply.rs`: ASCII or
//! binary, either byte order), OFF (`off.rs`), glTF 2.0 (`gltf/`: `.gltf` and `.glb`, node
//! trees and quantized positions) MuJoCo's `.msh` (`msh.rs`), COLLADA (`collada/`: node trees, instances and units) and
//! 3MF (`threemf/`, from its ZIP package, `zip.rs`), the formats of [`MESH_FORMATS`]; OBJ and STL by fast paths of our own
//! for the records nearly every file is made of (`obj_fast.rs`, `stl.rs`), and through `tobj`
//! and `stl_io` for every file they decline, with the same result bit for bit. Positions with
//! identical coordinates are welded so per-corner splitting in a file never changes the
//! topology; every object and group of a file forms one body.

mod body;
mod collada;
mod gltf;
mod msh;
mod obj;
mod obj_fast;
mod obj_parsed;
mod off;
mod ply;
mod stl;
mod threemf;
mod zip;

use std::path::Path;

pub use body::{BODY_FILE_EXTENSION, BODY_FILE_VERSION, BodyFile, PartEntry, is_body_file};
pub use collada::{ColladaFile, parse_collada, parse_collada_file};
pub use gltf::{parse_gltf, parse_gltf_with};
pub use msh::parse_msh;
#[cfg(fuzzing)]
pub use obj::fast_path_agrees;
pub use obj::parse_obj;
pub use off::parse_off;
pub use ply::parse_ply;
pub use stl::parse_stl;
pub use threemf::parse_3mf;

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
}

/// A mesh format the readers take: one row of [`MESH_FORMATS`], with everything a front end
/// needs to offer it (dialog filters, drop hints, help texts, a folder's file listing) and the
/// reader that reads it. Adding a format is its reader and one row.
#[derive(Debug)]
pub struct MeshFormat {
    /// Its name as people write it ("OBJ").
    pub name: &'static str,
    /// Its file extensions, lower case, without the dot; the first is the usual one.
    pub extensions: &'static [&'static str],
    /// Whether one file can hold several named parts (OBJ objects and groups, STL solids),
    /// which a body can give their own materials.
    pub holds_parts: bool,
    /// What a file of the format starts with, if it has a signature: a file is known by it
    /// before its extension, so one named wrongly, or not at all (bytes from a table), is read.
    pub magic: &'static [&'static [u8]],
    /// For a format without a signature at its start, a test of a whole file's bytes that only
    /// its files pass (COLLADA's root element, glTF's `"asset"`, a `.msh` length that its counts
    /// give): how bytes without a name, or with a wrong one, are still read.
    pub recognise: Option<fn(&[u8]) -> bool>,
    /// Reads a file from disk in blocks, calling the progress callback with the fraction read;
    /// `None` for a format read whole and parsed.
    load: Option<LoadFn>,
    /// Parses a file already in memory.
    parse: ParseFn,
    /// For a format whose file names other files beside it (glTF's buffers), the reader that
    /// takes them from a caller (the files a browser was given) rather than from the disk.
    parse_with: Option<ParseWithFn>,
}

/// A reader of files on disk: the path, and a callback given the fraction read so far.
type LoadFn = fn(&Path, &dyn Fn(f32)) -> Result<MeshFile, MeshError>;
/// A reader of files in memory: the bytes, and the path that names them in messages.
type ParseFn = fn(&[u8], &Path) -> Result<MeshFile, MeshError>;
/// The bytes of a file named beside another (by the name the file gives), or why not.
pub type Beside<'a> = &'a dyn Fn(&str) -> Result<Vec<u8>, String>;
/// A reader of files in memory that name files beside them, given how to read those.
type ParseWithFn = fn(&[u8], &Path, Beside) -> Result<MeshFile, MeshError>;

/// Every mesh format the readers take. OBJ (free text) and STL (a binary header is 80 free bytes,
/// which often begin "solid" like an ASCII file) have no signature: they are known by their
/// extension alone.
pub static MESH_FORMATS: [MeshFormat; 8] = [
    MeshFormat {
        name: "OBJ",
        extensions: &["obj"],
        holds_parts: true,
        magic: &[],
        recognise: None,
        load: Some(obj::load_obj),
        parse: parse_obj,
        parse_with: None,
    },
    MeshFormat {
        name: "STL",
        extensions: &["stl"],
        holds_parts: true,
        magic: &[],
        recognise: None,
        load: Some(stl::load_stl),
        parse: parse_stl,
        parse_with: None,
    },
    MeshFormat {
        name: "PLY",
        extensions: &["ply"],
        holds_parts: false,
        magic: &[b"ply\n", b"ply\r\n"],
        recognise: None,
        load: None,
        parse: parse_ply,
        parse_with: None,
    },
    MeshFormat {
        name: "OFF",
        extensions: &["off"],
        holds_parts: false,
        // The keyword, with the prefixes for what each vertex carries besides its position.
        magic: &[
            b"OFF", b"COFF", b"NOFF", b"CNOFF", b"STOFF", b"STCOFF", b"STNOFF",
        ],
        recognise: None,
        load: None,
        parse: parse_off,
        parse_with: None,
    },
    MeshFormat {
        name: "glTF",
        extensions: &["glb", "gltf"],
        holds_parts: true,
        // A GLB's header; a .gltf is JSON, known by its extension.
        magic: &[gltf::GLB_MAGIC],
        recognise: Some(gltf::is_gltf_json),
        load: None,
        parse: parse_gltf,
        parse_with: Some(parse_gltf_with),
    },
    MeshFormat {
        name: "MuJoCo MSH",
        extensions: &["msh"],
        holds_parts: false,
        magic: &[],
        recognise: Some(msh::is_msh),
        load: None,
        parse: parse_msh,
        parse_with: None,
    },
    MeshFormat {
        name: "COLLADA",
        extensions: &["dae"],
        holds_parts: true,
        magic: &[],
        recognise: Some(collada::is_collada),
        load: None,
        parse: parse_collada,
        parse_with: None,
    },
    MeshFormat {
        name: "3MF",
        extensions: &["3mf"],
        holds_parts: true,
        // A ZIP archive's first local header: 3MF is the only package format in the table.
        magic: &[threemf::ZIP_MAGIC],
        recognise: None,
        load: None,
        parse: parse_3mf,
        parse_with: None,
    },
];

impl MeshFormat {
    /// The format of a file, by its extension (any case).
    pub fn of(path: &Path) -> Option<&'static MeshFormat> {
        let extension = extension(path)?;
        MESH_FORMATS
            .iter()
            .find(|f| f.extensions.contains(&extension.as_str()))
    }

    /// The format whose signature `bytes` start with, else the one whose test they pass, if
    /// any.
    pub fn sniff(bytes: &[u8]) -> Option<&'static MeshFormat> {
        MESH_FORMATS
            .iter()
            .find(|f| f.magic.iter().any(|m| bytes.starts_with(m)))
            .or_else(|| {
                MESH_FORMATS
                    .iter()
                    .find(|f| f.recognise.is_some_and(|test| test(bytes)))
            })
    }

    /// The format of a file that starts with `head`: by its signature, else by its extension.
    pub fn of_file(path: &Path, head: &[u8]) -> Option<&'static MeshFormat> {
        MeshFormat::sniff(head).or_else(|| MeshFormat::of(path))
    }

    /// Every extension of every format, in table order.
    pub fn all_extensions() -> impl Iterator<Item = &'static str> {
        MESH_FORMATS
            .iter()
            .flat_map(|f| f.extensions.iter().copied())
    }

    /// The formats' names joined for a sentence ("OBJ/STL").
    pub fn names(separator: &str) -> String {
        let names: Vec<&str> = MESH_FORMATS.iter().map(|f| f.name).collect();
        names.join(separator)
    }
}

/// Loads a mesh file of any format in [`MESH_FORMATS`] (chosen by extension, case-insensitive)
/// as one body.
///
/// OBJ and binary STL files are read in blocks: the whole file is never in memory at once
/// (unless the OBJ fast path declines it; see [`parse_obj`]).
pub fn load_mesh(path: &Path) -> Result<MeshFile, MeshError> {
    load_mesh_reporting(path, &|_| {})
}

/// [`load_mesh`], calling `progress` with the fraction of the file read so far (0 to 1) after
/// each block.
pub fn load_mesh_reporting(path: &Path, progress: &dyn Fn(f32)) -> Result<MeshFile, MeshError> {
    let format = MeshFormat::of_file(path, &head(path)).ok_or_else(|| unsupported(path))?;
    if let Some(load) = format.load {
        return load(path, progress);
    }
    let bytes = std::fs::read(path).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source: source.into(),
    })?;
    progress(1.0);
    (format.parse)(&bytes, path)
}

/// The first bytes of a file, for its signature (none if it cannot be read: the reader then
/// says why).
fn head(path: &Path) -> Vec<u8> {
    use std::io::Read as _;
    let mut head = Vec::with_capacity(16);
    if let Ok(file) = std::fs::File::open(path) {
        let _ = file.take(16).read_to_end(&mut head);
    }
    head
}

/// Parses a file already in memory; `path` names it in messages and gives the format, unless
/// the bytes carry a format's signature.
pub fn parse_mesh(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let format = MeshFormat::of_file(path, bytes).ok_or_else(|| unsupported(path))?;
    (format.parse)(bytes, path)
}

/// [`parse_mesh`] for a file whose companions (glTF's `.bin` files) come from `beside`, not
/// from the disk: the browser's dropped files.
pub fn parse_mesh_with(bytes: &[u8], path: &Path, beside: Beside) -> Result<MeshFile, MeshError> {
    let format = MeshFormat::of_file(path, bytes).ok_or_else(|| unsupported(path))?;
    match format.parse_with {
        Some(parse) => parse(bytes, path, beside),
        None => (format.parse)(bytes, path),
    }
}

/// The error for a file of no format in the table, listing the extensions there are.
fn unsupported(path: &Path) -> MeshError {
    let mut expected: Vec<String> = MeshFormat::all_extensions()
        .map(|e| format!(".{e}"))
        .collect();
    let last = expected.pop().unwrap_or_default();
    let expected = if expected.is_empty() {
        last
    } else {
        format!("{} or {last}", expected.join(", "))
    };
    MeshError::UnsupportedFormat {
        path: path.to_path_buf(),
        expected,
    }
}

/// A reader's faces as a mesh: positions welded exactly (a file's per-corner copies of a point
/// become one vertex), each face's corners (indices into `positions`, `arities[f]` of them)
/// renumbered; a problem of the mesh is named with the file.
fn welded_mesh(
    path: &Path,
    positions: &[nalgebra::Point3<f64>],
    corners: impl IntoIterator<Item = usize>,
    arities: &[usize],
) -> Result<PolyMesh, MeshError> {
    let (welded, remap) = crate::mesh::weld_exact(positions);
    let indices = corners.into_iter().map(|i| remap[i]).collect();
    PolyMesh::from_flat(welded, indices, arities).map_err(|e| MeshError::InFile {
        path: path.to_path_buf(),
        line: None,
        source: Box::new(e),
    })
}

/// `name`, or `name 2`, `name 3`… if a part already has it: each instance stays its own part.
fn unique_name(name: String, taken: &[String]) -> String {
    if !taken.contains(&name) {
        return name;
    }
    (2..)
        .map(|k| format!("{name} {k}"))
        .find(|n| !taken.contains(n))
        .unwrap_or(name)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A mesh's faces as their corners' points, in order: what a reader must keep, whatever order
    /// it numbers the vertices in (the readers' tests compare each format with the OBJ by it).
    pub(super) fn face_points(mesh: &PolyMesh) -> Vec<Vec<nalgebra::Point3<f64>>> {
        (0..mesh.face_count())
            .map(|f| mesh.face_points(f).collect())
            .collect()
    }

    /// A solid box of sides `sides` (density 1), turned by `rotation` and centred at `center`:
    /// the closed form the readers' placements are checked against.
    pub(super) fn placed_box(
        sides: [f64; 3],
        rotation: nalgebra::Matrix3<f64>,
        center: [f64; 3],
    ) -> crate::MassProperties {
        let [a, b, c] = sides;
        let m = a * b * c;
        let own = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(
            m * (b * b + c * c) / 12.0,
            m * (a * a + c * c) / 12.0,
            m * (a * a + b * b) / 12.0,
        ));
        crate::MassProperties::new(
            m,
            nalgebra::Point3::from(center),
            rotation * own * rotation.transpose(),
        )
    }

    /// Two unit cubes (density 1) centred at the origin and at (4, 0, 0): each is 2 from their
    /// centre, adding m d² = 4 to Iyy and Izz (the readers' instancing tests).
    pub(super) fn two_unit_cubes_four_apart() -> crate::MassProperties {
        let one = placed_box([1.0; 3], nalgebra::Matrix3::identity(), [0.0; 3]);
        let mut pair = one.inertia_com * 2.0;
        pair[(1, 1)] += 8.0;
        pair[(2, 2)] += 8.0;
        crate::MassProperties::new(2.0, nalgebra::Point3::new(2.0, 0.0, 0.0), pair)
    }

    /// `found` is `expected` to 1e-12 (mass and tensor relative, centre absolute).
    pub(super) fn assert_close(
        found: &crate::MassProperties,
        expected: &crate::MassProperties,
        what: &str,
    ) {
        let scale = expected.inertia_com.norm();
        assert!(
            (found.mass - expected.mass).abs() < 1e-12 * expected.mass
                && (found.center_of_mass - expected.center_of_mass).norm() < 1e-12
                && (found.inertia_com - expected.inertia_com).norm() < 1e-12 * scale,
            "{what}: found {found:?}, expected {expected:?}"
        );
    }

    /// The volume the faces enclose, signed: positive when they are wound outward (mass
    /// properties turn an inside-out body round, so winding is checked by this).
    pub(super) fn signed_volume(mesh: &PolyMesh) -> f64 {
        (0..mesh.face_count())
            .map(|f| {
                let p: Vec<nalgebra::Point3<f64>> = mesh.face_points(f).collect();
                (1..p.len() - 1)
                    .map(|k| p[0].coords.dot(&p[k].coords.cross(&p[k + 1].coords)) / 6.0)
                    .sum::<f64>()
            })
            .sum()
    }

    /// A file's mass properties at density 1.
    pub(super) fn properties(file: &MeshFile) -> crate::MassProperties {
        crate::mass_properties(&file.mesh, 1.0).expect("integrates")
    }

    const TETRA_OBJ: &str =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    const TETRA_STL: &str = "solid t\n\
        facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n\
        facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n\
        facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n\
        facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\n\
        endsolid t\n";

    /// Each row is found by each of its extensions in any case, and no extension is in two rows.
    #[test]
    fn every_format_is_found_by_its_extensions() {
        let all: Vec<&str> = MeshFormat::all_extensions().collect();
        let mut distinct = all.clone();
        distinct.sort_unstable();
        distinct.dedup();
        assert_eq!(
            distinct.len(),
            all.len(),
            "an extension in two rows: {all:?}"
        );
        for format in &MESH_FORMATS {
            for ext in format.extensions {
                assert_eq!(
                    ext.to_ascii_lowercase(),
                    *ext,
                    "{} lists {ext}",
                    format.name
                );
                for name in [format!("a.{ext}"), format!("dir/B.{}", ext.to_uppercase())] {
                    let found = MeshFormat::of(Path::new(&name)).map(|f| f.name);
                    assert_eq!(found, Some(format.name), "{name}");
                }
            }
        }
        assert!(MeshFormat::of(Path::new("robot.urdf")).is_none());
        assert!(MeshFormat::of(Path::new("no_extension")).is_none());
    }

    /// A file with a signature is read by it whatever its name says: PLY and OFF named wrongly
    /// or not at all; a name alone still decides for OBJ and STL, which have none.
    #[test]
    fn a_signature_decides_before_the_name() {
        let ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
                   property float z\nelement face 4\nproperty list uchar int vertex_indices\n\
                   end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
        let off = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
        for (text, names) in [
            (ply, ["tetra", "tetra.stl", "tetra.bin"]),
            (off, ["tetra", "tetra.obj", "x.txt"]),
        ] {
            for name in names {
                let volume = parse_mesh(text.as_bytes(), Path::new(name))
                    .map_err(|e| e.to_string())
                    .and_then(|f| crate::mass_properties(&f.mesh, 1.0).map_err(|e| e.to_string()))
                    .map(|p| p.mass);
                assert!(
                    matches!(volume, Ok(v) if (v - 1.0 / 6.0).abs() < 1e-15),
                    "{name}: {volume:?}"
                );
            }
        }
        // Formats without a signature at their start, known by their content: glTF JSON by its
        // "asset", COLLADA by its root, a .msh by the length its counts give.
        let gltf = concat!(
            r#"{"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes":"#,
            r#" {"POSITION": 0}, "indices": 1}]}], "nodes": [{"mesh": 0}], "accessors": ["#,
            r#" {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},"#,
            r#" {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}],"#,
            r#" "bufferViews": [{"buffer": 0, "byteLength": 48},"#,
            r#" {"buffer": 0, "byteOffset": 48, "byteLength": 24}], "buffers": [{"byteLength": 72,"#,
            r#" "uri": "data:application/octet-stream;base64,"#,
            "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/",
            r#"AAACAAEAAAABAAMAAAADAAIAAQACAAMA"}]}"#
        );
        let dae = r##"<?xml version="1.0"?><COLLADA version="1.4.1"><library_geometries>
            <geometry id="g"><mesh><source id="p"><float_array id="a">0 0 0 1 0 0 0 1 0 0 0 1
            </float_array><technique_common><accessor source="#a" count="4" stride="3"/>
            </technique_common></source><vertices id="v"><input semantic="POSITION" source="#p"/>
            </vertices><triangles><input semantic="VERTEX" source="#v"/>
            <p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles></mesh></geometry></library_geometries>
            <asset><up_axis>Z_UP</up_axis></asset></COLLADA>"##;
        let mut msh: Vec<u8> = [4i32, 0, 0, 4]
            .iter()
            .flat_map(|n| n.to_le_bytes())
            .collect();
        msh.extend(
            [0f32, 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1.]
                .iter()
                .flat_map(|x| x.to_le_bytes()),
        );
        msh.extend(
            [0i32, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]
                .iter()
                .flat_map(|i| i.to_le_bytes()),
        );
        for (bytes, format) in [
            (gltf.as_bytes(), "glTF"),
            (dae.as_bytes(), "COLLADA"),
            (msh.as_slice(), "MuJoCo MSH"),
        ] {
            assert_eq!(MeshFormat::sniff(bytes).map(|f| f.name), Some(format));
            for name in ["tetra", "tetra.stl"] {
                let volume = parse_mesh(bytes, Path::new(name))
                    .map_err(|e| e.to_string())
                    .and_then(|f| crate::mass_properties(&f.mesh, 1.0).map_err(|e| e.to_string()))
                    .map(|p| p.mass);
                assert!(
                    matches!(volume, Ok(v) if (v - 1.0 / 6.0).abs() < 1e-15),
                    "{format} named {name}: {volume:?}"
                );
            }
        }
        for (start, format) in [(&b"glTF\x02\0\0\0"[..], "glTF"), (b"PK\x03\x04", "3MF")] {
            assert_eq!(MeshFormat::sniff(start).map(|f| f.name), Some(format));
        }
        // A .msh's length must be the one its counts give, to the byte.
        assert!(MeshFormat::sniff(&msh[..msh.len() - 4]).is_none());
        assert!(MeshFormat::sniff(TETRA_OBJ.as_bytes()).is_none());
        assert!(MeshFormat::sniff(TETRA_STL.as_bytes()).is_none());
        let e = parse_mesh(TETRA_OBJ.as_bytes(), Path::new("tetra")).map(|_| ());
        assert!(
            matches!(e, Err(MeshError::UnsupportedFormat { .. })),
            "{e:?}"
        );
    }

    /// The table's readers read the unit tetrahedron (volume 1/6) from each format's text, and a
    /// file of no format is refused with every extension named.
    #[test]
    fn the_table_dispatches_to_each_reader() {
        for (name, text) in [("t.obj", TETRA_OBJ), ("t.stl", TETRA_STL)] {
            let file = parse_mesh(text.as_bytes(), Path::new(name));
            let mesh = file.map(|f| f.mesh).map_err(|e| e.to_string());
            let volume = mesh
                .as_ref()
                .map(|m| crate::mass_properties(m, 1.0).map(|p| p.mass));
            assert!(
                matches!(volume, Ok(Ok(v)) if (v - 1.0 / 6.0).abs() < 1e-15),
                "{name}: {volume:?}"
            );
        }
        let e = parse_mesh(b"", Path::new("a.step"))
            .map(|_| ())
            .map_err(|e| e.to_string());
        assert_eq!(
            e,
            Err(
                "a.step: unsupported file type (expected .obj, .stl, .ply, .off, .glb, .gltf, .msh, .dae or .3mf)"
                    .to_owned()
            )
        );
    }
}
