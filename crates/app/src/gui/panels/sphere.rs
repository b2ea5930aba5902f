//! The momentum sphere: the body's angular momentum seen from the body, in the principal frame.
//! With no torque it stays on the sphere |L| = const and on its energy ellipsoid, so it runs along
//! its own polhode, drawn in L's colour among a family of others; the separatrix through axis 2
//! (orange) divides those circling the stable axes 1 and 3. The current L is the white dot with a fading trail; drag to
//! orbit. The geometry is `polhodes.rs`; this file only projects and paints it.

use egui::{Color32, Pos2, Sense, Stroke};
use nalgebra::{UnitQuaternion, Vector3};
use rbcore::{Integrator, RotationModel, Stability};

use super::{Frame, Panel};
use crate::gui::view3d::overlay::AXIS_COLORS;
use crate::i18n::{sci, tr};
use crate::lab::Lab;
use rbcore::polhode_curves::{self as polhodes, Curve, CurveKind, polhodes};

const POLHODE_COLOR: Color32 = Color32::from_rgb(150, 150, 160);
const SEPARATRIX_COLOR: Color32 = Color32::from_rgb(255, 170, 60);
/// L's own polhode, in the colour of the L arrow.
const OWN_COLOR: Color32 = Color32::from_rgb(220, 90, 255);
/// Seconds of history drawn as the trail.
const TRAIL_SECONDS: f64 = 4.0;
/// Polhodes drawn around each stable axis.
const PER_SIDE: usize = 3;
/// Points per polhode (about a chord every 6° of a great circle): smooth at this size, and few
/// enough vertices that software GL draws the sphere in about a millisecond.
const SAMPLES: usize = 64;

/// The momentum sphere panel, with its orbit and its curves (UI state, not persisted).
#[derive(Debug, Clone, PartialEq)]
pub struct SpherePanel {
    /// Turn about the screen's vertical (rad).
    pub yaw: f64,
    /// Tilt towards the viewer (rad).
    pub pitch: f64,
    /// The polhodes on the unit sphere for these moments: they change only with the body.
    curves: Option<(Vector3<f64>, Vec<Curve>)>,
}

impl Default for SpherePanel {
    fn default() -> Self {
        // All three axes visible, axis 2 towards the viewer's right.
        Self {
            yaw: 0.7,
            pitch: 0.4,
            curves: None,
        }
    }
}

impl SpherePanel {
    fn rotation(&self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_euler_angles(self.pitch, 0.0, 0.0)
            * UnitQuaternion::from_euler_angles(0.0, self.yaw, 0.0)
    }
}

impl Panel for SpherePanel {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        show(ui, f.lab, self);
    }
}

/// Shows the view in `ui`.
fn show(ui: &mut egui::Ui, lab: &Lab, state: &mut SpherePanel) {
    let primary = lab.primary();
    let body = primary.sim().body();
    let moments = body.moments();
    let l = body.angular_momentum_principal();
    let m = l.norm();
    ui.strong(tr!("sphere-heading"));
    let legend_height = 5.0 * ui.text_style_height(&egui::TextStyle::Small) + 12.0;
    let size = ui
        .available_width()
        .min(ui.available_height() - legend_height)
        .max(80.0);
    let (rect, response) = ui.allocate_exact_size(egui::vec2(size, size), Sense::drag());
    if response.dragged() {
        let d = response.drag_delta();
        state.yaw += f64::from(d.x) * 0.01;
        state.pitch = (state.pitch + f64::from(d.y) * 0.01).clamp(-1.5, 1.5);
    }
    let painter = ui.painter_at(rect);
    let center = rect.center();
    let radius = 0.40 * size;
    let view = state.rotation();
    // Screen point and depth (> 0 towards the viewer) of a principal-frame direction.
    let project = |p: &Vector3<f64>| -> (Pos2, f64) {
        let v = view * p;
        let at = center
            + egui::vec2(
                (v.x * f64::from(radius)) as f32,
                (-v.y * f64::from(radius)) as f32,
            );
        (at, v.z)
    };
    painter.circle_stroke(center, radius, Stroke::new(1.0, Color32::from_gray(90)));
    if state
        .curves
        .as_ref()
        .is_none_or(|(for_moments, _)| *for_moments != moments)
    {
        state.curves = Some((moments, polhodes(&moments, 1.0, PER_SIDE, SAMPLES)));
    }
    let curves = state.curves.as_ref().map_or(&[][..], |(_, c)| &c[..]);
    if m > 0.0 {
        for curve in curves {
            let color = match curve.kind {
                CurveKind::Separatrix => SEPARATRIX_COLOR,
                CurveKind::Around(_) => POLHODE_COLOR,
            };
            // One polyline per run of front or back points (far side faint): a few shapes per
            // curve rather than a segment each, which software GL draws far faster.
            let projected: Vec<(Pos2, bool)> = curve
                .points
                .iter()
                .chain(curve.points.first())
                .map(|p| {
                    let (at, depth) = project(p);
                    (at, depth >= 0.0)
                })
                .collect();
            let mut run: Vec<Pos2> = Vec::new();
            let mut front = projected.first().is_some_and(|p| p.1);
            for &(at, is_front) in &projected {
                run.push(at);
                if is_front != front {
                    polyline(&painter, std::mem::take(&mut run), color, front);
                    run.push(at);
                    front = is_front;
                }
            }
            polyline(&painter, run, color, front);
        }
    }
    // L's own polhode, for the E and |L| it has now (a poke or a new body gives a new one).
    if let Some(own) = polhodes::polhode_through(&moments, &l, SAMPLES) {
        let points: Vec<Pos2> = own
            .points
            .iter()
            .chain(own.points.first())
            .map(|p| project(p).0)
            .collect();
        painter.add(egui::Shape::line(points, Stroke::new(2.0, OWN_COLOR)));
    }
    for (i, color) in AXIS_COLORS.iter().enumerate() {
        let axis = Vector3::ith(i, 1.15);
        let (a, _) = project(&-axis);
        let (b, _) = project(&axis);
        painter.line_segment([a, b], Stroke::new(1.0, color.gamma_multiply(0.8)));
        painter.text(
            b,
            egui::Align2::CENTER_CENTER,
            format!("{}", i + 1),
            egui::FontId::proportional(13.0),
            *color,
        );
    }
    if m > 0.0 {
        trail(&painter, lab, &moments, &project);
        let (dot, _) = project(&(l / m));
        painter.circle_filled(dot, 4.5, Color32::WHITE);
        painter.circle_stroke(dot, 4.5, Stroke::new(1.0, Color32::BLACK));
    }
    legend(ui, &moments);
    let physics = &lab.settings().physics;
    let note = if physics.model == RotationModel::Textbook {
        Some(tr!("sphere-textbook-note"))
    } else {
        let reasons = [
            (physics.angular_damping > 0.0, tr!("sphere-reason-damping")),
            (primary.string_view().is_some(), tr!("sphere-reason-string")),
            (
                !conserves(physics.integrator),
                tr!("sphere-reason-integrator"),
            ),
        ]
        .into_iter()
        .filter_map(|(on, why)| on.then_some(why))
        .reduce(|first, second| tr!("sphere-reasons-and", first = first, second = second));
        reasons.map(|reasons| tr!("sphere-leaves-curve", reasons = reasons))
    };
    if let Some(note) = note {
        ui.add(egui::Label::new(egui::RichText::new(note).small().color(SEPARATRIX_COLOR)).wrap());
    }
}

/// Whether `integrator` keeps E and |L| of the free rotation (to round-off or, for splitting,
/// to a bounded error): the others let the dot drift off its curve.
fn conserves(integrator: Integrator) -> bool {
    matches!(
        integrator,
        Integrator::MidpointCayley | Integrator::Splitting | Integrator::Exact
    )
}

/// Draws `points` as one line, faint on the far side of the sphere.
fn polyline(painter: &egui::Painter, points: Vec<Pos2>, color: Color32, front: bool) {
    if points.len() < 2 {
        return;
    }
    let color = if front {
        color
    } else {
        color.gamma_multiply(0.25)
    };
    painter.add(egui::Shape::line(points, Stroke::new(1.2, color)));
}

/// The last seconds of L's direction, fading with age.
fn trail(
    painter: &egui::Painter,
    lab: &Lab,
    moments: &Vector3<f64>,
    project: &dyn Fn(&Vector3<f64>) -> (Pos2, f64),
) {
    let history = lab.primary().history();
    let Some(last) = history.last() else { return };
    let since = (last.t - TRAIL_SECONDS).max(history.disturbed_at());
    let start = history.samples().partition_point(|s| s.t < since);
    let samples: Vec<_> = history.samples().range(start..).collect();
    // About 300 segments whatever the step.
    let stride = (samples.len() / 300).max(1);
    let points: Vec<(f64, Pos2)> = samples
        .iter()
        .step_by(stride)
        .filter_map(|s| {
            let l = Vector3::from(s.omega_principal).component_mul(moments);
            let n = l.norm();
            (n > 0.0).then(|| (s.t, project(&(l / n)).0))
        })
        .collect();
    // Eight bands of age, one polyline each, oldest faintest.
    const BANDS: usize = 8;
    let per_band = points.len().div_ceil(BANDS).max(1);
    for (b, band) in points.chunks(per_band).enumerate() {
        // Each band starts where the previous one ended, so the trail has no gaps.
        let start = (b * per_band).saturating_sub(1);
        let line: Vec<Pos2> = points[start..start + band.len() + usize::from(b > 0)]
            .iter()
            .map(|p| p.1)
            .collect();
        let age = ((last.t - band[band.len() - 1].0) / TRAIL_SECONDS).clamp(0.0, 1.0) as f32;
        let color = Color32::WHITE.gamma_multiply(1.0 - 0.9 * age);
        if line.len() >= 2 {
            painter.add(egui::Shape::line(line, Stroke::new(2.0, color)));
        }
    }
}

/// How a spin about principal axis `i` behaves, in words (rbcore's classification).
fn stability(moments: &Vector3<f64>, i: usize) -> String {
    match rbcore::stability(moments, i) {
        Stability::Stable => tr!("sphere-stable"),
        Stability::Unstable => tr!("sphere-unstable"),
        Stability::Neutral => tr!("sphere-neutral"),
    }
}

/// The axes' moments and stability, in their colours.
fn legend(ui: &mut egui::Ui, moments: &Vector3<f64>) {
    for (i, color) in AXIS_COLORS.iter().enumerate() {
        ui.label(
            egui::RichText::new(tr!(
                "sphere-axis",
                axis = i + 1,
                moment = sci(moments[i], 4),
                stability = stability(moments, i)
            ))
            .small()
            .color(*color),
        );
    }
    ui.label(
        egui::RichText::new(tr!("sphere-legend"))
            .small()
            .color(Color32::GRAY),
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stability_of_each_axis() {
        let distinct = Vector3::new(1.0, 2.0, 3.0);
        let names: Vec<_> = (0..3).map(|i| stability(&distinct, i)).collect();
        assert_eq!(names, ["stable", "unstable", "stable"]);
        let top = Vector3::new(2.0, 2.0, 3.0);
        assert_eq!(stability(&top, 1), "neutral (equal moments)");
        assert_eq!(stability(&top, 2), "stable");
    }
}
