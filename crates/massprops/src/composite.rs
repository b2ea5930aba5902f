//! Bodies made of parts: each part a mesh with its own material (a density, a preset, a mass), a
//! void that removes material, or a thin wall on its faces, placed by a rigid motion. The
//! composite's mass properties are exact sums: masses add, the centre of mass is the
//! mass-weighted mean, and each part's tensor is moved to the common centre by the parallel-axis
//! theorem, I = Σ [Iᵢ + mᵢ(|dᵢ|²E − dᵢdᵢᵀ)] with dᵢ = cᵢ − c (Steiner; e.g. Goldstein,
//! Classical Mechanics, 3rd ed., §5.3), a void counting with negative mass.

use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

use crate::properties::{parallel_axis_term, positive};
use crate::{
    MassProperties, MassSpec, MeshError, Method, PolyMesh, Repairs, Warning, analyze_with,
};

/// How a part gets its mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fill {
    /// A solid of this density (kg/m³ with metres).
    Solid {
        /// Mass per volume.
        density: f64,
    },
    /// A solid of uniform density with this total mass.
    Mass {
        /// The part's mass.
        mass: f64,
    },
    /// Empty space inside another part: removes a solid of this density.
    Void {
        /// The density of the material removed.
        density: f64,
    },
    /// A wall of this thickness on the faces (the shell method, surface density ρ·t): a hollow
    /// crate, a racket's strings, a lamp shade.
    ThinWall {
        /// The wall material's density.
        density: f64,
        /// Wall thickness, in the mesh's units.
        thickness: f64,
    },
}

/// One part of a body.
#[derive(Debug, Clone)]
pub struct Part {
    /// Its name, for messages and reports.
    pub name: String,
    /// Its surface, in its own coordinates.
    pub mesh: PolyMesh,
    /// Where its mass comes from.
    pub fill: Fill,
    /// Mesh coordinates → body coordinates: the rotation (about the mesh origin), then the
    /// translation.
    pub placement: Isometry3<f64>,
}

/// What one part contributes, in body coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct PartProperties {
    /// The part's name.
    pub name: String,
    /// Mass per volume of its material (of the material removed, for a void).
    pub density: f64,
    /// Signed mass: negative for a void.
    pub mass: f64,
    /// The material's volume (a thin wall's area × thickness), positive.
    pub volume: f64,
    /// Its centre of mass.
    pub center_of_mass: Point3<f64>,
    /// Its inertia tensor about its own centre of mass, signed like `mass`.
    pub inertia_com: Matrix3<f64>,
    /// Its share of each principal moment of the composite (about the composite's centre and
    /// axes, moments ascending); the parts' shares add up to 1 for each moment.
    pub share: Vector3<f64>,
    /// What the part's mesh has wrong (faces count within the part's mesh).
    pub warnings: Vec<Warning>,
}

/// A body made of parts: the whole and each part.
#[derive(Debug, Clone, PartialEq)]
pub struct Composite {
    /// The composite's mass properties, in body coordinates.
    pub properties: MassProperties,
    /// Each part, in the order given.
    pub parts: Vec<PartProperties>,
}

/// The mass properties of a body made of `parts`, each part's mesh handled as `repairs` says.
///
/// ```
/// use massprops::{Fill, Part, Repairs, composite, shapes};
/// use nalgebra::{Isometry3, Point3, Vector3};
///
/// // A hollow box: a 2 m cube with a 1 m cube of its material removed, density 1.
/// let cube = |a: f64| shapes::cuboid(Vector3::repeat(a), Point3::origin()).build();
/// let part = |name: &str, a: f64, fill: Fill| Part {
///     name: name.into(),
///     mesh: cube(a),
///     fill,
///     placement: Isometry3::identity(),
/// };
/// let parts = [
///     part("shell", 2.0, Fill::Solid { density: 1.0 }),
///     part("cavity", 1.0, Fill::Void { density: 1.0 }),
/// ];
/// let body = composite(&parts, &Repairs::default()).unwrap();
/// // m = 8 − 1 and I = (8·2² − 1·1²)/6 about every axis.
/// assert!((body.properties.mass - 7.0).abs() < 1e-12);
/// assert!((body.properties.principal.moments.add_scalar(-31.0 / 6.0)).amax() < 1e-12);
/// assert!(body.parts[1].mass < 0.0); // a void counts negative
/// ```
///
/// Errors: no parts; a part that cannot be integrated (named); a fill that is not a positive
/// number; voids that remove as much as there is or more, or leave an inertia tensor that no
/// body has (named with the total found).
pub fn composite(parts: &[Part], repairs: &Repairs) -> Result<Composite, MeshError> {
    if parts.is_empty() {
        return Err(MeshError::Empty);
    }
    let mut each: Vec<PartProperties> = Vec::with_capacity(parts.len());
    for part in parts {
        let named = |source: MeshError| MeshError::InPart {
            part: part.name.clone(),
            source: Box::new(source),
        };
        each.push(one_part(part, repairs).map_err(named)?);
    }
    let masses: Vec<PartMass> = each
        .iter()
        .map(|p| PartMass {
            mass: p.mass,
            center_of_mass: p.center_of_mass,
            inertia_com: p.inertia_com,
        })
        .collect();
    let (properties, shares) = combine(&masses)?;
    for (p, share) in each.iter_mut().zip(shares) {
        p.share = share;
    }
    Ok(Composite {
        properties,
        parts: each,
    })
}

/// One part's mass as it counts in a body: signed (negative for a void), about its own centre,
/// in body coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartMass {
    /// Signed mass.
    pub mass: f64,
    /// Centre of mass, body coordinates.
    pub center_of_mass: Point3<f64>,
    /// Inertia about its own centre of mass, body axes, signed like `mass`.
    pub inertia_com: Matrix3<f64>,
}

/// The body the signed masses make together, and each one's share of each principal moment:
/// the sums of [`composite`] without the integration (for a caller that keeps each part's
/// integrals and changes only materials or placements).
///
/// Errors: nothing left, or a tensor that is no body's ([`MeshError::VoidTooLarge`]).
pub fn combine(parts: &[PartMass]) -> Result<(MassProperties, Vec<Vector3<f64>>), MeshError> {
    if parts.is_empty() {
        return Err(MeshError::Empty);
    }
    let mass: f64 = parts.iter().map(|p| p.mass).sum();
    if mass.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Err(MeshError::VoidTooLarge {
            mass,
            moments: None,
        });
    }
    let center = Point3::from(
        parts
            .iter()
            .map(|p| p.center_of_mass.coords * p.mass)
            .sum::<Vector3<f64>>()
            / mass,
    );
    let about_center: Vec<Matrix3<f64>> = parts
        .iter()
        .map(|p| p.inertia_com + parallel_axis_term(p.mass, &(p.center_of_mass - center)))
        .collect();
    let inertia: Matrix3<f64> = about_center.iter().sum();
    let properties = MassProperties::new(mass, center, inertia);
    let m = properties.principal.moments;
    // A real body's moments are positive and obey the triangle inequality (I₁ + I₂ ≥ I₃).
    if !m.iter().all(|&x| x > 0.0) || m.x + m.y < m.z * (1.0 - 1e-12) {
        return Err(MeshError::VoidTooLarge {
            mass,
            moments: Some([m.x, m.y, m.z]),
        });
    }
    let axes = properties.principal.rotation.matrix();
    let shares = about_center
        .iter()
        .map(|i| {
            Vector3::from_fn(|k, _| {
                let a = axes.column(k);
                (a.transpose() * i * a)[(0, 0)] / m[k]
            })
        })
        .collect();
    Ok((properties, shares))
}

/// One part's signed contribution, in body coordinates.
fn one_part(part: &Part, repairs: &Repairs) -> Result<PartProperties, MeshError> {
    let (method, spec, sign) = match part.fill {
        Fill::Solid { density } => (Method::Volume, MassSpec::Density(density), 1.0),
        Fill::Mass { mass } => (Method::Volume, MassSpec::Mass(mass), 1.0),
        Fill::Void { density } => (Method::Volume, MassSpec::Density(density), -1.0),
        Fill::ThinWall { density, thickness } => {
            positive("thickness", thickness)?;
            let sigma = positive("density", density)? * thickness;
            (Method::Shell, MassSpec::Density(sigma), 1.0)
        }
    };
    let a = analyze_with(&part.mesh, method, spec, repairs)?;
    let placed = a.properties.transformed(&part.placement);
    let (density, volume) = match part.fill {
        Fill::ThinWall { density, .. } => (density, placed.mass / density),
        _ => {
            let density = a.density.unwrap_or(f64::NAN);
            (density, a.volume.unwrap_or(placed.mass / density))
        }
    };
    Ok(PartProperties {
        name: part.name.clone(),
        density,
        mass: sign * placed.mass,
        volume,
        center_of_mass: placed.center_of_mass,
        inertia_com: placed.inertia_com * sign,
        share: Vector3::zeros(),
        warnings: a.warnings,
    })
}
