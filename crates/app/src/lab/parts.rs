//! A body made of parts, as the lab holds it: each part's settings as a body file writes them
//! ([`massprops::PartEntry`]), its mesh and its mass integrals at unit density, kept so that a
//! change of material or placement is a sum (`massprops::composite::combine`), not a new integration.

use crate::i18n::tr;
use std::path::{Path, PathBuf};

use std::sync::Arc;

use massprops::composite::{PartMass, PartProperties};
use massprops::{
    BodyFile, Fill, IntegratedPart, LengthUnit, MaterialEntry, MeshFile, PartEntry, PolyMesh,
    Repairs, Warning,
};
use nalgebra::Isometry3;

use super::error::LabError;
use inertia_io::input::{self, FileSet, Request, Resolved, Source};

/// One part: what the user set, and what was integrated once.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct PartModel {
    /// Name, mesh file, object, material, void, thin wall, placement (metres).
    pub entry: PartEntry,
    /// Drawn in the 3D view (its mass counts either way).
    pub visible: bool,
    /// Its mesh is only a piece of `entry.mesh` that no object names (a connected shell): a
    /// body file must get it its own mesh file.
    pub piece: bool,
    /// Its surface in its own coordinates (metres); shared, so that an edit copies no mesh.
    pub mesh: Arc<PolyMesh>,
    /// Its solid and surface at unit density, integrated once.
    integrated: Arc<IntegratedPart>,
}

impl PartModel {
    /// Integrates `mesh` once as a solid and as a surface.
    ///
    /// # Errors
    /// The mesh has no area (the message names the part).
    pub fn new(entry: PartEntry, mesh: PolyMesh) -> Result<Self, LabError> {
        let integrated = IntegratedPart::new(&mesh, &Repairs::default());
        Self::integrated(entry, Arc::new(mesh), Arc::new(integrated))
    }

    /// A part whose mesh was integrated already.
    ///
    /// # Errors
    /// The mesh has no area (the message names the part).
    pub fn integrated(
        entry: PartEntry,
        mesh: Arc<PolyMesh>,
        integrated: Arc<IntegratedPart>,
    ) -> Result<Self, LabError> {
        // A part must at least have a surface to be drawn and to take a thin wall.
        let wall = Fill::ThinWall {
            density: 1.0,
            thickness: 1.0,
        };
        integrated
            .properties(&entry.name, wall, &Isometry3::identity())
            .map_err(|source| LabError::Part {
                part: entry.name.clone(),
                source,
            })?;
        Ok(Self {
            entry,
            visible: true,
            piece: false,
            mesh,
            integrated,
        })
    }

    /// Mesh coordinates → body coordinates.
    pub fn placement(&self) -> Isometry3<f64> {
        // The lab keeps bodies in metres.
        self.entry.placement(1.0)
    }

    /// Its fill, by massprops' one rule (the lab keeps lengths in metres).
    pub fn fill(&self) -> Fill {
        self.entry.fill(1.0)
    }

    /// The part's density (kg/m³): given, or its preset's, or its mass over its volume.
    pub fn density(&self) -> Option<f64> {
        match &self.entry.material {
            MaterialEntry::Mass(m) => self.integrated.volume().map(|v| m / v),
            other => other.density(),
        }
    }

    /// What its mesh has wrong for its fill (faces count within the part).
    pub fn warnings(&self) -> &[Warning] {
        self.integrated.warnings(self.fill())
    }

    /// Its signed mass as it counts in the body, in body coordinates: a sum of its unit-density
    /// integrals, nothing integrated again.
    ///
    /// # Errors
    /// A solid, void or mass given to a part that encloses no volume, or no density.
    pub fn mass(&self) -> Result<PartMass, LabError> {
        self.properties().map(|p| p.part_mass())
    }

    /// The volume it adds to the body (m³): a solid's or a thin wall's material volume, negative
    /// for a void, as `props` reports each part.
    ///
    /// # Errors
    /// As [`PartModel::mass`].
    pub fn signed_volume(&self) -> Result<f64, LabError> {
        self.properties().map(|p| p.volume.copysign(p.mass))
    }

    fn properties(&self) -> Result<PartProperties, LabError> {
        let name = &self.entry.name;
        if self.density().is_none() {
            return Err(LabError::NoDensity { part: name.clone() });
        }
        let fill = self.fill();
        if self.integrated.volume().is_none() && !matches!(fill, Fill::ThinWall { .. }) {
            return Err(LabError::NoVolume { part: name.clone() });
        }
        self.integrated
            .properties(name, fill, &self.placement())
            .map_err(|source| LabError::Part {
                part: name.clone(),
                source,
            })
    }

    /// Its surface moved into place (body coordinates).
    pub fn placed_mesh(&self) -> Result<PolyMesh, LabError> {
        let p = self.placement();
        self.mesh
            .map_positions(|q| p * q)
            .map_err(|source| LabError::Part {
                part: self.entry.name.clone(),
                source,
            })
    }
}

/// The parts of a body file, through the one input path (in metres: placements and meshes
/// converted).
pub fn from_body_file(path: &Path) -> Result<Vec<PartModel>, LabError> {
    match input::resolve(Source::Path(path), &Request::default())? {
        Resolved::Parts(parts) => from_resolved(parts),
        Resolved::Mesh { .. } => Err(LabError::NotBodyFile(path.to_path_buf())),
    }
}

/// The lab's parts of a resolved body of parts, integrated already.
pub fn from_resolved(parts: input::Parts) -> Result<Vec<PartModel>, LabError> {
    // A body file not in metres: one written back from the lab (in metres) must carry its
    // parts' meshes in metres too.
    let piece = parts.body_file_units.is_some_and(|u| u != LengthUnit::M);
    parts
        .parts
        .into_iter()
        .map(|p| {
            let mut model = PartModel::integrated(p.entry, p.mesh, p.integrated)?;
            model.piece = piece;
            Ok(model)
        })
        .collect()
}

/// The body file that describes `parts`, to be written at `path` (mesh paths relative to its
/// folder where they can be).
pub fn to_body_file(parts: &[PartModel], path: &Path) -> BodyFile {
    let folder = path.parent().unwrap_or(Path::new(""));
    BodyFile {
        path: path.to_path_buf(),
        units: LengthUnit::M,
        parts: parts
            .iter()
            .map(|p| PartEntry {
                mesh: relative(&p.entry.mesh, folder),
                ..p.entry.clone()
            })
            .collect(),
    }
}

/// `path` relative to `folder` when it lies inside it (or beside it, by `..`), else as it is.
fn relative(path: &Path, folder: &Path) -> PathBuf {
    let absolute = |p: &Path| std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf());
    let (target, base) = (absolute(path), absolute(folder));
    let common = target
        .components()
        .zip(base.components())
        .take_while(|(a, b)| a == b)
        .count();
    if common == 0 {
        return path.to_path_buf();
    }
    let mut out = PathBuf::new();
    for _ in base.components().skip(common) {
        out.push("..");
    }
    for c in target.components().skip(common) {
        out.push(c);
    }
    out
}

/// A part made from a mesh file (all of it, or one object), of water's density at the origin.
pub fn entry_for(name: &str, mesh: &Path, object: Option<&str>) -> PartEntry {
    PartEntry::unplaced(name, mesh, object, MaterialEntry::Density(1000.0))
}

/// A mesh file as one new part (all of it), named after the file, of water's density.
pub fn from_mesh_file(path: &Path) -> Result<PartModel, LabError> {
    from_mesh(path, massprops::load_mesh(path)?)
}

/// Each file of `files` (meshes given by their bytes) as a new part, as [`from_mesh_file`].
pub fn from_files(files: &FileSet) -> Result<Vec<PartModel>, LabError> {
    // A glTF's `.bin` files come with it: they are read through it, not as parts.
    files
        .names()
        .filter(|path| massprops::io::MeshFormat::of(path).is_some())
        .map(|path| {
            let bytes = files.get(path).unwrap_or_default();
            from_mesh(path, files.parse_mesh(bytes, path)?)
        })
        .collect()
}

/// The mesh `file` read from `path` as one new part, named after the file.
fn from_mesh(path: &Path, file: MeshFile) -> Result<PartModel, LabError> {
    let name = path
        .file_stem()
        .map_or_else(|| "part".to_owned(), |s| s.to_string_lossy().into_owned());
    PartModel::new(entry_for(&name, path, None), file.mesh)
}

/// A single-mesh body's parts, each of `density`: the named parts of `file` (read from `path`,
/// shown as `body`), or its connected shells (a shell wound inward in a mesh that is not
/// inverted as a whole is a cavity: a void); or, when `whole`, the whole mesh as one part.
pub fn from_single(
    body: &str,
    path: &Path,
    file: &MeshFile,
    density: f64,
    whole: bool,
) -> Result<Vec<PartModel>, LabError> {
    let solid = |name: &str, object: Option<&str>, mesh: PolyMesh| {
        let mut entry = entry_for(name, path, object);
        entry.material = MaterialEntry::Density(density);
        PartModel::new(entry, mesh)
    };
    if whole {
        return Ok(vec![solid(body, None, file.mesh.clone())?]);
    }
    let named = !file.face_parts.is_empty();
    let pieces = file.parts();
    let mut parts = Vec::with_capacity(pieces.len());
    for (name, faces) in &pieces {
        let mesh = file.mesh.subset(faces)?;
        let mut part = solid(name, named.then_some(name.as_str()), mesh)?;
        part.piece = !named;
        parts.push(part);
    }
    if !named {
        // Volumes as wound: a lone inward shell's solid comes out turned.
        let signed: Vec<f64> = parts
            .iter()
            .map(|p| {
                let volume = p.integrated.volume().unwrap_or(0.0);
                if p.integrated.wound_inward() {
                    -volume
                } else {
                    volume
                }
            })
            .collect();
        if signed.iter().sum::<f64>() > 0.0 {
            for (part, v) in parts.iter_mut().zip(signed) {
                part.entry.void = v < 0.0;
            }
        }
    }
    Ok(parts)
}

/// Writes `parts` as a body file at `path`, with the meshes [`body_files`] adds. Returns what
/// was written, in words.
pub fn save(parts: &[PartModel], path: &Path) -> Result<String, LabError> {
    let files = body_files(parts, path);
    for (target, text) in &files {
        crate::platform::write_file(target, text.as_bytes()).map_err(|e| LabError::Write {
            path: target.clone(),
            message: e.to_string(),
        })?;
    }
    Ok(saved_words(parts.len(), &files))
}

/// What a save of `parts` as a body file at `path` writes, (path, text) each, the body file
/// last: a part whose mesh file is not on disk (a sample's, a connected shell's, one given by
/// its bytes) gets its own OBJ beside the body file.
pub fn body_files(parts: &[PartModel], path: &Path) -> Vec<(PathBuf, String)> {
    let folder = path.parent().unwrap_or(Path::new(""));
    let stem = path
        .file_stem()
        .map_or_else(|| "body".to_owned(), |s| s.to_string_lossy().into_owned());
    let mut files: Vec<(PathBuf, String)> = Vec::new();
    let mut saved = parts.to_vec();
    let referenced: Vec<PathBuf> = parts.iter().map(|p| p.entry.mesh.clone()).collect();
    for part in &mut saved {
        if part.entry.mesh.is_file() && !part.piece {
            continue;
        }
        // A name of its own: two parts may slug alike ("Part.1", "Part_1"), and a file another
        // part reads must not be overwritten.
        let base = format!("{stem}-{}", slug(&part.entry.name));
        let target = (1..)
            .map(|k| match k {
                1 => folder.join(format!("{base}.obj")),
                k => folder.join(format!("{base}-{k}.obj")),
            })
            .find(|t| !files.iter().any(|(f, _)| f == t) && !referenced.contains(t))
            .unwrap_or_default();
        files.push((target.clone(), obj_text(&part.entry.name, &part.mesh)));
        part.entry.mesh = target;
        part.entry.object = None;
        part.piece = false;
    }
    files.push((path.to_path_buf(), to_body_file(&saved, path).to_toml()));
    files
}

/// What a save wrote, in words: the number of parts and the meshes written beside the body.
pub fn saved_words(parts: usize, files: &[(PathBuf, String)]) -> String {
    let meshes: Vec<String> = files[..files.len().saturating_sub(1)]
        .iter()
        .filter_map(|(p, _)| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    if meshes.is_empty() {
        tr!("lab-parts", parts = parts)
    } else {
        tr!(
            "lab-parts-meshes",
            parts = parts,
            meshes = meshes.join(", ")
        )
    }
}

/// A file-name-safe form of a part's name.
fn slug(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect()
}

/// A mesh as OBJ text, one object.
fn obj_text(name: &str, mesh: &PolyMesh) -> String {
    let builder = massprops::shapes::MeshBuilder {
        positions: mesh.positions().to_vec(),
        faces: mesh
            .faces()
            .map(|f| f.iter().map(|&i| i as usize).collect())
            .collect(),
        objects: Vec::new(),
    };
    massprops::shapes::to_obj(name, "a part saved by Inertia Lab; metres", &builder)
}
