//! Per-step diagnostics, drift tracking and flip counting.

use nalgebra::{UnitQuaternion, Vector3};

/// Everything the lab plots, for one instant. Energies in joules, frames as named.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Diagnostics {
    /// Simulated time.
    pub time: f64,
    /// ω in the principal body frame (moments ascending).
    pub omega_principal: Vector3<f64>,
    /// ω in world.
    pub omega_world: Vector3<f64>,
    /// World angular momentum about the centre of mass.
    pub angular_momentum: Vector3<f64>,
    /// `|L|`.
    pub angular_momentum_norm: f64,
    /// Linear momentum.
    pub momentum: Vector3<f64>,
    /// Principal → world orientation.
    pub orientation: UnitQuaternion<f64>,
    /// `|p|²/2m`.
    pub kinetic_translational: f64,
    /// `½ L·ω`.
    pub kinetic_rotational: f64,
    /// `−m g·r`.
    pub potential_gravity: f64,
    /// Plain spring energy plus the soft string's equivalent spring energy.
    pub potential_spring: f64,
    /// `T` = translational + rotational kinetic energy.
    pub kinetic: f64,
    /// `U` = gravity + spring potential.
    pub potential: f64,
    /// `E = T + U`.
    pub energy: f64,
}

/// Maximum relative drifts from the first observed state: of |L|, of the world L vector
/// (`|L(t) − L₀|/|L₀|`) and of E (`|E − E₀|/|E₀|`). A zero reference makes the drift absolute.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DriftTracker {
    l0: Vector3<f64>,
    e0: f64,
    max_l_norm: f64,
    max_l_vector: f64,
    max_energy: f64,
}

fn relative(diff: f64, reference: f64) -> f64 {
    if reference == 0.0 {
        diff.abs()
    } else {
        (diff / reference).abs()
    }
}

impl DriftTracker {
    /// Starts tracking from `d`.
    pub fn new(d: &Diagnostics) -> Self {
        Self {
            l0: d.angular_momentum,
            e0: d.energy,
            max_l_norm: 0.0,
            max_l_vector: 0.0,
            max_energy: 0.0,
        }
    }
    /// Folds in one more state.
    pub fn observe(&mut self, d: &Diagnostics) {
        let n0 = self.l0.norm();
        self.max_l_norm = self
            .max_l_norm
            .max(relative(d.angular_momentum_norm - n0, n0));
        self.max_l_vector = self
            .max_l_vector
            .max(relative((d.angular_momentum - self.l0).norm(), n0));
        self.max_energy = self.max_energy.max(relative(d.energy - self.e0, self.e0));
    }
    /// Largest relative change of |L| seen.
    pub fn max_l_norm(&self) -> f64 {
        self.max_l_norm
    }
    /// Largest relative change of the world L vector seen.
    pub fn max_l_vector(&self) -> f64 {
        self.max_l_vector
    }
    /// Largest relative change of E seen.
    pub fn max_energy(&self) -> f64 {
        self.max_energy
    }
}

/// Counts reversals (sign changes) of one component of ω, e.g. ω₂ for the intermediate-axis
/// flip, and records crossing times by linear interpolation between samples.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FlipCounter {
    last: Option<(f64, f64)>,
    crossings: Vec<f64>,
}

impl FlipCounter {
    /// An empty counter.
    pub fn new() -> Self {
        Self::default()
    }
    /// Feeds the component value `w` at time `t` (times increasing). Exact zeros are skipped so
    /// touching zero without crossing is not a flip.
    pub fn observe(&mut self, t: f64, w: f64) {
        if w == 0.0 || !w.is_finite() {
            return;
        }
        if let Some((t0, w0)) = self.last
            && (w0 > 0.0) != (w > 0.0)
        {
            self.crossings.push(t0 + (t - t0) * w0 / (w0 - w));
        }
        self.last = Some((t, w));
    }
    /// Number of reversals so far.
    pub fn flips(&self) -> usize {
        self.crossings.len()
    }
    /// Interpolated crossing times.
    pub fn crossings(&self) -> &[f64] {
        &self.crossings
    }
    /// Mean full period (two reversals) from the first to the last crossing; needs ≥ 3 crossings.
    pub fn mean_period(&self) -> Option<f64> {
        let n = self.crossings.len();
        (n >= 3).then(|| 2.0 * (self.crossings[n - 1] - self.crossings[0]) / (n - 1) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flip_counter_finds_the_zeros_of_a_sine() {
        // sin(2πt/T) with T = 1.3 sampled at 1 ms over 5 s: zeros at multiples of T/2.
        let period = 1.3;
        let mut c = FlipCounter::new();
        for i in 1..=5000 {
            let t = i as f64 * 1e-3;
            c.observe(t, (2.0 * std::f64::consts::PI * t / period).sin());
        }
        assert_eq!(c.flips(), 7); // zeros at 0.65, 1.3, …, 4.55 (t = 0 is not sampled)
        assert!((c.crossings()[0] - 0.65).abs() < 1e-6);
        assert!((c.mean_period().expect("enough crossings") - period).abs() < 1e-6);
    }
}
