//! Fixed-step simulation with an accumulator, pause/step/reset, catch-up cap and divergence guard.

use nalgebra::{Point3, Vector3};

use crate::body::{Body, check_finite_vec};
use crate::diagnostics::Diagnostics;
use crate::error::{BodyError, SimError};
use crate::forces::{Damping, ForceModel, SoftString, Spring, gravity_potential};
use crate::integrators::{Integrator, RotationModel};

/// Largest accepted time step (s): beyond it no integrator here is meaningful for a body turning
/// at ordinary rates, and the implicit solves may fail to converge.
pub const MAX_DT: f64 = 1.0;

/// State magnitude beyond which a run is declared diverged (squares stay finite).
const DIVERGENCE_BOUND: f64 = 1e150;

/// Simulation settings, in the spirit of rapier's `IntegrationParameters`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Fixed time step (s), `0 < dt ≤ 1`. Default 1/240.
    pub dt: f64,
    /// Integrator. Default [`Integrator::MidpointCayley`].
    pub integrator: Integrator,
    /// Rotation model. Default [`RotationModel::Full`].
    pub model: RotationModel,
    /// Gravitational acceleration (m/s²), applied at the centre of mass. Default zero: the lab's
    /// first scene is a free body.
    pub gravity: Vector3<f64>,
    /// Linear and angular damping rates. Default none.
    pub damping: Damping,
    /// Most steps one [`Simulation::advance`] (or [`Simulation::advance_with`]) call may run; the
    /// rest of a long frame is dropped
    /// (reported in [`Advance::dropped`]) so a slow frame cannot snowball. Default 16, ≥ 1.
    pub max_catch_up_steps: u32,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            dt: 1.0 / 240.0,
            integrator: Integrator::default(),
            model: RotationModel::default(),
            gravity: Vector3::zeros(),
            damping: Damping::default(),
            max_catch_up_steps: 16,
        }
    }
}

impl Settings {
    /// Checks every field.
    ///
    /// # Errors
    /// `dt` not in `(0, MAX_DT]`, non-finite gravity, negative damping, zero catch-up cap.
    pub fn validate(&self) -> Result<(), BodyError> {
        if !(self.dt > 0.0 && self.dt <= MAX_DT) {
            return Err(BodyError::OutOfRange {
                name: "dt",
                requirement: "in (0, 1] s",
                value: self.dt,
            });
        }
        check_finite_vec(&self.gravity, "gravity")?;
        self.damping.validate()?;
        if self.max_catch_up_steps == 0 {
            return Err(BodyError::OutOfRange {
                name: "max catch-up steps",
                requirement: "at least 1",
                value: 0.0,
            });
        }
        Ok(())
    }
}

/// What one [`Simulation::advance`] or [`Simulation::advance_with`] did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Advance {
    /// Whole steps run.
    pub steps: u32,
    /// Frame time discarded by the catch-up cap (s).
    pub dropped: f64,
}

/// A body, its settings and the interaction forces, advanced deterministically in fixed steps.
///
/// ```
/// use nalgebra::{Point3, Vector3};
/// use rbcore::{Body, Settings, Simulation};
///
/// let body = Body::from_moments(2.0, Vector3::new(1.0, 2.0, 3.0)).unwrap();
/// let mut sim = Simulation::new(body, Settings::default()).unwrap(); // 1/240 s steps
/// // A poke J = (1, 0, 0) N·s at (0, 1, 0): Δp = J, ΔL = r × J = (0, 0, −1).
/// sim.poke(&Point3::new(0.0, 1.0, 0.0), &Vector3::new(1.0, 0.0, 0.0)).unwrap();
/// let run = sim.advance(1.0 / 60.0).unwrap(); // a frame of 1/60 s: four steps
/// assert_eq!((run.steps, sim.steps()), (4, 4));
/// assert!((sim.body().position().x - 0.5 / 60.0).abs() < 1e-15); // v = J/m
/// let d = sim.diagnostics();
/// assert!((d.angular_momentum - Vector3::new(0.0, 0.0, -1.0)).norm() < 1e-15);
/// // T = |J|²/2m + |L|²/2I₃: a spin about the major axis stays as it is.
/// assert!((d.kinetic - (0.25 + 1.0 / 6.0)).abs() < 1e-15);
/// assert!((d.omega_principal - Vector3::new(0.0, 0.0, -1.0 / 3.0)).norm() < 1e-15);
/// ```
#[derive(Clone, Debug)]
pub struct Simulation {
    settings: Settings,
    body: Body,
    initial: Body,
    forces: ForceModel,
    string: Option<SoftString>,
    /// Time and step count when `dt` last changed: time is `time_origin + (steps − steps_origin)·dt`,
    /// a product rather than a running sum, so t stays exactly n·dt to rounding.
    time_origin: f64,
    steps_origin: u64,
    steps: u64,
    accumulator: f64,
    paused: bool,
    halted: Option<SimError>,
}

impl Simulation {
    /// A simulation starting (and resetting) to `body`.
    ///
    /// # Errors
    /// Invalid settings.
    pub fn new(body: Body, settings: Settings) -> Result<Self, SimError> {
        settings.validate().map_err(SimError::InvalidSetting)?;
        Ok(Self {
            settings,
            body,
            initial: body,
            forces: ForceModel {
                gravity: settings.gravity,
                ..ForceModel::default()
            },
            string: None,
            time_origin: 0.0,
            steps_origin: 0,
            steps: 0,
            accumulator: 0.0,
            paused: false,
            halted: None,
        })
    }

    /// Current settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }
    /// Replaces the settings (takes effect at the next step).
    ///
    /// # Errors
    /// Invalid settings; the old ones stay.
    pub fn set_settings(&mut self, settings: Settings) -> Result<(), SimError> {
        settings.validate().map_err(SimError::InvalidSetting)?;
        self.time_origin = self.time();
        self.steps_origin = self.steps;
        self.settings = settings;
        self.forces.gravity = settings.gravity;
        Ok(())
    }
    /// The body.
    pub fn body(&self) -> &Body {
        &self.body
    }
    /// Mutable access to the body (its setters validate their input).
    pub fn body_mut(&mut self) -> &mut Body {
        &mut self.body
    }
    /// Simulated time (s).
    pub fn time(&self) -> f64 {
        self.time_origin + (self.steps - self.steps_origin) as f64 * self.settings.dt
    }
    /// Steps taken since the start or the last reset.
    pub fn steps(&self) -> u64 {
        self.steps
    }
    /// Stops [`Simulation::advance`] from running steps.
    pub fn pause(&mut self) {
        self.paused = true;
    }
    /// Lets [`Simulation::advance`] run again.
    pub fn resume(&mut self) {
        self.paused = false;
    }
    /// Whether paused.
    pub fn is_paused(&self) -> bool {
        self.paused
    }
    /// Back to the initial body at t = 0; clears the accumulator, the string and a divergence
    /// halt. Settings, the spring and the paused flag are kept.
    pub fn reset(&mut self) {
        self.body = self.initial;
        self.time_origin = 0.0;
        self.steps_origin = 0;
        self.steps = 0;
        self.accumulator = 0.0;
        self.string = None;
        self.halted = None;
    }
    /// Attaches or removes the plain spring-damper.
    pub fn set_spring(&mut self, spring: Option<Spring>) {
        self.forces.spring = spring;
    }
    /// Attaches (grab) or removes (release) the soft mouse string.
    pub fn set_string(&mut self, string: Option<SoftString>) {
        self.string = string;
    }
    /// The soft string, if attached (what the next step will apply).
    pub fn string(&self) -> Option<&SoftString> {
        self.string.as_ref()
    }
    /// The soft string, to move its target.
    pub fn string_mut(&mut self) -> Option<&mut SoftString> {
        self.string.as_mut()
    }
    /// The poke: impulse `J` at world point `x`, now (`Δp = J`, `ΔL = (x − r) × J`).
    ///
    /// # Errors
    /// Non-finite input.
    pub fn poke(&mut self, x: &Point3<f64>, j: &Vector3<f64>) -> Result<(), BodyError> {
        self.body.apply_impulse_at(x, j)
    }

    /// Adds `frame_dt` to the accumulator and runs the whole steps it holds (at most
    /// `max_catch_up_steps`). Paused: runs nothing. Deterministic for a given sequence of calls.
    ///
    /// # Errors
    /// A negative or non-finite `frame_dt`, or divergence (then every later call returns the
    /// same error until [`Simulation::reset`]).
    pub fn advance(&mut self, frame_dt: f64) -> Result<Advance, SimError> {
        self.advance_with(frame_dt, |_| {})
    }

    /// [`Simulation::advance`], calling `on_step(self)` after every completed step, so a caller
    /// can record diagnostics at every step rather than once per frame. The steps, accumulator
    /// and catch-up cap are exactly those of `advance` (which is this with a no-op callback).
    ///
    /// # Errors
    /// As [`Simulation::advance`]. A step that diverges mid-frame returns its error after the
    /// callbacks of the steps before it have run; the failed step gets no callback.
    pub fn advance_with(
        &mut self,
        frame_dt: f64,
        mut on_step: impl FnMut(&Simulation),
    ) -> Result<Advance, SimError> {
        if let Some(e) = &self.halted {
            return Err(e.clone());
        }
        if !(frame_dt >= 0.0 && frame_dt.is_finite()) {
            return Err(SimError::InvalidSetting(BodyError::OutOfRange {
                name: "frame time",
                requirement: "finite and non-negative",
                value: frame_dt,
            }));
        }
        let dt = self.settings.dt;
        let mut steps = 0;
        if !self.paused {
            self.accumulator += frame_dt;
            // A relative slack of 1e-9 keeps frame_dt = n·dt from losing a step to rounding.
            while self.accumulator >= dt * (1.0 - 1e-9) && steps < self.settings.max_catch_up_steps
            {
                self.step()?;
                self.accumulator -= dt;
                steps += 1;
                on_step(self);
            }
        }
        let mut dropped = 0.0;
        if self.accumulator >= dt {
            dropped = (self.accumulator / dt).floor() * dt;
            self.accumulator -= dropped;
        }
        Ok(Advance { steps, dropped })
    }

    /// Runs exactly one step of `dt` (also while paused: single-stepping).
    ///
    /// # Errors
    /// Divergence: the body stays at the last good state and the simulation halts.
    pub fn step(&mut self) -> Result<(), SimError> {
        if let Some(e) = &self.halted {
            return Err(e.clone());
        }
        let h = self.settings.dt;
        let mut b = self.body;
        if let Some(s) = &self.string {
            let x = b.point_to_world(&s.attachment());
            let j = s.impulse(&b, h);
            b.momentum += j;
            b.angular_momentum += (x - b.position).cross(&j);
        }
        self.settings.damping.apply(&mut b, 0.5 * h);
        self.settings
            .integrator
            .step(&mut b, &self.forces, h, self.settings.model);
        self.settings.damping.apply(&mut b, 0.5 * h);
        if let Some((quantity, value)) = divergence(&b) {
            let e = SimError::Diverged {
                time: self.time() + h,
                step: self.steps + 1,
                quantity,
                value,
            };
            self.halted = Some(e.clone());
            return Err(e);
        }
        self.body = b;
        self.steps += 1;
        Ok(())
    }

    /// Diagnostics of the current state.
    pub fn diagnostics(&self) -> Diagnostics {
        let b = &self.body;
        let kinetic = b.kinetic_translational() + b.kinetic_rotational();
        let ug = gravity_potential(b, &self.settings.gravity);
        let us = self.forces.spring.as_ref().map_or(0.0, |s| s.potential(b))
            + self.string.as_ref().map_or(0.0, |s| s.potential(b));
        let l = b.angular_momentum;
        Diagnostics {
            time: self.time(),
            omega_principal: b.omega_principal(),
            omega_world: b.omega_world(),
            angular_momentum: l,
            angular_momentum_norm: l.norm(),
            orientation: b.orientation,
            potential_gravity: ug,
            kinetic,
            potential: ug + us,
            energy: kinetic + ug + us,
        }
    }
}

/// The first state quantity that is non-finite or beyond [`DIVERGENCE_BOUND`].
fn divergence(b: &Body) -> Option<(&'static str, f64)> {
    let checks = [
        ("position", b.position.coords.norm()),
        ("momentum", b.momentum.norm()),
        ("angular momentum", b.angular_momentum.norm()),
        ("orientation", b.orientation.coords.norm()),
        ("rotational energy", b.kinetic_rotational()),
    ];
    checks
        .into_iter()
        .find(|(_, v)| !(v.is_finite() && *v < DIVERGENCE_BOUND))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sim() -> Simulation {
        let mut b = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).expect("valid");
        b.set_omega_principal(Vector3::new(0.1, 1.0, 0.1))
            .expect("finite");
        Simulation::new(b, Settings::default()).expect("valid settings")
    }

    #[test]
    fn rejects_bad_settings() {
        let b = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).expect("valid");
        for dt in [0.0, -1.0, f64::NAN, f64::INFINITY, 2.0] {
            let s = Settings {
                dt,
                ..Settings::default()
            };
            assert!(Simulation::new(b, s).is_err());
        }
        let s = Settings {
            gravity: Vector3::new(0.0, f64::NAN, 0.0),
            ..Settings::default()
        };
        assert!(Simulation::new(b, s).is_err());
        let s = Settings {
            damping: Damping {
                linear: -1.0,
                angular: 0.0,
            },
            ..Settings::default()
        };
        assert!(Simulation::new(b, s).is_err());
        let mut ok = sim();
        assert!(ok.advance(f64::NAN).is_err());
        assert!(ok.advance(-0.1).is_err());
    }

    #[test]
    fn accumulator_runs_whole_steps_caps_catch_up_and_pauses() {
        let mut s = sim();
        // 1/60 s frames at 240 Hz: exactly 4 steps each.
        for _ in 0..3 {
            assert_eq!(s.advance(1.0 / 60.0).expect("ok").steps, 4);
        }
        assert_eq!(s.steps(), 12);
        // Half a step carries over.
        assert_eq!(s.advance(0.5 / 240.0).expect("ok").steps, 0);
        assert_eq!(s.advance(0.5 / 240.0).expect("ok").steps, 1);
        // A 1 s hitch runs only 16 steps and drops the rest.
        let a = s.advance(1.0).expect("ok");
        assert_eq!(a.steps, 16);
        assert!((a.dropped - (240.0 - 16.0) / 240.0).abs() < 1e-9);
        s.pause();
        assert_eq!(s.advance(1.0).expect("ok").steps, 0);
        s.step().expect("single step while paused");
        assert_eq!(s.steps(), 30);
        s.reset();
        assert_eq!((s.steps(), s.time()), (0, 0.0));
        assert_eq!(s.body(), &sim().body);
    }

    #[test]
    fn advance_with_reports_every_step_of_a_capped_frame() {
        let s0 = sim();
        let dt = s0.settings().dt;
        assert_eq!(s0.settings().max_catch_up_steps, 16);
        let mut s = s0.clone();
        let mut seen = Vec::new();
        let a = s
            .advance_with(20.0 * dt, |sim| {
                seen.push((*sim.body(), sim.steps(), sim.time()));
            })
            .expect("stable");
        assert_eq!(a.steps, 16);
        assert_eq!(seen.len(), 16);
        assert!(
            (a.dropped - 4.0 * dt).abs() <= 1e-12 * 4.0 * dt,
            "{}",
            a.dropped
        );
        assert_eq!(s.time(), 16.0 * dt);
        // The callback sees each state as it is reached, identical to plain single steps.
        let mut reference = s0.clone();
        for (i, (body, steps, time)) in seen.iter().enumerate() {
            reference.step().expect("stable");
            assert_eq!(*steps, i as u64 + 1);
            assert_eq!(time.to_bits(), reference.time().to_bits());
            assert_eq!(
                body.position.map(f64::to_bits),
                reference.body.position.map(f64::to_bits)
            );
            assert_eq!(
                body.momentum.map(f64::to_bits),
                reference.body.momentum.map(f64::to_bits)
            );
            assert_eq!(
                body.orientation.coords.map(f64::to_bits),
                reference.body.orientation.coords.map(f64::to_bits)
            );
            assert_eq!(
                body.angular_momentum.map(f64::to_bits),
                reference.body.angular_momentum.map(f64::to_bits)
            );
        }
        // advance is advance_with without the callback: same steps, drop and state.
        let mut plain = s0.clone();
        assert_eq!(plain.advance(20.0 * dt), Ok(a));
        assert_eq!(plain.body(), s.body());
    }

    #[test]
    fn advance_with_reports_the_good_steps_before_a_divergence() {
        // A plain spring far too stiff for the step diverges after some steps; find how many
        // succeed by single-stepping a clone, then run them all in one frame.
        let mut s = sim();
        s.set_settings(Settings {
            max_catch_up_steps: 10_000,
            ..Settings::default()
        })
        .expect("valid");
        let grabbed = s.body().point_to_world(&Point3::new(0.5, 0.0, 0.0));
        let k = (2.0 * std::f64::consts::PI * 3000.0f64).powi(2);
        let spring = Spring::new(grabbed, Point3::new(0.5, 0.0, 0.0), k, 0.0).expect("valid");
        s.set_spring(Some(spring));
        let mut probe = s.clone();
        let good = (0..10_000).take_while(|_| probe.step().is_ok()).count();
        assert!(good > 0 && good < 10_000, "{good}");
        let mut calls = 0;
        let result = s.advance_with(10_000.0 * s.settings().dt, |_| calls += 1);
        assert!(
            matches!(result, Err(SimError::Diverged { .. })),
            "{result:?}"
        );
        assert_eq!(calls, good);
        assert_eq!(s.steps(), good as u64);
        assert_eq!(s.body(), probe.body());
    }

    #[test]
    fn string_is_readable_and_cleared_by_reset() {
        let mut s = sim();
        assert!(s.string().is_none());
        let string = SoftString::new(
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.5, 0.0, 0.0),
            5.0,
            1.0,
            10.0,
        )
        .expect("valid");
        s.set_string(Some(string));
        assert_eq!(s.string(), Some(&string));
        s.string_mut()
            .expect("attached")
            .set_target(Point3::new(2.0, 0.0, 0.0))
            .expect("finite");
        assert_eq!(
            s.string().map(SoftString::target),
            Some(Point3::new(2.0, 0.0, 0.0))
        );
        s.reset();
        assert!(s.string().is_none());
    }

    #[test]
    fn determinism_same_calls_same_state() {
        let (mut a, mut b) = (sim(), sim());
        for i in 0..50 {
            let f = 0.003 + 0.001 * (i % 7) as f64;
            a.advance(f).expect("ok");
            b.advance(f).expect("ok");
        }
        assert_eq!(a.body(), b.body());
    }

    #[test]
    fn damping_decays_momenta_exponentially() {
        let mut s = sim();
        s.body_mut()
            .set_velocity(Vector3::new(1.0, 0.0, 0.0))
            .expect("finite");
        let l0 = s.body().angular_momentum();
        let damping = Damping {
            linear: 0.5,
            angular: 0.25,
        };
        s.set_settings(Settings {
            damping,
            ..Settings::default()
        })
        .expect("valid");
        for _ in 0..240 {
            s.step().expect("stable");
        }
        assert!((s.body().velocity().x - (-0.5f64).exp()).abs() < 1e-12);
        assert!((s.body().angular_momentum().norm() - l0.norm() * (-0.25f64).exp()).abs() < 1e-12);
    }
}
