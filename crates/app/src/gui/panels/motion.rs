//! The Motion section: run, pause and step, the preset spins, the motion text (a flip told from
//! a wobble, predicted and measured), the motion baked into a file, the rotation model,
//! integrator and time step.

use std::path::PathBuf;

use rbcore::{Integrator, Polhode, RotationModel, Stability};

use super::{Frame, Panel, PanelState, number, restart_on_switch};
use crate::gui::platform::DialogPurpose;
use crate::lab::settings::AppSettings;
use crate::lab::specimen::TURNING_OVER;
use crate::lab::{Command, Lab, PRIMARY};

/// The Motion section: run, step, reset, the spins, the model and what the motion does.
pub struct MotionSection;

impl Panel for MotionSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        motion_section(ui, f.lab, f.commands, f.settings, f.shared);
    }
}

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

fn motion_section(
    ui: &mut egui::Ui,
    lab: &Lab,
    commands: &mut Vec<Command>,
    s: &mut AppSettings,
    shared: &mut PanelState,
) {
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
            motion_export(ui, shared, commands);
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

/// "Export motion" to the path typed (or chosen with "…"), with how many seconds and keyframes
/// a second it bakes.
fn motion_export(ui: &mut egui::Ui, state: &mut PanelState, commands: &mut Vec<Command>) {
    ui.horizontal(|ui| {
        let hint = "Bake the motion from now on into a glTF (.glb) or USD (.usda) file with the \
                    mesh: keyframes of this simulation, for Blender, viewers and engines.";
        let export = ui.button("Export motion").on_hover_text(hint);
        if export.clicked() && !state.motion_path.trim().is_empty() {
            commands.push(Command::ExportMotion {
                specimen: PRIMARY,
                path: PathBuf::from(state.motion_path.trim()),
                seconds: state.motion_seconds,
                fps: state.motion_fps,
            });
        }
        ui.add(egui::TextEdit::singleline(&mut state.motion_path).desired_width(110.0))
            .on_hover_text("the file: .glb or .usda")
            .labelled_by(export.id);
        if ui
            .add_enabled(!state.dialog_open, egui::Button::new("…"))
            .on_hover_text("choose where to save")
            .clicked()
        {
            state.dialog_request = Some(DialogPurpose::SaveMotion);
        }
    });
    number(
        ui,
        "Seconds baked",
        &mut state.motion_seconds,
        0.1..=600.0,
        0.5,
        " s",
    );
    number(
        ui,
        "Keyframes a second",
        &mut state.motion_fps,
        1.0..=240.0,
        1.0,
        " fps",
    );
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
}
