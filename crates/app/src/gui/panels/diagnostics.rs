//! The Mesh diagnostics section: what the mesh is made of (faces, edges, shells) and each warning
//! with its effect on the mass; clicking a warning highlights its faces in the 3D view.

use egui::{Color32, RichText};
use massprops::defects::Orientation;

use super::{Frame, Panel, PanelState};
use crate::gui::warnings;
use crate::i18n::{sci, tr};
use crate::lab::Lab;

/// The Mesh diagnostics section, for the primary specimen's body.
#[derive(Debug, Default)]
pub struct DiagnosticsSection;

impl Panel for DiagnosticsSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        show(ui, f.lab, f.shared);
    }
}

fn show(ui: &mut egui::Ui, lab: &Lab, state: &mut PanelState) {
    let body = lab.primary().body();
    let a = &body.analysis;
    if state
        .selected_warning
        .is_some_and(|i| i >= a.warnings.len())
    {
        state.selected_warning = None;
    }
    egui::CollapsingHeader::new(if a.warnings.is_empty() {
        tr!("diagnostics-header")
    } else {
        tr!("diagnostics-header-warnings", count = a.warnings.len())
    })
    // A new count of warnings is a new header (opened again when there are some), as when the
    // title was its id; the language is not.
    .id_salt(("diagnostics", a.warnings.len()))
    .default_open(!a.warnings.is_empty())
    .show(ui, |ui| {
        let d = &a.diagnostics;
        ui.label(tr!(
            "diagnostics-counts",
            vertices = d.vertices,
            faces = d.faces,
            triangles = d.triangles,
            edges = d.edges,
        ));
        ui.label(shells_line(a));
        // A body of parts has its volume from the parts (voids taken away); the surfaces
        // together enclose the voids twice.
        let volume = match &body.composition {
            Some(c) => Some(c.volume),
            None => a.volume,
        };
        if let Some(v) = volume {
            ui.label(tr!(
                "diagnostics-volume-area",
                volume = sci(v, 5),
                area = sci(d.surface_area, 5),
            ));
        }
        if a.warnings.is_empty() {
            ui.label(tr!("diagnostics-no-defects"));
            return;
        }
        ui.small(tr!("diagnostics-click-hint"));
        for (i, w) in a.warnings.iter().enumerate() {
            let selected = state.selected_warning == Some(i);
            let mut title = warnings::title(w);
            if let Some(effect) = warnings::effect(w) {
                title = format!("{title}: {effect}");
            }
            let text = RichText::new(title).color(Color32::YELLOW).strong();
            if ui.selectable_label(selected, text).clicked() {
                state.selected_warning = if selected { None } else { Some(i) };
            }
            ui.add(egui::Label::new(warnings::warning_text(w, &body.face_lines)).wrap());
        }
    });
}

/// "2 shells: 1 solid, 1 cavity" and the like.
fn shells_line(a: &massprops::Analysis) -> String {
    let closed: Vec<&massprops::defects::Shell> = a.shells.iter().filter(|s| s.closed).collect();
    let cavities = closed
        .iter()
        .filter(|s| s.orientation == Orientation::Inward && s.depth.is_some_and(|d| d % 2 == 1))
        .count();
    let capped = a.shells.iter().filter(|s| s.capped).count();
    let uneven = a.shells.len() - closed.len() - capped;
    let mut parts = vec![tr!("diagnostics-shells-closed", count = closed.len())];
    if cavities > 0 {
        parts.push(tr!("diagnostics-shells-cavities", count = cavities));
    }
    if capped > 0 {
        parts.push(tr!("diagnostics-shells-capped", count = capped));
    }
    if uneven > 0 {
        parts.push(tr!("diagnostics-shells-uneven", count = uneven));
    }
    tr!(
        "diagnostics-shells",
        count = a.shells.len(),
        parts = parts.join(", ")
    )
}
