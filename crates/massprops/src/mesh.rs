//! The polygon mesh: shared vertex positions and faces of any number of corners.
//!
//! Faces are stored compactly (one index array plus per-face offsets) so a 4M-triangle mesh costs
//! 48 MB of indices, and a mesh made only of triangles is recognised for the fast path.

use nalgebra::Point3;

use crate::MeshError;

/// A polygon mesh in f64: vertex positions and faces given as vertex-index loops.
///
/// Faces may be any planar polygon (convex or not) of three or more corners; their winding is
/// counter-clockwise seen from outside (right-hand rule gives the outward normal). A constructed
/// mesh is always valid for integration: every index is in range, every coordinate finite, every
/// face has at least three corners.
///
/// ```
/// use massprops::{PolyMesh, mass_properties};
/// use nalgebra::Point3;
///
/// // The tetrahedron with corners at the origin and the unit points, wound outward.
/// let corners = vec![
///     Point3::new(0.0, 0.0, 0.0),
///     Point3::new(1.0, 0.0, 0.0),
///     Point3::new(0.0, 1.0, 0.0),
///     Point3::new(0.0, 0.0, 1.0),
/// ];
/// let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let mesh = PolyMesh::new(corners, &faces).unwrap();
/// assert_eq!((mesh.face_count(), mesh.triangle_count()), (4, 4));
///
/// // Volume 1/6, centre (1/4, 1/4, 1/4); about the origin ∫x² dV = 1/60 and ∫xy dV = 1/120, so
/// // I_xx = ∫(y² + z²) dV = 1/30 and I_xy = −∫xy dV = −1/120.
/// let p = mass_properties(&mesh, 1.0).unwrap();
/// assert!((p.mass - 1.0 / 6.0).abs() < 1e-15);
/// assert!((p.center_of_mass - Point3::new(0.25, 0.25, 0.25)).norm() < 1e-15);
/// let origin = p.inertia_origin();
/// assert!((origin[(0, 0)] - 1.0 / 30.0).abs() < 1e-15);
/// assert!((origin[(0, 1)] + 1.0 / 120.0).abs() < 1e-15);
///
/// // Wound inward, the same body (the result is flipped).
/// assert!((mass_properties(&mesh.flipped(), 1.0).unwrap().mass - 1.0 / 6.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PolyMesh {
    positions: Vec<Point3<f64>>,
    indices: Vec<u32>,
    /// `face_starts[f]..face_starts[f + 1]` is face `f`'s range in `indices`.
    face_starts: Vec<u32>,
    all_triangles: bool,
    /// Bounding box `(min, max)` of the used positions, found once when the mesh is built.
    bounds: (Point3<f64>, Point3<f64>),
}

impl PolyMesh {
    /// Builds a mesh from positions and faces (each a loop of vertex indices), validating it.
    pub fn new<F: AsRef<[usize]>>(
        positions: Vec<Point3<f64>>,
        faces: &[F],
    ) -> Result<Self, MeshError> {
        let mut indices = Vec::with_capacity(faces.iter().map(|f| f.as_ref().len()).sum());
        let mut arities = Vec::with_capacity(faces.len());
        for face in faces {
            let face = face.as_ref();
            arities.push(face.len());
            for &i in face {
                indices.push(u32::try_from(i).unwrap_or(u32::MAX));
            }
        }
        Self::from_flat(positions, indices, &arities)
    }

    /// Builds a triangle mesh from positions and index triples, validating it.
    pub fn from_triangles(
        positions: Vec<Point3<f64>>,
        triangles: &[[u32; 3]],
    ) -> Result<Self, MeshError> {
        let indices = triangles.iter().flatten().copied().collect();
        Self::from_flat(positions, indices, &vec![3; triangles.len()])
    }

    /// Builds a mesh from a flat index array and the number of corners of each face.
    pub fn from_flat(
        positions: Vec<Point3<f64>>,
        indices: Vec<u32>,
        arities: &[usize],
    ) -> Result<Self, MeshError> {
        if arities.is_empty() || positions.is_empty() {
            return Err(MeshError::Empty);
        }
        if positions.len() > u32::MAX as usize {
            return Err(MeshError::TooLarge {
                what: "vertices".into(),
                count: positions.len(),
            });
        }
        if indices.len() >= u32::MAX as usize {
            return Err(MeshError::TooLarge {
                what: "corners".into(),
                count: indices.len(),
            });
        }
        for (vertex, p) in positions.iter().enumerate() {
            if let Some(&value) = p.coords.iter().find(|c| !c.is_finite()) {
                return Err(MeshError::NonFiniteVertex { vertex, value });
            }
        }
        let mut face_starts = Vec::with_capacity(arities.len() + 1);
        let mut start = 0usize;
        for (face, &corners) in arities.iter().enumerate() {
            if corners < 3 {
                return Err(MeshError::TooFewCorners { face, corners });
            }
            face_starts.push(start as u32);
            let end = start + corners;
            let Some(face_indices) = indices.get(start..end) else {
                return Err(MeshError::TooFewCorners {
                    face,
                    corners: indices.len().saturating_sub(start),
                });
            };
            if let Some(&bad) = face_indices
                .iter()
                .find(|&&i| i as usize >= positions.len())
            {
                return Err(MeshError::IndexOutOfRange {
                    face,
                    index: bad as usize,
                    vertex_count: positions.len(),
                });
            }
            start = end;
        }
        face_starts.push(start as u32);
        let bounds = used_bounds(&positions, &indices[..start]);
        let all_triangles = arities.iter().all(|&a| a == 3);
        Ok(Self {
            positions,
            indices,
            face_starts,
            all_triangles,
            bounds,
        })
    }

    /// Vertex positions.
    pub fn positions(&self) -> &[Point3<f64>] {
        &self.positions
    }

    /// The centre of the bounding box of the positions that faces use, which the volume integrals
    /// are taken about (a stray unused vertex far away would cost digits otherwise).
    pub(crate) fn reference_point(&self) -> Point3<f64> {
        let (lo, hi) = self.bounds;
        // Halving each bound first cannot overflow, whatever the coordinates.
        Point3::from(lo.coords * 0.5 + hi.coords * 0.5)
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        self.face_starts.len() - 1
    }

    /// Number of triangles after fan-triangulating every face (an n-gon gives n − 2).
    pub fn triangle_count(&self) -> usize {
        self.indices.len() - 2 * self.face_count()
    }

    /// The vertex-index loop of face `f`.
    ///
    /// # Panics
    /// If `f >= self.face_count()`.
    pub fn face(&self, f: usize) -> &[u32] {
        &self.indices[self.face_starts[f] as usize..self.face_starts[f + 1] as usize]
    }

    /// All faces, in order.
    pub fn faces(&self) -> impl ExactSizeIterator<Item = &[u32]> + '_ {
        self.face_starts
            .windows(2)
            .map(|w| &self.indices[w[0] as usize..w[1] as usize])
    }

    /// The index triples when every face is a triangle, for the triangle fast path.
    pub fn as_triangles(&self) -> Option<&[[u32; 3]]> {
        if !self.all_triangles {
            return None;
        }
        let (triangles, rest) = self.indices.as_chunks::<3>();
        debug_assert!(rest.is_empty());
        Some(triangles)
    }

    /// The corners of face `f` as points.
    pub fn face_points(&self, f: usize) -> impl ExactSizeIterator<Item = Point3<f64>> + '_ {
        self.face(f).iter().map(|&i| self.positions[i as usize])
    }

    /// Axis-aligned bounding box `(min, max)` of the vertices that faces use.
    pub fn bounding_box(&self) -> (Point3<f64>, Point3<f64>) {
        self.bounds
    }

    /// The positions some face refers to, each once, in index order.
    pub fn used_positions(&self) -> impl Iterator<Item = Point3<f64>> + '_ {
        let mut used = vec![false; self.positions.len()];
        for &i in &self.indices {
            used[i as usize] = true;
        }
        self.positions
            .iter()
            .zip(used)
            .filter_map(|(p, u)| u.then_some(*p))
    }

    /// The same mesh with every face's winding reversed (outward and inward swap).
    pub fn flipped(&self) -> Self {
        let mut out = self.clone();
        for w in self.face_starts.windows(2) {
            out.indices[w[0] as usize..w[1] as usize].reverse();
        }
        out
    }

    /// The mesh made of some of the faces (each index below `face_count`), with only the
    /// vertices they use, renumbered in order.
    pub fn subset(&self, faces: &[u32]) -> Result<Self, MeshError> {
        let mut new_index = vec![u32::MAX; self.positions.len()];
        let mut positions = Vec::new();
        let mut indices = Vec::new();
        let mut arities = Vec::with_capacity(faces.len());
        for &f in faces {
            let face = self.face(f as usize);
            for &i in face {
                if new_index[i as usize] == u32::MAX {
                    new_index[i as usize] = positions.len() as u32;
                    positions.push(self.positions[i as usize]);
                }
                indices.push(new_index[i as usize]);
            }
            arities.push(face.len());
        }
        Self::from_flat(positions, indices, &arities)
    }

    /// The same mesh with every vertex mapped through `f` (e.g. a rigid motion or a scale).
    pub fn map_positions(&self, f: impl Fn(Point3<f64>) -> Point3<f64>) -> Result<Self, MeshError> {
        let positions = self.positions.iter().map(|&p| f(p)).collect();
        let arities: Vec<usize> = self.faces().map(<[u32]>::len).collect();
        Self::from_flat(positions, self.indices.clone(), &arities)
    }
}

/// Per-axis (min, max) of the positions that `indices` use (all in range).
fn used_bounds(positions: &[Point3<f64>], indices: &[u32]) -> (Point3<f64>, Point3<f64>) {
    let mut used = vec![false; positions.len()];
    for &i in indices {
        used[i as usize] = true;
    }
    // Plain comparisons (not f64::min, whose NaN rules block vectorisation); coordinates are
    // finite by the mesh's invariant.
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for (p, &u) in positions.iter().zip(&used) {
        for k in 0..3 {
            let c = p[k];
            lo[k] = if u && c < lo[k] { c } else { lo[k] };
            hi[k] = if u && c > hi[k] { c } else { hi[k] };
        }
    }
    (Point3::from(lo), Point3::from(hi))
}

/// Merges vertices with bit-identical coordinates, so a file that repeats a position per corner
/// (for normals or texture coordinates) still has shared edges.
///
/// Returns the unique positions, in the order first given, and for each input position its new
/// index. `-0.0` and `0.0` are the same point; of equal points the first one's coordinates are
/// kept.
///
/// Partitioned hashing, not one big table: the points are bucketed by the top bits of a hash of
/// their coordinates (a counting sort, written in order), and each bucket, a few thousand points,
/// is welded in its own small open-addressing table that stays in the cache. On a million-point
/// scan a single table is a cache and TLB miss per point; this is a few sequential passes.
pub fn weld_exact(positions: &[Point3<f64>]) -> (Vec<Point3<f64>>, Vec<u32>) {
    let (firsts, remap) = weld_by_key(
        positions.len(),
        |i| weld_key(&positions[i]),
        |k| weld_hash(*k),
    );
    let unique = firsts.iter().map(|&i| positions[i as usize]).collect();
    (unique, remap)
}

/// The weld of `n` items by an exact key: the index of the first item of each distinct key, in
/// input order, and for each item the rank of its key among them. `hash` must give equal keys
/// equal hashes, with its top bits and its low bits both well mixed.
///
/// The items are scattered, key and index together, into buckets by the top bits of the hash (a
/// counting sort), so each bucket is then read in order and welded in a small table of keys that
/// stays in the cache: every pass is sequential but the last writes, which are cheap.
pub(crate) fn weld_by_key<K: Eq + Copy + Default>(
    n: usize,
    key: impl Fn(usize) -> K,
    hash: impl Fn(&K) -> u64,
) -> (Vec<u32>, Vec<u32>) {
    // About 2 048 items a bucket.
    let bits = (n / 2048)
        .max(1)
        .next_power_of_two()
        .trailing_zeros()
        .min(16);
    let bucket = |h: u64| {
        if bits == 0 {
            0
        } else {
            (h >> (64 - bits)) as usize
        }
    };
    let mut starts = vec![0u32; (1 << bits) + 1];
    for i in 0..n {
        starts[bucket(hash(&key(i))) + 1] += 1;
    }
    for b in 0..1 << bits {
        starts[b + 1] += starts[b];
    }
    let mut scattered = vec![(0u32, K::default()); n];
    let mut next = starts.clone();
    for i in 0..n {
        let k = key(i);
        let slot = &mut next[bucket(hash(&k))];
        scattered[*slot as usize] = (i as u32, k);
        *slot += 1;
    }
    // Each item's first equal item (itself when none came before).
    let mut first = vec![0u32; n];
    let largest = starts.windows(2).map(|w| w[1] - w[0]).max().unwrap_or(0) as usize;
    let mut table = vec![(EMPTY, K::default()); (2 * largest.max(4)).next_power_of_two()];
    for w in starts.windows(2) {
        let members = &scattered[w[0] as usize..w[1] as usize];
        let mask = (2 * members.len().max(4)).next_power_of_two() - 1;
        table[..=mask].fill((EMPTY, K::default()));
        // Members come in input order, so the first of equal items claims the slot.
        for &(i, k) in members {
            let mut slot = hash(&k) as usize & mask;
            first[i as usize] = loop {
                match table[slot] {
                    (EMPTY, _) => {
                        table[slot] = (i, k);
                        break i;
                    }
                    (j, other) if other == k => break j,
                    _ => slot = (slot + 1) & mask,
                }
            };
        }
    }
    drop(scattered);
    // Ranks in input order: an item that is its own first takes the next one.
    let mut firsts = Vec::new();
    let mut remap = vec![0u32; n];
    for i in 0..n {
        let f = first[i] as usize;
        remap[i] = if f == i {
            firsts.push(i as u32);
            (firsts.len() - 1) as u32
        } else {
            remap[f]
        };
    }
    (firsts, remap)
}

const EMPTY: u32 = u32::MAX;

/// The coordinates' bits, `-0.0` read as `0.0`.
fn weld_key(p: &Point3<f64>) -> [u64; 3] {
    [
        (p.x + 0.0).to_bits(),
        (p.y + 0.0).to_bits(),
        (p.z + 0.0).to_bits(),
    ]
}

pub(crate) fn weld_hash([x, y, z]: [u64; 3]) -> u64 {
    // Each coordinate through its own odd multiplier, mixed so both the top bits (the bucket)
    // and the low bits (the slot) depend on every input bit.
    let h = x.wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ y.wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ z.wrapping_mul(0x1656_67B1_9E37_79F9);
    let h = (h ^ (h >> 32)).wrapping_mul(0xD6E8_FEB8_6659_FD93);
    h ^ (h >> 32)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
        Point3::new(x, y, z)
    }

    #[test]
    fn rejects_bad_input_with_the_face_named() {
        let pts = vec![p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)];
        assert!(matches!(
            PolyMesh::new(pts.clone(), &[vec![0, 1, 3]]),
            Err(MeshError::IndexOutOfRange {
                face: 0,
                index: 3,
                vertex_count: 3
            })
        ));
        assert!(matches!(
            PolyMesh::new(pts.clone(), &[vec![0, 1, 2], vec![0, 1]]),
            Err(MeshError::TooFewCorners {
                face: 1,
                corners: 2
            })
        ));
        assert!(matches!(
            PolyMesh::new(pts.clone(), &[] as &[Vec<usize>]),
            Err(MeshError::Empty)
        ));
        let mut nan = pts;
        nan[1].y = f64::NAN;
        assert!(matches!(
            PolyMesh::new(nan, &[vec![0, 1, 2]]),
            Err(MeshError::NonFiniteVertex { vertex: 1, .. })
        ));
    }

    #[test]
    fn counts_triangles_of_polygons() {
        let pts = vec![p(0., 0., 0.), p(1., 0., 0.), p(1., 1., 0.), p(0., 1., 0.)];
        let m = PolyMesh::new(pts, &[vec![0, 1, 2, 3], vec![0, 2, 1]]).expect("valid");
        assert_eq!(m.face_count(), 2);
        assert_eq!(m.triangle_count(), 3);
        assert!(m.as_triangles().is_none());
        assert_eq!(m.flipped().face(0), &[3, 2, 1, 0]);
    }

    #[test]
    fn weld_merges_identical_and_signed_zero() {
        let (u, r) = weld_exact(&[p(0., 1., 2.), p(-0.0, 1., 2.), p(0., 1., 2.000_000_1)]);
        assert_eq!(u.len(), 2);
        assert_eq!(r, vec![0, 0, 1]);
    }
}
