//! Principal moments and axes: a scale-invariant Jacobi eigensolver for symmetric 3×3 tensors.
//!
//! The tensor is first divided by the power of two nearest its largest entry (an exact
//! operation), then diagonalised by cyclic Jacobi rotations (Golub & Van Loan, "Matrix
//! Computations", 4th ed., §8.5.2) whose stopping test is relative (Demmel & Veselić 1992:
//! |aₚq| ≤ ε·√(aₚₚ·aqq)), and the moments are multiplied back. No threshold is absolute, so a
//! 1 mm part in metres (moments ~1e-12) gets the same axes as the same part in millimetres, bit
//! for bit when the scale is a power of two. Equal or nearly equal moments are reported as
//! degenerate, and the free axes are then chosen deterministically (closest to the mesh axes).

use nalgebra::{Matrix3, Rotation3, Vector3};

/// Relative gap (to the largest moment) under which two moments count as equal.
pub const DEGENERACY_TOLERANCE: f64 = 1e-10;

/// Which principal moments coincide (within [`DEGENERACY_TOLERANCE`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Degeneracy {
    /// Three distinct moments: the axes are unique up to sign.
    Distinct,
    /// I₁ ≈ I₂ (a prolate body, like a rod): only axis 3 is unique.
    Moments12,
    /// I₂ ≈ I₃ (an oblate body, like a disc): only axis 1 is unique.
    Moments23,
    /// I₁ ≈ I₂ ≈ I₃ (a sphere or a cube): every axis is principal.
    Spherical,
}

impl Degeneracy {
    /// A short description for reports.
    pub fn describe(self) -> &'static str {
        match self {
            Degeneracy::Distinct => "distinct moments",
            Degeneracy::Moments12 => "I1 = I2 (axes 1 and 2 are any pair orthogonal to axis 3)",
            Degeneracy::Moments23 => "I2 = I3 (axes 2 and 3 are any pair orthogonal to axis 1)",
            Degeneracy::Spherical => "I1 = I2 = I3 (every axis is principal)",
        }
    }
}

/// Principal moments (ascending) and axes of an inertia tensor.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PrincipalInertia {
    /// I₁ ≤ I₂ ≤ I₃.
    pub moments: Vector3<f64>,
    /// Proper rotation whose column i is the unit axis of moment i (principal frame → mesh frame).
    pub rotation: Rotation3<f64>,
    /// Which moments are equal, i.e. which axes were chosen by convention.
    pub degeneracy: Degeneracy,
}

/// Eigenvalues (unsorted) and eigenvectors (columns) of a symmetric matrix by cyclic Jacobi.
///
/// Only the lower triangle's symmetric part is used: the input is symmetrised first.
pub fn symmetric_eigen(m: &Matrix3<f64>) -> (Vector3<f64>, Matrix3<f64>) {
    let mut a = (m + m.transpose()) * 0.5;
    let largest = a.amax();
    if largest == 0.0 || !largest.is_finite() {
        return (a.diagonal(), Matrix3::identity());
    }
    let scale = 2f64.powi(largest.log2().round() as i32);
    a /= scale;
    let mut v = Matrix3::identity();
    for _sweep in 0..64 {
        let mut rotated = false;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let apq = a[(p, q)];
            if apq == 0.0 {
                continue;
            }
            let (app, aqq) = (a[(p, p)], a[(q, q)]);
            // Relative test (Demmel–Veselić) or negligible next to the unit-scaled largest entry.
            if apq.abs() <= f64::EPSILON * (app * aqq).abs().sqrt()
                || apq.abs() <= f64::EPSILON * f64::EPSILON
            {
                a[(p, q)] = 0.0;
                a[(q, p)] = 0.0;
                continue;
            }
            rotated = true;
            let theta = (aqq - app) / (2.0 * apq);
            let t = if theta.abs() > 1e150 {
                0.5 / theta
            } else {
                theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt())
            };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            let mut j = Matrix3::identity();
            j[(p, p)] = c;
            j[(q, q)] = c;
            j[(p, q)] = s;
            j[(q, p)] = -s;
            a = j.transpose() * a * j;
            a[(p, q)] = 0.0;
            a[(q, p)] = 0.0;
            v *= j;
        }
        if !rotated {
            break;
        }
    }
    (a.diagonal() * scale, v)
}

/// Principal moments (ascending) and a right-handed set of principal axes of `tensor`.
pub fn principal_inertia(tensor: &Matrix3<f64>) -> PrincipalInertia {
    let (values, vectors) = symmetric_eigen(tensor);
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| values[i].total_cmp(&values[j]));
    let moments = Vector3::from_fn(|i, _| values[order[i]]);
    let axis = |i: usize| canonical_sign(vectors.column(order[i]).into_owned());

    let span = moments.amax();
    let equal = |x: f64, y: f64| (y - x).abs() <= DEGENERACY_TOLERANCE * span;
    let degeneracy = match (equal(moments[0], moments[1]), equal(moments[1], moments[2])) {
        (true, true) => Degeneracy::Spherical,
        (true, false) => Degeneracy::Moments12,
        (false, true) => Degeneracy::Moments23,
        (false, false) => Degeneracy::Distinct,
    };
    let columns = match degeneracy {
        Degeneracy::Spherical => [Vector3::x(), Vector3::y(), Vector3::z()],
        Degeneracy::Distinct => {
            let (a1, a2) = (axis(0), axis(1));
            [a1, a2, a1.cross(&a2).normalize()]
        }
        Degeneracy::Moments12 => {
            let a3 = axis(2);
            let a1 = closest_mesh_axis_orthogonal_to(&a3);
            [a1, a3.cross(&a1).normalize(), a3]
        }
        Degeneracy::Moments23 => {
            let a1 = axis(0);
            let a2 = closest_mesh_axis_orthogonal_to(&a1);
            [a1, a2, a1.cross(&a2).normalize()]
        }
    };
    PrincipalInertia {
        moments,
        rotation: Rotation3::from_matrix_unchecked(Matrix3::from_columns(&columns)),
        degeneracy,
    }
}

/// Flips `v` so its largest-magnitude component (the first, on ties) is positive.
fn canonical_sign(v: Vector3<f64>) -> Vector3<f64> {
    let v = v.normalize();
    if v[v.iamax()] < 0.0 { -v } else { v }
}

/// The mesh axis (x, y, z in that order of preference) least aligned with `n`, projected onto
/// the plane orthogonal to `n` and normalised.
fn closest_mesh_axis_orthogonal_to(n: &Vector3<f64>) -> Vector3<f64> {
    let i = n.iamin();
    let e = Vector3::ith(i, 1.0);
    (e - n * n.dot(&e)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check_decomposition(t: &Matrix3<f64>, p: &PrincipalInertia) {
        let r = p.rotation.matrix();
        let rebuilt = r * Matrix3::from_diagonal(&p.moments) * r.transpose();
        assert!((rebuilt - t).amax() <= 1e-14 * t.amax(), "{rebuilt} vs {t}");
        assert!((r.transpose() * r - Matrix3::identity()).amax() < 1e-14);
        assert!((r.determinant() - 1.0).abs() < 1e-14);
        assert!(p.moments[0] <= p.moments[1] && p.moments[1] <= p.moments[2]);
    }

    #[test]
    fn diagonalises_a_general_tensor() {
        let t = Matrix3::new(4.0, -1.0, 0.5, -1.0, 3.0, -0.25, 0.5, -0.25, 2.0);
        let p = principal_inertia(&t);
        check_decomposition(&t, &p);
        assert_eq!(p.degeneracy, Degeneracy::Distinct);
        // Trace and determinant are invariants.
        assert!((p.moments.sum() - 9.0).abs() < 1e-14);
        assert!((p.moments.product() - t.determinant()).abs() < 1e-13);
    }

    #[test]
    fn is_scale_invariant_from_1e_minus_20_to_1e20() {
        let t = Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.0);
        let base = principal_inertia(&t);
        for s in [1e-20, 3.7e-12, 1e-6, 1e6, 1e20] {
            let p = principal_inertia(&(t * s));
            check_decomposition(&(t * s), &p);
            assert!(((p.moments / s) - base.moments).amax() < 1e-14);
            assert!(
                (p.rotation.matrix() - base.rotation.matrix()).amax() < 1e-13,
                "scale {s}"
            );
        }
        let exact = principal_inertia(&(t * 2f64.powi(-70)));
        assert_eq!(exact.rotation, base.rotation);
        assert_eq!(exact.moments, base.moments * 2f64.powi(-70));
    }

    #[test]
    fn nearly_equal_moments_are_accurate_and_equal_ones_deterministic() {
        // Two moments 1e-9 apart in a rotated frame: still resolved to full accuracy.
        let r = Rotation3::from_euler_angles(0.3, -0.7, 1.1);
        let d = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0 + 1e-9, 3.0));
        let t = r.matrix() * d * r.matrix().transpose();
        let p = principal_inertia(&t);
        check_decomposition(&t, &p);
        assert_eq!(p.degeneracy, Degeneracy::Distinct);
        assert!((p.moments[1] - p.moments[0] - 1e-9).abs() < 1e-14);

        // Exactly equal pair: degenerate, axis 3 unique, axes 1/2 the projected mesh axes.
        let d = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 3.0));
        let t = r.matrix() * d * r.matrix().transpose();
        let p = principal_inertia(&t);
        check_decomposition(&t, &p);
        assert_eq!(p.degeneracy, Degeneracy::Moments12);
        let a3 = r.matrix().column(2).into_owned();
        assert!(p.rotation.matrix().column(2).dot(&a3).abs() > 1.0 - 1e-12);
        let again = principal_inertia(&(t.transpose()));
        assert_eq!(again.rotation, p.rotation);

        let sphere = principal_inertia(&(Matrix3::identity() * 2.5));
        assert_eq!(sphere.degeneracy, Degeneracy::Spherical);
        assert_eq!(sphere.rotation, Rotation3::identity());
        let oblate = principal_inertia(&Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 2.0)));
        assert_eq!(oblate.degeneracy, Degeneracy::Moments23);
        assert_eq!(oblate.rotation, Rotation3::identity());
    }

    #[test]
    fn zero_tensor_is_spherical() {
        let p = principal_inertia(&Matrix3::zeros());
        assert_eq!(p.moments, Vector3::zeros());
        assert_eq!(p.degeneracy, Degeneracy::Spherical);
    }
}
