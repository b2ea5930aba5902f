//! The side panel's Compare section: copies of the body from the same start, each differing in
//! one choice (the inertia source, the rotation model or the integrator), drawn as translucent
//! ghosts, with dashed ω curves in the plots and their E and |L| drift in a table here.

use egui::{Color32, RichText};
use rbcore::{Integrator, RotationModel};

use super::PanelState;
use crate::gui::view3d::ghost_color;
use crate::lab::settings::{AppSettings, GhostLayout, InertiaSource};
use crate::lab::{Command, Lab, MAX_COPIES, Variant};

/// The copies the user has ticked (UI state until "Compare" starts them).
#[derive(Debug, Clone, PartialEq)]
pub struct CompareChoice {
    /// A copy with the bounding-box inertia.
    pub bounding_box: bool,
    /// A copy with the point-mass inertia.
    pub point_masses: bool,
    /// A copy under the textbook model (no ω × Iω).
    pub textbook: bool,
    /// A copy with this integrator.
    pub integrator: Option<Integrator>,
}

impl Default for CompareChoice {
    fn default() -> Self {
        // The original tool's lesson: the bounding-box guess moves differently.
        Self {
            bounding_box: true,
            point_masses: false,
            textbook: false,
            integrator: None,
        }
    }
}

impl CompareChoice {
    /// The ticked copies, in the order shown.
    pub fn variants(&self) -> Vec<Variant> {
        let mut v = Vec::new();
        if self.bounding_box {
            v.push(Variant::Source(InertiaSource::BoundingBox));
        }
        if self.point_masses {
            v.push(Variant::Source(InertiaSource::PointMasses));
        }
        if self.textbook {
            v.push(Variant::Model(RotationModel::Textbook));
        }
        if let Some(i) = self.integrator {
            v.push(Variant::Integrator(i));
        }
        v
    }
}

/// Shows the section.
pub fn show(
    ui: &mut egui::Ui,
    lab: &Lab,
    s: &mut AppSettings,
    state: &mut PanelState,
    commands: &mut Vec<Command>,
) {
    egui::CollapsingHeader::new("Compare")
        .default_open(false)
        .show(ui, |ui| {
            ui.add(
                egui::Label::new(
                    "Copies of the body from the same start, each differing in one choice:",
                )
                .wrap(),
            );
            let c = &mut state.compare;
            ui.checkbox(&mut c.bounding_box, "bounding-box inertia");
            ui.checkbox(&mut c.point_masses, "point-mass inertia");
            ui.checkbox(&mut c.textbook, "textbook model (no ω × Iω)");
            ui.horizontal(|ui| {
                let mut on = c.integrator.is_some();
                ui.checkbox(&mut on, "integrator");
                let mut chosen = c.integrator.unwrap_or(Integrator::Rk4);
                egui::ComboBox::from_id_salt("compare-integrator")
                    .selected_text(chosen.name())
                    .show_ui(ui, |ui| {
                        for i in Integrator::ALL {
                            ui.selectable_value(&mut chosen, i, i.name());
                        }
                    });
                c.integrator = on.then_some(chosen);
            });
            let variants = c.variants();
            ui.horizontal_wrapped(|ui| {
                let ok = (1..=MAX_COPIES).contains(&variants.len());
                let label = format!("Compare {} from the start", variants.len());
                if ui.add_enabled(ok, egui::Button::new(label)).clicked() {
                    commands.push(Command::Compare(variants.clone()));
                }
                if lab.specimens().len() > 1 && ui.button("Stop comparing").clicked() {
                    commands.push(Command::Compare(Vec::new()));
                }
            });
            if variants.len() > MAX_COPIES {
                ui.colored_label(
                    Color32::from_rgb(255, 170, 60),
                    format!("At most {MAX_COPIES} copies at a time."),
                );
            }
            ui.horizontal(|ui| {
                ui.label("Ghosts");
                ui.radio_value(&mut s.view.ghosts, GhostLayout::Overlaid, "overlaid");
                ui.radio_value(&mut s.view.ghosts, GhostLayout::Row, "in a row");
            });
            if lab.specimens().len() > 1 {
                drift_table(ui, lab);
                ui.small(
                    "Drift since the start or the last poke, pull or change. Poke and string act \
                     on the body itself, not on its copies.",
                );
            }
        });
}

/// Each specimen's largest E and |L| drift since the start or its last disturbance.
fn drift_table(ui: &mut egui::Ui, lab: &Lab) {
    egui::Grid::new("compare-drift")
        .striped(true)
        .num_columns(3)
        .show(ui, |ui| {
            ui.label("");
            ui.strong("max ΔE/E");
            ui.strong("max Δ|L|/|L|");
            ui.end_row();
            for (k, sp) in lab.specimens().iter().enumerate() {
                let name = if k == 0 {
                    RichText::new("body")
                } else {
                    let [r, g, b, _] = ghost_color(k);
                    RichText::new(sp.variant().label()).color(Color32::from_rgb(r, g, b))
                };
                ui.label(name);
                ui.label(format!("{:.1e}", sp.drift().max_energy()));
                ui.label(format!("{:.1e}", sp.drift().max_l_norm()));
                ui.end_row();
            }
        });
}
