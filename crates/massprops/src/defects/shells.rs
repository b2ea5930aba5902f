//! Shells: the connected pieces of a surface, faces joined across manifold edges.
//!
//! An edge used by exactly two faces joins them. Around an edge used by more (two parts that
//! touch along it, a fin), the faces are ordered by angle about the edge and each face is joined
//! to its neighbour on its inner side (opposite its normal) when that neighbour's inner side
//! faces back and it runs the edge the other way: the radial pairing of non-manifold solid
//! modelling (Weiler's radial edge structure), which keeps touching solids apart and joins the
//! two sides of each wedge of material. A shell is closed when each of its edges is used as
//! often in one direction as in the other by its own faces.

use nalgebra::{Point3, Vector3};

use super::AUTO_WELD_RATIO;
use super::{CAP, Cleaned, UnionFind, face_volume};
use crate::PolyMesh;
use crate::edges::{EdgeTable, HalfEdge};
use crate::solid::ZERO_VOLUME_RATIO;

/// Whether a closed shell's faces point away from what it encloses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Orientation {
    /// Counter-clockwise seen from outside: positive signed volume.
    Outward,
    /// Clockwise seen from outside: negative signed volume (a cavity, inside another shell).
    Inward,
}

/// One connected piece of the mesh, as found in the file.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Shell {
    /// Faces of the file in this shell (duplicates removed, caps not counted).
    pub faces: usize,
    /// Closed in the file (after closing cracks).
    pub closed: bool,
    /// Open, and its holes were capped (an open shell that is not capped meets other shells
    /// along edges it uses unevenly, which caps do not close).
    pub capped: bool,
    /// Signed volume as wound in the file (of the capped shell when it was open).
    pub volume: f64,
    /// The sign of `volume`.
    pub orientation: Orientation,
    /// How many closed shells enclose this one (0: an outer surface; 1: a cavity's wall or a
    /// part inside one); `None` when not known (the comparison's work budget ran out, or the
    /// numbers do not use the volume).
    pub depth: Option<usize>,
}

/// A shell of the working mesh: its faces (ascending) and whether it is closed.
pub(crate) struct Part {
    pub faces: Vec<u32>,
    pub closed: bool,
    /// The shell's open sides, as their faces run them (from, to), with the face: edges that
    /// one of its faces uses and no other of its faces runs back. What caps can close.
    pub boundary: Vec<((u32, u32), u32)>,
    /// An edge that several faces share is run two or more times more one way than the other
    /// by this shell's faces (inconsistent winding): open in a way caps do not close.
    pub unbalanced: bool,
}

/// Splits the working mesh into shells, ordered by their first face.
pub(crate) fn split(mesh: &PolyMesh, table: &EdgeTable) -> Vec<Part> {
    let n = mesh.face_count();
    let mut sets = UnionFind::new(n);
    for group in table.groups() {
        match group.len() {
            1 => {}
            2 => sets.union(group[0].face, group[1].face),
            _ => {
                for (a, b) in radial_pairs(mesh, group) {
                    sets.union(a, b);
                }
            }
        }
    }
    let mut index = vec![u32::MAX; n];
    let mut parts: Vec<Part> = Vec::new();
    for f in 0..n as u32 {
        let root = sets.find(f) as usize;
        if index[root] == u32::MAX {
            index[root] = parts.len() as u32;
            parts.push(Part {
                faces: Vec::new(),
                closed: true,
                boundary: Vec::new(),
                unbalanced: false,
            });
        }
        parts[index[root] as usize].faces.push(f);
    }
    let shell_of = |sets: &mut UnionFind, f: u32| index[sets.find(f) as usize] as usize;
    for group in table.groups() {
        match group.len() {
            1 => {
                let s = shell_of(&mut sets, group[0].face);
                parts[s].closed = false;
                parts[s].boundary.push((group[0].directed(), group[0].face));
            }
            2 => {}
            _ => {
                // Each shell meeting here must use the edge as often each way; one side left
                // over is a hole's edge (a half whose wall another shell has).
                let mut balance: Vec<(usize, i32)> = Vec::new();
                for side in group {
                    let s = shell_of(&mut sets, side.face);
                    let step = if side.forward { 1 } else { -1 };
                    match balance.iter_mut().find(|(t, _)| *t == s) {
                        Some((_, b)) => *b += step,
                        None => balance.push((s, step)),
                    }
                }
                for (s, b) in balance {
                    if b == 0 {
                        continue;
                    }
                    parts[s].closed = false;
                    let leftover = group.iter().find(|side| {
                        side.forward == (b > 0) && shell_of(&mut sets, side.face) == s
                    });
                    match leftover {
                        Some(side) if b.abs() == 1 => {
                            parts[s].boundary.push((side.directed(), side.face));
                        }
                        _ => parts[s].unbalanced = true,
                    }
                }
            }
        }
    }
    parts
}

/// The pairs of faces around a non-manifold edge that bound one wedge of material: each face's
/// nearest neighbour in angle on the side opposite its normal, when the choice is mutual and the
/// two run the edge in opposite directions.
fn radial_pairs(mesh: &PolyMesh, group: &[HalfEdge]) -> Vec<(u32, u32)> {
    let at = |i: u32| mesh.positions()[i as usize];
    let (lo, hi) = (at(group[0].lo), at(group[0].hi));
    let Some(axis) = (hi - lo).try_normalize(0.0) else {
        return Vec::new();
    };
    let u = axis
        .cross(&Vector3::x())
        .try_normalize(1e-6)
        .unwrap_or_else(|| {
            axis.cross(&Vector3::y())
                .try_normalize(0.0)
                .unwrap_or_else(Vector3::z)
        });
    let v = axis.cross(&u);
    // Each side: its angle about the edge, and ±1: which way (in angle) its material lies.
    let mut sides: Vec<(f64, f64, usize)> = Vec::with_capacity(group.len());
    for (k, side) in group.iter().enumerate() {
        let face = mesh.face(side.face as usize);
        let centre = face.iter().map(|&i| at(i).coords).sum::<Vector3<f64>>() / face.len() as f64;
        let out = centre - lo.coords;
        let w = out - axis * axis.dot(&out);
        let normal: Vector3<f64> = face[1..]
            .windows(2)
            .map(|p| (at(p[0]) - at(face[0])).cross(&(at(p[1]) - at(face[0]))))
            .sum();
        let turn = normal.dot(&axis.cross(&w));
        if w.norm() == 0.0 || turn == 0.0 {
            continue;
        }
        // The normal points towards increasing angle when `turn` > 0: the material lies the
        // other way.
        sides.push((w.dot(&v).atan2(w.dot(&u)), -turn.signum(), k));
    }
    sides.sort_by(|a, b| a.0.total_cmp(&b.0));
    let n = sides.len();
    if n < 2 {
        return Vec::new();
    }
    let partner = |i: usize| {
        if sides[i].1 > 0.0 {
            (i + 1) % n
        } else {
            (i + n - 1) % n
        }
    };
    let mut pairs = Vec::new();
    for i in 0..n {
        let j = partner(i);
        let (a, b) = (&group[sides[i].2], &group[sides[j].2]);
        if i < j && partner(j) == i && a.forward != b.forward {
            pairs.push((a.face, b.face));
        }
    }
    pairs
}

/// The signed volume of each shell about `reference` (the enclosed volume for a closed shell).
pub(crate) fn volumes(mesh: &PolyMesh, parts: &[Part], reference: Point3<f64>) -> Vec<f64> {
    parts
        .iter()
        .map(|p| {
            p.faces
                .iter()
                .map(|&f| face_volume(mesh, f as usize, reference))
                .sum()
        })
        .collect()
}

/// Which shells are solids: closed, and thicker on average (volume over area) than
/// [`AUTO_WELD_RATIO`] × the mesh's diagonal. The rest (a sheet and its cap, a face with its
/// reverse) enclose nothing worth turning or comparing.
pub(crate) fn solids(mesh: &PolyMesh, parts: &[Part], volumes: &[f64]) -> Vec<bool> {
    let (lo, hi) = mesh.bounding_box();
    let diagonal = (hi - lo).norm();
    let floor = ZERO_VOLUME_RATIO * diagonal.powi(3);
    // Twice the area, by cross products from each face's first corner (no allocation).
    let twice_area = |f: u32| {
        let face = mesh.face(f as usize);
        let at = |i: u32| mesh.positions()[i as usize];
        let a = at(face[0]);
        let n: Vector3<f64> = face[1..]
            .windows(2)
            .map(|w| (at(w[0]) - a).cross(&(at(w[1]) - a)))
            .sum();
        n.norm()
    };
    parts
        .iter()
        .zip(volumes)
        .map(|(p, &v)| {
            // Most shells are plainly solid: their volume beats any area the test could find.
            if !p.closed || v.abs() <= floor {
                return false;
            }
            let area: f64 = 0.5 * p.faces.iter().map(|&f| twice_area(f)).sum::<f64>();
            v.abs() > AUTO_WELD_RATIO * area * diagonal
        })
        .collect()
}

/// The public description of each shell; `depth(s)` is how many closed shells hold shell `s`,
/// when known.
pub(crate) fn describe(
    work: &Cleaned<'_>,
    parts: &[Part],
    volumes: &[f64],
    depth: impl Fn(usize) -> Option<usize>,
) -> Vec<Shell> {
    let from_file = |f: u32| work.origin.as_ref().is_none_or(|o| o[f as usize] != CAP);
    parts
        .iter()
        .zip(volumes)
        .enumerate()
        .map(|(s, (part, &volume))| {
            let faces = part.faces.iter().filter(|&&f| from_file(f)).count();
            let capped = faces < part.faces.len();
            Shell {
                faces,
                closed: part.closed && !capped,
                capped,
                volume,
                orientation: if volume < 0.0 {
                    Orientation::Inward
                } else {
                    Orientation::Outward
                },
                depth: depth(s),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes;

    #[test]
    fn two_separate_boxes_and_an_open_one_make_three_shells() {
        let unit = Vector3::new(1.0, 1.0, 1.0);
        let mut b = shapes::cuboid(unit, Point3::origin());
        b.append(&shapes::cuboid(unit, Point3::new(3.0, 0.0, 0.0)));
        let mut open = shapes::cuboid(unit, Point3::new(6.0, 0.0, 0.0));
        open.faces.pop();
        b.append(&open);
        let mesh = b.build();
        let parts = split(&mesh, &EdgeTable::new(&mesh));
        assert_eq!(parts.len(), 3);
        assert_eq!(
            parts.iter().map(|p| p.faces.len()).collect::<Vec<_>>(),
            [6, 6, 5]
        );
        assert_eq!(
            parts.iter().map(|p| p.closed).collect::<Vec<_>>(),
            [true, true, false]
        );
        let v = volumes(&mesh, &parts, mesh.reference_point());
        assert!((v[0] - 1.0).abs() < 1e-12 && (v[1] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn boxes_touching_along_an_edge_stay_two_closed_shells() {
        let unit = Vector3::new(1.0, 1.0, 1.0);
        let mut b = shapes::cuboid(unit, Point3::origin());
        b.append(&shapes::cuboid(unit, Point3::new(1.0, 1.0, 0.0)));
        let (positions, remap) = crate::mesh::weld_exact(&b.positions);
        let faces: Vec<Vec<usize>> = b
            .faces
            .iter()
            .map(|f| f.iter().map(|&i| remap[i] as usize).collect())
            .collect();
        let mesh = PolyMesh::new(positions, &faces).expect("valid");
        let parts = split(&mesh, &EdgeTable::new(&mesh));
        assert_eq!(parts.len(), 2);
        assert!(parts.iter().all(|p| p.closed && p.faces.len() == 6));
    }
}
