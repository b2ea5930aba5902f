//! The estimator: vertical lines through a jittered grid, each shell's crossings along them
//! (exact winding numbers), and the lengths inside both shells, or inside one shell twice, that
//! estimate the shared volume by stratified sampling.

use nalgebra::Point3;

use super::solid::{PLANE_SLACK, PLANES_UP_TO, Solid, convex_once, separated};
use super::{CELLS, FINE_CELLS, REPLICATES, SELF_VOLUME_TOLERANCE, SelfOverlap, each};

/// What the lines through two shells found.
pub(super) struct Probe {
    pub(super) a_inside_b: bool,
    pub(super) b_inside_a: bool,
    pub(super) overlap_seen: bool,
    pub(super) volume: f64,
    pub(super) uncertainty: f64,
}

/// A crossing of a line with a face: the line, the height, ±1 (the face's normal points up
/// or down), and the face.
pub(super) type Crossing = (u32, f64, i8, u32);

pub(super) fn probe(a: &Solid, b: &Solid, tolerance: f64, seed: u64) -> Probe {
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
pub(super) struct Grid {
    pub(super) lo: Point3<f64>,
    pub(super) dx: f64,
    pub(super) dy: f64,
    pub(super) cells: usize,
}

impl Grid {
    pub(super) fn new(lo: Point3<f64>, hi: Point3<f64>, cells: usize) -> Self {
        Self {
            lo,
            dx: (hi.x - lo.x) / cells as f64,
            dy: (hi.y - lo.y) / cells as f64,
            cells,
        }
    }

    /// Lines per replicate.
    pub(super) fn per_replicate(&self) -> usize {
        self.cells * self.cells
    }

    /// The lines, replicate by replicate (one point drawn in each cell).
    pub(super) fn lines(&self, seed: u64) -> Vec<(f64, f64)> {
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
pub(super) fn probe_self(a: &Solid, tolerance: f64, seed: u64) -> Option<SelfOverlap> {
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
pub(super) fn self_lengths(
    a: &Solid,
    cells: usize,
    tolerance: f64,
    seed: u64,
) -> Option<SelfOverlap> {
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
pub(super) struct ByLine {
    pub(super) crossings: Vec<Crossing>,
    /// Line `l`'s crossings are `crossings[starts[l]..starts[l + 1]]`.
    pub(super) starts: Vec<usize>,
}

pub(super) fn crossings_by_line(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> ByLine {
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
pub(super) const SLICE_FACES: usize = 32_768;

/// [`slice_crossings`] of the whole shell: a big shell in slices of faces on the rayon pool (a
/// scan's one shell is most of the work).
pub(super) fn unordered_crossings(
    solid: &Solid,
    lines: &[(f64, f64)],
    grid: &Grid,
) -> Vec<Vec<Crossing>> {
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
pub(super) fn crossings(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> Vec<Crossing> {
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
pub(super) fn sort_by_height(line: &mut [Crossing]) {
    line.sort_unstable_by(|a, b| a.1.total_cmp(&b.1).then(a.3.cmp(&b.3)));
}

/// [`crossings`] of one slice of a shell's faces, unordered.
pub(super) fn slice_crossings(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> Vec<Crossing> {
    let mut out = Vec::new();
    visit_crossings(solid, lines, grid, |c| out.push(c));
    out
}

/// Calls `found` with each crossing of the solid's faces with the grid's lines, face by face.
pub(super) fn visit_crossings(
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
pub(super) fn some_line_folds(solid: &Solid, lines: &[(f64, f64)], grid: &Grid) -> bool {
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
pub(super) struct Lengths {
    pub(super) both: f64,
    pub(super) a_only: f64,
    pub(super) b_only: f64,
}

/// Walks down a line through both shells' crossings (each ascending in height): the winding
/// number below a crossing is that above it plus the crossing's sign.
pub(super) fn sweep(a: &[Crossing], b: &[Crossing]) -> Lengths {
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
pub(super) struct SplitMix(u64);

impl SplitMix {
    /// Uniform in [0, 1).
    pub(super) fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}
