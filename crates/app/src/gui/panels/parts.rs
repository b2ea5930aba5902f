//! The Parts section: a body made of parts, each with its colour, mass and share of the principal
//! moments; the selected part's material (preset, density or mass), void, thin wall and
//! placement, edited live (the motion goes on with p and L kept); adding a mesh as a part,
//! splitting a mesh into its parts, and saving the body as a body file.

use std::path::PathBuf;

use egui::{Color32, RichText};
use massprops::materials::MATERIALS;
use massprops::{MaterialEntry, PartEntry};

use super::{Frame, Panel, PanelState, localized, number};
use crate::gui::platform::{self, DialogPurpose};
use crate::gui::view3d::part_color;
use crate::i18n::{fixed, localize, tr};
use crate::lab::{Command, Lab};

/// The Parts section: where "Save" writes the body file is its own state.
#[derive(Debug)]
pub struct PartsSection {
    body_path: String,
}

impl Default for PartsSection {
    fn default() -> Self {
        Self {
            body_path: "body.toml".to_owned(),
        }
    }
}

impl Panel for PartsSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        show(ui, f.lab, f.shared, &mut self.body_path, f.commands);
    }
}

fn show(
    ui: &mut egui::Ui,
    lab: &Lab,
    state: &mut PanelState,
    body_path: &mut String,
    commands: &mut Vec<Command>,
) {
    let body = lab.primary().body();
    let composition = body.composition.as_ref();
    let title = match composition {
        Some(c) => tr!("parts-header-count", count = c.parts.len()),
        None => tr!("parts-header"),
    };
    egui::CollapsingHeader::new(title)
        // A new number of parts is a new header (opened again), as when the title was its id;
        // the language is not.
        .id_salt(("parts", composition.map(|c| c.parts.len())))
        .default_open(composition.is_some())
        .show(ui, |ui| {
            let Some(c) = composition else {
                ui.label(tr!("parts-one-mesh"));
                ui.horizontal_wrapped(|ui| {
                    if ui.button(tr!("parts-split")).clicked() {
                        commands.push(Command::SplitIntoParts);
                    }
                    add_part_buttons(ui, state, commands);
                });
                return;
            };
            if state.selected_part.is_some_and(|i| i >= c.parts.len()) {
                state.selected_part = None;
            }
            egui::Grid::new("parts").striped(true).show(ui, |ui| {
                ui.label("");
                ui.label(tr!("parts-column-part"));
                ui.label(tr!("parts-column-mass"));
                ui.label(tr!("parts-column-shares"));
                ui.end_row();
                for (k, part) in c.parts.iter().enumerate() {
                    let [r, g, b] = part_color(k);
                    let (rect, _) =
                        ui.allocate_exact_size(egui::vec2(12.0, 12.0), egui::Sense::hover());
                    ui.painter()
                        .rect_filled(rect, 2.0, Color32::from_rgb(r, g, b));
                    let selected = state.selected_part == Some(k);
                    let name = if part.entry.void {
                        tr!("parts-void-name", name = &part.entry.name)
                    } else {
                        part.entry.name.clone()
                    };
                    if ui.selectable_label(selected, name).clicked() {
                        state.selected_part = if selected { None } else { Some(k) };
                    }
                    ui.label(fixed(c.masses[k], 4));
                    let s = c.shares[k] * 100.0;
                    ui.label(format!("{:.0} {:.0} {:.0}", s.x, s.y, s.z));
                    ui.end_row();
                }
            });
            if let Some(k) = state.selected_part {
                ui.separator();
                // The last part shown stays shown: a body must have something to click.
                let shown = c.parts.iter().filter(|p| p.visible).count();
                let can_hide = shown > 1 || !c.parts[k].visible;
                editor(ui, k, &c.parts[k], can_hide, commands);
            } else {
                ui.small(tr!("parts-click-hint"));
            }
            ui.separator();
            ui.horizontal_wrapped(|ui| add_part_buttons(ui, state, commands));
            ui.horizontal(|ui| {
                let l = ui.label(tr!("parts-save-as"));
                ui.add(egui::TextEdit::singleline(body_path).desired_width(130.0))
                    .labelled_by(l.id);
                if ui.button(tr!("parts-save")).clicked() && !body_path.trim().is_empty() {
                    commands.push(Command::SaveBody(PathBuf::from(body_path.trim())));
                }
                if ui
                    .add_enabled(!state.dialog_open, egui::Button::new("…"))
                    .on_hover_text(tr!("parts-save-choose-hover"))
                    .clicked()
                {
                    state.dialog_request = Some(DialogPurpose::SaveBody);
                }
            });
        });
}

/// "Add part…" (a dialog) and adding the mesh named in the Path field.
fn add_part_buttons(ui: &mut egui::Ui, state: &mut PanelState, commands: &mut Vec<Command>) {
    if ui
        .add_enabled(!state.dialog_open, egui::Button::new(tr!("parts-add")))
        .clicked()
    {
        state.dialog_request = Some(DialogPurpose::AddPart);
    }
    let path = state.path.trim();
    if platform::READS_PATHS
        && !path.is_empty()
        && ui
            .button(tr!("parts-add-path"))
            .on_hover_text(path.to_owned())
            .clicked()
    {
        commands.push(Command::AddPart(PathBuf::from(path)));
    }
}

/// What a part's material is chosen as.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Choice {
    Preset(usize),
    Density,
    Mass,
}

/// The selected part's settings; any change becomes one [`Command::EditPart`].
fn editor(
    ui: &mut egui::Ui,
    index: usize,
    part: &crate::lab::parts::PartModel,
    can_hide: bool,
    commands: &mut Vec<Command>,
) {
    let mut entry: PartEntry = part.entry.clone();
    let mut visible = part.visible;
    ui.label(RichText::new(tr!("parts-part-title", name = &entry.name)).strong());
    ui.add_enabled(
        can_hide,
        egui::Checkbox::new(&mut visible, tr!("parts-visible")),
    )
    .on_disabled_hover_text(tr!("parts-visible-disabled"));
    let choice = match &entry.material {
        MaterialEntry::Preset(name) => MATERIALS
            .iter()
            .position(|m| m.name == name.to_ascii_lowercase())
            .map_or(Choice::Density, Choice::Preset),
        MaterialEntry::Density(_) => Choice::Density,
        MaterialEntry::Mass(_) => Choice::Mass,
    };
    // A preset's name is the body file's word for it (`material = "steel"`), kept as written.
    let label = |c: Choice| match c {
        Choice::Preset(i) => format!(
            "{} ({} kg/m³)",
            MATERIALS[i].name,
            localize(MATERIALS[i].density.to_string())
        ),
        Choice::Density => tr!("parts-choice-density"),
        Choice::Mass => tr!("parts-choice-mass"),
    };
    let mut chosen = choice;
    // The label may be the id: a combo box keeps only whether its list is open.
    egui::ComboBox::from_label(tr!("parts-material"))
        .selected_text(label(choice))
        .show_ui(ui, |ui| {
            for i in 0..MATERIALS.len() {
                ui.selectable_value(&mut chosen, Choice::Preset(i), label(Choice::Preset(i)));
            }
            ui.selectable_value(&mut chosen, Choice::Density, label(Choice::Density));
            if !entry.void && entry.thin_wall.is_none() {
                ui.selectable_value(&mut chosen, Choice::Mass, label(Choice::Mass));
            }
        });
    if chosen != choice {
        let density = part.density().unwrap_or(1000.0);
        entry.material = match chosen {
            Choice::Preset(i) => MaterialEntry::Preset(MATERIALS[i].name.to_owned()),
            Choice::Density => MaterialEntry::Density(density),
            Choice::Mass => MaterialEntry::Mass(part.mass().map_or(1.0, |m| m.mass.abs())),
        };
    }
    match &mut entry.material {
        MaterialEntry::Density(d) => {
            number(ui, &tr!("parts-density"), d, 1e-3..=1e6, 10.0, " kg/m³");
        }
        MaterialEntry::Mass(m) => {
            number(ui, &tr!("parts-part-mass"), m, 1e-9..=1e9, 0.01, " kg");
        }
        MaterialEntry::Preset(_) => {}
    }
    let can_void = !matches!(entry.material, MaterialEntry::Mass(_)) && entry.thin_wall.is_none();
    ui.add_enabled(
        can_void,
        egui::Checkbox::new(&mut entry.void, tr!("parts-void")),
    );
    let mut wall = entry.thin_wall.is_some();
    let can_wall = !entry.void && !matches!(entry.material, MaterialEntry::Mass(_));
    ui.horizontal(|ui| {
        ui.add_enabled(
            can_wall,
            egui::Checkbox::new(&mut wall, tr!("parts-thin-wall")),
        );
        if wall {
            let mut mm = entry.thin_wall.unwrap_or(0.002) * 1000.0;
            let l = ui.label(tr!("parts-thickness"));
            ui.add(
                localized(egui::DragValue::new(&mut mm))
                    .range(1e-3..=1e3)
                    .speed(0.1)
                    .suffix(" mm"),
            )
            .labelled_by(l.id);
            entry.thin_wall = Some(mm / 1000.0);
        } else {
            entry.thin_wall = None;
        }
    });
    ui.label(tr!("parts-placement"));
    ui.horizontal(|ui| {
        for (axis, value) in ["x", "y", "z"].iter().zip(entry.translation.iter_mut()) {
            let l = ui.label(*axis);
            ui.add(
                localized(egui::DragValue::new(value))
                    .speed(0.001)
                    .max_decimals(4),
            )
            .labelled_by(l.id);
        }
    });
    let (mut axis, mut degrees) = entry.rotation.unwrap_or(([0.0, 0.0, 1.0], 0.0));
    ui.horizontal(|ui| {
        let l = ui.label(tr!("parts-turn"));
        ui.add(
            localized(egui::DragValue::new(&mut degrees))
                .speed(1.0)
                .suffix("°")
                .max_decimals(2),
        )
        .labelled_by(l.id);
        ui.label(tr!("parts-about"));
        for (name, value) in ["x", "y", "z"].iter().zip(axis.iter_mut()) {
            let l = ui.label(*name);
            ui.add(
                localized(egui::DragValue::new(value))
                    .speed(0.01)
                    .max_decimals(3),
            )
            .labelled_by(l.id);
        }
    });
    // An axis of zeros is no axis: the last good one stays. No turn stays written as none.
    if axis.iter().any(|&c| c != 0.0) {
        let turned = Some((axis, degrees));
        let untouched = entry.rotation.is_none() && turned == Some(([0.0, 0.0, 1.0], 0.0));
        if !untouched {
            entry.rotation = turned;
        }
    }
    if entry != part.entry || visible != part.visible {
        commands.push(Command::EditPart {
            index,
            entry: Box::new(entry),
            visible,
        });
    }
    if ui.button(tr!("parts-remove")).clicked() {
        commands.push(Command::RemovePart(index));
    }
    for w in part.warnings() {
        ui.small(
            RichText::new(format!(
                "{}: {}",
                crate::gui::warnings::title(w),
                crate::gui::warnings::effect(w).unwrap_or_default()
            ))
            .color(Color32::YELLOW),
        );
    }
}
