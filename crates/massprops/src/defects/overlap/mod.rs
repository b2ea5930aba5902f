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

mod lines;
mod solid;

use nalgebra::Point3;

use super::shells::Part;
use crate::PolyMesh;
use crate::diagnostics::EXAMPLES;
use crate::warning::{Defect, Warning};
use lines::{Probe, probe, probe_self};
use solid::{Solid, solid};

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

#[cfg(test)]
mod tests {
    use super::solid::{convex_once, separated, winding_at};
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
