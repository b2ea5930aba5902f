//! `polhode`'s classification and flip period against an independent method: Euler's equations
//! for body angular momentum, dL/dt = L × I⁻¹L, integrated here by classical RK4 with a small
//! step (no code of the crate), the reversals of ω₂ timed by cubic Hermite interpolation, and the
//! axis that L circles read off as the component that never changes sign.

use nalgebra::Vector3;
use rbcore::{Polhode, polhode};

/// dL/dt in the body frame with no torque.
fn euler_rhs(i: &Vector3<f64>, l: &Vector3<f64>) -> Vector3<f64> {
    l.cross(&l.component_div(i))
}

fn rk4_step(i: &Vector3<f64>, l: &Vector3<f64>, h: f64) -> Vector3<f64> {
    let k1 = euler_rhs(i, l);
    let k2 = euler_rhs(i, &(l + k1 * (h / 2.0)));
    let k3 = euler_rhs(i, &(l + k2 * (h / 2.0)));
    let k4 = euler_rhs(i, &(l + k3 * h));
    l + (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0)
}

/// What the numerical flow shows over `duration`: the times where L₂ changes sign, and for
/// each axis whether its component ever changed sign.
struct Flow {
    reversals: Vec<f64>,
    changed_sign: [bool; 3],
}

fn integrate(i: &Vector3<f64>, l0: &Vector3<f64>, h: f64, duration: f64) -> Flow {
    let steps = (duration / h).ceil() as usize;
    let mut l = *l0;
    let mut flow = Flow {
        reversals: Vec::new(),
        changed_sign: [false; 3],
    };
    for n in 0..steps {
        let next = rk4_step(i, &l, h);
        for k in 0..3 {
            flow.changed_sign[k] |= (l[k] > 0.0) != (next[k] > 0.0);
        }
        if (l.y > 0.0) != (next.y > 0.0) {
            // Cubic Hermite on [0, h] through L₂ and its derivative at both ends; Newton from
            // the linear guess.
            let (y0, y1) = (l.y, next.y);
            let (d0, d1) = (euler_rhs(i, &l).y * h, euler_rhs(i, &next).y * h);
            let p = |s: f64| {
                let (s2, s3) = (s * s, s * s * s);
                (2.0 * s3 - 3.0 * s2 + 1.0) * y0
                    + (s3 - 2.0 * s2 + s) * d0
                    + (-2.0 * s3 + 3.0 * s2) * y1
                    + (s3 - s2) * d1
            };
            let dp = |s: f64| {
                let s2 = s * s;
                (6.0 * s2 - 6.0 * s) * y0
                    + (3.0 * s2 - 4.0 * s + 1.0) * d0
                    + (-6.0 * s2 + 6.0 * s) * y1
                    + (3.0 * s2 - 2.0 * s) * d1
            };
            let mut s = y0 / (y0 - y1);
            for _ in 0..8 {
                s -= p(s) / dp(s);
            }
            flow.reversals.push((n as f64 + s) * h);
        }
        l = next;
    }
    flow
}

/// The period of ω₂ measured from its reversals (two per period), first to last.
fn measured_period(reversals: &[f64]) -> f64 {
    assert!(reversals.len() >= 3, "{reversals:?}");
    let n = reversals.len() - 1;
    2.0 * (reversals[n] - reversals[0]) / n as f64
}

/// On both sides of the separatrix, near it and far from it, and for a symmetric top: the
/// period `polhode` gives is the one the numerically integrated flow shows (to about 10× what
/// RK4 at this step reaches), and the axis it names is the one whose component of L never changes
/// sign while the other two do.
#[test]
fn the_predicted_period_and_axis_are_those_of_the_integrated_flow() {
    // The tolerance is about 10× what RK4 at this step reaches: 1e-14 far from the separatrix;
    // near it, where the period depends on |L|² − 2E·I₂ (here 5e-9 of |L|²), RK4's own energy
    // error shows as 7.6e-9 and 1.5e-10.
    let cases: [([f64; 3], [f64; 3], usize, f64); 5] = [
        // The canonical case: close to the separatrix, on the major axis' side.
        ([1.0, 2.0, 3.0], [0.001, 10.0, 0.001], 2, 8e-8),
        // Just across it: the minor axis' side.
        ([1.0, 2.0, 3.0], [0.01, 10.0, 0.001], 0, 2e-9),
        // Far from it, both sides.
        ([0.9, 1.7, 2.3], [1.3, -2.1, 0.7], 0, 3e-13),
        ([0.9, 1.7, 2.3], [0.4, -2.1, 1.7], 2, 1e-13),
        // A symmetric top precesses about its distinct axis.
        ([2.0, 2.0, 3.0], [1.0, 2.0, 3.0], 2, 1e-14),
    ];
    for (moments, omega, axis, tol) in cases {
        let i = Vector3::from(moments);
        let l = i.component_mul(&Vector3::from(omega));
        let Polhode::Circles {
            axis: named,
            period,
            ..
        } = polhode(&i, &l)
        else {
            panic!("{moments:?} {omega:?}: {:?}", polhode(&i, &l));
        };
        assert_eq!(named, axis, "{moments:?} {omega:?}");
        let h = period / 40_000.0;
        let flow = integrate(&i, &l, h, 4.6 * period);
        let measured = measured_period(&flow.reversals);
        let rel = (measured - period) / period;
        assert!(
            rel.abs() < tol,
            "{moments:?} {omega:?}: polhode {period} s, integrated {measured} s ({rel:+e})"
        );
        // 9.2 half-periods: nine or ten reversals, by the phase.
        assert!(
            (9..=10).contains(&flow.reversals.len()),
            "{moments:?} {omega:?}: {:?}",
            flow.reversals
        );
        for k in 0..3 {
            assert_eq!(
                flow.changed_sign[k],
                k != axis,
                "{moments:?} {omega:?}: axis {} changed sign: {}",
                k + 1,
                flow.changed_sign[k]
            );
        }
    }
}

/// Steady spins, the separatrix, rest and three equal moments have no period; the integrated
/// flow agrees that ω₂ does not reverse in a long run for the steady spins.
#[test]
fn motions_without_a_flip_have_no_period() {
    let i = Vector3::new(1.0, 2.0, 3.0);
    for l in [Vector3::new(0.0, 0.0, 6.0), Vector3::new(2.0, 0.0, 0.0)] {
        assert!(matches!(polhode(&i, &l), Polhode::Steady { .. }), "{l}");
        let flow = integrate(&i, &l, 1e-3, 50.0);
        assert!(flow.reversals.is_empty(), "{l}: {:?}", flow.reversals);
    }
    // Σ (Iₖ − I₂) Lₖ²/Iₖ = −1 + 1 = 0: on the separatrix.
    assert_eq!(
        polhode(&i, &Vector3::new(1.0, 4.0, 3.0f64.sqrt())),
        Polhode::Separatrix
    );
    assert_eq!(polhode(&i, &Vector3::zeros()), Polhode::AtRest);
    assert_eq!(
        polhode(&Vector3::repeat(2.0), &Vector3::new(1.0, 2.0, 3.0)),
        Polhode::Spherical
    );
}
