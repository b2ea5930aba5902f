//! The ten volume integrals ∫1, ∫x, ∫y, ∫z, ∫x², ∫y², ∫z², ∫xy, ∫yz, ∫zx over the solid a closed
//! mesh bounds, taken about a local reference point.
//!
//! Two ways to compute them, which agree to round-off:
//! - [`mirtich`]: Mirtich (1996), "Fast and Accurate Computation of Polyhedral Mass Properties",
//!   J. Graphics Tools 1(2): divergence theorem → projection onto a coordinate plane → Green's
//!   theorem, for planar polygons of any shape;
//! - [`triangle`]: for triangle meshes, a sum of signed tetrahedra with the reference point as
//!   apex (Tonon 2004), sequential or parallel.
//!
//! Both run one face per SIMD lane, on the vector types of `simd` (AVX-512, AVX2 + FMA, or
//! portable scalar code, chosen at run time).
//!
//! Numerics: coordinates are taken relative to the bounding-box centre of the vertices faces use,
//! so a body far from the origin loses no digits to cancellation, and face contributions are
//! added in fixed blocks whose sums are combined with Neumaier's compensated summation. The
//! block order is fixed, so the parallel path (`parallel`) returns bit-for-bit the sequential
//! result.

pub mod mirtich;
#[cfg(feature = "parallel")]
mod parallel;
mod simd;
pub mod triangle;

use nalgebra::{Matrix3, Point3, Vector3};

/// Number of faces whose contributions are added plainly before the block sum is compensated.
pub(crate) const BLOCK: usize = 512;

/// Which algorithm integrates the faces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IntegrationPath {
    /// Mirtich's polygon method (any planar polygon).
    Polygon,
    /// The triangle specialisation on one thread (every face a triangle, else falls back to Polygon).
    Triangle,
    /// The triangle specialisation on the calling thread and the rayon pool (same result bit for
    /// bit). Like any rayon scope, it returns only once a pool thread has taken its helper task:
    /// do not call it while holding something the pool's other work waits for. Without the
    /// `parallel` feature it is [`IntegrationPath::Triangle`].
    TriangleParallel,
    /// Triangle paths when every face is a triangle (parallel above 64k triangles with the
    /// `parallel` feature, else on the calling thread), else Polygon.
    Auto,
}

/// The ten volume integrals of a solid about [`VolumeIntegrals::reference`].
///
/// `values` = [∫1, ∫x, ∫y, ∫z, ∫x², ∫y², ∫z², ∫xy, ∫yz, ∫zx] with x, y, z measured from the
/// reference point. The signed volume is negative when the faces wind inwards.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VolumeIntegrals {
    /// The point the coordinates are measured from.
    pub reference: Point3<f64>,
    /// The ten integrals.
    pub values: [f64; 10],
}

impl VolumeIntegrals {
    /// Signed volume.
    pub fn volume(&self) -> f64 {
        self.values[0]
    }

    /// First moments ∫r about the reference point.
    pub fn first_moment(&self) -> Vector3<f64> {
        Vector3::new(self.values[1], self.values[2], self.values[3])
    }

    /// Second-moment matrix ∫ r rᵀ about the reference point (the covariance, not the inertia).
    pub fn second_moment(&self) -> Matrix3<f64> {
        let v = &self.values;
        Matrix3::new(v[4], v[7], v[9], v[7], v[5], v[8], v[9], v[8], v[6])
    }

    /// The integrals of the same solid with its faces wound the other way.
    pub fn negated(&self) -> Self {
        Self {
            reference: self.reference,
            values: self.values.map(|v| -v),
        }
    }
}

/// Neumaier's improved Kahan summation of N values at once.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CompensatedSum<const N: usize> {
    sum: [f64; N],
    compensation: [f64; N],
}

impl<const N: usize> CompensatedSum<N> {
    pub(crate) fn new() -> Self {
        Self {
            sum: [0.0; N],
            compensation: [0.0; N],
        }
    }

    pub(crate) fn add(&mut self, values: &[f64; N]) {
        for ((s, c), &v) in self.sum.iter_mut().zip(&mut self.compensation).zip(values) {
            let t = *s + v;
            *c += if s.abs() >= v.abs() {
                (*s - t) + v
            } else {
                (v - t) + *s
            };
            *s = t;
        }
    }

    pub(crate) fn total(&self) -> [f64; N] {
        std::array::from_fn(|i| self.sum[i] + self.compensation[i])
    }
}

/// Sums per-block partial sums in their given order with compensation.
pub(crate) fn compensated_total<const N: usize>(
    blocks: impl IntoIterator<Item = [f64; N]>,
) -> [f64; N] {
    let mut acc = CompensatedSum::<N>::new();
    for b in blocks {
        acc.add(&b);
    }
    acc.total()
}

/// Triangles above which [`IntegrationPath::Auto`] takes the parallel path. A single call to an
/// idle pool gains nothing below this size on a 2-core VM (the bench's `cold_call` group:
/// 1.0–1.1× at 99k triangles, 1.4–1.8× at 1M).
pub const PARALLEL_ABOVE: usize = 1 << 16;

/// Computes the ten volume integrals of `mesh` about its bounding-box centre (found when the mesh
/// was built).
pub fn volume_integrals(mesh: &crate::PolyMesh, path: IntegrationPath) -> VolumeIntegrals {
    let positions = mesh.positions();
    let parallel = match (path, mesh.as_triangles()) {
        (IntegrationPath::TriangleParallel, Some(_)) => true,
        (IntegrationPath::Auto, Some(t)) => t.len() > PARALLEL_ABOVE,
        _ => false,
    };
    let reference = mesh.reference_point();
    let values = match (path, mesh.as_triangles()) {
        (_, Some(t)) if parallel => triangle::integrate_parallel(positions, t, reference),
        (IntegrationPath::Triangle | IntegrationPath::Auto, Some(t)) => {
            triangle::integrate(positions, t, reference)
        }
        _ => mirtich::integrate(mesh, reference),
    };
    VolumeIntegrals { reference, values }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// Asserts that two sets of the ten integrals of a body of size ~`scale` agree to 1e-13
    /// relative, each integral against the size of its degree (L³, L⁴, L⁵).
    pub(crate) fn assert_agree(fast: &[f64; 10], portable: &[f64; 10], scale: f64, what: &str) {
        for (degree, range) in [(3, 0..1), (4, 1..4), (5, 4..10)] {
            let tolerance = 1e-13 * scale.powi(degree);
            for i in range {
                assert!(
                    (fast[i] - portable[i]).abs() <= tolerance,
                    "{what}, integral {i}: {} vs {}",
                    fast[i],
                    portable[i]
                );
            }
        }
    }

    #[test]
    fn compensated_sum_recovers_what_plain_sum_loses() {
        let values = [1e16, 1.0, -1e16];
        let plain: f64 = values.iter().sum();
        let total = compensated_total(values.iter().map(|&v| [v]));
        assert_eq!(plain, 0.0);
        assert_eq!(total[0], 1.0);
    }
}
