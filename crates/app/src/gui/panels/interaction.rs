//! The Poke and string section: how much a click changes L, and the string's stiffness, damping
//! and force cap.

use super::{Frame, Panel, number};
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
    egui::CollapsingHeader::new("Poke and string")
        .default_open(false)
        .show(ui, |ui| {
            let i = &mut s.interaction;
            // Shown in percent; written back only when edited (×100 ÷ 100 need not give the same
            // number, and a changed draft is a settings command every frame).
            let mut percent = i.poke_fraction * 100.0;
            if number(ui, "Poke", &mut percent, 0.0..=100.0, 0.1, " % of |L|")
                .on_hover_text(
                    "How much a click changes the angular momentum L, at most: a click at the \
                     point farthest from the centre of mass, across it. Small, so that a stable \
                     spin stays stable; large enough to start a tumble from an unstable one.",
                )
                .changed()
            {
                i.poke_fraction = percent / 100.0;
            }
            let primary = lab.primary();
            let impulse = primary.poke_impulse(lab.settings());
            ui.small(format!(
                "J = {impulse:.4e} N·s, |ΔL| up to {:.4e} kg m²/s",
                impulse * primary.reach()
            ));
            number(
                ui,
                "String frequency",
                &mut i.string_frequency,
                0.05..=60.0,
                0.05,
                " Hz",
            );
            number(
                ui,
                "String damping ratio",
                &mut i.string_damping,
                0.0..=10.0,
                0.01,
                "",
            );
            number(
                ui,
                "Force cap F/m",
                &mut i.string_max_accel,
                0.0..=1e4,
                1.0,
                " m/s²",
            );
            let f = primary.string_max_force(lab.settings());
            ui.small(format!("F max = {f:.4e} N"));
        });
}
