//! GPU side of the 3D view: a three-d context wrapping eframe's own GL context, the body's mesh
//! and the lights. Everything here lives on the GL thread inside the paint callback (or a
//! headless EGL context in tests); the rest of the app never touches GPU resources.

use std::cell::RefCell;
use std::sync::Arc;

use three_d::{
    AmbientLight, Camera, ClearState, Context, CpuMaterial, CpuMesh, DirectionalLight, Gm, Mesh,
    PhysicalMaterial, RenderTarget, ScissorBox, Srgba, Vec3, Viewport, degrees,
};

use super::convert::FrameParams;
use crate::i18n::tr;

/// Background of the 3D view.
pub const BACKGROUND: [f32; 3] = [0.09, 0.10, 0.12];

thread_local! {
    /// The scene of the GL context this thread paints with (see [`SceneSlot`]).
    static SCENE: RefCell<Option<Scene>> = const { RefCell::new(None) };
}

/// The scene of this thread's GL context: eframe builds the UI and runs its paint callbacks on
/// one thread, and a browser's GL handles may not cross threads (a WebGL context is not
/// `Send`), so the scene lives in a thread-local slot rather than behind a lock. The handle is
/// what a paint callback captures.
#[derive(Debug, Clone, Copy)]
pub struct SceneSlot(());

impl SceneSlot {
    /// Makes `scene` this thread's (replacing any before it).
    pub fn install(scene: Scene) -> Self {
        SCENE.set(Some(scene));
        Self(())
    }

    /// Runs `f` on this thread's scene; `None` on a thread that has none.
    pub fn with<R>(self, f: impl FnOnce(&mut Scene) -> R) -> Option<R> {
        SCENE.with_borrow_mut(|scene| scene.as_mut().map(f))
    }
}

/// The body's GPU mesh and the lights.
pub struct Scene {
    context: Context,
    body: Option<(u64, Gm<Mesh, PhysicalMaterial>)>,
    ambient: AmbientLight,
    key: DirectionalLight,
    fill: DirectionalLight,
}

impl std::fmt::Debug for Scene {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Scene")
            .field("generation", &self.body.as_ref().map(|(g, _)| *g))
            .finish_non_exhaustive()
    }
}

impl Scene {
    /// Wraps an existing GL context (eframe's, or a headless one).
    ///
    /// # Errors
    /// three-d cannot use the context (too old a GL version).
    pub fn new(gl: Arc<three_d::context::Context>) -> Result<Self, String> {
        let context = Context::from_gl_context(gl)
            .map_err(|e| tr!("view3d-gl-context", error = e.to_string()))?;
        let white = Srgba::WHITE;
        Ok(Self {
            ambient: AmbientLight::new(&context, 0.35, white),
            key: DirectionalLight::new(&context, 2.2, white, Vec3::new(-0.5, -0.8, -0.6)),
            fill: DirectionalLight::new(&context, 0.8, white, Vec3::new(0.7, 0.3, 0.5)),
            body: None,
            context,
        })
    }

    /// The generation of the uploaded mesh, if any.
    pub fn generation(&self) -> Option<u64> {
        self.body.as_ref().map(|(g, _)| *g)
    }

    /// Uploads a body mesh (replacing the previous one).
    pub fn set_mesh(&mut self, generation: u64, mesh: &CpuMesh) {
        let material = PhysicalMaterial::new_opaque(
            &self.context,
            &CpuMaterial {
                albedo: Srgba::WHITE,
                roughness: 0.55,
                metallic: 0.1,
                ..Default::default()
            },
        );
        self.body = Some((
            generation,
            Gm::new(Mesh::new(&self.context, mesh), material),
        ));
    }

    /// Clears `scissor` and draws the body into `target` at `viewport` (pixels, origin
    /// bottom-left).
    pub fn render(
        &mut self,
        target: &RenderTarget<'_>,
        viewport: Viewport,
        scissor: ScissorBox,
        p: &FrameParams,
    ) {
        let camera = Camera::new_perspective(
            viewport,
            p.eye,
            p.target,
            p.up,
            degrees(p.fov_y_degrees),
            p.near,
            p.far,
        );
        let [r, g, b] = BACKGROUND;
        target.clear_partially(scissor, ClearState::color_and_depth(r, g, b, 1.0, 1.0));
        if let Some((_, body)) = &mut self.body {
            body.set_transformation(p.model);
            let [cr, cg, cb] = p.color;
            body.material.albedo = Srgba::new_opaque(cr, cg, cb);
            target.render_partially(
                scissor,
                &camera,
                std::iter::once(&*body),
                &[&self.ambient, &self.key, &self.fill],
            );
            // Translucent copies after the opaque body, on the same GPU mesh.
            for (model, [r, g, b, a]) in &p.ghosts {
                body.geometry.set_transformation(*model);
                let ghost = PhysicalMaterial::new_transparent(
                    &self.context,
                    &CpuMaterial {
                        albedo: Srgba::new(*r, *g, *b, *a),
                        roughness: 0.7,
                        metallic: 0.0,
                        ..Default::default()
                    },
                );
                target.render_partially_with_material(
                    scissor,
                    &ghost,
                    &camera,
                    std::iter::once(&body.geometry),
                    &[&self.ambient, &self.key, &self.fill],
                );
            }
        }
    }

    /// Draws into the default framebuffer inside an egui paint callback.
    pub fn paint(&mut self, info: &egui::PaintCallbackInfo, p: &FrameParams) {
        let vp = info.viewport_in_pixels();
        let clip = info.clip_rect_in_pixels();
        let viewport = Viewport {
            x: vp.left_px,
            y: vp.from_bottom_px,
            width: vp.width_px.max(1) as u32,
            height: vp.height_px.max(1) as u32,
        };
        // The clip rect is the whole Ui's: intersect it with the viewport or the clear would
        // erase neighbouring widgets (stack notes).
        let x0 = vp.left_px.max(clip.left_px);
        let y0 = vp.from_bottom_px.max(clip.from_bottom_px);
        let x1 = (vp.left_px + vp.width_px).min(clip.left_px + clip.width_px);
        let y1 = (vp.from_bottom_px + vp.height_px).min(clip.from_bottom_px + clip.height_px);
        if x1 <= x0 || y1 <= y0 {
            return;
        }
        let scissor = ScissorBox {
            x: x0,
            y: y0,
            width: (x1 - x0) as u32,
            height: (y1 - y0) as u32,
        };
        let [w, h] = info.screen_size_px;
        let target = RenderTarget::screen(&self.context, w, h);
        self.render(&target, viewport, scissor, p);
    }
}
