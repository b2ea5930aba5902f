//! The volume method: mass properties of the solid a closed mesh bounds, at uniform density.

use nalgebra::{Matrix3, Point3};

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

/// The solid bounded by a triangle mesh given as borrowed arrays: integrated on the calling
/// thread with no mesh built, so nothing is copied and nothing but the numbers is computed (no
/// weld, no diagnostics, no defect pass). For callers that hold the arrays already and trust
/// them, as the Python package's `check=False`; [`crate::analyze`] is the checked path.
///
/// The indices and coordinates are validated (one pass over each). The tetrahedra's common apex
/// is the centre of the box of *all* positions, where a [`PolyMesh`] takes the box of the used
/// ones: with every vertex used the result equals [`solid_properties`]' bit for bit; unused
/// vertices far from the body move the apex away and the round-off grows as the cube of that
/// distance over the body's size.
///
/// # Errors
/// No triangles or no positions, a non-finite coordinate, an index out of range, or zero
/// enclosed volume.
pub fn triangles_solid(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
) -> Result<Solid, MeshError> {
    if positions.is_empty() || triangles.is_empty() {
        return Err(MeshError::Empty);
    }
    let vertex_count = positions.len();
    // The largest index alone, a pass the compiler vectorises; the face is found only on error.
    let largest = triangles.as_flattened().iter().copied().max().unwrap_or(0);
    if largest as usize >= vertex_count {
        let face = triangles
            .iter()
            .position(|t| t.contains(&largest))
            .unwrap_or(0);
        return Err(MeshError::IndexOutOfRange {
            face,
            index: largest as usize,
            vertex_count,
        });
    }
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let mut finite = true;
    for p in positions {
        for k in 0..3 {
            let c = p[k];
            finite &= c.is_finite();
            lo[k] = if c < lo[k] { c } else { lo[k] };
            hi[k] = if c > hi[k] { c } else { hi[k] };
        }
    }
    if !finite {
        let (vertex, value) = positions
            .iter()
            .enumerate()
            .find_map(|(v, p)| p.coords.iter().find(|c| !c.is_finite()).map(|&c| (v, c)))
            .unwrap_or((0, f64::NAN));
        return Err(MeshError::NonFiniteVertex { vertex, value });
    }
    let (lo, hi) = (Point3::from(lo), Point3::from(hi));
    let reference = Point3::from(lo.coords * 0.5 + hi.coords * 0.5);
    let integrals = VolumeIntegrals {
        reference,
        values: crate::integrals::triangle::integrate(positions, triangles, reference),
    };
    solid_in_box(&integrals, (hi - lo).norm())
}

/// Turns the ten integrals into a volume, a centre of mass and the central inertia tensor.
pub fn solid_from_integrals(
    integrals: &VolumeIntegrals,
    mesh: &PolyMesh,
) -> Result<Solid, MeshError> {
    let (lo, hi) = mesh.bounding_box();
    solid_in_box(integrals, (hi - lo).norm())
}

/// [`solid_from_integrals`] of a body whose bounding box has this `diagonal` (the scale below
/// which a volume counts as zero).
fn solid_in_box(integrals: &VolumeIntegrals, diagonal: f64) -> Result<Solid, MeshError> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrals::IntegrationPath;
    use crate::shapes;

    #[test]
    fn borrowed_triangles_give_the_meshs_solid() {
        let mesh = shapes::torus(1.0, 0.3, 40, 20)
            .triangulated()
            .build()
            .map_positions(|p| p + nalgebra::Vector3::new(1e3, -2e3, 5.0))
            .expect("finite");
        let triangles = mesh.as_triangles().expect("triangles");
        let built = solid_properties(&mesh, IntegrationPath::Triangle).expect("solid");
        // Every vertex used: the same apex, the same numbers bit for bit.
        let borrowed = triangles_solid(mesh.positions(), triangles).expect("solid");
        assert_eq!(borrowed, built);
        // An unused vertex 10 sizes away moves the apex: round-off grows as its distance cubed.
        let mut positions = mesh.positions().to_vec();
        positions.push(Point3::new(1e3 + 26.0, -2e3, 5.0));
        let moved = triangles_solid(&positions, triangles).expect("solid");
        let (a, b) = (moved.unit_density, built.unit_density);
        assert!((moved.volume - built.volume).abs() < 1e-12 * built.volume);
        assert!((a.center_of_mass - b.center_of_mass).norm() < 1e-12 * 2.3e3);
        assert!((a.inertia_com - b.inertia_com).amax() < 1e-11 * b.inertia_com.amax());
        assert_ne!(moved, built, "the apex did move");
    }

    #[test]
    fn borrowed_triangles_are_validated() {
        let mesh = shapes::cube().triangulated().build();
        let positions = mesh.positions();
        let mut triangles = mesh.as_triangles().expect("triangles").to_vec();
        triangles[5][1] = 8;
        let err = triangles_solid(positions, &triangles).expect_err("index 8 of 8");
        assert!(
            matches!(
                err,
                MeshError::IndexOutOfRange {
                    face: 5,
                    index: 8,
                    vertex_count: 8
                }
            ),
            "{err:?}"
        );
        let mut bad = positions.to_vec();
        bad[3].y = f64::NAN;
        let err = triangles_solid(&bad, mesh.as_triangles().expect("triangles"))
            .expect_err("NaN coordinate");
        assert!(
            matches!(err, MeshError::NonFiniteVertex { vertex: 3, .. }),
            "{err:?}"
        );
        let flipped = mesh.flipped();
        let turned =
            triangles_solid(positions, flipped.as_triangles().expect("triangles")).expect("solid");
        assert!(turned.flipped && (turned.volume - 1.0).abs() < 1e-15);
    }
}
