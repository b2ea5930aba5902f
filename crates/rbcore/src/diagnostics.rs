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
    /// Principal → world orientation.
    pub orientation: UnitQuaternion<f64>,
    /// `−m g·r`.
    pub potential_gravity: f64,
    /// `T = |p|²/2m + ½ L·ω`, translational plus rotational kinetic energy.
    pub kinetic: f64,
    /// `U`: gravity plus the plain spring's energy plus the soft string's equivalent spring
    /// energy.
    pub potential: f64,
    /// `E = T + U`.
    pub energy: f64,
}

/// The relative change of `value` from `reference`, `(value − reference)/|reference|`: positive
/// when the value grew, whatever the sign of the reference (an energy may be negative).
///
/// `Some(0.0)` when `value == reference`, even for a zero reference. `None` when the reference is
/// zero or subnormal (`|reference| ≤ f64::MIN_POSITIVE`) and the value differs: a change from
/// zero has no relative size, and dividing by a subnormal would overflow to a meaningless huge
/// number. NaN inputs give `Some(NaN)` (NaN value) or `None` (NaN reference).
pub fn relative_change(value: f64, reference: f64) -> Option<f64> {
    if has_relative_size(reference) {
        Some((value - reference) / reference.abs())
    } else if value == reference {
        Some(0.0)
    } else {
        None
    }
}

/// Whether a change can be measured relative to `reference`: it is neither zero, subnormal nor NaN.
fn has_relative_size(reference: f64) -> bool {
    reference.abs() > f64::MIN_POSITIVE
}

/// Maximum drifts from the first observed state: of |L| (`||L| − |L₀||/|L₀|`), of the world L
/// vector (`|L − L₀|/|L₀|`) and of E (`|E − E₀|/|E₀|`).
///
/// Where the reference has no relative size ([`relative_change`] gives `None`: `|L₀|` or `E₀`
/// zero or subnormal), that drift is reported **absolute** instead, in the quantity's own units
/// (N·m·s for L, J for E), so a body starting at rest still shows that it moved; it stays 0 as
/// long as the quantity stays exactly at its zero reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DriftTracker {
    l0: Vector3<f64>,
    e0: f64,
    max_l_norm: f64,
    max_l_vector: f64,
    max_energy: f64,
}

/// `|relative_change(value, reference)|`, or the absolute change where that has no relative size.
fn drift(value: f64, reference: f64) -> f64 {
    relative_change(value, reference).map_or((value - reference).abs(), f64::abs)
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
        self.max_l_norm = self.max_l_norm.max(drift(d.angular_momentum_norm, n0));
        // |L − L₀|/|L₀| is a distance over a length, not the change of one number, so it cannot go
        // through relative_change; it follows the same rule about which references have a size.
        let moved = (d.angular_momentum - self.l0).norm();
        let vector = if has_relative_size(n0) {
            moved / n0
        } else {
            moved
        };
        self.max_l_vector = self.max_l_vector.max(vector);
        self.max_energy = self.max_energy.max(drift(d.energy, self.e0));
    }
    /// Largest relative change of |L| seen (absolute where `|L₀|` is zero: see the type's doc).
    pub fn max_l_norm(&self) -> f64 {
        self.max_l_norm
    }
    /// Largest relative change of the world L vector seen (absolute where `|L₀|` is zero).
    pub fn max_l_vector(&self) -> f64 {
        self.max_l_vector
    }
    /// Largest relative change of E seen (absolute where `E₀` is zero).
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
    /// Time of the last reversal, if any.
    pub fn last_crossing(&self) -> Option<f64> {
        self.crossings.last().copied()
    }
    /// Time between the last two reversals (half a period of ω₂ in torque-free motion).
    pub fn last_interval(&self) -> Option<f64> {
        match self.crossings[..] {
            [.., a, b] => Some(b - a),
            _ => None,
        }
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
        assert!((c.mean_period().expect("enough crossings") - period).abs() < 1e-6);
        // Two crossings are not a period yet.
        let mut short = FlipCounter::new();
        for (t, w) in [(0.0, 1.0), (1.0, -1.0), (2.0, 1.0)] {
            short.observe(t, w);
        }
        assert_eq!((short.flips(), short.mean_period()), (2, None));
        assert_eq!(short.last_interval(), Some(1.0));
        assert!((c.last_interval().expect("crossings") - period / 2.0).abs() < 1e-6);
        assert_eq!(FlipCounter::new().last_interval(), None);
    }

    #[test]
    fn relative_change_is_signed_by_growth_and_undefined_from_zero() {
        assert_eq!(relative_change(3.0, 2.0), Some(0.5));
        assert_eq!(relative_change(1.0, 2.0), Some(-0.5));
        // A negative reference (a bound energy): growing toward zero is a positive change.
        assert_eq!(relative_change(-1.0, -2.0), Some(0.5));
        assert_eq!(relative_change(-3.0, -2.0), Some(-0.5));
        assert_eq!(relative_change(-2.0, 2.0), Some(-2.0));
        // No change is zero even from zero; any change from zero or a subnormal has no size.
        assert_eq!(relative_change(0.0, 0.0), Some(0.0));
        assert_eq!(relative_change(-0.0, 0.0), Some(0.0));
        assert_eq!(relative_change(1e-300, 0.0), None);
        assert_eq!(relative_change(-1.0, -0.0), None);
        assert_eq!(relative_change(1.0, f64::MIN_POSITIVE), None);
        assert_eq!(relative_change(1.0, f64::MIN_POSITIVE / 4.0), None);
        // The smallest normal number above MIN_POSITIVE is a reference again.
        let tiny = f64::MIN_POSITIVE * 2.0;
        assert_eq!(relative_change(3.0 * tiny, tiny), Some(2.0));
        assert_eq!(relative_change(1.0, f64::NAN), None);
        assert!(relative_change(f64::NAN, 1.0).is_some_and(f64::is_nan));
    }

    fn state(l: Vector3<f64>, energy: f64) -> Diagnostics {
        Diagnostics {
            time: 0.0,
            omega_principal: Vector3::zeros(),
            omega_world: Vector3::zeros(),
            angular_momentum: l,
            angular_momentum_norm: l.norm(),
            orientation: UnitQuaternion::identity(),
            potential_gravity: 0.0,
            kinetic: energy,
            potential: 0.0,
            energy,
        }
    }

    #[test]
    fn drift_tracker_is_relative_and_absolute_from_a_zero_reference() {
        let mut t = DriftTracker::new(&state(Vector3::new(0.0, 3.0, 4.0), -2.0));
        // |L| unchanged but L turned: only the vector drifts, by |(3, −3, 0)|/5.
        t.observe(&state(Vector3::new(3.0, 0.0, 4.0), -2.5));
        assert_eq!(t.max_l_norm(), 0.0);
        assert!((t.max_l_vector() - 18f64.sqrt() / 5.0).abs() < 1e-15);
        // E from −2 to −2.5 is a 25 % change whatever the sign convention.
        assert_eq!(t.max_energy(), 0.25);
        // Maxima are kept.
        t.observe(&state(Vector3::new(0.0, 3.0, 4.0), -2.1));
        assert_eq!(t.max_energy(), 0.25);

        // A body at rest at the origin: L₀ = 0 and E₀ = 0 have no relative size, so the drifts
        // are absolute (N·m·s, J), and exactly zero while nothing moves.
        let mut rest = DriftTracker::new(&state(Vector3::zeros(), 0.0));
        rest.observe(&state(Vector3::zeros(), 0.0));
        assert_eq!(
            (rest.max_l_norm(), rest.max_l_vector(), rest.max_energy()),
            (0.0, 0.0, 0.0)
        );
        rest.observe(&state(Vector3::new(0.0, 3e-9, 4e-9), -1e-6));
        assert!((rest.max_l_norm() - 5e-9).abs() < 1e-24);
        assert!((rest.max_l_vector() - 5e-9).abs() < 1e-24);
        assert_eq!(rest.max_energy(), 1e-6);
    }
}
