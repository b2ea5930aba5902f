//! The body a specimen simulates, as loaded: its drawing and picking mesh, its analysis, and for
//! a body made of parts its [`Composition`]. An edit of a part's material, void or thin wall only
//! re-sums the parts' masses; a placement edit moves one part's vertices and refits the picking
//! index; only a change of topology (add, remove, split) assembles the body again.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use massprops::composite::combine;
use massprops::{
    Analysis, BodyFile, MassProperties, MassSpec, MeshFile, Method, PartEntry, PolyMesh,
};
use nalgebra::{Point3, Vector3};

use super::error::LabError;
use super::geometry::{DRAW_BUDGET, Drawn, TriMesh};
use super::parts::PartModel;
use super::picking::Bvh;
use super::samples::{SAMPLE_BODIES, SAMPLE_PART_MESHES, SAMPLES};
use inertia_io::input::Request;

/// A body made of parts, as loaded: the parts and what they make together.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct Composition {
    /// The parts, in order.
    pub parts: Vec<PartModel>,
    /// The whole at scale 1 (body coordinates, metres).
    pub whole: MassProperties,
    /// Each part's share of each principal moment of the whole.
    pub shares: Vec<Vector3<f64>>,
    /// Each part's signed mass.
    pub masses: Vec<f64>,
    /// The body's volume (m³, scale 1): its solid parts' and thin walls' material less its voids.
    pub volume: f64,
    /// Each part's triangles in [`LoadedBody::mesh`].
    pub triangles: Vec<Range<usize>>,
    /// Each part's vertices in [`LoadedBody::mesh`].
    pub vertices: Vec<Range<usize>>,
}

impl Composition {
    /// The sums of `parts`, laid out in the merged mesh as `triangles` and `vertices` say.
    fn summed(
        parts: Vec<PartModel>,
        triangles: Vec<Range<usize>>,
        vertices: Vec<Range<usize>>,
    ) -> Result<Self, LabError> {
        let masses = parts
            .iter()
            .map(PartModel::mass)
            .collect::<Result<Vec<_>, _>>()?;
        let (whole, shares) = combine(&masses)?;
        let volume = parts
            .iter()
            .map(PartModel::signed_volume)
            .sum::<Result<f64, _>>()?;
        Ok(Self {
            volume,
            masses: masses.iter().map(|m| m.mass).collect(),
            parts,
            whole,
            shares,
            triangles,
            vertices,
        })
    }
}

/// A mesh ready for the lab: its triangles, picking index and mass properties at unit density
/// and scale (the model rescales them live).
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct LoadedBody {
    /// Shown in the side panel and the messages (the file name, or the sample's label).
    pub name: String,
    /// Render and picking triangles, mesh coordinates (shared: an edit that keeps them copies
    /// nothing).
    pub mesh: Arc<TriMesh>,
    /// Picking index over `mesh`.
    pub bvh: Arc<Bvh>,
    /// What the 3D view draws instead of `mesh` when it has more than [`DRAW_BUDGET`]
    /// triangles; `None`: `mesh` itself.
    pub drawn: Option<Arc<Drawn>>,
    /// Bounding sphere (centre, radius) of `mesh`, mesh coordinates.
    pub sphere: (Point3<f64>, f64),
    /// Exact, bounding-box and point-mass properties at density 1, plus diagnostics and warnings.
    pub analysis: Analysis,
    /// The file line of each face (empty when the format has none), for the warnings' words.
    pub face_lines: Vec<u32>,
    /// For each warning of `analysis`, its example faces: (face index, corner vertices of
    /// `mesh`), for highlighting.
    pub warning_faces: Vec<Vec<(usize, Vec<u32>)>>,
    /// A single mesh's file: where it came from (a path, or a sample's or built body's name)
    /// and what was read, to split it into parts. `None` for a body made of parts.
    pub file: Option<(PathBuf, Arc<MeshFile>)>,
    /// The parts, for a body made of parts (`analysis` then describes their surfaces together,
    /// and the mass properties come from here).
    pub composition: Option<Composition>,
    /// What a robot description states for this body (a link shown alone), at scale 1, body
    /// coordinates: the "stated" inertia source.
    pub stated: Option<MassProperties>,
    /// A whole robot's links, each with its stated and computed inertia in body coordinates
    /// (drawn as equivalent ellipsoids); empty for any other body.
    pub links: Vec<LinkMark>,
}

/// One link of a robot drawn whole: its name, and its stated and computed inertia placed in the
/// robot's frame.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct LinkMark {
    /// The link's name.
    pub name: String,
    /// As the description states it.
    pub stated: Option<MassProperties>,
    /// From its geometry.
    pub computed: Option<MassProperties>,
}

/// What a part edit changed, for whoever draws the body.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EditEffect {
    /// Only masses: the drawing is the same.
    Masses,
    /// What is drawn changed (a part shown or hidden, or moved).
    Drawing,
}

impl LoadedBody {
    /// Analyses a mesh read from a file (its defects handled as massprops does by default).
    ///
    /// # Errors
    /// The mesh encloses no volume even with its holes capped, or is otherwise unusable; the
    /// message names the cause and `name`.
    pub(crate) fn new(name: &str, path: PathBuf, file: MeshFile) -> Result<Self, LabError> {
        // As the one input path analyses a file for the lab.
        let r = Request::default();
        let analysis = file
            .analyze(r.method, r.spec, &r.repairs)
            .map_err(|e| LabError::from(e).named(name))?;
        Ok(Self::analysed(name, path, file, analysis))
    }

    /// A mesh read from `path` with its analysis at unit density.
    pub fn analysed(name: &str, path: PathBuf, file: MeshFile, analysis: Analysis) -> Self {
        let mut body = Self::assemble(name, &file.mesh, analysis);
        body.face_lines = file.face_lines.clone();
        body.file = Some((path, Arc::new(file)));
        body
    }

    /// The drawing and picking mesh of `poly`, with its analysis and each warning's faces.
    fn assemble(name: &str, poly: &PolyMesh, analysis: Analysis) -> Self {
        let warning_faces = analysis
            .warnings
            .iter()
            .map(|w| {
                w.faces
                    .iter()
                    .map(|&f| (f, poly.face(f).to_vec()))
                    .collect()
            })
            .collect();
        let mesh = TriMesh::from_poly(poly);
        let bvh = Bvh::build(&mesh);
        Self {
            name: name.to_owned(),
            sphere: mesh.bounding_sphere(),
            drawn: Drawn::of(&mesh, DRAW_BUDGET).map(Arc::new),
            mesh: Arc::new(mesh),
            bvh: Arc::new(bvh),
            analysis,
            face_lines: Vec::new(),
            warning_faces,
            file: None,
            composition: None,
            stated: None,
            links: Vec::new(),
        }
    }

    /// A body made of `parts`: their placed surfaces together for drawing and picking, and their
    /// masses summed.
    ///
    /// # Errors
    /// No parts; a part without a mass; voids that leave no body.
    pub fn from_parts(name: &str, parts: Vec<PartModel>) -> Result<Self, LabError> {
        let named = |e: LabError| e.named(name);
        let mut positions = Vec::new();
        let mut indices = Vec::new();
        let mut arities = Vec::new();
        let mut triangles = Vec::with_capacity(parts.len());
        let mut vertices = Vec::with_capacity(parts.len());
        let mut first = 0;
        for part in &parts {
            let placed = part.placed_mesh()?;
            let base = positions.len() as u32;
            positions.extend_from_slice(placed.positions());
            vertices.push(base as usize..positions.len());
            for face in placed.faces() {
                indices.extend(face.iter().map(|&i| i + base));
                arities.push(face.len());
            }
            triangles.push(first..first + placed.triangle_count());
            first += placed.triangle_count();
        }
        let composition = Composition::summed(parts, triangles, vertices).map_err(named)?;
        let merged = PolyMesh::from_flat(positions, indices, &arities)
            .map_err(|e| named(LabError::from(e)))?;
        // The parts' surfaces together, for the diagnostics and the approximations (at the
        // whole's mass: no enclosed volume needed, so sheets and voids are fine).
        let analysis = massprops::analyze(
            &merged,
            Method::Points,
            MassSpec::Mass(composition.whole.mass),
        )
        .map_err(|e| named(LabError::from(e)))?;
        let mut body = Self::assemble(name, &merged, analysis);
        body.composition = Some(composition);
        Ok(body)
    }

    /// This body with part `index` given `entry` and `visible`, without assembling it again: the
    /// masses are re-summed from each part's unit-density integrals, and a moved part's vertices
    /// are placed anew (the picking index refitted, the approximations recomputed).
    ///
    /// # Errors
    /// Not a body made of parts, no such part, the last part shown hidden, or a mass the
    /// parts cannot make; `self` is unchanged then.
    pub fn edit_part(
        &self,
        index: usize,
        entry: PartEntry,
        visible: bool,
    ) -> Result<(Self, EditEffect), LabError> {
        let Some(c) = &self.composition else {
            return Err(LabError::NoPart(index));
        };
        let mut parts = c.parts.clone();
        let part = parts.get_mut(index).ok_or(LabError::NoPart(index))?;
        let moved =
            part.entry.rotation != entry.rotation || part.entry.translation != entry.translation;
        let shown = part.visible != visible;
        part.entry = entry;
        part.visible = visible;
        if !parts.iter().any(|p| p.visible) {
            return Err(LabError::LastShown);
        }
        let named = |e: LabError| e.named(&self.name);
        let composition =
            Composition::summed(parts, c.triangles.clone(), c.vertices.clone()).map_err(named)?;
        let mut body = self.clone();
        let whole = composition.whole.mass;
        if moved {
            let part = &composition.parts[index];
            let placed = part.placed_mesh()?;
            let mut mesh = (*self.mesh).clone();
            mesh.positions[composition.vertices[index].clone()].copy_from_slice(placed.positions());
            let mut bvh = (*self.bvh).clone();
            bvh.refit(&mesh);
            // The approximations need the vertices the faces use, as placed now.
            let merged = PolyMesh::from_triangles(mesh.positions.clone(), &mesh.triangles)
                .map_err(|e| named(LabError::from(e)))?;
            body.analysis.bounding_box =
                massprops::approximations::bounding_box_properties(&merged, whole)?;
            body.analysis.point_masses =
                massprops::approximations::point_mass_properties(&merged, whole)?;
            body.analysis.properties = body.analysis.point_masses;
            body.sphere = mesh.bounding_sphere();
            body.drawn = Drawn::of(&mesh, DRAW_BUDGET).map(Arc::new);
            body.mesh = Arc::new(mesh);
            body.bvh = Arc::new(bvh);
        } else {
            let rescaled = |p: &MassProperties| p.with_mass(whole).map_err(LabError::from);
            body.analysis.bounding_box = rescaled(&self.analysis.bounding_box)?;
            body.analysis.point_masses = rescaled(&self.analysis.point_masses)?;
            body.analysis.properties = rescaled(&self.analysis.properties)?;
        }
        body.composition = Some(composition);
        let effect = if moved || shown {
            EditEffect::Drawing
        } else {
            EditEffect::Masses
        };
        Ok((body, effect))
    }

    /// A sample body made of parts, by label.
    ///
    /// # Errors
    /// Unknown label, or (never for the shipped assets) a parse failure.
    fn sample_body(label: &str) -> Result<Self, LabError> {
        let (_, file, text) = SAMPLE_BODIES
            .iter()
            .find(|(l, ..)| *l == label)
            .ok_or_else(|| LabError::UnknownSample(label.to_owned()))?;
        let body = BodyFile::parse(text, Path::new(file))?;
        let embedded = |path: &Path| {
            let name = path
                .file_name()
                .and_then(|n| n.to_str())
                .unwrap_or_default();
            let text = SAMPLES
                .iter()
                .map(|(_, f, t)| (*f, *t))
                .chain(SAMPLE_PART_MESHES)
                .find(|(f, _)| *f == name)
                .map(|(_, t)| t);
            text.map(|t| massprops::parse_mesh(t.as_bytes(), path))
                .transpose()
        };
        let parts = body.load_with(&embedded)?;
        let models = body
            .parts
            .into_iter()
            .zip(parts)
            .map(|(entry, part)| PartModel::new(entry, part.mesh))
            .collect::<Result<Vec<_>, _>>()?;
        Self::from_parts(label, models)
    }

    /// Its volume at scale 1 (m³): a single mesh's enclosed volume (its analysis is at density
    /// 1), or a body of parts' solids and thin walls less its voids.
    pub fn volume(&self) -> f64 {
        self.composition
            .as_ref()
            .map_or(self.analysis.properties.mass, |c| c.volume)
    }

    /// A mesh built in code (no file, no lines), analysed as a file of it would be.
    pub fn built(name: &str, mesh: PolyMesh) -> Result<Self, LabError> {
        let file = MeshFile {
            mesh,
            face_lines: Vec::new(),
            warnings: Vec::new(),
            part_names: Vec::new(),
            face_parts: Vec::new(),
        };
        Self::new(name, PathBuf::from(format!("{name}.obj")), file)
    }

    /// A built-in sample by label.
    ///
    /// # Errors
    /// Unknown label, or (never for the shipped assets) a parse failure.
    pub fn sample(label: &str) -> Result<Self, LabError> {
        if SAMPLE_BODIES.iter().any(|(l, ..)| *l == label) {
            return Self::sample_body(label);
        }
        let (_, file, text) = SAMPLES
            .iter()
            .find(|(l, ..)| *l == label)
            .ok_or_else(|| LabError::UnknownSample(label.to_owned()))?;
        let parsed = massprops::parse_mesh(text.as_bytes(), Path::new(file))
            .map_err(|e| LabError::from(e).named(label))?;
        Self::new(label, PathBuf::from(file), parsed)
    }

    /// The default body: the T-handle.
    pub fn t_handle() -> Result<Self, LabError> {
        Self::built("T-handle", massprops::shapes::t_handle().build())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_sample_loads() {
        for (label, ..) in SAMPLES {
            let b = LoadedBody::sample(label).expect(label);
            assert!(b.analysis.properties.mass > 0.0, "{label}");
            assert!(!b.mesh.triangles.is_empty());
        }
        assert!(LoadedBody::sample("nope").is_err());
    }
}
