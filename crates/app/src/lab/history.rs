//! The plotted time series: one sample per simulation step in a bounded ring buffer, the energy
//! drift since the last disturbance, decimation for drawing, and CSV export in the schema of
//! [`crate::timeseries`] (the columns of the `simulate` command).

use std::collections::VecDeque;
use std::io::{self, Write};

use rbcore::{Diagnostics, FlipCounter, relative_change};

use crate::timeseries::{QuaternionSign, Sample};

/// Bounded history of samples plus the energy reference for the drift readout.
#[derive(Debug, Clone)]
pub struct History {
    samples: VecDeque<Sample>,
    capacity: usize,
    energy_reference: Option<f64>,
    max_drift: f64,
    sign: QuaternionSign,
    /// Reversals of ω₂ since the last disturbance.
    flips: FlipCounter,
    /// Time of the last sample before the last disturbance (−∞ if none).
    disturbed_at: f64,
}

impl History {
    /// An empty history holding at most `capacity` samples (≥ 2).
    pub fn new(capacity: usize) -> Self {
        Self {
            samples: VecDeque::with_capacity(capacity.clamp(2, 1 << 16)),
            capacity: capacity.max(2),
            energy_reference: None,
            max_drift: 0.0,
            sign: QuaternionSign::default(),
            flips: FlipCounter::new(),
            disturbed_at: f64::NEG_INFINITY,
        }
    }

    /// Changes the bound, dropping the oldest samples if needed.
    pub fn set_capacity(&mut self, capacity: usize) {
        self.capacity = capacity.max(2);
        while self.samples.len() > self.capacity {
            self.samples.pop_front();
        }
    }

    /// Appends a sample of `d` (skipped if not finite; returns whether it was kept). Samples must
    /// come in time order; one older than the last (after a reset) clears the history first.
    pub fn push(&mut self, d: &Diagnostics) -> bool {
        let mut s = Sample::new(d);
        if !s.is_finite() {
            return false;
        }
        if self.samples.back().is_some_and(|last| s.t < last.t) {
            self.clear();
        }
        self.sign.apply(&mut s);
        self.flips.observe(s.t, s.omega_principal[1]);
        let reference = *self.energy_reference.get_or_insert(s.energy);
        if let Some(drift) = relative_change(s.energy, reference) {
            self.max_drift = self.max_drift.max(drift.abs());
        }
        if self.samples.len() == self.capacity {
            self.samples.pop_front();
        }
        self.samples.push_back(s);
        true
    }

    /// Forgets all samples and the energy reference.
    pub fn clear(&mut self) {
        self.samples.clear();
        self.sign.reset();
        self.mark_disturbance();
    }

    /// Energy changed for a reason (poke, string, new mass properties, settings): the next sample
    /// becomes the reference the drift is measured from.
    pub fn mark_disturbance(&mut self) {
        self.energy_reference = None;
        self.max_drift = 0.0;
        self.flips = FlipCounter::new();
        self.disturbed_at = self.last().map_or(f64::NEG_INFINITY, |s| s.t);
    }

    /// Time of the last disturbance: samples from before it belong to another motion (another
    /// E, L or inertia), so paths drawn on the current one start after it.
    pub fn disturbed_at(&self) -> f64 {
        self.disturbed_at
    }

    /// The samples, oldest first.
    pub fn samples(&self) -> &VecDeque<Sample> {
        &self.samples
    }

    /// Latest sample.
    pub fn last(&self) -> Option<&Sample> {
        self.samples.back()
    }

    /// (current, largest) relative energy drift (E − E₀) / |E₀| since the reference; `None` when
    /// E changed from a zero reference (a body at rest has no scale to be relative to).
    pub fn energy_drift(&self) -> Option<(f64, f64)> {
        let current = relative_change(self.last()?.energy, self.energy_reference?)?;
        Some((current, self.max_drift))
    }

    /// Simulated time of the last reversal of ω₂ since the last disturbance, if any.
    pub fn last_reversal(&self) -> Option<f64> {
        self.flips.last_crossing()
    }

    /// Time between the last two reversals of ω₂ since the last disturbance (half the flip
    /// period of torque-free motion), once two have happened.
    pub fn flip_interval(&self) -> Option<f64> {
        self.flips.last_interval()
    }

    /// Points `[t, value(sample)]` from time `since` on, at most about `max_points` of them:
    /// each bucket of consecutive samples contributes its minimum and maximum, so spikes survive
    /// decimation while the plot costs the same for 60 s of history as for 1 s.
    pub fn series(
        &self,
        since: f64,
        max_points: usize,
        value: impl Fn(&Sample) -> f64,
    ) -> Vec<[f64; 2]> {
        let start = self.samples.partition_point(|s| s.t < since);
        let n = self.samples.len() - start;
        let buckets = (max_points / 2).clamp(1, n.max(1));
        let per_bucket = n.div_ceil(buckets).max(1);
        let mut out = Vec::with_capacity(2 * buckets);
        let mut i = start;
        while i < self.samples.len() {
            let end = (i + per_bucket).min(self.samples.len());
            if per_bucket == 1 {
                let s = &self.samples[i];
                out.push([s.t, value(s)]);
            } else {
                let (mut lo, mut hi) = (i, i);
                for k in i..end {
                    let v = value(&self.samples[k]);
                    if v < value(&self.samples[lo]) {
                        lo = k;
                    }
                    if v > value(&self.samples[hi]) {
                        hi = k;
                    }
                }
                for k in if lo <= hi { [lo, hi] } else { [hi, lo] } {
                    let s = &self.samples[k];
                    out.push([s.t, value(s)]);
                }
            }
            i = end;
        }
        out
    }

    /// Writes the history as CSV in the schema of [`crate::timeseries`].
    ///
    /// # Errors
    /// Writing to `out` failed.
    pub fn write_csv(&self, out: &mut dyn Write) -> io::Result<()> {
        crate::timeseries::write_csv(out, &self.samples)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;
    use rbcore::{Body, Settings, Simulation};

    fn sim() -> Simulation {
        let mut b = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).expect("valid");
        b.set_omega_principal(Vector3::new(0.1, 4.0, 0.1))
            .expect("finite");
        Simulation::new(b, Settings::default()).expect("valid")
    }

    #[test]
    fn bounded_time_ordered_and_finite() {
        let mut s = sim();
        let mut h = History::new(100);
        for _ in 0..250 {
            s.step().expect("stable");
            assert!(h.push(&s.diagnostics()));
        }
        assert_eq!(h.samples().len(), 100);
        assert!((h.samples()[0].t - 151.0 / 240.0).abs() < 1e-12);
        let mut bad = s.diagnostics();
        bad.energy = f64::NAN;
        assert!(!h.push(&bad));
        assert_eq!(h.samples().len(), 100);
        // A reset (time going back) starts over.
        s.reset();
        h.push(&s.diagnostics());
        assert_eq!(h.samples().len(), 1);
        h.set_capacity(1);
        assert_eq!(h.samples().len(), 1);
    }

    #[test]
    fn drift_is_relative_to_the_last_disturbance() {
        let mut s = sim();
        let mut h = History::new(10_000);
        h.push(&s.diagnostics());
        for _ in 0..1000 {
            s.step().expect("stable");
            h.push(&s.diagnostics());
        }
        let (now, max) = h.energy_drift().expect("reference");
        assert!(now.abs() <= max && max < 1e-10, "{now} {max}");
        h.mark_disturbance();
        let mut d = s.diagnostics();
        d.energy *= 2.0;
        h.push(&d);
        assert_eq!(h.energy_drift(), Some((0.0, 0.0)));
    }

    #[test]
    fn decimation_keeps_extremes_and_bounds_the_count() {
        let mut s = sim();
        let mut h = History::new(20_000);
        for _ in 0..14_400 {
            s.step().expect("stable");
            h.push(&s.diagnostics());
        }
        let all = h.series(0.0, usize::MAX, |s| s.omega_principal[1]);
        assert_eq!(all.len(), 14_400);
        let few = h.series(0.0, 1000, |s| s.omega_principal[1]);
        assert!(few.len() <= 1002, "{}", few.len());
        let max = |v: &[[f64; 2]]| v.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max);
        let min = |v: &[[f64; 2]]| v.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
        assert_eq!(max(&all), max(&few));
        assert_eq!(min(&all), min(&few));
        assert!(few.windows(2).all(|w| w[0][0] <= w[1][0]));
        let window = h.series(50.0, 1000, |s| s.t);
        assert!(window.iter().all(|p| p[0] >= 50.0));
    }

    #[test]
    fn csv_has_the_simulate_columns() {
        let mut s = sim();
        let mut h = History::new(10);
        for _ in 0..3 {
            s.step().expect("stable");
            h.push(&s.diagnostics());
        }
        let mut out = Vec::new();
        h.write_csv(&mut out).expect("in memory");
        let text = String::from_utf8(out).expect("utf-8");
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], crate::timeseries::CSV_HEADER);
        assert_eq!(lines.len(), 4);
        assert_eq!(
            lines[1].split(',').count(),
            crate::timeseries::CSV_HEADER.split(',').count()
        );
    }
}
