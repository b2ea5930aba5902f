//! The side panel's Compare section: copies of the body from the same start, each differing in
//! one choice (the inertia source, the rotation model or the integrator), drawn as translucent
//! ghosts, with dashed ω curves in the plots and their E and |L| drift in a table here.

use egui::{Color32, RichText};
use rbcore::{Integrator, RotationModel};

use super::{Frame, Panel};
use crate::gui::view3d::ghost_color;
use crate::i18n::{fixed, sci, tr};
use crate::lab::settings::{AppSettings, GhostLayout, InertiaSource};
use crate::lab::{Command, Lab, MAX_COPIES, Variant};

/// The copies the user has ticked (UI state until "Compare" starts them). Each offers the
/// choices other than the lab's own, so a copy always differs from the body.
#[derive(Debug, Clone, PartialEq)]
pub struct CompareChoice {
    /// A copy per inertia source, in [`InertiaSource::ALL`] order (the lab's own is not offered).
    pub sources: [bool; 4],
    /// A copy under the other rotation model.
    pub other_model: bool,
    /// A copy with this integrator (the lab's own is not offered).
    pub integrator: Option<Integrator>,
}

impl Default for CompareChoice {
    fn default() -> Self {
        // The original tool's lesson: the bounding-box guess moves differently.
        Self {
            sources: [false, true, false, false],
            other_model: false,
            integrator: None,
        }
    }
}

impl CompareChoice {
    /// The ticked copies that differ from `settings`, in the order shown.
    pub fn variants(&self, settings: &AppSettings) -> Vec<Variant> {
        let mut v: Vec<Variant> = InertiaSource::ALL
            .into_iter()
            .zip(self.sources)
            .filter(|&(source, on)| on && source != settings.body.source)
            .map(|(source, _)| Variant::Source(source))
            .collect();
        if self.other_model {
            v.push(Variant::Model(other_model(settings.physics.model)));
        }
        if let Some(i) = self
            .integrator
            .filter(|&i| i != settings.physics.integrator)
        {
            v.push(Variant::Integrator(i));
        }
        v
    }
}

/// The rotation model that is not `model`.
fn other_model(model: RotationModel) -> RotationModel {
    match model {
        RotationModel::Full => RotationModel::Textbook,
        RotationModel::Textbook => RotationModel::Full,
    }
}

/// The Compare section: the copies ticked are its own state.
#[derive(Debug, Default)]
pub struct CompareSection {
    choice: CompareChoice,
}

impl Panel for CompareSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        show(ui, f.lab, f.settings, &mut self.choice, f.commands);
    }
}

fn show(
    ui: &mut egui::Ui,
    lab: &Lab,
    s: &mut AppSettings,
    choice: &mut CompareChoice,
    commands: &mut Vec<Command>,
) {
    egui::CollapsingHeader::new(tr!("compare-header"))
        .id_salt("compare")
        .default_open(false)
        .show(ui, |ui| {
            ui.add(egui::Label::new(tr!("compare-intro")).wrap());
            let c = choice;
            let stated = lab.primary().body().stated.is_some();
            for (k, source) in InertiaSource::ALL.into_iter().enumerate() {
                if source == InertiaSource::Stated && !stated {
                    c.sources[k] = false;
                } else if source != s.body.source {
                    ui.checkbox(&mut c.sources[k], Variant::Source(source).label());
                }
            }
            let model = other_model(s.physics.model);
            let model_label = match model {
                RotationModel::Textbook => tr!("compare-model-textbook"),
                RotationModel::Full => tr!("compare-model-full"),
            };
            ui.checkbox(&mut c.other_model, model_label);
            ui.horizontal(|ui| {
                let mut on = c.integrator.is_some();
                ui.checkbox(&mut on, tr!("compare-integrator"));
                let own = s.physics.integrator;
                let mut chosen =
                    c.integrator
                        .filter(|&i| i != own)
                        .unwrap_or(if own == Integrator::Rk4 {
                            Integrator::Euler
                        } else {
                            Integrator::Rk4
                        });
                egui::ComboBox::from_id_salt("compare-integrator")
                    .selected_text(chosen.name())
                    .show_ui(ui, |ui| {
                        for i in Integrator::ALL.into_iter().filter(|&i| i != own) {
                            ui.selectable_value(&mut chosen, i, i.name());
                        }
                    });
                c.integrator = on.then_some(chosen);
            });
            let variants = c.variants(s);
            ui.horizontal_wrapped(|ui| {
                let ok = (1..=MAX_COPIES).contains(&variants.len());
                let label = tr!("compare-start", count = variants.len());
                if ui.add_enabled(ok, egui::Button::new(label)).clicked() {
                    commands.push(Command::Compare(variants.clone()));
                }
                if lab.specimens().len() > 1 && ui.button(tr!("compare-stop")).clicked() {
                    commands.push(Command::Compare(Vec::new()));
                }
            });
            if variants.len() > MAX_COPIES {
                ui.colored_label(
                    Color32::from_rgb(255, 170, 60),
                    tr!("compare-too-many", max = MAX_COPIES),
                );
            }
            ui.horizontal(|ui| {
                ui.label(tr!("compare-ghosts"));
                ui.radio_value(
                    &mut s.view.ghosts,
                    GhostLayout::Overlaid,
                    tr!("compare-overlaid"),
                );
                ui.radio_value(
                    &mut s.view.ghosts,
                    GhostLayout::Row,
                    tr!("compare-in-a-row"),
                );
            });
            if lab.specimens().len() > 1 {
                drift_table(ui, lab);
                ui.small(tr!("compare-drift-note"));
            }
        });
}

/// Each specimen's turn-over interval, predicted and measured, and its largest E and |L| drift
/// since the start or its last disturbance.
fn drift_table(ui: &mut egui::Ui, lab: &Lab) {
    let seconds =
        |t: Option<f64>| t.map_or_else(|| "—".to_owned(), |t| format!("{} s", fixed(t, 3)));
    egui::Grid::new("compare-drift")
        .striped(true)
        .num_columns(5)
        .show(ui, |ui| {
            ui.label("");
            ui.strong(tr!("compare-turns-over"))
                .on_hover_text(tr!("compare-turns-over-hover"));
            ui.strong(tr!("compare-measured"))
                .on_hover_text(tr!("compare-measured-hover"));
            ui.strong(tr!("compare-max-energy"));
            ui.strong(tr!("compare-max-momentum"));
            ui.end_row();
            for (k, sp) in lab.specimens().iter().enumerate() {
                let name = if k == 0 {
                    RichText::new(tr!("compare-body"))
                } else {
                    let [r, g, b, _] = ghost_color(k);
                    RichText::new(sp.variant().label()).color(Color32::from_rgb(r, g, b))
                };
                ui.label(name);
                ui.label(seconds(sp.turn_over_interval()));
                ui.label(seconds(sp.history().flip_interval()));
                ui.label(sci(sp.drift().max_energy(), 1));
                ui.label(sci(sp.drift().max_l_norm(), 1));
                ui.end_row();
            }
        });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A copy always differs from the body: the lab's own choices are never compared.
    #[test]
    fn the_lab_s_own_choices_are_not_offered() {
        let choice = CompareChoice {
            sources: [true, true, true, false],
            other_model: true,
            integrator: Some(Integrator::MidpointCayley),
        };
        let mut settings = AppSettings::default();
        assert_eq!(
            choice.variants(&settings),
            [
                Variant::Source(InertiaSource::BoundingBox),
                Variant::Source(InertiaSource::PointMasses),
                Variant::Model(RotationModel::Textbook),
            ]
        );
        settings.body.source = InertiaSource::BoundingBox;
        settings.physics.model = RotationModel::Textbook;
        assert_eq!(
            choice.variants(&settings)[..2],
            [
                Variant::Source(InertiaSource::Exact),
                Variant::Source(InertiaSource::PointMasses)
            ]
        );
        assert_eq!(
            choice.variants(&settings)[2],
            Variant::Model(RotationModel::Full)
        );
    }
}
