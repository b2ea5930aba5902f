//! CPU ray picking: a bounding-volume hierarchy over the triangles, built once per loaded mesh (on
//! the loader thread), and Möller–Trumbore ray–triangle tests (J. Graphics Tools 2(1), 1997).
//!
//! The body is rigid, so picking the world-space mesh equals picking the mesh in its own
//! coordinates with the ray mapped by the inverse pose: the index never needs rebuilding while the
//! body turns. A query visits O(log n) nodes: microseconds on a million triangles.

use nalgebra::{Point3, Vector3};

use super::geometry::TriMesh;

/// A ray `origin + t·dir`, `t ≥ 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    /// Start point.
    pub origin: Point3<f64>,
    /// Direction (any non-zero length; `t` is in units of it).
    pub dir: Vector3<f64>,
}

impl Ray {
    /// The point at parameter `t`.
    pub fn at(&self, t: f64) -> Point3<f64> {
        self.origin + self.dir * t
    }

    /// Where the ray meets the plane through `point` with normal `normal`; `None` when parallel
    /// or behind the origin.
    pub fn hit_plane(&self, point: &Point3<f64>, normal: &Vector3<f64>) -> Option<Point3<f64>> {
        let denom = self.dir.dot(normal);
        if denom.abs() < 1e-12 * self.dir.norm() * normal.norm() {
            return None;
        }
        let t = (point - self.origin).dot(normal) / denom;
        (t >= 0.0 && t.is_finite()).then(|| self.at(t))
    }
}

/// The nearest hit of a ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// Ray parameter of the hit.
    pub t: f64,
    /// The hit point.
    pub point: Point3<f64>,
    /// Index of the triangle hit.
    pub triangle: usize,
}

/// Triangles per leaf: small leaves keep queries short, the node count stays ≈ 2n/4.
const LEAF_SIZE: usize = 4;

#[derive(Debug, Clone, Copy, serde::Serialize, serde::Deserialize)]
struct Node {
    lo: Vector3<f64>,
    hi: Vector3<f64>,
    /// Leaf: first triangle in `order`; inner: index of the right child (the left is next).
    start: u32,
    /// Leaf: number of triangles; inner: 0.
    count: u32,
}

/// A bounding-volume hierarchy over a [`TriMesh`]'s triangles (median split on the longest axis
/// of the centroid bounds).
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct Bvh {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

impl Bvh {
    /// Builds the hierarchy.
    pub fn build(mesh: &TriMesh) -> Self {
        let n = mesh.triangles.len();
        let tri = |i: u32| mesh.triangles[i as usize].map(|v| mesh.positions[v as usize].coords);
        let centroids: Vec<Vector3<f64>> = (0..n as u32)
            .map(|i| {
                let [a, b, c] = tri(i);
                (a + b + c) / 3.0
            })
            .collect();
        let mut order: Vec<u32> = (0..n as u32).collect();
        let mut nodes = Vec::with_capacity(2 * n / LEAF_SIZE + 1);
        // Explicit stack of (node index, range) instead of recursion: deep meshes cannot overflow.
        let mut stack = vec![(0usize, 0usize, n)];
        nodes.push(empty_node());
        while let Some((node, begin, end)) = stack.pop() {
            let (mut lo, mut hi) = (
                Vector3::repeat(f64::INFINITY),
                Vector3::repeat(f64::NEG_INFINITY),
            );
            let (mut clo, mut chi) = (lo, hi);
            for &i in &order[begin..end] {
                for p in tri(i) {
                    lo = lo.inf(&p);
                    hi = hi.sup(&p);
                }
                clo = clo.inf(&centroids[i as usize]);
                chi = chi.sup(&centroids[i as usize]);
            }
            let axis = (chi - clo).imax();
            if end - begin <= LEAF_SIZE || chi[axis] <= clo[axis] {
                nodes[node] = Node {
                    lo,
                    hi,
                    start: begin as u32,
                    count: (end - begin) as u32,
                };
                continue;
            }
            let mid = begin + (end - begin) / 2;
            order[begin..end].select_nth_unstable_by(mid - begin, |&a, &b| {
                centroids[a as usize][axis].total_cmp(&centroids[b as usize][axis])
            });
            // Children are pushed as a pair, so an inner node stores the right child's index and
            // the left one is always the slot before it.
            let left = nodes.len();
            nodes.push(empty_node());
            nodes.push(empty_node());
            nodes[node] = Node {
                lo,
                hi,
                start: (left + 1) as u32,
                count: 0,
            };
            stack.push((left + 1, mid, end));
            stack.push((left, begin, mid));
        }
        Self { nodes, order }
    }

    /// Recomputes every box for moved vertices (the same triangles: a part placed elsewhere),
    /// keeping the tree. Children always come after their parent, so one backward pass sees
    /// both children of a node before the node. Picking stays exact; only its speed depends on
    /// how well the old split suits the new positions.
    pub fn refit(&mut self, mesh: &TriMesh) {
        for k in (0..self.nodes.len()).rev() {
            let node = self.nodes[k];
            let (lo, hi) = if node.count > 0 {
                let range = node.start as usize..(node.start + node.count) as usize;
                let mut lo = Vector3::repeat(f64::INFINITY);
                let mut hi = Vector3::repeat(f64::NEG_INFINITY);
                for &i in &self.order[range] {
                    for v in mesh.triangles[i as usize] {
                        let p = mesh.positions[v as usize].coords;
                        lo = lo.inf(&p);
                        hi = hi.sup(&p);
                    }
                }
                (lo, hi)
            } else {
                let (left, right) = (
                    &self.nodes[node.start as usize - 1],
                    &self.nodes[node.start as usize],
                );
                (left.lo.inf(&right.lo), left.hi.sup(&right.hi))
            };
            self.nodes[k].lo = lo;
            self.nodes[k].hi = hi;
        }
    }

    /// The nearest triangle the ray hits (front or back face), if any.
    pub fn pick(&self, mesh: &TriMesh, ray: &Ray) -> Option<Hit> {
        self.pick_where(mesh, ray, &|_| true)
    }

    /// [`Bvh::pick`] among the triangles `keep` accepts (the parts shown).
    pub fn pick_where(
        &self,
        mesh: &TriMesh,
        ray: &Ray,
        keep: &dyn Fn(usize) -> bool,
    ) -> Option<Hit> {
        if self.nodes.is_empty() || self.order.is_empty() {
            return None;
        }
        let inv = ray.dir.map(|d| 1.0 / d);
        let mut best: Option<Hit> = None;
        let mut stack = vec![0usize];
        while let Some(k) = stack.pop() {
            let node = &self.nodes[k];
            let limit = best.map_or(f64::INFINITY, |h| h.t);
            if !slab(&node.lo, &node.hi, ray, &inv, limit) {
                continue;
            }
            if node.count > 0 {
                let range = node.start as usize..(node.start + node.count) as usize;
                for &i in &self.order[range] {
                    if !keep(i as usize) {
                        continue;
                    }
                    let [a, b, c] = mesh.triangles[i as usize].map(|v| mesh.positions[v as usize]);
                    if let Some(t) = moller_trumbore(ray, &a, &b, &c)
                        && t < best.map_or(limit, |h| h.t)
                    {
                        best = Some(Hit {
                            t,
                            point: ray.at(t),
                            triangle: i as usize,
                        });
                    }
                }
            } else {
                let right = node.start as usize;
                stack.push(right);
                stack.push(right - 1);
            }
        }
        best
    }
}

fn empty_node() -> Node {
    Node {
        lo: Vector3::zeros(),
        hi: Vector3::zeros(),
        start: 0,
        count: 0,
    }
}

/// Slab test of the ray against a box, limited to `t ≤ limit` (Kay & Kajiya 1986). An axis the
/// ray is parallel to is decided by the origin alone: `0·∞` would give NaN there.
fn slab(lo: &Vector3<f64>, hi: &Vector3<f64>, ray: &Ray, inv: &Vector3<f64>, limit: f64) -> bool {
    let (mut t0, mut t1) = (0.0f64, limit);
    for a in 0..3 {
        if ray.dir[a] == 0.0 {
            if ray.origin[a] < lo[a] || ray.origin[a] > hi[a] {
                return false;
            }
            continue;
        }
        let ta = (lo[a] - ray.origin[a]) * inv[a];
        let tb = (hi[a] - ray.origin[a]) * inv[a];
        t0 = t0.max(ta.min(tb));
        t1 = t1.min(ta.max(tb));
    }
    t0 <= t1
}

/// Möller–Trumbore: the ray parameter of the hit on triangle abc, both sides.
fn moller_trumbore(ray: &Ray, a: &Point3<f64>, b: &Point3<f64>, c: &Point3<f64>) -> Option<f64> {
    let e1 = b - a;
    let e2 = c - a;
    let p = ray.dir.cross(&e2);
    let det = e1.dot(&p);
    if det.abs() <= f64::EPSILON * e1.norm() * e2.norm() * ray.dir.norm() {
        return None;
    }
    let inv_det = 1.0 / det;
    let s = ray.origin - a;
    let u = s.dot(&p) * inv_det;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(&e1);
    let v = ray.dir.dot(&q) * inv_det;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(&q) * inv_det;
    (t >= 0.0).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute(mesh: &TriMesh, ray: &Ray) -> Option<f64> {
        mesh.triangles
            .iter()
            .filter_map(|t| {
                let [a, b, c] = t.map(|v| mesh.positions[v as usize]);
                moller_trumbore(ray, &a, &b, &c)
            })
            .min_by(f64::total_cmp)
    }

    #[test]
    fn a_refitted_index_picks_what_brute_force_finds_after_a_part_moves() {
        // Two tori; the second is moved after the index is built (a part placed elsewhere).
        let mut b = massprops::shapes::torus(1.0, 0.3, 48, 24);
        let second = massprops::shapes::torus(0.5, 0.2, 32, 16);
        let first_vertices = b.positions.len();
        b.append(&second);
        let mut mesh = TriMesh::from_poly(&b.build());
        let mut bvh = Bvh::build(&mesh);
        for p in &mut mesh.positions[first_vertices..] {
            *p += Vector3::new(2.5, 0.4, -0.3);
        }
        let stale = bvh.clone();
        bvh.refit(&mesh);
        let (mut hits, mut stale_misses) = (0, 0);
        for k in 0..400 {
            let (x, y) = (
                -1.5 + f64::from(k % 20) * 0.25,
                -1.5 + f64::from(k / 20) * 0.15,
            );
            let ray = Ray {
                origin: Point3::new(x, y, 5.0),
                dir: Vector3::new(0.05, -0.02, -1.0),
            };
            let expected = brute(&mesh, &ray);
            let got = bvh.pick(&mesh, &ray).map(|h| h.t);
            assert_eq!(got, expected, "ray {k}");
            hits += usize::from(expected.is_some());
            stale_misses += usize::from(stale.pick(&mesh, &ray).map(|h| h.t) != expected);
        }
        assert!(hits > 50, "{hits} hits");
        // Without the refit the old boxes miss the moved torus.
        assert!(stale_misses > 10, "{stale_misses}");
    }

    #[test]
    fn hits_the_near_face_of_a_cube() {
        let mesh = TriMesh::from_poly(&massprops::shapes::cube().build());
        let bvh = Bvh::build(&mesh);
        let ray = Ray {
            origin: Point3::new(0.1, 0.2, 5.0),
            dir: Vector3::new(0.0, 0.0, -2.0),
        };
        let hit = bvh.pick(&mesh, &ray).expect("hits");
        assert!((hit.point - Point3::new(0.1, 0.2, 0.5)).norm() < 1e-14);
        assert!((hit.t - 2.25).abs() < 1e-14);
        let miss = Ray {
            origin: Point3::new(2.0, 0.0, 5.0),
            dir: -Vector3::z(),
        };
        assert_eq!(bvh.pick(&mesh, &miss), None);
        // From inside, the exit face is hit.
        let inside = Ray {
            origin: Point3::origin(),
            dir: Vector3::x(),
        };
        assert!((bvh.pick(&mesh, &inside).expect("exit").t - 0.5).abs() < 1e-14);
    }

    #[test]
    fn agrees_with_brute_force_on_a_torus() {
        let mesh = TriMesh::from_poly(&massprops::shapes::torus(1.0, 0.3, 40, 20).build());
        let bvh = Bvh::build(&mesh);
        let mut hits = 0;
        for i in 0..400 {
            let a = i as f64 * 0.61;
            let ray = Ray {
                origin: Point3::new(3.0 * a.cos(), 3.0 * a.sin(), 0.7 * (a * 0.37).sin()),
                dir: Vector3::new(-a.cos(), -a.sin() + 0.1 * (a * 1.3).cos(), -0.2 * a.sin()),
            };
            let fast = bvh.pick(&mesh, &ray).map(|h| h.t);
            let slow = brute(&mesh, &ray);
            assert_eq!(fast.is_some(), slow.is_some(), "ray {i}");
            if let (Some(f), Some(s)) = (fast, slow) {
                assert!((f - s).abs() < 1e-12, "ray {i}: {f} vs {s}");
                hits += 1;
            }
        }
        assert!(hits > 100, "{hits}");
    }

    #[test]
    fn ray_plane_intersection() {
        let ray = Ray {
            origin: Point3::new(0.0, 0.0, 2.0),
            dir: Vector3::new(1.0, 0.0, -1.0),
        };
        let p = ray
            .hit_plane(&Point3::origin(), &Vector3::z())
            .expect("meets");
        assert!((p - Point3::new(2.0, 0.0, 0.0)).norm() < 1e-15);
        assert_eq!(ray.hit_plane(&Point3::origin(), &Vector3::y()), None);
        assert_eq!(
            ray.hit_plane(&Point3::new(0.0, 0.0, 5.0), &Vector3::z()),
            None
        );
    }

    /// The boxes a ray meets, counted over the whole tree (descending only into boxes it meets,
    /// with no nearest-hit cut-off): what a query may visit, a measure of the tree, not a time.
    fn boxes_met(bvh: &Bvh, ray: &Ray) -> usize {
        let inv = ray.dir.map(|d| 1.0 / d);
        let (mut met, mut stack) = (0, vec![0usize]);
        while let Some(k) = stack.pop() {
            let node = &bvh.nodes[k];
            if !slab(&node.lo, &node.hi, ray, &inv, f64::INFINITY) {
                continue;
            }
            met += 1;
            if node.count == 0 {
                stack.push(node.start as usize);
                stack.push(node.start as usize - 1);
            }
        }
        met
    }

    /// The tree over 250k triangles (the 1M of the benchmark takes a minute unoptimised) is
    /// balanced and tight, so a query visits O(log n) nodes (the
    /// time per ray is measured by `benches/picking.rs`, not here): every leaf holds at most
    /// [`LEAF_SIZE`] triangles, no leaf is deeper than ⌈log₂(n / LEAF_SIZE)⌉, each triangle is in
    /// exactly one leaf, and a ray from outside meets a few hundred boxes at most (a tree split
    /// on the wrong axis or off the median meets thousands). Each ray finds the brute-force hit.
    #[test]
    fn a_quarter_million_triangle_tree_is_balanced_and_tight() {
        let mesh = TriMesh::from_poly(&massprops::shapes::torus(1.0, 0.3, 500, 250).build());
        let n = mesh.triangles.len();
        assert_eq!(n, 250_000);
        let bvh = Bvh::build(&mesh);
        let (mut seen, mut deepest, mut stack) = (vec![0u8; n], 0, vec![(0usize, 0usize)]);
        while let Some((k, depth)) = stack.pop() {
            let node = &bvh.nodes[k];
            if node.count == 0 {
                stack.push((node.start as usize, depth + 1));
                stack.push((node.start as usize - 1, depth + 1));
                continue;
            }
            assert!(node.count as usize <= LEAF_SIZE, "leaf {k}: {}", node.count);
            deepest = deepest.max(depth);
            for &i in &bvh.order[node.start as usize..(node.start + node.count) as usize] {
                seen[i as usize] += 1;
            }
        }
        assert!(seen.iter().all(|&s| s == 1), "each triangle in one leaf");
        let bound = (n as f64 / LEAF_SIZE as f64).log2().ceil() as usize;
        assert!(deepest <= bound, "depth {deepest} > {bound}");
        let mut met = Vec::new();
        for i in 0..200 {
            let a = f64::from(i) * 0.031;
            let ray = Ray {
                origin: Point3::new(0.0, 4.0 * a.cos(), 4.0 * a.sin()),
                dir: Vector3::new(1.0, -4.0 * a.cos(), -4.0 * a.sin()),
            };
            let hit = bvh.pick(&mesh, &ray).expect("every ray hits");
            if i % 100 == 0 {
                let slow = brute(&mesh, &ray).expect("brute force hits");
                assert!((hit.t - slow).abs() < 1e-12, "ray {i}: {} vs {slow}", hit.t);
            }
            met.push(boxes_met(&bvh, &ray));
        }
        met.sort_unstable();
        let (median, most) = (met[met.len() / 2], met[met.len() - 1]);
        eprintln!("boxes met per ray on 250k triangles: median {median}, most {most}");
        assert!(most <= 600, "median {median}, most {most} boxes per ray");
    }
}
