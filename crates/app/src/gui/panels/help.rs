//! The F1 help overlay: controls and what the views show.

use super::{Frame, Panel};
use crate::gui::view3d::overlay::AXIS_COLORS;
use crate::i18n::tr;

/// The help window, shown while the shared `help_open` is set (F1, or the Help button).
#[derive(Debug, Default)]
pub struct HelpWindow;

impl Panel for HelpWindow {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        show(ui.ctx(), &mut f.shared.help_open);
    }
}

/// Shows the help window while `open`.
fn show(ctx: &egui::Context, open: &mut bool) {
    egui::Window::new(tr!("help-title"))
        .open(open)
        .collapsible(false)
        .resizable(false)
        .default_width(460.0)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .show(ctx, |ui| {
            ui.heading(tr!("help-on-the-body"));
            egui::Grid::new("help-gestures")
                .striped(true)
                .show(ui, |ui| {
                    for (what, how) in [
                        (tr!("help-click-body"), tr!("help-click-body-does")),
                        (tr!("help-drag-body"), tr!("help-drag-body-does")),
                        (
                            tr!("help-drag-background"),
                            tr!("help-drag-background-does"),
                        ),
                        (tr!("help-pan-drag"), tr!("help-pan-drag-does")),
                        (tr!("help-wheel"), tr!("help-wheel-does")),
                        (tr!("help-frame-gesture"), tr!("help-frame-does")),
                    ] {
                        ui.strong(what);
                        ui.label(how);
                        ui.end_row();
                    }
                });
            ui.heading(tr!("help-keys"));
            egui::Grid::new("help-keys").striped(true).show(ui, |ui| {
                for (key, what) in [
                    (tr!("help-key-space"), tr!("help-key-space-does")),
                    ("S".to_owned(), tr!("help-key-s-does")),
                    ("R".to_owned(), tr!("help-key-r-does")),
                    ("1 2 3".to_owned(), tr!("help-key-axes-does")),
                    (tr!("help-key-arrows"), tr!("help-key-arrows-does")),
                    ("P".to_owned(), tr!("help-key-p-does")),
                    ("F".to_owned(), tr!("help-frame-does")),
                    ("L".to_owned(), tr!("help-key-l-does")),
                    (tr!("help-key-enter"), tr!("help-key-enter-does")),
                    ("F1".to_owned(), tr!("help-key-f1-does")),
                    (tr!("help-key-escape"), tr!("help-key-escape-does")),
                    (tr!("help-key-tab"), tr!("help-key-tab-does")),
                ] {
                    ui.strong(key);
                    ui.label(what);
                    ui.end_row();
                }
            });
            ui.heading(tr!("help-what-you-see"));
            ui.horizontal_wrapped(|ui| {
                ui.label(tr!("help-principal-axes"));
                for (i, c) in AXIS_COLORS.iter().enumerate() {
                    ui.colored_label(*c, format!("{}", i + 1));
                }
                ui.label(tr!("help-arrows-in-world"));
            });
            ui.label(tr!("help-axis-2-unstable"));
            ui.label(tr!("help-sphere-poinsot-compare"));
        });
}
