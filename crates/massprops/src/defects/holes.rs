//! Holes: each shell's open sides (an edge only one of its faces uses: a hole's rim, or the rim
//! of a wall that another shell owns) are chained into loops, each loop is closed by a fan
//! of triangles from the centroid of its corners, wound against the loop so that the cap's
//! edges pair with the boundary's. The result is the volume of the capped solid; how much the
//! caps carry (area and volume) says whether the holes matter.

use std::collections::HashMap;

use nalgebra::{Point3, Vector3};

use super::shells::Part;
use super::{Builder, CAP, Cleaned, fan_volume, input_faces};
use crate::MeshError;
use crate::defects::Holes;
use crate::warning::{Defect, Warning};

/// Caps every boundary loop (or refuses, per `holes`).
/// `surface` is the file's surface area, which the caps' area is given as a fraction of. Each
/// cap joins the shell of its hole's first face, which is closed once all its holes are.
pub(super) fn cap(
    work: &mut Cleaned<'_>,
    parts: &mut [Part],
    holes: Holes,
    reference: Point3<f64>,
    surface: f64,
) -> Result<(), MeshError> {
    let sides: Vec<((u32, u32), u32)> = parts
        .iter()
        .flat_map(|p| p.boundary.iter().copied())
        .collect();
    if sides.is_empty() {
        return Ok(());
    }
    let loops = chain(&sides);
    let around = input_faces(work.origin.as_deref(), sides.iter().map(|s| s.1));
    if holes == Holes::Refuse {
        return Err(MeshError::OpenMesh {
            boundary_edges: sides.len(),
            loops: loops.len(),
            faces: around,
        });
    }
    if loops.is_empty() {
        return Ok(());
    }
    let mesh = &work.mesh;
    let mut positions = mesh.positions().to_vec();
    let mut builder = Builder::with_capacity(mesh);
    for (f, face) in mesh.faces().enumerate() {
        builder.push(face, f as u32);
    }
    let mut shell_of = vec![0usize; mesh.face_count()];
    for (s, part) in parts.iter().enumerate() {
        for &f in &part.faces {
            shell_of[f as usize] = s;
        }
    }
    let mut capped_sides = vec![0usize; parts.len()];
    let mut next_face = mesh.face_count() as u32;
    let (mut cap_area, mut cap_volume) = (0.0, 0.0);
    for hole in &loops {
        let shell = shell_of[sides[hole[0]].1 as usize];
        capped_sides[shell] += hole.len();
        let corners = hole
            .iter()
            .map(|&s| positions[sides[s].0.0 as usize].coords);
        let centroid = Point3::from(corners.sum::<Vector3<f64>>() / hole.len() as f64);
        let c = positions.len() as u32;
        positions.push(centroid);
        for &s in hole {
            let (from, to) = sides[s].0;
            let triangle = [to, from, c];
            let at = |i: u32| positions[i as usize] - reference;
            cap_volume += fan_volume(&triangle, 0, at);
            let (a, b, c) = (at(triangle[0]), at(triangle[1]), at(triangle[2]));
            cap_area += 0.5 * (b - a).cross(&(c - a)).norm();
            builder.push(&triangle, CAP);
            parts[shell].faces.push(next_face);
            next_face += 1;
        }
    }
    for (part, capped) in parts.iter_mut().zip(capped_sides) {
        if capped > 0 && !part.unbalanced && capped == part.boundary.len() {
            part.closed = true;
        }
    }
    let boundary_edges: usize = loops.iter().map(Vec::len).sum();
    let faces = input_faces(
        work.origin.as_deref(),
        loops.iter().flatten().map(|&s| sides[s].1),
    );
    builder.finish_keeping_edges(work, positions)?;
    work.warnings.push(Warning {
        defect: Defect::HolesCapped {
            boundary_edges,
            cap_area_fraction: if surface > 0.0 {
                cap_area / surface
            } else {
                0.0
            },
        },
        count: loops.len(),
        faces,
        // The file's surface lacks what the caps hold.
        effect_on_mass: Some(-cap_volume),
    });
    Ok(())
}

/// Chains directed boundary sides (from, to) into closed loops, each a list of indices into
/// `sides` in order. Where several loops touch at a vertex any continuation is taken; a chain
/// that cannot close (sides left by inconsistent winding) is dropped.
fn chain(sides: &[((u32, u32), u32)]) -> Vec<Vec<usize>> {
    let mut leaving: HashMap<u32, Vec<usize>> = HashMap::with_capacity(sides.len());
    for (s, &((from, _), _)) in sides.iter().enumerate() {
        leaving.entry(from).or_default().push(s);
    }
    let mut used = vec![false; sides.len()];
    let mut loops = Vec::new();
    for start in 0..sides.len() {
        if used[start] {
            continue;
        }
        used[start] = true;
        let begin = sides[start].0.0;
        let mut hole = vec![start];
        let mut at = sides[start].0.1;
        let closed = loop {
            if at == begin {
                break true;
            }
            let next = leaving
                .get(&at)
                .and_then(|out| out.iter().copied().find(|&s| !used[s]));
            let Some(next) = next else { break false };
            used[next] = true;
            hole.push(next);
            at = sides[next].0.1;
        };
        if closed && hole.len() >= 3 {
            loops.push(hole);
        }
    }
    loops
}

#[cfg(test)]
mod tests {
    use super::chain;

    #[test]
    fn two_triangular_holes_sharing_a_vertex_make_two_loops() {
        let sides = [
            ((0, 1), 0),
            ((1, 2), 0),
            ((2, 0), 0),
            ((0, 3), 1),
            ((3, 4), 1),
            ((4, 0), 1),
        ];
        let mut loops = chain(&sides);
        loops.iter_mut().for_each(|l| l.sort_unstable());
        loops.sort();
        assert!(loops.iter().all(|l| l.len() == 3), "{loops:?}");
        assert_eq!(loops.iter().map(Vec::len).sum::<usize>(), 6);
    }
}
