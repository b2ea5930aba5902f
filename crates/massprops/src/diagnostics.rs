//! Mesh diagnostics, always computed beside the numbers: what a user must know to trust them.
//!
//! Edges come from `EdgeTable`: an edge used once is open (a hole),
//! more than twice non-manifold, and twice in the same direction means the two faces wind
//! inconsistently (one is flipped).

use nalgebra::{Point3, Vector3};
#[cfg(feature = "parallel")]
use rayon::prelude::*;

use crate::PolyMesh;
use crate::edges::EdgeTable;
use crate::integrals::mirtich::newell_normal;

/// Relative area (to the longest edge squared) below which a face counts as degenerate.
pub const DEGENERATE_AREA_RATIO: f64 = 1e-12;
/// Relative distance (to the longest edge) a polygon's corner may leave its plane.
pub const PLANARITY_TOLERANCE: f64 = 1e-8;
/// How many example faces or edges each diagnostic keeps for messages.
pub const EXAMPLES: usize = 5;

/// What the mesh is made of and what is wrong with it.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MeshDiagnostics {
    /// Vertex positions (after welding identical ones).
    pub vertices: usize,
    /// Faces as given (polygons count once).
    pub faces: usize,
    /// Triangles after fan-triangulating the faces.
    pub triangles: usize,
    /// Distinct undirected edges.
    pub edges: usize,
    /// Edges used by only one face (the mesh has holes).
    pub open_edges: usize,
    /// Edges used by more than two faces.
    pub nonmanifold_edges: usize,
    /// Edges whose two faces traverse them in the same direction (inconsistent winding).
    pub inconsistent_edges: usize,
    /// Faces of (numerically) zero area, which contribute nothing.
    pub degenerate_faces: usize,
    /// Polygons whose corners leave their plane by more than `PLANARITY_TOLERANCE`.
    pub nonplanar_faces: usize,
    /// Total surface area.
    pub surface_area: f64,
    /// Axis-aligned bounding box (min, max) of the used vertices.
    pub bounding_box: (Point3<f64>, Point3<f64>),
    /// Up to `EXAMPLES` open edges as zero-based vertex pairs.
    pub open_edge_examples: Vec<(u32, u32)>,
    /// Up to `EXAMPLES` non-manifold edges: the vertex pair and the zero-based faces sharing it.
    pub nonmanifold_edge_examples: Vec<((u32, u32), Vec<usize>)>,
    /// Up to `EXAMPLES` pairs of zero-based neighbouring faces that wind in the same sense along
    /// their shared edge (one of each pair is flipped).
    pub inconsistent_face_examples: Vec<(usize, usize)>,
    /// Up to `EXAMPLES` zero-based indices of degenerate faces.
    pub degenerate_face_examples: Vec<usize>,
    /// Up to `EXAMPLES` zero-based indices of non-planar faces.
    pub nonplanar_face_examples: Vec<usize>,
}

impl MeshDiagnostics {
    /// Every edge is shared by exactly two faces: the surface encloses a solid.
    pub fn is_closed(&self) -> bool {
        self.open_edges == 0 && self.nonmanifold_edges == 0
    }

    /// Every shared edge is traversed in opposite directions by its two faces.
    pub fn is_consistently_oriented(&self) -> bool {
        self.inconsistent_edges == 0
    }
}

/// Computes every diagnostic of `mesh`.
pub fn diagnose(mesh: &PolyMesh) -> MeshDiagnostics {
    diagnose_with(mesh, &EdgeTable::new(mesh))
}

/// [`diagnose`] with the edges already grouped.
pub(crate) fn diagnose_with(mesh: &PolyMesh, table: &EdgeTable) -> MeshDiagnostics {
    // Each face on its own, so the order of evaluation changes nothing: the area is summed below
    // in face order either way.
    #[cfg(feature = "parallel")]
    let face_stats: Vec<(f64, bool, bool)> = (0..mesh.face_count())
        .into_par_iter()
        .with_min_len(4096)
        .map_init(Vec::new, |corners, f| face_shape(mesh, f, corners))
        .collect();
    #[cfg(not(feature = "parallel"))]
    let face_stats: Vec<(f64, bool, bool)> = {
        let mut corners = Vec::new();
        (0..mesh.face_count())
            .map(|f| face_shape(mesh, f, &mut corners))
            .collect()
    };
    let mut degenerate = Vec::new();
    let mut nonplanar = Vec::new();
    let mut area = crate::integrals::CompensatedSum::<1>::new();
    let (mut degenerate_faces, mut nonplanar_faces) = (0, 0);
    for (f, &(a, is_degenerate, is_nonplanar)) in face_stats.iter().enumerate() {
        area.add(&[a]);
        if is_degenerate {
            degenerate_faces += 1;
            if degenerate.len() < EXAMPLES {
                degenerate.push(f);
            }
        }
        if is_nonplanar {
            nonplanar_faces += 1;
            if nonplanar.len() < EXAMPLES {
                nonplanar.push(f);
            }
        }
    }
    let edges = edge_report(table);
    MeshDiagnostics {
        vertices: mesh.positions().len(),
        faces: mesh.face_count(),
        triangles: mesh.triangle_count(),
        edges: edges.edges,
        open_edges: edges.open,
        nonmanifold_edges: edges.nonmanifold,
        inconsistent_edges: edges.inconsistent,
        degenerate_faces,
        nonplanar_faces,
        surface_area: area.total()[0],
        bounding_box: mesh.bounding_box(),
        open_edge_examples: edges.open_examples,
        nonmanifold_edge_examples: edges.nonmanifold_examples,
        inconsistent_face_examples: edges.inconsistent_examples,
        degenerate_face_examples: degenerate,
        nonplanar_face_examples: nonplanar,
    }
}

/// Area, degeneracy and non-planarity of face `f`.
pub(crate) fn face_shape(
    mesh: &PolyMesh,
    f: usize,
    corners: &mut Vec<Vector3<f64>>,
) -> (f64, bool, bool) {
    corners.clear();
    let first = mesh
        .face_points(f)
        .next()
        .map(|p| p.coords)
        .unwrap_or_default();
    // Corners relative to the first one, so a face far from the origin keeps its digits.
    corners.extend(mesh.face_points(f).map(|p| p.coords - first));
    let newell = newell_normal(corners);
    let twice_area = newell.norm();
    let mut longest2: f64 = 0.0;
    let mut prev = corners[corners.len() - 1];
    for &c in corners.iter() {
        longest2 = longest2.max((c - prev).norm_squared());
        prev = c;
    }
    // Not greater (including NaN from overflowing coordinates) counts as degenerate.
    let limit = 2.0 * DEGENERATE_AREA_RATIO * longest2;
    let degenerate = twice_area.partial_cmp(&limit) != Some(std::cmp::Ordering::Greater);
    let nonplanar = corners.len() > 3 && !degenerate && {
        let n = newell / twice_area;
        let mean = corners.iter().sum::<Vector3<f64>>() / corners.len() as f64;
        let limit = PLANARITY_TOLERANCE * longest2.sqrt();
        corners.iter().any(|c| n.dot(&(c - mean)).abs() > limit)
    };
    (0.5 * twice_area, degenerate, nonplanar)
}

/// What the edge table says, with examples (as in [`MeshDiagnostics`]).
pub(crate) struct EdgeReport {
    pub edges: usize,
    pub open: usize,
    pub nonmanifold: usize,
    pub inconsistent: usize,
    pub open_examples: Vec<(u32, u32)>,
    pub nonmanifold_examples: Vec<((u32, u32), Vec<usize>)>,
    pub inconsistent_examples: Vec<(usize, usize)>,
}

pub(crate) fn edge_report(table: &EdgeTable) -> EdgeReport {
    let mut report = EdgeReport {
        edges: 0,
        open: 0,
        nonmanifold: 0,
        inconsistent: 0,
        open_examples: Vec::new(),
        nonmanifold_examples: Vec::new(),
        inconsistent_examples: Vec::new(),
    };
    for group in table.groups() {
        report.edges += 1;
        let forward = group.iter().filter(|r| r.forward).count();
        let pair = (group[0].lo, group[0].hi);
        match group.len() {
            1 => {
                report.open += 1;
                if report.open_examples.len() < EXAMPLES {
                    report.open_examples.push(pair);
                }
            }
            2 if forward != 1 => {
                report.inconsistent += 1;
                if report.inconsistent_examples.len() < EXAMPLES {
                    let (a, b) = (group[0].face as usize, group[1].face as usize);
                    report.inconsistent_examples.push((a.min(b), a.max(b)));
                }
            }
            2 => {}
            _ => {
                report.nonmanifold += 1;
                if report.nonmanifold_examples.len() < EXAMPLES {
                    let faces: Vec<usize> = group.iter().map(|r| r.face as usize).collect();
                    report.nonmanifold_examples.push((pair, faces));
                }
            }
        }
    }
    report
}
