//! The app's wording of massprops warnings: a short title, the effect on the mass, and what the
//! numbers on screen mean for this mesh and what the user can do about it in a modelling
//! program (the command line's wording, with its flags, is `cli::report::words`).

use massprops::{Defect, Warning};

/// A one-line title: "Duplicate faces (12)".
pub fn title(w: &Warning) -> String {
    let what = match &w.defect {
        Defect::DuplicateFaces => "Duplicate faces",
        Defect::OppositeDuplicateFaces => "Internal walls",
        Defect::OverlappingShells { .. } => "Overlapping parts",
        Defect::NestedShell { .. } => "Part inside a part",
        Defect::SelfOverlappingShell { .. } => "Part passing through itself",
        Defect::CracksClosed { .. } => "Cracks closed",
        Defect::HolesCapped { .. } => "Holes capped",
        Defect::NonplanarFaces { .. } => "Non-flat polygons",
        Defect::TwoCornerFaces { .. } => "Faces with two corners",
        Defect::StlTriangleCount { .. } => "Wrong triangle count in the file",
        Defect::UpAxisNotApplied { .. } => "The file's up axis",
        Defect::InconsistentWinding { .. } => "Faces pointing the wrong way",
        Defect::Flipped { whole: true, .. } => "Inside-out mesh",
        Defect::Flipped { .. } => "Inside-out parts",
        Defect::DegenerateFaces => "Faces without area",
        Defect::NonmanifoldEdges { .. } => "Parts touching along edges",
    };
    format!("{what} ({})", w.count)
}

/// The effect on the mass as a signed percentage ("+9.4 % mass"), what capped holes add ("caps
/// add 1.4 % mass"), or the uncertainty for non-flat polygons ("± 0.3 % mass"); `None` when it is
/// not known.
pub fn effect(w: &Warning) -> Option<String> {
    match w.defect {
        Defect::NonplanarFaces { uncertainty } => {
            return Some(format!("± {} mass", percent(uncertainty)));
        }
        // The caps' share reads more plainly than what the holes "remove".
        Defect::HolesCapped { .. } => {
            let added = -w.effect_on_mass?;
            let verb = if added >= 0.0 { "add" } else { "remove" };
            return Some(format!("caps {verb} {} mass", percent(added.abs())));
        }
        _ => {}
    }
    let e = w.effect_on_mass?;
    Some(if e == 0.0 {
        "no effect on mass".to_owned()
    } else {
        let sign = if e > 0.0 { "+" } else { "−" };
        format!("{sign}{} mass", percent(e.abs()))
    })
}

/// `x` (a fraction) as a percentage with two significant digits: "9.4 %", "0.0012 %", "1.2e-5 %".
fn percent(x: f64) -> String {
    let p = x * 100.0;
    if p == 0.0 || !p.is_finite() {
        return format!("{p} %");
    }
    let digits = (1.0 - p.abs().log10().floor()).max(0.0) as usize;
    if digits > 4 {
        format!("{p:.1e} %")
    } else {
        format!("{p:.digits$} %")
    }
}

/// The warning in full, as the side panel shows it under its title: no command-line flags;
/// faces count from 0, as in the rest of the app, and name their file line where there is one
/// (`lines[f]` is face f's).
pub fn warning_text(w: &Warning, lines: &[u32]) -> String {
    let faces = faces(&w.faces, lines);
    match &w.defect {
        Defect::DuplicateFaces => format!(
            "These faces repeat another face exactly ({faces}). Each is counted once here; \
             counted twice they would have added their volume again. Remove the duplicates in \
             your modelling program."
        ),
        Defect::OppositeDuplicateFaces => format!(
            "These faces are listed together with their own reverse ({faces}): walls between two \
             parts, which enclose nothing. They are left out, so the parts count as one solid."
        ),
        Defect::OverlappingShells {
            volume,
            uncertainty,
            compared,
            candidates,
            ..
        } => {
            let mut text = format!(
                "Closed parts overlap ({faces}): the volume they share, about {volume:.3e} ± \
                 {uncertainty:.1e} (mesh units cubed), is counted twice, so the mass shown is too \
                 high by that much. Join the parts (a boolean union) in your modelling program."
            );
            if compared < candidates {
                text.push_str(&format!(
                    " Only {compared} of {candidates} pairs of parts could be compared within the \
                     work allowed; others may overlap too."
                ));
            }
            text
        }
        Defect::SelfOverlappingShell {
            volume,
            uncertainty,
            total_effect,
            ..
        } => format!(
            "A closed part passes through itself ({faces}): the volume where it does, about \
             {volume:.3e} ± {uncertainty:.1e} (mesh units cubed), is counted twice, so the mass \
             shown is too high by that much ({} with any overlap between parts). Remove the \
             self-intersection (a boolean union of the part with itself) in your modelling \
             program.",
            percent(*total_effect)
        ),
        Defect::NestedShell { .. } => format!(
            "A closed part lies inside another and points outward ({faces}), so its volume counts \
             a second time. If it is meant as a hollow, reverse its faces in your modelling \
             program; if it is a separate part inside, remove it or give it its own density."
        ),
        Defect::CracksClosed { largest_gap } => format!(
            "Vertices that should be one were a hair apart (at most {largest_gap:.2e}, the \
             rounding of the file's numbers; {faces}). They were merged, which closes the mesh; \
             the numbers barely change."
        ),
        Defect::HolesCapped {
            cap_area_fraction, ..
        } => format!(
            "The mesh has holes ({faces}). Each was closed by a fan from its centre; the caps \
             are {} of the surface. The effect on the mass says how much the numbers depend on \
             how the holes are closed: close them in your modelling program if it is large.",
            percent(*cap_area_fraction)
        ),
        Defect::NonplanarFaces { .. } => format!(
            "Some polygons are not flat ({faces}); each is counted as if pressed flat onto its \
             best-fit plane, and splitting them into triangles another way would change the mass \
             by up to the amount shown. Triangulate the mesh in your modelling program for exact \
             numbers."
        ),
        Defect::TwoCornerFaces { lines } => format!(
            "The file has faces with fewer than three corners (line {}), which are lines, not \
             faces: they were skipped.",
            list(lines)
        ),
        Defect::StlTriangleCount { header, records } => format!(
            "The file's header says it holds {header} triangles, but {records} follow it: all \
             {records} were read. The program that wrote it left the count wrong; nothing needs \
             fixing here."
        ),
        Defect::UpAxisNotApplied { axis } => format!(
            "The file says {} is up. Its axes are used as they are, as robot tools (rviz, \
             MoveIt, Gazebo) use a robot's meshes, so the numbers are in the file's own axes.",
            axis.trim_end_matches("_UP")
        ),
        Defect::InconsistentWinding { face_pairs } => {
            let pairs: Vec<String> = face_pairs
                .iter()
                .map(|&(a, b)| format!("{} and {}", face(a, lines), face(b, lines)))
                .collect();
            if w.effect_on_mass.is_some() {
                return format!(
                    "Some faces pointed the wrong way (between {}): they were turned to agree \
                     with their neighbours, and the numbers are those of the mesh made \
                     consistent. Recalculate the normals in your modelling program to fix the \
                     file itself.",
                    pairs.join(", ")
                );
            }
            format!(
                "Some faces point the wrong way (between faces {}: one of each pair is \
                 flipped) and cannot all be made to agree (a one-sided surface); they count as \
                 negative volume, so the numbers are wrong. Recalculate the normals (make them \
                 consistent) in your modelling program.",
                pairs.join(", ")
            )
        }
        Defect::Flipped { whole: true, .. } => "All faces point inwards; the numbers shown are \
             those of the correctly oriented mesh, so nothing needs fixing for them here."
            .to_owned(),
        Defect::Flipped { .. } => format!(
            "Some separate parts point inwards ({faces}); they were turned outward (a part \
             cannot have negative mass). Flip their normals in your modelling program."
        ),
        Defect::DegenerateFaces => format!(
            "These faces have no area ({faces}); they change nothing, but often mark a \
             modelling mistake worth cleaning up."
        ),
        Defect::NonmanifoldEdges { .. } => format!(
            "Edges shared by more than two faces ({faces}): parts that touch there are each \
             counted in full, which is right when they only touch."
        ),
    }
}

/// "face 12 (line 40)" or "face 12".
fn face(f: usize, lines: &[u32]) -> String {
    format!("face {}", inertia_io::wording::face_line(f, lines))
}

/// "e.g. face 12 (line 40), face 13 (line 41)".
fn faces(list: &[usize], lines: &[u32]) -> String {
    if list.is_empty() {
        return "no face of the file".to_owned();
    }
    let named: Vec<String> = list.iter().map(|&f| face(f, lines)).collect();
    format!("e.g. {}", named.join(", "))
}

fn list(indices: &[usize]) -> String {
    inertia_io::wording::list(indices)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn warning(defect: Defect, faces: Vec<usize>, effect: Option<f64>) -> Warning {
        Warning {
            defect,
            count: faces.len().max(1),
            faces,
            effect_on_mass: effect,
        }
    }

    #[test]
    fn gui_wording_names_no_command_line_flag_and_says_what_to_do() {
        let all = [
            warning(Defect::DuplicateFaces, vec![6, 7], Some(1.0 / 3.0)),
            warning(Defect::OppositeDuplicateFaces, vec![1, 8], Some(0.0)),
            warning(
                Defect::OverlappingShells {
                    pairs: vec![(0, 1)],
                    volume: 2.0,
                    uncertainty: 0.01,
                    compared: 1,
                    candidates: 3,
                    uncompared_bound: 0.5,
                },
                vec![0, 6],
                Some(0.17),
            ),
            warning(
                Defect::NestedShell { shells: vec![1] },
                vec![6],
                Some(0.036),
            ),
            warning(
                Defect::CracksClosed { largest_gap: 1e-8 },
                vec![1],
                Some(1e-9),
            ),
            warning(
                Defect::HolesCapped {
                    boundary_edges: 4,
                    cap_area_fraction: 0.2,
                },
                vec![1, 2],
                Some(-1.0 / 6.0),
            ),
            warning(
                Defect::NonplanarFaces { uncertainty: 0.003 },
                vec![1, 2, 5],
                None,
            ),
            warning(
                Defect::TwoCornerFaces { lines: vec![11] },
                vec![],
                Some(0.0),
            ),
            warning(
                Defect::InconsistentWinding {
                    face_pairs: vec![(0, 5)],
                },
                vec![0, 5],
                None,
            ),
            warning(
                Defect::Flipped {
                    shells: vec![1],
                    whole: false,
                },
                vec![6],
                Some(-1.0),
            ),
            warning(Defect::DegenerateFaces, vec![12, 13], Some(0.0)),
            warning(
                Defect::NonmanifoldEdges {
                    edges: vec![((3, 7), vec![1, 4, 9])],
                },
                vec![1, 4, 9],
                Some(0.0),
            ),
        ];
        let lines: Vec<u32> = (10..30).collect();
        for w in &all {
            let text = warning_text(w, &lines);
            assert!(!text.contains("--"), "{text}");
            assert!(!title(w).contains(w.code()), "{}", title(w));
        }
        assert_eq!(title(&all[0]), "Duplicate faces (2)");
        assert_eq!(effect(&all[0]).as_deref(), Some("+33 % mass"));
        assert_eq!(effect(&all[5]).as_deref(), Some("caps add 17 % mass"));
        assert_eq!(effect(&all[4]).as_deref(), Some("+1.0e-7 % mass"));
        assert_eq!(effect(&all[6]).as_deref(), Some("± 0.30 % mass"));
        assert_eq!(effect(&all[8]), None);
        assert_eq!(effect(&all[1]).as_deref(), Some("no effect on mass"));
        let duplicates = warning_text(&all[0], &lines);
        assert!(
            duplicates.contains("face 6 (line 16), face 7 (line 17)"),
            "{duplicates}"
        );
        assert!(warning_text(&all[0], &[]).contains("e.g. face 6, face 7"));
        assert!(warning_text(&all[2], &lines).contains("Only 1 of 3 pairs"));
        assert!(warning_text(&all[7], &lines).contains("line 11"));
    }
}
