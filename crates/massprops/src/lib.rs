//! # massprops — exact mass properties of polygon meshes
//!
//! Volume, mass, centre of mass and inertia tensor of the solid a closed mesh bounds, by
//! B. Mirtich, "Fast and Accurate Computation of Polyhedral Mass Properties", J. Graphics Tools
//! 1(2), 1996 (divergence theorem → projection → Green's theorem, Newell normals), for planar
//! polygons of any shape, with a triangle fast path of signed tetrahedra (F. Tonon, "Explicit
//! Exact Formulas for the 3-D Tetrahedron Inertia Tensor", J. Math. Stat. 1(1), 2004) that
//! agrees with it to round-off. Also the thin
//! shell, the vertex point-mass sum and the bounding-box cuboid, principal moments and axes by a
//! scale-invariant Jacobi eigensolver, mesh diagnostics, and OBJ, STL, PLY and OFF loading.
//!
//! Cargo features, both on by default: `io` (OBJ, STL, PLY and OFF parsing and file loading, by fast
//! paths of our own beside `tobj` and `stl_io`) and `parallel` (the triangle path and the
//! diagnostics on the rayon pool).
//! Without `parallel`, [`integrals::IntegrationPath::TriangleParallel`] and [`integrals::IntegrationPath::Auto`] run
//! the triangle path on the calling thread, with the same result bit for bit (the block order is
//! fixed either way). With neither, only `nalgebra` and `thiserror` are built: what a dynamics
//! crate needs for [`principal::symmetric_eigen`].
//!
//! Conventions: lengths in the mesh's unit (metres for SI), density per volume (kg/m³); the
//! inertia tensor is I = ∫ρ(|r|²E − r rᵀ)dV, **off-diagonals −∑m·x·y**; faces wind
//! counter-clockwise seen from outside.
//!
//! ```
//! use massprops::{mass_properties, shapes};
//! let book = shapes::book().build(); // 1 × 4 × 7 box
//! let p = mass_properties(&book, 2.0).unwrap();
//! assert!((p.mass - 56.0).abs() < 1e-12);
//! // Ixx = m (4² + 7²) / 12
//! assert!((p.inertia_com[(0, 0)] - 56.0 * 65.0 / 12.0).abs() < 1e-10);
//! ```

/// The README's example, compiled and run as a doctest.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

mod analysis;
pub mod approximations;
pub mod composite;
pub mod defects;
pub mod diagnostics;
mod edges;
mod error;
pub mod integrals;
#[cfg(feature = "io")]
pub mod io;
mod laws;
pub mod materials;
pub mod mesh;
pub mod principal;
pub mod properties;
pub mod shapes;
pub mod shell;
pub mod solid;
mod units;
mod warning;

// The face of the crate: what a caller reaches for. The layers beneath (the integrals, the
// eigensolver, the defect pass, the diagnostics, the approximations, the readers) are public
// modules of their own.
pub use analysis::{Analysis, MassSpec, Method, analyze, analyze_with};
pub use composite::{
    Composite, Fill, IntegratedPart, MaterialEntry, Part, PartProperties, composite,
};
pub use defects::Repairs;
pub use error::MeshError;
#[cfg(feature = "io")]
pub use io::{
    BodyFile, MeshFile, PartEntry, load_mesh, load_mesh_reporting, parse_mesh, parse_mesh_with,
};
pub use materials::{Material, material};
pub use mesh::PolyMesh;
pub use principal::PrincipalInertia;
pub use properties::MassProperties;
pub use units::{LengthUnit, UnknownUnit};
pub use warning::{Defect, DefectKind, Warning};

/// Mass properties of the solid bounded by `mesh` at uniform `density` (volume method).
///
/// Errors: zero enclosed volume, or a density that is not finite and positive. An inward-wound
/// mesh gives the same result as its outward-wound twin (see [`solid::Solid::flipped`]).
pub fn mass_properties(mesh: &PolyMesh, density: f64) -> Result<MassProperties, MeshError> {
    solid::solid_properties(mesh, integrals::IntegrationPath::Auto)?.with_density(density)
}
