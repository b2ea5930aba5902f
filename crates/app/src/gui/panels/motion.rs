//! The Motion section: run, pause and step, the preset spins, the motion text (a flip told from
//! a wobble, predicted and measured), the motion baked into a file, the rotation model,
//! integrator and time step.

use std::path::PathBuf;

use rbcore::{Integrator, Polhode, RotationModel, Stability};

use super::{Frame, Panel, PanelState, number, restart_on_switch};
use crate::gui::platform::DialogPurpose;
use crate::i18n::{fixed, tr};
use crate::lab::settings::{AppSettings, model_words};
use crate::lab::specimen::TURNING_OVER;
use crate::lab::{Command, Lab, PRIMARY};

/// The Motion section: run, step, reset, the spins, the model and what the motion does.
pub struct MotionSection;

impl Panel for MotionSection {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        motion_section(ui, f.lab, f.commands, f.settings, f.shared);
    }
}

/// What the motion text's terms mean, shown over it: a line a term.
fn motion_terms() -> String {
    [
        tr!("motion-terms-period"),
        tr!("motion-terms-turns-over"),
        tr!("motion-terms-wobbles"),
        tr!("motion-terms-separatrix"),
    ]
    .join("\n")
}

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
            tr!(
                "motion-equal-moments",
                p = p,
                q = q,
                axis = axis + 1,
                cone = fixed(cone.to_degrees(), 1),
                period = fixed(period, 3),
            )
        }
        Polhode::Circles {
            axis,
            period,
            separation,
        } if cone >= TURNING_OVER => {
            let half = fixed(period / 2.0, 3);
            let mut t = match measured {
                Some(m) => tr!(
                    "motion-turns-over-measured",
                    half = half,
                    measured = fixed(m, 3),
                    axis = axis + 1,
                ),
                None => tr!("motion-turns-over", half = half, axis = axis + 1),
            };
            if separation.abs() < 1e-3 {
                t.push(' ');
                t.push_str(&tr!("motion-near-separatrix"));
            }
            t
        }
        Polhode::Circles { axis, period, .. } => tr!(
            "motion-wobbles",
            cone = fixed(cone.to_degrees(), 1),
            axis = axis + 1,
            period = fixed(period, 3),
        ),
        Polhode::Separatrix => tr!("motion-separatrix"),
        Polhode::Steady { axis } => match rbcore::stability(moments, axis) {
            Stability::Unstable => tr!("motion-steady-unstable", axis = axis + 1),
            Stability::Stable => tr!("motion-steady-stable", axis = axis + 1),
            Stability::Neutral => tr!("motion-steady-neutral", axis = axis + 1),
        },
        Polhode::Spherical => tr!("motion-spherical"),
        Polhode::AtRest => tr!("motion-at-rest"),
    };
    if model == RotationModel::Textbook {
        text.push(' ');
        text.push_str(&tr!("motion-textbook-note"));
    } else if !torque_free {
        text.push(' ');
        text.push_str(&tr!("motion-torque-note"));
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
    egui::CollapsingHeader::new(tr!("motion-header"))
        .id_salt("motion")
        .default_open(true)
        .show(ui, |ui| {
            ui.horizontal(|ui| {
                super::pause_button(ui, lab, commands);
                if ui.button(tr!("motion-step")).clicked() {
                    commands.push(Command::Step);
                }
                if ui.button(tr!("motion-reset")).clicked() {
                    commands.push(Command::Reset);
                }
                ui.label(format!("t = {} s", fixed(lab.primary().sim().time(), 2)));
            });
            ui.horizontal(|ui| {
                for axis in 0..3 {
                    if ui
                        .button(tr!("motion-spin-axis", axis = axis + 1))
                        .on_hover_text(tr!("motion-spin-axis-hover"))
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
                .on_hover_text(motion_terms());
            motion_export(ui, shared, commands);
            number(
                ui,
                &tr!("motion-spin-rate"),
                &mut s.body.spin_rate,
                0.0..=1000.0,
                0.1,
                &format!(" {}", tr!("motion-unit-rad-per-second")),
            );
            // A combo box's label may be its id: all it keeps is whether its list is open, and
            // choosing a language elsewhere closes it.
            egui::ComboBox::from_label(tr!("motion-integrator"))
                .selected_text(s.physics.integrator.name())
                .show_ui(ui, |ui| {
                    for i in Integrator::ALL {
                        ui.selectable_value(&mut s.physics.integrator, i, i.name());
                    }
                });
            egui::ComboBox::from_label(tr!("motion-rotation-model"))
                .selected_text(model_words(s.physics.model))
                .show_ui(ui, |ui| {
                    for m in [RotationModel::Full, RotationModel::Textbook] {
                        ui.selectable_value(&mut s.physics.model, m, model_words(m));
                    }
                });
            restart_on_switch(ui, s);
            number(
                ui,
                &tr!("motion-gravity"),
                &mut s.physics.gravity,
                -100.0..=100.0,
                0.1,
                " m/s²",
            );
            number(
                ui,
                &tr!("motion-linear-damping"),
                &mut s.physics.linear_damping,
                0.0..=100.0,
                0.01,
                " 1/s",
            );
            number(
                ui,
                &tr!("motion-angular-damping"),
                &mut s.physics.angular_damping,
                0.0..=100.0,
                0.01,
                " 1/s",
            );
            number(
                ui,
                &tr!("motion-time-scale"),
                &mut s.physics.time_scale,
                0.0..=10.0,
                0.01,
                "×",
            );
            number(
                ui,
                &tr!("motion-time-step"),
                &mut s.physics.dt,
                1e-5..=0.1,
                1e-4,
                " s",
            );
        });
}

/// "Export motion" to the path typed (or chosen with "…"), with how many seconds and keyframes
/// a second it bakes.
fn motion_export(ui: &mut egui::Ui, state: &mut PanelState, commands: &mut Vec<Command>) {
    ui.horizontal(|ui| {
        let export = ui
            .button(tr!("motion-export"))
            .on_hover_text(tr!("motion-export-hover"));
        if export.clicked() && !state.motion_path.trim().is_empty() {
            commands.push(Command::ExportMotion {
                specimen: PRIMARY,
                path: PathBuf::from(state.motion_path.trim()),
                seconds: state.motion_seconds,
                fps: state.motion_fps,
            });
        }
        ui.add(egui::TextEdit::singleline(&mut state.motion_path).desired_width(110.0))
            .on_hover_text(tr!("motion-export-file-hover"))
            .labelled_by(export.id);
        if ui
            .add_enabled(!state.dialog_open, egui::Button::new("…"))
            .on_hover_text(tr!("motion-export-choose-hover"))
            .clicked()
        {
            state.dialog_request = Some(DialogPurpose::SaveMotion);
        }
    });
    number(
        ui,
        &tr!("motion-seconds-baked"),
        &mut state.motion_seconds,
        0.1..=600.0,
        0.5,
        " s",
    );
    number(
        ui,
        &tr!("motion-keyframes"),
        &mut state.motion_fps,
        1.0..=240.0,
        1.0,
        &format!(" {}", tr!("motion-unit-fps")),
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
