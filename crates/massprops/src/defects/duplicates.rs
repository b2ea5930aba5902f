//! Duplicate faces: the same vertex cycle listed more than once (CAD exports, merged scans).
//!
//! Listed twice with the same winding, a face is counted twice: the extra copies are removed.
//! Listed with its reverse, it is an internal wall between two solids (or both sides of a sheet)
//! and adds no volume: for the volume the pair goes, which also joins the solids it separated;
//! for a thin shell one copy stays. A duplicate shares every edge with its twin, so only faces on
//! non-manifold edges, and shells of two faces, can be duplicates: the rest are not looked at.

use nalgebra::{Point3, Vector3};

use super::shells::Part;
use super::{Builder, Cleaned, face_volume, input_faces};
use crate::diagnostics::face_shape;
use crate::integrals::mirtich::newell_normal;
use crate::warning::{Defect, Warning};

/// Removes duplicates; returns whether any face was removed.
pub(super) fn remove(
    work: &mut Cleaned<'_>,
    parts: &[Part],
    reference: Point3<f64>,
    uses_volume: bool,
) -> bool {
    let mesh = &work.mesh;
    let mut candidates: Vec<u32> = work
        .table
        .groups()
        .filter(|g| g.len() > 2)
        .flat_map(|g| g.iter().map(|s| s.face))
        .chain(
            parts
                .iter()
                .filter(|p| p.faces.len() == 2)
                .flat_map(|p| p.faces.iter().copied()),
        )
        .collect();
    if candidates.is_empty() {
        return false;
    }
    candidates.sort_unstable();
    candidates.dedup();
    // A face of no area is degenerate (reported as such, adding nothing): several of them on
    // the same vertices are not copies of a face.
    let mut corners = Vec::new();
    candidates.retain(|&f| !face_shape(mesh, f as usize, &mut corners).1);
    let mut keyed: Vec<(Vec<u32>, bool, u32)> = candidates
        .iter()
        .map(|&f| {
            let (key, forward) = canonical(mesh.face(f as usize));
            (key, forward, f)
        })
        .collect();
    keyed.sort_unstable();
    let mut drop = vec![false; mesh.face_count()];
    let (mut same, mut opposite) = (Vec::new(), Vec::new());
    for group in keyed.chunk_by(|a, b| a.0 == b.0) {
        if group.len() < 2 {
            continue;
        }
        let forward: Vec<u32> = group.iter().filter(|g| g.1).map(|g| g.2).collect();
        let backward: Vec<u32> = group.iter().filter(|g| !g.1).map(|g| g.2).collect();
        let pairs = forward.len().min(backward.len());
        let (major, minor) = if forward.len() >= backward.len() {
            (&forward, &backward)
        } else {
            (&backward, &forward)
        };
        if uses_volume {
            // The pairs cancel; of the rest, one copy stays.
            opposite.extend_from_slice(&major[..pairs]);
            opposite.extend_from_slice(&minor[..pairs]);
            if major.len() > pairs {
                same.extend_from_slice(&major[pairs + 1..]);
            }
        } else {
            // A thin wall: one copy of the surface stays, whatever its winding.
            same.extend_from_slice(&major[1..]);
            opposite.extend_from_slice(minor);
        }
    }
    if same.is_empty() && opposite.is_empty() {
        return false;
    }
    let measure = |f: u32| {
        if uses_volume {
            face_volume(mesh, f as usize, reference)
        } else {
            let corners: Vec<Vector3<f64>> =
                mesh.face_points(f as usize).map(|p| p.coords).collect();
            0.5 * newell_normal(&corners).norm()
        }
    };
    let mut warnings = Vec::new();
    for (faces, defect) in [
        (&mut same, Defect::DuplicateFaces),
        (&mut opposite, Defect::OppositeDuplicateFaces),
    ] {
        if faces.is_empty() {
            continue;
        }
        faces.sort_unstable();
        for &f in faces.iter() {
            drop[f as usize] = true;
        }
        warnings.push(Warning {
            defect,
            count: faces.len(),
            faces: input_faces(work.origin.as_deref(), faces.iter().copied()),
            effect_on_mass: Some(faces.iter().map(|&f| measure(f)).sum()),
        });
    }
    let mut builder = Builder::with_capacity(mesh);
    for (f, face) in mesh.faces().enumerate() {
        if !drop[f] {
            builder.push(face, f as u32);
        }
    }
    if builder.is_empty() {
        // Nothing but cancelling pairs: there is no surface to keep, and the zero-volume
        // error that follows says so better than an empty mesh would.
        return false;
    }
    let positions = mesh.positions().to_vec();
    if builder.finish_into(work, positions).is_err() {
        return false;
    }
    work.warnings.extend(warnings);
    true
}

/// The cycle rotated to start at its smallest vertex, in whichever direction gives the smaller
/// sequence, and whether that is the face's own direction.
fn canonical(face: &[u32]) -> (Vec<u32>, bool) {
    let n = face.len();
    let start = (0..n).min_by_key(|&i| face[i]).unwrap_or(0);
    let forward: Vec<u32> = (0..n).map(|k| face[(start + k) % n]).collect();
    let backward: Vec<u32> = (0..n).map(|k| face[(start + n - k) % n]).collect();
    if forward <= backward {
        (forward, true)
    } else {
        (backward, false)
    }
}

#[cfg(test)]
mod tests {
    use super::canonical;

    #[test]
    fn a_cycle_and_its_rotations_share_a_key_and_its_reverse_is_told_apart() {
        let (k, f) = canonical(&[5, 2, 9]);
        assert_eq!((k.clone(), f), (vec![2, 5, 9], false));
        assert_eq!(canonical(&[9, 5, 2]), (k.clone(), false));
        assert_eq!(canonical(&[2, 5, 9]), (k, true));
    }
}
