//! Mass properties of a rigid body and the laws that move them: parallel-axis shift, rotation
//! into another frame, and scaling at fixed density or fixed mass.
//!
//! Tensor convention everywhere: the inertia tensor I = ∫ρ(|r|²E − r rᵀ) dV, so its
//! off-diagonal entries are the negated products of inertia, Iₓᵧ = −∫ρ x y dV.

use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

use crate::MeshError;
use crate::principal::{Degeneracy, PrincipalInertia, principal_inertia};

/// Mass, centre of mass and inertia tensor (tensor convention, about the centre of mass, in the
/// mesh's axes), with the principal moments and axes derived from it.
///
/// ```
/// use massprops::{MassProperties, mass_properties, shapes};
/// use nalgebra::{Matrix3, Point3, Vector3};
///
/// // A 1 × 4 × 7 box centred on the origin at density 2: m = 56, I = m·diag(65, 50, 17)/12.
/// let p: MassProperties = mass_properties(&shapes::book().build(), 2.0).unwrap();
/// let expected = Matrix3::from_diagonal(&Vector3::new(65.0, 50.0, 17.0)) * (56.0 / 12.0);
/// assert!((p.inertia_com - expected).amax() < 1e-12);
/// assert!((p.principal.moments.x - 56.0 * 17.0 / 12.0).abs() < 1e-12); // ascending
///
/// // About a corner (the parallel-axis theorem): off-diagonals −m·dx·dy.
/// let corner = Point3::new(0.5, 2.0, 3.5);
/// assert!((p.inertia_about(&corner)[(0, 1)] - -56.0 * 0.5 * 2.0).abs() < 1e-12);
///
/// // Twice the size at the same density: m·8, I·32.
/// let big = p.scaled_at_fixed_density(2.0).unwrap();
/// assert!((big.mass - 448.0).abs() < 1e-12);
/// assert!((big.inertia_com - expected * 32.0).amax() < 1e-9);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MassProperties {
    /// Mass (kg when lengths are metres and density is kg/m³).
    pub mass: f64,
    /// Centre of mass in mesh coordinates.
    pub center_of_mass: Point3<f64>,
    /// Inertia tensor about the centre of mass, mesh axes, off-diagonals −∑m·x·y.
    pub inertia_com: Matrix3<f64>,
    /// Principal moments (ascending) and axes of `inertia_com`.
    pub principal: PrincipalInertia,
}

/// The parallel-axis term m(|d|²E − d dᵀ): what the inertia gains about a point `d` away from the
/// centre of mass.
pub fn parallel_axis_term(mass: f64, d: &Vector3<f64>) -> Matrix3<f64> {
    (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * mass
}

impl MassProperties {
    /// Assembles mass properties from mass, centre of mass and the tensor about it.
    pub fn new(mass: f64, center_of_mass: Point3<f64>, inertia_com: Matrix3<f64>) -> Self {
        let inertia_com = (inertia_com + inertia_com.transpose()) * 0.5;
        Self {
            mass,
            center_of_mass,
            inertia_com,
            principal: principal_inertia(&inertia_com),
        }
    }

    /// Inertia tensor about an arbitrary point, mesh axes (parallel-axis theorem).
    pub fn inertia_about(&self, point: &Point3<f64>) -> Matrix3<f64> {
        self.inertia_com + parallel_axis_term(self.mass, &(point - self.center_of_mass))
    }

    /// Inertia tensor about the mesh origin, mesh axes.
    pub fn inertia_origin(&self) -> Matrix3<f64> {
        self.inertia_about(&Point3::origin())
    }

    /// The same body after a rigid motion (rotation then translation) of the mesh.
    pub fn transformed(&self, motion: &Isometry3<f64>) -> Self {
        let r = motion.rotation.to_rotation_matrix();
        Self::new(
            self.mass,
            motion * self.center_of_mass,
            r.matrix() * self.inertia_com * r.matrix().transpose(),
        )
    }

    /// The same body with every length multiplied by `s` at fixed density: m ∝ s³, I ∝ s⁵.
    pub fn scaled_at_fixed_density(&self, s: f64) -> Result<Self, MeshError> {
        let s = positive("scale", s)?;
        Ok(Self::new(
            self.mass * s.powi(3),
            self.center_of_mass * s,
            self.inertia_com * s.powi(5),
        ))
    }

    /// The same body with every length multiplied by `s` at fixed mass: I ∝ s².
    pub fn scaled_at_fixed_mass(&self, s: f64) -> Result<Self, MeshError> {
        let s = positive("scale", s)?;
        Ok(Self::new(
            self.mass,
            self.center_of_mass * s,
            self.inertia_com * (s * s),
        ))
    }

    /// The same shape with its density changed so the mass is `mass` (inertia scales with it).
    pub fn with_mass(&self, mass: f64) -> Result<Self, MeshError> {
        let mass = positive("mass", mass)?;
        let k = mass / self.mass;
        Ok(Self::new(mass, self.center_of_mass, self.inertia_com * k))
    }
}

/// How far an approximation is from the exact mass properties.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Comparison {
    /// Relative error of each principal moment, (approx − exact) / exact, ascending order.
    pub moment_error: Vector3<f64>,
    /// Angle (radians, 0 to π/2) between corresponding principal axes; `None` where either
    /// body's axis is not unique (equal moments).
    pub axis_angle: [Option<f64>; 3],
    /// Distance between the centres of mass.
    pub com_offset: f64,
}

impl MassProperties {
    /// Compares `self` (an approximation) with `exact`.
    pub fn compare_to(&self, exact: &MassProperties) -> Comparison {
        let unique = |p: &PrincipalInertia, i: usize| match p.degeneracy {
            Degeneracy::Distinct => true,
            Degeneracy::Moments12 => i == 2,
            Degeneracy::Moments23 => i == 0,
            Degeneracy::Spherical => false,
        };
        let axis_angle = std::array::from_fn(|i| {
            (unique(&self.principal, i) && unique(&exact.principal, i)).then(|| {
                let a = self.principal.rotation.matrix().column(i);
                let b = exact.principal.rotation.matrix().column(i);
                // atan2 keeps small angles accurate where acos of a dot product cannot.
                a.cross(&b).norm().atan2(a.dot(&b).abs())
            })
        });
        Comparison {
            moment_error: (self.principal.moments - exact.principal.moments)
                .component_div(&exact.principal.moments),
            axis_angle,
            com_offset: (self.center_of_mass - exact.center_of_mass).norm(),
        }
    }
}

/// Checks that a parameter is finite and greater than zero.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, MeshError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(MeshError::InvalidParameter {
            name: name.into(),
            value,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion};

    fn sample() -> MassProperties {
        let i = Matrix3::new(3.0, -0.2, 0.1, -0.2, 2.0, 0.05, 0.1, 0.05, 1.5);
        MassProperties::new(2.0, Point3::new(0.5, -1.0, 2.0), i)
    }

    #[test]
    fn parallel_axis_of_a_point_mass() {
        // A point mass m at (a, b, 0) seen from the origin: Ixx = m b², Iyy = m a², Ixy = −m a b.
        let t = parallel_axis_term(3.0, &Vector3::new(2.0, 5.0, 0.0));
        assert_eq!(
            t,
            Matrix3::new(75.0, -30.0, 0.0, -30.0, 12.0, 0.0, 0.0, 0.0, 87.0)
        );
    }

    /// ∫ from `lo` to `hi` of (u − q)ᵏ du, for k = 0, 1, 2.
    fn power_integral(lo: f64, hi: f64, q: f64, k: i32) -> f64 {
        ((hi - q).powi(k + 1) - (lo - q).powi(k + 1)) / f64::from(k + 1)
    }

    #[test]
    fn inertia_about_a_point_is_the_box_integrated_about_that_point() {
        // A solid box [lo, hi] of density ρ, integrated directly about q, with no shift theorem:
        // Cᵢⱼ = ρ∫(xᵢ − qᵢ)(xⱼ − qⱼ)dV is a product of one-dimensional integrals, I = tr(C)E − C.
        let (lo, hi, rho) = ([-0.5, 1.0, 2.0], [1.5, 1.5, 5.0], 3.0);
        let sides: [f64; 3] = std::array::from_fn(|i| hi[i] - lo[i]);
        let mass = rho * sides.iter().product::<f64>();
        let centre = Point3::from(std::array::from_fn(|i| (lo[i] + hi[i]) / 2.0));
        let [a, b, c] = sides;
        let central =
            Matrix3::from_diagonal(&Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b))
                * (mass / 12.0);
        let p = MassProperties::new(mass, centre, central);
        // The third point is the centre: the direct integral there is the closed-form central tensor.
        for q in [
            [7.0, 1.0, -3.0],
            [0.0; 3],
            [0.5, 1.25, 3.5],
            [-40.0, 25.0, 1e3],
        ] {
            let cov = Matrix3::from_fn(|i, j| {
                rho * (0..3)
                    .map(|k| {
                        let power = i32::from(k == i) + i32::from(k == j);
                        power_integral(lo[k], hi[k], q[k], power)
                    })
                    .product::<f64>()
            });
            let want = Matrix3::identity() * cov.trace() - cov;
            let got = p.inertia_about(&Point3::from(q));
            assert!(
                (got - want).amax() <= 1e-13 * want.amax(),
                "about {q:?}: {got} vs {want}"
            );
        }
    }

    #[test]
    fn rotation_keeps_moments_and_scaling_laws_hold() {
        let p = sample();
        let motion = Isometry3::from_parts(
            Translation3::new(1.0, 2.0, 3.0),
            UnitQuaternion::from_euler_angles(0.4, 1.2, -0.3),
        );
        let q = p.transformed(&motion);
        assert!((q.principal.moments - p.principal.moments).amax() < 1e-14);
        assert!((q.inertia_com.trace() - p.inertia_com.trace()).abs() < 1e-14);
        let d = p.scaled_at_fixed_density(2.0).expect("valid");
        assert_eq!(d.mass, 16.0);
        assert!((d.inertia_com - p.inertia_com * 32.0).amax() < 1e-13);
        let m = p.scaled_at_fixed_mass(3.0).expect("valid");
        assert_eq!(m.mass, 2.0);
        assert!((m.inertia_com - p.inertia_com * 9.0).amax() < 1e-13);
        assert!(p.with_mass(-1.0).is_err());
        assert!(p.scaled_at_fixed_mass(f64::NAN).is_err());
    }
}
