//! Faces wound against their neighbours: on each shell, faces are turned to agree with the
//! faces they share an edge with (breadth-first across edges two faces share, as a manifold
//! surface's orientation propagates), the shell's minority turned, so that a mesh with a few
//! flipped faces integrates as the surface it is instead of counting those faces as negative
//! volume. Which way the whole shell then faces is decided afterwards, as for any shell
//! (`orient`). A shell whose faces cannot all agree (a Möbius band) is left as it is.

use std::collections::VecDeque;

use nalgebra::Point3;

use super::shells::Part;
use super::{Builder, Cleaned, face_volume, input_faces};
use crate::analysis::{Defect, Warning};
use crate::diagnostics::EXAMPLES;

/// Turns the faces that disagree with their shell; returns whether any was turned.
pub(super) fn reorient(work: &mut Cleaned<'_>, parts: &[Part], reference: Point3<f64>) -> bool {
    let mesh = &work.mesh;
    let n = mesh.face_count();
    // Each face's neighbours across edges exactly two faces share, and whether the two run the
    // edge the same way (then one of them is turned).
    let mut neighbours: Vec<Vec<(u32, bool)>> = vec![Vec::new(); n];
    let mut disagreeing = Vec::new();
    for group in work.table.groups() {
        if let [a, b] = group
            && a.face != b.face
        {
            let same = a.forward == b.forward;
            neighbours[a.face as usize].push((b.face, same));
            neighbours[b.face as usize].push((a.face, same));
            if same && disagreeing.len() < EXAMPLES {
                disagreeing.push((a.face.min(b.face), a.face.max(b.face)));
            }
        }
    }
    if disagreeing.is_empty() {
        return false;
    }
    let mut turn = vec![false; n];
    let mut flip_of: Vec<Option<bool>> = vec![None; n];
    let mut queue = VecDeque::new();
    for part in parts {
        let Some(&first) = part.faces.first() else {
            continue;
        };
        let mut label: Vec<(u32, bool)> = Vec::with_capacity(part.faces.len());
        let mut consistent = true;
        flip_of[first as usize] = Some(false);
        queue.push_back(first);
        while let Some(f) = queue.pop_front() {
            let flip = flip_of[f as usize].unwrap_or(false);
            label.push((f, flip));
            for &(g, same) in &neighbours[f as usize] {
                // Running the edge the same way, they disagree: one of the two is turned.
                let wanted = flip ^ same;
                match flip_of[g as usize] {
                    Some(had) => consistent &= had == wanted,
                    None => {
                        flip_of[g as usize] = Some(wanted);
                        queue.push_back(g);
                    }
                }
            }
        }
        if !consistent {
            continue;
        }
        // The minority is what was flipped in the file.
        let flipped = label.iter().filter(|(_, flip)| *flip).count();
        let minority = flipped * 2 <= label.len();
        for (f, flip) in label {
            turn[f as usize] = flip == minority;
        }
    }
    let turned: Vec<u32> = (0..n as u32).filter(|&f| turn[f as usize]).collect();
    if turned.is_empty() {
        return false;
    }
    // The file taken literally minus the repaired mesh: a turned face's cone counts with the
    // opposite sign.
    let effect: f64 = turned
        .iter()
        .map(|&f| 2.0 * face_volume(mesh, f as usize, reference))
        .sum();
    let origin = work.origin.clone();
    let pairs: Vec<(usize, usize)> = disagreeing
        .iter()
        .map(|&(a, b)| {
            let to_input = |f: u32| origin.as_deref().map_or(f, |o| o[f as usize]) as usize;
            (to_input(a), to_input(b))
        })
        .collect();
    let mut builder = Builder::with_capacity(mesh);
    let mut reversed = Vec::new();
    for (f, face) in mesh.faces().enumerate() {
        if turn[f] {
            reversed.clear();
            reversed.extend(face.iter().rev());
            builder.push(&reversed, f as u32);
        } else {
            builder.push(face, f as u32);
        }
    }
    let positions = mesh.positions().to_vec();
    if builder.finish_into(work, positions).is_err() {
        return false;
    }
    work.warnings.push(Warning {
        defect: Defect::InconsistentWinding { face_pairs: pairs },
        count: turned.len(),
        faces: input_faces(origin.as_deref(), turned.iter().copied()),
        effect_on_mass: Some(effect),
    });
    true
}
