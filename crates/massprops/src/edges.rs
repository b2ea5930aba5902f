//! The edges of a mesh, each with every face that uses it: the one table that the diagnostics,
//! the shell split, crack welding and hole capping read.
//!
//! Each face side is a record (low vertex, high vertex, face, direction). Records are bucketed on
//! their low vertex by a counting sort (O(E), no hash table and no comparison sort of the whole
//! array) and each bucket, a handful of records, is then ordered by its high vertex. A group of
//! equal (low, high) is one undirected edge: one record means a hole, three or more a
//! non-manifold edge, two in the same direction an inconsistent winding.

use crate::PolyMesh;

/// One side of one face.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct HalfEdge {
    /// The lower vertex index of the edge.
    pub lo: u32,
    /// The higher vertex index.
    pub hi: u32,
    /// The face this side belongs to.
    pub face: u32,
    /// The face runs lo → hi along it.
    pub forward: bool,
}

impl HalfEdge {
    /// The side as the face traverses it: (from, to).
    pub fn directed(&self) -> (u32, u32) {
        if self.forward {
            (self.lo, self.hi)
        } else {
            (self.hi, self.lo)
        }
    }
}

/// Every face side, grouped by undirected edge.
pub(crate) struct EdgeTable {
    records: Vec<HalfEdge>,
}

impl EdgeTable {
    /// Collects and groups the sides of every face of `mesh`. A side whose two corners are the
    /// same vertex (a repeated corner) is no edge and is left out.
    pub fn new(mesh: &PolyMesh) -> Self {
        match mesh.as_triangles() {
            // The common case without the per-face slices: three sides a triangle.
            Some(triangles) => Self::from_sides(mesh.positions().len(), |side| {
                for (f, &[a, b, c]) in triangles.iter().enumerate() {
                    for (from, to) in [(a, b), (b, c), (c, a)] {
                        if from != to {
                            side(from, to, f as u32);
                        }
                    }
                }
            }),
            None => Self::from_sides(mesh.positions().len(), |side| {
                for (f, face) in mesh.faces().enumerate() {
                    let last = face[face.len() - 1];
                    for (from, to) in std::iter::once(last).chain(face.iter().copied()).zip(face) {
                        if from != *to {
                            side(from, *to, f as u32);
                        }
                    }
                }
            }),
        }
    }

    /// The table of the sides `each` gives (called twice: to count, then to place), as
    /// `side(from, to, face)`.
    fn from_sides(vertices: usize, each: impl Fn(&mut dyn FnMut(u32, u32, u32))) -> Self {
        let mut starts = vec![0u32; vertices + 1];
        each(&mut |a, b, _| starts[a.min(b) as usize + 1] += 1);
        for v in 0..vertices {
            starts[v + 1] += starts[v];
        }
        let total = starts[vertices] as usize;
        let mut next = starts.clone();
        let empty = HalfEdge {
            lo: 0,
            hi: 0,
            face: 0,
            forward: false,
        };
        let mut records = vec![empty; total];
        each(&mut |a, b, face| {
            let lo = a.min(b);
            let slot = &mut next[lo as usize];
            records[*slot as usize] = HalfEdge {
                lo,
                hi: a.max(b),
                face,
                forward: a < b,
            };
            *slot += 1;
        });
        // Buckets hold a few records each (about six on a triangle mesh): an insertion sort on
        // the high vertex, stable, so each group lists its faces in ascending order.
        for w in starts.windows(2) {
            let bucket = &mut records[w[0] as usize..w[1] as usize];
            for i in 1..bucket.len() {
                let mut j = i;
                while j > 0 && bucket[j - 1].hi > bucket[j].hi {
                    bucket.swap(j - 1, j);
                    j -= 1;
                }
            }
        }
        Self { records }
    }

    /// The undirected edges, each as the sides that use it (faces ascending).
    pub fn groups(&self) -> impl Iterator<Item = &[HalfEdge]> + '_ {
        self.records.chunk_by(|a, b| (a.lo, a.hi) == (b.lo, b.hi))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes;

    #[test]
    fn a_closed_box_has_twelve_edges_each_used_once_each_way() {
        let size = nalgebra::Vector3::new(1.0, 2.0, 3.0);
        let quads = shapes::cuboid(size, nalgebra::Point3::origin());
        for (cube, edges) in [(quads.clone(), 12), (quads.triangulated(), 18)] {
            let table = EdgeTable::new(&cube.build());
            let groups: Vec<&[HalfEdge]> = table.groups().collect();
            assert_eq!(groups.len(), edges);
            for g in &groups {
                assert_eq!(g.len(), 2);
                assert_ne!(g[0].forward, g[1].forward);
                assert!(g[0].face < g[1].face);
            }
        }
    }

    #[test]
    fn repeated_corners_make_no_edge() {
        let p = |x, y| nalgebra::Point3::new(x, y, 0.0);
        let m = PolyMesh::new(vec![p(0., 0.), p(1., 0.), p(0., 1.)], &[vec![0, 1, 1, 2]])
            .expect("valid");
        let table = EdgeTable::new(&m);
        assert_eq!(table.groups().count(), 3);
        let directed: Vec<(u32, u32)> = table.groups().map(|g| g[0].directed()).collect();
        assert_eq!(directed, vec![(0, 1), (2, 0), (1, 2)]);
    }
}
