//! One call that gives everything a report needs: the chosen method's numbers, both
//! approximations at the same mass, the diagnostics and typed warnings ([`Warning`]; the wording
//! for users is the caller's, as a command line and a window say different things).

use crate::approximations::{bounding_box_properties, point_mass_properties};
use crate::defects::{self, Cleaned, Holes, Repairs, Shell, input_faces, nonplanar};
use crate::diagnostics::{MeshDiagnostics, diagnose_with, edge_report};
use crate::edges::EdgeTable;
use crate::integrals::IntegrationPath;
use crate::properties::{MassProperties, positive};
use crate::shell::shell_properties;
use crate::solid::{Solid, solid_properties};
use crate::warning::{Defect, Warning};
use crate::{MeshError, PolyMesh};

/// How the mass is distributed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
///
/// ```
/// use massprops::{Analysis, MassSpec, Method, analyze, shapes};
///
/// // The unit cube at a mass of 3 kg: density 3, every moment m·a²/6 = 0.5.
/// let cube = shapes::cube().build();
/// let a: Analysis = analyze(&cube, Method::Volume, MassSpec::Mass(3.0)).unwrap();
/// assert_eq!((a.volume, a.density), (Some(1.0), Some(3.0)));
/// assert!((a.properties.principal.moments.add_scalar(-0.5)).amax() < 1e-12);
/// // Its eight vertices as point masses of 3/8 kg, each (1/2)² + (1/2)² from every axis.
/// assert!((a.point_masses.principal.moments.add_scalar(-1.5)).amax() < 1e-12);
/// // The thin shell of the same mass: 5/18 · m·a².
/// let shell = analyze(&cube, Method::Shell, MassSpec::Mass(3.0)).unwrap();
/// assert!((shell.properties.principal.moments.add_scalar(-5.0 / 6.0)).amax() < 1e-12);
/// assert!(a.warnings.is_empty() && !a.flipped);
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
    /// Mesh diagnostics, of the mesh as given.
    pub diagnostics: MeshDiagnostics,
    /// The connected shells of the mesh, in order of their first face.
    pub shells: Vec<Shell>,
    /// What the user should know before trusting the numbers, in the order of
    /// [`Defect::code`]'s list.
    pub warnings: Vec<Warning>,
}

impl Analysis {
    /// Adds warnings found elsewhere (by a file reader), in the order of [`Defect::code`]'s list.
    pub fn add_warnings(&mut self, more: impl IntoIterator<Item = Warning>) {
        self.warnings.extend(more);
        self.warnings.sort_by_key(|w| w.defect.kind());
    }
}

/// Computes the chosen method's mass properties, the approximations and the diagnostics, with
/// the default handling of defects ([`Repairs::default`]).
///
/// ```
/// use massprops::{MassSpec, Method, analyze, shapes};
///
/// // The L-bracket (metres) in steel: 100 × 10 + 10 × 50 mm² of section, 30 mm deep.
/// let mesh = shapes::l_bracket().build();
/// let a = analyze(&mesh, Method::Volume, MassSpec::Density(7850.0)).unwrap();
/// let volume = (0.1 * 0.01 + 0.01 * 0.05) * 0.03;
/// assert!((a.volume.unwrap() - volume).abs() < 1e-15);
/// assert!((a.properties.mass - 7850.0 * volume).abs() < 1e-12);
/// // Its centre of mass is far from its bounding box's, which the approximation keeps.
/// let bbox = a.bounding_box.compare_to(&a.properties);
/// assert!(bbox.com_offset > 0.01);
/// ```
pub fn analyze(mesh: &PolyMesh, method: Method, spec: MassSpec) -> Result<Analysis, MeshError> {
    analyze_with(mesh, method, spec, &Repairs::default())
}

/// [`analyze`] with the handling of defects chosen: cracks, holes, and the time the shell
/// comparison may take.
pub fn analyze_with(
    mesh: &PolyMesh,
    method: Method,
    spec: MassSpec,
    repairs: &Repairs,
) -> Result<Analysis, MeshError> {
    match spec {
        MassSpec::Density(d) => positive("density", d)?,
        MassSpec::Mass(m) => positive("mass", m)?,
    };
    check_range(mesh_size(mesh), method, spec)?;
    let table = EdgeTable::new(mesh);
    let diagnostics = diagnose_with(mesh, &table);
    analyze_diagnosed(mesh, method, spec, repairs, diagnostics, table)
}

/// [`analyze_with`] for several methods at one `spec` (whose range is the caller's to check),
/// the mesh diagnosed once.
pub(crate) fn analyze_methods<const N: usize>(
    mesh: &PolyMesh,
    methods: [Method; N],
    spec: MassSpec,
    repairs: &Repairs,
) -> [Result<Analysis, MeshError>; N] {
    let table = EdgeTable::new(mesh);
    let diagnostics = diagnose_with(mesh, &table);
    let mut table = Some(table);
    methods.map(|method| {
        // Each repair pass consumes an edge table; the first takes the one diagnosed.
        let table = table.take().unwrap_or_else(|| EdgeTable::new(mesh));
        analyze_diagnosed(mesh, method, spec, repairs, diagnostics.clone(), table)
    })
}

/// [`analyze_with`] after the checks, with the mesh's edge table and diagnostics.
fn analyze_diagnosed(
    mesh: &PolyMesh,
    method: Method,
    spec: MassSpec,
    repairs: &Repairs,
    diagnostics: MeshDiagnostics,
    table: EdgeTable,
) -> Result<Analysis, MeshError> {
    // With the mass given, the approximations use no volume (nor a density found from it):
    // they serve open meshes and sheets too, and their numbers never depend on holes.
    let uses_volume = !matches!(
        (method, spec),
        (Method::Shell, _) | (Method::Points | Method::BoundingBox, MassSpec::Mass(_))
    );
    let cleaned = defects::clean(mesh, table, repairs, uses_volume, diagnostics.surface_area)?;
    let body: &PolyMesh = &cleaned.mesh;
    let solid = solid_properties(body, IntegrationPath::Auto)
        .map_err(|e| explain(e, &diagnostics, repairs.holes == Holes::Cap));
    // Without the repairs that make it one (caps), an open surface encloses no definite volume.
    let enclosed = uses_volume || diagnostics.is_closed();
    let volume = solid.as_ref().ok().filter(|_| enclosed).map(|s| s.volume);
    let solid_flipped = enclosed && solid.as_ref().is_ok_and(|s| s.flipped);
    // The solid, when the numbers come from it: checked against the laws of real bodies below.
    let mut checked_solid = None;
    let (properties, density, scale) = match (method, spec) {
        (Method::Shell, _) => {
            let (unit, area) = shell_properties(body, 1.0)?;
            let sigma = match spec {
                MassSpec::Density(d) => d,
                MassSpec::Mass(m) => m / area,
            };
            // A given mass is kept exactly (σ·area would round it: 0.2 → 0.20000000000000004).
            let mass = match spec {
                MassSpec::Density(d) => d * area,
                MassSpec::Mass(m) => m,
            };
            (unit.with_mass(mass)?, Some(sigma), area)
        }
        // A mesh without area is no body at all.
        (Method::Points | Method::BoundingBox, MassSpec::Mass(mass)) => {
            if diagnostics.surface_area.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                return Err(MeshError::ZeroArea);
            }
            let p = approximation(mesh, method, mass)?;
            (p, None, diagnostics.surface_area)
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
            checked_solid = Some(exact);
            let p = match method {
                Method::Volume => exact,
                _ => approximation(mesh, method, exact.mass)?,
            };
            (p, Some(density), solid.volume)
        }
    };
    let flipped = if uses_volume {
        cleaned.flipped_whole || solid_flipped
    } else {
        solid_flipped
    };
    let warnings = warnings(
        mesh,
        &diagnostics,
        &cleaned,
        uses_volume,
        solid_flipped,
        scale,
    );
    if let Some(solid) = &checked_solid {
        caps_within(&warnings, repairs.max_cap_share)?;
        crate::laws::check(solid, mesh, &warnings)?;
    }
    Ok(Analysis {
        method,
        density,
        volume,
        flipped,
        // The file's own vertices: caps add centroids that are not the body's.
        bounding_box: bounding_box_properties(mesh, properties.mass)?,
        point_masses: point_mass_properties(mesh, properties.mass)?,
        properties,
        diagnostics,
        shells: cleaned.shells,
        warnings,
    })
}

/// Longest bounding-box sides accepted: the integrals multiply up to five coordinates, and
/// (1e±50)⁵ = 1e±250 keeps every product a normal f64 (1e-308 to 1e308) with room to spare.
const SIZE_RANGE: (f64, f64) = (1e-50, 1e50);

/// Masses and moments of inertia accepted, as orders of magnitude: far enough inside the normal
/// f64 range that a thin body (volume ≪ size³) or a sum of many terms stays in it.
const RESULT_RANGE: (f64, f64) = (1e-250, 1e250);

/// The longest side of `mesh`'s bounding box: the size [`check_range`] judges.
pub(crate) fn mesh_size(mesh: &PolyMesh) -> f64 {
    let (lo, hi) = mesh.bounding_box();
    (hi - lo).amax()
}

/// Refuses a body whose numbers f64 cannot hold to full precision, from their orders of
/// magnitude: size L (longest side), mass ~ ρL³ (ρL² for a shell) or as given, inertia ~ mL².
/// Without this, overflow gives NaN and underflow gives zero moments, both silently.
pub(crate) fn check_range(size: f64, method: Method, spec: MassSpec) -> Result<(), MeshError> {
    if size == 0.0 {
        // A point: the zero-volume and zero-area checks say what is wrong.
        return Ok(());
    }
    let out_of =
        |quantity: &'static str, estimate: f64, (low, high): (f64, f64), advice: &'static str| {
            if (low..=high).contains(&estimate) {
                Ok(())
            } else {
                Err(MeshError::OutOfRange {
                    quantity: std::borrow::Cow::Borrowed(quantity),
                    estimate,
                    low,
                    high,
                    advice: std::borrow::Cow::Borrowed(advice),
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

/// Refuses a solid whose caps make more than `max_share` of its closed surface.
pub(crate) fn caps_within(warnings: &[Warning], max_share: f64) -> Result<(), MeshError> {
    for w in warnings {
        if let Defect::HolesCapped {
            cap_area_fraction, ..
        } = w.defect
        {
            let share = cap_area_fraction / (1.0 + cap_area_fraction);
            if share > max_share {
                return Err(MeshError::CapsTooLarge {
                    share,
                    threshold: max_share,
                    holes: w.count,
                });
            }
        }
    }
    Ok(())
}

/// Replaces a zero-volume error's generic cause by what the diagnostics found: a mesh with
/// inconsistently wound faces can cancel its own volume exactly; an open one that encloses
/// nothing even once capped is a sheet.
fn explain(e: MeshError, d: &MeshDiagnostics, capped: bool) -> MeshError {
    match e {
        MeshError::ZeroVolume {
            volume, diagonal, ..
        } if capped && d.open_edges > 0 && d.inconsistent_edges == 0 => MeshError::ZeroVolume {
            volume,
            diagonal,
            cause: format!(
                "it has {} open edge(s), and even with its holes capped it encloses nothing: it \
                 is a sheet (a plane, a terrain, cloth); use the shell method for its mass",
                d.open_edges
            ),
        },
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

/// Every warning, in the order of [`Defect::code`]'s list, effects made relative to `scale` (the
/// volume, or the area when the volume is not used).
fn warnings(
    mesh: &PolyMesh,
    input: &MeshDiagnostics,
    cleaned: &Cleaned<'_>,
    uses_volume: bool,
    solid_flipped: bool,
    scale: f64,
) -> Vec<Warning> {
    let mut w = cleaned.warnings.clone();
    // Edge defects as they remain after the repairs, named by the input's faces.
    let origin = cleaned.origin.as_deref();
    let repaired;
    let (nonmanifold, nonmanifold_examples, inconsistent, inconsistent_examples) =
        if cleaned.edges_changed {
            repaired = edge_report(&cleaned.table);
            (
                repaired.nonmanifold,
                &repaired.nonmanifold_examples,
                repaired.inconsistent,
                &repaired.inconsistent_examples,
            )
        } else {
            (
                input.nonmanifold_edges,
                &input.nonmanifold_edge_examples,
                input.inconsistent_edges,
                &input.inconsistent_face_examples,
            )
        };
    let to_input = |f: usize| origin.map_or(f, |o| o[f] as usize);
    if nonmanifold > 0 {
        let examples: Vec<((u32, u32), Vec<usize>)> = nonmanifold_examples
            .iter()
            .map(|(pair, faces)| (*pair, faces.iter().map(|&f| to_input(f)).collect()))
            .collect();
        let faces = examples.iter().flat_map(|e| e.1.iter().map(|&f| f as u32));
        w.push(Warning {
            defect: Defect::NonmanifoldEdges {
                edges: examples.clone(),
            },
            count: nonmanifold,
            faces: input_faces(None, faces),
            effect_on_mass: Some(0.0),
        });
    }
    // Faces turned to agree with their neighbours are reported by the repair; what remains is
    // a shell whose faces cannot agree.
    let repaired_winding = w.iter().any(|w| w.code() == "inconsistent_winding");
    if inconsistent > 0 && !repaired_winding {
        let pairs: Vec<(usize, usize)> = inconsistent_examples
            .iter()
            .map(|&(a, b)| (to_input(a), to_input(b)))
            .collect();
        let faces = pairs.iter().flat_map(|&(a, b)| [a as u32, b as u32]);
        w.push(Warning {
            defect: Defect::InconsistentWinding {
                face_pairs: pairs.clone(),
            },
            count: inconsistent,
            faces: input_faces(None, faces),
            effect_on_mass: None,
        });
    }
    if uses_volume && solid_flipped && !cleaned.flipped_whole {
        w.push(Warning {
            defect: Defect::Flipped {
                shells: Vec::new(),
                whole: true,
            },
            count: cleaned.shells.len(),
            faces: Vec::new(),
            effect_on_mass: Some(0.0),
        });
    }
    if input.degenerate_faces > 0 {
        w.push(Warning {
            defect: Defect::DegenerateFaces,
            count: input.degenerate_faces,
            faces: input.degenerate_face_examples.clone(),
            effect_on_mass: Some(0.0),
        });
    }
    if input.nonplanar_faces > 0 {
        let spread = nonplanar::spread(mesh, mesh.reference_point(), uses_volume);
        w.push(Warning {
            defect: Defect::NonplanarFaces {
                uncertainty: spread / scale,
            },
            count: input.nonplanar_faces,
            faces: input.nonplanar_face_examples.clone(),
            effect_on_mass: None,
        });
    }
    for warning in &mut w {
        if let Some(e) = &mut warning.effect_on_mass {
            *e /= scale;
        }
        if let Defect::SelfOverlappingShell {
            total_effect,
            total_uncertainty,
            ..
        } = &mut warning.defect
        {
            *total_effect /= scale;
            *total_uncertainty /= scale;
        }
    }
    w.sort_by_key(|w| w.defect.kind());
    w
}
