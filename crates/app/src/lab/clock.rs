//! The frame clock: turns wall-clock time between frames into simulated time for the fixed-step
//! accumulator in `rbcore::Simulation::advance_with`, so the physics runs at the same speed
//! whatever the frame rate.
//!
//! The clock caps nothing: a slow frame or a stall (window hidden, a debugger) is bounded by
//! rbcore's catch-up cap, which runs at most its number of steps and reports the rest as
//! dropped, so the app can say how much simulated time it skipped.

use std::time::Duration;

use crate::platform::Instant;

/// Measures frame gaps and scales them by the time scale.
#[derive(Debug, Clone, Default)]
pub struct FrameClock {
    last: Option<Instant>,
}

impl FrameClock {
    /// A clock that has not ticked yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Simulated seconds to advance for the frame starting at `now`: the wall-clock gap since the
    /// previous tick times `time_scale` (a non-finite or negative
    /// scale counts as 0). The first tick after [`FrameClock::stop`] returns 0.
    pub fn tick(&mut self, now: Instant, time_scale: f64) -> f64 {
        let gap = self
            .last
            .map_or(Duration::ZERO, |last| now.saturating_duration_since(last));
        self.last = Some(now);
        let scale = if time_scale.is_finite() && time_scale > 0.0 {
            time_scale
        } else {
            0.0
        };
        gap.as_secs_f64() * scale
    }

    /// Forgets the last tick: while paused no time accrues, so resuming does not jump.
    pub fn stop(&mut self) {
        self.last = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gaps_are_scaled_uncapped_and_reset_by_stop() {
        let t0 = Instant::now();
        let mut c = FrameClock::new();
        assert_eq!(c.tick(t0, 1.0), 0.0);
        let t1 = t0 + Duration::from_millis(16);
        assert!((c.tick(t1, 0.5) - 0.008).abs() < 1e-12);
        let t2 = t1 + Duration::from_secs(5);
        assert!((c.tick(t2, 1.0) - 5.0).abs() < 1e-12);
        c.stop();
        assert_eq!(c.tick(t2 + Duration::from_secs(1), 1.0), 0.0);
        let t3 = t2 + Duration::from_millis(1010);
        assert_eq!(c.tick(t3, f64::NAN), 0.0);
        // Time going backwards (another clock source) is not negative time.
        assert_eq!(c.tick(t0, 1.0), 0.0);
    }

    #[test]
    fn simulated_time_is_independent_of_frame_rate() {
        use nalgebra::Vector3;
        use rbcore::{Body, Settings, Simulation};
        let run = |frame_ms: u64| {
            let mut b = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).expect("valid");
            b.set_omega_principal(Vector3::new(0.1, 5.0, 0.1))
                .expect("finite");
            let mut sim = Simulation::new(b, Settings::default()).expect("valid");
            let mut clock = FrameClock::new();
            let t0 = Instant::now();
            let frames = 3000 / frame_ms;
            for k in 0..=frames {
                let dt = clock.tick(t0 + Duration::from_millis(k * frame_ms), 1.0);
                sim.advance(dt).expect("stable");
            }
            sim
        };
        // 3 s of wall time at 50, 33 and 20 frames per second: the same number of fixed steps
        // (±1 from the accumulator remainder), so the same motion. (Below 15 fps the catch-up
        // cap of 16 steps drops time on purpose.)
        let (a, b, c) = (run(20), run(30), run(50));
        for s in [&b, &c] {
            assert!(
                a.steps().abs_diff(s.steps()) <= 1,
                "{} vs {}",
                a.steps(),
                s.steps()
            );
        }
        assert!(a.steps() >= 719);
    }
}
