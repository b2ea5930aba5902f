//! The Body section: opening a file (the Path field, the dialog, a drop), the samples, the
//! loading's stage, the body's size and its mass or density.

use std::path::PathBuf;

use super::{Frame, HEADING_CHARS, Panel, PanelState, elide, number};
use crate::gui::platform::{self, DialogPurpose};
use crate::i18n::{sci, tr};
use crate::lab::loader::Stage;
use crate::lab::samples::{SAMPLE_BODIES, SAMPLES};
use crate::lab::settings::{AppSettings, InertiaSource, MassGiven};
use crate::lab::{Command, Lab};

/// The Body section: opening a file, the samples, loading, size and mass.
pub struct BodySection;

impl Panel for BodySection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        body_section(ui, f.lab, f.shared, f.commands, f.settings);
    }
}

fn body_section(
    ui: &mut egui::Ui,
    lab: &Lab,
    state: &mut PanelState,
    commands: &mut Vec<Command>,
    s: &mut AppSettings,
) {
    egui::CollapsingHeader::new(tr!("body-header"))
        .id_salt("body")
        .default_open(true)
        .show(ui, |ui| {
            // Wrapped: a row wider than the panel would widen it for good.
            ui.horizontal_wrapped(|ui| {
                if ui
                    .add_enabled(!state.dialog_open, egui::Button::new(tr!("body-open-mesh")))
                    .clicked()
                {
                    state.dialog_request = Some(DialogPurpose::OpenMesh);
                }
                ui.label(platform::drop_hint())
                    .on_hover_text(mesh_formats());
            });
            if platform::READS_PATHS {
                ui.horizontal(|ui| {
                    let l = ui.label(tr!("body-path"));
                    let edit = ui
                        .add(egui::TextEdit::singleline(&mut state.path).desired_width(150.0))
                        .labelled_by(l.id);
                    let enter = edit.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                    if (ui.button(tr!("body-load")).clicked() || enter)
                        && !state.path.trim().is_empty()
                    {
                        commands.push(Command::LoadFile(PathBuf::from(state.path.trim())));
                    }
                });
            }
            ui.horizontal_wrapped(|ui| {
                ui.label(tr!("body-samples"));
                for (label, ..) in SAMPLES {
                    if ui.small_button(label).clicked() {
                        commands.push(Command::LoadSample(label.to_owned()));
                    }
                }
            });
            ui.horizontal_wrapped(|ui| {
                ui.label(tr!("body-made-of-parts"));
                for (label, ..) in SAMPLE_BODIES {
                    if ui.small_button(label).clicked() {
                        commands.push(Command::LoadSample(label.to_owned()));
                    }
                }
            });
            if let Some(l) = lab.loading() {
                // A horizontal row does not wrap: a long path there would widen the panel for
                // good (a resizable panel keeps its widest width), so the name is shortened.
                let name = l.path.file_name().map_or_else(
                    || l.path.display().to_string(),
                    |n| n.to_string_lossy().into_owned(),
                );
                ui.horizontal(|ui| {
                    ui.spinner();
                    ui.label(elide(&name, HEADING_CHARS))
                        .on_hover_text(l.path.display().to_string());
                });
                ui.label(stage_text(l.stage));
                // A stage that measures no fraction has the spinner alone.
                if let Some(f) = l.fraction {
                    ui.add(egui::ProgressBar::new(f).show_percentage());
                }
            }
            number(
                ui,
                &tr!("body-size"),
                &mut s.body.scale,
                1e-3..=1e3,
                0.01,
                "",
            );
            if lab.primary().body().composition.is_some() {
                let m = lab.primary().properties(InertiaSource::Exact).mass;
                ui.label(tr!("body-mass-from-parts", mass = sci(m, 4)));
                ui.label(tr!("body-volume", volume = sci(lab.primary().volume(), 4)))
                    .on_hover_text(tr!("body-volume-hover"));
                return;
            }
            ui.horizontal(|ui| {
                let density = matches!(s.body.mass, MassGiven::Density(_));
                let primary = lab.primary();
                if ui.radio(density, tr!("body-density")).clicked() && !density {
                    s.body.mass = MassGiven::Density(primary.density());
                }
                if ui.radio(!density, tr!("body-mass")).clicked() && density {
                    let exact = primary.properties(InertiaSource::Exact);
                    s.body.mass = MassGiven::Mass(exact.mass);
                }
            });
            match &mut s.body.mass {
                MassGiven::Density(d) => {
                    number(ui, &tr!("body-density"), d, 1e-6..=1e6, 10.0, " kg/m³");
                }
                MassGiven::Mass(m) => {
                    number(ui, &tr!("body-mass"), m, 1e-9..=1e9, 0.01, " kg");
                }
            }
            let primary = lab.primary();
            ui.label(tr!(
                "body-volume-mass",
                volume = sci(primary.volume(), 4),
                mass = sci(primary.properties(InertiaSource::Exact).mass, 4),
            ));
        });
}

/// The mesh formats the readers take, for the drop hint's tooltip: "Meshes: OBJ (.obj), …".
fn mesh_formats() -> String {
    let formats: Vec<String> = massprops::io::MESH_FORMATS
        .iter()
        .map(|f| {
            let extensions: Vec<String> = f.extensions.iter().map(|e| format!(".{e}")).collect();
            format!("{} ({})", f.name, extensions.join(", "))
        })
        .collect();
    tr!("body-mesh-formats", formats = formats.join(", "))
}

/// Where a load is, in the user's words (the lab's `Display` stays English: the page's state
/// reports it to scripts).
fn stage_text(stage: Stage) -> String {
    match stage {
        Stage::Starting => tr!("body-stage-starting"),
        Stage::Reading => tr!("body-stage-reading"),
        Stage::Checking => tr!("body-stage-checking"),
        Stage::PickingIndex => tr!("body-stage-picking-index"),
        Stage::Robot => tr!("body-stage-robot"),
    }
}
