//! The volume method: mass properties of the solid a closed mesh bounds, at uniform density.

use nalgebra::Matrix3;

use crate::integrals::{IntegrationPath, VolumeIntegrals, volume_integrals};
use crate::properties::{MassProperties, parallel_axis_term, positive};
use crate::{MeshError, PolyMesh};

/// Volume-method result at unit density, before a density or mass is chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solid {
    /// Enclosed volume (positive).
    pub volume: f64,
    /// The faces wound inwards (negative signed volume) and the result was flipped to match an
    /// outward-wound mesh.
    pub flipped: bool,
    /// Mass properties at density 1 (mass = volume).
    pub unit_density: MassProperties,
}

impl Solid {
    /// Mass properties at `density`.
    pub fn with_density(&self, density: f64) -> Result<MassProperties, MeshError> {
        let density = positive("density", density)?;
        let u = &self.unit_density;
        Ok(MassProperties::new(
            u.mass * density,
            u.center_of_mass,
            u.inertia_com * density,
        ))
    }
}

/// Relative size of |V| against the bounding-box diagonal cubed below which a mesh counts as
/// enclosing no volume (a flat sheet integrates to round-off, ~1e-16 of diagonal³).
pub(crate) const ZERO_VOLUME_RATIO: f64 = 1e-12;

/// Integrates the solid bounded by `mesh` by the chosen path.
pub fn solid_properties(mesh: &PolyMesh, path: IntegrationPath) -> Result<Solid, MeshError> {
    solid_from_integrals(&volume_integrals(mesh, path), mesh)
}

/// Turns the ten integrals into a volume, a centre of mass and the central inertia tensor.
pub fn solid_from_integrals(
    integrals: &VolumeIntegrals,
    mesh: &PolyMesh,
) -> Result<Solid, MeshError> {
    let (lo, hi) = mesh.bounding_box();
    let diagonal = (hi - lo).norm();
    let signed = integrals.volume();
    let limit = ZERO_VOLUME_RATIO * diagonal.powi(3);
    // NaN (from overflow) fails this test too.
    if signed.abs().partial_cmp(&limit) != Some(std::cmp::Ordering::Greater) {
        return Err(MeshError::ZeroVolume {
            volume: signed,
            diagonal,
            cause: "it is flat, open or self-cancelling; use the shell method for sheets".into(),
        });
    }
    let flipped = signed < 0.0;
    let integrals = if flipped {
        integrals.negated()
    } else {
        *integrals
    };
    let volume = integrals.volume();
    let com_local = integrals.first_moment() / volume;
    let c = integrals.second_moment();
    let about_reference = Matrix3::identity() * c.trace() - c;
    let inertia_com = about_reference - parallel_axis_term(volume, &com_local);
    Ok(Solid {
        volume,
        flipped,
        unit_density: MassProperties::new(volume, integrals.reference + com_local, inertia_com),
    })
}
