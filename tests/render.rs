//! The 3D scene rendered headless (surfaceless EGL on Mesa's software device, no window): the
//! framed T-handle covers the middle of the picture, lit, in its own colour.
//!
//! Creating an EGL context and loading GL entry points is FFI that glutin and glow mark unsafe;
//! this test is the one place the project does it (eframe does it for the window).
#![allow(unsafe_code)]

mod common;

use glutin::api::egl::{context::PossiblyCurrentContext, device::Device, display::Display};
use glutin::config::{ConfigSurfaceTypes, ConfigTemplateBuilder};
use glutin::context::{ContextApi, ContextAttributesBuilder, Version};
use glutin::display::GlDisplay;
use std::sync::Arc;

use nalgebra::{Matrix4, Point3};
use three_d::{DepthTexture2D, Interpolation, Texture2D, Wrapping};

use inertia_lab::gui::view3d::camera::OrbitCamera;
use inertia_lab::gui::view3d::convert::{self, FrameParams};
use inertia_lab::gui::view3d::scene::{BACKGROUND, Scene};
use inertia_lab::lab::geometry::TriMesh;
use three_d::{Context, RenderTarget, Viewport};

use common::skip;

/// A surfaceless EGL context on the first EGL device (Mesa's software device on a machine
/// without a GPU), made current on this thread.
fn headless_gl() -> Result<(Display, PossiblyCurrentContext, three_d::context::Context), String> {
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
            skip(
                "renders_the_t_handle_headless",
                &format!("no headless OpenGL ({e})"),
                "apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri",
            );
            return;
        }
    };
    let gl = Arc::new(gl);
    let mut scene = Scene::new(Arc::clone(&gl)).expect("three-d on EGL");
    let context = Context::from_gl_context(gl).expect("context");
    let mesh = TriMesh::from_poly(&massprops::shapes::t_handle().build());
    let (center, radius) = mesh.bounding_sphere();
    scene.set_mesh(1, &convert::cpu_mesh(&mesh, &center, &[]));
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
    let depth =
        DepthTexture2D::new::<f32>(&context, w, h, Wrapping::ClampToEdge, Wrapping::ClampToEdge);
    let target = RenderTarget::new(color.as_color_target(None), depth.as_depth_target());
    let viewport = Viewport::new_at_origo(w, h);
    scene.render(&target, viewport, viewport.into(), &params);
    let pixels: Vec<[u8; 4]> = target.read_color();
    assert_eq!(pixels.len(), (w * h) as usize);

    let background = BACKGROUND.map(|c| (c * 255.0).round() as i32);
    let is_background = |p: &[u8; 4]| (0..3).all(|k| (i32::from(p[k]) - background[k]).abs() <= 2);
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
