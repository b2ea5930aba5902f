//! Lessons: short guided activities that the lab runs and checks from its own state.
//!
//! A lesson is data, not code: a TOML file (format in `docs/lessons.md`) of a title, a goal and
//! steps. Each step says what to do, may set the lab up ([`Setup`]: a sample, a spin, the
//! inertia source, the rotation model, a pause), may ask for a [`Prediction`] that the student
//! commits to before the checks count, lists [`Check`]s that the lab evaluates from its state as
//! time runs (a reversal of ω₂ measured, a poke that changed L by r × J, a flip period within
//! 5 % of a target, a part moved with I changed as the parallel-axis theorem says, …), and ends
//! with an explanation shown once every check has held. The built-in lessons are the files in
//! the repository's `lessons/` folder; a teacher's file opens the same way.
//!
//! Method: PhET's guided-inquiry pattern (predict, act, observe, explain), with checks in place
//! of a teacher looking over the student's shoulder.

mod checks;

use std::sync::Arc;

use serde::Deserialize;

use crate::i18n::Language;

pub use checks::{CheckState, Snapshot};

/// A built-in lesson's file: its name, its text, and its words in each language of
/// [`TRANSLATED`] (`lessons/<code>/<name>`).
type BuiltIn = (&'static str, &'static str, [&'static str; 2]);

/// The languages the built-in lessons are written in besides English.
const TRANSLATED: [Language; 2] = [Language::German, Language::Spanish];

/// The built-in lessons, in the order they are offered (`?lesson=1` is the first).
const BUILT_IN: [BuiltIn; 8] = [
    (
        "01-tensor.toml",
        include_str!("../../../../../lessons/01-tensor.toml"),
        [
            include_str!("../../../../../lessons/de/01-tensor.toml"),
            include_str!("../../../../../lessons/es/01-tensor.toml"),
        ],
    ),
    (
        "02-stable-axes.toml",
        include_str!("../../../../../lessons/02-stable-axes.toml"),
        [
            include_str!("../../../../../lessons/de/02-stable-axes.toml"),
            include_str!("../../../../../lessons/es/02-stable-axes.toml"),
        ],
    ),
    (
        "03-racket-flip.toml",
        include_str!("../../../../../lessons/03-racket-flip.toml"),
        [
            include_str!("../../../../../lessons/de/03-racket-flip.toml"),
            include_str!("../../../../../lessons/es/03-racket-flip.toml"),
        ],
    ),
    (
        "04-textbook-model.toml",
        include_str!("../../../../../lessons/04-textbook-model.toml"),
        [
            include_str!("../../../../../lessons/de/04-textbook-model.toml"),
            include_str!("../../../../../lessons/es/04-textbook-model.toml"),
        ],
    ),
    (
        "05-parallel-axis.toml",
        include_str!("../../../../../lessons/05-parallel-axis.toml"),
        [
            include_str!("../../../../../lessons/de/05-parallel-axis.toml"),
            include_str!("../../../../../lessons/es/05-parallel-axis.toml"),
        ],
    ),
    (
        "06-conservation.toml",
        include_str!("../../../../../lessons/06-conservation.toml"),
        [
            include_str!("../../../../../lessons/de/06-conservation.toml"),
            include_str!("../../../../../lessons/es/06-conservation.toml"),
        ],
    ),
    (
        "07-design-a-body.toml",
        include_str!("../../../../../lessons/07-design-a-body.toml"),
        [
            include_str!("../../../../../lessons/de/07-design-a-body.toml"),
            include_str!("../../../../../lessons/es/07-design-a-body.toml"),
        ],
    ),
    (
        "08-your-object.toml",
        include_str!("../../../../../lessons/08-your-object.toml"),
        [
            include_str!("../../../../../lessons/de/08-your-object.toml"),
            include_str!("../../../../../lessons/es/08-your-object.toml"),
        ],
    ),
];

/// One lesson, as its file says.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lesson {
    /// A short name for links and progress (`?lesson=tensor`): letters, digits and `-`.
    pub id: String,
    /// The title shown.
    pub title: String,
    /// What the student will have seen at the end, in one sentence.
    pub goal: String,
    /// The steps, in order.
    #[serde(rename = "step")]
    pub steps: Vec<Step>,
    /// Its words in other languages (the built-in lessons'), each checked to fit its steps.
    #[serde(skip)]
    pub translations: Vec<(Language, Words)>,
}

/// A lesson's words in another language (`lessons/<code>/<file>` for a built-in lesson): the
/// title, the goal and each step's text, question, choices and explanation, in the lesson's
/// order. What a step sets up and checks is the lesson's own, written once.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Words {
    /// The title.
    pub title: String,
    /// The goal.
    pub goal: String,
    /// Each step's words, in order.
    #[serde(rename = "step")]
    pub steps: Vec<StepWords>,
}

/// One step's words in another language.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StepWords {
    /// What to do.
    pub text: String,
    /// The prediction's question (where the step asks one).
    #[serde(default)]
    pub question: Option<String>,
    /// The prediction's choices, in the lesson's order.
    #[serde(default)]
    pub choices: Vec<String>,
    /// The explanation.
    pub explain: String,
}

/// One step of a lesson.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Step {
    /// What to do.
    pub text: String,
    /// What the lab does when the step begins.
    #[serde(default)]
    pub setup: Setup,
    /// The view this step needs (pointed at, and opened where it can be).
    #[serde(default)]
    pub view: Option<View>,
    /// A question answered before the checks count.
    #[serde(default)]
    pub predict: Option<Prediction>,
    /// What must hold, all of it, for the step to be done.
    #[serde(default, rename = "check")]
    pub checks: Vec<Check>,
    /// Shown once the checks hold: what it means, with its equation.
    pub explain: String,
}

/// What a step sets up when it begins; each field left out leaves the lab as it is.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Setup {
    /// A built-in sample, by its label ("T-handle", "Tennis racket", "Hammer", …).
    pub sample: Option<String>,
    /// Which inertia drives the simulation.
    pub source: Option<Source>,
    /// The full Euler equation or the textbook model.
    pub model: Option<Model>,
    /// Spin about principal axis 1, 2 or 3 (moments ascending), slightly perturbed.
    pub spin_axis: Option<usize>,
    /// Pause (true) or run (false).
    pub pause: Option<bool>,
    /// Show the momentum sphere.
    pub momentum_sphere: Option<bool>,
    /// Show Poinsot's construction.
    pub poinsot: Option<bool>,
}

/// The inertia a lesson names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Source {
    /// The exact solid.
    Exact,
    /// The cuboid filling the bounding box.
    BoundingBox,
    /// Point masses at the vertices.
    PointMasses,
}

/// The rotation model a lesson names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Model {
    /// dL/dt = τ with ω = R I⁻¹ Rᵀ L.
    Full,
    /// dω/dt = I⁻¹ τ, without ω × Iω.
    Textbook,
}

/// The views a step can point at.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum View {
    /// The 3D view.
    Body,
    /// The table of exact against bounding-box mass properties.
    Table,
    /// The plots of ω, L and energy.
    Plots,
    /// The momentum sphere.
    Sphere,
    /// The parts list.
    Parts,
    /// The motion controls.
    Motion,
}

/// A question with its choices; `answer` is revealed once the step is done.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Prediction {
    /// The question.
    pub question: String,
    /// The choices offered.
    pub choices: Vec<String>,
    /// The index of the right choice.
    pub answer: usize,
}

/// What the lab checks; each holds once and stays held for the step.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Check {
    /// The body shown is the built-in sample with this label.
    Sample {
        /// Its label.
        label: String,
    },
    /// The body was opened from a file of the student's own (not a sample).
    OwnMesh,
    /// The simulation uses this inertia.
    Source {
        /// Which.
        source: Source,
    },
    /// The simulation uses this rotation model.
    Model {
        /// Which.
        model: Model,
    },
    /// The body was last spun about this principal axis (1, 2 or 3).
    SpinAxis {
        /// Which.
        axis: usize,
    },
    /// This many reversals of ω₂ were measured since the step began.
    Reversals {
        /// How many.
        at_least: usize,
    },
    /// This much simulated time passed since the step began (or since the last change of
    /// spin, model or source) with no reversal of ω₂.
    NoReversalFor {
        /// Seconds.
        seconds: f64,
    },
    /// The measured time between reversals of ω₂ is the predicted one, within `tolerance`
    /// (relative).
    MeasuredHalfPeriod {
        /// Relative tolerance.
        tolerance: f64,
    },
    /// The predicted flip period (two reversals) is `seconds` within `tolerance` (relative).
    FlipPeriod {
        /// The target.
        seconds: f64,
        /// Relative tolerance.
        tolerance: f64,
    },
    /// Two principal moments are equal within `tolerance` (relative to the larger).
    MomentsEqual {
        /// Relative tolerance.
        tolerance: f64,
    },
    /// The body was poked since the step began, and L changed by r × J.
    Poked,
    /// This much simulated time passed undisturbed since the step began (or the last poke),
    /// with the energy and |L| held to `tolerance` (relative).
    Conserved {
        /// Seconds.
        seconds: f64,
        /// Relative tolerance.
        tolerance: f64,
    },
    /// This much simulated time passed since the step began.
    Elapsed {
        /// Seconds.
        seconds: f64,
    },
    /// The body has at least this many parts.
    Parts {
        /// How many.
        at_least: usize,
    },
    /// One part moved at least `distance` metres since the step began, the others stayed, and
    /// the tensor about the origin changed as the parallel-axis theorem says.
    PartMoved {
        /// Metres.
        distance: f64,
    },
}

/// Why a lesson file could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LessonError {
    /// Not TOML of the lesson format.
    #[error("{file}: {message}")]
    Format {
        /// The file.
        file: String,
        /// What the TOML reader said (with the line).
        message: String,
    },
    /// Read, but not a lesson that can run.
    #[error("{file}: {problem}")]
    Invalid {
        /// The file.
        file: String,
        /// What is wrong.
        problem: String,
    },
    /// No built-in lesson has this id or number.
    #[error("no lesson is {0:?}: the lessons are 1 to {n} or {ids}", n = BUILT_IN.len(), ids = built_in_ids().join(", "))]
    Unknown(String),
}

fn built_in_ids() -> Vec<String> {
    built_in().iter().map(|l| l.id.clone()).collect()
}

impl Lesson {
    /// Reads a lesson file's text (`file` names it in errors).
    ///
    /// # Errors
    /// The text is not the lesson format, or names a step, view, axis or sample the lab lacks.
    pub fn parse(file: &str, text: &str) -> Result<Self, LessonError> {
        let lesson: Lesson = toml::from_str(text).map_err(|e| LessonError::Format {
            file: file.to_owned(),
            message: e.to_string().trim_end().to_owned(),
        })?;
        lesson.validate().map_err(|problem| LessonError::Invalid {
            file: file.to_owned(),
            problem,
        })?;
        Ok(lesson)
    }

    /// Adds the lesson's words in `language` from the text of `file`.
    ///
    /// # Errors
    /// The text is not TOML of [`Words`], or its steps, questions or choices do not match the
    /// lesson's.
    pub fn translate(
        &mut self,
        language: Language,
        file: &str,
        text: &str,
    ) -> Result<(), LessonError> {
        let words: Words = toml::from_str(text).map_err(|e| LessonError::Format {
            file: file.to_owned(),
            message: e.to_string().trim_end().to_owned(),
        })?;
        let invalid = |problem: String| LessonError::Invalid {
            file: file.to_owned(),
            problem,
        };
        if words.steps.len() != self.steps.len() {
            return Err(invalid(format!(
                "{} steps, where the lesson has {}",
                words.steps.len(),
                self.steps.len()
            )));
        }
        for (k, (step, said)) in self.steps.iter().zip(&words.steps).enumerate() {
            let choices = step.predict.as_ref().map_or(0, |p| p.choices.len());
            if step.predict.is_some() != said.question.is_some() || said.choices.len() != choices {
                return Err(invalid(format!(
                    "step {}: {} choices and {} question, where the lesson has {choices} and {}",
                    k + 1,
                    said.choices.len(),
                    if said.question.is_some() { "a" } else { "no" },
                    if step.predict.is_some() { "a" } else { "none" },
                )));
            }
        }
        self.translations.push((language, words));
        Ok(())
    }

    /// The lesson in `language`: its own words where it has none in that language.
    pub fn in_language(&self, language: Language) -> Lesson {
        let mut lesson = self.clone();
        let Some((_, words)) = self.translations.iter().find(|(l, _)| *l == language) else {
            return lesson;
        };
        lesson.title.clone_from(&words.title);
        lesson.goal.clone_from(&words.goal);
        for (step, said) in lesson.steps.iter_mut().zip(&words.steps) {
            step.text.clone_from(&said.text);
            step.explain.clone_from(&said.explain);
            if let (Some(p), Some(question)) = (&mut step.predict, &said.question) {
                p.question.clone_from(question);
                p.choices.clone_from(&said.choices);
            }
        }
        lesson
    }

    fn validate(&self) -> Result<(), String> {
        if self.id.is_empty()
            || !self
                .id
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-')
        {
            return Err(format!(
                "id {:?} must be letters, digits and -, not empty",
                self.id
            ));
        }
        if self.steps.is_empty() {
            return Err("a lesson needs at least one [[step]]".to_owned());
        }
        let samples = super::samples::labels();
        for (k, step) in self.steps.iter().enumerate() {
            let at = |what: String| format!("step {}: {what}", k + 1);
            if let Some(axis) = step.setup.spin_axis
                && !(1..=3).contains(&axis)
            {
                return Err(at(format!("spin_axis is {axis}; it must be 1, 2 or 3")));
            }
            if let Some(sample) = &step.setup.sample
                && !samples.contains(&sample.as_str())
            {
                return Err(at(format!(
                    "there is no sample {sample:?}; the samples are {}",
                    samples.join(", ")
                )));
            }
            if let Some(p) = &step.predict
                && (p.choices.len() < 2 || p.answer >= p.choices.len())
            {
                return Err(at(format!(
                    "a prediction needs two choices or more and an answer among them (answer {} \
                     of {} choices, counted from 0)",
                    p.answer,
                    p.choices.len()
                )));
            }
            for check in &step.checks {
                if let Check::SpinAxis { axis } = check
                    && !(1..=3).contains(axis)
                {
                    return Err(at(format!("check spin_axis {axis}: it must be 1, 2 or 3")));
                }
                if let Check::Sample { label } = check
                    && !samples.contains(&label.as_str())
                {
                    return Err(at(format!("check sample: there is no sample {label:?}")));
                }
            }
        }
        Ok(())
    }
}

/// The built-in lessons, in order, each with its words in every language (read once: the
/// panel lists them every frame).
pub fn built_in() -> Vec<Arc<Lesson>> {
    static LESSONS: std::sync::OnceLock<Vec<Arc<Lesson>>> = std::sync::OnceLock::new();
    LESSONS.get_or_init(read_built_in).clone()
}

fn read_built_in() -> Vec<Arc<Lesson>> {
    BUILT_IN
        .iter()
        .map(|(file, text, translations)| {
            let mut lesson =
                Lesson::parse(file, text).unwrap_or_else(|e| panic!("built-in lesson: {e}"));
            for (language, words) in TRANSLATED.iter().zip(translations) {
                let name = format!("{}/{file}", language.code());
                lesson
                    .translate(*language, &name, words)
                    .unwrap_or_else(|e| panic!("built-in lesson: {e}"));
            }
            Arc::new(lesson)
        })
        .collect()
}

/// The built-in lesson named by `key`: its number from 1, or its id.
///
/// # Errors
/// No built-in lesson has that number or id.
pub fn find(key: &str) -> Result<Arc<Lesson>, LessonError> {
    let all = built_in();
    let found = match key.trim().parse::<usize>() {
        Ok(n) if (1..=all.len()).contains(&n) => Some(all[n - 1].clone()),
        _ => all.iter().find(|l| l.id == key.trim()).cloned(),
    };
    found.ok_or_else(|| LessonError::Unknown(key.to_owned()))
}

/// Where a lesson to open comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum LessonSource {
    /// A built-in lesson by its number from 1 or its id.
    BuiltIn(String),
    /// A lesson file on disk.
    Path(std::path::PathBuf),
    /// A lesson file's text (a dropped file, or one the page fetched), named `file`.
    Text {
        /// The file's name, for errors.
        file: String,
        /// Its text.
        text: String,
    },
}

impl LessonSource {
    /// The lesson it names.
    ///
    /// # Errors
    /// No such built-in lesson, a file that cannot be read, or one not in the lesson format.
    pub fn lesson(&self) -> Result<Arc<Lesson>, LessonError> {
        match self {
            LessonSource::BuiltIn(key) => find(key),
            LessonSource::Path(path) => {
                let file = path.display().to_string();
                let text = std::fs::read_to_string(path).map_err(|e| LessonError::Format {
                    file: file.clone(),
                    message: e.to_string(),
                })?;
                Lesson::parse(&file, &text).map(Arc::new)
            }
            LessonSource::Text { file, text } => Lesson::parse(file, text).map(Arc::new),
        }
    }
}

/// Whether `path` names a lesson file (`….lesson.toml`; a plain `.toml` is a body file).
pub fn is_lesson_file(path: &std::path::Path) -> bool {
    path.file_name()
        .and_then(|n| n.to_str())
        .is_some_and(|n| n.to_ascii_lowercase().ends_with(".lesson.toml"))
}

/// The lesson among files given by their bytes (a drop, the page's input), if one is.
pub fn lesson_in(files: &inertia_io::input::FileSet) -> Option<LessonSource> {
    let name = files.names().find(|n| is_lesson_file(n))?;
    let text = String::from_utf8_lossy(files.get(name)?).into_owned();
    Some(LessonSource::Text {
        file: name.display().to_string(),
        text,
    })
}

/// A lesson in progress: where the student is, what they predicted, which checks held.
#[derive(Debug, Clone)]
pub struct LessonRun {
    /// The lesson.
    pub lesson: Arc<Lesson>,
    /// The step shown (from 0).
    pub step: usize,
    /// The choice committed to for this step's prediction.
    pub prediction: Option<usize>,
    /// Each check of this step: whether it held, and what was measured.
    pub checks: Vec<CheckState>,
    /// The lab's state when the step began (or its prediction was made).
    pub snapshot: Snapshot,
}

impl LessonRun {
    /// The step shown.
    pub fn current(&self) -> &Step {
        &self.lesson.steps[self.step]
    }

    /// Whether this step's prediction is still to be made (the checks wait for it).
    pub fn awaits_prediction(&self) -> bool {
        self.current().predict.is_some() && self.prediction.is_none()
    }

    /// Whether every check of this step held (and its prediction was made).
    pub fn step_done(&self) -> bool {
        !self.awaits_prediction() && self.checks.iter().all(|c| c.met)
    }

    /// Whether the last step is done.
    pub fn finished(&self) -> bool {
        self.step + 1 == self.lesson.steps.len() && self.step_done()
    }

    /// `k/N` (from 1), or `done` once the last step is done: as the page publishes it.
    pub fn progress(&self) -> String {
        if self.finished() {
            "done".to_owned()
        } else {
            format!("{}/{}", self.step + 1, self.lesson.steps.len())
        }
    }
}

#[cfg(test)]
mod tests;
