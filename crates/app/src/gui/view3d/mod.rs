//! The 3D view: camera control, the poke and string gestures (recorded as commands), the three-d
//! paint callback for the shaded body, and the overlay drawn with egui on top.

pub mod camera;
pub mod convert;
pub mod overlay;
pub mod scene;

use std::sync::Arc;

use egui::{Color32, PointerButton, Sense, Stroke};
use nalgebra::{Matrix4, Point3, Vector3};

use self::camera::OrbitCamera;
use crate::i18n::{self, tr};
use crate::lab::geometry::WIREFRAME_MAX_EDGES;
use crate::lab::settings::GhostLayout;
use crate::lab::{Command, Lab, PRIMARY};
use crate::platform::Instant;
use convert::FrameParams;
use overlay::{Overlay, Selection};
use scene::SceneSlot;

/// What a primary-button drag is doing.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Gesture {
    /// Turning the camera (the drag started off the body).
    Orbit,
    /// Pulling the string, moving its end in the plane through `point` with normal `normal`.
    String {
        point: Point3<f64>,
        normal: Vector3<f64>,
    },
}

/// View state of the 3D panel: camera and the gesture in progress (not persisted, not model).
#[derive(Debug, Clone, Default)]
pub struct View3d {
    /// The camera.
    pub camera: OrbitCamera,
    gesture: Option<Gesture>,
    /// Mesh generation, number of specimens and ghost layout last framed: a new body, a new
    /// comparison or another layout is framed once.
    framed: Option<(u64, usize, GhostLayout)>,
    /// Centre of mass the camera last followed: the target moves with the body by the change.
    followed: Option<Point3<f64>>,
    /// Where the view was last drawn (points).
    shown: Option<egui::Rect>,
    /// The keyboard's aim (the arrow keys move it, P pokes there): its offset from the view's
    /// centre in view heights, once the arrows have moved it.
    aim: Option<egui::Vec2>,
}

/// How far one press of an arrow key moves the keyboard's aim (view heights).
const AIM_STEP: f32 = 0.02;

/// Where specimen `k` (0: the body) stands in a row, in bounding radii along the screen's right:
/// the body in the middle, the first copy to its left, the others to its right.
fn row_offset(k: usize) -> f64 {
    const SPACING: f64 = 2.2;
    match k {
        0 => 0.0,
        1 => -SPACING,
        _ => SPACING * (k - 1) as f64,
    }
}

/// The colour of part `k` of a body made of parts (the Parts section shows the same swatch).
pub fn part_color(k: usize) -> [u8; 3] {
    const PALETTE: [[u8; 3]; 8] = [
        [200, 160, 90],
        [110, 160, 220],
        [120, 200, 120],
        [220, 110, 110],
        [190, 130, 220],
        [230, 200, 90],
        [90, 200, 200],
        [220, 150, 180],
    ];
    PALETTE[k % PALETTE.len()]
}

/// The translucent colour of compared copy `k` (1-based), also its swatch in the tables.
pub fn ghost_color(k: usize) -> [u8; 4] {
    const COLORS: [[u8; 4]; 3] = [[80, 220, 230, 90], [230, 90, 230, 90], [150, 230, 90, 90]];
    COLORS[(k + COLORS.len() - 1) % COLORS.len()]
}

impl View3d {
    /// Whether a gesture is in progress (the app keeps repainting).
    pub fn is_dragging(&self) -> bool {
        self.gesture.is_some()
    }

    /// Centres the camera on the body, with room for the ω and L arrows (up to 1.3 radii from
    /// the centre of mass at the preset spin).
    pub fn frame_body(&mut self, lab: &Lab) {
        let (c, r) = lab.primary().bounding_sphere();
        let copies = lab.specimens().len() - 1;
        if lab.settings().view.ghosts == GhostLayout::Row && copies > 0 {
            // The whole row: from the leftmost ghost to the rightmost.
            let offsets: Vec<f64> = (0..=copies).map(row_offset).collect();
            let (lo, hi) = offsets
                .iter()
                .fold((0.0f64, 0.0f64), |(lo, hi), &o| (lo.min(o), hi.max(o)));
            let centre = c + self.camera.right() * ((lo + hi) / 2.0 * r);
            self.camera.frame(centre, 1.8 * r * (1.0 + (hi - lo) / 2.0));
        } else {
            self.camera.frame(c, 1.8 * r);
        }
    }

    /// Moves the target with the centre of mass (keeping any pan offset), so a poked or pulled
    /// body that drifts stays in view.
    fn follow(&mut self, lab: &Lab) {
        let com = lab.primary().sim().body().position();
        if lab.settings().view.follow_body
            && let Some(last) = self.followed
        {
            self.camera.target += com - last;
        }
        self.followed = Some(com);
    }

    /// Where the view was last drawn (points), once it has been.
    pub fn rect(&self) -> Option<egui::Rect> {
        self.shown
    }

    /// Shows the view in the remaining space of `ui`.
    pub fn show(
        &mut self,
        ui: &mut egui::Ui,
        lab: &Lab,
        scene: Option<SceneSlot>,
        selection: Selection,
        commands: &mut Vec<Command>,
    ) {
        let shown = (
            lab.generation(),
            lab.specimens().len(),
            lab.settings().view.ghosts,
        );
        if self.framed != Some(shown) {
            self.framed = Some(shown);
            self.frame_body(lab);
        }
        self.follow(lab);
        // The hint under the view: the controls, after what is drawn differently. Its height is
        // measured at the view's width: a longer language wraps it onto more lines.
        let mut hint = tr!("view3d-hint");
        if let Some(drawn) = &lab.primary().body().drawn {
            let count = |n: usize| i18n::localize(inertia_io::wording::millions(n));
            hint = tr!(
                "view3d-drawn-simplified",
                drawn = count(drawn.mesh.triangles.len()),
                total = count(lab.primary().body().mesh.triangles.len()),
                hint = hint,
            );
        }
        if lab.settings().view.wireframe
            && lab.primary().body().analysis.diagnostics.edges > WIREFRAME_MAX_EDGES
        {
            hint = tr!(
                "view3d-wireframe-off",
                edges = WIREFRAME_MAX_EDGES,
                hint = hint
            );
        }
        let width = ui.available_width();
        let hint_height = ui
            .painter()
            .layout(
                hint.clone(),
                egui::TextStyle::Small.resolve(ui.style()),
                egui::Color32::PLACEHOLDER,
                width,
            )
            .size()
            .y
            + 6.0;
        let mut rect = ui.available_rect_before_wrap();
        rect.max.y -= hint_height;
        self.shown = Some(rect);
        let response = ui
            .allocate_rect(rect, Sense::click_and_drag())
            .on_hover_cursor(egui::CursorIcon::Crosshair);
        // What the view shows, in words, for a screen reader (AccessKit names the view so).
        let description = crate::lab::describe::description(lab);
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &description));
        self.handle_input(ui, &response, lab, commands);

        let (origin, params) = self.frame_params(lab);
        match scene {
            Some(scene) => {
                if scene.with(|s| s.generation()) != Some(Some(lab.generation())) {
                    let body = lab.primary().body();
                    let colors = triangle_colors(body);
                    let cpu = match &body.drawn {
                        Some(drawn) => {
                            let colors: Vec<_> = if colors.is_empty() {
                                colors
                            } else {
                                drawn.from.iter().map(|&k| colors[k as usize]).collect()
                            };
                            convert::cpu_mesh(&drawn.mesh, &origin, &colors)
                        }
                        None => convert::cpu_mesh(&body.mesh, &origin, &colors),
                    };
                    scene.with(|s| s.set_mesh(lab.generation(), &cpu));
                }
                let callback = egui_glow::CallbackFn::new(move |info, _painter| {
                    scene.with(|s| s.paint(&info, &params));
                });
                ui.painter().add(egui::PaintCallback {
                    rect,
                    callback: Arc::new(callback),
                });
            }
            None => {
                let [r, g, b] = scene::BACKGROUND.map(|c| (c * 255.0) as u8);
                ui.painter()
                    .rect_filled(rect, 0.0, Color32::from_rgb(r, g, b));
                ui.painter().text(
                    rect.center(),
                    egui::Align2::CENTER_CENTER,
                    tr!("view3d-unavailable"),
                    egui::FontId::proportional(14.0),
                    Color32::GRAY,
                );
            }
        }
        self.paint_overlay(ui, rect, lab, selection);
        ui.allocate_ui(egui::vec2(rect.width(), hint_height), |ui| {
            ui.small(hint);
        });
    }

    /// Camera values and the mesh → world matrix for the renderer, with the upload origin (the
    /// mesh's bounding-sphere centre).
    fn frame_params(&self, lab: &Lab) -> (Point3<f64>, FrameParams) {
        let primary = lab.primary();
        let origin = primary.body().sphere.0;
        let model = primary.placement().matrix();
        let mut params = FrameParams::new(&self.camera, &model, &origin);
        if primary.body().composition.is_some() {
            // The parts' own colours, untinted.
            params.color = [255, 255, 255];
        }
        // A row runs along the screen's right at the primary's depth, about a body width apart.
        let (_, radius) = primary.bounding_sphere();
        let right = self.camera.right();
        for (k, copy) in lab.specimens().iter().enumerate().skip(1) {
            let shift = match lab.settings().view.ghosts {
                GhostLayout::Overlaid => Vector3::zeros(),
                GhostLayout::Row => right * (row_offset(k) * radius),
            };
            let m = Matrix4::new_translation(&shift) * copy.placement().matrix();
            params.add_ghost(&m, &origin, ghost_color(k));
        }
        (origin, params)
    }

    fn handle_input(
        &mut self,
        ui: &egui::Ui,
        response: &egui::Response,
        lab: &Lab,
        commands: &mut Vec<Command>,
    ) {
        let rect = response.rect;
        let size = convert::size(rect.size());
        let ray_at =
            |cam: &OrbitCamera, pos: egui::Pos2| cam.ray(convert::view_pixel(pos, rect.min), size);
        if response.drag_started_by(PointerButton::Primary) {
            let origin = ui
                .input(|i| i.pointer.press_origin())
                .or(response.interact_pointer_pos());
            let hit = origin.and_then(|p| lab.primary().pick(&ray_at(&self.camera, p)));
            self.gesture = Some(match hit {
                Some(hit) => {
                    commands.push(Command::Grab {
                        specimen: PRIMARY,
                        point: hit.point,
                    });
                    Gesture::String {
                        point: hit.point,
                        normal: self.camera.forward(),
                    }
                }
                None => Gesture::Orbit,
            });
        }
        if response.dragged_by(PointerButton::Primary) {
            match self.gesture {
                Some(Gesture::Orbit) => {
                    let d = response.drag_delta();
                    self.camera.orbit(f64::from(d.x), f64::from(d.y));
                }
                Some(Gesture::String { point, normal }) => {
                    if let Some(pos) = response.interact_pointer_pos()
                        && let Some(target) = ray_at(&self.camera, pos).hit_plane(&point, &normal)
                    {
                        commands.push(Command::Drag {
                            specimen: PRIMARY,
                            target,
                        });
                    }
                }
                None => {}
            }
        }
        if response.drag_stopped() {
            if matches!(self.gesture, Some(Gesture::String { .. })) {
                commands.push(Command::Release { specimen: PRIMARY });
            }
            self.gesture = None;
        }
        if response.dragged_by(PointerButton::Secondary)
            || response.dragged_by(PointerButton::Middle)
        {
            let d = response.drag_delta();
            self.camera
                .pan(f64::from(d.x), f64::from(d.y), f64::from(rect.height()));
        }
        if response.clicked_by(PointerButton::Primary)
            && let Some(pos) = response.interact_pointer_pos()
        {
            let ray = ray_at(&self.camera, pos);
            if let Some(hit) = lab.primary().pick(&ray) {
                commands.push(Command::Poke {
                    specimen: PRIMARY,
                    point: hit.point,
                    direction: ray.dir,
                });
            }
        }
        if response.double_clicked() {
            self.frame_body(lab);
        }
        // The keyboard's poke: the arrows aim, P pokes along the view ray through the aim (while
        // no widget holds the keys, which the arrows would move between).
        if !ui.ctx().text_edit_focused() && ui.memory(|m| m.focused().is_none()) {
            let moved = ui.input(|i| {
                [
                    (egui::Key::ArrowLeft, egui::vec2(-1.0, 0.0)),
                    (egui::Key::ArrowRight, egui::vec2(1.0, 0.0)),
                    (egui::Key::ArrowUp, egui::vec2(0.0, -1.0)),
                    (egui::Key::ArrowDown, egui::vec2(0.0, 1.0)),
                ]
                .into_iter()
                .filter(|(k, _)| i.key_pressed(*k))
                .map(|(_, d)| d * AIM_STEP)
                .reduce(|a, b| a + b)
            });
            if let Some(d) = moved {
                let aim = self.aim.unwrap_or_default() + d;
                self.aim = Some(aim.clamp(egui::vec2(-0.5, -0.5), egui::vec2(0.5, 0.5)));
            }
            if ui.input(|i| i.key_pressed(egui::Key::P)) {
                let pos = rect.center() + self.aim.unwrap_or_default() * rect.height();
                let ray = ray_at(&self.camera, pos);
                if let Some(hit) = lab.primary().pick(&ray) {
                    commands.push(Command::Poke {
                        specimen: PRIMARY,
                        point: hit.point,
                        direction: ray.dir,
                    });
                }
            }
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                self.camera.zoom((-f64::from(scroll) * 0.002).exp());
            }
        }
    }

    fn paint_overlay(&self, ui: &egui::Ui, rect: egui::Rect, lab: &Lab, selection: Selection) {
        let overlay = Overlay::build(lab, Instant::now(), selection);
        let painter = ui.painter_at(rect);
        let size = convert::size(rect.size());
        let project = |p: &Point3<f64>| {
            self.camera
                .project(p, size)
                .map(|q| convert::screen(&q, rect.min))
        };
        if let Some(aim) = self.aim {
            // The keyboard's aim: a ring where P pokes.
            let at = rect.center() + aim * rect.height();
            painter.circle_stroke(at, 7.0, Stroke::new(2.0, Color32::WHITE));
            painter.circle_stroke(at, 9.0, Stroke::new(1.0, Color32::BLACK));
        }
        for s in &overlay.segments {
            let (Some(a), Some(b)) = (project(&s.a), project(&s.b)) else {
                continue;
            };
            painter.line_segment([a, b], Stroke::new(s.width, s.color));
            if s.arrow {
                let d = b - a;
                let len = d.length();
                if len > 1.0 {
                    let u = d / len;
                    let n = egui::vec2(-u.y, u.x);
                    let head = 10.0_f32.min(len * 0.5);
                    for side in [-1.0, 1.0] {
                        painter.line_segment(
                            [b, b - u * head + n * (side * head * 0.5)],
                            Stroke::new(s.width, s.color),
                        );
                    }
                }
            }
        }
        for (p, color) in &overlay.markers {
            if let Some(q) = project(p) {
                painter.circle_filled(q, 4.0, *color);
                painter.circle_stroke(q, 4.0, Stroke::new(1.0, Color32::BLACK));
            }
        }
        for l in &overlay.labels {
            if let Some(q) = project(&l.at) {
                painter.text(
                    q,
                    l.align,
                    &l.text,
                    egui::FontId::proportional(13.0),
                    l.color,
                );
            }
        }
    }
}

/// For a body made of parts, each triangle's colour (its part's), or `None` for a hidden part;
/// empty for a single mesh (drawn in the body colour).
fn triangle_colors(body: &crate::lab::body::LoadedBody) -> Vec<Option<[u8; 3]>> {
    let Some(c) = &body.composition else {
        return Vec::new();
    };
    let mut colors = vec![None; body.mesh.triangles.len()];
    for (k, (part, range)) in c.parts.iter().zip(&c.triangles).enumerate() {
        if part.visible {
            colors[range.clone()].fill(Some(part_color(k)));
        }
    }
    colors
}
