//! The reference for the app's frame time: a mesh drawn alone by three-d in a window of the
//! app's size (1280 × 800), the whole window one paint callback with the app's own scene
//! (material, lights, GPU mesh as the app builds it), framed as the app frames it, and nothing
//! else: no panels, plots or overlays. Prints the same frame-time line as `--bench-frames`.
//!
//! `cargo run --release -p inertia-lab --example draw_alone -- dragon.obj 60`

use std::sync::{Arc, Mutex};
use std::time::Instant;

use inertia_lab::gui::view3d::camera::OrbitCamera;
use inertia_lab::gui::view3d::convert::{FrameParams, cpu_mesh};
use inertia_lab::gui::view3d::scene::Scene;
use inertia_lab::lab::geometry::TriMesh;
use nalgebra::Matrix4;

/// Frames skipped before measuring, as the app's benchmark skips them.
const WARMUP: usize = 10;

struct Alone {
    scene: Arc<Mutex<Scene>>,
    params: FrameParams,
    frames: usize,
    last: Option<Instant>,
    times: Vec<f64>,
    work: Vec<f64>,
}

impl eframe::App for Alone {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let now = Instant::now();
        if let Some(last) = self.last {
            self.times.push((now - last).as_secs_f64() * 1e3);
        }
        self.last = Some(now);
        if let Some(cpu) = frame.info().cpu_usage {
            self.work.push(f64::from(cpu) * 1e3);
        }
        if self.times.len() >= WARMUP + self.frames {
            let mut t = self.times[WARMUP..].to_vec();
            t.sort_by(f64::total_cmp);
            let work = &self.work[WARMUP.min(self.work.len())..];
            println!(
                "alone: frames {}, mean {:.1} ms, p50 {:.1} ms, whole frame's work {:.2} ms",
                t.len(),
                t.iter().sum::<f64>() / t.len() as f64,
                t[t.len() / 2],
                work.iter().sum::<f64>() / work.len().max(1) as f64
            );
            ui.ctx().send_viewport_cmd(egui::ViewportCommand::Close);
        }
        let rect = ui.max_rect();
        let (scene, params) = (Arc::clone(&self.scene), self.params.clone());
        let callback = egui_glow::CallbackFn::new(move |info, _| {
            if let Ok(mut s) = scene.lock() {
                s.paint(&info, &params);
            }
        });
        ui.painter().add(egui::PaintCallback {
            rect,
            callback: Arc::new(callback),
        });
        ui.ctx().request_repaint();
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let usage = "usage: draw_alone MESH [FRAMES]";
    let path = args.next().ok_or(usage)?;
    let frames: usize = args.next().map_or(Ok(60), |n| n.parse())?;
    let file = massprops::load_mesh(std::path::Path::new(&path))?;
    let mesh = TriMesh::from_poly(&file.mesh);
    let (centre, radius) = mesh.bounding_sphere();
    let mut camera = OrbitCamera::default();
    camera.frame(centre, 1.8 * radius);
    let params = FrameParams::new(&camera, &Matrix4::identity(), &centre);
    let cpu = cpu_mesh(&mesh, &centre, &[]);
    let options = eframe::NativeOptions {
        renderer: eframe::Renderer::Glow,
        depth_buffer: 24,
        multisampling: 0,
        glow_options: egui_glow::GlowConfiguration {
            vsync: false,
            ..Default::default()
        },
        viewport: egui::ViewportBuilder::default()
            .with_title("draw alone")
            .with_inner_size([1280.0, 800.0]),
        ..Default::default()
    };
    eframe::run_native(
        "draw-alone",
        options,
        Box::new(move |cc| {
            let gl = cc.gl.clone().ok_or("no GL context")?;
            let mut scene = Scene::new(gl)?;
            scene.set_mesh(1, &cpu);
            Ok(Box::new(Alone {
                scene: Arc::new(Mutex::new(scene)),
                params,
                frames,
                last: None,
                times: Vec::new(),
                work: Vec::new(),
            }))
        }),
    )?;
    Ok(())
}
