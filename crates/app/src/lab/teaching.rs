//! The lab's lesson commands (open, predict, next, back), one method each, like the part
//! commands in `editing.rs`, and the evaluation of the open step's checks after every command
//! and every advance.

use std::collections::BTreeMap;

use super::lessons::{self, CheckState, LessonRun, LessonSource, Model, Snapshot, Source};
use super::loader::LoadSource;
use super::settings::InertiaSource;
use super::{Command, Lab, LabError, LoadedBody, RunMode};

/// `command` as the lesson it opens, when it opens or drops a lesson file (`….lesson.toml`);
/// otherwise `command` itself.
pub(super) fn lesson_opened(command: Command) -> Command {
    match command {
        Command::LoadFile(path) | Command::Drop(LoadSource::Path(path))
            if lessons::is_lesson_file(&path) =>
        {
            Command::OpenLesson(LessonSource::Path(path))
        }
        Command::LoadFiles(files) => match lessons::lesson_in(&files) {
            Some(lesson) => Command::OpenLesson(lesson),
            None => Command::LoadFiles(files),
        },
        Command::Drop(LoadSource::Files(files)) => match lessons::lesson_in(&files) {
            Some(lesson) => Command::OpenLesson(lesson),
            None => Command::Drop(LoadSource::Files(files)),
        },
        other => other,
    }
}

impl Lab {
    /// The lesson open, if any.
    pub fn lesson(&self) -> Option<&LessonRun> {
        self.lesson.as_ref()
    }

    /// For each lesson (by id) the most steps ever done.
    pub fn lesson_progress(&self) -> &BTreeMap<String, usize> {
        &self.lesson_progress
    }

    /// Progress kept from an earlier run (the GUI's storage); the larger count wins.
    pub fn restore_lesson_progress(&mut self, progress: BTreeMap<String, usize>) {
        for (id, done) in progress {
            let kept = self.lesson_progress.entry(id).or_default();
            *kept = (*kept).max(done);
        }
    }

    pub(super) fn open_lesson(&mut self, source: &LessonSource) -> Result<(), LabError> {
        let lesson = source.lesson()?;
        let mut run = LessonRun {
            lesson,
            step: 0,
            prediction: None,
            checks: Vec::new(),
            snapshot: Snapshot::of(self),
        };
        self.begin_step(&mut run)?;
        self.lesson = Some(run);
        Ok(())
    }

    pub(super) fn predict(&mut self, choice: usize) -> Result<(), LabError> {
        let run = self
            .lesson
            .as_mut()
            .ok_or(LabError::LessonStep("no lesson is open"))?;
        let Some(p) = &run.current().predict else {
            return Err(LabError::LessonStep("this step asks for no prediction"));
        };
        if choice >= p.choices.len() {
            return Err(LabError::LessonStep("that choice is not offered"));
        }
        if run.prediction.is_some() {
            return Err(LabError::LessonStep("the prediction is made already"));
        }
        run.prediction = Some(choice);
        // The checks count from the moment the student committed, and time runs again.
        self.run_mode = RunMode::Running;
        self.clock.stop();
        let snapshot = Snapshot::of(self);
        if let Some(run) = &mut self.lesson {
            run.snapshot = snapshot;
        }
        Ok(())
    }

    pub(super) fn next_step(&mut self) -> Result<(), LabError> {
        let mut run = self
            .lesson
            .take()
            .ok_or(LabError::LessonStep("no lesson is open"))?;
        if !run.step_done() || run.step + 1 >= run.lesson.steps.len() {
            let why = if run.step_done() {
                "this is the lesson's last step"
            } else {
                "this step's checks have not all held yet"
            };
            self.lesson = Some(run);
            return Err(LabError::LessonStep(why));
        }
        run.step += 1;
        let begun = self.begin_step(&mut run);
        self.lesson = Some(run);
        begun
    }

    pub(super) fn previous_step(&mut self) -> Result<(), LabError> {
        let mut run = self
            .lesson
            .take()
            .ok_or(LabError::LessonStep("no lesson is open"))?;
        if run.step == 0 {
            self.lesson = Some(run);
            return Err(LabError::LessonStep("this is the lesson's first step"));
        }
        run.step -= 1;
        let begun = self.begin_step(&mut run);
        self.lesson = Some(run);
        begun
    }

    pub(super) fn go_to_step(&mut self, step: usize) -> Result<(), LabError> {
        let mut run = self
            .lesson
            .take()
            .ok_or(LabError::LessonStep("no lesson is open"))?;
        if step >= run.lesson.steps.len() {
            self.lesson = Some(run);
            return Err(LabError::LessonStep("the lesson has no such step"));
        }
        run.step = step;
        let begun = self.begin_step(&mut run);
        self.lesson = Some(run);
        begun
    }

    /// Sets the lab up as `run`'s present step says and starts its checks afresh.
    fn begin_step(&mut self, run: &mut LessonRun) -> Result<(), LabError> {
        let setup = run.current().setup.clone();
        if let Some(label) = &setup.sample {
            self.install(LoadedBody::sample(label)?)?;
        }
        let mut settings = self.settings.clone();
        if let Some(source) = setup.source {
            settings.body.source = match source {
                Source::Exact => InertiaSource::Exact,
                Source::BoundingBox => InertiaSource::BoundingBox,
                Source::PointMasses => InertiaSource::PointMasses,
            };
        }
        if let Some(model) = setup.model {
            settings.physics.model = match model {
                Model::Full => rbcore::RotationModel::Full,
                Model::Textbook => rbcore::RotationModel::Textbook,
            };
        }
        if let Some(on) = setup.momentum_sphere {
            settings.view.momentum_sphere = on;
        }
        if let Some(on) = setup.poinsot {
            settings.view.poinsot = on;
        }
        if settings != self.settings {
            self.set_settings(settings)?;
        }
        if let Some(axis) = setup.spin_axis {
            self.restart(axis - 1)?;
        }
        let step = run.current();
        let paused = setup.pause.unwrap_or(false) || step.predict.is_some();
        let checks = step.checks.len();
        self.run_mode = if paused {
            RunMode::Paused
        } else {
            RunMode::Running
        };
        self.clock.stop();
        run.prediction = None;
        run.checks = vec![CheckState::default(); checks];
        run.snapshot = Snapshot::of(self);
        Ok(())
    }

    /// Evaluates the open step's checks that have not held yet (those that did stay held).
    pub(super) fn update_lesson(&mut self) {
        let Some(mut run) = self.lesson.take() else {
            return;
        };
        if !run.awaits_prediction() {
            run.snapshot.observe(self);
            let checks = run.current().checks.clone();
            for (state, check) in run.checks.iter_mut().zip(&checks) {
                if !state.met {
                    *state = check.evaluate(self, &run.snapshot);
                }
            }
            if run.step_done() {
                let done = self
                    .lesson_progress
                    .entry(run.lesson.id.clone())
                    .or_default();
                *done = (*done).max(run.step + 1);
            }
        }
        self.lesson = Some(run);
    }
}
