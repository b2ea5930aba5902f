//! The toolbar over the 3D view: overlay toggles and "frame the body".

use super::{Frame, Panel};
use crate::lab::settings::{AppSettings, Equivalent};

/// The toolbar over the 3D view.
#[derive(Debug, Default)]
pub struct Toolbar;

impl Panel for Toolbar {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        // "Frame" is a camera action, not a command: the app frames the body.
        if show(ui, f.settings) {
            f.shared.frame_request = true;
        }
    }
}

/// Shows the toolbar, editing the frame's settings draft; returns whether "Frame" was clicked.
fn show(ui: &mut egui::Ui, s: &mut AppSettings) -> bool {
    let mut frame = false;
    // Wraps onto a second row in a narrow window (the 3D view takes what is left): a row that
    // scrolled sideways hid its last controls, and nothing said they were there.
    ui.horizontal_wrapped(|ui| {
        frame = ui
            .button("Frame")
            .on_hover_text("centre the camera on the body (F)")
            .clicked();
        let v = &mut s.view;
        ui.checkbox(&mut v.follow_body, "Follow body")
            .on_hover_text(
                "the camera moves with the centre of mass, so a poked body stays in view",
            );
        ui.checkbox(&mut v.wireframe, "Wireframe");
        ui.checkbox(&mut v.bounding_box, "Bounding box")
            .on_hover_text("the axis-aligned box around the mesh: the usual inertia guess");
        ui.checkbox(&mut v.center_of_mass, "CoM")
            .on_hover_text("the centre of mass");
        ui.checkbox(&mut v.principal_axes, "Principal axes")
            .on_hover_text("the axes of the principal moments, 1 the least, 3 the greatest");
        ui.checkbox(&mut v.omega_arrow, "ω")
            .on_hover_text("the angular velocity ω (rad/s)");
        ui.checkbox(&mut v.l_arrow, "L")
            .on_hover_text("the angular momentum L = Iω, fixed in space with no torque");
        ui.checkbox(&mut v.poinsot, "Poinsot").on_hover_text(
            "the inertia ellipsoid rolling without slipping on the plane perpendicular to L",
        );
        ui.checkbox(&mut v.momentum_sphere, "Sphere").on_hover_text(
            "the momentum sphere: L as the body sees it, on a sphere of radius |L|; its path, \
                 the polhode, circles axis 1 or 3 and crosses at the separatrix through axis 2",
        );
        ui.separator();
        egui::ComboBox::from_label("Equivalent")
            .selected_text(equivalent_name(v.equivalent))
            .show_ui(ui, |ui| {
                for e in [Equivalent::None, Equivalent::Box, Equivalent::Ellipsoid] {
                    ui.selectable_value(&mut v.equivalent, e, equivalent_name(e));
                }
            });
    });
    frame
}

fn equivalent_name(e: Equivalent) -> &'static str {
    match e {
        Equivalent::None => "none",
        Equivalent::Box => "box",
        Equivalent::Ellipsoid => "ellipsoid",
    }
}
