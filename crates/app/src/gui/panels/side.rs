//! The side panel: body and loading, mass-properties table, the inertia source, motion controls
//! and presets, interaction strengths, view toggles, diagnostics and warnings.

use super::body::BodySection;
use super::compare::CompareSection;
use super::diagnostics::DiagnosticsSection;
use super::interaction::InteractionSection;
use super::motion::MotionSection;
use super::parts::PartsSection;
use super::robot::RobotSection;
use super::table::TableSection;
use super::{Frame, HEADING_CHARS, Panel, elide};
use crate::i18n::tr;
use crate::lab::Command;

/// The side panel: the body's name over its sections, in the one list that registers them.
pub struct SidePanel {
    sections: Vec<Box<dyn Panel>>,
}

impl Default for SidePanel {
    fn default() -> Self {
        Self {
            sections: vec![
                Box::new(BodySection),
                Box::new(RobotSection),
                Box::new(TableSection),
                Box::new(MotionSection),
                Box::new(CompareSection::default()),
                Box::new(InteractionSection),
                Box::new(PartsSection::default()),
                Box::new(DiagnosticsSection),
            ],
        }
    }
}

impl SidePanel {
    /// Shows the panel contents, editing the frame's settings draft.
    pub fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        // Shortened so that the panel keeps its width whatever the file is called (egui's own
        // truncation still let the first frame's full-width text widen a resizable panel).
        let name = &f.lab.primary().body().name;
        ui.heading(elide(name, HEADING_CHARS))
            .on_hover_text(name.as_str());
        egui::ScrollArea::vertical().show(ui, |ui| {
            for section in &mut self.sections {
                section.show(ui, f);
            }
            ui.separator();
            if ui.button(tr!("side-reset-settings")).clicked() {
                f.commands.push(Command::ResetSettings);
            }
            // Tab moves the focus without scrolling: a keyboard user would tab on out of sight.
            let focused = ui
                .memory(|m| m.focused())
                .and_then(|id| ui.ctx().read_response(id));
            if let Some(r) =
                focused.filter(|r| r.gained_focus() && ui.min_rect().contains_rect(r.rect))
            {
                ui.scroll_to_rect(r.rect, None);
            }
        });
    }
}
