//! One call that gives everything a report needs: the chosen method's numbers, both
//! approximations at the same mass, the diagnostics and typed warnings ([`Warning`]; the wording
//! for users is the caller's, as a command line and a window say different things).

use crate::approximations::{bounding_box_properties, point_mass_properties};
use crate::diagnostics::{MeshDiagnostics, diagnose};
use crate::integrals::IntegrationPath;
use crate::properties::{MassProperties, positive};
use crate::shell::shell_properties;
use crate::solid::{Solid, solid_properties};
use crate::{MeshError, PolyMesh};

/// How the mass is distributed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// A solid of uniform density bounded by a closed mesh (Mirtich 1996). Density in kg/m³.
    Volume,
    /// A thin wall of uniform surface density on the faces. Density in kg/m².
    Shell,
    /// Equal point masses at the vertices (approximation); mass as the solid's.
    Points,
    /// A solid cuboid filling the bounding box (approximation); mass as the solid's.
    BoundingBox,
}

impl Method {
    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::Volume => "volume",
            Method::Shell => "shell",
            Method::Points => "points",
            Method::BoundingBox => "bbox",
        }
    }
}

/// How much mass: a density, or a total mass (the density follows).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassSpec {
    /// Density: per volume for the volume, points and bbox methods; per area for shell.
    Density(f64),
    /// Total mass.
    Mass(f64),
}

/// Everything known about a body: the chosen method's result and the rest for comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    /// The method of `properties`.
    pub method: Method,
    /// kg/m³ (kg/m² for shell); `None` when the mass was given and the mesh encloses no volume.
    pub density: Option<f64>,
    /// Enclosed volume, when the mesh encloses one.
    pub volume: Option<f64>,
    /// The faces wound inwards; results are those of the outward-wound mesh.
    pub flipped: bool,
    /// The chosen method's mass properties.
    pub properties: MassProperties,
    /// Bounding-box cuboid with the same mass, about the box centre.
    pub bounding_box: MassProperties,
    /// Vertex point masses with the same mass, about their centre.
    pub point_masses: MassProperties,
    /// Mesh diagnostics.
    pub diagnostics: MeshDiagnostics,
    /// What the user should know before trusting the numbers, in this order: open mesh,
    /// non-manifold edges, inconsistent winding, flipped, degenerate faces, non-planar faces.
    pub warnings: Vec<Warning>,
}

/// Something wrong with the mesh that the numbers of an [`Analysis`] depend on or hide.
///
/// Vertex, face and edge indices count from 0 (vertices after welding), as in
/// [`MeshDiagnostics`]; each `examples` list holds at most
/// [`EXAMPLES`](crate::diagnostics::EXAMPLES) items. New variants may be added, so match with a
/// wildcard arm.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Warning {
    /// The surface has holes, and the enclosed volume (so the mass and inertia) depends on where
    /// they are. Only given when the numbers use that volume (not for the shell method, nor for
    /// the approximations at a given mass).
    OpenMesh {
        /// Edges used by only one face.
        boundary_edges: usize,
        /// Some of them, as vertex pairs (low, high).
        examples: Vec<(u32, u32)>,
    },
    /// Edges shared by more than two faces: touching or overlapping parts each count in full.
    NonManifoldEdges {
        /// How many such edges.
        count: usize,
        /// Some of them: the vertex pair and the faces sharing it (zero-based).
        examples: Vec<((u32, u32), Vec<usize>)>,
    },
    /// Edges whose two faces traverse them in the same direction: some faces are wound the
    /// other way, and the volume method counts them as negative volume.
    InconsistentWinding {
        /// How many such edges.
        edges: usize,
        /// Some neighbouring face pairs (zero-based) that wind in the same sense along their
        /// shared edge: one face of each is flipped.
        examples: Vec<(usize, usize)>,
    },
    /// The faces wind clockwise seen from outside (negative signed volume); the results are those
    /// of the outward-wound mesh. Only given when the numbers use the enclosed volume.
    Flipped,
    /// Faces of (numerically) zero area, which contribute nothing.
    DegenerateFaces {
        /// How many such faces.
        count: usize,
        /// Some of their indices.
        examples: Vec<usize>,
    },
    /// Polygons whose corners leave their plane; each is integrated as projected onto its
    /// best-fit plane.
    NonPlanarFaces {
        /// How many such faces.
        count: usize,
        /// Some of their indices.
        examples: Vec<usize>,
    },
}

impl Warning {
    /// A stable snake_case identifier of the variant, for machine-readable output (JSON):
    /// `open_mesh`, `non_manifold_edges`, `inconsistent_winding`, `flipped`, `degenerate_faces`,
    /// `non_planar_faces`.
    pub fn code(&self) -> &'static str {
        match self {
            Warning::OpenMesh { .. } => "open_mesh",
            Warning::NonManifoldEdges { .. } => "non_manifold_edges",
            Warning::InconsistentWinding { .. } => "inconsistent_winding",
            Warning::Flipped => "flipped",
            Warning::DegenerateFaces { .. } => "degenerate_faces",
            Warning::NonPlanarFaces { .. } => "non_planar_faces",
        }
    }
}

/// Computes the chosen method's mass properties, the approximations and the diagnostics.
pub fn analyze(mesh: &PolyMesh, method: Method, spec: MassSpec) -> Result<Analysis, MeshError> {
    match spec {
        MassSpec::Density(d) => positive("density", d)?,
        MassSpec::Mass(m) => positive("mass", m)?,
    };
    check_range(mesh, method, spec)?;
    let diagnostics = diagnose(mesh);
    let solid = solid_properties(mesh, IntegrationPath::Auto).map_err(|e| explain(e, &diagnostics));
    let volume = solid.as_ref().ok().map(|s| s.volume);
    let (properties, density, flipped) = match (method, spec) {
        (Method::Shell, _) => {
            let (unit, area) = shell_properties(mesh, 1.0)?;
            let sigma = match spec {
                MassSpec::Density(d) => d,
                MassSpec::Mass(m) => m / area,
            };
            // A given mass is kept exactly (σ·area would round it: 0.2 → 0.20000000000000004).
            let mass = match spec {
                MassSpec::Density(d) => d * area,
                MassSpec::Mass(m) => m,
            };
            let p = unit.with_mass(mass)?;
            (p, Some(sigma), solid.as_ref().is_ok_and(|s| s.flipped))
        }
        // With the mass given, the approximations use no volume (nor a density found from it):
        // they serve open meshes and sheets too, and their numbers never depend on holes. A
        // mesh without area is no body at all.
        (Method::Points | Method::BoundingBox, MassSpec::Mass(mass)) => {
            if diagnostics.surface_area.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                return Err(MeshError::ZeroArea);
            }
            let flipped = solid.as_ref().is_ok_and(|s| s.flipped);
            (approximation(mesh, method, mass)?, None, flipped)
        }
        (Method::Volume | Method::Points | Method::BoundingBox, _) => {
            let solid: Solid = solid?;
            let density = match spec {
                MassSpec::Density(d) => d,
                MassSpec::Mass(m) => m / solid.volume,
            };
            let mut exact = solid.with_density(density)?;
            if let MassSpec::Mass(m) = spec {
                // Kept exactly: ρ·V with ρ = m/V would round it (0.2 → 0.20000000000000004).
                exact = exact.with_mass(m)?;
            }
            let p = match method {
                Method::Volume => exact,
                _ => approximation(mesh, method, exact.mass)?,
            };
            (p, Some(density), solid.flipped)
        }
    };
    let warnings = warnings(&diagnostics, method, density.is_some(), flipped);
    Ok(Analysis {
        method,
        density,
        volume,
        flipped,
        bounding_box: bounding_box_properties(mesh, properties.mass)?,
        point_masses: point_mass_properties(mesh, properties.mass)?,
        properties,
        diagnostics,
        warnings,
    })
}

/// Longest bounding-box sides accepted: the integrals multiply up to five coordinates, and
/// (1e±50)⁵ = 1e±250 keeps every product a normal f64 (1e-308 to 1e308) with room to spare.
const SIZE_RANGE: (f64, f64) = (1e-50, 1e50);

/// Masses and moments of inertia accepted, as orders of magnitude: far enough inside the normal
/// f64 range that a thin body (volume ≪ size³) or a sum of many terms stays in it.
const RESULT_RANGE: (f64, f64) = (1e-250, 1e250);

/// Refuses a body whose numbers f64 cannot hold to full precision, from their orders of
/// magnitude: size L (longest side), mass ~ ρL³ (ρL² for a shell) or as given, inertia ~ mL².
/// Without this, overflow gives NaN and underflow gives zero moments, both silently.
fn check_range(mesh: &PolyMesh, method: Method, spec: MassSpec) -> Result<(), MeshError> {
    let (lo, hi) = mesh.bounding_box();
    let size = (hi - lo).amax();
    if size == 0.0 {
        // A point: the zero-volume and zero-area checks say what is wrong.
        return Ok(());
    }
    let out_of = |quantity, estimate: f64, (low, high): (f64, f64), advice| {
        if (low..=high).contains(&estimate) {
            Ok(())
        } else {
            Err(MeshError::OutOfRange {
                quantity,
                estimate,
                low,
                high,
                advice,
            })
        }
    };
    let units = "express the mesh in other units";
    out_of("size", size, SIZE_RANGE, units)?;
    let (mass, other) = match (spec, method) {
        (MassSpec::Mass(m), _) => (m, "give another mass"),
        (MassSpec::Density(sigma), Method::Shell) => (sigma * size * size, "use another density"),
        (MassSpec::Density(rho), _) => (rho * size.powi(3), "use another density"),
    };
    out_of("mass", mass, RESULT_RANGE, other)?;
    let advice = match spec {
        MassSpec::Mass(_) => "express the mesh in other units, or give another mass",
        MassSpec::Density(_) => "express the mesh in other units, or use another density",
    };
    out_of("inertia", mass * size * size, RESULT_RANGE, advice)
}

/// Replaces a zero-volume error's generic cause by what the diagnostics found: a mesh with
/// inconsistently wound faces can cancel its own volume exactly.
fn explain(e: MeshError, d: &MeshDiagnostics) -> MeshError {
    match e {
        MeshError::ZeroVolume {
            volume, diagonal, ..
        } if d.inconsistent_edges > 0 || d.open_edges > 0 || d.nonmanifold_edges > 0 => {
            MeshError::ZeroVolume {
                volume,
                diagonal,
                cause: format!(
                    "the mesh has {} inconsistently wound edge(s), {} open edge(s) and {} \
                     non-manifold edge(s): fix the winding and close the holes (or use the shell \
                     method for sheets)",
                    d.inconsistent_edges, d.open_edges, d.nonmanifold_edges
                ),
            }
        }
        other => other,
    }
}

/// The vertex point masses, or the bounding-box cuboid, of `mass`.
fn approximation(mesh: &PolyMesh, method: Method, mass: f64) -> Result<MassProperties, MeshError> {
    match method {
        Method::BoundingBox => bounding_box_properties(mesh, mass),
        _ => point_mass_properties(mesh, mass),
    }
}

/// `used_volume`: whether the numbers depend on the enclosed volume (not for the approximations
/// at a given mass).
fn warnings(d: &MeshDiagnostics, method: Method, used_volume: bool, flipped: bool) -> Vec<Warning> {
    // Holes and winding only matter to numbers that come from the enclosed volume.
    let volume_matters = method != Method::Shell && used_volume;
    let mut w = Vec::new();
    if d.open_edges > 0 && volume_matters {
        w.push(Warning::OpenMesh {
            boundary_edges: d.open_edges,
            examples: d.open_edge_examples.clone(),
        });
    }
    if d.nonmanifold_edges > 0 {
        w.push(Warning::NonManifoldEdges {
            count: d.nonmanifold_edges,
            examples: d.nonmanifold_edge_examples.clone(),
        });
    }
    if d.inconsistent_edges > 0 {
        w.push(Warning::InconsistentWinding {
            edges: d.inconsistent_edges,
            examples: d.inconsistent_face_examples.clone(),
        });
    }
    if flipped && volume_matters {
        w.push(Warning::Flipped);
    }
    if d.degenerate_faces > 0 {
        w.push(Warning::DegenerateFaces {
            count: d.degenerate_faces,
            examples: d.degenerate_face_examples.clone(),
        });
    }
    if d.nonplanar_faces > 0 {
        w.push(Warning::NonPlanarFaces {
            count: d.nonplanar_faces,
            examples: d.nonplanar_face_examples.clone(),
        });
    }
    w
}
