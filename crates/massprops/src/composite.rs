//! Bodies made of parts: each part a mesh with its own material (a density, a preset, a mass), a
//! void that removes material, or a thin wall on its faces, placed by a rigid motion. The
//! composite's mass properties are exact sums: masses add, the centre of mass is the
//! mass-weighted mean, and each part's tensor is moved to the common centre by the parallel-axis
//! theorem, I = Σ [Iᵢ + mᵢ(|dᵢ|²E − dᵢdᵢᵀ)] with dᵢ = cᵢ − c (Steiner; e.g. Goldstein,
//! Classical Mechanics, 3rd ed., §5.3), a void counting with negative mass.

use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

use crate::analysis::{analyze_methods, check_range, mesh_size};
#[cfg(doc)]
use crate::analyze_with;
use crate::properties::{parallel_axis_term, positive};
use crate::{Analysis, MassProperties, MassSpec, MeshError, Method, PolyMesh, Repairs, Warning};

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

/// How a part's mass is given, as a body file (and the app) writes it.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum MaterialEntry {
    /// `density = ρ` (kg/m³ with metres).
    Density(f64),
    /// `material = "steel"`: a preset of [`MATERIALS`](crate::materials::MATERIALS).
    Preset(String),
    /// `mass = m` (kg).
    Mass(f64),
}

impl MaterialEntry {
    /// Its density: given, or its preset's; `None` for a mass (the volume decides) or an unknown
    /// preset.
    pub fn density(&self) -> Option<f64> {
        match self {
            MaterialEntry::Density(d) => Some(*d),
            MaterialEntry::Preset(name) => crate::material(name).map(|m| m.density),
            MaterialEntry::Mass(_) => None,
        }
    }

    /// The one rule that turns a material into a fill: a mass is a solid of that mass; otherwise
    /// the density fills a void, a thin wall of `thin_wall` (in the mesh's units) or a solid. A
    /// density that is missing is NaN, which [`IntegratedPart::properties`] refuses by name.
    pub fn fill(&self, void: bool, thin_wall: Option<f64>) -> Fill {
        let density = self.density().unwrap_or(f64::NAN);
        match (self, void, thin_wall) {
            (MaterialEntry::Mass(mass), ..) => Fill::Mass { mass: *mass },
            (_, true, _) => Fill::Void { density },
            (_, false, Some(thickness)) => Fill::ThinWall { density, thickness },
            (_, false, None) => Fill::Solid { density },
        }
    }
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

/// The mass properties of a body made of `parts`, each part's mesh handled as `repairs` says:
/// each part integrated once ([`IntegratedPart`]), then the sums of [`combine`].
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
///
/// ```
/// use massprops::{Fill, Part, Repairs, composite, shapes};
/// use nalgebra::{Isometry3, Point3, Vector3};
/// let cube = |x: f64, density: f64| Part {
///     name: format!("cube at {x}"),
///     mesh: shapes::cuboid(Vector3::repeat(1.0), Point3::origin()).build(),
///     fill: Fill::Solid { density },
///     placement: Isometry3::translation(x, 0.0, 0.0),
/// };
/// let body = composite(&[cube(0.0, 1.0), cube(3.0, 2.0)], &Repairs::default()).unwrap();
/// assert!((body.properties.mass - 3.0).abs() < 1e-12);
/// assert!((body.properties.center_of_mass.x - 2.0).abs() < 1e-12); // (0·1 + 3·2) / 3
/// ```
pub fn composite(parts: &[Part], repairs: &Repairs) -> Result<Composite, MeshError> {
    let integrated: Vec<IntegratedPart> = parts
        .iter()
        .map(|p| IntegratedPart::new(&p.mesh, repairs))
        .collect();
    let placed: Vec<PlacedPart<'_>> = parts
        .iter()
        .zip(&integrated)
        .map(|(p, integrated)| PlacedPart {
            name: &p.name,
            fill: p.fill,
            placement: p.placement,
            integrated,
        })
        .collect();
    sum(&placed)
}

/// A part integrated already ([`IntegratedPart`]), with its name, fill and placement: what
/// [`sum`] adds up.
#[derive(Debug, Clone, Copy)]
pub struct PlacedPart<'a> {
    /// Its name, for messages and reports.
    pub name: &'a str,
    /// Where its mass comes from.
    pub fill: Fill,
    /// Mesh coordinates → body coordinates.
    pub placement: Isometry3<f64>,
    /// Its mesh's unit-density integrals.
    pub integrated: &'a IntegratedPart,
}

/// The body that `parts` make together: each part's contribution from its integrals, then the
/// sums of [`combine`] (the second half of [`composite`], for a caller that keeps the
/// integrals).
///
/// Errors: as [`composite`].
pub fn sum(parts: &[PlacedPart<'_>]) -> Result<Composite, MeshError> {
    if parts.is_empty() {
        return Err(MeshError::Empty);
    }
    let mut each: Vec<PartProperties> = Vec::with_capacity(parts.len());
    for part in parts {
        let named = |source: MeshError| MeshError::InPart {
            part: part.name.to_owned(),
            source: Box::new(source),
        };
        each.push(
            part.integrated
                .properties(part.name, part.fill, &part.placement)
                .map_err(named)?,
        );
    }
    let masses: Vec<PartMass> = each.iter().map(PartProperties::part_mass).collect();
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

/// A part's mesh integrated once, at unit density, as a solid and as a surface (each with its
/// defects handled and its warnings): from it, [`IntegratedPart::properties`] gives the part's
/// mass properties for any [`Fill`] and placement by scaling and moving, without integrating
/// again. The result is bit for bit what [`analyze_with`] gives for that fill's method and
/// density.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IntegratedPart {
    /// The solid at density 1 (volume method), or why it has none.
    solid: Result<Analysis, MeshError>,
    /// The surface at surface density 1 (shell method), or why it has none.
    surface: Result<Analysis, MeshError>,
    /// The longest side of the mesh's bounding box, for the range checks of a fill.
    size: f64,
}

impl IntegratedPart {
    /// Integrates `mesh` as a solid and as a surface (one diagnostics pass for both).
    pub fn new(mesh: &PolyMesh, repairs: &Repairs) -> Self {
        let unit = MassSpec::Density(1.0);
        let [solid, surface] =
            analyze_methods(mesh, [Method::Volume, Method::Shell], unit, repairs);
        Self {
            solid,
            surface,
            size: mesh_size(mesh),
        }
    }

    /// The volume the solid encloses, if it encloses one.
    pub fn volume(&self) -> Option<f64> {
        self.solid.as_ref().ok().and_then(|a| a.volume)
    }

    /// Whether the faces wind inward (the solid is that of the outward-wound surface).
    pub fn wound_inward(&self) -> bool {
        self.solid.as_ref().is_ok_and(|a| a.flipped)
    }

    /// What the mesh has wrong for `fill`'s method (faces count within the part's mesh): the
    /// surface's warnings for a thin wall, the solid's otherwise (the surface's when there is no
    /// solid).
    pub fn warnings(&self, fill: Fill) -> &[Warning] {
        let used = match (fill, &self.solid) {
            (Fill::ThinWall { .. }, _) | (_, Err(_)) => &self.surface,
            (_, solid) => solid,
        };
        used.as_ref().map_or(&[], |a| a.warnings.as_slice())
    }

    /// The part's signed contribution with `fill`, placed by `placement` (mesh → body
    /// coordinates), named `name`; its `share` is left zero (the whole's sums give it).
    ///
    /// Errors: as [`analyze_with`] for the fill's method and mass: a fill that is not a positive
    /// number, a mass out of range, a mesh that encloses no volume (for a solid, a mass or a
    /// void) or has no area.
    pub fn properties(
        &self,
        name: &str,
        fill: Fill,
        placement: &Isometry3<f64>,
    ) -> Result<PartProperties, MeshError> {
        let analysed = |method: Method, spec: MassSpec| -> Result<&Analysis, MeshError> {
            match spec {
                MassSpec::Density(d) => positive("density", d)?,
                MassSpec::Mass(m) => positive("mass", m)?,
            };
            check_range(self.size, method, spec)?;
            let a = match method {
                Method::Shell => &self.surface,
                _ => &self.solid,
            };
            a.as_ref().map_err(Clone::clone)
        };
        let (unit, sign, density, scaled) = match fill {
            Fill::Solid { density } | Fill::Void { density } => {
                let a = analysed(Method::Volume, MassSpec::Density(density))?;
                let sign = if matches!(fill, Fill::Void { .. }) {
                    -1.0
                } else {
                    1.0
                };
                (a, sign, density, with_density(&a.properties, density)?)
            }
            Fill::Mass { mass } => {
                let a = analysed(Method::Volume, MassSpec::Mass(mass))?;
                let volume = a.volume.unwrap_or(a.properties.mass);
                let density = mass / volume;
                // Kept exactly, as `analyze_with` does: ρ·V with ρ = m/V would round it.
                let scaled = with_density(&a.properties, density)?.with_mass(mass)?;
                (a, 1.0, density, scaled)
            }
            Fill::ThinWall { density, thickness } => {
                positive("thickness", thickness)?;
                let sigma = positive("density", density)? * thickness;
                let a = analysed(Method::Shell, MassSpec::Density(sigma))?;
                // The unit surface's mass is its area.
                let scaled = a.properties.with_mass(sigma * a.properties.mass)?;
                (a, 1.0, density, scaled)
            }
        };
        let placed = scaled.transformed(placement);
        let volume = match fill {
            Fill::ThinWall { .. } => placed.mass / density,
            _ => unit.volume.unwrap_or(placed.mass / density),
        };
        Ok(PartProperties {
            name: name.to_owned(),
            density,
            mass: sign * placed.mass,
            volume,
            center_of_mass: placed.center_of_mass,
            inertia_com: placed.inertia_com * sign,
            share: Vector3::zeros(),
            warnings: unit.warnings.clone(),
        })
    }
}

impl PartProperties {
    /// Its signed mass, centre and tensor: what [`combine`] sums.
    pub fn part_mass(&self) -> PartMass {
        PartMass {
            mass: self.mass,
            center_of_mass: self.center_of_mass,
            inertia_com: self.inertia_com,
        }
    }
}

/// A unit-density solid's mass properties at `density` (as [`crate::solid::Solid::with_density`]).
fn with_density(unit: &MassProperties, density: f64) -> Result<MassProperties, MeshError> {
    let density = positive("density", density)?;
    Ok(MassProperties::new(
        unit.mass * density,
        unit.center_of_mass,
        unit.inertia_com * density,
    ))
}

#[cfg(test)]
mod tests {
    use nalgebra::{Translation3, UnitQuaternion};

    use super::*;
    use crate::{analyze_with, shapes};

    /// What `analyze_with` gives for `fill`, placed: the reference an integrated part must equal
    /// bit for bit.
    fn analysed(mesh: &PolyMesh, fill: Fill, placement: &Isometry3<f64>) -> (f64, MassProperties) {
        let (method, spec, sign) = match fill {
            Fill::Solid { density } => (Method::Volume, MassSpec::Density(density), 1.0),
            Fill::Mass { mass } => (Method::Volume, MassSpec::Mass(mass), 1.0),
            Fill::Void { density } => (Method::Volume, MassSpec::Density(density), -1.0),
            Fill::ThinWall { density, thickness } => {
                (Method::Shell, MassSpec::Density(density * thickness), 1.0)
            }
        };
        let a = analyze_with(mesh, method, spec, &Repairs::default()).expect("analysis");
        (sign, a.properties.transformed(placement))
    }

    #[test]
    fn an_integrated_part_gives_what_the_analysis_of_each_fill_gives_bit_for_bit() {
        let placement = Isometry3::from_parts(
            Translation3::new(0.3, -1.25, 2.0),
            UnitQuaternion::from_euler_angles(0.4, -1.1, 2.3),
        );
        let fills = [
            Fill::Solid { density: 7850.0 },
            Fill::Mass { mass: 0.2 },
            Fill::Void { density: 600.0 },
            Fill::ThinWall {
                density: 1240.0,
                thickness: 0.0015,
            },
        ];
        for (name, mesh) in [
            ("hammer", shapes::hammer().build()),
            ("torus", shapes::sample_torus().build()),
            ("T-handle", shapes::t_handle().build()),
        ] {
            let part = IntegratedPart::new(&mesh, &Repairs::default());
            for fill in fills {
                let p = part.properties(name, fill, &placement).expect("fill");
                let (sign, expected) = analysed(&mesh, fill, &placement);
                assert_eq!(p.mass, sign * expected.mass, "{name} {fill:?}");
                assert_eq!(p.center_of_mass, expected.center_of_mass, "{name} {fill:?}");
                assert_eq!(
                    p.inertia_com,
                    expected.inertia_com * sign,
                    "{name} {fill:?}"
                );
            }
        }
    }

    #[test]
    fn a_sheet_takes_a_thin_wall_and_refuses_a_solid_as_the_analysis_does() {
        let mut sheet = shapes::cube();
        sheet.faces.truncate(1);
        let mesh = sheet.build();
        let part = IntegratedPart::new(&mesh, &Repairs::default());
        assert_eq!(part.volume(), None);
        let wall = Fill::ThinWall {
            density: 1000.0,
            thickness: 0.002,
        };
        let p = part
            .properties("sheet", wall, &Isometry3::identity())
            .expect("a wall");
        // One unit square at 2 kg/m².
        assert!((p.mass - 2.0).abs() < 1e-12, "{}", p.mass);
        let solid = Fill::Solid { density: 1000.0 };
        let e = part
            .properties("sheet", solid, &Isometry3::identity())
            .expect_err("no volume");
        let direct = analyze_with(
            &mesh,
            Method::Volume,
            MassSpec::Density(1000.0),
            &Repairs::default(),
        )
        .expect_err("no volume");
        assert_eq!(e.to_string(), direct.to_string());
        let bad = part.properties(
            "sheet",
            Fill::Solid { density: -1.0 },
            &Isometry3::identity(),
        );
        assert!(bad.expect_err("negative").to_string().contains("density"));
    }
}
