//! Which closed shells lie inside which, and how much volume overlapping shells count twice.
//!
//! Two shells whose bounding boxes meet are cut by vertical lines through a jittered grid over
//! the common box. Along each line the winding number of each shell is exact: it changes by the
//! sign of the normal's z component at each crossing of a face (the generalized winding number
//! restricted to a ray). Where both are non-zero the line is inside both: those lengths, times
//! the cell area, estimate the common volume by stratified sampling across lines. The grid is
//! drawn [`REPLICATES`] times with independent jitter; the spread of the replicate estimates gives
//! the uncertainty (one standard error). A shell is inside another when its bounding box is, and
//! no line finds a stretch of it outside the other. A shell that passes through itself (winding
//! number ±2 somewhere) is found on the coarse grid and then measured again on a grid
//! [`FINE_CELLS`] on a side, whose crossings also name the faces that bound the doubly counted
//! volume.

use nalgebra::{Point3, Vector3};

use super::shells::Part;
use crate::PolyMesh;
use crate::diagnostics::EXAMPLES;
use crate::warning::{Defect, Warning};

/// Independent jitterings of the grid.
const REPLICATES: usize = 4;
/// Cells along each side of the grid, per replicate.
const CELLS: usize = 32;
/// Cells along each side of the grid that measures a shell found passing through itself: the
/// doubly counted part is often a thin sliver, which the coarse grid finds but measures to only
/// ±40 % (the a1 trunk of pybullet_data).
const FINE_CELLS: usize = 128;
/// Lengths along a line below this fraction of the bounding-box diagonal are round-off (a shell
/// touching another's wall from inside).
const LENGTH_TOLERANCE: f64 = 1e-9;

/// A shell's volume counted twice below this fraction of its bounding box's is round-off.
const SELF_VOLUME_TOLERANCE: f64 = 1e-9;

/// Two closed shells that overlap without one holding the other.
#[derive(Debug, Clone, Copy)]
struct Overlap {
    a: usize,
    b: usize,
    volume: f64,
    uncertainty: f64,
}

/// A closed shell that passes through itself: where its winding number is ±2 or more, its
/// volume counts more than once.
#[derive(Debug, Clone)]
struct SelfOverlap {
    shell: usize,
    /// The volume counted more than once (each extra time counted again).
    volume: f64,
    uncertainty: f64,
    /// The shell's faces that bound the doubly counted volume (indices into the mesh), ascending.
    faces: Vec<u32>,
}

/// What the comparison of the closed shells found.
pub(crate) struct Relations {
    /// For each shell, the closed shells it lies inside (`None`: not known).
    containers: Vec<Option<Vec<usize>>>,
    overlaps: Vec<Overlap>,
    /// Shells that pass through themselves.
    selves: Vec<SelfOverlap>,
    /// The most volume the pairs not compared can share: the sum of the smaller shell's volume
    /// of each.
    uncompared_bound: f64,
    /// Pairs whose boxes meet, and how many of them were compared within the work budget.
    candidates: usize,
    compared: usize,
}

impl Relations {
    /// Nothing compared (the numbers do not use the volume).
    pub fn none(shells: usize) -> Self {
        Self {
            containers: vec![None; shells],
            overlaps: Vec::new(),
            selves: Vec::new(),
            uncompared_bound: 0.0,
            candidates: 0,
            compared: 0,
        }
    }

    /// How many closed shells hold shell `s`, when known.
    pub fn depth(&self, s: usize) -> Option<usize> {
        self.containers[s].as_ref().map(Vec::len)
    }

    /// The outermost shell holding `s` (itself when none does); `None` when that is not known
    /// (a comparison of `s` or of a shell holding it was cut short).
    pub fn root(&self, s: usize) -> Option<usize> {
        let containers = self.containers[s].as_ref()?;
        if containers.iter().any(|&o| self.depth(o).is_none()) {
            return None;
        }
        Some(
            containers
                .iter()
                .copied()
                .find(|&o| self.depth(o) == Some(0))
                .unwrap_or(s),
        )
    }

    /// The `self_overlapping_shell` warning, when a closed shell passes through itself.
    /// `sign(s)` is ±1 as shell `s` counts.
    pub fn self_overlap_warning(
        &self,
        parts: &[Part],
        sign: &dyn Fn(usize) -> f64,
    ) -> Option<Warning> {
        if self.selves.is_empty() {
            return None;
        }
        let volume: f64 = self.selves.iter().map(|o| o.volume).sum();
        let variance: f64 = self.selves.iter().map(|o| o.uncertainty.powi(2)).sum();
        let effect: f64 = self.selves.iter().map(|o| o.volume * sign(o.shell)).sum();
        let between = self.overlap_effect(sign);
        let between_variance: f64 = self.overlaps.iter().map(|o| o.uncertainty.powi(2)).sum();
        let mut faces: Vec<usize> = self
            .selves
            .iter()
            .flat_map(|o| o.faces.iter().map(|&f| f as usize))
            .collect();
        faces.sort_unstable();
        faces.dedup();
        Some(Warning {
            defect: Defect::SelfOverlappingShell {
                shells: self.selves.iter().take(EXAMPLES).map(|o| o.shell).collect(),
                volume,
                uncertainty: variance.sqrt(),
                crossing_faces: faces.len(),
                total_effect: effect + between,
                total_uncertainty: (variance + between_variance).sqrt(),
            },
            count: self.selves.len(),
            faces: if faces.is_empty() {
                self.selves
                    .iter()
                    .filter_map(|o| parts[o.shell].faces.first().map(|&f| f as usize))
                    .collect()
            } else {
                faces
            },
            effect_on_mass: Some(effect),
        })
    }

    /// The volume counted twice (removed twice, for cavities) between overlapping shells.
    fn overlap_effect(&self, sign: &dyn Fn(usize) -> f64) -> f64 {
        // Two solids count their common part twice; two cavities remove it twice.
        self.overlaps
            .iter()
            .map(|o| o.volume * (sign(o.a) + sign(o.b)) / 2.0)
            .sum()
    }

    /// The `overlapping_shells` warning, when shells overlap or the budget cut the comparison
    /// short. `sign(s)` is ±1 as shell `s` counts (outward solid or inward cavity).
    pub fn overlap_warning(&self, parts: &[Part], sign: &dyn Fn(usize) -> f64) -> Option<Warning> {
        let cut_short = self.compared < self.candidates;
        if self.overlaps.is_empty() && !cut_short {
            return None;
        }
        let volume: f64 = self.overlaps.iter().map(|o| o.volume).sum();
        let variance: f64 = self.overlaps.iter().map(|o| o.uncertainty.powi(2)).sum();
        let effect = self.overlap_effect(sign);
        let faces = self
            .overlaps
            .iter()
            .flat_map(|o| [o.a, o.b])
            .filter_map(|s| parts[s].faces.first().copied())
            .map(|f| f as usize)
            .collect();
        Some(Warning {
            defect: Defect::OverlappingShells {
                pairs: self
                    .overlaps
                    .iter()
                    .take(EXAMPLES)
                    .map(|o| (o.a, o.b))
                    .collect(),
                volume,
                uncertainty: variance.sqrt(),
                compared: self.compared,
                candidates: self.candidates,
                uncompared_bound: self.uncompared_bound,
            },
            count: self.overlaps.len(),
            faces,
            effect_on_mass: Some(effect),
        })
    }
}

/// One closed shell: its faces in the mesh, with its bounding box.
#[derive(Clone, Copy)]
struct Solid<'a> {
    mesh: &'a PolyMesh,
    faces: &'a [u32],
    lo: Point3<f64>,
    hi: Point3<f64>,
}

impl Solid<'_> {
    /// The faces as fan triangles, each with its face.
    fn triangles(&self) -> impl Iterator<Item = ([Point3<f64>; 3], u32)> + '_ {
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
const PLANES_UP_TO: usize = 256;

/// How far a vertex may lie past a plane and still count as on it, relative to the tolerance on
/// lengths: far below any length the lines could measure.
const PLANE_SLACK: f64 = 1e-3;

impl Solid<'_> {
    /// The shell's vertices, each once.
    fn points(&self) -> Vec<Point3<f64>> {
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
    fn planes(&self) -> Vec<(Vector3<f64>, Point3<f64>)> {
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
fn sides(plane: &(Vector3<f64>, Point3<f64>), points: &[Point3<f64>], slack: f64) -> (bool, bool) {
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
fn separated(a: &Solid, b: &Solid, slack: f64) -> bool {
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
fn convex_once(a: &Solid, slack: f64) -> bool {
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
fn winding_at(solid: &Solid, c: Point3<f64>) -> Option<i32> {
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

/// Compares the pairs of closed shells whose bounding boxes meet, in order, as long as the work
/// fits in `budget` (work units: a pair costs the triangles of both shells and the lines of its
/// grid). What is
/// compared, and so the result, depends on the mesh and the budget alone, never on the machine
/// or its load; the pairs are probed in parallel (each on its own, so the order changes nothing).
pub(crate) fn compare(
    mesh: &PolyMesh,
    parts: &[Part],
    solids: &[bool],
    volumes: &[f64],
    budget: u64,
) -> Relations {
    let (lo, hi) = mesh.bounding_box();
    let tolerance = LENGTH_TOLERANCE * (hi - lo).norm();
    let closed: Vec<usize> = (0..parts.len()).filter(|&s| solids[s]).collect();
    let mut relations = Relations::none(parts.len());
    for &s in &closed {
        relations.containers[s] = Some(Vec::new());
    }
    if closed.is_empty() {
        return relations;
    }
    let boxes: Vec<(Point3<f64>, Point3<f64>)> = closed
        .iter()
        .map(|&s| bounds(mesh, &parts[s].faces))
        .collect();
    let mut order: Vec<usize> = (0..closed.len()).collect();
    order.sort_by(|&i, &j| boxes[i].0.x.total_cmp(&boxes[j].0.x));
    let mut pairs = Vec::new();
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            if boxes[j].0.x >= boxes[i].1.x {
                break;
            }
            let meet =
                (0..3).all(|d| boxes[i].0[d] < boxes[j].1[d] && boxes[j].0[d] < boxes[i].1[d]);
            if meet {
                pairs.push((i.min(j), i.max(j)));
            }
        }
    }
    pairs.sort_unstable();
    relations.candidates = pairs.len();
    // Which pairs the budget allows, decided before any is probed: a pair costs the triangles of
    // both shells and the grid's lines.
    let triangle_count = |k: usize| -> u64 {
        parts[closed[k]]
            .faces
            .iter()
            .map(|&f| mesh.face(f as usize).len().saturating_sub(2) as u64)
            .sum()
    };
    let costs: Vec<u64> = (0..closed.len()).map(triangle_count).collect();
    let mut unknown = vec![false; parts.len()];
    let mut spent = 0u64;
    let mut chosen = Vec::with_capacity(pairs.len());
    for &(i, j) in &pairs {
        let cost = costs[i] + costs[j] + (REPLICATES * CELLS * CELLS) as u64;
        if spent.saturating_add(cost) > budget {
            unknown[closed[i]] = true;
            unknown[closed[j]] = true;
            // Two shells can share at most the smaller one's volume.
            relations.uncompared_bound += volumes[closed[i]].abs().min(volumes[closed[j]].abs());
            continue;
        }
        spent += cost;
        chosen.push((i, j));
    }
    // Then each closed shell against itself, as far as the budget still goes.
    let mut own = Vec::with_capacity(closed.len());
    for (k, &cost) in costs.iter().enumerate() {
        let cost = cost + (REPLICATES * CELLS * CELLS) as u64;
        if spent.saturating_add(cost) > budget {
            continue;
        }
        spent += cost;
        own.push(k);
    }
    let mut needed = vec![false; closed.len()];
    for &(i, j) in &chosen {
        needed[i] = true;
        needed[j] = true;
    }
    for &k in &own {
        needed[k] = true;
    }
    let built: Vec<Option<Solid>> = each(needed.len(), &|k| {
        needed[k].then(|| solid(mesh, &parts[closed[k]].faces, boxes[k]))
    });
    let found: Vec<Option<Probe>> = each(chosen.len(), &|n| {
        let (i, j) = chosen[n];
        let (Some(a), Some(b)) = (&built[i], &built[j]) else {
            return None;
        };
        let seed = ((closed[i] as u64) << 32) ^ closed[j] as u64;
        Some(probe(a, b, tolerance, seed))
    });
    let selves: Vec<Option<SelfOverlap>> = each(own.len(), &|n| {
        let k = own[n];
        let solid = built[k].as_ref()?;
        probe_self(solid, tolerance, closed[k] as u64)
    });
    for (&k, found) in own.iter().zip(selves) {
        if let Some(found) = found {
            relations.selves.push(SelfOverlap {
                shell: closed[k],
                ..found
            });
        }
    }
    for (&(i, j), found) in chosen.iter().zip(found) {
        let Some(found) = found else { continue };
        relations.compared += 1;
        let (sa, sb) = (closed[i], closed[j]);
        match (found.a_inside_b, found.b_inside_a) {
            (true, false) => push(&mut relations.containers[sa], sb),
            (false, true) => push(&mut relations.containers[sb], sa),
            _ if found.overlap_seen => relations.overlaps.push(Overlap {
                a: sa,
                b: sb,
                volume: found.volume,
                uncertainty: found.uncertainty,
            }),
            _ => {}
        }
    }
    for (s, &u) in unknown.iter().enumerate() {
        if u {
            relations.containers[s] = None;
        }
    }
    relations
}

/// `f(0..n)`, on the rayon pool with the `parallel` feature; in index order either way.
fn each<T: Send>(n: usize, f: &(dyn Fn(usize) -> T + Sync)) -> Vec<T> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        (0..n).into_par_iter().map(f).collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        (0..n).map(f).collect()
    }
}

fn push(list: &mut Option<Vec<usize>>, s: usize) {
    if let Some(list) = list {
        list.push(s);
    }
}

/// Bounding box of some faces' corners.
fn bounds(mesh: &PolyMesh, faces: &[u32]) -> (Point3<f64>, Point3<f64>) {
    let mut lo = Point3::from([f64::INFINITY; 3]);
    let mut hi = Point3::from([f64::NEG_INFINITY; 3]);
    for &f in faces {
        for p in mesh.face_points(f as usize) {
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        }
    }
    (lo, hi)
}

/// One shell's faces as a [`Solid`].
fn solid<'a>(
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

/// What the lines through two shells found.
struct Probe {
    a_inside_b: bool,
    b_inside_a: bool,
    overlap_seen: bool,
    volume: f64,
    uncertainty: f64,
}

/// A crossing of a line with a face: the line, the height, ±1 (the face's normal points up
/// or down), and the face.
type Crossing = (u32, f64, i8, u32);

fn probe(a: &Solid, b: &Solid, tolerance: f64, seed: u64) -> Probe {
    let small = a.faces.len() <= PLANES_UP_TO && b.faces.len() <= PLANES_UP_TO;
    let slack = PLANE_SLACK * tolerance;
    if small && (separated(a, b, slack) || separated(b, a, slack)) {
        return Probe {
            a_inside_b: false,
            b_inside_a: false,
            overlap_seen: false,
            volume: 0.0,
            uncertainty: 0.0,
        };
    }
    let lo = a.lo.sup(&b.lo);
    let hi = a.hi.inf(&b.hi);
    let grid = Grid::new(lo, hi, CELLS);
    let lines = grid.lines(seed);
    let crossings_a = crossings(a, &lines, &grid);
    let crossings_b = crossings(b, &lines, &grid);
    let mut both = [0.0; REPLICATES];
    let (mut a_only, mut b_only) = (false, false);
    let mut overlap_seen = false;
    let (mut ia, mut ib) = (0, 0);
    for (line, _) in lines.iter().enumerate() {
        let line = line as u32;
        let start_a = ia;
        while ia < crossings_a.len() && crossings_a[ia].0 == line {
            ia += 1;
        }
        let start_b = ib;
        while ib < crossings_b.len() && crossings_b[ib].0 == line {
            ib += 1;
        }
        let lengths = sweep(&crossings_a[start_a..ia], &crossings_b[start_b..ib]);
        both[line as usize / grid.per_replicate()] += lengths.both;
        overlap_seen |= lengths.both > tolerance;
        a_only |= lengths.a_only > tolerance;
        b_only |= lengths.b_only > tolerance;
    }
    let estimates = both.map(|l| l * grid.dx * grid.dy);
    let volume = estimates.iter().sum::<f64>() / REPLICATES as f64;
    let spread = estimates.iter().map(|e| (e - volume).powi(2)).sum::<f64>();
    let uncertainty = (spread / (REPLICATES * (REPLICATES - 1)) as f64).sqrt();
    let within = |inner: &Solid, outer: &Solid| {
        (0..3).all(|d| {
            inner.lo[d] >= outer.lo[d] - tolerance && inner.hi[d] <= outer.hi[d] + tolerance
        })
    };
    Probe {
        a_inside_b: overlap_seen && !a_only && within(a, b),
        b_inside_a: overlap_seen && !b_only && within(b, a),
        overlap_seen,
        volume,
        uncertainty,
    }
}

/// [`REPLICATES`] jittered grids of `cells × cells` vertical lines over a box's footprint.
struct Grid {
    lo: Point3<f64>,
    dx: f64,
    dy: f64,
    cells: usize,
}

impl Grid {
    fn new(lo: Point3<f64>, hi: Point3<f64>, cells: usize) -> Self {
        Self {
            lo,
            dx: (hi.x - lo.x) / cells as f64,
            dy: (hi.y - lo.y) / cells as f64,
            cells,
        }
    }

    /// Lines per replicate.
    fn per_replicate(&self) -> usize {
        self.cells * self.cells
    }

    /// The lines, replicate by replicate (one point drawn in each cell).
    fn lines(&self, seed: u64) -> Vec<(f64, f64)> {
        let mut rng = SplitMix(seed);
        (0..REPLICATES * self.per_replicate())
            .map(|n| {
                let cell = n % self.per_replicate();
                let (i, j) = (cell % self.cells, cell / self.cells);
                (
                    self.lo.x + (i as f64 + rng.unit()) * self.dx,
                    self.lo.y + (j as f64 + rng.unit()) * self.dy,
                )
            })
            .collect()
    }
}

/// The volume a shell counts more than once (where it passes through itself: winding number ±2
/// or more along a line), with one standard error and the faces bounding it; `None` when no line
/// of the coarse grid finds any. `shell` is left 0 for the caller.
fn probe_self(a: &Solid, tolerance: f64, seed: u64) -> Option<SelfOverlap> {
    if a.faces.len() <= PLANES_UP_TO && convex_once(a, PLANE_SLACK * tolerance) {
        return None;
    }
    let coarse = self_lengths(a, CELLS, tolerance, seed ^ 0x5E1F_0000_0000_0000)?;
    let fine = self_lengths(a, FINE_CELLS, tolerance, seed ^ 0x5E1F_F000_0000_0000);
    // The fine grid measures; it finds nothing only where the coarse grid's find was round-off.
    let found = fine.unwrap_or(coarse);
    // Round-off where the shell's own faces meet at a fold is no volume.
    let extent = a.hi - a.lo;
    let boxed = extent.x * extent.y * extent.z.max(f64::MIN_POSITIVE);
    (found.volume > SELF_VOLUME_TOLERANCE * boxed).then_some(found)
}

/// [`probe_self`] on one grid of `cells` on a side.
fn self_lengths(a: &Solid, cells: usize, tolerance: f64, seed: u64) -> Option<SelfOverlap> {
    let grid = Grid::new(a.lo, a.hi, cells);
    if grid.dx <= 0.0 || grid.dy <= 0.0 {
        return None;
    }
    let lines = grid.lines(seed);
    // A shell small enough for one slice (below) is counted first; a big one goes straight to
    // the crossings, which are found on the pool.
    if a.faces.len() <= SLICE_FACES && !some_line_folds(a, &lines, &grid) {
        return None;
    }
    let ByLine {
        mut crossings,
        starts,
    } = crossings_by_line(a, &lines, &grid);
    let mut extra = [0.0; REPLICATES];
    let mut seen = false;
    let mut faces = Vec::new();
    for bounds in starts.windows(2) {
        let line = &mut crossings[bounds[0]..bounds[1]];
        // The winding number passes ±1 only where a line has two crossings of one sign; a line
        // of one crossing, or of two that cancel, never does (most lines of most shells: they
        // are left unsorted).
        if line.len() < 2 || (line.len() == 2 && line[0].2 != line[1].2) {
            continue;
        }
        sort_by_height(line);
        let line = &*line;
        // Down the line from the top: the winding number below a crossing is that above it plus
        // the crossing's sign; |w| − 1 more counts of each stretch where |w| > 1. A crossing
        // with |w| > 1 on either side bounds that stretch.
        let (mut w, mut z_prev) = (0i32, f64::INFINITY);
        let mut length = 0.0;
        for &(_, z, sign, face) in line.iter().rev() {
            if w.abs() > 1 && z_prev.is_finite() {
                length += f64::from(w.abs() - 1) * (z_prev - z);
            }
            let above = w;
            w += i32::from(sign);
            if above.abs() > 1 || w.abs() > 1 {
                faces.push(face);
            }
            z_prev = z;
        }
        seen |= length > tolerance;
        extra[line[0].0 as usize / grid.per_replicate()] += length;
    }
    if !seen {
        return None;
    }
    let estimates = extra.map(|l| l * grid.dx * grid.dy);
    let volume = estimates.iter().sum::<f64>() / REPLICATES as f64;
    let spread = estimates.iter().map(|e| (e - volume).powi(2)).sum::<f64>();
    faces.sort_unstable();
    faces.dedup();
    Some(SelfOverlap {
        shell: 0,
        volume,
        uncertainty: (spread / (REPLICATES * (REPLICATES - 1)) as f64).sqrt(),
        faces,
    })
}

/// Every crossing of the shell's faces with the grid's lines, grouped by line (a counting sort;
/// in each line in no order).
struct ByLine {
    crossings: Vec<Crossing>,
    /// Line `l`'s crossings are `crossings[starts[l]..starts[l + 1]]`.
    starts: Vec<usize>,
}

fn crossings_by_line(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> ByLine {
    let found = unordered_crossings(solid, lines, grid);
    let mut starts = vec![0usize; lines.len() + 1];
    for c in found.iter().flatten() {
        starts[c.0 as usize + 1] += 1;
    }
    for l in 0..lines.len() {
        starts[l + 1] += starts[l];
    }
    let mut next = starts.clone();
    let mut crossings = vec![(0, 0.0, 0, 0); starts[lines.len()]];
    // Slices in order, each in its own order: the same grouping whatever the split.
    for c in found.into_iter().flatten() {
        let at = &mut next[c.0 as usize];
        crossings[*at] = c;
        *at += 1;
    }
    ByLine { crossings, starts }
}

/// The faces of one slice of a shell whose crossings are found on the pool.
const SLICE_FACES: usize = 32_768;

/// [`slice_crossings`] of the whole shell: a big shell in slices of faces on the rayon pool (a
/// scan's one shell is most of the work).
fn unordered_crossings(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> Vec<Vec<Crossing>> {
    let slices = (solid.faces.len() / SLICE_FACES).clamp(1, 64);
    each(slices, &|k| {
        let faces =
            &solid.faces[k * solid.faces.len() / slices..(k + 1) * solid.faces.len() / slices];
        let slice = Solid { faces, ..*solid };
        slice_crossings(&slice, lines, grid)
    })
}

/// Every crossing of the shell's faces with the grid's lines, ordered by line, then height, then
/// face: grouped by line by a counting sort, then each line's few crossings sorted.
fn crossings(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> Vec<Crossing> {
    let ByLine {
        mut crossings,
        starts,
    } = crossings_by_line(solid, lines, grid);
    for bounds in starts.windows(2) {
        sort_by_height(&mut crossings[bounds[0]..bounds[1]]);
    }
    crossings
}

/// One line's crossings in order of height, ties by face: the same order whatever the split of
/// the faces.
fn sort_by_height(line: &mut [Crossing]) {
    line.sort_unstable_by(|a, b| a.1.total_cmp(&b.1).then(a.3.cmp(&b.3)));
}

/// [`crossings`] of one slice of a shell's faces, unordered.
fn slice_crossings(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> Vec<Crossing> {
    let mut out = Vec::new();
    visit_crossings(solid, lines, grid, |c| out.push(c));
    out
}

/// Calls `found` with each crossing of the solid's faces with the grid's lines, face by face.
fn visit_crossings(
    solid: &Solid,
    lines: &[(f64, f64)],
    grid: &Grid,
    mut found: impl FnMut(Crossing),
) {
    let Grid {
        lo, dx, dy, cells, ..
    } = *grid;
    let per_replicate = grid.per_replicate();
    let cell_range = |min: f64, max: f64, origin: f64, step: f64| {
        let first = ((min - origin) / step).floor().max(0.0) as usize;
        let last = (((max - origin) / step).floor().max(0.0) as usize).min(cells - 1);
        first..=last
    };
    for ([p, q, r], face) in solid.triangles() {
        let twice_area = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
        if twice_area == 0.0 {
            continue;
        }
        let (min_x, max_x) = (p.x.min(q.x).min(r.x), p.x.max(q.x).max(r.x));
        let (min_y, max_y) = (p.y.min(q.y).min(r.y), p.y.max(q.y).max(r.y));
        if max_x < lo.x
            || max_y < lo.y
            || min_x > lo.x + dx * cells as f64
            || min_y > lo.y + dy * cells as f64
        {
            continue;
        }
        let sign: i8 = if twice_area > 0.0 { 1 } else { -1 };
        for j in cell_range(min_y, max_y, lo.y, dy) {
            for i in cell_range(min_x, max_x, lo.x, dx) {
                for k in 0..REPLICATES {
                    let line = k * per_replicate + j * cells + i;
                    let (x, y) = lines[line];
                    let edge = |a: Point3<f64>, b: Point3<f64>| {
                        (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)
                    };
                    let (w0, w1, w2) = (edge(q, r), edge(r, p), edge(p, q));
                    let inside = if sign > 0 {
                        w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0
                    } else {
                        w0 <= 0.0 && w1 <= 0.0 && w2 <= 0.0
                    };
                    if inside {
                        let z = (w0 * p.z + w1 * q.z + w2 * r.z) / twice_area;
                        found((line as u32, z, sign, face));
                    }
                }
            }
        }
    }
}

/// Whether some line crosses the shell twice the same way (two crossings of one sign): only
/// there can its winding number pass ±1. Counted without storing a crossing, so that the shells
/// that cannot pass through themselves (most: every line in and out once) cost no allocation
/// and no sort.
fn some_line_folds(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> bool {
    // [inward, outward] crossings of each line, saturating (two is all that matters).
    let mut counts = vec![[0u8; 2]; lines.len()];
    let mut folds = false;
    visit_crossings(solid, lines, grid, |(line, _, sign, _)| {
        let c = &mut counts[line as usize][usize::from(sign > 0)];
        *c = c.saturating_add(1);
        folds |= *c > 1;
    });
    folds
}

/// Lengths along one line inside both shells, inside only the first, inside only the second.
struct Lengths {
    both: f64,
    a_only: f64,
    b_only: f64,
}

/// Walks down a line through both shells' crossings (each ascending in height): the winding
/// number below a crossing is that above it plus the crossing's sign.
fn sweep(a: &[Crossing], b: &[Crossing]) -> Lengths {
    let mut out = Lengths {
        both: 0.0,
        a_only: 0.0,
        b_only: 0.0,
    };
    let (mut i, mut j) = (a.len(), b.len());
    let (mut wa, mut wb) = (0i32, 0i32);
    let mut z_prev = f64::INFINITY;
    while i > 0 || j > 0 {
        let take_a = j == 0 || (i > 0 && a[i - 1].1 >= b[j - 1].1);
        let (z, sign) = if take_a {
            i -= 1;
            (a[i].1, a[i].2)
        } else {
            j -= 1;
            (b[j].1, b[j].2)
        };
        if z_prev.is_finite() {
            let length = z_prev - z;
            match (wa != 0, wb != 0) {
                (true, true) => out.both += length,
                (true, false) => out.a_only += length,
                (false, true) => out.b_only += length,
                (false, false) => {}
            }
        }
        if take_a {
            wa += i32::from(sign);
        } else {
            wb += i32::from(sign);
        }
        z_prev = z;
    }
    out
}

/// A small, fixed-seed generator (SplitMix64, Steele et al. 2014): the same mesh always gets the
/// same estimate.
struct SplitMix(u64);

impl SplitMix {
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes;

    fn whole(mesh: &PolyMesh, faces: &[u32]) -> (Point3<f64>, Point3<f64>) {
        bounds(mesh, faces)
    }

    #[test]
    fn a_convex_shell_covered_once_is_told_from_one_covered_twice() {
        let cube = shapes::cube().triangulated().build();
        let faces: Vec<u32> = (0..cube.face_count() as u32).collect();
        let once = solid(&cube, &faces, whole(&cube, &faces));
        assert_eq!(winding_at(&once, Point3::new(0.1, 0.2, 0.05)), Some(1));
        assert!(convex_once(&once, 1e-12));
        // The same faces twice: convex by every plane, but the winding number inside is 2.
        let doubled: Vec<u32> = faces.iter().chain(&faces).copied().collect();
        let twice = solid(&cube, &doubled, whole(&cube, &doubled));
        assert_eq!(winding_at(&twice, Point3::new(0.1, 0.2, 0.05)), Some(2));
        assert!(!convex_once(&twice, 1e-12));
        // Inward-wound: −1, still once.
        let flipped = cube.flipped();
        let inward = solid(&flipped, &faces, whole(&flipped, &faces));
        assert_eq!(winding_at(&inward, Point3::new(0.1, 0.2, 0.05)), Some(-1));
        // A line along the cube's diagonal edges meets two triangles' shared edge: no answer.
        assert_eq!(winding_at(&once, Point3::new(0.0, 0.0, 0.0)), None);
        // The L-bracket is not convex.
        let bracket = shapes::l_bracket().build();
        let all: Vec<u32> = (0..bracket.face_count() as u32).collect();
        assert!(!convex_once(
            &solid(&bracket, &all, whole(&bracket, &all)),
            1e-12
        ));
    }

    #[test]
    fn a_face_plane_separates_boxes_that_touch_but_not_boxes_that_overlap() {
        let pair = |dx: f64| {
            let mut b = shapes::cube();
            b.append(&shapes::cube().transformed(&nalgebra::Isometry3::translation(dx, 0.3, 0.0)));
            b.build()
        };
        for (dx, apart) in [(1.0, true), (1.5, true), (0.9, false)] {
            let mesh = pair(dx);
            let (first, second): (Vec<u32>, Vec<u32>) = ((0..6).collect(), (6..12).collect());
            let a = solid(&mesh, &first, whole(&mesh, &first));
            let b = solid(&mesh, &second, whole(&mesh, &second));
            assert_eq!(separated(&a, &b, 1e-12), apart, "dx {dx}");
            assert_eq!(separated(&b, &a, 1e-12), apart, "dx {dx}");
        }
    }
}
