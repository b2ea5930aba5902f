//! Loading a body off the UI thread: read (with progress), parse, mass properties and the picking
//! index run on a worker thread that reports through a channel, so a large mesh never freezes the
//! UI.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::thread;

use std::ops::Range;
use std::sync::Arc;

use massprops::{
    Analysis, BodyFile, MassProperties, MassSpec, MeshFile, Method, PolyMesh, Repairs,
};
use nalgebra::Vector3;

use super::geometry::TriMesh;
use super::parts::{PartModel, from_body_file};
use super::picking::Bvh;

/// The sample bodies, embedded so the binary needs no files: (label, file name, OBJ text).
pub const SAMPLES: [(&str, &str, &str); 7] = [
    (
        "T-handle",
        "t_handle.obj",
        include_str!("../../../../assets/t_handle.obj"),
    ),
    (
        "Tennis racket",
        "tennis_racket.obj",
        include_str!("../../../../assets/tennis_racket.obj"),
    ),
    (
        "Book",
        "book.obj",
        include_str!("../../../../assets/book.obj"),
    ),
    (
        "Hammer",
        "hammer.obj",
        include_str!("../../../../assets/hammer.obj"),
    ),
    (
        "L-bracket",
        "l_bracket.obj",
        include_str!("../../../../assets/l_bracket.obj"),
    ),
    (
        "Cube",
        "cube.obj",
        include_str!("../../../../assets/cube.obj"),
    ),
    (
        "Torus",
        "torus.obj",
        include_str!("../../../../assets/torus.obj"),
    ),
];

/// Sample bodies made of parts, embedded with their meshes: (label, body file name, body file
/// text). Their meshes are among [`SAMPLES`].
pub const SAMPLE_BODIES: [(&str, &str, &str); 3] = [
    (
        "Hammer: steel & wood",
        "hammer.toml",
        include_str!("../../../../assets/hammer.toml"),
    ),
    (
        "Racket: frame, strings, handle",
        "tennis_racket.toml",
        include_str!("../../../../assets/tennis_racket.toml"),
    ),
    (
        "Hollow box & solid box",
        "hollow_box.toml",
        include_str!("../../../../assets/hollow_box.toml"),
    ),
];

/// The mesh files the sample bodies use, besides [`SAMPLES`].
const SAMPLE_PART_MESHES: [(&str, &str); 1] = [(
    "hollow_box.obj",
    include_str!("../../../../assets/hollow_box.obj"),
)];

/// A body made of parts, as loaded: the parts and what they make together.
#[derive(Debug, Clone)]
pub struct Composition {
    /// The parts, in order.
    pub parts: Vec<PartModel>,
    /// The whole at scale 1 (body coordinates, metres).
    pub whole: MassProperties,
    /// Each part's share of each principal moment of the whole.
    pub shares: Vec<Vector3<f64>>,
    /// Each part's signed mass.
    pub masses: Vec<f64>,
    /// Each part's triangles in [`LoadedBody::mesh`].
    pub triangles: Vec<Range<usize>>,
}

/// A mesh ready for the lab: its triangles, picking index and mass properties at unit density
/// and scale (the model rescales them live).
#[derive(Debug, Clone)]
pub struct LoadedBody {
    /// Shown in the side panel and the messages (the file name, or the sample's label).
    pub name: String,
    /// Render and picking triangles, mesh coordinates.
    pub mesh: TriMesh,
    /// Picking index over `mesh`.
    pub bvh: Bvh,
    /// Bounding sphere (centre, radius) of `mesh`, mesh coordinates.
    pub sphere: (nalgebra::Point3<f64>, f64),
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
}

impl LoadedBody {
    /// Analyses a mesh read from a file (its defects handled as massprops does by default).
    ///
    /// # Errors
    /// The mesh encloses no volume even with its holes capped, or is otherwise unusable; the
    /// message names the cause and `name`.
    pub fn new(name: &str, path: PathBuf, file: MeshFile) -> Result<Self, String> {
        let analysis = file
            .analyze(Method::Volume, MassSpec::Density(1.0), &Repairs::default())
            .map_err(|e| format!("{name}: {e}"))?;
        let mut body = Self::assemble(name, &file.mesh, analysis);
        body.face_lines = file.face_lines.clone();
        body.file = Some((path, Arc::new(file)));
        Ok(body)
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
            mesh,
            bvh,
            analysis,
            face_lines: Vec::new(),
            warning_faces,
            file: None,
            composition: None,
        }
    }

    /// A body made of `parts`: their placed surfaces together for drawing and picking, and their
    /// masses summed.
    ///
    /// # Errors
    /// No parts; a part without a mass; voids that leave no body.
    pub fn from_parts(name: &str, parts: Vec<PartModel>) -> Result<Self, String> {
        let masses = parts
            .iter()
            .map(PartModel::mass)
            .collect::<Result<Vec<_>, _>>()?;
        let (whole, shares) = massprops::combine(&masses).map_err(|e| format!("{name}: {e}"))?;
        let mut positions = Vec::new();
        let mut indices = Vec::new();
        let mut arities = Vec::new();
        let mut triangles = Vec::with_capacity(parts.len());
        let mut first = 0;
        for part in &parts {
            let placed = part.placed_mesh()?;
            let base = positions.len() as u32;
            positions.extend_from_slice(placed.positions());
            for face in placed.faces() {
                indices.extend(face.iter().map(|&i| i + base));
                arities.push(face.len());
            }
            triangles.push(first..first + placed.triangle_count());
            first += placed.triangle_count();
        }
        let merged = PolyMesh::from_flat(positions, indices, &arities)
            .map_err(|e| format!("{name}: {e}"))?;
        // The parts' surfaces together, for the diagnostics and the approximations (at the
        // whole's mass: no enclosed volume needed, so sheets and voids are fine).
        let analysis = massprops::analyze(&merged, Method::Points, MassSpec::Mass(whole.mass))
            .map_err(|e| format!("{name}: {e}"))?;
        let mut body = Self::assemble(name, &merged, analysis);
        body.composition = Some(Composition {
            masses: masses.iter().map(|m| m.mass).collect(),
            parts,
            whole,
            shares,
            triangles,
        });
        Ok(body)
    }

    /// A sample body made of parts, by label.
    ///
    /// # Errors
    /// Unknown label, or (never for the shipped assets) a parse failure.
    fn sample_body(label: &str) -> Result<Self, String> {
        let (_, file, text) = SAMPLE_BODIES
            .iter()
            .find(|(l, ..)| *l == label)
            .ok_or_else(|| format!("no sample called '{label}'"))?;
        let body = BodyFile::parse(text, Path::new(file)).map_err(|e| e.to_string())?;
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
        let parts = body.load_with(&embedded).map_err(|e| e.to_string())?;
        let models = body
            .parts
            .into_iter()
            .zip(parts)
            .map(|(entry, part)| PartModel::new(entry, part.mesh))
            .collect::<Result<Vec<_>, _>>()?;
        Self::from_parts(label, models)
    }

    /// [`LoadedBody::new`] for a mesh built in code (no file, no lines).
    pub fn built(name: &str, mesh: PolyMesh) -> Result<Self, String> {
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
    pub fn sample(label: &str) -> Result<Self, String> {
        if SAMPLE_BODIES.iter().any(|(l, ..)| *l == label) {
            return Self::sample_body(label);
        }
        let (_, file, text) = SAMPLES
            .iter()
            .find(|(l, ..)| *l == label)
            .ok_or_else(|| format!("no sample called '{label}'"))?;
        let parsed = massprops::parse_mesh(text.as_bytes(), Path::new(file))
            .map_err(|e| format!("{label}: {e}"))?;
        Self::new(label, PathBuf::from(file), parsed)
    }

    /// The default body: the T-handle.
    pub fn t_handle() -> Result<Self, String> {
        Self::built("T-handle", massprops::shapes::t_handle().build())
    }
}

/// What the worker reports.
#[derive(Debug)]
pub enum LoadEvent {
    /// A stage name and its completed fraction (0 to 1).
    Progress(&'static str, f32),
    /// The result; the worker then exits.
    Done(Box<Result<LoadedBody, String>>),
}

/// A running load.
#[derive(Debug)]
pub struct Loading {
    /// What is being loaded.
    pub path: PathBuf,
    /// Latest progress report.
    pub stage: &'static str,
    /// Fraction of the stage done.
    pub fraction: f32,
    events: Receiver<LoadEvent>,
}

impl Loading {
    /// Starts loading `path` on a worker thread; `wake` is called after each report (the UI
    /// passes a repaint request).
    pub fn start(path: PathBuf, wake: impl Fn() + Send + 'static) -> Self {
        let (tx, rx) = channel();
        let p = path.clone();
        thread::spawn(move || {
            let send = |e: LoadEvent| {
                // The receiver is gone only if the app closed or started another load.
                let _ = tx.send(e);
                wake();
            };
            let result = load(&p, &|stage, f| send(LoadEvent::Progress(stage, f)));
            send(LoadEvent::Done(Box::new(result)));
        });
        Self {
            path,
            stage: "starting",
            fraction: 0.0,
            events: rx,
        }
    }

    /// Drains the reports; returns the result once the worker is done.
    pub fn poll(&mut self) -> Option<Result<LoadedBody, String>> {
        loop {
            match self.events.try_recv() {
                Ok(LoadEvent::Progress(stage, f)) => {
                    self.stage = stage;
                    self.fraction = f;
                }
                Ok(LoadEvent::Done(result)) => return Some(*result),
                Err(TryRecvError::Empty) => return None,
                Err(TryRecvError::Disconnected) => {
                    return Some(Err(format!(
                        "{}: the loader stopped unexpectedly",
                        self.path.display()
                    )));
                }
            }
        }
    }
}

/// Reads, parses and analyses a mesh file, reporting progress.
fn load(path: &Path, progress: &dyn Fn(&'static str, f32)) -> Result<LoadedBody, String> {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let ctx = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let mut file = std::fs::File::open(path).map_err(|e| ctx(&e))?;
    let total = file.metadata().map(|m| m.len()).unwrap_or(0).max(1);
    let mut bytes = Vec::with_capacity(usize::try_from(total).unwrap_or(0));
    let mut chunk = vec![0u8; 1 << 20];
    loop {
        let n = file.read(&mut chunk).map_err(|e| ctx(&e))?;
        if n == 0 {
            break;
        }
        bytes.extend_from_slice(&chunk[..n]);
        progress("reading", bytes.len() as f32 / total as f32);
    }
    if massprops::is_body_file(path) {
        progress("parts", 0.0);
        let parts = from_body_file(path)?;
        return LoadedBody::from_parts(&name, parts);
    }
    progress("parsing", 0.0);
    let file = massprops::parse_mesh(&bytes, path).map_err(|e| e.to_string())?;
    drop(bytes);
    progress("mass properties and picking index", 0.0);
    LoadedBody::new(&name, path.to_path_buf(), file).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wait(mut l: Loading) -> Result<LoadedBody, String> {
        for _ in 0..2000 {
            if let Some(r) = l.poll() {
                return r;
            }
            thread::sleep(std::time::Duration::from_millis(5));
        }
        Err("timed out".to_owned())
    }

    #[test]
    fn every_sample_loads() {
        for (label, ..) in SAMPLES {
            let b = LoadedBody::sample(label).expect(label);
            assert!(b.analysis.properties.mass > 0.0, "{label}");
            assert!(!b.mesh.triangles.is_empty());
        }
        assert!(LoadedBody::sample("nope").is_err());
    }

    #[test]
    fn loads_a_file_and_reports_errors_with_the_path() {
        let dir = std::env::temp_dir().join(format!("inertia-lab-loader-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let good = dir.join("cube.obj");
        std::fs::write(&good, SAMPLES[5].2).expect("write");
        let body = wait(Loading::start(good, || {})).expect("loads");
        assert_eq!(body.name, "cube.obj");
        assert!((body.analysis.properties.mass - 1.0).abs() < 1e-12);

        let bad = dir.join("broken.obj");
        std::fs::write(&bad, "v 0 0 0\nf 1 2 3\n").expect("write");
        let err = wait(Loading::start(bad.clone(), || {})).expect_err("bad file");
        assert!(err.contains("broken.obj"), "{err}");
        let missing = dir.join("missing.stl");
        let err = wait(Loading::start(missing, || {})).expect_err("no file");
        assert!(err.contains("missing.stl"), "{err}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
