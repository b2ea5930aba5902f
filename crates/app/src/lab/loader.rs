//! Loading a body off the UI thread: read (with progress), parse, mass properties and the picking
//! index run on a worker thread that reports through a channel, so a large mesh never freezes the
//! UI.

use std::path::{Path, PathBuf};
use std::sync::mpsc::{Receiver, Sender, TryRecvError, channel};

use super::body::LoadedBody;
use super::error::LabError;
use super::parts::from_resolved;
use super::robot::{self, RobotModel};
use crate::input::{self, FileSet, Request, Resolved, Source};
use crate::platform;

/// What the worker reports.
#[derive(Debug)]
pub enum LoadEvent {
    /// A stage name and its completed fraction (0 to 1), when the stage can measure one.
    Progress(&'static str, Option<f32>),
    /// The result; the worker then exits.
    Done(Box<Result<Loaded, LabError>>),
}

/// What a file loads as.
#[derive(Debug)]
pub enum Loaded {
    /// A mesh or a body file: the body.
    Body(LoadedBody),
    /// A robot description: the audited robot and the body it shows first (the whole robot).
    Robot(Box<RobotModel>, LoadedBody),
}

/// A running load.
#[derive(Debug)]
pub struct Loading {
    /// What is being loaded.
    pub path: PathBuf,
    /// Latest progress report.
    pub stage: &'static str,
    /// Fraction of the stage done.
    pub fraction: Option<f32>,
    events: Receiver<LoadEvent>,
}

impl Loading {
    /// Starts loading `path` on a worker thread; `wake` is called after each report (the UI
    /// passes a repaint request).
    pub fn start(path: PathBuf, wake: impl Fn() + Send + 'static) -> Self {
        let p = path.clone();
        Self::spawn(path, wake, move |send| {
            if robot::is_description(&p) {
                send(LoadEvent::Progress("reading and auditing the robot", None));
                robot::load(&p).map(|(model, body)| Loaded::Robot(Box::new(model), body))
            } else {
                let report = |f: f32| reading(send, f);
                load(&p, Source::Reported(&p, &report), send).map(Loaded::Body)
            }
        })
    }

    /// Starts loading files given by their bytes (the browser's): the body file among them with
    /// its meshes, else the first mesh. A robot description is refused: its meshes are named
    /// by paths a set of files cannot resolve.
    pub fn start_files(files: FileSet, wake: impl Fn() + Send + 'static) -> Self {
        let path = files.main().map(Path::to_path_buf).unwrap_or_default();
        let p = path.clone();
        Self::spawn(path, wake, move |send| {
            if robot::is_description(&p) {
                return Err(LabError::RobotFromFiles(p));
            }
            send(LoadEvent::Progress(
                "checking the mesh and its mass properties",
                None,
            ));
            load(&p, Source::Set(&files, &p), send).map(Loaded::Body)
        })
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
            stage: "starting",
            fraction: None,
            events: rx,
        }
    }

    /// Drains the reports; returns the result once the worker is done.
    pub fn poll(&mut self) -> Option<Result<Loaded, LabError>> {
        platform::run_spawned();
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
        LoadEvent::Progress("reading", Some(f))
    } else {
        LoadEvent::Progress("checking the mesh and its mass properties", None)
    });
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
    send(LoadEvent::Progress("picking index", None));
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
                    Loaded::Body(b) | Loaded::Robot(_, b) => b,
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
            .filter(|(stage, _)| *stage == "reading")
            .filter_map(|(_, f)| *f)
            .collect();
        assert!(reading.len() >= 3, "{events:?}");
        assert!(reading.windows(2).all(|w| w[0] < w[1]), "{reading:?}");
        assert!(reading.iter().all(|f| (0.0..1.0).contains(f)));
        let after: Vec<_> = events.iter().skip_while(|(s, _)| *s == "reading").collect();
        assert_eq!(
            after,
            [
                &("checking the mesh and its mass properties", None),
                &("picking index", None)
            ]
        );
        // 2π²Rr² to the polygon's accuracy.
        let exact = 2.0 * std::f64::consts::PI.powi(2) * 0.3 * 0.3;
        assert!((body.analysis.properties.mass / exact - 1.0).abs() < 1e-3);
    }

    #[test]
    fn loads_a_file_and_reports_errors_with_the_path() {
        let dir = std::env::temp_dir().join(format!("inertia-lab-loader-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let good = dir.join("cube.obj");
        std::fs::write(&good, crate::lab::samples::SAMPLES[5].2).expect("write");
        let body = wait(Loading::start(good, || {})).expect("loads");
        assert_eq!(body.name, "cube.obj");
        assert!((body.analysis.properties.mass - 1.0).abs() < 1e-12);

        let bad = dir.join("broken.obj");
        std::fs::write(&bad, "v 0 0 0\nf 1 2 3\n").expect("write");
        let err = wait(Loading::start(bad.clone(), || {}))
            .expect_err("bad file")
            .to_string();
        assert!(err.contains("broken.obj"), "{err}");
        let missing = dir.join("missing.stl");
        let err = wait(Loading::start(missing, || {}))
            .expect_err("no file")
            .to_string();
        assert!(err.contains("missing.stl"), "{err}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
