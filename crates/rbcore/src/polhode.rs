//! Which way a torque-free body's angular momentum moves in the body, and when it flips.
//!
//! With no torque, world L is fixed and body L stays on the sphere |L| = const and on the energy
//! ellipsoid 2E = Σ Lₖ²/Iₖ; their intersections, the polhodes, circle the axis of least moment
//! when |L|² < 2E·I₂ and the axis of greatest moment when |L|² > 2E·I₂, and meet at the
//! separatrix through the intermediate axis (Landau & Lifshitz, *Mechanics* §37). Along a
//! polhode ω₂ reverses twice per period 4K(k)/λ ([`crate::torque_free_period`]): that reversal
//! is the intermediate-axis (tennis-racket, Dzhanibekov) flip.

use nalgebra::Vector3;

use crate::Body;
use crate::integrators::exact::torque_free_period;

/// Moments this close (relative to the largest) count as equal, and |L|² − 2E·I₂ this small
/// (relative to |L|²) as the separatrix: round-off of the inputs, not a different motion.
const EQUAL: f64 = 1e-12;

/// The torque-free motion of body angular momentum, classified.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Polhode {
    /// No angular momentum: nothing turns.
    AtRest,
    /// Three equal moments: every axis is principal, so L never moves in the body.
    Spherical,
    /// L lies along principal axis `axis` (0, 1 or 2, moments ascending): a steady rotation.
    Steady {
        /// The axis, counting from 0.
        axis: usize,
    },
    /// L circles principal axis `axis` (0 or 2; a symmetric top's distinct axis), and ω₂
    /// reverses every half `period`.
    Circles {
        /// The axis circled, counting from 0.
        axis: usize,
        /// The period 4K(k)/λ of ω in the body (s).
        period: f64,
        /// (|L|² − 2E·I₂)/|L|²: how far from the separatrix (0 on it; small near it, where the
        /// period grows without bound); infinite for a symmetric top, which has none.
        separation: f64,
    },
    /// On the separatrix through the intermediate axis: the period is infinite.
    Separatrix,
}

/// How a steady spin about a principal axis responds to a small disturbance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stability {
    /// It wobbles and stays (the axes of least and greatest moment).
    Stable,
    /// It flips (the intermediate axis).
    Unstable,
    /// It drifts to a neighbouring axis of equal moment and stays there (equal moments).
    Neutral,
}

/// The stability of a spin about principal axis `i` (0, 1 or 2, moments ascending).
pub fn stability(moments: &Vector3<f64>, i: usize) -> Stability {
    let equal = |a: usize, b: usize| (moments[b] - moments[a]).abs() <= EQUAL * moments.z;
    match i {
        0 | 1 if equal(0, 1) => Stability::Neutral,
        1 | 2 if equal(1, 2) => Stability::Neutral,
        1 => Stability::Unstable,
        _ => Stability::Stable,
    }
}

/// The polhode of body angular momentum `l` (principal frame) for principal `moments`
/// (ascending).
///
/// ```
/// use nalgebra::Vector3;
/// use rbcore::{Polhode, Stability, polhode, stability};
///
/// let i = Vector3::new(1.0, 2.0, 3.0);
/// assert_eq!(stability(&i, 1), Stability::Unstable); // the intermediate axis flips
/// assert_eq!(polhode(&i, &Vector3::new(0.0, 0.0, 6.0)), Polhode::Steady { axis: 2 });
/// // Mostly about axis 2 with |L|² > 2E·I₂: L circles axis 3 and ω₂ reverses every T/2.
/// let l = i.component_mul(&Vector3::new(0.001, 10.0, 0.001));
/// assert!(matches!(polhode(&i, &l), Polhode::Circles { axis: 2, .. }));
///
/// // A symmetric top, I = (2, 2, 3), at ω = (1, 2, 3): ω turns about axis 3 at
/// // Ω = (I₃ − I₁)/I₁ · ω₃ = 1.5 rad/s, so the period is 2π/Ω.
/// let top = Vector3::new(2.0, 2.0, 3.0);
/// let l = top.component_mul(&Vector3::new(1.0, 2.0, 3.0));
/// let Polhode::Circles { axis, period, .. } = polhode(&top, &l) else {
///     panic!("a precessing top");
/// };
/// assert_eq!(axis, 2);
/// assert!((period - 2.0 * std::f64::consts::PI / 1.5).abs() < 1e-12);
/// ```
pub fn polhode(moments: &Vector3<f64>, l: &Vector3<f64>) -> Polhode {
    let l2 = l.norm_squared();
    if l2.is_nan() || l2 <= 0.0 {
        return Polhode::AtRest;
    }
    let i = moments;
    let (equal12, equal23) = (i.y - i.x <= EQUAL * i.z, i.z - i.y <= EQUAL * i.z);
    if equal12 && equal23 {
        return Polhode::Spherical;
    }
    let along: Vec<usize> = (0..3).filter(|&k| l[k] != 0.0).collect();
    if let [axis] = along[..] {
        return Polhode::Steady { axis };
    }
    // A symmetric top spinning in its plane of equal moments: every axis there is principal,
    // so L lies along one and nothing moves.
    if (equal12 && l.z == 0.0) || (equal23 && l.x == 0.0) {
        return Polhode::Steady { axis: along[0] };
    }
    // |L|² − 2E·I₂ = Σ (Iₖ − I₂) Lₖ²/Iₖ, term by term so that the large L₂ term cannot cancel.
    let beyond: f64 = (0..3).map(|k| (i[k] - i.y) * l[k] * l[k] / i[k]).sum();
    let separation = beyond / l2;
    let axis = match (equal12, equal23) {
        // A symmetric top's polhodes circle its distinct axis.
        (true, _) => 2,
        (_, true) => 0,
        _ if separation.abs() <= EQUAL => return Polhode::Separatrix,
        _ if separation < 0.0 => 0,
        _ => 2,
    };
    let separation = if equal12 || equal23 {
        f64::INFINITY
    } else {
        separation
    };
    match torque_free_period(moments, l) {
        Some(period) => Polhode::Circles {
            axis,
            period,
            separation,
        },
        None => Polhode::Separatrix,
    }
}

/// The widest angle (radians) between body angular momentum `l` and principal axis `axis` (0 or
/// 2, the axis its polhode circles) over one torque-free period: how far the body swings.
///
/// On the polhode about axis 3, Σ Lₖ²(1/Iₖ − 1/I₃) = 2E − |L|²/I₃ is fixed; L₁² + L₂² is largest
/// where that sum rests on the smaller coefficient, at L₁ = 0 (1/I₂ − 1/I₃ ≤ 1/I₁ − 1/I₃), so
/// sin² θ = (2E − |L|²/I₃) / ((1/I₂ − 1/I₃)|L|²). About axis 1, likewise with |L|²/I₁ − 2E at
/// L₃ = 0. For a symmetric top the angle is constant. Near the separatrix it nears 90°: axis 2
/// swings round and the body turns over; far from it, the body only wobbles.
///
/// ```
/// use nalgebra::Vector3;
/// // A symmetric top: L at a fixed 45° from its axis.
/// let top = Vector3::new(2.0, 2.0, 3.0);
/// let angle = rbcore::cone_angle(&top, &Vector3::new(1.0, 0.0, 1.0), 2);
/// assert!((angle - std::f64::consts::FRAC_PI_4).abs() < 1e-12);
/// ```
pub fn cone_angle(moments: &Vector3<f64>, l: &Vector3<f64>, axis: usize) -> f64 {
    let l2 = l.norm_squared();
    if l2.is_nan() || l2 <= 0.0 {
        return 0.0;
    }
    let i = moments;
    let (off, coefficient) = if axis == 0 {
        let off: f64 = (1..3).map(|k| l[k] * l[k] * (1.0 / i.x - 1.0 / i[k])).sum();
        (off, 1.0 / i.x - 1.0 / i.y)
    } else {
        let off: f64 = (0..2).map(|k| l[k] * l[k] * (1.0 / i[k] - 1.0 / i.z)).sum();
        (off, 1.0 / i.y - 1.0 / i.z)
    };
    // Equal moments along the swing: the angle off the axis is L's own, and fixed.
    let sin2 = if coefficient > 0.0 {
        off / (coefficient * l2)
    } else {
        1.0 - l[axis] * l[axis] / l2
    };
    sin2.clamp(0.0, 1.0).sqrt().asin()
}

/// Poinsot's construction of a torque-free body's motion (Landau & Lifshitz, *Mechanics* §37):
/// the ellipsoid ωᵀIω = 2T, fixed in the body, passes through ω's tip, where its tangent plane is
/// perpendicular to L: the invariable plane, fixed in space while no torque acts. The ellipsoid
/// rolls on it without slipping, and ω's tip traces the herpolhode on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Poinsot {
    /// The ellipsoid's semi-axes along the principal axes (moments ascending), √(2T/Iᵢ), in ω's
    /// units (rad/s).
    pub semi_axes: Vector3<f64>,
    /// The plane's unit normal: world L's direction.
    pub normal: Vector3<f64>,
    /// The plane's distance from the centre of mass along the normal, ω·L/|L| = 2T/|L| (rad/s).
    pub distance: f64,
}

/// Poinsot's construction for `body` now; `None` for a body at rest (no L, no kinetic energy).
pub fn poinsot(body: &Body) -> Option<Poinsot> {
    let (w, l) = (body.omega_world(), body.angular_momentum());
    let two_t = w.dot(&l);
    let normal = l.try_normalize(0.0)?;
    (two_t.is_finite() && two_t > 0.0).then(|| Poinsot {
        semi_axes: body.moments().map(|i| (two_t / i).sqrt()),
        normal,
        distance: two_t / l.norm(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const I: Vector3<f64> = Vector3::new(1.0, 2.0, 3.0);

    #[test]
    fn the_sign_of_l2_minus_2ei2_picks_the_axis() {
        // ω = (0.001, 10, 0.001): |L|² − 2E·I₂ = −1e-6 + 3e-6 > 0, around the major axis.
        let l = I.component_mul(&Vector3::new(0.001, 10.0, 0.001));
        let Polhode::Circles {
            axis,
            period,
            separation,
        } = polhode(&I, &l)
        else {
            panic!("{:?}", polhode(&I, &l));
        };
        assert_eq!(axis, 2);
        assert!((separation - 2e-6 / l.norm_squared()).abs() < 1e-12 * separation);
        // 4K(k)/λ written out (Landau & Lifshitz §37, |L|² > 2E·I₂), K by an AGM of its own:
        // λ² = (I₃ − I₂)(|L|² − 2E·I₁)/(I₁I₂I₃), k′² = (I₃ − I₁)(|L|² − 2E·I₂)/((I₃ − I₂)(|L|² − 2E·I₁)).
        let beyond = |j: usize| {
            (0..3)
                .map(|k| (I[k] - I[j]) * l[k] * l[k] / I[k])
                .sum::<f64>()
        };
        let lambda = ((I.z - I.y) * beyond(0) / (I.x * I.y * I.z)).sqrt();
        let kp = ((I.z - I.x) * beyond(1) / ((I.z - I.y) * beyond(0))).sqrt();
        let (mut a, mut b) = (1.0_f64, kp);
        for _ in 0..40 {
            (a, b) = (0.5 * (a + b), (a * b).sqrt());
        }
        let want = 4.0 * std::f64::consts::PI / (2.0 * a) / lambda;
        assert!(
            (period - want).abs() < 1e-13 * want,
            "{period} vs 4K/λ = {want}"
        );
        // README's canonical figure.
        assert!((period - 7.101450608).abs() < 1e-9, "{period}");
        let minor = I.component_mul(&Vector3::new(0.01, 10.0, 0.001));
        assert!(matches!(
            polhode(&I, &minor),
            Polhode::Circles { axis: 0, .. }
        ));
    }

    /// The widest swing of L from the circled axis, against Euler's equations integrated with
    /// RK4 over more than a period (dL/dt = L × ω in the body, ω = L/I).
    #[test]
    fn cone_angle_is_the_widest_swing_of_the_integrated_motion() {
        let rate = |l: &Vector3<f64>| l.cross(&l.component_div(&I));
        for omega in [
            Vector3::new(0.2, 10.0, 0.2),
            Vector3::new(0.2, 0.5, 10.0),
            Vector3::new(10.0, 0.5, 0.2),
            Vector3::new(1.0, 8.0, 1.0),
        ] {
            let mut l = I.component_mul(&omega);
            let Polhode::Circles { axis, period, .. } = polhode(&I, &l) else {
                panic!("{omega}");
            };
            let want = cone_angle(&I, &l, axis);
            let steps = 200_000;
            let h = 1.2 * period / f64::from(steps);
            let mut widest = 0.0_f64;
            for _ in 0..steps {
                let k1 = rate(&l);
                let k2 = rate(&(l + k1 * (h / 2.0)));
                let k3 = rate(&(l + k2 * (h / 2.0)));
                let k4 = rate(&(l + k3 * h));
                l += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
                widest = widest.max((l[axis].abs() / l.norm()).acos());
            }
            assert!((widest - want).abs() < 1e-6, "{omega}: {widest} vs {want}");
        }
    }

    #[test]
    fn symmetric_tops_spinning_in_their_equal_plane_are_steady_and_neutral() {
        let rod = Vector3::new(1.0, 3.0, 3.0);
        assert_eq!(
            polhode(&rod, &Vector3::new(0.0, 3.0, 6.0)),
            Polhode::Steady { axis: 1 }
        );
        assert_eq!(stability(&rod, 2), Stability::Neutral);
        assert_eq!(stability(&rod, 0), Stability::Stable);
        assert_eq!(stability(&I, 1), Stability::Unstable);
        let top = Vector3::new(2.0, 2.0, 3.0);
        let Polhode::Circles { separation, .. } = polhode(&top, &Vector3::new(2.0, 2.0, 0.03))
        else {
            panic!("a precessing top");
        };
        assert!(separation.is_infinite(), "a top has no separatrix");
    }

    #[test]
    fn special_motions() {
        assert_eq!(polhode(&I, &Vector3::zeros()), Polhode::AtRest);
        assert_eq!(
            polhode(&Vector3::repeat(2.0), &Vector3::new(1.0, 2.0, 3.0)),
            Polhode::Spherical
        );
        assert_eq!(
            polhode(&I, &Vector3::new(0.0, 0.0, 6.0)),
            Polhode::Steady { axis: 2 }
        );
        assert_eq!(
            polhode(&I, &Vector3::new(0.0, 4.0, 0.0)),
            Polhode::Steady { axis: 1 }
        );
        // Σ (Iₖ − I₂) Lₖ²/Iₖ = −1 + 1 = 0 with L = (1, 4, √3): the separatrix.
        let on = Vector3::new(1.0, 4.0, 3.0f64.sqrt());
        assert_eq!(polhode(&I, &on), Polhode::Separatrix);
        // A symmetric top (I₁ = I₂) precesses about its distinct axis at Ω = (I₃ − I₁)/I₁·ω₃.
        let top = Vector3::new(2.0, 2.0, 3.0);
        let l = top.component_mul(&Vector3::new(1.0, 2.0, 3.0));
        let Polhode::Circles { axis, period, .. } = polhode(&top, &l) else {
            panic!("{:?}", polhode(&top, &l));
        };
        assert_eq!(axis, 2);
        let precession = 2.0 * std::f64::consts::PI / (0.5 * 3.0);
        assert!((period - precession).abs() < 1e-12 * precession);
    }

    /// Along a tumble ω's tip stays on the invariable plane (fixed in space) and on the
    /// ellipsoid (fixed in the body), whose construction is the same at every step.
    #[test]
    fn omega_rolls_the_ellipsoid_on_the_invariable_plane() {
        let mut body = Body::from_moments(2.0, I).expect("body");
        body.set_omega_principal(Vector3::new(0.3, 5.0, 0.2))
            .expect("spin");
        let mut sim = crate::Simulation::new(body, crate::Settings::default()).expect("simulation");
        let first = poinsot(sim.body()).expect("moving");
        for _ in 0..2400 {
            sim.step().expect("step");
            let body = sim.body();
            let now = poinsot(body).expect("moving");
            let w = body.omega_world();
            assert!((w.dot(&first.normal) - first.distance).abs() < 1e-9 * first.distance);
            let w_principal = body.orientation().inverse() * w;
            let on: f64 = (0..3)
                .map(|i| (w_principal[i] / now.semi_axes[i]).powi(2))
                .sum();
            assert!((on - 1.0).abs() < 1e-9, "{on}");
            assert!((now.semi_axes - first.semi_axes).norm() < 1e-9 * first.semi_axes.norm());
        }
        assert_eq!(poinsot(&Body::from_moments(1.0, I).expect("body")), None);
    }
}
