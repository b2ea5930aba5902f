//! One input path: a file (a mesh of any format in massprops' table, or a body file of parts) and what the user said
//! about its mass and its defects, turned into a body. `props`, `export` and `simulate` and the
//! app's loader all come through [`resolve`], so the same file with the same flags is the same
//! body everywhere, with the same warnings.
//!
//! A mesh file is one body unless its parts are given their own materials ([`Request::parts`]) or
//! a report per part is asked for ([`Request::by_part`]); a body file is always parts, with the
//! materials, placements and units it gives (in metres once read).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use massprops::composite::PlacedPart;
use massprops::{
    Analysis, BodyFile, Composite, Fill, IntegratedPart, LengthUnit, MassSpec, MaterialEntry,
    MeshError, MeshFile, Method, PartEntry, PolyMesh, Repairs,
};
use nalgebra::Isometry3;

/// How a body is to be made of a file.
#[derive(Debug, Clone)]
pub struct Request {
    /// How the mass is distributed (a body of parts: each part's fill decides).
    pub method: Method,
    /// A density (per mesh unit cubed, per unit squared for the shell method) or a mass.
    pub spec: MassSpec,
    /// Every coordinate multiplied by this before computing (1 for none).
    pub scale: f64,
    /// How cracks and holes are handled.
    pub repairs: Repairs,
    /// Materials given to single parts of a mesh file, by part name.
    pub parts: Vec<PartMaterial>,
    /// A mesh file reported part by part even without materials of their own.
    pub by_part: bool,
    /// kg/m³ → the mesh's density unit (1 for metres, `unit³` for a mesh in another unit), for
    /// the part materials.
    pub density_factor: f64,
}

impl Default for Request {
    /// The solid at density 1, defects handled as massprops does by default.
    fn default() -> Self {
        Self {
            method: Method::Volume,
            spec: MassSpec::Density(1.0),
            scale: 1.0,
            repairs: Repairs::default(),
            parts: Vec::new(),
            by_part: false,
            density_factor: 1.0,
        }
    }
}

/// A material given to one named part of a mesh file.
#[derive(Debug, Clone, PartialEq)]
pub struct PartMaterial {
    /// Where it was given (`--density-of`, …), for messages.
    pub source: &'static str,
    /// The part's name.
    pub name: String,
    /// Its material (a density in kg/m³, a preset, or a mass in kg).
    pub material: MaterialEntry,
}

/// A file made into a body.
#[derive(Debug, Clone)]
pub enum Resolved {
    /// One mesh, as read (and scaled), with its analysis.
    Mesh {
        /// The file's mesh, face lines and reader warnings.
        file: MeshFile,
        /// Its mass properties, approximations, diagnostics and warnings.
        analysis: Box<Analysis>,
    },
    /// A body made of parts.
    Parts(Parts),
}

/// A body made of parts, as resolved: each part integrated once, and the sums.
#[derive(Debug, Clone)]
pub struct Parts {
    /// The body file's unit, or `None` for a mesh file's parts (in its units times the scale).
    pub body_file_units: Option<LengthUnit>,
    /// Each part: its settings (lengths in metres for a body file), mesh and integrals.
    pub parts: Vec<ResolvedPart>,
    /// The whole and each part's contribution.
    pub composite: Composite,
}

/// One part of a [`Parts`].
#[derive(Debug, Clone)]
pub struct ResolvedPart {
    /// Its settings as a body file writes them (a mesh file's part: its file and object).
    pub entry: PartEntry,
    /// Its surface, in its own coordinates.
    pub mesh: Arc<PolyMesh>,
    /// Its solid and surface at unit density.
    pub integrated: Arc<IntegratedPart>,
}

/// Why a file gives no body.
#[derive(Debug, Clone, thiserror::Error)]
pub enum InputError {
    /// The file (or a part's mesh) cannot be read or gives no body.
    #[error("{}: {source}", path.display())]
    Mesh {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        #[source]
        source: MeshError,
    },
    /// The file cannot be read or parsed at all (the message names it already).
    #[error(transparent)]
    Read(MeshError),
    /// A part material names a part the file does not have.
    #[error("{flag}: the file has no part {name:?} (its parts: {})", known.join(", "))]
    UnknownPart {
        /// Where it was given.
        flag: &'static str,
        /// The name given.
        name: String,
        /// The file's parts.
        known: Vec<String>,
    },
    /// A body of parts needs each part's mass, not one for the whole.
    #[error("with parts, give each part's mass with --mass-of NAME=M (--mass is the whole body's)")]
    MassOfParts,
}

/// Where the file's bytes come from.
#[derive(Clone, Copy)]
pub enum Source<'a> {
    /// Read the file.
    Path(&'a Path),
    /// Bytes already read from this path.
    Bytes(&'a [u8], &'a Path),
    /// Read the file, reporting the fraction read (the app's progress bar).
    Reported(&'a Path, &'a dyn Fn(f32)),
    /// The file of this name in a set given by their bytes; a body file's meshes come from the
    /// same set.
    Set(&'a FileSet, &'a Path),
}

impl Source<'_> {
    fn path(&self) -> &Path {
        match self {
            Source::Path(p) | Source::Bytes(_, p) | Source::Reported(p, _) | Source::Set(_, p) => p,
        }
    }
}

/// Files given by their bytes, not by a path: what a browser hands over when files are dropped
/// on the page or picked (it gives names, never folders). A body file arrives with its meshes.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FileSet {
    files: Vec<(PathBuf, Arc<[u8]>)>,
}

impl FileSet {
    /// Adds a file (a later file of the same name replaces an earlier one).
    pub fn add(&mut self, name: impl Into<PathBuf>, bytes: impl Into<Arc<[u8]>>) {
        let name = name.into();
        self.files.retain(|(n, _)| *n != name);
        self.files.push((name, bytes.into()));
    }

    /// The names, in the order added.
    pub fn names(&self) -> impl Iterator<Item = &Path> {
        self.files.iter().map(|(n, _)| n.as_path())
    }

    /// The bytes of `path`: the file of that name, or else the one whose name is its last
    /// component (a body file's `meshes/head.obj` is the dropped `head.obj`).
    pub fn get(&self, path: &Path) -> Option<&[u8]> {
        let exact = self.files.iter().find(|(n, _)| n == path);
        let by_name = || {
            let name = path.file_name()?;
            self.files.iter().find(|(n, _)| n.file_name() == Some(name))
        };
        exact.or_else(by_name).map(|(_, b)| &b[..])
    }

    /// The file that says what the body is: the first body file, else the first mesh (not a
    /// glTF's `.bin` dropped before it), else the first file.
    pub fn main(&self) -> Option<&Path> {
        let body = self.names().find(|n| massprops::io::is_body_file(n));
        let mesh = || {
            self.names()
                .find(|n| massprops::io::MeshFormat::of(n).is_some())
        };
        body.or_else(mesh).or_else(|| self.names().next())
    }

    /// Reads a mesh of the set, its companions (a glTF's `.bin` files) from the set too.
    pub fn parse_mesh(&self, bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
        let beside = |name: &str| {
            self.get(Path::new(name))
                .map(<[u8]>::to_vec)
                .ok_or_else(|| format!("{name} is not among the files given with it"))
        };
        massprops::parse_mesh_with(bytes, path, &beside)
    }
}

/// A set crosses to the page's worker as its names and bytes (bytes as one block each, not a
/// number per byte).
impl serde::Serialize for FileSet {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(
            self.files
                .iter()
                .map(|(name, bytes)| (name, serde_bytes::Bytes::new(bytes))),
        )
    }
}

impl<'de> serde::Deserialize<'de> for FileSet {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let files: Vec<(PathBuf, serde_bytes::ByteBuf)> = serde::Deserialize::deserialize(d)?;
        Ok(Self {
            files: files
                .into_iter()
                .map(|(name, bytes)| (name, bytes.into_vec().into()))
                .collect(),
        })
    }
}

/// Makes `source` into a body as `request` says.
///
/// # Errors
/// The file cannot be read, parsed or integrated (named, with the reason), a part material names
/// no part of the file, or a total mass is given for parts.
pub fn resolve(source: Source<'_>, request: &Request) -> Result<Resolved, InputError> {
    let path = source.path();
    if massprops::io::is_body_file(path) {
        let parse = |bytes: &[u8], p: &Path| {
            std::str::from_utf8(bytes)
                .map_err(|e| MeshError::Malformed {
                    path: p.to_path_buf(),
                    line: None,
                    message: format!("not UTF-8 text: {e}"),
                })
                .and_then(|text| BodyFile::parse(text, p))
        };
        let (body, loaded) = match source {
            Source::Path(p) | Source::Reported(p, _) => {
                BodyFile::read(p).and_then(|body| body.load().map(|parts| (body, parts)))
            }
            Source::Bytes(bytes, p) => {
                parse(bytes, p).and_then(|body| body.load().map(|parts| (body, parts)))
            }
            Source::Set(set, p) => set
                .get(p)
                .ok_or_else(|| missing(p))
                .and_then(|bytes| parse(bytes, p))
                .and_then(|body| {
                    let read = |mesh: &Path| {
                        set.get(mesh)
                            .map(|bytes| set.parse_mesh(bytes, mesh))
                            .transpose()
                    };
                    body.load_with(&read).map(|parts| (body, parts))
                }),
        }
        .map_err(InputError::Read)?;
        return body_file_parts(&body, loaded, request).map(Resolved::Parts);
    }
    let file = match source {
        Source::Path(p) => massprops::load_mesh(p),
        Source::Reported(p, progress) => massprops::load_mesh_reporting(p, progress),
        Source::Bytes(bytes, p) => massprops::parse_mesh(bytes, p),
        Source::Set(set, p) => set
            .get(p)
            .ok_or_else(|| missing(p))
            .and_then(|bytes| set.parse_mesh(bytes, p)),
    }
    .map_err(InputError::Read)?;
    resolve_mesh(path, file, request)
}

/// [`resolve`] of a mesh file already read from `path`: scaled, then its parts or the one body.
///
/// # Errors
/// As [`resolve`], after reading.
pub fn resolve_mesh(
    path: &Path,
    mut file: MeshFile,
    request: &Request,
) -> Result<Resolved, InputError> {
    let at = |source: MeshError| InputError::Mesh {
        path: path.to_path_buf(),
        source,
    };
    if request.scale != 1.0 {
        file.mesh = file.mesh.map_positions(|p| p * request.scale).map_err(at)?;
    }
    if !request.parts.is_empty() || request.by_part {
        return mesh_file_parts(path, &file, request).map(Resolved::Parts);
    }
    let analysis = file
        .analyze(request.method, request.spec, &request.repairs)
        .map_err(at)?;
    Ok(Resolved::Mesh {
        file,
        analysis: Box::new(analysis),
    })
}

/// A file a [`FileSet`] does not hold, said as the file system says it.
fn missing(path: &Path) -> MeshError {
    MeshError::Io {
        path: path.to_path_buf(),
        source: Arc::new(std::io::Error::new(
            std::io::ErrorKind::NotFound,
            "not among the files given",
        )),
    }
}

/// A body file's parts (`loaded`: their meshes, as [`BodyFile::load`] gives them), integrated
/// and summed.
fn body_file_parts(
    body: &BodyFile,
    loaded: Vec<massprops::composite::Part>,
    request: &Request,
) -> Result<Parts, InputError> {
    let at = |source: MeshError| InputError::Mesh {
        path: body.path.clone(),
        source,
    };
    let entries = body.in_metres().parts;
    let parts = entries
        .into_iter()
        .zip(loaded)
        .map(|(entry, part)| (entry, part.mesh, part.fill, part.placement))
        .collect();
    let mut parts = integrate(parts, &request.repairs).map_err(at)?;
    parts.body_file_units = Some(body.units);
    Ok(parts)
}

/// A mesh file's parts (its objects, groups or solids, or its connected shells), each with the
/// material `request` gives it or the request's density.
fn mesh_file_parts(path: &Path, file: &MeshFile, request: &Request) -> Result<Parts, InputError> {
    let MassSpec::Density(density) = request.spec else {
        return Err(InputError::MassOfParts);
    };
    let found = file.parts();
    let names: Vec<String> = found.iter().map(|(n, _)| n.clone()).collect();
    let default = MaterialEntry::Density(density);
    let mut materials: Vec<MaterialEntry> = vec![default; found.len()];
    for given in &request.parts {
        let Some(k) = names.iter().position(|n| *n == given.name) else {
            return Err(InputError::UnknownPart {
                flag: given.source,
                name: given.name.clone(),
                known: names,
            });
        };
        // Densities in kg/m³ become the mesh's density unit; a mass stays in kg.
        materials[k] = match &given.material {
            MaterialEntry::Mass(m) => MaterialEntry::Mass(*m),
            m => MaterialEntry::Density(m.density().unwrap_or(f64::NAN) * request.density_factor),
        };
    }
    let named = !file.part_names.is_empty();
    let mut parts = Vec::with_capacity(found.len());
    for ((name, faces), material) in found.iter().zip(materials) {
        let mesh = file.mesh.subset(faces).map_err(|e| InputError::Mesh {
            path: path.to_path_buf(),
            source: MeshError::InPart {
                part: name.clone(),
                source: Box::new(e),
            },
        })?;
        let fill = material.fill(false, None);
        let object = named.then_some(name.as_str());
        let entry = PartEntry::unplaced(name, path, object, material);
        parts.push((entry, mesh, fill, Isometry3::identity()));
    }
    integrate(parts, &request.repairs).map_err(|source| InputError::Mesh {
        path: path.to_path_buf(),
        source,
    })
}

/// Integrates each part once and sums them: `(settings, mesh, fill, placement)` each.
fn integrate(
    parts: Vec<(PartEntry, PolyMesh, Fill, Isometry3<f64>)>,
    repairs: &Repairs,
) -> Result<Parts, MeshError> {
    let resolved: Vec<ResolvedPart> = parts
        .iter()
        .map(|(entry, mesh, ..)| ResolvedPart {
            entry: entry.clone(),
            integrated: Arc::new(IntegratedPart::new(mesh, repairs)),
            mesh: Arc::new(PolyMesh::clone(mesh)),
        })
        .collect();
    let placed: Vec<PlacedPart<'_>> = parts
        .iter()
        .zip(&resolved)
        .map(|((entry, _, fill, placement), r)| PlacedPart {
            name: &entry.name,
            fill: *fill,
            placement: *placement,
            integrated: &r.integrated,
        })
        .collect();
    let composite = massprops::composite::sum(&placed)?;
    Ok(Parts {
        body_file_units: None,
        parts: resolved,
        composite,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_set_finds_files_by_path_or_name_and_opens_the_body_file() {
        let mut set = FileSet::default();
        set.add("head.obj", b"a".to_vec());
        set.add("hammer.toml", b"b".to_vec());
        set.add("meshes/head.obj", b"c".to_vec());
        set.add("hammer.toml", b"d".to_vec());
        assert_eq!(set.get(Path::new("meshes/head.obj")), Some(&b"c"[..]));
        assert_eq!(set.get(Path::new("head.obj")), Some(&b"a"[..]));
        // A body file's folder is not the browser's: the name alone finds it.
        assert_eq!(set.get(Path::new("parts/head.obj")), Some(&b"a"[..]));
        assert_eq!(set.get(Path::new("hammer.toml")), Some(&b"d"[..]));
        assert_eq!(set.get(Path::new("handle.obj")), None);
        assert_eq!(set.names().count(), 3);
        assert_eq!(set.main(), Some(Path::new("hammer.toml")));
        let mut meshes = FileSet::default();
        meshes.add("b.stl", b"".to_vec());
        meshes.add("a.obj", b"".to_vec());
        assert_eq!(meshes.main(), Some(Path::new("b.stl")));
        assert_eq!(FileSet::default().main(), None);
    }

    /// A `.gltf` whose buffer is a `.bin` beside it opens from a set that holds both, whatever
    /// their order, and as a body file's mesh; without the `.bin`, the error names it.
    #[test]
    fn a_gltf_from_a_set_reads_its_bin_from_the_set() {
        let gltf = r#"{"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                          {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}],
            "bufferViews": [{"buffer": 0, "byteLength": 48},
                            {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
            "buffers": [{"byteLength": 72, "uri": "tetra.bin"}]}"#;
        let mut bin: Vec<u8> = [0f32, 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1.]
            .iter()
            .flat_map(|x| x.to_le_bytes())
            .collect();
        bin.extend(
            [0u16, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]
                .iter()
                .flat_map(|i| i.to_le_bytes()),
        );
        let body = "version = 1\nunits = \"m\"\n\n[[part]]\nname = \"tip\"\n\
                    mesh = \"meshes/tetra.gltf\"\ndensity = 3.0\n";
        let request = Request::default();
        let volume = |set: &FileSet| -> Result<f64, String> {
            let main = set.main().ok_or("no file")?.to_path_buf();
            match resolve(Source::Set(set, &main), &request).map_err(|e| e.to_string())? {
                Resolved::Mesh { analysis, .. } => Ok(analysis.properties.mass),
                Resolved::Parts(parts) => Ok(parts.composite.properties.mass / 3.0),
            }
        };
        for order in [["tetra.bin", "tetra.gltf"], ["tetra.gltf", "tetra.bin"]] {
            let mut set = FileSet::default();
            for name in order {
                let bytes = if name.ends_with("bin") {
                    bin.clone()
                } else {
                    gltf.into()
                };
                set.add(name, bytes);
            }
            assert_eq!(set.main(), Some(Path::new("tetra.gltf")));
            let v = volume(&set).expect("reads");
            assert!((v - 1.0 / 6.0).abs() < 1e-15, "{order:?}: {v}");
            set.add("tip.toml", body.as_bytes().to_vec());
            let v = volume(&set).expect("the body file's mesh");
            assert!((v - 1.0 / 6.0).abs() < 1e-15, "as a part: {v}");
        }
        let mut alone = FileSet::default();
        alone.add("tetra.gltf", gltf.as_bytes().to_vec());
        assert_eq!(
            volume(&alone),
            Err(
                "tetra.gltf: buffer 0: cannot read tetra.bin: tetra.bin is not among the files \
                 given with it"
                    .to_owned()
            )
        );
    }

    #[test]
    fn a_mesh_from_a_set_is_the_mesh_from_its_bytes() {
        let text = massprops::shapes::to_obj(
            "cube",
            "",
            &massprops::shapes::cuboid(
                nalgebra::Vector3::new(2.0, 2.0, 2.0),
                nalgebra::Point3::origin(),
            ),
        );
        let mut set = FileSet::default();
        set.add("cube.obj", text.as_bytes().to_vec());
        let request = Request::default();
        let from_set = resolve(Source::Set(&set, Path::new("cube.obj")), &request).expect("set");
        let from_bytes = resolve(
            Source::Bytes(text.as_bytes(), Path::new("cube.obj")),
            &request,
        )
        .expect("bytes");
        let mass = |r: &Resolved| match r {
            Resolved::Mesh { analysis, .. } => analysis.properties.mass,
            Resolved::Parts(_) => panic!("one mesh"),
        };
        assert_eq!(mass(&from_set), 8.0);
        assert_eq!(mass(&from_set), mass(&from_bytes));
        let missing = resolve(Source::Set(&set, Path::new("torus.obj")), &request);
        assert!(
            matches!(&missing, Err(InputError::Read(MeshError::Io { path, .. })) if path.ends_with("torus.obj")),
            "{missing:?}"
        );
    }
}
