//! The Lessons panel, beside the 3D view: the built-in lessons with the progress kept for each, and the lesson
//! open: its goal, the step's text and the view it needs, the prediction to commit to, the
//! checks as the lab evaluates them, and the explanation once they hold.

use super::{Frame, Panel};
use crate::lab::Command;
use crate::lab::lessons::{self, LessonRun, LessonSource};

/// The Lessons panel (the top bar's Lessons button shows it; an open lesson keeps it shown).
#[derive(Default)]
pub struct LessonsPanel {
    /// The choice selected for the step's prediction, before it is committed.
    choice: Option<usize>,
}

impl Panel for LessonsPanel {
    fn show(&mut self, ui: &mut egui::Ui, f: &mut Frame<'_>) {
        ui.heading("Lessons");
        egui::ScrollArea::vertical().show(ui, |ui| match f.lab.lesson() {
            Some(run) => self.lesson(ui, run, f.commands),
            None => list(ui, f),
        });
    }
}

/// The built-in lessons, each a button with its progress.
fn list(ui: &mut egui::Ui, f: &mut Frame<'_>) {
    for (k, lesson) in lessons::built_in().iter().enumerate() {
        let done = f
            .lab
            .lesson_progress()
            .get(&lesson.id)
            .copied()
            .unwrap_or(0);
        let steps = lesson.steps.len();
        // Words, not a check mark: egui's default fonts have no ✔.
        let mark = if done >= steps {
            " (done)".to_owned()
        } else if done > 0 {
            format!(" ({done}/{steps})")
        } else {
            String::new()
        };
        if ui
            .button(format!("{}. {}{mark}", k + 1, lesson.title))
            .on_hover_text(lesson.goal.as_str())
            .clicked()
        {
            f.commands.push(Command::OpenLesson(LessonSource::BuiltIn(
                lesson.id.clone(),
            )));
        }
    }
    ui.small("A lesson file of your own (….lesson.toml) opens with Open mesh… or by dropping it on the window.");
}

impl LessonsPanel {
    fn lesson(&mut self, ui: &mut egui::Ui, run: &LessonRun, commands: &mut Vec<Command>) {
        let lesson = &run.lesson;
        let step = run.current();
        ui.strong(lesson.title.as_str());
        ui.label(egui::RichText::new(lesson.goal.as_str()).italics());
        ui.label(format!("Step {} of {}", run.step + 1, lesson.steps.len()));
        ui.label(tidy(&step.text));
        if let Some(view) = step.view {
            ui.small(format!("Look at {}.", view.label()));
        }
        if let Some(p) = &step.predict {
            ui.separator();
            ui.label(format!("Predict: {}", p.question));
            match run.prediction {
                None => {
                    for (k, choice) in p.choices.iter().enumerate() {
                        ui.radio_value(&mut self.choice, Some(k), choice.as_str());
                    }
                    let commit = ui.add_enabled(
                        self.choice.is_some(),
                        egui::Button::new("Commit to my prediction"),
                    );
                    if commit.clicked()
                        && let Some(k) = self.choice.take()
                    {
                        commands.push(Command::Predict(k));
                    }
                    ui.small("The lab waits, paused, until you commit.");
                }
                Some(k) => {
                    ui.label(format!("You predicted: {}", p.choices[k]));
                }
            }
        }
        if !run.awaits_prediction() {
            ui.separator();
            for (check, state) in step.checks.iter().zip(&run.checks) {
                let mark = if state.met { "Done:" } else { "Waiting:" };
                let what = describe(check);
                let text = match &state.finding {
                    Some(found) => format!("{mark} {what}: {found}"),
                    None => format!("{mark} {what}"),
                };
                ui.label(text);
            }
        }
        if run.step_done() {
            ui.separator();
            if let Some(p) = &step.predict
                && let Some(k) = run.prediction
            {
                let verdict = if k == p.answer {
                    "Your prediction was right."
                } else {
                    "Your prediction was not what happened."
                };
                ui.label(format!("{verdict} The answer: {}.", p.choices[p.answer]));
            }
            ui.label(tidy(&step.explain));
        }
        ui.horizontal(|ui| {
            if ui
                .add_enabled(run.step > 0, egui::Button::new("Back"))
                .clicked()
            {
                commands.push(Command::PreviousStep);
            }
            let last = run.step + 1 == lesson.steps.len();
            if !last
                && ui
                    .add_enabled(run.step_done(), egui::Button::new("Next step"))
                    .clicked()
            {
                self.choice = None;
                commands.push(Command::NextStep);
            }
            if ui.button("Close lesson").clicked() {
                self.choice = None;
                commands.push(Command::CloseLesson);
            }
        });
        if run.finished() {
            ui.label("Lesson done.");
        }
    }
}

/// A lesson file's text as a paragraph: its line breaks are the file's, not the reader's.
fn tidy(text: &str) -> String {
    text.split("\n\n")
        .map(|p| p.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect::<Vec<_>>()
        .join("\n\n")
}

/// What a check asks, in words.
fn describe(check: &lessons::Check) -> String {
    use lessons::Check;
    match check {
        Check::Sample { label } => format!("the {label} is loaded"),
        Check::OwnMesh => "a mesh of your own is open".to_owned(),
        Check::Source { source } => format!(
            "the simulation uses the {} inertia",
            match source {
                lessons::Source::Exact => "exact",
                lessons::Source::BoundingBox => "bounding-box",
                lessons::Source::PointMasses => "point-mass",
            }
        ),
        Check::Model { model } => match model {
            lessons::Model::Full => "the full Euler equation is on".to_owned(),
            lessons::Model::Textbook => "the textbook model is on".to_owned(),
        },
        Check::SpinAxis { axis } => format!("it spins about axis {axis}"),
        Check::Reversals { .. } => "reversals of ω₂".to_owned(),
        Check::NoReversalFor { .. } => "steady".to_owned(),
        Check::MeasuredHalfPeriod { tolerance } => {
            format!("measured as predicted, within {:.0} %", tolerance * 100.0)
        }
        Check::FlipPeriod { .. } => "the flip period".to_owned(),
        Check::MomentsEqual { tolerance } => {
            format!("two moments equal within {:.0} %", tolerance * 100.0)
        }
        Check::Poked => "a poke changed L by r × J".to_owned(),
        Check::Conserved { .. } => "E and |L| held".to_owned(),
        Check::Elapsed { .. } => "time".to_owned(),
        Check::Parts { at_least } => format!("at least {at_least} parts"),
        Check::PartMoved { distance } => format!("a part moved {distance} m"),
    }
}
