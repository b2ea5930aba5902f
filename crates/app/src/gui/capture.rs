//! `--screenshot OUT.png --after SECONDS`: the app's own pixels (3D view, panels and plots) after
//! a given simulated time, written as PNG, then the window closes. Teachers put these in slides;
//! the docs' screenshots are made with it.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// Frames drawn before the picture: the window maps, the mesh is uploaded, shaders compile.
const WARM_UP_FRAMES: usize = 10;

/// What became of the picture, read once the window has closed.
pub type Outcome = Arc<Mutex<Option<Result<(), String>>>>;

/// A screenshot to take once the window has warmed up.
#[derive(Debug)]
pub struct Capture {
    path: PathBuf,
    frames_left: usize,
    requested: bool,
    outcome: Outcome,
}

impl Capture {
    /// A capture to `path`, reporting through `outcome`.
    pub fn new(path: PathBuf, outcome: Outcome) -> Self {
        Self {
            path,
            frames_left: WARM_UP_FRAMES,
            requested: false,
            outcome,
        }
    }

    /// Called every frame: after the warm-up asks egui for the next frame's pixels; once they
    /// arrive, writes them (off the UI thread) and closes the window.
    pub fn frame(&mut self, ctx: &egui::Context) {
        if self.requested {
            return;
        }
        ctx.request_repaint();
        if self.frames_left > 0 {
            self.frames_left -= 1;
            return;
        }
        self.requested = true;
        let (path, outcome, ctx2) = (self.path.clone(), Arc::clone(&self.outcome), ctx.clone());
        ctx.request_screenshot(move |image| {
            std::thread::spawn(move || {
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

/// Writes `image` (opaque RGBA, rows top to bottom) as an 8-bit RGBA PNG.
///
/// # Errors
/// The file cannot be created or written; the message names it.
pub fn write_png(path: &Path, image: &egui::ColorImage) -> Result<(), String> {
    let fail = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", path.display());
    let [w, h] = image.size;
    let (w, h) = (
        u32::try_from(w).map_err(|e| fail(&e))?,
        u32::try_from(h).map_err(|e| fail(&e))?,
    );
    let file = std::fs::File::create(path).map_err(|e| fail(&e))?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), w, h);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| fail(&e))?;
    writer
        .write_image_data(image.as_raw())
        .map_err(|e| fail(&e))?;
    writer.finish().map_err(|e| fail(&e))
}

#[cfg(test)]
mod tests {
    use super::*;

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
