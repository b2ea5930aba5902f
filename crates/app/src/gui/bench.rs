//! `--bench-frames N`: the app's frame time measured on its real window (percentiles of N
//! frames after a warm-up, the UI's own work, eframe's whole-frame work), then picking timed
//! through a grid of pixels, and the resident memory then; each printed as one line before the
//! window closes.

use std::time::Duration;

use crate::platform::Instant;

use crate::lab::Lab;

use super::view3d::View3d;

/// Frames skipped before measuring (window mapping, first uploads, shader compilation).
const WARMUP: usize = 10;

/// Frame-time measurement of `--bench-frames`.
#[derive(Debug)]
pub(super) struct Bench {
    frames: usize,
    hide_plots: bool,
    last: Option<Instant>,
    times: Vec<f64>,
    /// Milliseconds spent building the UI (CPU, excluding tessellation and painting) per frame.
    ui_times: Vec<f64>,
    /// eframe's measure of the previous frame's work (UI, tessellation, painting; not waiting).
    cpu_times: Vec<f64>,
    /// Frames still to skip before measuring.
    warmup: usize,
}

impl Bench {
    /// A measurement of `frames` frames, with the plot panel collapsed when `hide_plots`.
    pub(super) fn new(frames: usize, hide_plots: bool) -> Self {
        Self {
            frames: frames.max(1),
            hide_plots,
            last: None,
            times: Vec::with_capacity(frames),
            ui_times: Vec::with_capacity(frames),
            cpu_times: Vec::with_capacity(frames),
            warmup: WARMUP,
        }
    }

    /// Whether the plot panel is collapsed (to measure what the plots cost).
    pub(super) fn hides_plots(&self) -> bool {
        self.hide_plots
    }

    /// Records one frame's work: building the UI took `ui`; eframe measured `cpu` seconds for
    /// the previous frame.
    pub(super) fn record_work(&mut self, ui: Duration, cpu: Option<f32>) {
        if self.warmup == 0 {
            self.ui_times.push(ui.as_secs_f64() * 1e3);
            if let Some(cpu) = cpu {
                self.cpu_times.push(f64::from(cpu) * 1e3);
            }
        }
    }

    /// Counts a frame; after the last one prints the tables and returns `true` (close the
    /// window).
    pub(super) fn frame(&mut self, lab: &Lab, view: &mut View3d) -> bool {
        if self.times.len() >= self.frames {
            // Already reported; the window is closing.
            return false;
        }
        let now = Instant::now();
        if let Some(last) = self.last {
            if self.warmup > 0 {
                self.warmup -= 1;
            } else {
                self.times.push((now - last).as_secs_f64() * 1e3);
            }
        }
        self.last = Some(now);
        if self.times.len() < self.frames {
            return false;
        }
        let mut t = self.times.clone();
        t.sort_by(f64::total_cmp);
        let pct = |p: f64| t[((p / 100.0) * (t.len() - 1) as f64).round() as usize];
        let mean = t.iter().sum::<f64>() / t.len() as f64;
        let mean_of = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
        let (ui_mean, cpu_mean) = (mean_of(&self.ui_times), mean_of(&self.cpu_times));
        crate::platform::print(&format!(
            "frames {} ({} triangles, {} samples of history, plots {}): mean {:.1} ms \
             ({:.1} fps), p50 {:.1} ms, p90 {:.1} ms, p99 {:.1} ms, max {:.1} ms; \
             building the UI {:.2} ms, whole frame's work {:.2} ms",
            t.len(),
            lab.primary().body().mesh.triangles.len(),
            lab.primary().history().samples().len(),
            if self.hide_plots { "hidden" } else { "shown" },
            mean,
            1e3 / mean,
            pct(50.0),
            pct(90.0),
            pct(99.0),
            pct(100.0),
            ui_mean,
            cpu_mean
        ));
        picking(lab, view);
        if let Some(m) = crate::platform::memory() {
            crate::platform::print(&format!(
                "resident memory {:.1} MB (peak {:.1} MB)",
                m.resident_kib as f64 / 1024.0,
                m.peak_kib as f64 / 1024.0
            ));
        }
        true
    }
}

/// Times picking the body through a grid of pixels over the framed view (800 × 600).
fn picking(lab: &Lab, view: &mut View3d) {
    view.frame_body(lab);
    let size = nalgebra::Vector2::new(800.0, 600.0);
    let rays: Vec<_> = (0..400)
        .map(|k| {
            let pixel = nalgebra::Point2::new(
                250.0 + f64::from(k % 20) * 15.0,
                150.0 + f64::from(k / 20) * 15.0,
            );
            view.camera.ray(pixel, size)
        })
        .collect();
    let start = Instant::now();
    let primary = lab.primary();
    let hits = rays.iter().filter(|r| primary.pick(r).is_some()).count();
    let per_ray = start.elapsed().as_secs_f64() / rays.len() as f64;
    crate::platform::print(&format!(
        "picking ({} triangles): {:.1} µs per ray ({} of {} rays hit)",
        primary.body().mesh.triangles.len(),
        per_ray * 1e6,
        hits,
        rays.len()
    ));
}
