//! Mirtich's polygon method (B. Mirtich, "Fast and Accurate Computation of Polyhedral Mass
//! Properties", J. Graphics Tools 1(2), 1996).
//!
//! Per face: the Newell normal n and plane offset w (n·x + w = 0); project onto the coordinate
//! plane (α, β) orthogonal to the normal's largest component γ; Green's theorem turns the
//! projection integrals (paper eq. 25–34, "π" integrals) into sums over edges; the face integrals
//! follow from the plane equation (eq. 18–24); the divergence theorem (eq. 6–17) sums them into the
//! volume integrals. Faces of zero area have a zero Newell normal and contribute exactly zero.
//!
//! Speed: the formulas are written once, generic over [`Real`], and run either on one face
//! (`f64`) or on four faces of the same corner count side by side ([`Lanes`], one SIMD lane
//! each). Each face's corners are permuted into (α, β) order when they are loaded, so every lane
//! does the same arithmetic whatever its projection plane.

use std::ops::{Add, Div, Mul, Neg, Sub};

use nalgebra::{Point3, Vector3};

use super::{BLOCK, compensated_total};
use crate::PolyMesh;

/// The ten volume integrals of `mesh` with coordinates measured from `reference`.
pub fn integrate(mesh: &PolyMesh, reference: Point3<f64>) -> [f64; 10] {
    let mut faces = mesh.faces().peekable();
    let blocks = std::iter::from_fn(|| {
        faces.peek()?;
        Some(block_sum(
            mesh.positions(),
            faces.by_ref().take(BLOCK),
            reference,
        ))
    });
    let mut total = compensated_total(blocks);
    for (t, scale) in total.iter_mut().zip(SCALE) {
        *t *= scale;
    }
    total
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

/// Faces integrated side by side.
const LANES: usize = 4;

/// The block kernel for this CPU: AVX2 where available (twice the vector width, and twice the
/// registers' capacity, which the four-lane formulas need).
fn block_sum<'a>(
    positions: &[Point3<f64>],
    faces: impl Iterator<Item = &'a [u32]>,
    reference: Point3<f64>,
) -> [f64; 10] {
    #[cfg(target_arch = "x86_64")]
    if super::has_avx2_fma() {
        // SAFETY: the CPU supports AVX2 (checked at run time just above), which is all
        // `block_sum_avx2` requires beyond safe Rust.
        #[allow(unsafe_code)]
        return unsafe { block_sum_avx2(positions, faces, reference) };
    }
    block_kernel(positions, faces, reference)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn block_sum_avx2<'a>(
    positions: &[Point3<f64>],
    faces: impl Iterator<Item = &'a [u32]>,
    reference: Point3<f64>,
) -> [f64; 10] {
    block_kernel(positions, faces, reference)
}

/// Sum of the (unscaled) contributions of a block of faces. Triangles and quads are queued and
/// integrated four at a time; other polygons, and what is left in the queues at the end of the
/// block, one at a time. The order is fixed by the face order, so results are reproducible.
#[inline(always)]
fn block_kernel<'a>(
    positions: &[Point3<f64>],
    faces: impl Iterator<Item = &'a [u32]>,
    reference: Point3<f64>,
) -> [f64; 10] {
    let corner = |i: u32| positions[i as usize] - reference;
    let mut acc = [0.0; 10];
    let mut triangles: Queue<3> = Queue::default();
    let mut quads: Queue<4> = Queue::default();
    let mut corners = Vec::with_capacity(16);
    for face in faces {
        match *face {
            [a, b, c] => triangles.push([a, b, c], positions, reference, &mut acc),
            [a, b, c, d] => quads.push([a, b, c, d], positions, reference, &mut acc),
            _ => {
                corners.clear();
                corners.extend(face.iter().map(|&i| corner(i)));
                add_face(&corners, &mut acc);
            }
        }
    }
    for f in triangles.pending() {
        add_face(&f.map(corner), &mut acc);
    }
    for f in quads.pending() {
        add_face(&f.map(corner), &mut acc);
    }
    acc
}

/// Up to [`LANES`] faces of `N` corners (as vertex indices) waiting to be integrated together.
struct Queue<const N: usize> {
    faces: [[u32; N]; LANES],
    len: usize,
}

impl<const N: usize> Default for Queue<N> {
    fn default() -> Self {
        Self {
            faces: [[0; N]; LANES],
            len: 0,
        }
    }
}

impl<const N: usize> Queue<N> {
    /// Queues a face; integrates the queue when it is full.
    #[inline(always)]
    fn push(
        &mut self,
        face: [u32; N],
        positions: &[Point3<f64>],
        reference: Point3<f64>,
        acc: &mut [f64; 10],
    ) {
        self.faces[self.len] = face;
        self.len += 1;
        if self.len == LANES {
            add_faces_side_by_side(&self.faces, positions, reference, acc);
            self.len = 0;
        }
    }

    fn pending(&self) -> &[[u32; N]] {
        &self.faces[..self.len]
    }
}

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

/// A face's plane, ready for projection: γ = the normal's largest component, (α, β) the next two
/// cyclically, the normal scaled to a convenient size, and the plane offset w.
struct Plane {
    gamma: usize,
    n: Vector3<f64>,
    w: f64,
}

/// The plane of a face, or `None` for a face of zero area (which contributes nothing).
#[inline(always)]
fn plane(corners: &[Vector3<f64>]) -> Option<Plane> {
    let n = newell_normal(corners);
    let gamma = n.iamax();
    if n[gamma] == 0.0 || !n[gamma].is_finite() {
        return None;
    }
    // Every face term is homogeneous of degree 0 in (n, w), so any multiple of the Newell normal
    // serves as well as the unit one, without a square root or a division. But not of any size:
    // |n| ~ L² for a face of size L, and the cubic terms (n³·L⁵ ~ L¹¹) would underflow below
    // L ~ 1e-27 (overflow above 1e27). Scaling n by the power of two that brings |n_γ| into
    // [1, 2) is exact and keeps the unit normal's range.
    let exponent = (n[gamma].abs().to_bits() >> 52) as i64; // biased: 0 (subnormal) ..= 2046
    let n = n * f64::from_bits(((2046 - exponent) as u64) << 52);
    // The plane through the corners' mean keeps non-planar polygons' error symmetric.
    let mean = corners.iter().sum::<Vector3<f64>>() * (1.0 / corners.len() as f64);
    Some(Plane {
        gamma,
        n,
        w: -n.dot(&mean),
    })
}

/// Adds one face's contribution (before the factors of [`SCALE`]) to `acc`.
#[inline(always)]
fn add_face(corners: &[Vector3<f64>], acc: &mut [f64; 10]) {
    let Some(plane) = plane(corners) else {
        return;
    };
    let (a, b) = ((plane.gamma + 1) % 3, (plane.gamma + 2) % 3);
    let mut alpha = [0.0; 16];
    let mut beta = [0.0; 16];
    let mut alpha_long = Vec::new();
    let mut beta_long = Vec::new();
    let (alpha, beta) = if corners.len() <= 16 {
        for (k, p) in corners.iter().enumerate() {
            alpha[k] = p[a];
            beta[k] = p[b];
        }
        (&alpha[..corners.len()], &beta[..corners.len()])
    } else {
        alpha_long.extend(corners.iter().map(|p| p[a]));
        beta_long.extend(corners.iter().map(|p| p[b]));
        (&alpha_long[..], &beta_long[..])
    };
    let n = plane.n;
    let terms = face_terms(
        &projection(alpha, beta),
        n[a],
        n[b],
        n[plane.gamma],
        plane.w,
    );
    scatter(&terms, plane.gamma, acc);
}

/// Adds [`LANES`] faces of `N` corners, integrated side by side: the same steps as [`plane`]
/// and [`add_face`], with the per-face choice of projection plane made by lane-wise selects.
#[inline(always)]
fn add_faces_side_by_side<const N: usize>(
    faces: &[[u32; N]; LANES],
    positions: &[Point3<f64>],
    reference: Point3<f64>,
    acc: &mut [f64; 10],
) {
    // Plain loops throughout (see `lanewise!` on closures).
    let zero = Lanes::constant(0.0);
    let (mut x, mut y, mut z) = ([zero; N], [zero; N], [zero; N]);
    for (l, face) in faces.iter().enumerate() {
        for (k, &i) in face.iter().enumerate() {
            let p = positions[i as usize] - reference;
            (x[k].0[l], y[k].0[l], z[k].0[l]) = (p.x, p.y, p.z);
        }
    }
    let (mut nx, mut ny, mut nz) = (zero, zero, zero);
    let (mut sx, mut sy, mut sz) = (zero, zero, zero);
    let mut prev = N - 1;
    for k in 0..N {
        nx = nx + (y[prev] - y[k]) * (z[prev] + z[k]);
        ny = ny + (z[prev] - z[k]) * (x[prev] + x[k]);
        nz = nz + (x[prev] - x[k]) * (y[prev] + y[k]);
        (sx, sy, sz) = (sx + x[k], sy + y[k], sz + z[k]);
        prev = k;
    }
    // Per lane, as [`plane`] does for one face: γ, the exact power-of-two rescaling, and the
    // corners permuted into (α, β). A zero-area lane keeps harmless values (n_γ = 1, the rest 0)
    // and is skipped at the end.
    let mut gamma = [0usize; LANES];
    let mut valid = [false; LANES];
    let (mut na, mut nb, mut nc, mut scale) = (zero, zero, Lanes::constant(1.0), zero);
    let (mut alpha, mut beta) = ([zero; N], [zero; N]);
    for l in 0..LANES {
        let n = [nx.0[l], ny.0[l], nz.0[l]];
        // The largest component, the first on ties (as `Vector3::iamax`).
        let g = if n[0].abs() >= n[1].abs() && n[0].abs() >= n[2].abs() {
            0
        } else if n[1].abs() >= n[2].abs() {
            1
        } else {
            2
        };
        if n[g] == 0.0 || !n[g].is_finite() {
            continue;
        }
        let exponent = (n[g].abs().to_bits() >> 52) as i64;
        let s = f64::from_bits(((2046 - exponent) as u64) << 52);
        let (a, b) = ((g + 1) % 3, (g + 2) % 3);
        (valid[l], gamma[l], scale.0[l]) = (true, g, s);
        (na.0[l], nb.0[l], nc.0[l]) = (n[a] * s, n[b] * s, n[g] * s);
        for k in 0..N {
            let v = [x[k].0[l], y[k].0[l], z[k].0[l]];
            (alpha[k].0[l], beta[k].0[l]) = (v[a], v[b]);
        }
    }
    let w = -((nx * sx + ny * sy + nz * sz) * scale) * Lanes::constant(1.0 / N as f64);
    let terms = face_terms(&projection(&alpha, &beta), na, nb, nc, w);
    for l in 0..LANES {
        if valid[l] {
            let mut t = [0.0; 12];
            for (tj, term) in t.iter_mut().zip(&terms) {
                *tj = term.0[l];
            }
            scatter(&t, gamma[l], acc);
        }
    }
}

/// Adds one face's twelve terms to the ten integrals, un-permuting (α, β, γ) back to (x, y, z).
#[inline(always)]
fn scatter(t: &[f64; 12], gamma: usize, acc: &mut [f64; 10]) {
    let (a, b, c) = ((gamma + 1) % 3, (gamma + 2) % 3, gamma);
    // ∫1 = ∮ x n_x dA, with whichever of the α, β, γ terms is the x one.
    acc[0] += if a == 0 {
        t[0]
    } else if b == 0 {
        t[1]
    } else {
        t[2]
    };
    acc[1 + a] += t[3];
    acc[1 + b] += t[4];
    acc[1 + c] += t[5];
    acc[4 + a] += t[6];
    acc[4 + b] += t[7];
    acc[4 + c] += t[8];
    // Products: slot 7 + a holds ∫αβ because (a, b) = (x, y), (y, z) or (z, x).
    acc[7 + a] += t[9];
    acc[7 + b] += t[10];
    acc[7 + c] += t[11];
}

/// The arithmetic the formulas need: `f64`, or [`Lanes`] of them.
trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    fn constant(v: f64) -> Self;
}

impl Real for f64 {
    #[inline(always)]
    fn constant(v: f64) -> Self {
        v
    }
}

/// [`LANES`] values operated on element by element (the compiler maps each to one SIMD op).
#[derive(Clone, Copy)]
struct Lanes([f64; LANES]);

// Loops, not `array::from_fn`: closures are not inlined into the AVX2 kernel's target-feature
// context, and an out-of-line SSE2 call per operation costs several times the arithmetic.
macro_rules! lanewise {
    ($trait:ident, $method:ident, $op:tt) => {
        impl $trait for Lanes {
            type Output = Lanes;
            #[inline(always)]
            fn $method(mut self, rhs: Lanes) -> Lanes {
                for l in 0..LANES {
                    self.0[l] $op rhs.0[l];
                }
                self
            }
        }
    };
}
lanewise!(Add, add, +=);
lanewise!(Sub, sub, -=);
lanewise!(Mul, mul, *=);
lanewise!(Div, div, /=);

impl Neg for Lanes {
    type Output = Lanes;
    #[inline(always)]
    fn neg(mut self) -> Lanes {
        for v in &mut self.0 {
            *v = -*v;
        }
        self
    }
}

impl Real for Lanes {
    #[inline(always)]
    fn constant(v: f64) -> Self {
        Lanes([v; LANES])
    }
}

/// Projection integrals over the face's projection onto the (α, β) plane (paper eq. 25–34).
struct Projection<T> {
    p1: T,
    pa: T,
    pb: T,
    paa: T,
    pab: T,
    pbb: T,
    paaa: T,
    paab: T,
    pabb: T,
    pbbb: T,
}

/// Green's theorem over the polygon's edges (α[k], β[k]) → (α[k+1], β[k+1]).
#[inline(always)]
fn projection<T: Real>(alpha: &[T], beta: &[T]) -> Projection<T> {
    let k = T::constant;
    let zero = k(0.0);
    let (mut p1, mut pa, mut pb, mut paa, mut pab, mut pbb) = (zero, zero, zero, zero, zero, zero);
    let (mut paaa, mut paab, mut pabb, mut pbbb) = (zero, zero, zero, zero);
    let last = alpha.len() - 1;
    let (mut a0, mut b0) = (alpha[last], beta[last]);
    for (&a1, &b1) in alpha.iter().zip(beta) {
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
        let cab = k(3.0) * a1_2 + k(2.0) * a1 * a0 + a0_2;
        let kab = a1_2 + k(2.0) * a1 * a0 + k(3.0) * a0_2;
        let caab = a0 * cab + k(4.0) * a1_3;
        let kaab = a1 * kab + k(4.0) * a0_3;
        let cabb = k(4.0) * b1_3 + k(3.0) * b1_2 * b0 + k(2.0) * b1 * b0_2 + b0_3;
        let kabb = b1_3 + k(2.0) * b1_2 * b0 + k(3.0) * b1 * b0_2 + k(4.0) * b0_3;
        p1 = p1 + db * c1;
        pa = pa + db * ca;
        paa = paa + db * caa;
        paaa = paaa + db * caaa;
        pb = pb + da * cb;
        pbb = pbb + da * cbb;
        pbbb = pbbb + da * cbbb;
        pab = pab + db * (b1 * cab + b0 * kab);
        paab = paab + db * (b1 * caab + b0 * kaab);
        pabb = pabb + da * (a1 * cabb + a0 * kabb);
        (a0, b0) = (a1, b1);
    }
    // Multiplications by the constant reciprocals: divisions would dominate the cost.
    Projection {
        p1: p1 * k(0.5),
        pa: pa * k(1.0 / 6.0),
        paa: paa * k(1.0 / 12.0),
        paaa: paaa * k(1.0 / 20.0),
        pb: pb * k(-1.0 / 6.0),
        pbb: pbb * k(-1.0 / 12.0),
        pbbb: pbbb * k(-1.0 / 20.0),
        pab: pab * k(1.0 / 24.0),
        paab: paab * k(1.0 / 60.0),
        pabb: pabb * k(-1.0 / 60.0),
    }
}

/// The face integrals (paper eq. 18–24) times the normal components, as twelve terms:
/// [nα·Fα, nβ·Fβ, nγ·Fγ, nα·Fα², nβ·Fβ², nγ·Fγ², nα·Fα³, nβ·Fβ³, nγ·Fγ³, nα·Fα²β, nβ·Fβ²γ, nγ·Fγ²α].
#[inline(always)]
fn face_terms<T: Real>(p: &Projection<T>, na: T, nb: T, nc: T, w: T) -> [T; 12] {
    let k = T::constant;
    let k1 = k(1.0) / nc;
    let (k2, k3) = (k1 * k1, k1 * k1 * k1);
    let k4 = k2 * k2;
    let fa = k1 * p.pa;
    let fb = k1 * p.pb;
    let fc = -k2 * (na * p.pa + nb * p.pb + w * p.p1);
    let faa = k1 * p.paa;
    let fbb = k1 * p.pbb;
    let quad = na * na * p.paa + k(2.0) * na * nb * p.pab + nb * nb * p.pbb;
    let fcc = k3 * (quad + w * (k(2.0) * (na * p.pa + nb * p.pb) + w * p.p1));
    let faaa = k1 * p.paaa;
    let fbbb = k1 * p.pbbb;
    let cubic = na * na * na * p.paaa
        + k(3.0) * na * na * nb * p.paab
        + k(3.0) * na * nb * nb * p.pabb
        + nb * nb * nb * p.pbbb;
    let fccc =
        -k4 * (cubic + k(3.0) * w * quad + w * w * (k(3.0) * (na * p.pa + nb * p.pb) + w * p.p1));
    let faab = k1 * p.paab;
    let fbbc = -k2 * (na * p.pabb + nb * p.pbbb + w * p.pbb);
    let fcca = k3
        * (na * na * p.paaa
            + k(2.0) * na * nb * p.paab
            + nb * nb * p.pabb
            + w * (k(2.0) * (na * p.paa + nb * p.pab) + w * p.pa));
    [
        na * fa,
        nb * fb,
        nc * fc,
        na * faa,
        nb * fbb,
        nc * fcc,
        na * faaa,
        nb * fbbb,
        nc * fccc,
        na * faab,
        nb * fbbc,
        nc * fcca,
    ]
}
