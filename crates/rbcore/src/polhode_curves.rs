//! The momentum sphere's geometry: the polhodes of a body at a given |L|, in its principal frame,
//! as curves to draw (the app's momentum sphere draws them; [`crate::polhode`] classifies one).
//!
//! With no torque, body angular momentum stays on the sphere |L| = M and on the energy ellipsoid
//! Σ Lₖ²/Iₖ = 2E; each polhode is their intersection (Landau & Lifshitz, *Mechanics* §37). With
//! `D = M²/2E` between I₂ and I₃ it circles axis 3, between I₁ and I₂ axis 1, and `D = I₂` is the
//! separatrix: the two planes L₃ = ±κ L₁, κ = √((1/I₁ − 1/I₂)/(1/I₂ − 1/I₃)), through ±axis 2.
//!
//! A curve around axis 3 is written with the polar angle φ about that axis: L₁ = ρ cos φ,
//! L₂ = ρ sin φ, L₃ = ±√(M² − ρ²), where the energy gives
//! `ρ² = (2E − M²/I₃) / (cos²φ/I₁ + sin²φ/I₂ − 1/I₃)`; around axis 1 the same with axes 1 and 3
//! exchanged. Both halves (±) are separate closed curves.

use nalgebra::Vector3;

/// Moments this close (relative to the largest) count as equal.
const EQUAL: f64 = 1e-12;

/// What a curve is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveKind {
    /// A polhode circling principal axis `0` or `2` (moments ascending).
    Around(usize),
    /// The separatrix through ±axis 2.
    Separatrix,
}

/// One closed curve on the momentum sphere (principal frame, units of L).
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// What it is.
    pub kind: CurveKind,
    /// Points along it; the last joins the first.
    pub points: Vec<Vector3<f64>>,
}

/// The polhodes of a body with principal `moments` (ascending) at |L| = `m`: `per_side` curves
/// around each of axes 1 and 3 (spaced evenly in `D = M²/2E`, endpoints excluded) and the
/// separatrix, each with `samples` points. Symmetric bodies have circles about their distinct
/// axis and no separatrix; three equal moments have no curves (L never moves in the body).
pub fn polhodes(moments: &Vector3<f64>, m: f64, per_side: usize, samples: usize) -> Vec<Curve> {
    let i = moments;
    let (equal12, equal23) = (i.y - i.x <= EQUAL * i.z, i.z - i.y <= EQUAL * i.z);
    let mut curves = Vec::new();
    if (equal12 && equal23) || m.is_nan() || m <= 0.0 {
        return curves;
    }
    for (axis, lo, hi) in [(2, i.y, i.z), (0, i.x, i.y)] {
        if hi - lo <= EQUAL * i.z {
            continue;
        }
        for j in 1..=per_side {
            let d = lo + (hi - lo) * j as f64 / (per_side + 1) as f64;
            let two_e = m * m / d;
            for sign in [1.0, -1.0] {
                curves.push(Curve {
                    kind: CurveKind::Around(axis),
                    points: around(i, m, two_e, axis, sign, samples),
                });
            }
        }
    }
    if !(equal12 || equal23) {
        curves.extend(separatrix(i, m, samples));
    }
    curves
}

/// The polhode through body angular momentum `l`, on the unit sphere (|L| scaled to 1): the
/// curve the torque-free motion of `l` follows. `None` at rest, with three equal moments, in a
/// steady spin or on the separatrix (drawn by [`polhodes`]).
pub fn polhode_through(moments: &Vector3<f64>, l: &Vector3<f64>, samples: usize) -> Option<Curve> {
    let crate::Polhode::Circles { axis, .. } = crate::polhode(moments, l) else {
        return None;
    };
    let unit = l.normalize();
    let sign = if unit[axis] < 0.0 { -1.0 } else { 1.0 };
    Some(Curve {
        kind: CurveKind::Around(axis),
        points: around(
            moments,
            1.0,
            two_energy(moments, &unit),
            axis,
            sign,
            samples,
        ),
    })
}

/// The energy 2E of body angular momentum `l`.
pub fn two_energy(moments: &Vector3<f64>, l: &Vector3<f64>) -> f64 {
    (0..3).map(|k| l[k] * l[k] / moments[k]).sum()
}

/// The half (`sign` of the axis component) of the polhode at energy `two_e` around `axis`.
fn around(
    i: &Vector3<f64>,
    m: f64,
    two_e: f64,
    axis: usize,
    sign: f64,
    samples: usize,
) -> Vec<Vector3<f64>> {
    // (a, b): the two other axes, in the order that keeps the polar formula's denominator
    // positive (1/Iₐ, 1/I_b on the far side of 1/I_axis).
    let (a, b) = if axis == 2 { (0, 1) } else { (1, 2) };
    // Evenly spaced φ crowds the points where the curve is slow and spreads them where it is
    // fast (near the separatrix, beside axis 2): sample densely, then keep a point each time the
    // curve has gone one target spacing, so the chords stay short everywhere.
    let dense = samples * 16;
    let spacing = std::f64::consts::TAU * m / samples as f64;
    let mut points: Vec<Vector3<f64>> = Vec::with_capacity(2 * samples);
    for s in 0..dense {
        let phi = std::f64::consts::TAU * s as f64 / dense as f64;
        let (c, sn) = (phi.cos(), phi.sin());
        let rho2 = ((two_e - m * m / i[axis]) / (c * c / i[a] + sn * sn / i[b] - 1.0 / i[axis]))
            .clamp(0.0, m * m);
        let rho = rho2.sqrt();
        let mut p = Vector3::zeros();
        p[a] = rho * c;
        p[b] = rho * sn;
        p[axis] = sign * (m * m - rho2).sqrt();
        if points.last().is_none_or(|q| (p - q).norm() >= spacing) {
            points.push(p);
        }
    }
    points
}

/// The separatrix: the great circles where the planes L₃ = ±κ L₁ cut the sphere.
fn separatrix(i: &Vector3<f64>, m: f64, samples: usize) -> Vec<Curve> {
    let kappa = ((1.0 / i.x - 1.0 / i.y) / (1.0 / i.y - 1.0 / i.z)).sqrt();
    [kappa, -kappa]
        .into_iter()
        .map(|k| {
            // Unit vectors spanning the plane: along axis 2, and (1, 0, k) normalised.
            let u = Vector3::new(1.0, 0.0, k).normalize();
            let points = (0..samples)
                .map(|s| {
                    let t = std::f64::consts::TAU * s as f64 / samples as f64;
                    (u * t.cos() + Vector3::y() * t.sin()) * m
                })
                .collect();
            Curve {
                kind: CurveKind::Separatrix,
                points,
            }
        })
        .collect()
}

/// The largest distance from `p` to the closed polyline `points`.
#[cfg(test)]
fn distance_to(points: &[Vector3<f64>], p: &Vector3<f64>) -> f64 {
    (0..points.len())
        .map(|k| {
            let (a, b) = (points[k], points[(k + 1) % points.len()]);
            let ab = b - a;
            let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
            (a + ab * t - p).norm()
        })
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    const I: Vector3<f64> = Vector3::new(1.0, 2.0, 3.0);

    #[test]
    fn every_point_is_on_the_sphere_and_its_energy_ellipsoid() {
        let m = 20.0;
        let curves = polhodes(&I, m, 4, 96);
        assert_eq!(curves.len(), 4 * 2 * 2 + 2);
        for c in &curves {
            let e0 = two_energy(&I, &c.points[0]);
            for p in &c.points {
                assert!((p.norm() - m).abs() < 1e-12 * m, "{p}");
                assert!((two_energy(&I, p) - e0).abs() < 1e-12 * e0, "{:?}", c.kind);
            }
            // Around an axis the curve keeps the sign of that axis' component.
            if let CurveKind::Around(axis) = c.kind {
                let s = c.points[0][axis].signum();
                assert!(c.points.iter().all(|p| p[axis] * s > 0.0));
            }
        }
    }

    #[test]
    fn separatrix_passes_through_both_ends_of_axis_two_at_energy_m2_over_i2() {
        let m = 5.0;
        let curves = polhodes(&I, m, 0, 400);
        assert_eq!(curves.len(), 2);
        for c in &curves {
            assert_eq!(c.kind, CurveKind::Separatrix);
            for p in &c.points {
                assert!((two_energy(&I, p) - m * m / I.y).abs() < 1e-12 * m * m);
            }
            for end in [Vector3::new(0.0, m, 0.0), Vector3::new(0.0, -m, 0.0)] {
                assert!(distance_to(&c.points, &end) < 1e-12 * m);
            }
        }
    }

    /// The exact solution's L (rbcore's elliptic functions) stays on the polhode the view draws
    /// through the start's L, to the drawing's chord tolerance.
    #[test]
    fn the_exact_trail_lies_on_the_drawn_curve() {
        for omega in [Vector3::new(0.4, 3.0, 0.7), Vector3::new(1.5, 3.0, 0.2)] {
            let l0 = I.component_mul(&omega);
            let m = l0.norm();
            let curve = polhode_through(&I, &l0, 256).expect("a polhode").points;
            let period = crate::torque_free_period(&I, &l0).expect("periodic");
            for k in 0..50 {
                let t = period * f64::from(k) / 50.0;
                let w = crate::torque_free_omega(&I, &l0, t).expect("periodic");
                let l = I.component_mul(&w) / m;
                // Drawing tolerance: the view draws the unit sphere ~120 px wide, so 1e-3 is an
                // eighth of a pixel; what remains is the chords' sagitta (measured ≤ 4.3e-4).
                let off = distance_to(&curve, &l);
                assert!(off < 1e-3, "t = {t}: {off} off the curve");
            }
        }
        assert!(polhode_through(&I, &Vector3::new(0.0, 0.0, 2.0), 64).is_none());
    }

    #[test]
    fn symmetric_and_spherical_bodies() {
        let top = Vector3::new(2.0, 2.0, 3.0);
        let curves = polhodes(&top, 1.0, 3, 32);
        assert_eq!(curves.len(), 6);
        assert!(curves.iter().all(|c| c.kind == CurveKind::Around(2)));
        // Circles of constant L₃ about the symmetry axis.
        for c in &curves {
            let z = c.points[0].z;
            assert!(c.points.iter().all(|p| (p.z - z).abs() < 1e-12));
        }
        assert!(polhodes(&Vector3::repeat(2.0), 1.0, 3, 32).is_empty());
        assert!(polhodes(&I, 0.0, 3, 32).is_empty());
    }
}
