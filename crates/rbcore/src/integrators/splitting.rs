//! Symplectic splitting of the free rotor `H = Σ Lᵢ²/2Iᵢ` into its three exactly solvable parts.
//!
//! The flow of `Lᵢ²/2Iᵢ` turns the body about principal axis `i` by `θ = h Lᵢ/Iᵢ` (and body L by
//! `−θ`), so each sub-step keeps world L and |L| exact; the symmetric composition
//! R3(h/2) R2(h/2) R1(h) R2(h/2) R3(h/2) is second order and time-reversible, with E bounded
//! (Touma & Wisdom 1994; McLachlan 1993; Dullweber, Leimkuhler & McLachlan 1997).

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use crate::body::Body;

/// Axis index and fraction of `h` of each sub-step.
const SEQUENCE: [(usize, f64); 5] = [(2, 0.5), (1, 0.5), (0, 1.0), (1, 0.5), (2, 0.5)];

/// One free-rotor step of length `h`.
pub(crate) fn free_rotor(body: &mut Body, h: f64) {
    let mut l = body.angular_momentum_principal();
    let mut q = body.orientation.into_inner();
    for (i, frac) in SEQUENCE {
        let theta = h * frac * l[i] * body.inv_moments[i];
        let (s, c) = (0.5 * theta).sin_cos();
        let mut axis = Vector3::zeros();
        axis[i] = s;
        q *= Quaternion::from_parts(c, axis);
        // Body L turns by −θ about axis i.
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let (st, ct) = theta.sin_cos();
        let (lj, lk) = (l[j], l[k]);
        l[j] = ct * lj + st * lk;
        l[k] = -st * lj + ct * lk;
    }
    body.orientation = UnitQuaternion::new_normalize(q);
}
