//! The Poke and string section: how much a click changes L, and the string's stiffness, damping
//! and force cap.

use super::{Frame, Panel, number};
use crate::i18n::{sci, tr};
use crate::lab::Lab;
use crate::lab::settings::AppSettings;

/// The Poke and string section: the interaction strengths.
pub struct InteractionSection;

impl Panel for InteractionSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        interaction_section(ui, f.lab, f.settings);
    }
}

fn interaction_section(ui: &mut egui::Ui, lab: &Lab, s: &mut AppSettings) {
    egui::CollapsingHeader::new(tr!("interaction-header"))
        .id_salt("interaction")
        .default_open(false)
        .show(ui, |ui| {
            let i = &mut s.interaction;
            // Shown in percent; written back only when edited (×100 ÷ 100 need not give the same
            // number, and a changed draft is a settings command every frame).
            let mut percent = i.poke_fraction * 100.0;
            let unit = format!(" {}", tr!("interaction-poke-unit"));
            if number(
                ui,
                &tr!("interaction-poke"),
                &mut percent,
                0.0..=100.0,
                0.1,
                &unit,
            )
            .on_hover_text(tr!("interaction-poke-hover"))
            .changed()
            {
                i.poke_fraction = percent / 100.0;
            }
            let primary = lab.primary();
            let impulse = primary.poke_impulse(lab.settings());
            ui.small(tr!(
                "interaction-impulse",
                impulse = sci(impulse, 4),
                delta = sci(impulse * primary.reach(), 4),
            ));
            number(
                ui,
                &tr!("interaction-string-frequency"),
                &mut i.string_frequency,
                0.05..=60.0,
                0.05,
                " Hz",
            );
            number(
                ui,
                &tr!("interaction-string-damping"),
                &mut i.string_damping,
                0.0..=10.0,
                0.01,
                "",
            );
            number(
                ui,
                &tr!("interaction-force-cap"),
                &mut i.string_max_accel,
                0.0..=1e4,
                1.0,
                " m/s²",
            );
            let f = primary.string_max_force(lab.settings());
            ui.small(tr!("interaction-max-force", force = sci(f, 4)));
        });
}
