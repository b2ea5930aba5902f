//! The triangle fast path: Mirtich's integrals reduced algebraically for a triangle
//! (D. Eberly, "Polyhedral Mass Properties (Revisited)", Geometric Tools, 2002, which expands the
//! divergence-theorem surface integrals over a triangle parametrised by its edges).
//!
//! With d = (p₁ − p₀) × (p₂ − p₀) and per-axis symmetric polynomials f₁, f₂, f₃, g₀, g₁, g₂ of the
//! three corner coordinates, each integral is one product per triangle, e.g. ∫1 += dₓ·f₁(x)/6.

use nalgebra::Point3;
use rayon::prelude::*;

use super::{BLOCK, compensated_total};

/// Final factors of Eberly's sums: 1/6, 1/24, 1/60, 1/120.
const SCALE: [f64; 10] = [
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 24.0,
    1.0 / 24.0,
    1.0 / 60.0,
    1.0 / 60.0,
    1.0 / 60.0,
    1.0 / 120.0,
    1.0 / 120.0,
    1.0 / 120.0,
];

/// The ten volume integrals, sequentially.
pub fn integrate(positions: &[Point3<f64>], triangles: &[[u32; 3]], reference: Point3<f64>) -> [f64; 10] {
    let blocks = triangles
        .chunks(BLOCK)
        .map(|chunk| block_sum(positions, chunk, reference));
    scaled(compensated_total(blocks))
}

/// The ten volume integrals on the rayon pool; equal bit for bit to [`integrate`].
pub fn integrate_parallel(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    reference: Point3<f64>,
) -> [f64; 10] {
    let blocks: Vec<[f64; 10]> = triangles
        .par_chunks(BLOCK)
        .map(|chunk| block_sum(positions, chunk, reference))
        .collect();
    scaled(compensated_total(blocks))
}

fn scaled(mut total: [f64; 10]) -> [f64; 10] {
    for (t, s) in total.iter_mut().zip(SCALE) {
        *t *= s;
    }
    total
}

/// Eberly's per-axis subexpressions of the corner coordinates w₀, w₁, w₂.
#[inline(always)]
fn subexpressions(w0: f64, w1: f64, w2: f64) -> (f64, f64, f64, f64, f64, f64) {
    let t0 = w0 + w1;
    let f1 = t0 + w2;
    let t1 = w0 * w0;
    let t2 = t1 + w1 * t0;
    let f2 = t2 + w2 * f1;
    let f3 = w0 * t1 + w1 * t2 + w2 * f2;
    let g0 = f2 + w0 * (f1 + w0);
    let g1 = f2 + w1 * (f1 + w1);
    let g2 = f2 + w2 * (f1 + w2);
    (f1, f2, f3, g0, g1, g2)
}

#[inline]
fn block_sum(positions: &[Point3<f64>], chunk: &[[u32; 3]], reference: Point3<f64>) -> [f64; 10] {
    let mut s = [0.0; 10];
    for &[i0, i1, i2] in chunk {
        let p0 = positions[i0 as usize] - reference;
        let p1 = positions[i1 as usize] - reference;
        let p2 = positions[i2 as usize] - reference;
        let d = (p1 - p0).cross(&(p2 - p0));
        let (f1x, f2x, f3x, g0x, g1x, g2x) = subexpressions(p0.x, p1.x, p2.x);
        let (_, f2y, f3y, g0y, g1y, g2y) = subexpressions(p0.y, p1.y, p2.y);
        let (_, f2z, f3z, g0z, g1z, g2z) = subexpressions(p0.z, p1.z, p2.z);
        s[0] += d.x * f1x;
        s[1] += d.x * f2x;
        s[2] += d.y * f2y;
        s[3] += d.z * f2z;
        s[4] += d.x * f3x;
        s[5] += d.y * f3y;
        s[6] += d.z * f3z;
        s[7] += d.x * (p0.y * g0x + p1.y * g1x + p2.y * g2x);
        s[8] += d.y * (p0.z * g0y + p1.z * g1y + p2.z * g2y);
        s[9] += d.z * (p0.x * g0z + p1.x * g1z + p2.x * g2z);
    }
    s
}
