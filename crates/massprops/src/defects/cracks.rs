//! Cracks: an exporter that writes float32 (or rounds to a few decimals) can leave two vertices
//! that should be one a hair apart, so the edges on either side of the seam are each used once
//! and the mesh looks open. Only vertices on such boundary edges are considered, and those
//! within the tolerance of each other are merged (found through a hash grid of cells the size of
//! the tolerance, so each vertex looks at 27 cells).

use std::collections::HashMap;

use nalgebra::Point3;

use super::{Builder, Cleaned, UnionFind, face_volume, input_faces};
use crate::MeshError;
use crate::warning::{Defect, Warning};

/// Merges boundary vertices within `tolerance` and reports what that closed.
pub(super) fn close(
    work: &mut Cleaned<'_>,
    tolerance: f64,
    reference: Point3<f64>,
) -> Result<(), MeshError> {
    let open_before = work.table.groups().filter(|g| g.len() == 1).count();
    if open_before == 0 || tolerance <= 0.0 {
        return Ok(());
    }
    let mesh = &work.mesh;
    let positions = mesh.positions();
    let mut boundary: Vec<u32> = work
        .table
        .groups()
        .filter(|g| g.len() == 1)
        .flat_map(|g| [g[0].lo, g[0].hi])
        .collect();
    boundary.sort_unstable();
    boundary.dedup();
    // Float-to-integer casts saturate, so far-out coordinates share edge cells and are still
    // compared by distance below.
    let cell = |p: &Point3<f64>| p.coords.map(|c| (c / tolerance).floor() as i64);
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::with_capacity(boundary.len());
    for &v in &boundary {
        let c = cell(&positions[v as usize]);
        grid.entry([c.x, c.y, c.z]).or_default().push(v);
    }
    let mut sets = UnionFind::new(positions.len());
    let mut merged_any = false;
    for &v in &boundary {
        let p = positions[v as usize];
        let c = cell(&p);
        for dx in -1..=1i64 {
            for dy in -1..=1i64 {
                for dz in -1..=1i64 {
                    let key = [
                        c.x.saturating_add(dx),
                        c.y.saturating_add(dy),
                        c.z.saturating_add(dz),
                    ];
                    for &u in grid.get(&key).into_iter().flatten() {
                        if u > v && (positions[u as usize] - p).norm() <= tolerance {
                            sets.union(u, v);
                            merged_any = true;
                        }
                    }
                }
            }
        }
    }
    if !merged_any {
        return Ok(());
    }
    let mut largest_gap: f64 = 0.0;
    for &v in &boundary {
        let root = sets.find(v);
        largest_gap = largest_gap.max((positions[v as usize] - positions[root as usize]).norm());
    }
    let mut builder = Builder::with_capacity(mesh);
    let mut changed = Vec::new();
    let mut effect = 0.0;
    let mut face = Vec::new();
    for (f, old) in mesh.faces().enumerate() {
        face.clear();
        for &i in old {
            let j = sets.find(i);
            if face.last() != Some(&j) {
                face.push(j);
            }
        }
        while face.len() > 1 && face.first() == face.last() {
            face.pop();
        }
        if face.as_slice() == old {
            builder.push(old, f as u32);
            continue;
        }
        changed.push(f as u32);
        // The file as written minus the welded mesh, as for every repair.
        effect += face_volume(mesh, f, reference);
        if face.len() >= 3 {
            builder.push(&face, f as u32);
            effect -= face_of(&face, positions, reference);
        }
    }
    let faces = input_faces(work.origin.as_deref(), changed.iter().copied());
    if builder.is_empty() {
        let (lo, hi) = work.mesh.bounding_box();
        return Err(MeshError::ZeroVolume {
            volume: 0.0,
            diagonal: (hi - lo).norm(),
            cause: format!(
                "closing its cracks (merging open-edge vertices up to {tolerance:e} apart) \
                 collapses every face: the weld distance is larger than the mesh's details"
            ),
        });
    }
    let positions = positions.to_vec();
    builder.finish_into(work, positions)?;
    let open_after = work.table.groups().filter(|g| g.len() == 1).count();
    work.warnings.push(Warning {
        defect: Defect::CracksClosed { largest_gap },
        count: open_before.saturating_sub(open_after),
        faces,
        effect_on_mass: Some(effect),
    });
    Ok(())
}

/// [`face_volume`] of a face not (yet) in a mesh.
fn face_of(face: &[u32], positions: &[Point3<f64>], reference: Point3<f64>) -> f64 {
    super::fan_volume(face, 0, |i| positions[i as usize] - reference)
}
