//! The app's wording of massprops warnings: what the numbers on screen mean for this mesh and
//! what the user can do about it in a modelling program (the command line's wording, with its
//! flags, is `cli::report::warning_text`).

use massprops::Warning;

/// The warning `w` as the side panel shows it: no command-line flags; vertex and face numbers
/// count from 0, as in the rest of the app.
pub fn warning_text(w: &Warning) -> String {
    match w {
        Warning::OpenMesh {
            boundary_edges,
            examples,
        } => {
            let examples: Vec<String> = examples.iter().map(|(a, b)| format!("{a}–{b}")).collect();
            format!(
                "The mesh has holes ({boundary_edges} open edge(s), e.g. between vertices {}). \
                 An open surface encloses no definite volume, so the mass, centre of mass and \
                 inertia shown depend on where the holes are. Close the holes in your modelling \
                 program and load the mesh again.",
                examples.join(", ")
            )
        }
        Warning::NonManifoldEdges { count, examples } => {
            let named: Vec<String> = examples
                .iter()
                .map(|((a, b), faces)| format!("vertices {a}–{b}, faces {}", list(faces)))
                .collect();
            format!(
                "{count} edge(s) are shared by more than two faces (e.g. {}): parts that touch or \
                 overlap are each counted in full, so overlapping volume counts twice. Merge or \
                 separate the parts in your modelling program if that is not intended.",
                named.join("; ")
            )
        }
        Warning::InconsistentWinding { edges, examples } => {
            let pairs: Vec<String> = examples
                .iter()
                .map(|(a, b)| format!("{a} and {b}"))
                .collect();
            format!(
                "Some faces point the wrong way ({edges} edge(s) between faces wound in opposite \
                 senses, e.g. faces {}: one of each pair is flipped); they count as negative \
                 volume, so the numbers are wrong. Recalculate the normals (make them consistent) \
                 in your modelling program.",
                pairs.join(", ")
            )
        }
        Warning::Flipped => "All faces point inwards; the numbers shown are those of the \
                             correctly oriented mesh, so nothing needs fixing for them here."
            .to_owned(),
        Warning::DegenerateFaces { count, examples } => format!(
            "{count} face(s) have no area (e.g. face {}); they change nothing, but often mark \
             a modelling mistake worth cleaning up.",
            list(examples)
        ),
        Warning::NonPlanarFaces { count, examples } => format!(
            "{count} polygon(s) are not flat (e.g. face {}); each is counted as if pressed flat \
             onto its best-fit plane. Triangulate the mesh in your modelling program for exact \
             numbers.",
            list(examples)
        ),
        // massprops may add warnings; their code still names them.
        other => format!("Mesh warning: {}", other.code()),
    }
}

fn list(indices: &[usize]) -> String {
    indices
        .iter()
        .map(usize::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gui_wording_names_no_command_line_flag_and_says_what_to_do() {
        let all = [
            Warning::OpenMesh {
                boundary_edges: 4,
                examples: vec![(0, 1), (2, 3)],
            },
            Warning::NonManifoldEdges {
                count: 1,
                examples: vec![((3, 7), vec![1, 4, 9])],
            },
            Warning::InconsistentWinding {
                edges: 4,
                examples: vec![(0, 5)],
            },
            Warning::Flipped,
            Warning::DegenerateFaces {
                count: 2,
                examples: vec![12, 13],
            },
            Warning::NonPlanarFaces {
                count: 3,
                examples: vec![1, 2, 5],
            },
        ];
        for w in &all {
            let text = warning_text(w);
            assert!(!text.contains("--"), "{text}");
        }
        let open = warning_text(&all[0]);
        assert!(
            open.contains("4 open edge(s)") && open.contains("0–1, 2–3"),
            "{open}"
        );
        assert!(open.contains("Close the holes"), "{open}");
        assert!(warning_text(&all[4]).contains("12, 13"));
        assert!(warning_text(&all[5]).contains("1, 2, 5"));
    }
}
