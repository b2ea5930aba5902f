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
use crate::diagnostics::EXAMPLES;
use crate::warning::{Defect, Warning};

/// Turns the faces that disagree with their shell; returns whether any was turned.
pub(super) fn reorient(work: &mut Cleaned<'_>, parts: &[Part], reference: Point3<f64>) -> bool {
    let mesh = &work.mesh;
    let n = mesh.face_count();
    // Edges exactly two faces share: the pair, and whether the two run the edge the same way
    // (then one of them is turned).
    let shared = || {
        work.table.groups().filter_map(|group| match group {
            [a, b] if a.face != b.face => Some((a.face, b.face, a.forward == b.forward)),
            _ => None,
        })
    };
    // Most meshes agree everywhere: one pass over the edges says so, before anything is built.
    let disagreeing: Vec<(u32, u32)> = shared()
        .filter(|&(_, _, same)| same)
        .take(EXAMPLES)
        .map(|(a, b, _)| (a.min(b), a.max(b)))
        .collect();
    if disagreeing.is_empty() {
        return false;
    }
    // Each face's neighbours, as one array cut at `starts` (a counting sort by face).
    let mut starts = vec![0u32; n + 1];
    for (a, b, _) in shared() {
        starts[a as usize + 1] += 1;
        starts[b as usize + 1] += 1;
    }
    for f in 0..n {
        starts[f + 1] += starts[f];
    }
    let mut next = starts.clone();
    let mut adjacent = vec![(0u32, false); starts[n] as usize];
    for (a, b, same) in shared() {
        for (from, to) in [(a, b), (b, a)] {
            adjacent[next[from as usize] as usize] = (to, same);
            next[from as usize] += 1;
        }
    }
    let neighbours =
        |f: u32| &adjacent[starts[f as usize] as usize..starts[f as usize + 1] as usize];
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
            for &(g, same) in neighbours(f) {
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
