//! The exact torque-free flow of an asymmetric rigid body, and the elliptic functions it needs.
//!
//! Body angular momentum follows Jacobi's elliptic functions (Landau & Lifshitz, *Mechanics* §37;
//! van Zon & Schofield 2007, J. Comput. Phys. 225; Celledoni, Fassò, Säfström & Zanna 2008, SIAM
//! J. Sci. Comput. 30). With moments `I₁ < I₂ < I₃`, `M = |L|`, and `|L|² ≥ 2E I₂` (motion around
//! the major axis):
//!
//! `ω₁ = A₁ cn τ`, `ω₂ = s A₂ sn τ`, `ω₃ = s A₃ dn τ`, `τ = τ₀ + λt`, with
//! `A₁² = (2EI₃ − M²)/(I₁(I₃−I₁))`, `A₂² = (2EI₃ − M²)/(I₂(I₃−I₂))`, `A₃² = (M² − 2EI₁)/(I₃(I₃−I₁))`,
//! `λ² = (I₃−I₂)(M² − 2EI₁)/(I₁I₂I₃)`, `k² = (I₂−I₁)(2EI₃ − M²)/((I₃−I₂)(M² − 2EI₁))`,
//! `s = sign ω₃`; for `|L|² < 2E I₂` (motion around the minor axis) indices 1 and 3 swap. The
//! differences `2EI₃ − M²` etc. are formed term by term so nothing cancels near the separatrix,
//! and `k'² = (I₃−I₁)|M² − 2EI₂| / ((I₃−I₂)(M² − 2EI₁))` is computed directly, never as `1 − k²`.
//!
//! The orientation follows from body L up to the angle ψ about world L. In 3-1-3 Euler angles with
//! world z along L and a reference principal axis `a` that L never approaches (the major axis for
//! motion around the minor one and vice versa), `θ`, `φ` are read off body L and
//! `ψ̇ = |L| (L_b²/I_b + L_c²/I_c)/(L_b² + L_c²)` (Landau §37). Instead of writing ψ with the
//! elliptic integral of the third kind we integrate this analytic, bounded rate with 8-point
//! Gauss-Legendre quadrature on panels of at most a quarter of `1/λ`, which is exact to round-off.
//!
//! Elliptic functions use the modulus `k` (not the parameter `m = k²`) and are evaluated by the
//! arithmetic-geometric mean: `K` by `π/(2 AGM(1, k'))`, `F(φ, k)` by the AGM/descending Landen
//! transformation, and `sn`, `cn`, `dn` by the descending Landen sequence (Abramowitz & Stegun
//! 16.4 and 17.6).

use std::f64::consts::PI;

use nalgebra::{UnitQuaternion, Vector3};

use crate::body::Body;

/// AGM / Landen iteration cap (convergence is quadratic; 6-8 iterations at `k' = 1e-8`).
const MAX_AGM: usize = 64;

/// Gauss-Legendre nodes and weights on [−1, 1], 8 points (Abramowitz & Stegun Table 25.4).
const GL_NODES: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
const GL_WEIGHTS: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];

/// `k' = √(1 − k²)` formed as `√((1−k)(1+k))`.
fn complementary(k: f64) -> f64 {
    ((1.0 - k) * (1.0 + k)).max(0.0).sqrt()
}

/// Complete elliptic integral of the first kind `K(k) = ∫₀^{π/2} dθ/√(1 − k² sin²θ)` from the
/// complementary modulus `k' = √(1 − k²)`, by the arithmetic-geometric mean `π/(2 AGM(1, k'))`.
/// Taking `k'` keeps full accuracy near `k = 1`, where `K` has its log singularity; `+∞` at
/// `k' = 0`.
fn k_from_complementary(kp: f64) -> f64 {
    if kp == 0.0 {
        return f64::INFINITY;
    }
    let (mut a, mut b) = (1.0_f64, kp);
    for _ in 0..MAX_AGM {
        if (a - b).abs() <= f64::EPSILON * a {
            break;
        }
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

/// Incomplete elliptic integral of the first kind `F(φ, k) = ∫₀^φ dθ/√(1 − k² sin²θ)` for any
/// real `φ`, `0 ≤ k ≤ 1`, by the AGM with descending Landen transformations
/// (`φₙ₊₁ = φₙ + arctan((bₙ/aₙ) tan φₙ)` on the branch nearest `φₙ`, `F = φ_N/(2^N a_N)`).
pub fn elliptic_f(phi: f64, k: f64) -> f64 {
    if !(0.0..=1.0).contains(&k) {
        return f64::NAN;
    }
    f_from_complementary(phi, complementary(k))
}

fn f_from_complementary(phi: f64, kp: f64) -> f64 {
    if kp == 0.0 {
        // F(φ, 1) = artanh(sin φ), finite only on (−π/2, π/2).
        return if phi.abs() < 0.5 * PI {
            phi.sin().atanh()
        } else {
            phi.signum() * f64::INFINITY
        };
    }
    let (mut a, mut b, mut phi, mut pow2) = (1.0_f64, kp, phi, 1.0_f64);
    for _ in 0..MAX_AGM {
        if (a - b).abs() <= f64::EPSILON * a {
            break;
        }
        let mut d = (b * phi.sin()).atan2(a * phi.cos());
        d += 2.0 * PI * ((phi - d) / (2.0 * PI)).round();
        phi += d;
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
        pow2 *= 2.0;
    }
    phi / (pow2 * a)
}

/// Jacobi elliptic functions `(sn, cn, dn)(u, k)`, `0 ≤ k ≤ 1`, by the descending Landen / AGM
/// sequence (A&S 16.4), with `u` first reduced modulo the period `4K`.
pub fn jacobi_elliptic(u: f64, k: f64) -> (f64, f64, f64) {
    if !(0.0..=1.0).contains(&k) {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    jacobi_with_complementary(u, k, complementary(k))
}

fn jacobi_with_complementary(u: f64, k: f64, kp: f64) -> (f64, f64, f64) {
    if kp == 0.0 {
        let sech = 1.0 / u.cosh();
        return (u.tanh(), sech, sech);
    }
    if k == 0.0 {
        let (s, c) = u.sin_cos();
        return (s, c, 1.0);
    }
    let mut a = [0.0_f64; MAX_AGM];
    let mut c = [0.0_f64; MAX_AGM];
    let (mut an, mut bn, mut cn) = (1.0_f64, kp, k);
    let mut n = 0;
    while cn.abs() > f64::EPSILON * an && n < MAX_AGM {
        (an, bn, cn) = (0.5 * (an + bn), (an * bn).sqrt(), 0.5 * (an - bn));
        a[n] = an;
        c[n] = cn;
        n += 1;
    }
    let quarter_period = PI / (2.0 * an);
    let u = u - 4.0 * quarter_period * (u / (4.0 * quarter_period)).round();
    let mut phi = u * an * 2f64.powi(n as i32);
    for i in (0..n).rev() {
        phi = 0.5 * (phi + (c[i] / a[i] * phi.sin()).asin());
    }
    let (s, cph) = phi.sin_cos();
    // dn² = k'² + k² cn² keeps full relative accuracy when k' is tiny.
    (s, cph, (kp * kp + k * k * cph * cph).sqrt())
}

/// The closed-form torque-free solution for given principal moments and initial body L.
#[derive(Clone, Copy, Debug)]
struct EllipticMotion {
    /// Indices of the principal axes carried by cn, sn, dn.
    axes: [usize; 3],
    amplitude: [f64; 3],
    sign: f64,
    lambda: f64,
    k: f64,
    kp: f64,
    tau0: f64,
    moments: Vector3<f64>,
}

impl EllipticMotion {
    /// `None` for steady or separatrix motion, where the formulas degenerate.
    fn new(l: &Vector3<f64>, moments: &Vector3<f64>) -> Option<Self> {
        let i = moments;
        let sq = l.component_mul(l);
        // Term-by-term forms of M² − 2EI₁, 2EI₃ − M², M² − 2EI₂ (no cancellation).
        let d1 = sq[1] * (1.0 - i[0] / i[1]) + sq[2] * (1.0 - i[0] / i[2]);
        let d3 = sq[0] * (i[2] / i[0] - 1.0) + sq[1] * (i[2] / i[1] - 1.0);
        let d2 = sq[0] * (1.0 - i[1] / i[0]) + sq[2] * (1.0 - i[1] / i[2]);
        let (axes, dc, dd) = if d2 >= 0.0 {
            ([0, 1, 2], d3, d1)
        } else {
            ([2, 1, 0], d1, d3)
        };
        let [c, s, d] = axes;
        let (ic, is, id) = (i[c], i[s], i[d]);
        let amplitude = [
            (dc / (ic * (id - ic).abs())).sqrt(),
            (dc / (is * (id - is).abs())).sqrt(),
            (dd / (id * (id - ic).abs())).sqrt(),
        ];
        let lambda = ((id - is).abs() * dd / (ic * is * id)).sqrt();
        let k = ((is - ic).abs() * dc / ((id - is).abs() * dd)).sqrt();
        let kp = ((id - ic).abs() * d2.abs() / ((id - is).abs() * dd)).sqrt();
        let ok = amplitude.iter().all(|x| x.is_finite())
            && lambda.is_finite()
            && lambda > 0.0
            && k.is_finite()
            && kp.is_finite()
            && kp > 0.0
            && k < 1.0;
        if !ok {
            return None;
        }
        let w = l.component_div(moments);
        let sign = if w[d] >= 0.0 { 1.0 } else { -1.0 };
        let phi0 = (sign * w[s] * amplitude[0]).atan2(w[c] * amplitude[1]);
        let tau0 = f_from_complementary(phi0, kp);
        tau0.is_finite().then_some(Self {
            axes,
            amplitude,
            sign,
            lambda,
            k,
            kp,
            tau0,
            moments: *moments,
        })
    }

    /// Body angular momentum at time `t` after the initial state.
    fn momentum_at(&self, t: f64) -> Vector3<f64> {
        let (sn, cn, dn) = jacobi_with_complementary(self.tau0 + self.lambda * t, self.k, self.kp);
        let [c, s, d] = self.axes;
        let mut l = Vector3::zeros();
        l[c] = self.amplitude[0] * cn * self.moments[c];
        l[s] = self.sign * self.amplitude[1] * sn * self.moments[s];
        l[d] = self.sign * self.amplitude[2] * dn * self.moments[d];
        l
    }
}

/// Period of the flip: `4K(k)/λ`, the period of body ω (ω₂ changes sign twice per period).
/// `None` for steady rotations and on the separatrix (infinite period).
pub fn torque_free_period(moments: &Vector3<f64>, l_principal: &Vector3<f64>) -> Option<f64> {
    let m = EllipticMotion::new(l_principal, moments)?;
    Some(4.0 * k_from_complementary(m.kp) / m.lambda)
}

/// Angular velocity in the principal frame at time `t` of the exact torque-free motion starting
/// from body angular momentum `l0` (moments ascending). `None` where [`torque_free_period`] is.
pub fn torque_free_omega(
    moments: &Vector3<f64>,
    l0: &Vector3<f64>,
    t: f64,
) -> Option<Vector3<f64>> {
    let m = EllipticMotion::new(l0, moments)?;
    Some(m.momentum_at(t).component_div(moments))
}

/// 3-1-3 Euler angles (θ, φ) of the body relative to world-L-up, in axes permuted so that the
/// reference axis `a` is z: `L_perm = |L|(sinθ sinφ, sinθ cosφ, cosθ)`.
fn theta_phi(lp: &Vector3<f64>) -> (f64, f64) {
    ((lp.x.hypot(lp.y)).atan2(lp.z), lp.x.atan2(lp.y))
}

/// One exact free-rotor step of length `h`; steady and separatrix motion (measure zero) fall
/// back to the midpoint-Cayley step, which is exact for a steady spin up to `O(h³)` phase.
pub(crate) fn free_rotor(body: &mut Body, h: f64) {
    let l = body.angular_momentum_principal();
    let Some(motion) = EllipticMotion::new(&l, &body.moments) else {
        super::midpoint_cayley::free_rotor(body, h);
        return;
    };
    // Reference axis: the major one (index 2) when motion circles the minor axis, else the minor.
    let a = if motion.axes[0] == 2 { 2 } else { 0 };
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    let permute = |v: &Vector3<f64>| Vector3::new(v[b], v[c], v[a]);
    // Π: principal → permuted coordinates, a proper (cyclic) rotation.
    let pi = UnitQuaternion::from_rotation_matrix(&nalgebra::Rotation3::from_matrix_unchecked(
        nalgebra::Matrix3::from_rows(&[
            Vector3::ith(b, 1.0).transpose(),
            Vector3::ith(c, 1.0).transpose(),
            Vector3::ith(a, 1.0).transpose(),
        ]),
    ));
    let l_norm = l.norm();
    let rate = |t: f64| {
        let lt = motion.momentum_at(t);
        let (lb, lc) = (lt[b], lt[c]);
        l_norm * (lb * lb / body.moments[b] + lc * lc / body.moments[c]) / (lb * lb + lc * lc)
    };
    let panels = ((motion.lambda * h / 0.25).ceil() as usize).clamp(1, 1 << 20);
    let width = h / panels as f64;
    let mut dpsi = 0.0;
    for p in 0..panels {
        let mid = (p as f64 + 0.5) * width;
        let half = 0.5 * width;
        for (x, w) in GL_NODES.iter().zip(GL_WEIGHTS) {
            dpsi += w * half * (rate(mid - half * x) + rate(mid + half * x));
        }
    }
    let (th0, ph0) = theta_phi(&permute(&l));
    let (th1, ph1) = theta_phi(&permute(&motion.momentum_at(h)));
    let rz = |x: f64| UnitQuaternion::from_axis_angle(&Vector3::z_axis(), x);
    let rx = |x: f64| UnitQuaternion::from_axis_angle(&Vector3::x_axis(), x);
    let q =
        body.orientation * pi.inverse() * rz(-ph0) * rx(-th0) * rz(dpsi) * rx(th1) * rz(ph1) * pi;
    if q.coords.iter().all(|x| x.is_finite()) {
        body.orientation = q;
    } else {
        super::midpoint_cayley::free_rotor(body, h);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `K(k)` from the modulus, as a caller would write it.
    fn elliptic_k(k: f64) -> f64 {
        k_from_complementary(complementary(k))
    }

    /// Simpson's rule for F(φ, k), an independent check of the AGM.
    fn quadrature_f(phi: f64, k: f64) -> f64 {
        let n = 20_000;
        let h = phi / n as f64;
        let f = |t: f64| 1.0 / (1.0 - (k * t.sin()).powi(2)).sqrt();
        let mut s = f(0.0) + f(phi);
        for i in 1..n {
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * h);
        }
        s * h / 3.0
    }

    #[test]
    fn complete_integral_matches_known_values() {
        assert!((elliptic_k(0.0) - PI / 2.0).abs() < 1e-15);
        // Lemniscate case: K(1/√2) = Γ(1/4)²/(4√π).
        assert!((elliptic_k(0.5f64.sqrt()) - 1.854_074_677_301_371_9).abs() < 1e-15);
        // K(0.5) from A&S Table 17.1 (m = 0.25).
        assert!((elliptic_k(0.5) - 1.685_750_354_812_596).abs() < 1e-14);
        // Near k = 1, K ≈ ln(4/k') + (k'²/4)(ln(4/k') − 1).
        let kp: f64 = 1e-6;
        let k = (1.0 - kp * kp).sqrt();
        let approx = (4.0 / kp).ln() + kp * kp / 4.0 * ((4.0 / kp).ln() - 1.0);
        assert!((k_from_complementary(kp) - approx).abs() < 1e-12);
        // From k itself k' carries the rounding of 1 − k² (relative 1e-4 here), which is why
        // the integrator forms k' directly.
        assert!((elliptic_k(k) - approx).abs() < 1e-3);
        assert_eq!(elliptic_k(1.0), f64::INFINITY);
    }

    #[test]
    fn incomplete_integral_matches_quadrature_and_limits() {
        for k in [0.0, 0.3, 0.7, 0.99] {
            for phi in [0.4, 1.2, 2.5, -3.0, 7.0] {
                let f = elliptic_f(phi, k);
                assert!(
                    (f - quadrature_f(phi, k)).abs() < 1e-11 * f.abs(),
                    "k={k} phi={phi}"
                );
            }
            assert!((elliptic_f(PI / 2.0, k) - elliptic_k(k)).abs() < 1e-14);
        }
        assert!((elliptic_f(0.8, 1.0) - 0.8f64.sin().atanh()).abs() < 1e-15);
    }

    #[test]
    fn jacobi_functions_match_known_values() {
        for k in [0.3, 0.5f64.sqrt(), 0.99, 1.0 - 1e-10] {
            let kp = complementary(k);
            let kk = elliptic_k(k);
            // Quarter and half-quarter periods: sn(K) = 1, dn(K) = k'; sn(K/2) = 1/√(1+k'),
            // cn(K/2) = √(k'/(1+k')), dn(K/2) = √k'.
            let (s, c, d) = jacobi_elliptic(kk, k);
            assert!(
                (s - 1.0).abs() < 1e-14 && c.abs() < 1e-7 && (d - kp).abs() < 1e-7 * kp.max(1e-3)
            );
            let (s, c, d) = jacobi_elliptic(0.5 * kk, k);
            assert!((s - 1.0 / (1.0 + kp).sqrt()).abs() < 1e-13);
            assert!((c - (kp / (1.0 + kp)).sqrt()).abs() < 1e-13);
            assert!((d - kp.sqrt()).abs() < 1e-12);
            // Periodicity 4K and the inverse F(am u) = u.
            for u in [0.3, 1.1, 2.9] {
                let (s1, c1, d1) = jacobi_elliptic(u, k);
                let (s2, c2, d2) = jacobi_elliptic(u + 4.0 * kk, k);
                assert!(
                    (s1 - s2).abs() < 1e-12 && (c1 - c2).abs() < 1e-12 && (d1 - d2).abs() < 1e-12
                );
                assert!((s1 * s1 + c1 * c1 - 1.0).abs() < 1e-15);
                assert!((elliptic_f(s1.atan2(c1), k) - u).abs() < 1e-12 * kk);
            }
        }
        let (s, c, d) = jacobi_elliptic(0.7, 0.0);
        assert_eq!((s, c, d), (0.7f64.sin(), 0.7f64.cos(), 1.0));
        let (s, c, d) = jacobi_elliptic(0.7, 1.0);
        assert!((s - 0.7f64.tanh()).abs() < 1e-16 && (c - d).abs() < 1e-16);
    }

    #[test]
    fn gauss_legendre_integrates_degree_15_exactly() {
        let integral = |f: &dyn Fn(f64) -> f64| {
            GL_NODES
                .iter()
                .zip(GL_WEIGHTS)
                .map(|(x, w)| w * (f(*x) + f(-x)))
                .sum::<f64>()
        };
        assert!((integral(&|_| 1.0) - 2.0).abs() < 1e-15);
        assert!((integral(&|x| x.powi(14)) - 2.0 / 15.0).abs() < 1e-15);
    }

    #[test]
    fn closed_form_satisfies_eulers_equations() {
        // Central difference of the closed form against L × I⁻¹L, both sides of the separatrix.
        let moments = Vector3::new(1.0, 2.0, 3.0);
        for l0 in [
            Vector3::new(0.3, 2.0, 0.9),
            Vector3::new(2.0, 0.5, -0.3),
            Vector3::new(-0.5, -1.0, 2.5),
        ] {
            let m = EllipticMotion::new(&l0, &moments).expect("generic motion");
            assert!((m.momentum_at(0.0) - l0).norm() < 1e-13);
            for t in [0.4, 1.7, 5.0] {
                let e = 1e-5;
                let deriv = (m.momentum_at(t + e) - m.momentum_at(t - e)) / (2.0 * e);
                let l = m.momentum_at(t);
                assert!((deriv - l.cross(&l.component_div(&moments))).norm() < 1e-8);
            }
        }
    }
}
