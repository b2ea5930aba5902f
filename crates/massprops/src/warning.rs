//! What the diagnostics and the defect pass find, as typed data: each [`Warning`] is a
//! [`Defect`] (with its own numbers), how many, where (faces), and how much it changes the mass.
//! The words are each front end's.

/// Something about the mesh that the numbers of an [`Analysis`](crate::Analysis) depend on, or that was repaired
/// to get them: what ([`Defect`]), how many, where, and how much it changes the mass.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Warning {
    /// What kind of defect, with its own data.
    pub defect: Defect,
    /// How many: faces for the face defects (faces removed, for duplicates; faces turned for
    /// `inconsistent_winding` when they could be), edges for the edge defects and cracks, shells for `flipped` and `nested_shell`, shell pairs for overlaps,
    /// holes for `holes_capped`, records for `two_corner_faces`.
    pub count: usize,
    /// Some of the faces concerned, as zero-based indices into the mesh given to [`analyze`](crate::analyze),
    /// ascending, at most five.
    pub faces: Vec<usize>,
    /// The estimated relative change in mass that the defect makes, as a fraction of the mass
    /// found (of the area for the shell method): positive when the defect adds mass. For a
    /// defect counted as it is (overlaps, nested shells) the mass it adds; for a repaired one,
    /// the difference between the file taken literally and the repaired result (duplicates:
    /// what they would have added; holes: minus what the caps add; cracks: the open mesh minus
    /// the welded one). `None` when it cannot be estimated.
    pub effect_on_mass: Option<f64>,
}

impl Warning {
    /// The stable identifier of the defect, as in JSON: see [`Defect::code`].
    pub fn code(&self) -> &'static str {
        self.defect.code()
    }
}

/// The kinds of defect, each with what is particular to it. Every front end matches it without
/// a wildcard arm, so a new variant does not compile until each has its words and JSON data.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Defect {
    /// The same vertex cycle more than once with the same winding: counted once.
    DuplicateFaces,
    /// A face together with its reverse (an internal wall, or both sides of a sheet): for the
    /// volume both go (they cancel); for a thin shell one copy stays.
    OppositeDuplicateFaces,
    /// Closed shells that overlap without one holding the other: their common volume is counted
    /// twice (the result is the sum; the effect is the estimate).
    OverlappingShells {
        /// Some overlapping pairs (shell indices, as in [`Analysis::shells`](crate::Analysis::shells)).
        pairs: Vec<(usize, usize)>,
        /// Estimated common volume, all pairs, in the mesh's units cubed.
        volume: f64,
        /// One standard error of `volume`.
        uncertainty: f64,
        /// Pairs compared within the work budget ([`Repairs::overlap_budget`](crate::Repairs::overlap_budget)), of `candidates`
        /// whose boxes meet: fewer means
        /// the comparison was cut short and some overlaps may be missing.
        compared: usize,
        /// Pairs of closed shells whose bounding boxes meet.
        candidates: usize,
        /// The most volume the pairs not compared can share (each pair at most the smaller
        /// shell's volume): the result may count up to this much more twice. 0 when all were
        /// compared.
        uncompared_bound: f64,
    },
    /// Closed shells that pass through themselves (consistently wound, yet with a winding number
    /// of ±2 or more inside): that volume is counted twice (the result is as counted; the effect
    /// is the estimate, which adds to `overlapping_shells`' for the total counted twice).
    SelfOverlappingShell {
        /// Some of these shells (indices into [`Analysis::shells`](crate::Analysis::shells)).
        shells: Vec<usize>,
        /// Estimated volume counted more than once, in the mesh's units cubed.
        volume: f64,
        /// One standard error of `volume` (of the sampling by lines).
        uncertainty: f64,
        /// How many faces bound the doubly counted volume (the warning's `faces` are some).
        crossing_faces: usize,
        /// The volume counted more than once in all — within these shells and between
        /// overlapping shells (`overlapping_shells`) — as a fraction of the mass, like
        /// [`Warning::effect_on_mass`]: the sum of both warnings' effects.
        total_effect: f64,
        /// One standard error of `total_effect`, as the same fraction.
        total_uncertainty: f64,
    },
    /// A closed shell whose winding disagrees with its depth: wound outward inside a solid (a
    /// cavity's wall wound the wrong way, or a part inside another), so its volume counts twice.
    NestedShell {
        /// Some of these shells (indices into [`Analysis::shells`](crate::Analysis::shells)).
        shells: Vec<usize>,
    },
    /// Boundary vertices a tiny gap apart (float32 rounding) were merged, closing cracks.
    CracksClosed {
        /// The largest distance a vertex moved, in the mesh's units.
        largest_gap: f64,
    },
    /// Holes were capped by fans from their centroids; the result is the capped solid.
    HolesCapped {
        /// Boundary edges around the holes.
        boundary_edges: usize,
        /// The caps' area as a fraction of the mesh's surface.
        cap_area_fraction: f64,
    },
    /// Polygons whose corners leave their plane; each is integrated projected onto its
    /// best-fit plane, and the result depends on the triangulation by up to `uncertainty`.
    NonplanarFaces {
        /// How far apart the extreme fan triangulations put the mass, relative to the mass.
        uncertainty: f64,
    },
    /// OBJ `f` records with two corners (segments written as faces), skipped.
    TwoCornerFaces {
        /// Some of their one-based file lines.
        lines: Vec<usize>,
    },
    /// A binary STL whose header counts fewer triangles than the whole 50-byte records that
    /// follow it (some exporters leave the count 0): every record was read.
    StlTriangleCount {
        /// The count the header gives.
        header: u64,
        /// The records the file holds, all read.
        records: u64,
    },
    /// A COLLADA file whose `<up_axis>` is not Z_UP: its axes are used as they are (the numbers
    /// are in the file's own axes), as rviz, MoveIt and Gazebo use a URDF's meshes.
    UpAxisNotApplied {
        /// The file's axis: "X_UP" or "Y_UP".
        axis: String,
    },
    /// Edges whose two faces traverse them in the same direction: some faces are wound the other
    /// way. For the volume, each shell's faces are turned to agree with their neighbours (the
    /// count is then the faces turned, the effect what they took away as wound); a shell whose
    /// faces cannot agree (one-sided) is counted as wound (the count is then its edges, the
    /// effect unknown).
    InconsistentWinding {
        /// Some neighbouring face pairs (zero-based) that wind in the same sense along their
        /// shared edge: one face of each is flipped.
        face_pairs: Vec<(usize, usize)>,
    },
    /// Shells wound inward that enclose nothing else's cavity were turned outward (a solid has
    /// no negative mass).
    Flipped {
        /// Some of these shells (indices into [`Analysis::shells`](crate::Analysis::shells)).
        shells: Vec<usize>,
        /// Every shell: the mesh as a whole is wound inward (a mirrored convention).
        whole: bool,
    },
    /// Faces of (numerically) zero area, which contribute nothing.
    DegenerateFaces,
    /// Edges shared by more than two faces that remain after duplicates are removed: shells
    /// that touch along them (each counted in full; overlaps are reported separately).
    NonmanifoldEdges {
        /// Some of them: the vertex pair and the faces sharing it (zero-based).
        edges: Vec<((u32, u32), Vec<usize>)>,
    },
}

/// Declares [`DefectKind`] from one list of kinds and their codes, in the order warnings are
/// listed in: the enum, [`DefectKind::ALL`] and [`DefectKind::code`] all come from it, so no list
/// of codes is kept by hand beside the enum (and [`Defect::kind`]'s exhaustive match makes a new
/// [`Defect`] variant need a row here).
macro_rules! defect_kinds {
    ($($(#[$doc:meta])* $kind:ident => $code:literal,)+) => {
        /// What kind of [`Defect`] a warning is, without its data: one per variant, in the order
        /// warnings are listed in (an analysis's `warnings` and every report).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub enum DefectKind {
            $($(#[$doc])* $kind,)+
        }

        impl DefectKind {
            /// Every kind, in the order warnings are listed in.
            pub const ALL: &'static [DefectKind] = &[$(DefectKind::$kind,)+];

            /// A stable snake_case identifier, for machine-readable output.
            pub const fn code(self) -> &'static str {
                match self {
                    $(DefectKind::$kind => $code,)+
                }
            }
        }

        impl Defect {
            /// Every code [`Defect::code`] gives, in the order warnings are listed in.
            pub const CODES: &'static [&'static str] = &[$($code,)+];
        }
    };
}

defect_kinds! {
    /// [`Defect::DuplicateFaces`].
    DuplicateFaces => "duplicate_faces",
    /// [`Defect::OppositeDuplicateFaces`].
    OppositeDuplicateFaces => "opposite_duplicate_faces",
    /// [`Defect::OverlappingShells`].
    OverlappingShells => "overlapping_shells",
    /// [`Defect::SelfOverlappingShell`].
    SelfOverlappingShell => "self_overlapping_shell",
    /// [`Defect::NestedShell`].
    NestedShell => "nested_shell",
    /// [`Defect::CracksClosed`].
    CracksClosed => "cracks_closed",
    /// [`Defect::HolesCapped`].
    HolesCapped => "holes_capped",
    /// [`Defect::NonplanarFaces`].
    NonplanarFaces => "nonplanar_faces",
    /// [`Defect::TwoCornerFaces`].
    TwoCornerFaces => "two_corner_faces",
    /// [`Defect::StlTriangleCount`].
    StlTriangleCount => "stl_triangle_count",
    /// [`Defect::UpAxisNotApplied`].
    UpAxisNotApplied => "up_axis_not_applied",
    /// [`Defect::InconsistentWinding`].
    InconsistentWinding => "inconsistent_winding",
    /// [`Defect::Flipped`].
    Flipped => "flipped",
    /// [`Defect::DegenerateFaces`].
    DegenerateFaces => "degenerate_faces",
    /// [`Defect::NonmanifoldEdges`].
    NonmanifoldEdges => "nonmanifold_edges",
}

impl Defect {
    /// Which kind of defect this is (the variant without its data).
    pub const fn kind(&self) -> DefectKind {
        match self {
            Defect::DuplicateFaces => DefectKind::DuplicateFaces,
            Defect::OppositeDuplicateFaces => DefectKind::OppositeDuplicateFaces,
            Defect::OverlappingShells { .. } => DefectKind::OverlappingShells,
            Defect::SelfOverlappingShell { .. } => DefectKind::SelfOverlappingShell,
            Defect::NestedShell { .. } => DefectKind::NestedShell,
            Defect::CracksClosed { .. } => DefectKind::CracksClosed,
            Defect::HolesCapped { .. } => DefectKind::HolesCapped,
            Defect::NonplanarFaces { .. } => DefectKind::NonplanarFaces,
            Defect::TwoCornerFaces { .. } => DefectKind::TwoCornerFaces,
            Defect::StlTriangleCount { .. } => DefectKind::StlTriangleCount,
            Defect::UpAxisNotApplied { .. } => DefectKind::UpAxisNotApplied,
            Defect::InconsistentWinding { .. } => DefectKind::InconsistentWinding,
            Defect::Flipped { .. } => DefectKind::Flipped,
            Defect::DegenerateFaces => DefectKind::DegenerateFaces,
            Defect::NonmanifoldEdges { .. } => DefectKind::NonmanifoldEdges,
        }
    }

    /// A stable snake_case identifier, for machine-readable output: `duplicate_faces`,
    /// `opposite_duplicate_faces`, `overlapping_shells`, `self_overlapping_shell`, `nested_shell`, `cracks_closed`,
    /// `holes_capped`, `nonplanar_faces`, `two_corner_faces`, `stl_triangle_count`,
    /// `up_axis_not_applied`, `inconsistent_winding`,
    /// `flipped`, `degenerate_faces`, `nonmanifold_edges`.
    pub const fn code(&self) -> &'static str {
        self.kind().code()
    }
}

#[cfg(test)]
mod tests {
    use super::{Defect, DefectKind};

    /// The kinds are listed once each, in their declared order, and each code is its own.
    #[test]
    fn each_kind_has_one_code_in_order() {
        for (i, kind) in DefectKind::ALL.iter().enumerate() {
            assert_eq!(*kind as usize, i, "{kind:?}");
            assert_eq!(Defect::CODES[i], kind.code());
        }
        let mut codes = Defect::CODES.to_vec();
        codes.sort_unstable();
        codes.dedup();
        assert_eq!(codes.len(), DefectKind::ALL.len(), "a code is used twice");
        assert_eq!(
            Defect::HolesCapped {
                boundary_edges: 3,
                cap_area_fraction: 0.1
            }
            .code(),
            "holes_capped"
        );
    }
}
