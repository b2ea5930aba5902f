//! The toolbar over the 3D view: overlay toggles and "frame the body".

use crate::lab::settings::{AppSettings, Equivalent};

/// Shows the toolbar, editing the frame's settings draft; returns whether "Frame" was clicked
/// (a camera action, not a command).
pub fn show(ui: &mut egui::Ui, s: &mut AppSettings) -> bool {
    let mut frame = false;
    ui.horizontal_wrapped(|ui| {
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
        ui.separator();
        ui.label("Equivalent:");
        ui.radio_value(&mut v.equivalent, Equivalent::None, "none");
        ui.radio_value(&mut v.equivalent, Equivalent::Box, "box");
        ui.radio_value(&mut v.equivalent, Equivalent::Ellipsoid, "ellipsoid");
    });
    frame
}
