//! GPU side of the 3D view: a three-d context wrapping eframe's own GL context, the body's mesh
//! and the lights. Everything here lives on the GL thread inside the paint callback (or a
//! headless EGL context in tests); the rest of the app never touches GPU resources.

use std::sync::Arc;

use three_d::{
    AmbientLight, Camera, ClearState, Context, CpuMaterial, CpuMesh, DirectionalLight, Gm, Mesh,
    PhysicalMaterial, RenderTarget, ScissorBox, Srgba, Vec3, Viewport, degrees,
};

use super::convert::FrameParams;

/// Background of the 3D view.
pub const BACKGROUND: [f32; 3] = [0.09, 0.10, 0.12];

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
        let context =
            Context::from_gl_context(gl).map_err(|e| format!("cannot use the GL context: {e}"))?;
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

#[cfg(test)]
// Creating an EGL context and loading GL entry points is FFI that glutin and glow mark unsafe;
// this test-only module is the one place the app does it (eframe does it for the window).
#[allow(unsafe_code)]
mod tests {
    use glutin::api::egl::{context::PossiblyCurrentContext, device::Device, display::Display};
    use glutin::config::{ConfigSurfaceTypes, ConfigTemplateBuilder};
    use glutin::context::{ContextApi, ContextAttributesBuilder, Version};
    use glutin::display::GlDisplay;
    use nalgebra::{Matrix4, Point3};
    use three_d::{DepthTexture2D, Interpolation, Texture2D, Wrapping};

    use super::*;
    use crate::lab::camera::OrbitCamera;
    use crate::lab::geometry::TriMesh;
    use crate::gui::view3d::convert;

    /// A surfaceless EGL context on the first EGL device (Mesa's software device on a machine
    /// without a GPU), made current on this thread.
    fn headless_gl() -> Result<(Display, PossiblyCurrentContext, three_d::context::Context), String>
    {
        let device = Device::query_devices()
            .map_err(|e| format!("no EGL: {e}"))?
            .next()
            .ok_or("no EGL device")?;
        // SAFETY: no native display is passed; the device comes from EGL itself.
        let display = unsafe { Display::with_device(&device, None) }.map_err(|e| e.to_string())?;
        let template = ConfigTemplateBuilder::new()
            .with_surface_type(ConfigSurfaceTypes::empty())
            .build();
        // SAFETY: the display is valid for the whole call.
        let config = unsafe { display.find_configs(template) }
            .map_err(|e| e.to_string())?
            .next()
            .ok_or("no surfaceless EGL config")?;
        let attributes = ContextAttributesBuilder::new()
            .with_context_api(ContextApi::OpenGl(Some(Version::new(3, 3))))
            .build(None);
        // SAFETY: config and attributes come from this display.
        let context = unsafe { display.create_context(&config, &attributes) }
            .map_err(|e| e.to_string())?
            .make_current_surfaceless()
            .map_err(|e| e.to_string())?;
        // SAFETY: the context is current on this thread and stays alive (returned with it).
        let gl = unsafe {
            three_d::context::Context::from_loader_function_cstr(|s| display.get_proc_address(s))
        };
        Ok((display, context, gl))
    }

    #[test]
    fn renders_the_t_handle_headless() {
        let (_display, _context, gl) = match headless_gl() {
            Ok(x) => x,
            Err(e) => {
                eprintln!("SKIPPED headless render: {e} (install libegl1 and Mesa)");
                return;
            }
        };
        let gl = Arc::new(gl);
        let mut scene = Scene::new(Arc::clone(&gl)).expect("three-d on EGL");
        let context = Context::from_gl_context(gl).expect("context");
        let mesh = TriMesh::from_poly(&massprops::shapes::t_handle().build());
        let (center, radius) = mesh.bounding_sphere();
        scene.set_mesh(1, &convert::cpu_mesh(&mesh, &center));
        let mut camera = OrbitCamera::default();
        camera.frame(center, radius);
        let params = FrameParams::new(&camera, &Matrix4::identity(), &center);

        let (w, h) = (160u32, 120u32);
        let color = Texture2D::new_empty::<[u8; 4]>(
            &context,
            w,
            h,
            Interpolation::Nearest,
            Interpolation::Nearest,
            None,
            Wrapping::ClampToEdge,
            Wrapping::ClampToEdge,
        );
        let depth = DepthTexture2D::new::<f32>(
            &context,
            w,
            h,
            Wrapping::ClampToEdge,
            Wrapping::ClampToEdge,
        );
        let target = RenderTarget::new(color.as_color_target(None), depth.as_depth_target());
        let viewport = Viewport::new_at_origo(w, h);
        scene.render(&target, viewport, viewport.into(), &params);
        let pixels: Vec<[u8; 4]> = target.read_color();
        assert_eq!(pixels.len(), (w * h) as usize);

        let background = BACKGROUND.map(|c| (c * 255.0).round() as i32);
        let is_background =
            |p: &[u8; 4]| (0..3).all(|k| (i32::from(p[k]) - background[k]).abs() <= 2);
        // The T-handle is framed: its centre of mass (on the crossbar/stem junction) projects
        // near the middle, and it leaves the corners empty.
        let com = massprops::mass_properties(&massprops::shapes::t_handle().build(), 1.0)
            .expect("closed")
            .center_of_mass;
        let px = camera
            .project(
                &Point3::from(com.coords),
                nalgebra::Vector2::new(f64::from(w), f64::from(h)),
            )
            .expect("visible");
        // Rows come bottom-up from GL.
        let at = |x: u32, y: u32| pixels[((h - 1 - y) * w + x) as usize];
        assert!(is_background(&at(0, 0)) && is_background(&at(w - 1, h - 1)));
        let body: Vec<&[u8; 4]> = pixels.iter().filter(|p| !is_background(p)).collect();
        let share = body.len() as f64 / pixels.len() as f64;
        assert!((0.05..0.6).contains(&share), "body covers {share}");
        // Lit, not flat: the tan body shows several distinct shades (faces at different angles).
        let mut shades: Vec<u8> = body.iter().map(|p| p[0] / 4).collect();
        shades.sort_unstable();
        shades.dedup();
        assert!(shades.len() >= 3, "{shades:?}");
        assert!(body.iter().all(|p| p[0] >= p[2]), "tan, not blue");
        let c = at(px.x as u32, px.y as u32);
        assert!(
            !is_background(&c),
            "body at the projected centre of mass, got {c:?}"
        );
    }
}
