//! The toolbar over the 3D view: overlay toggles and "frame the body".

use crate::lab::settings::{AppSettings, Equivalent};

/// Shows the toolbar, editing the frame's settings draft; returns whether "Frame" was clicked
/// (a camera action, not a command).
pub fn show(ui: &mut egui::Ui, s: &mut AppSettings) -> bool {
    let mut frame = false;
    // One row that scrolls sideways in a narrow window rather than wrapping onto the 3D view.
    egui::ScrollArea::horizontal().show(ui, |ui| {
        ui.horizontal(|ui| {
            frame = ui
                .button("Frame")
                .on_hover_text("centre the camera on the body (F)")
                .clicked();
            let v = &mut s.view;
            ui.checkbox(&mut v.follow_body, "Follow body");
            ui.checkbox(&mut v.wireframe, "Wireframe");
            ui.checkbox(&mut v.bounding_box, "Bounding box");
            ui.checkbox(&mut v.center_of_mass, "CoM");
            ui.checkbox(&mut v.principal_axes, "Principal axes");
            ui.checkbox(&mut v.omega_arrow, "ω");
            ui.checkbox(&mut v.l_arrow, "L");
            ui.checkbox(&mut v.poinsot, "Poinsot").on_hover_text(
                "the inertia ellipsoid rolling without slipping on the plane perpendicular to L",
            );
            ui.checkbox(&mut v.momentum_sphere, "Sphere")
                .on_hover_text("the momentum sphere: L in the body, on its polhode");
            ui.separator();
            egui::ComboBox::from_label("Equivalent")
                .selected_text(equivalent_name(v.equivalent))
                .show_ui(ui, |ui| {
                    for e in [Equivalent::None, Equivalent::Box, Equivalent::Ellipsoid] {
                        ui.selectable_value(&mut v.equivalent, e, equivalent_name(e));
                    }
                });
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
