//! The Lessons panel, beside the 3D view: the built-in lessons with the progress kept for each, and the lesson
//! open: its goal, the step's text and the view it needs, the prediction to commit to, the
//! checks as the lab evaluates them, and the explanation once they hold.

use super::{Frame, Panel};
use crate::i18n::{fixed, language, localize, tr};
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
        ui.heading(tr!("lessons-heading"));
        // Back, Next and Close stay in view below the text, however long it is.
        if let Some(run) = f.lab.lesson() {
            egui::Panel::bottom("lesson-navigation")
                .show(ui, |ui| self.navigation(ui, run, f.commands));
        }
        egui::ScrollArea::vertical().show(ui, |ui| match f.lab.lesson() {
            Some(run) => self.lesson(ui, run, f.commands),
            None => list(ui, f),
        });
    }
}

/// The built-in lessons, each a button with its progress.
fn list(ui: &mut egui::Ui, f: &mut Frame<'_>) {
    for (k, lesson) in lessons::built_in().iter().enumerate() {
        let lesson = lesson.in_language(language());
        let done = f
            .lab
            .lesson_progress()
            .get(&lesson.id)
            .copied()
            .unwrap_or(0);
        let steps = lesson.steps.len();
        // Words, not a check mark: egui's default fonts have no ✔.
        let mark = if done >= steps {
            format!(" {}", tr!("lessons-done-mark"))
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
    ui.small(tr!("lessons-own-file"));
}

impl LessonsPanel {
    fn lesson(&mut self, ui: &mut egui::Ui, run: &LessonRun, commands: &mut Vec<Command>) {
        let lesson = run.lesson.in_language(language());
        let step = &lesson.steps[run.step];
        ui.strong(lesson.title.as_str());
        ui.label(egui::RichText::new(lesson.goal.as_str()).italics());
        ui.label(tr!(
            "lessons-step",
            step = run.step + 1,
            steps = lesson.steps.len()
        ));
        // At the top, where the student looks first: the panel may scroll.
        if run.finished() {
            ui.strong(tr!("lessons-finished"));
        }
        ui.label(tidy(&step.text));
        if let Some(view) = step.view {
            ui.small(look_at(view));
        }
        if let Some(p) = &step.predict {
            ui.separator();
            ui.label(tr!("lessons-predict", question = &p.question));
            match run.prediction {
                None => {
                    for (k, choice) in p.choices.iter().enumerate() {
                        ui.radio_value(&mut self.choice, Some(k), choice.as_str());
                    }
                    let commit = ui.add_enabled(
                        self.choice.is_some(),
                        egui::Button::new(tr!("lessons-commit")),
                    );
                    if commit.clicked()
                        && let Some(k) = self.choice.take()
                    {
                        commands.push(Command::Predict(k));
                    }
                    ui.small(tr!("lessons-waits-for-commit"));
                }
                Some(k) => {
                    ui.label(tr!("lessons-predicted", choice = &p.choices[k]));
                }
            }
        }
        if !run.awaits_prediction() {
            ui.separator();
            for (check, state) in step.checks.iter().zip(&run.checks) {
                let what = describe(check);
                let text = match (state.met, &state.finding) {
                    (true, Some(found)) => {
                        tr!("lessons-check-done-found", what = what, found = found)
                    }
                    (true, None) => tr!("lessons-check-done", what = what),
                    (false, Some(found)) => {
                        tr!("lessons-check-waiting-found", what = what, found = found)
                    }
                    (false, None) => tr!("lessons-check-waiting", what = what),
                };
                ui.label(text);
            }
        }
        if run.step_done() {
            ui.separator();
            if let Some(p) = &step.predict
                && let Some(k) = run.prediction
            {
                let answer = &p.choices[p.answer];
                ui.label(if k == p.answer {
                    tr!("lessons-prediction-right", answer = answer)
                } else {
                    tr!("lessons-prediction-wrong", answer = answer)
                });
            }
            ui.label(tidy(&step.explain));
        }
    }

    /// The step's buttons: back, next (once the step is done), close.
    fn navigation(&mut self, ui: &mut egui::Ui, run: &LessonRun, commands: &mut Vec<Command>) {
        ui.horizontal_wrapped(|ui| {
            if ui
                .add_enabled(run.step > 0, egui::Button::new(tr!("lessons-back")))
                .clicked()
            {
                commands.push(Command::PreviousStep);
            }
            let last = run.step + 1 == run.lesson.steps.len();
            if !last
                && ui
                    .add_enabled(run.step_done(), egui::Button::new(tr!("lessons-next-step")))
                    .clicked()
            {
                self.choice = None;
                commands.push(Command::NextStep);
            }
            if ui.button(tr!("lessons-close")).clicked() {
                self.choice = None;
                commands.push(Command::CloseLesson);
            }
        });
    }
}

/// A lesson file's text as a paragraph: its line breaks are the file's, not the reader's.
fn tidy(text: &str) -> String {
    text.split("\n\n")
        .map(|p| p.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect::<Vec<_>>()
        .join("\n\n")
}

/// Where a step points the student, as a sentence (the lesson module's own names are English).
fn look_at(view: lessons::View) -> String {
    use lessons::View;
    match view {
        View::Body => tr!("lessons-look-body"),
        View::Table => tr!("lessons-look-table"),
        View::Plots => tr!("lessons-look-plots"),
        View::Sphere => tr!("lessons-look-sphere"),
        View::Parts => tr!("lessons-look-parts"),
        View::Motion => tr!("lessons-look-motion"),
    }
}

/// What a check asks, in words.
fn describe(check: &lessons::Check) -> String {
    use lessons::Check;
    match check {
        Check::Sample { label } => tr!("lessons-check-sample", sample = label),
        Check::OwnMesh => tr!("lessons-check-own-mesh"),
        Check::Source { source } => match source {
            lessons::Source::Exact => tr!("lessons-check-source-exact"),
            lessons::Source::BoundingBox => tr!("lessons-check-source-bounding-box"),
            lessons::Source::PointMasses => tr!("lessons-check-source-point-masses"),
        },
        Check::Model { model } => match model {
            lessons::Model::Full => tr!("lessons-check-model-full"),
            lessons::Model::Textbook => tr!("lessons-check-model-textbook"),
        },
        Check::SpinAxis { axis } => tr!("lessons-check-spin-axis", axis = *axis),
        Check::Reversals { .. } => tr!("lessons-check-reversals"),
        Check::NoReversalFor { .. } => tr!("lessons-check-steady"),
        Check::MeasuredHalfPeriod { tolerance } => tr!(
            "lessons-check-half-period",
            tolerance = fixed(tolerance * 100.0, 0)
        ),
        Check::FlipPeriod { .. } => tr!("lessons-check-flip-period"),
        Check::MomentsEqual { tolerance } => tr!(
            "lessons-check-moments-equal",
            tolerance = fixed(tolerance * 100.0, 0)
        ),
        Check::Poked => tr!("lessons-check-poked"),
        Check::Conserved { .. } => tr!("lessons-check-conserved"),
        Check::Elapsed { .. } => tr!("lessons-check-elapsed"),
        Check::Parts { at_least } => tr!("lessons-check-parts", count = *at_least),
        // As the lesson file writes it (`{distance}`), with the language's separator.
        Check::PartMoved { distance } => tr!(
            "lessons-check-part-moved",
            distance = localize(distance.to_string())
        ),
    }
}
