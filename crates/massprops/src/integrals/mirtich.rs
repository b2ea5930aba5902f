//! Mirtich's polygon method (B. Mirtich, "Fast and Accurate Computation of Polyhedral Mass
//! Properties", J. Graphics Tools 1(2), 1996).
//!
//! Per face: the Newell normal n̂ and plane offset w (n̂·x + w = 0); project onto the coordinate
//! plane (α, β) orthogonal to the normal's largest component γ; Green's theorem turns the
//! projection integrals (paper eq. 25–34, "π" integrals) into sums over edges; the face integrals
//! follow from the plane equation (eq. 18–24); the divergence theorem (eq. 6–17) sums them into the
//! volume integrals. Faces of zero area have a zero Newell normal and contribute exactly zero.

use nalgebra::{Point3, Vector3};

use super::{BLOCK, compensated_total, madd};
use crate::PolyMesh;

/// The ten volume integrals of `mesh` with coordinates measured from `reference`.
pub fn integrate(mesh: &PolyMesh, reference: Point3<f64>) -> [f64; 10] {
    let faces: Vec<&[u32]> = mesh.faces().collect();
    let blocks = faces
        .chunks(BLOCK)
        .map(|chunk| block_sum::<false>(mesh.positions(), chunk, reference));
    let mut total = compensated_total(blocks);
    for (t, scale) in total.iter_mut().zip(SCALE) {
        *t *= scale;
    }
    total
}

/// Sum of the (unscaled) contributions of a block of faces. Triangles and quads get their own
/// copies of the face code, with loops of known length the compiler unrolls.
// Measured: fused multiply-add makes this kernel slower (longer dependency chains), so it
// is instantiated without it; the parameter stays for the shared face code.
fn block_sum<const FMA: bool>(
    positions: &[Point3<f64>],
    faces: &[&[u32]],
    reference: Point3<f64>,
) -> [f64; 10] {
    let corner = |i: u32| positions[i as usize] - reference;
    let mut block = [0.0; 10];
    let mut corners = Vec::with_capacity(16);
    for face in faces {
        match *face {
            [a, b, c] => face_contribution::<FMA>(&[a, b, c].map(|&i| corner(i)), &mut block),
            [a, b, c, d] => face_contribution::<FMA>(&[a, b, c, d].map(|&i| corner(i)), &mut block),
            _ => {
                corners.clear();
                corners.extend(face.iter().map(|&i| corner(i)));
                face_contribution::<FMA>(&corners, &mut block);
            }
        }
    }
    block
}

/// The divergence-theorem factors of eq. (13)–(17): T1/2, T2/3, TP/2.
const SCALE: [f64; 10] = [
    1.0,
    0.5,
    0.5,
    0.5,
    1.0 / 3.0,
    1.0 / 3.0,
    1.0 / 3.0,
    0.5,
    0.5,
    0.5,
];

/// Newell's normal of a polygon: twice its vector area, exact for planar polygons of any shape.
#[inline(always)]
pub(crate) fn newell_normal(corners: &[Vector3<f64>]) -> Vector3<f64> {
    let mut n = Vector3::zeros();
    let mut prev = corners[corners.len() - 1];
    for &cur in corners {
        n.x += (prev.y - cur.y) * (prev.z + cur.z);
        n.y += (prev.z - cur.z) * (prev.x + cur.x);
        n.z += (prev.x - cur.x) * (prev.y + cur.y);
        prev = cur;
    }
    n
}

/// Projection integrals over the face's projection onto the (α, β) plane, by Green's theorem.
struct Projection {
    p1: f64,
    pa: f64,
    pb: f64,
    paa: f64,
    pab: f64,
    pbb: f64,
    paaa: f64,
    paab: f64,
    pabb: f64,
    pbbb: f64,
}

#[inline(always)]
fn projection_integrals<const FMA: bool, const A: usize, const B: usize>(
    corners: &[Vector3<f64>],
) -> Projection {
    let (a, b) = (A, B);
    let (mut p1, mut pa, mut pb, mut paa, mut pab, mut pbb) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    let (mut paaa, mut paab, mut pabb, mut pbbb) = (0.0, 0.0, 0.0, 0.0);
    let mut prev = corners[corners.len() - 1];
    for &cur in corners {
        let (a0, b0, a1, b1) = (prev[a], prev[b], cur[a], cur[b]);
        prev = cur;
        let (da, db) = (a1 - a0, b1 - b0);
        let (a0_2, b0_2, a1_2, b1_2) = (a0 * a0, b0 * b0, a1 * a1, b1 * b1);
        let (a0_3, b0_3, a1_3, b1_3) = (a0_2 * a0, b0_2 * b0, a1_2 * a1, b1_2 * b1);
        let c1 = a1 + a0;
        let ca = a1 * c1 + a0_2;
        let caa = a1 * ca + a0_3;
        let caaa = a1 * caa + a0_3 * a0;
        let cb = b1 * (b1 + b0) + b0_2;
        let cbb = b1 * cb + b0_3;
        let cbbb = b1 * cbb + b0_3 * b0;
        let cab = 3.0 * a1_2 + 2.0 * a1 * a0 + a0_2;
        let kab = a1_2 + 2.0 * a1 * a0 + 3.0 * a0_2;
        let caab = a0 * cab + 4.0 * a1_3;
        let kaab = a1 * kab + 4.0 * a0_3;
        let cabb = 4.0 * b1_3 + 3.0 * b1_2 * b0 + 2.0 * b1 * b0_2 + b0_3;
        let kabb = b1_3 + 2.0 * b1_2 * b0 + 3.0 * b1 * b0_2 + 4.0 * b0_3;
        p1 = madd::<FMA>(db, c1, p1);
        pa = madd::<FMA>(db, ca, pa);
        paa = madd::<FMA>(db, caa, paa);
        paaa = madd::<FMA>(db, caaa, paaa);
        pb = madd::<FMA>(da, cb, pb);
        pbb = madd::<FMA>(da, cbb, pbb);
        pbbb = madd::<FMA>(da, cbbb, pbbb);
        pab = madd::<FMA>(db, madd::<FMA>(b1, cab, b0 * kab), pab);
        paab = madd::<FMA>(db, madd::<FMA>(b1, caab, b0 * kaab), paab);
        pabb = madd::<FMA>(da, madd::<FMA>(a1, cabb, a0 * kabb), pabb);
    }
    // Multiplications by the constant reciprocals: divisions would dominate the cost.
    Projection {
        p1: p1 * 0.5,
        pa: pa * (1.0 / 6.0),
        paa: paa * (1.0 / 12.0),
        paaa: paaa * (1.0 / 20.0),
        pb: pb * (-1.0 / 6.0),
        pbb: pbb * (-1.0 / 12.0),
        pbbb: pbbb * (-1.0 / 20.0),
        pab: pab * (1.0 / 24.0),
        paab: paab * (1.0 / 60.0),
        pabb: pabb * (-1.0 / 60.0),
    }
}

/// Adds one face's contribution (before the factors of [`SCALE`]) to `acc`.
#[inline(always)]
fn face_contribution<const FMA: bool>(corners: &[Vector3<f64>], acc: &mut [f64; 10]) {
    // Every term below is homogeneous of degree 0 in (n, w), so the unnormalised Newell normal
    // serves as well as the unit one and saves a square root and a division per face.
    let n = newell_normal(corners);
    let c = n.iamax();
    if n[c] == 0.0 || !n[c].is_finite() {
        return;
    }
    // But not of any size: |n| ~ L² for a face of size L, and the cubic terms (n³·L⁵ ~ L¹¹)
    // underflow below L ~ 1e-27 (overflow above 1e27). Scaling n by the power of two that brings
    // |n_γ| into [1, 2) is exact and keeps the unit normal's range.
    let exponent = (n[c].abs().to_bits() >> 52) as i64; // biased: 0 (subnormal) ..= 2046
    let n = n * f64::from_bits(((2046 - exponent) as u64) << 52);
    // The plane through the corners' mean keeps non-planar polygons' error symmetric.
    let mean = corners.iter().sum::<Vector3<f64>>() * (1.0 / corners.len() as f64);
    let w = -n.dot(&mean);
    match c {
        0 => add_projected::<FMA, 0, 1, 2>(corners, &n, w, acc),
        1 => add_projected::<FMA, 1, 2, 0>(corners, &n, w, acc),
        _ => add_projected::<FMA, 2, 0, 1>(corners, &n, w, acc),
    }
}

/// The face's contribution once γ = `C` (the normal's largest component) is known; the
/// projection plane is (α, β) = (`A`, `B`), cyclic after `C`, so every index is a constant.
#[inline(always)]
fn add_projected<const FMA: bool, const C: usize, const A: usize, const B: usize>(
    corners: &[Vector3<f64>],
    n: &Vector3<f64>,
    w: f64,
    acc: &mut [f64; 10],
) {
    let (a, b, c) = (A, B, C);
    let p = projection_integrals::<FMA, A, B>(corners);

    let (na, nb, nc) = (n[a], n[b], n[c]);
    let k1 = 1.0 / nc;
    let (k2, k3, k4) = (k1 * k1, k1 * k1 * k1, k1 * k1 * k1 * k1);
    let fa = k1 * p.pa;
    let fb = k1 * p.pb;
    let fc = -k2 * (na * p.pa + nb * p.pb + w * p.p1);
    let faa = k1 * p.paa;
    let fbb = k1 * p.pbb;
    let quad = na * na * p.paa + 2.0 * na * nb * p.pab + nb * nb * p.pbb;
    let fcc = k3 * (quad + w * (2.0 * (na * p.pa + nb * p.pb) + w * p.p1));
    let faaa = k1 * p.paaa;
    let fbbb = k1 * p.pbbb;
    let cubic = na * na * na * p.paaa
        + 3.0 * na * na * nb * p.paab
        + 3.0 * na * nb * nb * p.pabb
        + nb * nb * nb * p.pbbb;
    let fccc = -k4 * (cubic + 3.0 * w * quad + w * w * (3.0 * (na * p.pa + nb * p.pb) + w * p.p1));
    let faab = k1 * p.paab;
    let fbbc = -k2 * (na * p.pabb + nb * p.pbbb + w * p.pbb);
    let fcca = k3
        * (na * na * p.paaa
            + 2.0 * na * nb * p.paab
            + nb * nb * p.pabb
            + w * (2.0 * (na * p.paa + nb * p.pab) + w * p.pa));

    // ∫1 = ∮ x n_x dA, with whichever of Fα, Fβ, Fγ is the face integral of x.
    let fx = if a == 0 {
        fa
    } else if b == 0 {
        fb
    } else {
        fc
    };
    acc[0] += n.x * fx;
    acc[1 + a] += na * faa;
    acc[1 + b] += nb * fbb;
    acc[1 + c] += nc * fcc;
    acc[4 + a] += na * faaa;
    acc[4 + b] += nb * fbbb;
    acc[4 + c] += nc * fccc;
    // Products: slot 7 + a holds ∫αβ because (a, b) = (x, y), (y, z) or (z, x).
    acc[7 + a] += na * faab;
    acc[7 + b] += nb * fbbc;
    acc[7 + c] += nc * fcca;
}
