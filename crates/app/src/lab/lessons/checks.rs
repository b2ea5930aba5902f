//! A lesson's checks, evaluated from the lab's state against a [`Snapshot`] taken when the step
//! began. Each returns whether it holds and, where something was measured, what (in words the
//! panel shows beside the check).

use crate::i18n::{fixed, localize, sci, tr};
use nalgebra::{Matrix3, Point3};

use super::{Check, Model, Source};
use crate::lab::Lab;
use crate::lab::settings::InertiaSource;

/// Relative agreement asked of the parallel-axis theorem and of r × J: both are identities of
/// the lab's own arithmetic, so anything above rounding is a bug.
const IDENTITY: f64 = 1e-9;

/// One check's state.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CheckState {
    /// It held (once held, it stays held for the step).
    pub met: bool,
    /// What was measured, when the check measures something.
    pub finding: Option<String>,
}

/// What a step's checks compare with: the lab when the step began.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// Simulated time.
    pub time: f64,
    /// The body's name.
    pub body: String,
    /// Each part's mass and centre of mass (body coordinates, scale 1).
    parts: Vec<PartPlace>,
    /// The whole body's tensor about its origin (scale 1), when it has parts.
    inertia_origin: Option<Matrix3<f64>>,
    /// How many pokes the primary had had.
    pokes: u64,
    /// Reversals of ω₂ counted so far in this step, and the last one seen.
    pub(crate) reversals: usize,
    last_reversal: Option<f64>,
    /// When the spin, model or source last changed, or a poke happened (simulated time).
    changed_at: f64,
    /// When the last reversal counted happened.
    reversal_at: f64,
    /// What that was measured against: (preset axis, model, source, pokes).
    state: (usize, Model, Source, u64),
    /// Simulated time at the last look (a restart sets the clock back).
    seen: f64,
}

fn lesson_source(source: InertiaSource) -> Source {
    match source {
        InertiaSource::BoundingBox => Source::BoundingBox,
        InertiaSource::PointMasses => Source::PointMasses,
        InertiaSource::Exact | InertiaSource::Stated => Source::Exact,
    }
}

fn lesson_model(lab: &Lab) -> Model {
    match lab.settings().physics.model {
        rbcore::RotationModel::Textbook => Model::Textbook,
        _ => Model::Full,
    }
}

/// A part's mass and centre of mass (body coordinates, scale 1).
type PartPlace = (f64, Point3<f64>);

/// The whole body's parts (mass, centre) and tensor about the origin, at scale 1.
fn composition(lab: &Lab) -> (Vec<PartPlace>, Option<Matrix3<f64>>) {
    let Some(c) = &lab.primary().body().composition else {
        return (Vec::new(), None);
    };
    let parts = c
        .parts
        .iter()
        .filter_map(|p| p.mass().ok())
        .map(|m| (m.mass, m.center_of_mass))
        .collect();
    (
        parts,
        Some(about_origin(
            c.whole.mass,
            &c.whole.center_of_mass,
            &c.whole.inertia_com,
        )),
    )
}

/// `inertia_com` of `mass` at `center` moved to the origin (the parallel-axis theorem).
fn about_origin(mass: f64, center: &Point3<f64>, inertia_com: &Matrix3<f64>) -> Matrix3<f64> {
    let c = center.coords;
    inertia_com + mass * (Matrix3::identity() * c.dot(&c) - c * c.transpose())
}

impl Snapshot {
    /// The lab now.
    pub fn of(lab: &Lab) -> Self {
        let (parts, inertia_origin) = composition(lab);
        let s = lab.primary();
        let time = s.sim().time();
        Self {
            time,
            body: s.body().name.clone(),
            parts,
            inertia_origin,
            pokes: s.pokes(),
            reversals: 0,
            last_reversal: s.history().last_reversal(),
            changed_at: time,
            reversal_at: time,
            state: state(lab),
            seen: time,
        }
    }

    /// Counts a reversal of ω₂ that happened since the last look, and notes a change of spin,
    /// model, source or a poke (the start of a quiet stretch).
    pub(crate) fn observe(&mut self, lab: &Lab) {
        let s = lab.primary();
        let now = s.sim().time();
        if now < self.seen {
            // A new spin or body started the clock again: measure from its start, keeping what
            // was counted.
            self.time = now;
            self.pokes = s.pokes();
            self.last_reversal = None;
            self.changed_at = now;
            self.reversal_at = now;
        }
        self.seen = now;
        let last = s.history().last_reversal();
        // ω₂ also crosses zero in the small wobble of a stable spin: a reversal counts only
        // while the body turns over.
        if let Some(t) = last
            && t > self.time
            && self.last_reversal.is_none_or(|seen| t > seen)
            && s.turn_over_interval().is_some()
        {
            self.reversals += 1;
            self.reversal_at = t;
        }
        self.last_reversal = last;
        let changed = state(lab);
        if changed != self.state {
            self.state = changed;
            self.changed_at = now;
        }
    }
}

fn state(lab: &Lab) -> (usize, Model, Source, u64) {
    (
        lab.preset_axis(),
        lesson_model(lab),
        lesson_source(lab.settings().body.source),
        lab.primary().pokes(),
    )
}

impl Check {
    /// Whether the check holds now, against `snapshot`.
    pub fn evaluate(&self, lab: &Lab, snapshot: &Snapshot) -> CheckState {
        let s = lab.primary();
        let now = s.sim().time();
        let met = |met: bool| CheckState { met, finding: None };
        match self {
            Check::Sample { label } => met(&s.body().name == label),
            // Not a sample (the T-handle the lab starts with is one).
            Check::OwnMesh => met(!crate::lab::samples::labels().contains(&s.body().name.as_str())),
            Check::Source { source } => met(lesson_source(lab.settings().body.source) == *source),
            Check::Model { model } => met(lesson_model(lab) == *model),
            Check::SpinAxis { axis } => met(lab.preset_axis() + 1 == *axis),
            Check::Reversals { at_least } => CheckState {
                met: snapshot.reversals >= *at_least,
                finding: Some(tr!(
                    "check-reversals",
                    measured = snapshot.reversals.min(*at_least),
                    wanted = *at_least
                )),
            },
            Check::NoReversalFor { seconds } => {
                let quiet = now - snapshot.changed_at.max(snapshot.reversal_at);
                CheckState {
                    met: quiet >= *seconds,
                    finding: Some(tr!(
                        "check-no-reversal",
                        passed = fixed(quiet.min(*seconds), 1),
                        seconds = fixed(*seconds, 0)
                    )),
                }
            }
            Check::MeasuredHalfPeriod { tolerance } => {
                match (s.history().flip_interval(), s.turn_over_interval()) {
                    (Some(measured), Some(predicted)) if snapshot.reversals >= 2 => {
                        let off = (measured - predicted).abs() / predicted;
                        CheckState {
                            met: off <= *tolerance,
                            finding: Some(tr!(
                                "check-half-period",
                                measured = fixed(measured, 2),
                                predicted = fixed(predicted, 2),
                                apart = fixed(off * 100.0, 1)
                            )),
                        }
                    }
                    _ => met(false),
                }
            }
            Check::FlipPeriod { seconds, tolerance } => match s.turn_over_interval() {
                Some(half) => {
                    let period = 2.0 * half;
                    CheckState {
                        met: (period - seconds).abs() <= tolerance * seconds,
                        finding: Some(tr!(
                            "check-flip-period",
                            period = fixed(period, 2),
                            target = localize(seconds.to_string()),
                            tolerance = fixed(tolerance * 100.0, 0)
                        )),
                    }
                }
                None => CheckState {
                    met: false,
                    finding: Some(tr!("check-no-flip")),
                },
            },
            Check::MomentsEqual { tolerance } => {
                let m = s.sim().body().moments();
                let closest = (m[1] - m[0]).min(m[2] - m[1]).abs() / m[2];
                CheckState {
                    met: closest <= *tolerance,
                    finding: Some(tr!(
                        "check-moments-apart",
                        apart = fixed(closest * 100.0, 1)
                    )),
                }
            }
            Check::Poked => match s.last_poke() {
                Some(p) if s.pokes() > snapshot.pokes => {
                    let off = (p.measured - p.predicted).norm() / p.predicted.norm().max(1e-300);
                    CheckState {
                        met: off <= IDENTITY,
                        finding: Some(format!(
                            "ΔL = {} kg·m²/s, r × J = {} kg·m²/s",
                            sci(p.measured.norm(), 3),
                            sci(p.predicted.norm(), 3)
                        )),
                    }
                }
                _ => met(false),
            },
            Check::Conserved { seconds, tolerance } => {
                let quiet = now - snapshot.changed_at.max(s.history().disturbed_at());
                let drift = s.history().energy_drift().map_or(0.0, |(_, max)| max);
                CheckState {
                    met: quiet >= *seconds && drift <= *tolerance,
                    finding: Some(tr!(
                        "check-conserved",
                        passed = fixed(quiet.clamp(0.0, *seconds), 1),
                        seconds = fixed(*seconds, 0),
                        drift = sci(drift, 1)
                    )),
                }
            }
            Check::Elapsed { seconds } => {
                let passed = now - snapshot.time;
                CheckState {
                    met: passed >= *seconds,
                    finding: Some(tr!(
                        "check-elapsed",
                        passed = fixed(passed.clamp(0.0, *seconds), 1),
                        seconds = fixed(*seconds, 0)
                    )),
                }
            }
            Check::Parts { at_least } => {
                let n = s.body().composition.as_ref().map_or(1, |c| c.parts.len());
                CheckState {
                    met: n >= *at_least,
                    finding: Some(tr!("check-parts", parts = n)),
                }
            }
            Check::PartMoved { distance } => part_moved(lab, snapshot, *distance),
        }
    }
}

/// [`Check::PartMoved`]: one part moved by `distance` or more, the rest stayed, and the
/// tensor about the origin changed by exactly m(|p₁|² − |p₀|²)E − m(p₁p₁ᵀ − p₀p₀ᵀ).
fn part_moved(lab: &Lab, snapshot: &Snapshot, distance: f64) -> CheckState {
    let (parts, inertia) = composition(lab);
    let (Some(before), Some(after)) = (&snapshot.inertia_origin, inertia) else {
        return CheckState::default();
    };
    if parts.len() != snapshot.parts.len() {
        return CheckState::default();
    }
    let moved: Vec<usize> = (0..parts.len())
        .filter(|&k| (parts[k].1 - snapshot.parts[k].1).norm() > 1e-12)
        .collect();
    let &[k] = moved.as_slice() else {
        return CheckState::default();
    };
    let (m, p1) = parts[k];
    let (m0, p0) = snapshot.parts[k];
    let d = (p1 - p0).norm();
    if (m - m0).abs() > IDENTITY * m.abs() {
        return CheckState::default();
    }
    let shift = |p: &Point3<f64>| about_origin(m, p, &Matrix3::zeros());
    let predicted = shift(&p1) - shift(&p0);
    let measured = after - before;
    let off = (measured - predicted).amax() / before.amax();
    CheckState {
        met: d >= distance && off <= IDENTITY,
        finding: Some(tr!(
            "check-part-moved",
            mass = fixed(m, 3),
            distance = fixed(d, 3),
            measured = sci(measured.amax(), 4),
            predicted = sci(predicted.amax(), 4)
        )),
    }
}
