//! The side panel: body and loading, mass-properties table, the inertia source, motion controls
//! and presets, interaction strengths, view toggles, diagnostics and warnings.

use massprops::MassProperties;
use std::path::PathBuf;

use egui::{Color32, RichText};
use rbcore::{Integrator, Polhode, RotationModel, Stability};

use super::compare::CompareSection;
use super::diagnostics::DiagnosticsSection;
use super::parts::PartsSection;
use super::robot::RobotSection;
use super::{Frame, PanelState, Section, number};
use crate::gui::platform::{self, DialogPurpose};
use crate::lab::samples::{SAMPLE_BODIES, SAMPLES};
use crate::lab::settings::{AppSettings, InertiaSource, MassGiven};
use crate::lab::specimen::TURNING_OVER;
use crate::lab::{Command, Lab};

/// The side panel: the body's name over its sections, in the one list that registers them.
pub struct SidePanel {
    sections: Vec<Box<dyn Section>>,
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
            if ui.button("Reset settings").clicked() {
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

/// The Body section: opening a file, the samples, loading, size and mass.
struct BodySection;

impl Section for BodySection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        body_section(ui, f.lab, f.shared, f.commands, f.settings);
    }
}

/// The Mass properties section: the table of every source and the inertia the simulation uses.
struct TableSection;

impl Section for TableSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        table_section(ui, f.lab, f.settings);
    }
}

/// The Motion section: run, step, reset, the spins, the model and what the motion does.
struct MotionSection;

impl Section for MotionSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        motion_section(ui, f.lab, f.commands, f.settings);
    }
}

/// The Poke and string section: the interaction strengths.
struct InteractionSection;

impl Section for InteractionSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        interaction_section(ui, f.lab, f.settings);
    }
}

/// Longest body name shown whole in the heading (fits the default panel width).
const HEADING_CHARS: usize = 28;

/// `text` shortened to at most `max` characters by an ellipsis in the middle, keeping the start
/// and the end (where file names differ).
fn elide(text: &str, max: usize) -> String {
    let n = text.chars().count();
    if n <= max {
        return text.to_owned();
    }
    let keep = max.saturating_sub(1);
    let head: String = text.chars().take(keep - keep / 2).collect();
    let tail: String = text.chars().skip(n - keep / 2).collect();
    format!("{head}…{tail}")
}

fn body_section(
    ui: &mut egui::Ui,
    lab: &Lab,
    state: &mut PanelState,
    commands: &mut Vec<Command>,
    s: &mut AppSettings,
) {
    egui::CollapsingHeader::new("Body")
        .default_open(true)
        .show(ui, |ui| {
            // Wrapped: a row wider than the panel would widen it for good.
            ui.horizontal_wrapped(|ui| {
                if ui
                    .add_enabled(!state.dialog_open, egui::Button::new("Open mesh…"))
                    .clicked()
                {
                    state.dialog_request = Some(DialogPurpose::OpenMesh);
                }
                ui.label(platform::drop_hint())
                    .on_hover_text(inertia_io::kind::mesh_formats_hint());
            });
            if platform::READS_PATHS {
                ui.horizontal(|ui| {
                    let l = ui.label("Path");
                    let edit = ui
                        .add(egui::TextEdit::singleline(&mut state.path).desired_width(150.0))
                        .labelled_by(l.id);
                    let enter = edit.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                    if (ui.button("Load").clicked() || enter) && !state.path.trim().is_empty() {
                        commands.push(Command::LoadFile(PathBuf::from(state.path.trim())));
                    }
                });
            }
            ui.horizontal_wrapped(|ui| {
                ui.label("Samples:");
                for (label, ..) in SAMPLES {
                    if ui.small_button(label).clicked() {
                        commands.push(Command::LoadSample(label.to_owned()));
                    }
                }
            });
            ui.horizontal_wrapped(|ui| {
                ui.label("Made of parts:");
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
                ui.label(format!("{}…", l.stage));
                // A stage that measures no fraction has the spinner alone.
                if let Some(f) = l.fraction {
                    ui.add(egui::ProgressBar::new(f).show_percentage());
                }
            }
            number(ui, "Size ×", &mut s.body.scale, 1e-3..=1e3, 0.01, "");
            if lab.primary().body().composition.is_some() {
                let m = lab.primary().properties(InertiaSource::Exact).mass;
                ui.label(format!(
                    "Mass {m:.4e} kg, from the parts' materials (below)"
                ));
                ui.label(format!("Volume {:.4e} m³", lab.primary().volume()))
                    .on_hover_text("The solid parts and thin walls, less the voids.");
                return;
            }
            ui.horizontal(|ui| {
                let density = matches!(s.body.mass, MassGiven::Density(_));
                let primary = lab.primary();
                if ui.radio(density, "Density").clicked() && !density {
                    s.body.mass = MassGiven::Density(primary.density());
                }
                if ui.radio(!density, "Mass").clicked() && density {
                    let exact = primary.properties(InertiaSource::Exact);
                    s.body.mass = MassGiven::Mass(exact.mass);
                }
            });
            match &mut s.body.mass {
                MassGiven::Density(d) => {
                    number(ui, "Density", d, 1e-6..=1e6, 10.0, " kg/m³");
                }
                MassGiven::Mass(m) => {
                    number(ui, "Mass", m, 1e-9..=1e9, 0.01, " kg");
                }
            }
            let primary = lab.primary();
            ui.label(format!(
                "Volume {:.4e} m³, mass {:.4e} kg",
                primary.volume(),
                primary.properties(InertiaSource::Exact).mass
            ));
        });
}

fn fmt(x: f64) -> String {
    format!("{x:.4e}")
}

fn table_section(ui: &mut egui::Ui, lab: &Lab, s: &mut AppSettings) {
    egui::CollapsingHeader::new("Mass properties")
        .default_open(true)
        .show(ui, |ui| {
            let primary = lab.primary();
            let sources = shown_sources(primary);
            let exact = primary.properties(InertiaSource::Exact);
            let others: Vec<(&MassProperties, massprops::properties::Comparison)> = sources[1..]
                .iter()
                .map(|&src| (primary.properties(src), primary.comparison(src)))
                .collect();
            egui::Grid::new("mass-table")
                .striped(true)
                .num_columns(sources.len() + 1)
                .show(ui, |ui| {
                    ui.label("");
                    for src in &sources {
                        ui.strong(match src {
                            InertiaSource::BoundingBox => "bbox",
                            InertiaSource::PointMasses => "points",
                            other => other.label(),
                        })
                        .on_hover_text(source_meaning(*src));
                    }
                    ui.end_row();
                    ui.label("mass (kg)");
                    ui.label(fmt(exact.mass));
                    for (p, _) in &others {
                        ui.label(if p.mass == exact.mass {
                            "same".to_owned()
                        } else {
                            fmt(p.mass)
                        });
                    }
                    ui.end_row();
                    for i in 0..3 {
                        ui.label(format!("I{} (kg·m²)", i + 1))
                            .on_hover_text(format!("Principal moment of inertia about principal axis {}, moments ascending (axis 1 the least)", i + 1));
                        ui.label(fmt(exact.principal.moments[i]));
                        for (p, _) in &others {
                            ui.label(fmt(p.principal.moments[i]));
                        }
                        ui.end_row();
                    }
                    for i in 0..3 {
                        ui.label(format!("error I{}", i + 1))
                            .on_hover_text(format!("How far the approximation's moment I{} is from the exact one, in percent (red beyond 5 %)", i + 1));
                        ui.label("—");
                        for (_, c) in &others {
                            let e = c.moment_error[i] * 100.0;
                            ui.label(error_text(format!("{e:+.1} %"), e.abs() > 5.0));
                        }
                        ui.end_row();
                    }
                    for i in 0..3 {
                        ui.label(format!("axis {} angle", i + 1))
                            .on_hover_text(format!("The angle between the approximation's principal axis {} and the exact one (red beyond 5°)", i + 1));
                        ui.label("—");
                        for (_, c) in &others {
                            match c.axis_angle[i] {
                                Some(a) => {
                                    let deg = a.to_degrees();
                                    ui.label(error_text(format!("{deg:.1}°"), deg > 5.0))
                                }
                                None => ui.label("n/a"),
                            };
                        }
                        ui.end_row();
                    }
                    ui.label("CoM offset (m)").on_hover_text(
                        "How far the approximation's centre of mass is from the exact one",
                    );
                    ui.label("—");
                    for (_, c) in &others {
                        ui.label(fmt(c.com_offset));
                    }
                    ui.end_row();
                });
            // A coordinate below 1e-12 of the body's size is round-off of a zero (as in the
            // command line's table): shown as 0, not as -5.3e-19.
            let size = primary.bounding_sphere().1;
            let c = exact
                .center_of_mass
                .map(|x| if x.abs() < 1e-12 * size { 0.0 } else { x });
            ui.add(
                egui::Label::new(
                    RichText::new(format!(
                        "exact centre of mass ({:.3e}, {:.3e}, {:.3e}) m",
                        c.x, c.y, c.z
                    ))
                    .small(),
                )
                .wrap(),
            );
            ui.label(RichText::new("Simulation uses").strong());
            ui.horizontal(|ui| {
                for src in sources {
                    ui.radio_value(&mut s.body.source, src, src.label())
                        .on_hover_text(source_meaning(src));
                }
            });
            restart_on_switch(ui, s);
        });
}

/// The choice beside "Simulation uses" and "Rotation model" (one setting, shown at both).
fn restart_on_switch(ui: &mut egui::Ui, s: &mut AppSettings) {
    ui.checkbox(&mut s.physics.restart_on_switch, "Switching starts again")
        .on_hover_text(
            "A new inertia or rotation model starts the motion again from the same spin, so \
             that the runs compare fairly. Off: the motion goes on from where it is.",
        );
}

/// What each inertia source is, for the table's headers and the radio buttons.
fn source_meaning(source: InertiaSource) -> &'static str {
    match source {
        InertiaSource::Exact => {
            "Exact: the solid the mesh encloses, integrated over its volume (Mirtich's method)"
        }
        InertiaSource::BoundingBox => {
            "Bounding box (bbox): a solid box around the mesh, axis-aligned, with the same mass, \
             the usual guess of game engines"
        }
        InertiaSource::PointMasses => {
            "Points: the mass shared equally among the mesh's vertices, as if each were a point mass"
        }
        InertiaSource::Stated => "Stated: what the robot description says",
    }
}

/// The sources the body has: the stated one only for a robot link that states an inertia.
fn shown_sources(primary: &crate::lab::Specimen) -> Vec<InertiaSource> {
    InertiaSource::ALL
        .into_iter()
        .filter(|&s| s != InertiaSource::Stated || primary.body().stated.is_some())
        .collect()
}

fn error_text(text: String, large: bool) -> RichText {
    if large {
        RichText::new(text).color(Color32::from_rgb(255, 140, 90))
    } else {
        RichText::new(text)
    }
}

/// What the panel says about the flip: the interval between reversals of ω₂ predicted from the
/// current E and |L| (rbcore's exact solution) beside the one measured, or why there is none.
/// What the motion text's terms mean, shown over it.
const MOTION_TERMS: &str = "T: the period of the motion seen from the body (ω returns to where \
    it was), predicted from the energy E and |L|.\nTurns over: axis 2 swings round to point \
    the other way, and back, every T/2: the intermediate-axis (tennis-racket) flip.\nWobbles: \
    the spin axis circles a stable axis at a small angle and never turns over.\nSeparatrix: \
    the boundary between the motions about axis 1 and about axis 3, through axis 2; the closer \
    a spin to it, the longer between flips.";

/// The motion text: a flip told from a wobble, predicted, and measured once seen. `cone` is the
/// widest angle of L from the axis it circles ([`crate::lab::specimen::Specimen::cone_angle`]).
fn flip_text(
    polhode: Polhode,
    cone: f64,
    moments: &nalgebra::Vector3<f64>,
    measured: Option<f64>,
    model: RotationModel,
    torque_free: bool,
) -> String {
    let mut text = match polhode {
        Polhode::Circles {
            axis,
            period,
            separation,
        } if separation.is_infinite() => {
            let (p, q) = if axis == 2 { (1, 2) } else { (2, 3) };
            format!(
                "Axes {p} and {q} have equal moments: the body precesses about axis {}, its spin \
                 axis at {:.1}° from it, once every T = {period:.3} s, and never turns over.",
                axis + 1,
                cone.to_degrees()
            )
        }
        Polhode::Circles {
            axis,
            period,
            separation,
        } if cone >= TURNING_OVER => {
            let mut t = format!(
                "Turns over every T/2 = {:.3} s (predicted from E and |L|",
                period / 2.0
            );
            match measured {
                Some(m) => t.push_str(&format!("; measured {m:.3} s)")),
                None => t.push_str("; measured after two turns)"),
            }
            t.push_str(&format!(
                ": axis 2 swings round and back while L circles axis {}.",
                axis + 1
            ));
            if separation.abs() < 1e-3 {
                t.push_str(
                    " Near the separatrix: the closer the spin to it, the longer the interval, \
                     without bound.",
                );
            }
            t
        }
        Polhode::Circles { axis, period, .. } => format!(
            "Wobbles by ±{:.1}° about axis {} and never turns over (one wobble every T = {period:.3} s).",
            cone.to_degrees(),
            axis + 1
        ),
        Polhode::Separatrix => "On the separatrix through axis 2: the interval between flips \
                                grows without bound."
            .to_owned(),
        Polhode::Steady { axis } => match rbcore::stability(moments, axis) {
            Stability::Unstable => format!(
                "Steady spin about axis {}: unstable, the slightest disturbance (a poke) starts \
                 the flips.",
                axis + 1
            ),
            Stability::Stable => format!(
                "Steady spin about axis {}: stable, nothing flips (a poke only makes it wobble).",
                axis + 1
            ),
            Stability::Neutral => format!(
                "Steady spin about axis {}: its moment equals another's, so every axis in their \
                 plane is principal and nothing flips.",
                axis + 1
            ),
        },
        Polhode::Spherical => "All three moments are equal: every axis is principal, so the spin \
                               never moves in the body and nothing flips."
            .to_owned(),
        Polhode::AtRest => "At rest: nothing turns.".to_owned(),
    };
    if model == RotationModel::Textbook {
        text.push_str(
            " The textbook model drops ω × Iω, so this body never flips: the prediction is the \
             real body's.",
        );
    } else if !torque_free {
        text.push_str(" Damping or the string changes E and |L|: the prediction follows them.");
    }
    text
}

fn motion_section(ui: &mut egui::Ui, lab: &Lab, commands: &mut Vec<Command>, s: &mut AppSettings) {
    egui::CollapsingHeader::new("Motion")
        .default_open(true)
        .show(ui, |ui| {
            ui.horizontal(|ui| {
                super::pause_button(ui, lab, commands);
                if ui.button("Step").clicked() {
                    commands.push(Command::Step);
                }
                if ui.button("Reset").clicked() {
                    commands.push(Command::Reset);
                }
                ui.label(format!("t = {:.2} s", lab.primary().sim().time()));
            });
            ui.horizontal(|ui| {
                for axis in 0..3 {
                    if ui
                        .button(format!("Spin axis {}", axis + 1))
                        .on_hover_text("about this principal axis, plus a 2 % perturbation")
                        .clicked()
                    {
                        commands.push(Command::Preset(axis));
                    }
                }
            });
            let primary = lab.primary();
            let physics = &lab.settings().physics;
            let torque_free = physics.angular_damping == 0.0 && primary.string_view().is_none();
            let text = flip_text(
                primary.polhode(),
                primary.cone_angle(),
                &primary.sim().body().moments(),
                primary.history().flip_interval(),
                physics.model,
                torque_free,
            );
            ui.add(egui::Label::new(text).wrap())
                .on_hover_text(MOTION_TERMS);
            number(
                ui,
                "Spin rate",
                &mut s.body.spin_rate,
                0.0..=1000.0,
                0.1,
                " rad/s",
            );
            egui::ComboBox::from_label("Integrator")
                .selected_text(s.physics.integrator.name())
                .show_ui(ui, |ui| {
                    for i in Integrator::ALL {
                        ui.selectable_value(&mut s.physics.integrator, i, i.name());
                    }
                });
            egui::ComboBox::from_label("Rotation model")
                .selected_text(s.physics.model.name())
                .show_ui(ui, |ui| {
                    for m in [RotationModel::Full, RotationModel::Textbook] {
                        ui.selectable_value(&mut s.physics.model, m, m.name());
                    }
                });
            restart_on_switch(ui, s);
            number(
                ui,
                "Gravity (−y)",
                &mut s.physics.gravity,
                -100.0..=100.0,
                0.1,
                " m/s²",
            );
            number(
                ui,
                "Linear damping",
                &mut s.physics.linear_damping,
                0.0..=100.0,
                0.01,
                " 1/s",
            );
            number(
                ui,
                "Angular damping",
                &mut s.physics.angular_damping,
                0.0..=100.0,
                0.01,
                " 1/s",
            );
            number(
                ui,
                "Time scale",
                &mut s.physics.time_scale,
                0.0..=10.0,
                0.01,
                "×",
            );
            number(ui, "Time step", &mut s.physics.dt, 1e-5..=0.1, 1e-4, " s");
        });
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flip_text_tells_a_flip_from_a_wobble_predicts_and_measures() {
        let circles = Polhode::Circles {
            axis: 2,
            period: 7.101450607931697,
            separation: 5e-9,
        };
        let full = RotationModel::Full;
        let i = nalgebra::Vector3::new(1.0, 2.0, 3.0);
        let wide = 89f64.to_radians();
        let t = flip_text(circles, wide, &i, Some(3.5507), full, true);
        assert!(
            t.starts_with("Turns over every T/2 = 3.551 s") && t.contains("measured 3.551 s"),
            "{t}"
        );
        assert!(t.contains("axis 3") && t.contains("without bound"), "{t}");
        assert!(flip_text(circles, wide, &i, None, full, true).contains("after two turns"));
        // A steady spin about axis 3, nudged: the same reversal of a small ω₂ is a wobble.
        let narrow = flip_text(circles, 2.3f64.to_radians(), &i, Some(3.5), full, true);
        assert!(
            narrow.starts_with("Wobbles by ±2.3° about axis 3 and never turns over")
                && !narrow.contains("Turns over")
                && !narrow.contains("measured"),
            "{narrow}"
        );
        let top = Polhode::Circles {
            axis: 2,
            period: 4.2,
            separation: f64::INFINITY,
        };
        let equal = flip_text(
            top,
            0.7,
            &nalgebra::Vector3::new(2.0, 2.0, 3.0),
            None,
            full,
            true,
        );
        assert!(
            equal.contains("Axes 1 and 2 have equal moments") && equal.contains("never turns over"),
            "{equal}"
        );
        let textbook = flip_text(circles, wide, &i, None, RotationModel::Textbook, true);
        assert!(textbook.contains("never flips"), "{textbook}");
        assert!(flip_text(circles, wide, &i, None, full, false).contains("Damping or the string"));
        assert!(flip_text(Polhode::Spherical, 0.0, &i, None, full, true).contains("equal"));
        let steady = |axis| flip_text(Polhode::Steady { axis }, 0.0, &i, None, full, true);
        assert!(steady(1).contains("unstable"));
        assert!(steady(0).contains("stable"));
        assert!(
            flip_text(Polhode::Separatrix, 0.0, &i, None, full, true).contains("without bound")
        );
        let rod = nalgebra::Vector3::new(1.0, 3.0, 3.0);
        let neutral = flip_text(Polhode::Steady { axis: 1 }, 0.0, &rod, None, full, true);
        assert!(neutral.contains("every axis in their plane"), "{neutral}");
    }

    #[test]
    fn long_names_lose_their_middle() {
        assert_eq!(elide("T-handle", 28), "T-handle");
        let long = "scanned_turbine_blade_with_holes_final.obj";
        let short = elide(long, 28);
        assert_eq!(short.chars().count(), 28);
        assert_eq!(short, "scanned_turbin…les_final.obj");
        assert_eq!(elide("αβγδε", 3), "α…ε");
    }
}
