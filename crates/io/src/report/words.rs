//! massprops' warnings in the command line's words: what each defect is, where (faces and their
//! file lines), and its effect on the mass, with the flags that change how it is handled.

use std::fmt::Write as _;

use massprops::{Defect, Warning};

use super::significant;

/// The command line's wording of a massprops warning. Faces count from 0, as everywhere; where
/// the file has lines (`lines[f]` is face f's), each example face names its line too.
pub fn warning_text(w: &Warning, lines: &[u32]) -> String {
    let faces = faces_text(&w.faces, lines);
    let effect = w.effect_on_mass.map(percent).unwrap_or_default();
    let count = w.count;
    match &w.defect {
        Defect::DuplicateFaces => format!(
            "{count} duplicate face(s) (the same corners, wound the same way, as another face; \
             {faces}): each is counted once; counted twice they would have added {effect} to \
             the mass"
        ),
        Defect::OppositeDuplicateFaces => format!(
            "{count} face(s) listed together with their reverse (internal walls; {faces}): they \
             enclose nothing, so a solid leaves both out and a thin shell keeps one copy"
        ),
        Defect::OverlappingShells {
            pairs,
            volume,
            uncertainty,
            compared,
            candidates,
            uncompared_bound,
        } => {
            let mut text = if pairs.is_empty() {
                String::from("no overlapping closed shells were found")
            } else {
                let u = w
                    .effect_on_mass
                    .filter(|&e| e != 0.0)
                    .map(|e| percent((e * uncertainty / volume).abs()).replace('+', ""))
                    .unwrap_or_default();
                format!(
                    "{count} pair(s) of closed shells overlap (shells {}; {faces}): their common \
                     volume, {} ± {} (mesh units cubed; ± one standard error of the sampling by \
                     lines, not of the lines' spacing), is counted twice, adding {effect} ± {u} \
                     to the mass; the numbers are the sum of the shells",
                    shell_pairs(pairs),
                    significant(*volume, 3),
                    significant(*uncertainty, 2),
                )
            };
            if compared < candidates {
                let _ = write!(
                    text,
                    " (only {compared} of the {candidates} pairs of shells whose boxes meet were \
                     compared within the work budget; the others may overlap too, by at most {} \
                     mesh units cubed, each pair at most its smaller shell)",
                    significant(*uncompared_bound, 3)
                );
            }
            text
        }
        Defect::SelfOverlappingShell {
            shells,
            volume,
            uncertainty,
            crossing_faces,
            total_effect,
            total_uncertainty,
        } => {
            let mut text = format!(
                "{count} closed shell(s) pass through themselves (shell {}; {crossing_faces} \
                 faces bound the part inside itself, {faces}): {} ± {} (mesh units cubed; ± one \
                 standard error of the sampling by lines, not of the lines' spacing) of their \
                 volume is counted twice, adding {effect} to the mass",
                join(shells),
                significant(*volume, 3),
                significant(*uncertainty, 2),
            );
            let own = w.effect_on_mass.unwrap_or(0.0);
            if (total_effect - own).abs() > 0.0 {
                let _ = write!(
                    text,
                    "; with the overlap between shells, volume counted twice adds {} ± {} in all",
                    percent_to(*total_effect, 3),
                    percent(*total_uncertainty).replace('+', "")
                );
            }
            text
        }
        Defect::NestedShell { shells } => format!(
            "{count} closed shell(s) wound outward inside another solid (shell {}; {faces}): each \
             is counted as solid again, adding {effect} to the mass; if it is meant as a cavity, \
             reverse its faces (it would then remove as much)",
            join(shells)
        ),
        Defect::CracksClosed { largest_gap } => format!(
            "{count} open edge(s) closed by merging vertices at most {} apart (float32 rounding \
             in the file; {faces}): the mass changed by {effect}",
            significant(*largest_gap, 3)
        ),
        Defect::HolesCapped {
            boundary_edges,
            cap_area_fraction,
        } => format!(
            "{count} hole(s) ({boundary_edges} open edges; {faces}) capped by fans from their \
             centres, which are {} of the surface: without the caps the mass would differ by {} \
             (how much the result depends on how the holes are closed)",
            percent(*cap_area_fraction).replace('+', ""),
            w.effect_on_mass.map(percent).unwrap_or_default()
        ),
        Defect::NonplanarFaces { uncertainty } => format!(
            "{count} non-planar polygon(s) ({faces}), each integrated projected onto its best-fit \
             plane: triangulating them otherwise would change the mass by up to {}",
            percent(*uncertainty)
        ),
        Defect::TwoCornerFaces { lines } => format!(
            "{count} `f` record(s) of fewer than three corners skipped (line {}): segments bound \
             no volume",
            join(lines)
        ),
        Defect::StlTriangleCount { header, records } => format!(
            "the binary STL header counts {header} triangle(s) but {records} whole 50-byte \
             records follow it: all {records} were read (the header's count is wrong; some \
             exporters leave it 0)"
        ),
        Defect::UpAxisNotApplied { axis } => format!(
            "the COLLADA file's <up_axis> is {axis}, not Z_UP: it is not applied, so the numbers \
             are in the file's own axes (as rviz, MoveIt and Gazebo use a URDF's meshes)"
        ),
        Defect::InconsistentWinding { face_pairs } => match w.effect_on_mass {
            Some(_) => format!(
                "{count} face(s) wound against their neighbours ({faces}; pairs that met \
                 wrongly: {}) were turned to agree with them: counted as wound they would have \
                 changed the mass by {effect}",
                face_pairs_text(face_pairs, lines)
            ),
            None => format!(
                "{count} edge(s) where neighbouring faces wind in opposite senses (faces {}; one \
                 of each pair is flipped) on a surface whose faces cannot all agree (one-sided, \
                 like a Möbius band): the volume method counts the flipped faces as negative \
                 volume",
                face_pairs_text(face_pairs, lines)
            ),
        },
        Defect::Flipped { whole: true, .. } => "the faces wind clockwise seen from outside \
             (negative signed volume): the results are those of the outward-wound mesh"
            .to_owned(),
        Defect::Flipped { shells, .. } => format!(
            "{count} shell(s) wound inward and inside no other (shell {}; {faces}) were turned \
             outward: counted as wound they would have changed the mass by {effect}",
            join(shells)
        ),
        Defect::DegenerateFaces => {
            format!("{count} face(s) of zero area ({faces}): they contribute nothing")
        }
        Defect::NonmanifoldEdges { edges } => format!(
            "{count} non-manifold edge(s) (shared by more than two faces; e.g. {}): the shells \
             that meet there are each counted in full, and any overlap is reported separately",
            edge_faces(edges, lines)
        ),
        // massprops may add warnings; their code still names them.
    }
}

/// A relative change as a signed percentage to two significant digits: "+9.4 %", "-1.2e-7 %".
fn percent(x: f64) -> String {
    percent_to(x, 2)
}

/// `x` as a signed percentage to `digits` significant digits.
fn percent_to(x: f64, digits: usize) -> String {
    let sign = if x > 0.0 { "+" } else { "" };
    format!("{sign}{} %", significant(x * 100.0, digits))
}

/// Indices as "1, 4, 9".
fn join(v: &[usize]) -> String {
    crate::wording::list(v)
}

/// One face as "12" or "12 (line 40)".
fn face_text(f: usize, lines: &[u32]) -> String {
    crate::wording::face_line(f, lines)
}

/// "e.g. faces 12 (line 40), 13 (line 41), counting from 0", or "faces not named".
fn faces_text(faces: &[usize], lines: &[u32]) -> String {
    if faces.is_empty() {
        return "no face of the file".to_owned();
    }
    let list: Vec<String> = faces.iter().map(|&f| face_text(f, lines)).collect();
    format!("e.g. faces {}, counting from 0", list.join(", "))
}

/// Shell pairs as "0 and 1, 2 and 5".
fn shell_pairs(pairs: &[(usize, usize)]) -> String {
    pairs
        .iter()
        .map(|(a, b)| format!("{a} and {b}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Non-manifold edges as "edge 3-7 (faces 1, 4 (line 9))".
fn edge_faces(examples: &[((u32, u32), Vec<usize>)], lines: &[u32]) -> String {
    examples
        .iter()
        .map(|((a, b), faces)| {
            let faces: Vec<String> = faces.iter().map(|&f| face_text(f, lines)).collect();
            format!("edge {a}-{b} (faces {})", faces.join(", "))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// Face pairs as "4 and 9, 12 and 13", with lines where known.
fn face_pairs_text(examples: &[(usize, usize)], lines: &[u32]) -> String {
    examples
        .iter()
        .map(|&(a, b)| format!("{} and {}", face_text(a, lines), face_text(b, lines)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The warnings of a resolved body as `export` and `simulate` print them on stderr, one line
/// each: "warning: FILE: TEXT", or "warning: FILE: part "NAME": TEXT" for a body of parts.
pub fn warning_lines(file: &str, body: &crate::input::Resolved) -> Vec<String> {
    match body {
        crate::input::Resolved::Mesh {
            file: read,
            analysis,
        } => analysis
            .warnings
            .iter()
            .map(|w| format!("warning: {file}: {}", warning_text(w, &read.face_lines)))
            .collect(),
        crate::input::Resolved::Parts(parts) => parts
            .composite
            .parts
            .iter()
            .flat_map(|part| {
                part.warnings.iter().map(move |w| {
                    format!(
                        "warning: {file}: part {:?}: {}",
                        part.name,
                        warning_text(w, &[])
                    )
                })
            })
            .collect(),
    }
}
