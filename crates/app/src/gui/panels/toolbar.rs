//! The toolbar over the 3D view: overlay toggles and "frame the body".

use super::{Frame, Panel};
use crate::i18n::tr;
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
            .button(tr!("toolbar-frame"))
            .on_hover_text(tr!("toolbar-frame-hover"))
            .clicked();
        let v = &mut s.view;
        ui.checkbox(&mut v.follow_body, tr!("toolbar-follow-body"))
            .on_hover_text(tr!("toolbar-follow-body-hover"));
        ui.checkbox(&mut v.wireframe, tr!("toolbar-wireframe"));
        ui.checkbox(&mut v.bounding_box, tr!("toolbar-bounding-box"))
            .on_hover_text(tr!("toolbar-bounding-box-hover"));
        ui.checkbox(&mut v.center_of_mass, tr!("toolbar-com"))
            .on_hover_text(tr!("toolbar-com-hover"));
        ui.checkbox(&mut v.principal_axes, tr!("toolbar-principal-axes"))
            .on_hover_text(tr!("toolbar-principal-axes-hover"));
        ui.checkbox(&mut v.omega_arrow, "ω")
            .on_hover_text(tr!("toolbar-omega-hover"));
        ui.checkbox(&mut v.l_arrow, "L")
            .on_hover_text(tr!("toolbar-l-hover"));
        ui.checkbox(&mut v.poinsot, tr!("toolbar-poinsot"))
            .on_hover_text(tr!("toolbar-poinsot-hover"));
        ui.checkbox(&mut v.momentum_sphere, tr!("toolbar-sphere"))
            .on_hover_text(tr!("toolbar-sphere-hover"));
        ui.separator();
        // Its own id: the label changes with the language, the menu's state must not.
        egui::ComboBox::new("toolbar-equivalent", tr!("toolbar-equivalent"))
            .selected_text(equivalent_name(v.equivalent))
            .show_ui(ui, |ui| {
                for e in [Equivalent::None, Equivalent::Box, Equivalent::Ellipsoid] {
                    ui.selectable_value(&mut v.equivalent, e, equivalent_name(e));
                }
            });
    });
    frame
}

fn equivalent_name(e: Equivalent) -> String {
    match e {
        Equivalent::None => tr!("toolbar-equivalent-none"),
        Equivalent::Box => tr!("toolbar-equivalent-box"),
        Equivalent::Ellipsoid => tr!("toolbar-equivalent-ellipsoid"),
    }
}
