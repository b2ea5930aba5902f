//! The motion as keyframes: the body's pose at evenly spaced times, for a file that plays it back
//! (glTF animation channels, USD time samples).
//!
//! A keyframe is the simulation's own state at that time, never an interpolation: the frame
//! interval is made a whole number of steps (the step shortened where `dt` does not divide it),
//! so the integrator lands on every frame. Consecutive quaternions are kept in one hemisphere
//! (q and −q are one rotation) so that a player interpolating between them turns the short way.

use nalgebra::{Point3, UnitQuaternion};

use crate::error::{BodyError, SimError};
use crate::simulation::{MAX_DT, Simulation};

/// The body's pose at one time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Simulated time (s).
    pub time: f64,
    /// Centre of mass in world.
    pub position: Point3<f64>,
    /// Body (mesh) axes → world ([`crate::Body::body_orientation`]).
    pub orientation: UnitQuaternion<f64>,
}

/// The poses at `fps` frames a second over `duration` seconds, and the step that made them.
#[derive(Debug, Clone, PartialEq)]
pub struct Keyframes {
    /// Frames a second.
    pub fps: f64,
    /// The step the simulation ran at: its `dt`, or the largest below it dividing 1/fps.
    pub dt: f64,
    /// One pose a frame, the first at the simulation's time when sampling began.
    pub poses: Vec<Pose>,
}

/// The most frames one call makes: a day at 10 frames a second, and few enough that every
/// frame's time stays distinct in single precision (glTF keys its animations in f32).
pub const MAX_FRAMES: f64 = 1e6;

/// Runs `sim` for `duration` seconds and returns its pose every 1/`fps` s, frame 0 its present
/// state. The step is set to the largest at or below the simulation's `dt` that divides the
/// frame interval, so that every keyframe is a state the integrator reached.
///
/// # Errors
/// `fps` or `duration` out of range ([`SimError::InvalidSetting`]), or divergence.
///
/// ```
/// use nalgebra::Vector3;
/// use rbcore::{Body, Integrator, Settings, Simulation, keyframes};
///
/// let mut body = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).unwrap();
/// body.set_omega_principal(Vector3::new(0.0, 0.0, 1.0)).unwrap();
/// let settings = Settings { integrator: Integrator::Exact, ..Settings::default() };
/// let mut sim = Simulation::new(body, settings).unwrap();
/// let k = keyframes(&mut sim, 2.0, 25.0).unwrap();
/// assert_eq!(k.poses.len(), 51);
/// // A steady spin about axis 3: after 2 s it has turned 2 rad about z.
/// let (axis, angle) = k.poses[50].orientation.axis_angle().unwrap();
/// assert!((angle - 2.0).abs() < 1e-9 && (axis.z - 1.0).abs() < 1e-12);
/// ```
pub fn keyframes(sim: &mut Simulation, duration: f64, fps: f64) -> Result<Keyframes, SimError> {
    let invalid = |name, requirement, value| {
        SimError::InvalidSetting(BodyError::OutOfRange {
            name,
            requirement,
            value,
        })
    };
    if !(fps.is_finite() && fps > 0.0 && 1.0 / fps <= 3600.0) {
        return Err(invalid("fps", "positive, a frame at most an hour", fps));
    }
    if !(duration.is_finite() && duration >= 0.0) {
        return Err(invalid("duration", "finite and >= 0", duration));
    }
    let frames = (duration * fps).round();
    if frames > MAX_FRAMES {
        return Err(invalid("duration x fps", "at most 1e6 frames", frames));
    }
    let interval = 1.0 / fps;
    let dt = sim.settings().dt.min(MAX_DT);
    // The step count a frame: dt divides the interval when it is within rounding of a whole
    // number of steps (1/240 in 1/30), else one more step than fits, each shorter.
    let ratio = interval / dt;
    let steps_per_frame = if (ratio - ratio.round()).abs() <= 1e-9 * ratio {
        ratio.round().max(1.0)
    } else {
        ratio.ceil()
    };
    let mut settings = *sim.settings();
    settings.dt = interval / steps_per_frame;
    sim.set_settings(settings)?;
    let pose = |sim: &Simulation| Pose {
        time: sim.time(),
        position: sim.body().position(),
        orientation: sim.body().body_orientation(),
    };
    let mut poses = Vec::with_capacity(frames as usize + 1);
    poses.push(pose(sim));
    for _ in 0..frames as u64 {
        for _ in 0..steps_per_frame as u64 {
            sim.step()?;
        }
        let mut next = pose(sim);
        let previous = poses.last().map_or(next.orientation, |p| p.orientation);
        if next.orientation.coords.dot(&previous.coords) < 0.0 {
            next.orientation = UnitQuaternion::new_unchecked(-next.orientation.into_inner());
        }
        poses.push(next);
    }
    Ok(Keyframes {
        fps,
        dt: settings.dt,
        poses,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Body, Integrator, Settings};
    use nalgebra::Vector3;

    fn tumbling(integrator: Integrator, dt: f64) -> Simulation {
        let mut body = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).expect("body");
        body.set_omega_principal(Vector3::new(0.001, 10.0, 0.001))
            .expect("omega");
        let settings = Settings {
            dt,
            integrator,
            ..Settings::default()
        };
        Simulation::new(body, settings).expect("simulation")
    }

    /// Each keyframe is the state the same simulation, stepped on its own, has at that time.
    #[test]
    fn keyframes_are_the_simulations_states() {
        let mut sim = tumbling(Integrator::MidpointCayley, 1.0 / 240.0);
        let mut alone = sim.clone();
        let k = keyframes(&mut sim, 3.0, 30.0).expect("keyframes");
        assert_eq!(k.dt, 1.0 / 240.0);
        assert_eq!(k.poses.len(), 91);
        for (n, pose) in k.poses.iter().enumerate() {
            if n > 0 {
                for _ in 0..8 {
                    alone.step().expect("step");
                }
            }
            let q = alone.body().body_orientation();
            assert_eq!(pose.time, alone.time());
            assert!((pose.time - n as f64 / 30.0).abs() < 1e-12);
            assert!(
                pose.orientation.angle_to(&q) < 1e-12,
                "frame {n}: {}",
                pose.orientation.angle_to(&q)
            );
            assert_eq!(pose.position, alone.body().position());
        }
    }

    /// A step that does not divide the frame interval is shortened to one that does: the exact
    /// flow's keyframes are the same whatever step it is given.
    #[test]
    fn a_step_that_does_not_divide_a_frame_is_shortened() {
        let mut sim = tumbling(Integrator::Exact, 0.007);
        let k = keyframes(&mut sim, 2.0, 24.0).expect("keyframes");
        // 1/24 s is 5.95 steps of 7 ms: six steps of 1/144 s.
        assert!((k.dt - 1.0 / 144.0).abs() < 1e-15, "{}", k.dt);
        let mut reference = tumbling(Integrator::Exact, 1.0 / 24.0);
        let r = keyframes(&mut reference, 2.0, 24.0).expect("keyframes");
        assert_eq!(r.dt, 1.0 / 24.0);
        for (a, b) in k.poses.iter().zip(&r.poses) {
            assert!((a.time - b.time).abs() < 1e-12);
            assert!(a.orientation.angle_to(&b.orientation) < 1e-9);
        }
    }

    /// Consecutive keyframes turn the short way: no two are in opposite hemispheres, over a run
    /// that turns many times.
    #[test]
    fn consecutive_quaternions_stay_in_one_hemisphere() {
        for integrator in Integrator::ALL {
            let mut sim = tumbling(integrator, 1.0 / 240.0);
            let k = keyframes(&mut sim, 20.0, 30.0).expect("keyframes");
            let mut turned = 0.0;
            for w in k.poses.windows(2) {
                assert!(
                    w[0].orientation.coords.dot(&w[1].orientation.coords) > 0.0,
                    "{integrator} at {} s",
                    w[1].time
                );
                turned += w[0].orientation.angle_to(&w[1].orientation);
            }
            assert!(turned > 100.0, "{turned}");
        }
    }

    #[test]
    fn bad_rates_and_durations_are_refused() {
        let mut sim = tumbling(Integrator::MidpointCayley, 1.0 / 240.0);
        for (duration, fps) in [
            (1.0, 0.0),
            (1.0, -30.0),
            (1.0, f64::NAN),
            (-1.0, 30.0),
            (f64::INFINITY, 30.0),
            (1e9, 30.0),
        ] {
            assert!(
                matches!(
                    keyframes(&mut sim, duration, fps),
                    Err(SimError::InvalidSetting(_))
                ),
                "{duration} {fps}"
            );
        }
    }
}
