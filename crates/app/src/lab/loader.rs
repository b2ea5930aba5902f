//! The one load path: every file the lab opens or adds as a part is read (with progress),
//! parsed, integrated and indexed for picking away from the UI, and reports through a channel,
//! so a large mesh never freezes the UI, whether it opens a body or joins one. A file by its
//! path loads on a thread; files given by their bytes (the browser's) load as the [`LoadFiles`]
//! job: on a thread on the desktop, in the page's worker in a browser. What a file holds is
//! decided once, by [`FileKind`]; what the files are for is the load's [`Purpose`].

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, TryRecvError, channel};

use super::body::LoadedBody;
use super::error::LabError;
use super::parts::{self, PartModel, from_resolved};
use super::robot::{self, RobotModel};
use crate::platform::{self, Job, JobEvent};
use inertia_io::input::{self, FileSet, Request, Resolved, Source};
use inertia_io::kind::FileKind;

/// Where a load is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Stage {
    /// Not begun (the page's worker may still be starting).
    Starting,
    /// Reading the file (its fraction is measured).
    Reading,
    /// Parsing, checking the mesh and integrating it.
    Checking,
    /// Building the picking index and what the view draws.
    PickingIndex,
    /// Reading and auditing a robot description.
    Robot,
}

impl std::fmt::Display for Stage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Stage::Starting => "starting",
            Stage::Reading => "reading",
            Stage::Checking => "checking the mesh and its mass properties",
            Stage::PickingIndex => "picking index",
            Stage::Robot => "reading and auditing the robot",
        })
    }
}

/// What the worker reports.
#[derive(Debug)]
pub enum LoadEvent {
    /// A stage and its completed fraction (0 to 1), when the stage can measure one.
    Progress(Stage, Option<f32>),
    /// The result; the worker then exits.
    Done(Box<Result<Loaded, LabError>>),
}

/// What a load makes of its files.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub enum Purpose {
    /// A new body (or robot) in place of the current one.
    Open,
    /// Each mesh a new part of the body named `body` made of `parts` (the current body's).
    AddParts {
        /// The body's name.
        body: String,
        /// Its parts now.
        parts: Vec<PartModel>,
    },
}

/// Files given by their bytes and what they are for: the [`LoadFiles`] job's input.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct FilesToLoad {
    /// The files.
    pub files: FileSet,
    /// What they are for.
    pub purpose: Purpose,
}

/// Loading files given by their bytes: to open, the body file among them with its meshes, else
/// the first mesh; to add, every mesh as a part. A robot description is refused: its meshes are
/// named by paths a set of files cannot resolve. Its error crosses as its words (the page shows
/// nothing else of it).
#[derive(Debug)]
pub struct LoadFiles;

impl Job for LoadFiles {
    const NAME: &'static str = "load files";
    type Input = FilesToLoad;
    type Progress = (Stage, Option<f32>);
    type Output = Result<LoadedBody, String>;

    fn run(job: FilesToLoad, progress: &dyn Fn((Stage, Option<f32>))) -> Self::Output {
        let FilesToLoad { files, purpose } = job;
        let path = files.main().map(Path::to_path_buf).unwrap_or_default();
        if FileKind::is_robot(&path) {
            return Err(LabError::RobotFromFiles(path).to_string());
        }
        progress((Stage::Checking, None));
        let send = |e: LoadEvent| {
            if let LoadEvent::Progress(stage, f) = e {
                progress((stage, f));
            }
        };
        match purpose {
            Purpose::Open => load(&path, Source::Set(&files, &path), &send),
            Purpose::AddParts { body, parts } => {
                join(&body, parts, parts::from_files(&files), &send)
            }
        }
        .map_err(|e| e.to_string())
    }
}

/// What a file loads as.
#[derive(Debug)]
pub enum Loaded {
    /// A mesh or a body file: the body.
    Body(LoadedBody),
    /// A robot description: the audited robot and the body it shows first (the whole robot).
    Robot(Box<RobotModel>, LoadedBody),
    /// New parts: the body they joined, and the files they came from (for the message).
    Joined(LoadedBody, String),
}

/// Where a load's files come from.
#[derive(Debug, Clone, PartialEq)]
pub enum LoadSource {
    /// A file on disk (and the files it names).
    Path(PathBuf),
    /// Files given by their bytes (the browser's).
    Files(FileSet),
}

impl LoadSource {
    /// The names of the files given (a path's own name for a file on disk).
    pub fn names(&self) -> Vec<&Path> {
        match self {
            LoadSource::Path(path) => vec![path.as_path()],
            LoadSource::Files(files) => files.names().collect(),
        }
    }
}

/// A running load.
#[derive(Debug)]
pub struct Loading {
    /// What is being loaded.
    pub path: PathBuf,
    /// Latest progress report.
    pub stage: Stage,
    /// Fraction of the stage done.
    pub fraction: Option<f32>,
    /// For new parts, the body they join: the lab installs the result only while that body is
    /// still the one shown (an edit meanwhile would otherwise be undone).
    pub joins: Option<Arc<LoadedBody>>,
    events: Receiver<LoadEvent>,
}

impl Loading {
    /// Starts loading `source` for `purpose` off the UI thread; `wake` is called after each
    /// report (the UI passes a repaint request).
    pub fn begin(source: LoadSource, purpose: Purpose, wake: impl Fn() + Send + 'static) -> Self {
        match source {
            LoadSource::Path(path) => Self::start(path, purpose, wake),
            LoadSource::Files(files) => Self::start_files(FilesToLoad { files, purpose }, wake),
        }
    }

    /// Starts loading `path` for `purpose` on a worker thread; `wake` is called after each
    /// report (the UI passes a repaint request).
    pub fn start(path: PathBuf, purpose: Purpose, wake: impl Fn() + Send + 'static) -> Self {
        let p = path.clone();
        Self::spawn(path, wake, move |send| match purpose {
            Purpose::Open if FileKind::is_robot(&p) => {
                send(LoadEvent::Progress(Stage::Robot, None));
                robot::load(&p).map(|(model, body)| Loaded::Robot(Box::new(model), body))
            }
            Purpose::Open => {
                let report = |f: f32| reading(send, f);
                load(&p, Source::Reported(&p, &report), send).map(Loaded::Body)
            }
            Purpose::AddParts { body, parts } => {
                send(LoadEvent::Progress(Stage::Checking, None));
                let new = parts::from_mesh_file(&p).map(|part| vec![part]);
                join(&body, parts, new, send).map(|b| Loaded::Joined(b, p.display().to_string()))
            }
        })
    }

    /// Starts loading files given by their bytes (the browser's) as the [`LoadFiles`] job.
    pub fn start_files(job: FilesToLoad, wake: impl Fn() + Send + 'static) -> Self {
        let path = job.files.main().map(Path::to_path_buf).unwrap_or_default();
        let names: Vec<String> = job.files.names().map(|p| p.display().to_string()).collect();
        let adding = matches!(job.purpose, Purpose::AddParts { .. });
        let (tx, rx): (Sender<LoadEvent>, _) = channel();
        platform::start_job::<LoadFiles>(job, move |event| {
            let event = match event {
                JobEvent::Progress((stage, f)) => LoadEvent::Progress(stage, f),
                JobEvent::Done(result) => LoadEvent::Done(Box::new(
                    result
                        .map(|body| {
                            if adding {
                                Loaded::Joined(body, names.join(", "))
                            } else {
                                Loaded::Body(body)
                            }
                        })
                        .map_err(LabError::Relayed),
                )),
                JobEvent::Lost(words) => LoadEvent::Done(Box::new(Err(LabError::Relayed(words)))),
            };
            // The receiver is gone only if the app closed or started another load.
            let _ = tx.send(event);
            wake();
        });
        Self {
            path,
            stage: Stage::Starting,
            fraction: None,
            joins: None,
            events: rx,
        }
    }

    /// Runs `job` off the UI thread (the platform's way), reporting through the channel.
    fn spawn(
        path: PathBuf,
        wake: impl Fn() + Send + 'static,
        job: impl FnOnce(&dyn Fn(LoadEvent)) -> Result<Loaded, LabError> + Send + 'static,
    ) -> Self {
        let (tx, rx): (Sender<LoadEvent>, _) = channel();
        platform::spawn(move || {
            let send = |e: LoadEvent| {
                // The receiver is gone only if the app closed or started another load.
                let _ = tx.send(e);
                wake();
            };
            let result = job(&send);
            send(LoadEvent::Done(Box::new(result)));
        });
        Self {
            path,
            stage: Stage::Starting,
            fraction: None,
            joins: None,
            events: rx,
        }
    }

    /// Drains the reports; returns the result once the worker is done.
    pub fn poll(&mut self) -> Option<Result<Loaded, LabError>> {
        loop {
            match self.events.try_recv() {
                Ok(LoadEvent::Progress(stage, f)) => {
                    self.stage = stage;
                    self.fraction = f;
                }
                Ok(LoadEvent::Done(result)) => return Some(*result),
                Err(TryRecvError::Empty) => return None,
                Err(TryRecvError::Disconnected) => {
                    return Some(Err(LabError::LoaderStopped(self.path.clone())));
                }
            }
        }
    }
}

/// The reading stage's report: its fraction, then the analysis that follows it.
fn reading(send: &dyn Fn(LoadEvent), f: f32) {
    send(if f < 1.0 {
        LoadEvent::Progress(Stage::Reading, Some(f))
    } else {
        LoadEvent::Progress(Stage::Checking, None)
    });
}

/// The body named `body` made of `parts` and the `new` ones (their summing and the picking
/// index of the whole are the slow part for a large mesh, so they run here too).
fn join(
    body: &str,
    mut parts: Vec<PartModel>,
    new: Result<Vec<PartModel>, LabError>,
    send: &dyn Fn(LoadEvent),
) -> Result<LoadedBody, LabError> {
    parts.extend(new?);
    send(LoadEvent::Progress(Stage::PickingIndex, None));
    LoadedBody::from_parts(body, parts)
}

/// Parses and analyses the mesh or body file `path` from `source`, reporting progress.
fn load(path: &Path, source: Source<'_>, send: &dyn Fn(LoadEvent)) -> Result<LoadedBody, LabError> {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    // The one input path every command takes, at density 1 with the default repairs (the lab
    // rescales mass and size live); a file on disk is read in blocks, never whole.
    let resolved = input::resolve(source, &Request::default())?;
    send(LoadEvent::Progress(Stage::PickingIndex, None));
    match resolved {
        Resolved::Mesh { file, analysis } => Ok(LoadedBody::analysed(
            &name,
            path.to_path_buf(),
            file,
            *analysis,
        )),
        Resolved::Parts(parts) => LoadedBody::from_parts(&name, from_resolved(parts)?),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wait(mut l: Loading) -> Result<LoadedBody, LabError> {
        for _ in 0..2000 {
            if let Some(r) = l.poll() {
                return r.map(|loaded| match loaded {
                    Loaded::Body(b) | Loaded::Robot(_, b) | Loaded::Joined(b, _) => b,
                });
            }
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        Err(LabError::LoaderStopped("timed out".into()))
    }

    /// A file of several blocks reports its reading as a rising fraction that ends at the
    /// whole, then the stages that measure none; the body is the file's.
    #[test]
    fn reading_reports_a_rising_fraction_then_the_unmeasured_stages() {
        let dir = std::env::temp_dir().join(format!("inertia-lab-progress-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let path = dir.join("torus.obj");
        let torus = massprops::shapes::torus(1.0, 0.3, 400, 200).triangulated();
        std::fs::write(&path, massprops::shapes::to_obj("torus", "", &torus)).expect("write");
        let events = std::cell::RefCell::new(Vec::new());
        let send = |e: LoadEvent| {
            if let LoadEvent::Progress(stage, f) = e {
                events.borrow_mut().push((stage, f));
            }
        };
        let report = |f: f32| reading(&send, f);
        let body = load(&path, Source::Reported(&path, &report), &send).expect("loads");
        std::fs::remove_dir_all(&dir).ok();
        let events = events.into_inner();
        let reading: Vec<f32> = events
            .iter()
            .filter(|(stage, _)| *stage == Stage::Reading)
            .filter_map(|(_, f)| *f)
            .collect();
        assert!(reading.len() >= 3, "{events:?}");
        assert!(reading.windows(2).all(|w| w[0] < w[1]), "{reading:?}");
        assert!(reading.iter().all(|f| (0.0..1.0).contains(f)));
        let after: Vec<_> = events
            .iter()
            .skip_while(|(s, _)| *s == Stage::Reading)
            .collect();
        assert_eq!(
            after,
            [&(Stage::Checking, None), &(Stage::PickingIndex, None)]
        );
        // 2π²Rr² to the polygon's accuracy.
        let exact = 2.0 * std::f64::consts::PI.powi(2) * 0.3 * 0.3;
        assert!((body.analysis.properties.mass / exact - 1.0).abs() < 1e-3);
    }

    /// Files loaded as the page's worker loads them (the job's input, reports and output
    /// crossing as bytes) give the body that a load on a thread gives: the same mass
    /// properties, mesh, picking index and warnings; a file that gives no body gives its words.
    #[test]
    fn files_loaded_through_the_wire_are_the_body_loaded_here() {
        let served = |files: &FileSet| {
            let posted = std::cell::RefCell::new(Vec::new());
            let job = FilesToLoad {
                files: files.clone(),
                purpose: Purpose::Open,
            };
            let input = platform::encode(&job).expect("encodes");
            platform::serve::<LoadFiles>(&input, &|done, bytes| {
                posted
                    .borrow_mut()
                    .push(platform::event_of::<LoadFiles>(done, &bytes));
            })
            .expect("served");
            posted.into_inner()
        };
        let mut files = FileSet::default();
        let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
        for name in ["hammer.toml", "hammer.obj"] {
            files.add(name, std::fs::read(assets.join(name)).expect("asset"));
        }
        let events = served(&files);
        let stages: Vec<Stage> = events
            .iter()
            .filter_map(|e| match e {
                JobEvent::Progress((stage, _)) => Some(*stage),
                _ => None,
            })
            .collect();
        assert_eq!(stages, [Stage::Checking, Stage::PickingIndex]);
        let Some(JobEvent::Done(Ok(body))) = events.last() else {
            panic!("{:?}", events.last());
        };
        let job = FilesToLoad {
            files: files.clone(),
            purpose: Purpose::Open,
        };
        let here = LoadFiles::run(job, &|_| {}).expect("loads here");
        assert_eq!(body.analysis, here.analysis);
        assert_eq!(*body.mesh, *here.mesh);
        let (whole, whole_here) = (
            &body.composition.as_ref().expect("parts").whole,
            &here.composition.as_ref().expect("parts").whole,
        );
        assert_eq!(whole, whole_here);
        assert!(whole.mass > 0.0);
        let ray = |b: &LoadedBody| {
            let centre = b.sphere.0;
            let from = centre + nalgebra::Vector3::new(0.0, 0.0, 10.0 * b.sphere.1);
            let dir = -nalgebra::Vector3::z();
            let hit = b
                .bvh
                .pick(&b.mesh, &crate::lab::picking::Ray { origin: from, dir });
            hit.map(|h| (h.triangle, h.t))
        };
        assert_eq!(ray(body), ray(&here));

        let mut broken = FileSet::default();
        broken.add("broken.obj", &b"v 0 0 0\nf 1 2 3\n"[..]);
        match served(&broken).last() {
            Some(JobEvent::Done(Err(words))) => assert!(words.contains("broken.obj"), "{words}"),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn loads_a_file_and_reports_errors_with_the_path() {
        let dir = std::env::temp_dir().join(format!("inertia-lab-loader-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let good = dir.join("cube.obj");
        std::fs::write(&good, crate::lab::samples::SAMPLES[5].2).expect("write");
        let body = wait(Loading::start(good, Purpose::Open, || {})).expect("loads");
        assert_eq!(body.name, "cube.obj");
        assert!((body.analysis.properties.mass - 1.0).abs() < 1e-12);

        let bad = dir.join("broken.obj");
        std::fs::write(&bad, "v 0 0 0\nf 1 2 3\n").expect("write");
        let err = wait(Loading::start(bad.clone(), Purpose::Open, || {}))
            .expect_err("bad file")
            .to_string();
        assert!(err.contains("broken.obj"), "{err}");
        let missing = dir.join("missing.stl");
        let err = wait(Loading::start(missing, Purpose::Open, || {}))
            .expect_err("no file")
            .to_string();
        assert!(err.contains("missing.stl"), "{err}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
