//! Shells: the connected pieces of a surface, faces joined across manifold edges.
//!
//! An edge used by exactly two faces joins them; an edge used by three or more (two parts that
//! touch along it) joins nothing, so touching parts stay separate shells. A shell is closed when
//! each of its edges is used as often in one direction as in the other by its own faces.

use nalgebra::{Point3, Vector3};

use super::AUTO_WELD_RATIO;
use super::overlap::Relations;
use super::{CAP, Cleaned, UnionFind, face_volume};
use crate::PolyMesh;
use crate::edges::EdgeTable;
use crate::solid::ZERO_VOLUME_RATIO;

/// Whether a closed shell's faces point away from what it encloses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Orientation {
    /// Counter-clockwise seen from outside: positive signed volume.
    Outward,
    /// Clockwise seen from outside: negative signed volume (a cavity, inside another shell).
    Inward,
}

/// One connected piece of the mesh, as found in the file.
#[derive(Debug, Clone, PartialEq)]
pub struct Shell {
    /// Faces of the file in this shell (duplicates removed, caps not counted).
    pub faces: usize,
    /// Closed in the file (after closing cracks); an open shell's holes were capped.
    pub closed: bool,
    /// Signed volume as wound in the file (of the capped shell when it was open).
    pub volume: f64,
    /// The sign of `volume`.
    pub orientation: Orientation,
    /// How many closed shells enclose this one (0: an outer surface; 1: a cavity's wall or a
    /// part inside one); `None` when not known (the comparison's time budget ran out, or the
    /// numbers do not use the volume).
    pub depth: Option<usize>,
}

/// A shell of the working mesh: its faces (ascending) and whether it is closed.
pub(crate) struct Part {
    pub faces: Vec<u32>,
    pub closed: bool,
    /// Edges used by one face only (of this shell): what caps can close.
    pub open_sides: usize,
    /// An edge that several faces share is used more often one way than the other by this
    /// shell's faces: open in a way caps do not close.
    pub unbalanced: bool,
}

/// Splits the working mesh into shells, ordered by their first face.
pub(crate) fn split(mesh: &PolyMesh, table: &EdgeTable) -> Vec<Part> {
    let n = mesh.face_count();
    let mut sets = UnionFind::new(n);
    for group in table.groups() {
        if group.len() == 2 {
            sets.union(group[0].face, group[1].face);
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
                open_sides: 0,
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
                parts[s].open_sides += 1;
            }
            2 => {}
            _ => {
                // Each shell meeting here must use the edge as often each way.
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
                    if b != 0 {
                        parts[s].closed = false;
                        parts[s].unbalanced = true;
                    }
                }
            }
        }
    }
    parts
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

/// The public description of each shell.
pub(crate) fn describe(
    work: &Cleaned<'_>,
    parts: &[Part],
    volumes: &[f64],
    relations: &Relations,
) -> Vec<Shell> {
    let from_file = |f: u32| work.origin.as_ref().is_none_or(|o| o[f as usize] != CAP);
    parts
        .iter()
        .zip(volumes)
        .enumerate()
        .map(|(s, (part, &volume))| {
            let faces = part.faces.iter().filter(|&&f| from_file(f)).count();
            Shell {
                faces,
                closed: part.closed && faces == part.faces.len(),
                volume,
                orientation: if volume < 0.0 {
                    Orientation::Inward
                } else {
                    Orientation::Outward
                },
                depth: relations.depth(s),
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
        let (positions, remap) = crate::weld_exact(&b.positions);
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
