//! Rigid-body state: mass properties, pose, momenta, and body ↔ world transforms.
//!
//! Frames. *World* is inertial. The *body frame* is the mesh's own axes with the origin moved to the
//! centre of mass; body points `x_b` map to world as `x_w = R·x_b + r`. The *principal frame* has the
//! principal axes (moments ascending) as its axes; `principal_axes()` maps principal → body and
//! `orientation()` maps principal → world, so `R = orientation · principal_axesᵀ`.
//!
//! The state keeps the momenta (`p`, world angular momentum `L` about the centre of mass), not the
//! velocities: they are what the equations of motion conserve. `ω = R_p I⁻¹ R_pᵀ L` is derived.
//! Consequently changing mass, inertia or scale mid-run keeps `p` and `L` and the velocities change
//! (like a skater pulling in her arms), which is the physically right choice for an instantaneous
//! change of mass distribution.

use nalgebra::{Matrix3, Point3, Rotation3, UnitQuaternion, Vector3};

use crate::error::BodyError;

/// Relative slack on the triangle inequality `I1 + I2 ≥ I3`: a flat plate sits exactly on it and
/// rounding may put it a few ulps below.
const TRIANGLE_SLACK: f64 = 1e-9;

/// Relative asymmetry accepted in an inertia tensor before it is rejected.
const SYMMETRY_SLACK: f64 = 1e-9;

pub(crate) fn check_finite_vec(v: &Vector3<f64>, what: &'static str) -> Result<(), BodyError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(BodyError::NonFinite(what))
    }
}

/// Sorts principal moments ascending, permuting the axis columns, and makes the axes right-handed.
fn sorted_principal(moments: Vector3<f64>, axes: Matrix3<f64>) -> (Vector3<f64>, Matrix3<f64>) {
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
    let m = Vector3::new(moments[idx[0]], moments[idx[1]], moments[idx[2]]);
    let mut a = Matrix3::from_columns(&[
        axes.column(idx[0]).into_owned(),
        axes.column(idx[1]).into_owned(),
        axes.column(idx[2]).into_owned(),
    ]);
    if a.determinant() < 0.0 {
        a.set_column(2, &(-a.column(2)));
    }
    (m, a)
}

/// A rigid body: constant mass properties plus the dynamic state (pose and momenta).
///
/// ```
/// use nalgebra::{Matrix3, Point3, Vector3};
/// use rbcore::Body;
///
/// // A tensor (body axes, about the centre of mass) with its moments out of order: they come
/// // back ascending, so principal axis 3 is the body's x.
/// let inertia = Matrix3::from_diagonal(&Vector3::new(3.0, 1.0, 2.0));
/// let mut body = Body::from_inertia_tensor(2.0, &inertia).unwrap();
/// assert!((body.moments() - Vector3::new(1.0, 2.0, 3.0)).norm() < 1e-12);
///
/// // The principal frame starts aligned with world. Spin at 2 rad/s about axis 3: L = I₃ω.
/// body.set_omega_principal(Vector3::new(0.0, 0.0, 2.0)).unwrap();
/// assert!((body.angular_momentum() - Vector3::new(0.0, 0.0, 6.0)).norm() < 1e-12);
/// assert!((body.omega_world() - Vector3::new(0.0, 0.0, 2.0)).norm() < 1e-12);
///
/// // x_w = R·x_b + r: the body's x axis (principal axis 3) lies along world z.
/// body.set_position(Point3::new(1.0, 0.0, 0.0)).unwrap();
/// let tip = body.point_to_world(&Point3::new(0.5, 0.0, 0.0));
/// assert!((tip - Point3::new(1.0, 0.0, 0.5)).norm() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    pub(crate) mass: f64,
    pub(crate) moments: Vector3<f64>,
    pub(crate) inv_moments: Vector3<f64>,
    /// Principal → body (mesh) axes.
    pub(crate) axes: Rotation3<f64>,
    /// Centre of mass in world.
    pub(crate) position: Point3<f64>,
    /// Linear momentum `p = m v`.
    pub(crate) momentum: Vector3<f64>,
    /// Principal → world.
    pub(crate) orientation: UnitQuaternion<f64>,
    /// World angular momentum about the centre of mass.
    pub(crate) angular_momentum: Vector3<f64>,
}

impl Body {
    /// A body at rest at the origin with the given principal moments (any order) about principal
    /// axes given as columns of `axes` in the body frame. The principal frame starts aligned with
    /// world.
    ///
    /// # Errors
    /// Non-finite or non-positive mass or moments, or moments breaking `I1 + I2 ≥ I3`.
    pub fn from_principal(
        mass: f64,
        moments: Vector3<f64>,
        axes: Rotation3<f64>,
    ) -> Result<Self, BodyError> {
        let (moments, axes) = validate_mass_properties(mass, moments, *axes.matrix())?;
        Ok(Self {
            mass,
            moments,
            inv_moments: moments.map(|i| 1.0 / i),
            axes,
            position: Point3::origin(),
            momentum: Vector3::zeros(),
            orientation: UnitQuaternion::identity(),
            angular_momentum: Vector3::zeros(),
        })
    }

    /// A body whose body axes are its principal axes (`moments` may be in any order; they are
    /// sorted and the axes permuted accordingly).
    ///
    /// # Errors
    /// As [`Body::from_principal`].
    pub fn from_moments(mass: f64, moments: Vector3<f64>) -> Result<Self, BodyError> {
        Self::from_principal(mass, moments, Rotation3::identity())
    }

    /// A body from a full symmetric inertia tensor about the centre of mass in body axes
    /// (tensor convention: off-diagonals `−∑ m x y`). Diagonalised with nalgebra's
    /// `SymmetricEigen`; moments sorted ascending, axes made right-handed.
    ///
    /// # Errors
    /// Non-finite or asymmetric tensor, plus everything [`Body::from_principal`] rejects.
    pub fn from_inertia_tensor(mass: f64, inertia: &Matrix3<f64>) -> Result<Self, BodyError> {
        let (moments, axes) = principal_of_tensor(inertia)?;
        Self::from_principal(mass, moments, Rotation3::from_matrix_unchecked(axes))
    }

    /// Replaces mass and inertia (e.g. after rescaling the mesh) keeping `p`, `L` and the pose of
    /// the body axes in world; velocities change accordingly.
    ///
    /// # Errors
    /// As [`Body::from_principal`]; on error the body is unchanged.
    pub fn set_mass_properties(
        &mut self,
        mass: f64,
        moments: Vector3<f64>,
        axes: Rotation3<f64>,
    ) -> Result<(), BodyError> {
        let body_to_world = self.body_orientation();
        let (moments, axes) = validate_mass_properties(mass, moments, *axes.matrix())?;
        self.mass = mass;
        self.moments = moments;
        self.inv_moments = moments.map(|i| 1.0 / i);
        self.axes = axes;
        self.orientation = body_to_world * UnitQuaternion::from_rotation_matrix(&axes);
        Ok(())
    }

    /// Mass.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Principal moments, ascending.
    pub fn moments(&self) -> Vector3<f64> {
        self.moments
    }
    /// Principal → body-frame rotation (column i = principal axis i in body axes, right-handed).
    pub fn principal_axes(&self) -> Rotation3<f64> {
        self.axes
    }
    /// Centre of mass in world.
    pub fn position(&self) -> Point3<f64> {
        self.position
    }
    /// Linear momentum.
    pub fn momentum(&self) -> Vector3<f64> {
        self.momentum
    }
    /// Velocity of the centre of mass.
    pub fn velocity(&self) -> Vector3<f64> {
        self.momentum / self.mass
    }
    /// Principal frame → world (a Hamilton unit quaternion; identity for a new body).
    pub fn orientation(&self) -> UnitQuaternion<f64> {
        self.orientation
    }
    /// Body (mesh) frame → world.
    pub fn body_orientation(&self) -> UnitQuaternion<f64> {
        self.orientation * UnitQuaternion::from_rotation_matrix(&self.axes).inverse()
    }
    /// World angular momentum about the centre of mass.
    pub fn angular_momentum(&self) -> Vector3<f64> {
        self.angular_momentum
    }
    /// Angular momentum in the principal frame.
    pub fn angular_momentum_principal(&self) -> Vector3<f64> {
        self.orientation
            .inverse_transform_vector(&self.angular_momentum)
    }
    /// Angular velocity in the principal frame, `I⁻¹ L_p`.
    pub(crate) fn omega_principal(&self) -> Vector3<f64> {
        self.angular_momentum_principal()
            .component_mul(&self.inv_moments)
    }
    /// Angular velocity in world, `R_p I⁻¹ R_pᵀ L`.
    pub fn omega_world(&self) -> Vector3<f64> {
        self.orientation.transform_vector(&self.omega_principal())
    }
    /// World inverse inertia tensor about the centre of mass.
    pub(crate) fn inverse_inertia_world(&self) -> Matrix3<f64> {
        let r = self.orientation.to_rotation_matrix();
        r.matrix() * Matrix3::from_diagonal(&self.inv_moments) * r.matrix().transpose()
    }
    /// Translational kinetic energy `|p|²/2m`.
    pub(crate) fn kinetic_translational(&self) -> f64 {
        0.5 * self.momentum.norm_squared() / self.mass
    }
    /// Rotational kinetic energy `½ L·ω`.
    pub(crate) fn kinetic_rotational(&self) -> f64 {
        let l = self.angular_momentum_principal();
        0.5 * l.component_mul(&l).dot(&self.inv_moments)
    }

    /// Body-frame point (mesh axes, relative to the centre of mass) → world.
    pub fn point_to_world(&self, x_body: &Point3<f64>) -> Point3<f64> {
        self.position + self.vector_to_world(&x_body.coords)
    }
    /// World point → body frame.
    pub fn point_to_body(&self, x_world: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.vector_to_body(&(x_world - self.position)))
    }
    /// Body-frame vector → world (rotation only).
    pub(crate) fn vector_to_world(&self, v_body: &Vector3<f64>) -> Vector3<f64> {
        self.orientation
            .transform_vector(&self.axes.inverse_transform_vector(v_body))
    }
    /// World vector → body frame.
    pub fn vector_to_body(&self, v_world: &Vector3<f64>) -> Vector3<f64> {
        self.axes
            .transform_vector(&self.orientation.inverse_transform_vector(v_world))
    }
    /// Velocity of the material point currently at world position `x_world`: `v + ω × (x − r)`.
    pub(crate) fn point_velocity(&self, x_world: &Point3<f64>) -> Vector3<f64> {
        self.velocity() + self.omega_world().cross(&(x_world - self.position))
    }

    /// Sets the centre of mass position.
    ///
    /// # Errors
    /// Non-finite input.
    pub fn set_position(&mut self, r: Point3<f64>) -> Result<(), BodyError> {
        check_finite_vec(&r.coords, "position")?;
        self.position = r;
        Ok(())
    }
    /// Sets the velocity of the centre of mass (`p = m v`).
    ///
    /// # Errors
    /// Non-finite input.
    pub fn set_velocity(&mut self, v: Vector3<f64>) -> Result<(), BodyError> {
        check_finite_vec(&v, "velocity")?;
        self.momentum = v * self.mass;
        Ok(())
    }
    /// Sets the principal → world orientation.
    ///
    /// # Errors
    /// Non-finite input.
    pub fn set_orientation(&mut self, q: UnitQuaternion<f64>) -> Result<(), BodyError> {
        check_finite_vec(&q.imag(), "orientation")?;
        if !q.w.is_finite() {
            return Err(BodyError::NonFinite("orientation"));
        }
        self.orientation = q;
        Ok(())
    }
    /// Sets the body (mesh) frame → world orientation ([`Body::body_orientation`]): the
    /// identity places the body as its mesh lies, world axes = mesh axes.
    ///
    /// # Errors
    /// Non-finite input.
    pub fn set_body_orientation(&mut self, q: UnitQuaternion<f64>) -> Result<(), BodyError> {
        self.set_orientation(q * UnitQuaternion::from_rotation_matrix(&self.axes))
    }
    /// Sets the angular velocity given in the principal frame (`L = R_p I ω`).
    ///
    /// # Errors
    /// Non-finite input.
    pub fn set_omega_principal(&mut self, w: Vector3<f64>) -> Result<(), BodyError> {
        let l = w.component_mul(&self.moments);
        check_finite_vec(&l, "angular velocity")?;
        self.angular_momentum = self.orientation.transform_vector(&l);
        Ok(())
    }
    /// Applies an impulse `J` at world point `x`: `Δp = J`, `ΔL = (x − r) × J`.
    ///
    /// # Errors
    /// Non-finite input (the body is then unchanged).
    pub(crate) fn apply_impulse_at(
        &mut self,
        x: &Point3<f64>,
        j: &Vector3<f64>,
    ) -> Result<(), BodyError> {
        check_finite_vec(&x.coords, "impulse point")?;
        check_finite_vec(j, "impulse")?;
        let dl = (x - self.position).cross(j);
        check_finite_vec(&dl, "angular impulse")?;
        self.momentum += j;
        self.angular_momentum += dl;
        Ok(())
    }
}

/// Principal moments (ascending) and right-handed axes (columns) of a symmetric tensor.
fn principal_of_tensor(inertia: &Matrix3<f64>) -> Result<(Vector3<f64>, Matrix3<f64>), BodyError> {
    if !inertia.iter().all(|x| x.is_finite()) {
        return Err(BodyError::NonFinite("inertia tensor"));
    }
    let scale = inertia.amax();
    if (inertia - inertia.transpose()).amax() > SYMMETRY_SLACK * scale {
        return Err(BodyError::AsymmetricInertia);
    }
    // massprops' Jacobi solver: relative accuracy at any scale, where nalgebra's QR iteration
    // lost the 1e-12 round trip on nearly equal moments.
    let (values, vectors) = massprops::principal::symmetric_eigen(inertia);
    Ok(sorted_principal(values, vectors))
}

fn validate_mass_properties(
    mass: f64,
    moments: Vector3<f64>,
    axes: Matrix3<f64>,
) -> Result<(Vector3<f64>, Rotation3<f64>), BodyError> {
    if !(mass.is_finite() && mass > 0.0 && (1.0 / mass).is_finite()) {
        return Err(BodyError::InvalidMass(mass));
    }
    check_finite_vec(&moments, "principal moments")?;
    if !axes.iter().all(|x| x.is_finite()) {
        return Err(BodyError::NonFinite("principal axes"));
    }
    let (m, a) = sorted_principal(moments, axes);
    let arr = [m.x, m.y, m.z];
    if arr.iter().any(|&i| !(i > 0.0 && (1.0 / i).is_finite())) {
        return Err(BodyError::NonPositiveInertia(arr));
    }
    if m.x + m.y < m.z * (1.0 - TRIANGLE_SLACK) {
        return Err(BodyError::TriangleInequality(arr));
    }
    // Re-orthonormalise so a slightly sloppy caller rotation cannot leak scale into the state.
    // Starting from the matrix itself, an already orthonormal one is kept to round-off.
    let rot =
        Rotation3::from_matrix_eps(&a, f64::EPSILON, 100, Rotation3::from_matrix_unchecked(a));
    Ok((m, rot))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn the_body_orientation_set_is_the_one_read() {
        let axes = Rotation3::from_euler_angles(0.4, -1.2, 2.5);
        let mut body =
            Body::from_principal(2.0, Vector3::new(1.0, 2.0, 3.0), axes).expect("a body");
        let q = UnitQuaternion::from_euler_angles(-0.3, 0.9, 0.1);
        body.set_body_orientation(q).expect("finite");
        assert!(body.body_orientation().angle_to(&q) < 1e-15);
        // A body point goes where the body orientation takes it.
        let p = Point3::new(0.3, -0.2, 0.5);
        assert!((body.point_to_world(&p) - q * p).norm() < 1e-15);
    }

    #[test]
    fn rejects_bad_mass_properties() {
        let ok = Vector3::new(1.0, 2.0, 3.0);
        assert_eq!(
            Body::from_moments(0.0, ok),
            Err(BodyError::InvalidMass(0.0))
        );
        assert!(Body::from_moments(f64::NAN, ok).is_err());
        assert!(Body::from_moments(1.0, Vector3::new(1.0, 2.0, f64::INFINITY)).is_err());
        assert!(matches!(
            Body::from_moments(1.0, Vector3::new(-1.0, 2.0, 3.0)),
            Err(BodyError::NonPositiveInertia(_))
        ));
        assert!(matches!(
            Body::from_moments(1.0, Vector3::new(1.0, 1.0, 3.0)),
            Err(BodyError::TriangleInequality(_))
        ));
        let asym = Matrix3::new(1.0, 0.5, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 3.0);
        assert_eq!(
            Body::from_inertia_tensor(1.0, &asym),
            Err(BodyError::AsymmetricInertia)
        );
        // A flat plate sits exactly on the triangle inequality and is accepted.
        assert!(Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).is_ok());
    }

    #[test]
    fn tensor_is_diagonalised_ascending_and_right_handed() {
        // A box tensor diag(3, 1, 2) rotated by a known rotation: moments come back 1, 2, 3 and
        // the axes reproduce the tensor.
        let rot = Rotation3::from_euler_angles(0.3, -0.7, 1.1);
        let t = rot.matrix()
            * Matrix3::from_diagonal(&Vector3::new(3.0, 1.0, 2.0))
            * rot.matrix().transpose();
        let b = Body::from_inertia_tensor(2.0, &t).expect("valid tensor");
        assert!(close(b.moments().x, 1.0, 1e-13));
        assert!(close(b.moments().y, 2.0, 1e-13));
        assert!(close(b.moments().z, 3.0, 1e-13));
        let a = b.principal_axes();
        assert!(close(a.matrix().determinant(), 1.0, 1e-13));
        let back = a.matrix() * Matrix3::from_diagonal(&b.moments()) * a.matrix().transpose();
        assert!((back - t).amax() < 1e-12);
    }

    #[test]
    fn transforms_round_trip_and_follow_x_w_equals_r_x_plus_r() {
        let rot = Rotation3::from_euler_angles(0.2, 0.4, -0.9);
        let mut b = Body::from_principal(1.0, Vector3::new(1.0, 2.0, 3.0), rot).expect("valid");
        b.set_position(Point3::new(1.0, -2.0, 0.5)).expect("finite");
        b.set_orientation(UnitQuaternion::from_euler_angles(1.0, 0.1, 0.3))
            .expect("finite");
        let x = Point3::new(0.3, 0.7, -1.2);
        let xw = b.point_to_world(&x);
        let r = b.body_orientation().to_rotation_matrix();
        assert!((xw - (r * x + b.position().coords)).norm() < 1e-14);
        assert!((b.point_to_body(&xw) - x).norm() < 1e-14);
    }

    #[test]
    fn changing_mass_properties_keeps_momenta_and_pose() {
        let mut b = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).expect("valid");
        b.set_omega_principal(Vector3::new(0.5, 1.0, -2.0))
            .expect("finite");
        b.set_velocity(Vector3::new(1.0, 0.0, 0.0)).expect("finite");
        let (l, p, pose) = (b.angular_momentum(), b.momentum(), b.body_orientation());
        // Doubling every dimension at fixed density: mass ×8, inertia ×32.
        b.set_mass_properties(8.0, Vector3::new(32.0, 64.0, 96.0), Rotation3::identity())
            .expect("valid");
        assert_eq!(b.angular_momentum(), l);
        assert_eq!(b.momentum(), p);
        assert!(b.body_orientation().angle_to(&pose) < 1e-15);
        assert!((b.omega_principal() - Vector3::new(0.5, 1.0, -2.0) / 32.0).norm() < 1e-15);
    }
}
