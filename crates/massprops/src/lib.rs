//! # massprops — exact mass properties of polygon meshes
//!
//! Volume, mass, centre of mass and inertia tensor of the solid a closed mesh bounds, by
//! B. Mirtich, "Fast and Accurate Computation of Polyhedral Mass Properties", J. Graphics Tools
//! 1(2), 1996 (divergence theorem → projection → Green's theorem, Newell normals), for planar
//! polygons of any shape, with a triangle fast path of signed tetrahedra (F. Tonon, "Explicit
//! Exact Formulas for the 3-D Tetrahedron Inertia Tensor", J. Math. Stat. 1(1), 2004) that
//! agrees with it to round-off. Also the thin
//! shell, the vertex point-mass sum and the bounding-box cuboid, principal moments and axes by a
//! scale-invariant Jacobi eigensolver, mesh diagnostics, and OBJ/STL loading.
//!
//! Cargo features, both on by default: `io` (OBJ and STL parsing and file loading, through
//! `tobj` and `stl_io`) and `parallel` (the triangle path and the diagnostics on the rayon pool).
//! Without `parallel`, [`IntegrationPath::TriangleParallel`] and [`IntegrationPath::Auto`] run
//! the triangle path on the calling thread, with the same result bit for bit (the block order is
//! fixed either way). With neither, only `nalgebra` and `thiserror` are built: what a dynamics
//! crate needs for [`symmetric_eigen`].
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
mod approximations;
mod composite;
mod defects;
mod diagnostics;
mod edges;
mod error;
pub mod integrals;
#[cfg(feature = "io")]
mod io;
mod materials;
mod mesh;
mod principal;
mod properties;
pub mod shapes;
mod shell;
mod solid;

pub use analysis::{Analysis, Defect, MassSpec, Method, Warning, analyze, analyze_with};
pub use approximations::{bounding_box_properties, point_mass_properties};
pub use composite::{Composite, Fill, Part, PartMass, PartProperties, combine, composite};
pub use defects::{AUTO_WELD_RATIO, Holes, Orientation, Repairs, Shell, Weld, shell_faces};
pub use diagnostics::{MeshDiagnostics, diagnose};
pub use error::MeshError;
pub use integrals::{IntegrationPath, VolumeIntegrals, volume_integrals};
#[cfg(feature = "io")]
pub use io::{
    BODY_FILE_VERSION, BodyFile, LENGTH_UNITS, MaterialEntry, MeshFile, PartEntry, is_body_file,
    load_mesh, parse_mesh, parse_obj, parse_stl,
};
pub use materials::{MATERIALS, Material, material, material_names};
pub use mesh::{PolyMesh, weld_exact};
pub use principal::{
    DEGENERACY_TOLERANCE, Degeneracy, PrincipalInertia, principal_inertia, symmetric_eigen,
};
pub use properties::{Comparison, MassProperties, parallel_axis_term};
pub use shell::shell_properties;
pub use solid::{Solid, solid_properties};

/// Mass properties of the solid bounded by `mesh` at uniform `density` (volume method).
///
/// Errors: zero enclosed volume, or a density that is not finite and positive. An inward-wound
/// mesh gives the same result as its outward-wound twin (see [`Solid::flipped`]).
pub fn mass_properties(mesh: &PolyMesh, density: f64) -> Result<MassProperties, MeshError> {
    solid_properties(mesh, IntegrationPath::Auto)?.with_density(density)
}
