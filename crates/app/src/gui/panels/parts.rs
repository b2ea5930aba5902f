//! The Parts section: a body made of parts, each with its colour, mass and share of the principal
//! moments; the selected part's material (preset, density or mass), void, thin wall and
//! placement, edited live (the motion goes on with p and L kept); adding a mesh as a part,
//! splitting a mesh into its parts, and saving the body as a body file.

use std::path::PathBuf;

use egui::{Color32, RichText};
use massprops::materials::MATERIALS;
use massprops::{MaterialEntry, PartEntry};

use super::{Frame, Panel, PanelState, number};
use crate::gui::platform::{self, DialogPurpose};
use crate::gui::view3d::part_color;
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
        Some(c) => format!("Parts ({})", c.parts.len()),
        None => "Parts".to_owned(),
    };
    egui::CollapsingHeader::new(title)
        .default_open(composition.is_some())
        .show(ui, |ui| {
            let Some(c) = composition else {
                ui.label(
                    "One mesh at one density. Split it into its parts (its objects, groups or \
                     separate pieces) to give each its own material, or add a mesh as a part.",
                );
                ui.horizontal_wrapped(|ui| {
                    if ui.button("Split into parts").clicked() {
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
                ui.label("part");
                ui.label("mass (kg)");
                ui.label("% of I1 I2 I3");
                ui.end_row();
                for (k, part) in c.parts.iter().enumerate() {
                    let [r, g, b] = part_color(k);
                    let (rect, _) =
                        ui.allocate_exact_size(egui::vec2(12.0, 12.0), egui::Sense::hover());
                    ui.painter()
                        .rect_filled(rect, 2.0, Color32::from_rgb(r, g, b));
                    let selected = state.selected_part == Some(k);
                    let mut name = part.entry.name.clone();
                    if part.entry.void {
                        name.push_str(" (void)");
                    }
                    if ui.selectable_label(selected, name).clicked() {
                        state.selected_part = if selected { None } else { Some(k) };
                    }
                    ui.label(format!("{:.4}", c.masses[k]));
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
                ui.small("Click a part to edit it.");
            }
            ui.separator();
            ui.horizontal_wrapped(|ui| add_part_buttons(ui, state, commands));
            ui.horizontal(|ui| {
                let l = ui.label("Save as");
                ui.add(egui::TextEdit::singleline(body_path).desired_width(130.0))
                    .labelled_by(l.id);
                if ui.button("Save").clicked() && !body_path.trim().is_empty() {
                    commands.push(Command::SaveBody(PathBuf::from(body_path.trim())));
                }
                if ui
                    .add_enabled(!state.dialog_open, egui::Button::new("…"))
                    .on_hover_text("Choose where to save the body file")
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
        .add_enabled(!state.dialog_open, egui::Button::new("Add part…"))
        .clicked()
    {
        state.dialog_request = Some(DialogPurpose::AddPart);
    }
    let path = state.path.trim();
    if platform::READS_PATHS
        && !path.is_empty()
        && ui
            .button("Add the Path's mesh")
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
    ui.label(RichText::new(format!("Part “{}”", entry.name)).strong());
    ui.add_enabled(can_hide, egui::Checkbox::new(&mut visible, "Visible"))
        .on_disabled_hover_text("the only part shown");
    let choice = match &entry.material {
        MaterialEntry::Preset(name) => MATERIALS
            .iter()
            .position(|m| m.name == name.to_ascii_lowercase())
            .map_or(Choice::Density, Choice::Preset),
        MaterialEntry::Density(_) => Choice::Density,
        MaterialEntry::Mass(_) => Choice::Mass,
    };
    let label = |c: Choice| match c {
        Choice::Preset(i) => format!("{} ({} kg/m³)", MATERIALS[i].name, MATERIALS[i].density),
        Choice::Density => "density".to_owned(),
        Choice::Mass => "mass".to_owned(),
    };
    let mut chosen = choice;
    egui::ComboBox::from_label("Material")
        .selected_text(label(choice))
        .show_ui(ui, |ui| {
            for i in 0..MATERIALS.len() {
                ui.selectable_value(&mut chosen, Choice::Preset(i), label(Choice::Preset(i)));
            }
            ui.selectable_value(&mut chosen, Choice::Density, "density");
            if !entry.void && entry.thin_wall.is_none() {
                ui.selectable_value(&mut chosen, Choice::Mass, "mass");
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
            number(ui, "Density", d, 1e-3..=1e6, 10.0, " kg/m³");
        }
        MaterialEntry::Mass(m) => {
            number(ui, "Part mass", m, 1e-9..=1e9, 0.01, " kg");
        }
        MaterialEntry::Preset(_) => {}
    }
    let can_void = !matches!(entry.material, MaterialEntry::Mass(_)) && entry.thin_wall.is_none();
    ui.add_enabled(
        can_void,
        egui::Checkbox::new(&mut entry.void, "Void (removes material)"),
    );
    let mut wall = entry.thin_wall.is_some();
    let can_wall = !entry.void && !matches!(entry.material, MaterialEntry::Mass(_));
    ui.horizontal(|ui| {
        ui.add_enabled(can_wall, egui::Checkbox::new(&mut wall, "Thin wall"));
        if wall {
            let mut mm = entry.thin_wall.unwrap_or(0.002) * 1000.0;
            let l = ui.label("thickness");
            ui.add(
                egui::DragValue::new(&mut mm)
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
    ui.label("Placement (metres; rotation first, about the mesh origin):");
    ui.horizontal(|ui| {
        for (axis, value) in ["x", "y", "z"].iter().zip(entry.translation.iter_mut()) {
            let l = ui.label(*axis);
            ui.add(egui::DragValue::new(value).speed(0.001).max_decimals(4))
                .labelled_by(l.id);
        }
    });
    let (mut axis, mut degrees) = entry.rotation.unwrap_or(([0.0, 0.0, 1.0], 0.0));
    ui.horizontal(|ui| {
        let l = ui.label("turn");
        ui.add(
            egui::DragValue::new(&mut degrees)
                .speed(1.0)
                .suffix("°")
                .max_decimals(2),
        )
        .labelled_by(l.id);
        ui.label("about");
        for (name, value) in ["x", "y", "z"].iter().zip(axis.iter_mut()) {
            let l = ui.label(*name);
            ui.add(egui::DragValue::new(value).speed(0.01).max_decimals(3))
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
    if ui.button("Remove part").clicked() {
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
