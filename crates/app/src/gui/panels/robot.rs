//! The Robot section: a loaded URDF, MJCF or SDFormat description's links, worst finding first, each with
//! its findings; choosing one makes it the body (its stated inertia then a source of its own),
//! and "Whole robot" shows every link at the zero pose with its ellipsoids.

use egui::{Color32, RichText};

use super::{Frame, Panel};
use crate::i18n::{localize, tr};
use crate::lab::{Command, Lab};
use inertia_io::report::findings::{finding_text, num};
use robot::GeometryKind;

/// Colour of a finding that proves the stated inertia impossible, and of the others.
const PROOF: Color32 = Color32::from_rgb(255, 120, 90);
const OTHER: Color32 = Color32::from_rgb(240, 200, 110);

/// The Robot section, shown when a robot description is loaded.
#[derive(Debug, Default)]
pub struct RobotSection;

impl Panel for RobotSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        show(ui, f.lab, f.commands);
    }
}

fn show(ui: &mut egui::Ui, lab: &Lab, commands: &mut Vec<Command>) {
    let Some(model) = lab.robot() else {
        return;
    };
    let robot = &model.robot;
    let flagged = model.audit.links.iter().filter(|l| l.flagged()).count();
    egui::CollapsingHeader::new(tr!("robot-header"))
        .id_salt("robot")
        .default_open(true)
        .show(ui, |ui| {
            ui.add(
                egui::Label::new(tr!(
                    "robot-summary",
                    name = &robot.name,
                    format = robot.format.name().to_uppercase(),
                    links = robot.links.len(),
                    flagged = flagged,
                ))
                .wrap(),
            );
            if ui
                .selectable_label(model.shown.is_none(), tr!("robot-whole"))
                .clicked()
            {
                commands.push(Command::ShowLink(None));
            }
            egui::ScrollArea::vertical()
                .id_salt("robot-links")
                .max_height(180.0)
                .show(ui, |ui| {
                    for l in model.audit.worst_first() {
                        let link = &robot.links[l.link];
                        let mut codes: Vec<&str> = l.findings.iter().map(|f| f.code()).collect();
                        codes.dedup();
                        let mass = l.stated.as_ref().map_or_else(
                            || tr!("robot-no-inertial"),
                            |p| format!("{} kg", localize(num(p.mass))),
                        );
                        let text = format!("{}  {mass}  {}", link.name, codes.join(", "));
                        let color = match l.worst() {
                            0 => PROOF,
                            1..=6 => OTHER,
                            _ => ui.visuals().text_color(),
                        };
                        let chosen = model.shown == Some(l.link);
                        if ui
                            .selectable_label(chosen, RichText::new(text).color(color))
                            .clicked()
                        {
                            commands.push(Command::ShowLink(Some(l.link)));
                        }
                    }
                });
            if let Some(i) = model.shown {
                let l = &model.audit.links[i];
                ui.separator();
                ui.strong(tr!("robot-link", name = &robot.links[i].name));
                if let (Some(s), Ok(c)) = (&l.stated, &l.computed) {
                    let m = |p: &massprops::MassProperties| {
                        let v = p.principal.moments;
                        localize(format!("{} {} {}", num(v.x), num(v.y), num(v.z)))
                    };
                    ui.label(tr!("robot-stated-moments", moments = m(s)));
                    ui.label(tr!("robot-computed-moments", moments = m(&c.properties)));
                }
                for f in &l.findings {
                    let color = if f.severity() == 0 { PROOF } else { OTHER };
                    // The findings' sentences are the audit library's, in English.
                    ui.add(
                        egui::Label::new(
                            RichText::new(finding_text(f, GeometryKind::Collision.name(), |w| {
                                crate::gui::warnings::warning_text(w, &[])
                            }))
                            .small()
                            .color(color),
                        )
                        .wrap(),
                    );
                }
            }
        });
}
