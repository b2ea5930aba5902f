//! The app's own pixels (3D view, panels and plots) as PNG: `--screenshot OUT.png --after
//! SECONDS` takes one after a given simulated time and closes the window; the Record button
//! writes a numbered PNG sequence for some seconds (teachers put these in slides; any video tool
//! turns a sequence into a clip): files in a folder, or one ZIP archive of them (a page's
//! download). Encoding runs off the UI thread (in a page, between frames).

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use super::archive::Archive;
use crate::i18n::{self, tr};
use crate::platform::Instant;

/// Frames drawn before the picture: the window maps, the mesh is uploaded, shaders compile.
const WARM_UP_FRAMES: usize = 10;

/// What became of the picture, read once the window has closed.
pub type Outcome = Arc<Mutex<Option<Result<(), String>>>>;

/// A screenshot to take once the window has warmed up.
#[derive(Debug)]
pub struct Capture {
    path: PathBuf,
    frames_left: usize,
    requested: Option<Instant>,
    outcome: Outcome,
}

/// How long to wait for the pixels before giving up (a window that is never drawn).
const CAPTURE_TIMEOUT: Duration = Duration::from_secs(20);

impl Capture {
    /// A capture to `path`, reporting through `outcome`.
    pub fn new(path: PathBuf, outcome: Outcome) -> Self {
        Self {
            path,
            frames_left: WARM_UP_FRAMES,
            requested: None,
            outcome,
        }
    }

    /// Gives up before the first frame, saying why (a file that did not load must not give a
    /// picture of the default body).
    pub fn fail(&self, why: String) {
        if let Ok(mut slot) = self.outcome.lock() {
            *slot = Some(Err(why));
        }
    }

    /// Called every frame: after the warm-up asks egui for the next frame's pixels; once they
    /// arrive, writes them (off the UI thread) and closes the window.
    pub fn frame(&mut self, ctx: &egui::Context) {
        ctx.request_repaint();
        if let Some(at) = self.requested {
            if at.elapsed() > CAPTURE_TIMEOUT
                && let Ok(mut slot) = self.outcome.lock()
            {
                slot.get_or_insert(Err(tr!("capture-no-pixels")));
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            }
            return;
        }
        if self.frames_left > 0 {
            self.frames_left -= 1;
            return;
        }
        self.requested = Some(Instant::now());
        let (path, outcome, ctx2) = (self.path.clone(), Arc::clone(&self.outcome), ctx.clone());
        // The language is a thread's own: the writing thread words a failure in the app's.
        let language = i18n::language();
        ctx.request_screenshot(move |image| {
            std::thread::spawn(move || {
                i18n::set_language(language);
                let result = write_png(&path, &image);
                if let Ok(mut slot) = outcome.lock() {
                    *slot = Some(result);
                }
                ctx2.send_viewport_cmd(egui::ViewportCommand::Close);
                ctx2.request_repaint();
            });
        });
    }
}

/// Frames per second of a recording: smooth enough for a flip, light enough for software GL
/// (each picture is read back from the GPU and encoded).
pub const RECORD_FPS: f64 = 10.0;

/// Where a recording's pictures go.
#[derive(Debug, Clone)]
enum Pictures {
    /// Each a file in this folder.
    Folder(PathBuf),
    /// Into one archive, written as the file `name` at the end.
    Archive {
        name: PathBuf,
        archive: Arc<Mutex<Archive>>,
    },
}

impl Pictures {
    fn keep(&self, name: &str, image: &egui::ColorImage) -> Result<(), String> {
        match self {
            Pictures::Folder(dir) => write_png(&dir.join(name), image),
            Pictures::Archive { archive, .. } => {
                let png = png_bytes(image)?;
                let mut archive = archive.lock().map_err(|e| e.to_string())?;
                archive.add(name, &png)
            }
        }
    }
}

/// A running recording: a picture every 1/[`RECORD_FPS`] s of wall time until `until`.
#[derive(Debug)]
pub struct Recording {
    pictures: Pictures,
    until: Instant,
    next: Instant,
    requested: usize,
    /// Pictures written, and the first failure.
    written: Arc<AtomicUsize>,
    failure: Arc<Mutex<Option<String>>>,
}

impl Recording {
    /// Starts recording `seconds` of the window into the new folder `dir`.
    ///
    /// # Errors
    /// The folder cannot be created.
    pub fn start(dir: PathBuf, seconds: f64, now: Instant) -> Result<Self, String> {
        std::fs::create_dir_all(&dir).map_err(|e| {
            tr!(
                "capture-cannot-create",
                path = dir.display().to_string(),
                error = e.to_string()
            )
        })?;
        Ok(Self::with_pictures(Pictures::Folder(dir), seconds, now))
    }

    /// Starts recording `seconds` of the window into one ZIP archive, written as the file
    /// `name` when the recording ends (a page: one download).
    pub fn start_archive(name: PathBuf, seconds: f64, now: Instant) -> Self {
        let archive = Arc::default();
        Self::with_pictures(Pictures::Archive { name, archive }, seconds, now)
    }

    fn with_pictures(pictures: Pictures, seconds: f64, now: Instant) -> Self {
        Self {
            pictures,
            until: now + Duration::from_secs_f64(seconds.clamp(0.1, 600.0)),
            next: now,
            requested: 0,
            written: Arc::default(),
            failure: Arc::default(),
        }
    }

    /// Called every frame: asks for a picture when one is due. Returns the outcome line once
    /// the time is up and every picture asked for is written (or one failed).
    pub fn frame(&mut self, ctx: &egui::Context, now: Instant) -> Option<(String, bool)> {
        ctx.request_repaint();
        if let Some(e) = self.failure.lock().ok().and_then(|f| f.clone()) {
            return Some((tr!("capture-recording-stopped", error = e), true));
        }
        if now < self.until {
            if now >= self.next {
                self.next += Duration::from_secs_f64(1.0 / RECORD_FPS);
                self.requested += 1;
                let name = format!("frame-{:04}.png", self.requested);
                let pictures = self.pictures.clone();
                let (written, failure) = (Arc::clone(&self.written), Arc::clone(&self.failure));
                // The language is a thread's own: the writing thread words a failure in the app's.
                let language = i18n::language();
                ctx.request_screenshot(move |image| {
                    crate::platform::spawn(move || {
                        i18n::set_language(language);
                        match pictures.keep(&name, &image) {
                            Ok(()) => {
                                written.fetch_add(1, Ordering::SeqCst);
                            }
                            Err(e) => {
                                if let Ok(mut f) = failure.lock() {
                                    f.get_or_insert(e);
                                }
                            }
                        }
                    });
                });
            }
            return None;
        }
        let written = self.written.load(Ordering::SeqCst);
        // A picture asked for but never delivered (a hidden window) must not hang the recording.
        let late = now > self.until + Duration::from_secs(5);
        if written < self.requested && !late {
            return None;
        }
        let place = match &self.pictures {
            Pictures::Folder(dir) => dir.clone(),
            Pictures::Archive { name, archive } => {
                let archive = archive.lock().map(|mut a| std::mem::take(&mut *a));
                let saved = archive.map_err(|e| e.to_string()).and_then(|a| {
                    crate::platform::write_file(name, &a.finish()).map_err(|e| e.to_string())
                });
                if let Err(e) = saved {
                    return Some((
                        tr!(
                            "capture-recording-not-saved",
                            path = name.display().to_string(),
                            error = e
                        ),
                        true,
                    ));
                }
                name.clone()
            }
        };
        Some((
            tr!(
                "capture-recorded",
                written = written,
                requested = self.requested,
                rate = i18n::localize(RECORD_FPS.to_string()),
                path = place.display().to_string()
            ),
            written < self.requested,
        ))
    }

    /// Ends the recording now (the pictures asked for are still written).
    pub fn stop(&mut self, now: Instant) {
        self.until = self.until.min(now);
    }

    /// Seconds left to record.
    pub fn remaining(&self, now: Instant) -> f64 {
        self.until.saturating_duration_since(now).as_secs_f64()
    }
}

/// Writes `image` (opaque RGBA, rows top to bottom) as an 8-bit RGBA PNG.
///
/// # Errors
/// The file cannot be created or written; the message names it.
pub fn write_png(path: &Path, image: &egui::ColorImage) -> Result<(), String> {
    let fail = |e: &dyn std::fmt::Display| {
        tr!(
            "capture-cannot-write",
            path = path.display().to_string(),
            error = e.to_string()
        )
    };
    std::fs::write(path, png_bytes(image).map_err(|e| fail(&e))?).map_err(|e| fail(&e))
}

/// `image` (opaque RGBA, rows top to bottom) as the bytes of an 8-bit RGBA PNG.
///
/// # Errors
/// The image is larger than a PNG can say (the encoder's words).
pub fn png_bytes(image: &egui::ColorImage) -> Result<Vec<u8>, String> {
    let [w, h] = image.size;
    let (w, h) = (
        u32::try_from(w).map_err(|e| e.to_string())?,
        u32::try_from(h).map_err(|e| e.to_string())?,
    );
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, w, h);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
    writer
        .write_image_data(image.as_raw())
        .map_err(|e| e.to_string())?;
    writer.finish().map_err(|e| e.to_string())?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pictures are asked for at the set rate; ones never delivered (here: no window) end the
    /// recording 5 s late with an error that counts them; Stop ends it early.
    #[test]
    fn recording_paces_its_pictures_and_never_hangs() {
        let ctx = egui::Context::default();
        let dir = std::env::temp_dir().join(format!("inertia-lab-{}-rec", std::process::id()));
        let t0 = Instant::now();
        let mut r = Recording::start(dir.clone(), 1.0, t0).expect("folder");
        for k in 0..30 {
            let now = t0 + Duration::from_millis(k * 33);
            assert!(r.frame(&ctx, now).is_none());
        }
        assert_eq!(r.requested, 10, "10 per second over 1 s");
        assert!(
            r.frame(&ctx, t0 + Duration::from_secs(3)).is_none(),
            "waits for them"
        );
        let (text, error) = r.frame(&ctx, t0 + Duration::from_secs(7)).expect("gave up");
        assert!(error && text.contains("0 of 10"), "{text}");
        let mut early = Recording::start(dir.clone(), 60.0, t0).expect("folder");
        early.frame(&ctx, t0);
        early.stop(t0 + Duration::from_millis(10));
        assert_eq!(early.remaining(t0 + Duration::from_millis(20)), 0.0);
        std::fs::remove_dir_all(&dir).ok();
        assert!(Recording::start(PathBuf::from("/proc/no-such/x"), 1.0, t0).is_err());
    }

    /// A recording into an archive writes it once, when the pictures asked for are kept: one
    /// PNG per picture, in order, named as a folder's would be.
    #[test]
    fn an_archived_recording_is_one_file_of_its_pictures() {
        let ctx = egui::Context::default();
        let path = std::env::temp_dir().join(format!("inertia-lab-{}-rec.zip", std::process::id()));
        let t0 = Instant::now();
        let mut r = Recording::start_archive(path.clone(), 0.25, t0);
        for k in 0..3 {
            assert!(r.frame(&ctx, t0 + Duration::from_millis(k * 100)).is_none());
        }
        assert_eq!(r.requested, 3);
        // What the screenshots would deliver: three pictures of different colours.
        for k in 0..3u8 {
            let image = egui::ColorImage::filled([4, 2], egui::Color32::from_rgb(k, 2 * k, 3));
            r.pictures
                .keep(&format!("frame-{:04}.png", k + 1), &image)
                .expect("kept");
            r.written.fetch_add(1, Ordering::SeqCst);
        }
        assert!(!path.exists(), "written only at the end");
        let (text, error) = r.frame(&ctx, t0 + Duration::from_secs(1)).expect("ended");
        assert!(
            !error && text.contains("3 of 3") && text.contains("rec.zip"),
            "{text}"
        );
        let zip = std::fs::read(&path).expect("the archive");
        std::fs::remove_file(&path).ok();
        let pngs = zip
            .windows(8)
            .filter(|w| *w == b"\x89PNG\r\n\x1a\n")
            .count();
        let names: Vec<usize> = (1..=3)
            .map(|k| {
                let name = format!("frame-{k:04}.png");
                zip.windows(name.len())
                    .position(|w| w == name.as_bytes())
                    .expect(&name)
            })
            .collect();
        assert_eq!(pngs, 3);
        assert!(names.windows(2).all(|w| w[0] < w[1]), "{names:?}");
        // The end record counts them.
        assert_eq!(&zip[zip.len() - 22..zip.len() - 18], b"PK\x05\x06");
        assert_eq!(zip[zip.len() - 12], 3);
    }

    #[test]
    fn png_round_trips_and_a_bad_path_is_named() {
        let mut image = egui::ColorImage::filled([3, 2], egui::Color32::from_rgb(10, 20, 30));
        image.pixels[4] = egui::Color32::from_rgb(200, 100, 50);
        let path =
            std::env::temp_dir().join(format!("inertia-lab-{}-shot.png", std::process::id()));
        write_png(&path, &image).expect("written");
        let decoder = png::Decoder::new(std::io::BufReader::new(
            std::fs::File::open(&path).expect("file"),
        ));
        let mut reader = decoder.read_info().expect("a PNG");
        let mut bytes = vec![0; reader.output_buffer_size().expect("size")];
        let info = reader.next_frame(&mut bytes).expect("pixels");
        assert_eq!((info.width, info.height), (3, 2));
        assert_eq!(&bytes[16..20], &[200, 100, 50, 255]);
        assert_eq!(&bytes[0..4], &[10, 20, 30, 255]);
        std::fs::remove_file(&path).ok();
        let bad = Path::new("/no/such/dir/shot.png");
        assert!(write_png(bad, &image).is_err_and(|e| e.contains("/no/such/dir")));
    }
}
