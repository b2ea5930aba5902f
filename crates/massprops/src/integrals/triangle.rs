//! The triangle fast path: Mirtich's integrals reduced algebraically for a triangle
//! (D. Eberly, "Polyhedral Mass Properties (Revisited)", Geometric Tools, 2002, which expands the
//! divergence-theorem surface integrals over a triangle parametrised by its edges).
//!
//! With d = (p₁ − p₀) × (p₂ − p₀) and per-axis symmetric polynomials f₁, f₂, f₃, g₀, g₁, g₂ of the
//! three corner coordinates, each integral is one product per triangle, e.g. ∫1 += dₓ·f₁(x)/6.

use nalgebra::Point3;
use rayon::prelude::*;

use super::{BLOCK, compensated_total, madd};

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
pub fn integrate(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    reference: Point3<f64>,
) -> [f64; 10] {
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

/// Eberly's per-axis subexpressions f₁, f₂, f₃, g₀, g₁, g₂ of the corner coordinates w₀, w₁, w₂.
#[inline(always)]
fn subexpressions<const FMA: bool>(w0: f64, w1: f64, w2: f64) -> [f64; 6] {
    let t0 = w0 + w1;
    let f1 = t0 + w2;
    let t1 = w0 * w0;
    let t2 = madd::<FMA>(w1, t0, t1);
    let f2 = madd::<FMA>(w2, f1, t2);
    let f3 = madd::<FMA>(w2, f2, madd::<FMA>(w1, t2, w0 * t1));
    let g0 = madd::<FMA>(w0, f1 + w0, f2);
    let g1 = madd::<FMA>(w1, f1 + w1, f2);
    let g2 = madd::<FMA>(w2, f1 + w2, f2);
    [f1, f2, f3, g0, g1, g2]
}

/// Adds one triangle (corners relative to the reference point, as `[x, y, z]` of each corner)
/// to the ten sums.
#[inline(always)]
fn add_triangle<const FMA: bool>(p: [[f64; 3]; 3], s: &mut [f64; 10]) {
    let [[x0, y0, z0], [x1, y1, z1], [x2, y2, z2]] = p;
    let (ax, ay, az) = (x1 - x0, y1 - y0, z1 - z0);
    let (bx, by, bz) = (x2 - x0, y2 - y0, z2 - z0);
    let dx = madd::<FMA>(ay, bz, -(az * by));
    let dy = madd::<FMA>(az, bx, -(ax * bz));
    let dz = madd::<FMA>(ax, by, -(ay * bx));
    let [f1x, f2x, f3x, g0x, g1x, g2x] = subexpressions::<FMA>(x0, x1, x2);
    let [_, f2y, f3y, g0y, g1y, g2y] = subexpressions::<FMA>(y0, y1, y2);
    let [_, f2z, f3z, g0z, g1z, g2z] = subexpressions::<FMA>(z0, z1, z2);
    s[0] = madd::<FMA>(dx, f1x, s[0]);
    s[1] = madd::<FMA>(dx, f2x, s[1]);
    s[2] = madd::<FMA>(dy, f2y, s[2]);
    s[3] = madd::<FMA>(dz, f2z, s[3]);
    s[4] = madd::<FMA>(dx, f3x, s[4]);
    s[5] = madd::<FMA>(dy, f3y, s[5]);
    s[6] = madd::<FMA>(dz, f3z, s[6]);
    let pxy = madd::<FMA>(y2, g2x, madd::<FMA>(y1, g1x, y0 * g0x));
    let pyz = madd::<FMA>(z2, g2y, madd::<FMA>(z1, g1y, z0 * g0y));
    let pzx = madd::<FMA>(x2, g2z, madd::<FMA>(x1, g1z, x0 * g0z));
    s[7] = madd::<FMA>(dx, pxy, s[7]);
    s[8] = madd::<FMA>(dy, pyz, s[8]);
    s[9] = madd::<FMA>(dz, pzx, s[9]);
}

/// Triangles handled side by side, so the compiler can put one triangle in each SIMD lane.
const LANES: usize = 8;

/// Sum of one block of triangles: `LANES` independent partial sums, added lane by lane at the end.
#[inline(always)]
fn block_kernel<const FMA: bool>(
    positions: &[Point3<f64>],
    chunk: &[[u32; 3]],
    reference: Point3<f64>,
) -> [f64; 10] {
    let corner = |i: u32| {
        let p = positions[i as usize];
        [p.x - reference.x, p.y - reference.y, p.z - reference.z]
    };
    let mut lanes = [[0.0; 10]; LANES];
    let (groups, tail) = chunk.as_chunks::<LANES>();
    for group in groups {
        let corners: [[[f64; 3]; 3]; LANES] = std::array::from_fn(|l| group[l].map(corner));
        for (lane, triangle) in lanes.iter_mut().zip(corners) {
            add_triangle::<FMA>(triangle, lane);
        }
    }
    for (lane, triangle) in lanes.iter_mut().zip(tail) {
        add_triangle::<FMA>(triangle.map(corner), lane);
    }
    std::array::from_fn(|k| lanes.iter().map(|lane| lane[k]).sum())
}

/// The block kernel for this CPU: AVX2 with fused multiply-add where available.
fn block_sum(positions: &[Point3<f64>], chunk: &[[u32; 3]], reference: Point3<f64>) -> [f64; 10] {
    #[cfg(target_arch = "x86_64")]
    if super::has_avx2_fma() {
        // SAFETY: the CPU supports AVX2 and FMA (checked at run time just above), which is all
        // `block_sum_avx2` requires beyond safe Rust.
        #[allow(unsafe_code)]
        return unsafe { block_sum_avx2(positions, chunk, reference) };
    }
    block_kernel::<false>(positions, chunk, reference)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn block_sum_avx2(
    positions: &[Point3<f64>],
    chunk: &[[u32; 3]],
    reference: Point3<f64>,
) -> [f64; 10] {
    block_kernel::<true>(positions, chunk, reference)
}
