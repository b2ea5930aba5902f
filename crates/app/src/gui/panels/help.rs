//! The F1 help overlay: controls and what the views show.

use super::{Frame, Panel};
use crate::gui::view3d::overlay::AXIS_COLORS;

/// The help window, shown while the shared `help_open` is set (F1, or the Help button).
#[derive(Debug, Default)]
pub struct HelpWindow;

impl Panel for HelpWindow {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        show(ui.ctx(), &mut f.shared.help_open);
    }
}

/// Shows the help window while `open`.
fn show(ctx: &egui::Context, open: &mut bool) {
    egui::Window::new("Help (F1)")
        .open(open)
        .collapsible(false)
        .resizable(false)
        .default_width(460.0)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .show(ctx, |ui| {
            ui.heading("On the body");
            egui::Grid::new("help-gestures")
                .striped(true)
                .show(ui, |ui| {
                    for (what, how) in [
                        (
                            "Click the body",
                            "poke: impulse J along the view ray; ΔL = r × J flashes",
                        ),
                        (
                            "Drag the body",
                            "string: pulls the grabbed point towards the pointer",
                        ),
                        ("Drag the background", "orbit the camera"),
                        ("Right or middle drag", "pan"),
                        ("Wheel", "zoom"),
                        ("F or double-click", "frame the body"),
                    ] {
                        ui.strong(what);
                        ui.label(how);
                        ui.end_row();
                    }
                });
            ui.heading("Keys");
            egui::Grid::new("help-keys").striped(true).show(ui, |ui| {
                for (key, what) in [
                    ("Space", "pause / run"),
                    ("S", "one step (pauses)"),
                    ("R", "reset to the start state"),
                    ("1 2 3", "spin about principal axis 1, 2, 3"),
                    ("Arrows", "move the aim (a ring) over the 3D view"),
                    ("P", "poke the body at the aim, along the view ray"),
                    ("F", "frame the body"),
                    ("L", "show or hide the lessons"),
                    (
                        "Enter",
                        "press the focused button, choose the focused option",
                    ),
                    ("F1", "this help"),
                    (
                        "Escape",
                        "gives the keys back to the view from a button or field \
                         (the keys above act whatever button has focus; a field being edited \
                         takes them)",
                    ),
                    ("Tab", "moves between the buttons and fields"),
                ] {
                    ui.strong(key);
                    ui.label(what);
                    ui.end_row();
                }
            });
            ui.heading("What you see");
            ui.horizontal_wrapped(|ui| {
                ui.label("Principal axes");
                for (i, c) in AXIS_COLORS.iter().enumerate() {
                    ui.colored_label(*c, format!("{}", i + 1));
                }
                ui.label(
                    "(moments ascending). Orange ω and purple L arrows are in world space: with \
                     no torque L stays fixed while ω wanders — the T-handle flips about it.",
                );
            });
            ui.label(
                "Spinning about axis 2 (intermediate moment) is unstable: a tiny perturbation \
                 grows and the body flips periodically (Dzhanibekov effect). Axes 1 and 3 are \
                 stable. Switch \"Simulation uses\" to the bounding box to see how the usual \
                 approximation changes the motion; the Textbook model drops the gyroscopic term \
                 and never flips.",
            );
            ui.label(
                "The momentum sphere (right) shows L as seen from the body: it runs along its \
                 violet polhode; the orange separatrix through axis 2 parts the curves around \
                 axes 1 and 3. Poinsot (toolbar) rolls the inertia ellipsoid on the plane \
                 perpendicular to L. Compare (side panel) runs copies that differ in one choice \
                 as ghosts; Record (plot bar) saves the window as pictures.",
            );
        });
}
