//! One closed shell as a solid ([`Solid`]: its faces and bounding box) and the geometric
//! predicates on it that settle a pair or a shell without casting a line: face planes that
//! separate two shells, a convex shell, the winding number at a point.

use nalgebra::{Point3, Vector3};

use crate::PolyMesh;

/// One closed shell: its faces in the mesh, with its bounding box.
#[derive(Clone, Copy)]
pub(super) struct Solid<'a> {
    pub(super) mesh: &'a PolyMesh,
    pub(super) faces: &'a [u32],
    pub(super) lo: Point3<f64>,
    pub(super) hi: Point3<f64>,
}

impl Solid<'_> {
    /// The faces as fan triangles, each with its face.
    pub(super) fn triangles(&self) -> impl Iterator<Item = ([Point3<f64>; 3], u32)> + '_ {
        let at = |i: u32| self.mesh.positions()[i as usize];
        self.faces.iter().flat_map(move |&f| {
            let face = self.mesh.face(f as usize);
            face[1..]
                .windows(2)
                .map(move |w| ([at(face[0]), at(w[0]), at(w[1])], f))
        })
    }
}

/// Shells of at most this many faces are first tested by their face planes (each plane against
/// every vertex of the shell or of the other: quadratic, so only for small shells, the pieces of
/// a convex decomposition), which settles most pairs and selves without casting a line.
pub(super) const PLANES_UP_TO: usize = 256;

/// How far a vertex may lie past a plane and still count as on it, relative to the tolerance on
/// lengths: far below any length the lines could measure.
pub(super) const PLANE_SLACK: f64 = 1e-3;

impl Solid<'_> {
    /// The shell's vertices, each once.
    pub(super) fn points(&self) -> Vec<Point3<f64>> {
        let mut ids: Vec<u32> = self
            .faces
            .iter()
            .flat_map(|&f| self.mesh.face(f as usize).iter().copied())
            .collect();
        ids.sort_unstable();
        ids.dedup();
        ids.into_iter()
            .map(|i| self.mesh.positions()[i as usize])
            .collect()
    }

    /// Each face's plane, a unit normal (Newell's) and a point on it; faces without area left out.
    pub(super) fn planes(&self) -> Vec<(Vector3<f64>, Point3<f64>)> {
        let at = |i: u32| self.mesh.positions()[i as usize];
        self.faces
            .iter()
            .filter_map(|&f| {
                let face = self.mesh.face(f as usize);
                let mut normal = Vector3::zeros();
                for (k, &i) in face.iter().enumerate() {
                    let (p, q) = (at(i), at(face[(k + 1) % face.len()]));
                    normal += Vector3::new(
                        (p.y - q.y) * (p.z + q.z),
                        (p.z - q.z) * (p.x + q.x),
                        (p.x - q.x) * (p.y + q.y),
                    );
                }
                normal.try_normalize(0.0).map(|n| (n, at(face[0])))
            })
            .collect()
    }
}

/// Whether any of `points` lies more than `slack` above the plane, and any more than `slack`
/// below it.
pub(super) fn sides(
    plane: &(Vector3<f64>, Point3<f64>),
    points: &[Point3<f64>],
    slack: f64,
) -> (bool, bool) {
    let (n, o) = plane;
    let (mut above, mut below) = (false, false);
    for p in points {
        let d = n.dot(&(p - o));
        above |= d > slack;
        below |= d < -slack;
    }
    (above, below)
}

/// Whether a plane of one of `a`'s faces has all of `a`'s vertices on one side and all of
/// `b`'s on the other: the solids (each within the hull of its vertices) then share no volume.
pub(super) fn separated(a: &Solid, b: &Solid, slack: f64) -> bool {
    let (pa, pb) = (a.points(), b.points());
    a.planes().iter().any(|plane| {
        let (a_above, a_below) = sides(plane, &pa, slack);
        let (b_above, b_below) = sides(plane, &pb, slack);
        (!a_above && !b_below) || (!a_below && !b_above)
    })
}

/// Whether the shell is the boundary of a convex body, covered once: every vertex on one side
/// of every face's plane (so every face lies on the boundary of the polytope those sides
/// bound), and a line through the vertices' centroid, inside it, crossed so that the winding
/// number there is ±1 (a surface wrapped twice round the polytope would give ±2). Such a shell
/// never passes through itself.
pub(super) fn convex_once(a: &Solid, slack: f64) -> bool {
    let points = a.points();
    let planes = a.planes();
    // For each plane, +1 when the vertices are on or below it, −1 when on or above.
    let mut inner = Vec::with_capacity(planes.len());
    for plane in &planes {
        match sides(plane, &points, slack) {
            (true, true) => return false,
            (false, _) => inner.push(1.0),
            (true, false) => inner.push(-1.0),
        }
    }
    if points.is_empty() {
        return false;
    }
    let centroid =
        Point3::from(points.iter().map(|p| p.coords).sum::<Vector3<f64>>() / points.len() as f64);
    // The centroid's vertical line may run along an edge (a symmetric body's triangulated
    // faces): two more points near it, inside by every plane, are tried.
    let extent = a.hi - a.lo;
    [(0.0, 0.0), (0.0137, 0.0291), (-0.0219, 0.0173)]
        .into_iter()
        .map(|(u, v)| centroid + Vector3::new(u * extent.x, v * extent.y, 0.0))
        .filter(|c| {
            planes
                .iter()
                .zip(&inner)
                .all(|((n, o), side)| side * n.dot(&(c - o)) < -slack)
        })
        .find_map(|c| winding_at(a, c))
        .is_some_and(|w| w.abs() == 1)
}

/// The winding number of the shell about `c`, by the vertical line through it (the crossings
/// above `c`, each ±1 as in [`slice_crossings`]); `None` when the line meets an edge or a face
/// at `c` itself, where the count would be ambiguous.
pub(super) fn winding_at(solid: &Solid, c: Point3<f64>) -> Option<i32> {
    let mut w = 0;
    for ([p, q, r], _) in solid.triangles() {
        let twice_area = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
        if twice_area == 0.0 {
            continue;
        }
        let edge =
            |a: Point3<f64>, b: Point3<f64>| (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        let (w0, w1, w2) = (edge(q, r), edge(r, p), edge(p, q));
        let sign = twice_area.signum();
        let (s0, s1, s2) = (w0 * sign, w1 * sign, w2 * sign);
        if s0 < 0.0 || s1 < 0.0 || s2 < 0.0 {
            continue;
        }
        if s0 == 0.0 || s1 == 0.0 || s2 == 0.0 {
            return None;
        }
        let z = (w0 * p.z + w1 * q.z + w2 * r.z) / twice_area;
        if z == c.z {
            return None;
        }
        if z > c.z {
            w += sign as i32;
        }
    }
    Some(w)
}

/// One shell's faces as a [`Solid`].
pub(super) fn solid<'a>(
    mesh: &'a PolyMesh,
    faces: &'a [u32],
    (lo, hi): (Point3<f64>, Point3<f64>),
) -> Solid<'a> {
    Solid {
        mesh,
        faces,
        lo,
        hi,
    }
}
