//! The app's wording of massprops warnings: a short title, the effect on the mass, and what the
//! numbers on screen mean for this mesh and what the user can do about it in a modelling
//! program (the command line's wording, with its flags, is `cli::report::words`).

use massprops::{Defect, Warning};

use crate::i18n::{localize, sci, tr};

/// A one-line title: "Duplicate faces (12)".
pub fn title(w: &Warning) -> String {
    let what = match &w.defect {
        Defect::DuplicateFaces => tr!("warnings-duplicate-faces"),
        Defect::OppositeDuplicateFaces => tr!("warnings-internal-walls"),
        Defect::OverlappingShells { .. } => tr!("warnings-overlapping-parts"),
        Defect::NestedShell { .. } => tr!("warnings-nested-part"),
        Defect::SelfOverlappingShell { .. } => tr!("warnings-self-overlapping-part"),
        Defect::CracksClosed { .. } => tr!("warnings-cracks-closed"),
        Defect::HolesCapped { .. } => tr!("warnings-holes-capped"),
        Defect::NonplanarFaces { .. } => tr!("warnings-nonplanar-faces"),
        Defect::TwoCornerFaces { .. } => tr!("warnings-two-corner-faces"),
        Defect::StlTriangleCount { .. } => tr!("warnings-stl-triangle-count"),
        Defect::UpAxisNotApplied { .. } => tr!("warnings-up-axis"),
        Defect::InconsistentWinding { .. } => tr!("warnings-inconsistent-winding"),
        Defect::Flipped { whole: true, .. } => tr!("warnings-inside-out-mesh"),
        Defect::Flipped { .. } => tr!("warnings-inside-out-parts"),
        Defect::DegenerateFaces => tr!("warnings-degenerate-faces"),
        Defect::NonmanifoldEdges { .. } => tr!("warnings-nonmanifold-edges"),
    };
    format!("{what} ({})", w.count)
}

/// The effect on the mass as a signed percentage ("+9.4 % mass"), what capped holes add ("caps
/// add 1.4 % mass"), or the uncertainty for non-flat polygons ("± 0.3 % mass"); `None` when it is
/// not known.
pub fn effect(w: &Warning) -> Option<String> {
    match w.defect {
        Defect::NonplanarFaces { uncertainty } => {
            return Some(tr!(
                "warnings-effect-uncertainty",
                percent = percent(uncertainty)
            ));
        }
        // The caps' share reads more plainly than what the holes "remove".
        Defect::HolesCapped { .. } => {
            let added = -w.effect_on_mass?;
            let share = percent(added.abs());
            return Some(if added >= 0.0 {
                tr!("warnings-effect-caps-add", percent = share)
            } else {
                tr!("warnings-effect-caps-remove", percent = share)
            });
        }
        _ => {}
    }
    let e = w.effect_on_mass?;
    Some(if e == 0.0 {
        tr!("warnings-effect-none")
    } else if e > 0.0 {
        tr!("warnings-effect-more", percent = percent(e))
    } else {
        tr!("warnings-effect-less", percent = percent(e.abs()))
    })
}

/// `x` (a fraction) as a percentage with two significant digits: "9.4 %", "0.0012 %", "1.2e-5 %",
/// with the language's decimal separator.
fn percent(x: f64) -> String {
    let p = x * 100.0;
    if p == 0.0 || !p.is_finite() {
        return localize(format!("{p} %"));
    }
    let digits = (1.0 - p.abs().log10().floor()).max(0.0) as usize;
    localize(if digits > 4 {
        format!("{p:.1e} %")
    } else {
        format!("{p:.digits$} %")
    })
}

/// A whole number of the library's (a file's triangle count) as a message's count.
fn count(n: u64) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

/// The warning in full, as the side panel shows it under its title: no command-line flags;
/// faces count from 0, as in the rest of the app, and name their file line where there is one
/// (`lines[f]` is face f's).
pub fn warning_text(w: &Warning, lines: &[u32]) -> String {
    let faces = faces(&w.faces, lines);
    match &w.defect {
        Defect::DuplicateFaces => tr!("warnings-duplicate-faces-text", faces = faces),
        Defect::OppositeDuplicateFaces => tr!("warnings-internal-walls-text", faces = faces),
        Defect::OverlappingShells {
            volume,
            uncertainty,
            compared,
            candidates,
            ..
        } => {
            let mut text = tr!(
                "warnings-overlapping-parts-text",
                faces = faces,
                volume = sci(*volume, 3),
                uncertainty = sci(*uncertainty, 1),
            );
            if compared < candidates {
                text.push(' ');
                text.push_str(&tr!(
                    "warnings-overlapping-parts-uncompared",
                    compared = *compared,
                    candidates = *candidates,
                ));
            }
            text
        }
        Defect::SelfOverlappingShell {
            volume,
            uncertainty,
            total_effect,
            ..
        } => tr!(
            "warnings-self-overlapping-part-text",
            faces = faces,
            volume = sci(*volume, 3),
            uncertainty = sci(*uncertainty, 1),
            total = percent(*total_effect),
        ),
        Defect::NestedShell { .. } => tr!("warnings-nested-part-text", faces = faces),
        Defect::CracksClosed { largest_gap } => tr!(
            "warnings-cracks-closed-text",
            gap = sci(*largest_gap, 2),
            faces = faces,
        ),
        Defect::HolesCapped {
            cap_area_fraction, ..
        } => tr!(
            "warnings-holes-capped-text",
            faces = faces,
            share = percent(*cap_area_fraction),
        ),
        Defect::NonplanarFaces { .. } => tr!("warnings-nonplanar-faces-text", faces = faces),
        Defect::TwoCornerFaces { lines } => {
            tr!("warnings-two-corner-faces-text", lines = list(lines))
        }
        Defect::StlTriangleCount { header, records } => tr!(
            "warnings-stl-triangle-count-text",
            header = count(*header),
            records = count(*records),
        ),
        Defect::UpAxisNotApplied { axis } => {
            tr!("warnings-up-axis-text", axis = axis.trim_end_matches("_UP"),)
        }
        Defect::InconsistentWinding { face_pairs } => {
            let pairs: Vec<String> = face_pairs
                .iter()
                .map(|&(a, b)| tr!("warnings-face-pair", a = face(a, lines), b = face(b, lines)))
                .collect();
            if w.effect_on_mass.is_some() {
                return tr!("warnings-winding-fixed-text", pairs = pairs.join(", "));
            }
            tr!("warnings-winding-text", pairs = pairs.join(", "))
        }
        Defect::Flipped { whole: true, .. } => tr!("warnings-inside-out-mesh-text"),
        Defect::Flipped { .. } => tr!("warnings-inside-out-parts-text", faces = faces),
        Defect::DegenerateFaces => tr!("warnings-degenerate-faces-text", faces = faces),
        Defect::NonmanifoldEdges { .. } => tr!("warnings-nonmanifold-edges-text", faces = faces),
    }
}

/// "face 12 (line 40)" or "face 12" (the app's own wording of `inertia_io::wording::face_line`,
/// which is the command line's English).
fn face(f: usize, lines: &[u32]) -> String {
    match lines.get(f) {
        Some(&line) => tr!("warnings-face-line", face = f, line = line),
        None => tr!("warnings-face", face = f),
    }
}

/// "e.g. face 12 (line 40), face 13 (line 41)".
fn faces(list: &[usize], lines: &[u32]) -> String {
    if list.is_empty() {
        return tr!("warnings-no-face");
    }
    let named: Vec<String> = list.iter().map(|&f| face(f, lines)).collect();
    tr!("warnings-example-faces", faces = named.join(", "))
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
