//! Mirtich's polygon method (B. Mirtich, "Fast and Accurate Computation of Polyhedral Mass
//! Properties", J. Graphics Tools 1(2), 1996).
//!
//! Per face: the Newell normal n and plane offset w (n·x + w = 0); project onto the coordinate
//! plane (α, β) orthogonal to the normal's largest component γ; Green's theorem turns the
//! projection integrals (paper eq. 25–34, "π" integrals) into sums over edges; the face integrals
//! follow from the plane equation (eq. 18–24); the divergence theorem (eq. 6–17) sums them into the
//! volume integrals. Faces of zero area have a zero Newell normal and contribute exactly zero.
//!
//! Speed: the formulas are written once, generic over `Real`, and run on one face (`f64`) or
//! on several faces of the same corner count side by side (one SIMD lane each). Each lane's
//! choice of γ is a mask; corners are permuted into (α, β) and the results back into (x, y, z)
//! by selects, so every lane does the same arithmetic whatever its projection plane.

use std::ops::Range;

use nalgebra::{Point3, Vector3};

use super::simd::{Kernel, Level, Real};
use super::{BLOCK, compensated_total};
use crate::PolyMesh;

/// The ten volume integrals of `mesh` with coordinates measured from `reference`.
pub fn integrate(mesh: &PolyMesh, reference: Point3<f64>) -> [f64; 10] {
    integrate_with(Level::detect(), mesh, reference)
}

/// [`integrate`] with the kernels of `level`.
pub(crate) fn integrate_with(level: Level, mesh: &PolyMesh, reference: Point3<f64>) -> [f64; 10] {
    let faces = mesh.face_count();
    let blocks = (0..faces).step_by(BLOCK).map(|start| {
        level.run(BlockSum {
            mesh,
            faces: start..faces.min(start + BLOCK),
            reference,
        })
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

/// Most lanes of any vector type.
const MAX_LANES: usize = 8;

/// Sum of the (unscaled) contributions of a block of faces. Triangles and quads are queued and
/// integrated [`Real::LANES`] at a time; other polygons, and what is left in the queues at the
/// end of the block, one at a time. The order is fixed by the face order, so results are
/// reproducible (bit for bit on CPUs with the same instruction set).
struct BlockSum<'a> {
    mesh: &'a PolyMesh,
    faces: Range<usize>,
    reference: Point3<f64>,
}

impl Kernel for BlockSum<'_> {
    type Output = [f64; 10];

    #[inline(always)]
    fn run<T: Real>(self) -> [f64; 10] {
        let Self {
            mesh,
            faces,
            reference,
        } = self;
        const { assert!(T::LANES <= MAX_LANES) };
        let positions = mesh.positions();
        let mut lanes = [T::splat(0.0); 10];
        let mut single = [0.0; 10];
        let mut triangles: Queue<3> = Queue::default();
        let mut quads: Queue<4> = Queue::default();
        let (mut x, mut y, mut z) = (Vec::new(), Vec::new(), Vec::new());
        for f in faces {
            match *mesh.face(f) {
                [a, b, c] => {
                    if let Some(full) = triangles.push([a, b, c], T::LANES) {
                        add_faces(full, positions, reference, &mut lanes);
                    }
                }
                [a, b, c, d] => {
                    if let Some(full) = quads.push([a, b, c, d], T::LANES) {
                        add_faces(full, positions, reference, &mut lanes);
                    }
                }
                ref face => {
                    x.clear();
                    y.clear();
                    z.clear();
                    for &i in face {
                        let p = positions[i as usize] - reference;
                        x.push(p.x);
                        y.push(p.y);
                        z.push(p.z);
                    }
                    add_polygon(&x, &y, &z, &mut single);
                }
            }
        }
        add_each(triangles.pending(), positions, reference, &mut single);
        add_each(quads.pending(), positions, reference, &mut single);
        for (s, l) in single.iter_mut().zip(lanes) {
            *s += l.sum_lanes();
        }
        single
    }
}

/// Faces of `N` corners (as vertex indices) waiting to be integrated together.
struct Queue<const N: usize> {
    faces: [[u32; N]; MAX_LANES],
    len: usize,
}

impl<const N: usize> Default for Queue<N> {
    fn default() -> Self {
        Self {
            faces: [[0; N]; MAX_LANES],
            len: 0,
        }
    }
}

impl<const N: usize> Queue<N> {
    /// Queues a face; returns the queued faces (and empties the queue) once there are `lanes`.
    #[inline(always)]
    fn push(&mut self, face: [u32; N], lanes: usize) -> Option<&[[u32; N]]> {
        self.faces[self.len] = face;
        self.len += 1;
        if self.len < lanes {
            return None;
        }
        self.len = 0;
        Some(&self.faces[..lanes])
    }

    fn pending(&self) -> &[[u32; N]] {
        &self.faces[..self.len]
    }
}

/// Adds the faces `faces[0..T::LANES]` of `N` corners each, one per lane.
#[inline(always)]
fn add_faces<T: Real, const N: usize>(
    faces: &[[u32; N]],
    positions: &[Point3<f64>],
    reference: Point3<f64>,
    acc: &mut [T; 10],
) {
    let zero = T::splat(0.0);
    let (mut x, mut y, mut z) = ([zero; N], [zero; N], [zero; N]);
    for k in 0..N {
        [x[k], y[k], z[k]] = T::gather(positions, reference, faces, k);
    }
    add_polygon(&x, &y, &z, acc);
}

/// Adds `faces` one at a time, in order.
fn add_each<const N: usize>(
    faces: &[[u32; N]],
    positions: &[Point3<f64>],
    reference: Point3<f64>,
    acc: &mut [f64; 10],
) {
    for face in faces.chunks(1) {
        add_faces(face, positions, reference, acc);
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

/// Which coordinate is γ (the normal's largest component, the first on ties, as
/// `Vector3::iamax`) in each lane: `x` where γ = x; `y` where γ = y unless `x` is set.
#[derive(Clone, Copy)]
struct Gamma<M> {
    x: M,
    y: M,
}

impl<M: Copy> Gamma<M> {
    /// The (α, β, γ) coordinates of (x, y, z): γ = x → (y, z, x), γ = y → (z, x, y),
    /// γ = z → (x, y, z).
    #[inline(always)]
    fn permute<T: Real<Mask = M>>(self, x: T, y: T, z: T) -> [T; 3] {
        [
            T::select(self.x, y, T::select(self.y, z, x)),
            T::select(self.x, z, T::select(self.y, x, y)),
            T::select(self.x, x, T::select(self.y, y, z)),
        ]
    }

    /// The (x, y, z) values of terms given in (α, β, γ) order: the inverse of [`Self::permute`].
    #[inline(always)]
    fn unpermute<T: Real<Mask = M>>(self, [a, b, c]: [T; 3]) -> [T; 3] {
        [
            T::select(self.x, c, T::select(self.y, b, a)),
            T::select(self.x, a, T::select(self.y, c, b)),
            T::select(self.x, b, T::select(self.y, a, c)),
        ]
    }
}

/// Adds one polygon per lane, given by its corners' coordinates relative to the reference point,
/// to the ten sums (before the factors of [`SCALE`]).
#[inline(always)]
fn add_polygon<T: Real>(x: &[T], y: &[T], z: &[T], acc: &mut [T; 10]) {
    let zero = T::splat(0.0);
    let corners = x.len();
    let (mut nx, mut ny, mut nz) = (zero, zero, zero);
    let (mut sx, mut sy, mut sz) = (zero, zero, zero);
    let mut prev = corners - 1;
    for k in 0..corners {
        nx += (y[prev] - y[k]) * (z[prev] + z[k]);
        ny += (z[prev] - z[k]) * (x[prev] + x[k]);
        nz += (x[prev] - x[k]) * (y[prev] + y[k]);
        (sx, sy, sz) = (sx + x[k], sy + y[k], sz + z[k]);
        prev = k;
    }
    let (ax, ay, az) = (nx.abs(), ny.abs(), nz.abs());
    let gamma = Gamma {
        x: ax.ge(ay) & ax.ge(az),
        y: ay.ge(az),
    };
    let [_, _, n_gamma] = gamma.permute(nx, ny, nz);
    // A face of zero area (or overflowing normal) gets a zero scale, hence n = 0 and w = 0, with
    // n_γ = 1 to keep the arithmetic finite; its terms are dropped at the end.
    let valid = n_gamma.is_finite_nonzero();
    // Every face term is homogeneous of degree 0 in (n, w), so any multiple of the Newell normal
    // serves as well as the unit one, without a square root or a division. But not of any size:
    // |n| ~ L² for a face of size L, and the cubic terms (n³·L⁵ ~ L¹¹) would underflow below
    // L ~ 1e-27 (overflow above 1e27). Scaling n by the power of two that brings |n_γ| into
    // [1, 2) is exact and keeps the unit normal's range.
    let scale = T::select(valid, n_gamma.scale_to_unit_exponent(), zero);
    let (nx, ny, nz) = (nx * scale, ny * scale, nz * scale);
    let [na, nb, nc] = gamma.permute(nx, ny, nz);
    let nc = T::select(valid, nc, T::splat(1.0));
    // The plane through the corners' mean keeps non-planar polygons' error symmetric.
    let w = -(nx * sx + ny * sy + nz * sz) * T::splat(1.0 / corners as f64);
    let mut t = face_terms(&projection(x, y, z, gamma), na, nb, nc, w);
    for term in &mut t {
        *term = T::select(valid, *term, zero);
    }
    let [volume, _, _] = gamma.unpermute([t[0], t[1], t[2]]);
    acc[0] += volume;
    for (slots, terms) in [(1, 3), (4, 6), (7, 9)] {
        let xyz = gamma.unpermute([t[terms], t[terms + 1], t[terms + 2]]);
        for (k, v) in xyz.into_iter().enumerate() {
            acc[slots + k] += v;
        }
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

/// Green's theorem over the polygon's edges (α[k], β[k]) → (α[k+1], β[k+1]), with (α, β) the
/// corners' coordinates permuted by `gamma`.
#[inline(always)]
fn projection<T: Real>(x: &[T], y: &[T], z: &[T], gamma: Gamma<T::Mask>) -> Projection<T> {
    let k = T::splat;
    let zero = k(0.0);
    let (mut p1, mut pa, mut pb, mut paa, mut pab, mut pbb) = (zero, zero, zero, zero, zero, zero);
    let (mut paaa, mut paab, mut pabb, mut pbbb) = (zero, zero, zero, zero);
    let last = x.len() - 1;
    let [mut a0, mut b0, _] = gamma.permute(x[last], y[last], z[last]);
    for c in 0..x.len() {
        let [a1, b1, _] = gamma.permute(x[c], y[c], z[c]);
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
        p1 += db * c1;
        pa += db * ca;
        paa += db * caa;
        paaa += db * caaa;
        pb += da * cb;
        pbb += da * cbb;
        pbbb += da * cbbb;
        pab += db * (b1 * cab + b0 * kab);
        paab += db * (b1 * caab + b0 * kaab);
        pabb += da * (a1 * cabb + a0 * kabb);
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
    let k = T::splat;
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

#[cfg(test)]
mod tests {
    use nalgebra::{Isometry3, Vector3};

    use super::*;
    use crate::integrals::tests::assert_agree;
    use crate::shapes;

    /// Faces of 3, 4 and 23 corners, each kind in a count that leaves a partial group of lanes,
    /// over two blocks, plus a zero-area triangle and a zero-area quad, scaled by `scale`.
    fn mixed_mesh(scale: f64) -> PolyMesh {
        let mut parts = shapes::torus(1.0, 0.3, 31, 19);
        parts
            .append(&shapes::torus(0.5, 0.2, 11, 5).triangulated())
            .append(
                &shapes::cylinder(0.4, -1.0, 0.7, 23).transformed(&Isometry3::new(
                    Vector3::new(0.3, 2.0, 0.1),
                    Vector3::new(0.4, 0.1, 0.0),
                )),
            );
        let mesh = parts.build();
        let positions = mesh.positions().iter().map(|p| p * scale).collect();
        let mut faces: Vec<Vec<usize>> = mesh
            .faces()
            .map(|f| f.iter().map(|&i| i as usize).collect())
            .collect();
        faces.push(vec![0, 0, 1]);
        faces.push(vec![0, 1, 1, 0]);
        assert_eq!(faces.len(), 31 * 19 + 2 * 11 * 5 + 25 + 2);
        PolyMesh::new(positions, &faces).expect("valid")
    }

    #[test]
    fn every_instruction_set_agrees_with_the_portable_kernel() {
        for scale in [1e-9, 1.0, 1e9] {
            let mesh = mixed_mesh(scale);
            let reference = mesh.reference_point();
            let portable = integrate_with(Level::Portable, &mesh, reference);
            // ∫1 = π·0.4²·1.7 + the tori's volumes (2π²Rr², nearly, for these polygonal tori).
            let cylinder = std::f64::consts::PI * 0.16 * 1.7;
            assert!(portable[0] > cylinder * scale.powi(3));
            for level in Level::available() {
                let fast = integrate_with(level, &mesh, reference);
                assert_agree(
                    &fast,
                    &portable,
                    scale,
                    &format!("{level:?}, scale {scale}"),
                );
            }
        }
    }
}
