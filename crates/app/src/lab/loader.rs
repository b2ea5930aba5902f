//! Loading a body off the UI thread: read (with progress), parse, mass properties and the picking
//! index run on a worker thread that reports through a channel, so a large mesh never freezes the
//! UI.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::thread;

use massprops::{Analysis, MassSpec, MeshFile, Method, PolyMesh, Repairs};

use super::geometry::TriMesh;
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
}

impl LoadedBody {
    /// Analyses a mesh read from a file (its defects handled as massprops does by default).
    ///
    /// # Errors
    /// The mesh encloses no volume even with its holes capped, or is otherwise unusable; the
    /// message names the cause and `name`.
    pub fn new(name: &str, file: &MeshFile) -> Result<Self, String> {
        let analysis = file
            .analyze(Method::Volume, MassSpec::Density(1.0), &Repairs::default())
            .map_err(|e| format!("{name}: {e}"))?;
        let poly = &file.mesh;
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
        Ok(Self {
            name: name.to_owned(),
            sphere: mesh.bounding_sphere(),
            mesh,
            bvh,
            analysis,
            face_lines: file.face_lines.clone(),
            warning_faces,
        })
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
        Self::new(name, &file)
    }

    /// A built-in sample by label.
    ///
    /// # Errors
    /// Unknown label, or (never for the shipped assets) a parse failure.
    pub fn sample(label: &str) -> Result<Self, String> {
        let (_, file, text) = SAMPLES
            .iter()
            .find(|(l, ..)| *l == label)
            .ok_or_else(|| format!("no sample called '{label}'"))?;
        let file = massprops::parse_mesh(text.as_bytes(), Path::new(file))
            .map_err(|e| format!("{label}: {e}"))?;
        Self::new(label, &file)
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
    progress("parsing", 0.0);
    let file = massprops::parse_mesh(&bytes, path).map_err(|e| e.to_string())?;
    drop(bytes);
    progress("mass properties and picking index", 0.0);
    LoadedBody::new(&name, &file).map_err(|e| format!("{}: {e}", path.display()))
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
