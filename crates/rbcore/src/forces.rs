//! Forces and impulses: force at a point, gravity, a plain spring-damper, the soft mouse string
//! (Catto's soft constraint), the poke impulse, and damping factors.

use nalgebra::{Matrix3, Point3, Vector3};

use crate::body::{Body, check_finite_vec};
use crate::error::BodyError;

/// A force and the torque it exerts about the centre of mass, both in world.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Wrench {
    /// Force.
    pub(crate) force: Vector3<f64>,
    /// Torque about the centre of mass.
    pub(crate) torque: Vector3<f64>,
}

impl Wrench {
    /// The wrench of force `f` applied at world point `x` on a body whose centre of mass is at
    /// `center`: `τ = (x − center) × f`.
    pub(crate) fn at_point(f: Vector3<f64>, x: &Point3<f64>, center: &Point3<f64>) -> Self {
        Self {
            force: f,
            torque: (x - center).cross(&f),
        }
    }
}

/// Gravity acts at the centre of mass: force `m g`, no torque.
pub(crate) fn gravity(body: &Body, g: &Vector3<f64>) -> Wrench {
    Wrench {
        force: g * body.mass(),
        torque: Vector3::zeros(),
    }
}

/// Gravitational potential energy `−m g·r` (zero at the world origin).
pub(crate) fn gravity_potential(body: &Body, g: &Vector3<f64>) -> f64 {
    -body.mass() * g.dot(&body.position().coords)
}

fn check_nonneg(name: &'static str, value: f64) -> Result<f64, BodyError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(BodyError::OutOfRange {
            name,
            requirement: "finite and non-negative",
            value,
        })
    }
}

/// A plain zero-rest-length spring-damper between a world anchor and a body point, integrated
/// explicitly like any other force. Kept for comparison with [`SoftString`]: it is only stable
/// while `ω_eff·dt` stays below about 2, so a stiff spring diverges.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spring {
    anchor: Point3<f64>,
    attachment: Point3<f64>,
    stiffness: f64,
    damping: f64,
}

impl Spring {
    /// A spring from world `anchor` to the body-frame point `attachment`, stiffness `k` (N/m) and
    /// damping `c` (N·s/m) on the attachment point's velocity.
    ///
    /// # Errors
    /// Non-finite points, negative or non-finite `k` or `c`.
    pub fn new(
        anchor: Point3<f64>,
        attachment: Point3<f64>,
        stiffness: f64,
        damping: f64,
    ) -> Result<Self, BodyError> {
        check_finite_vec(&anchor.coords, "spring anchor")?;
        check_finite_vec(&attachment.coords, "spring attachment")?;
        Ok(Self {
            anchor,
            attachment,
            stiffness: check_nonneg("spring stiffness", stiffness)?,
            damping: check_nonneg("spring damping", damping)?,
        })
    }
    /// Force `−k (x − a) − c v_x` at the attachment point, as a wrench.
    pub(crate) fn wrench(&self, body: &Body) -> Wrench {
        let x = body.point_to_world(&self.attachment);
        let f = -(x - self.anchor) * self.stiffness - body.point_velocity(&x) * self.damping;
        Wrench::at_point(f, &x, &body.position())
    }
    /// Elastic energy `½ k |x − a|²`.
    pub(crate) fn potential(&self, body: &Body) -> f64 {
        0.5 * self.stiffness * (body.point_to_world(&self.attachment) - self.anchor).norm_squared()
    }
}

/// The mouse string as a soft constraint `C = x − target = 0` on a body point, solved at the
/// velocity level once per step with Catto's soft step ("Soft Constraints", GDC 2011; the
/// frequency/damping-ratio form of Box2D v3):
///
/// `ω = 2πf`, `a₁ = 2ζ + hω`, `a₂ = hωa₁`, bias rate `β = ω/a₁`, mass scale `s = a₂/(1+a₂)`,
/// impulse `J = −s·K⁻¹(Ċ + βC)` with `K = m⁻¹·1 − [r]ₓ I_w⁻¹ [r]ₓ` the point's 3×3 inverse effective
/// mass, capped at `|J| ≤ F_max·h`.
///
/// As `f → ∞`, `s → 1` and `β → 1/h`: the step becomes a rigid projection, never an explosion,
/// so every frequency a user can set is stable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SoftString {
    target: Point3<f64>,
    attachment: Point3<f64>,
    frequency_hz: f64,
    damping_ratio: f64,
    max_force: f64,
}

impl SoftString {
    /// A string pulling body-frame point `attachment` toward world `target`.
    ///
    /// # Errors
    /// Non-finite points, `frequency_hz` not finite and positive, `damping_ratio` or `max_force`
    /// negative or NaN (`max_force` may be `f64::INFINITY` for no cap).
    pub fn new(
        target: Point3<f64>,
        attachment: Point3<f64>,
        frequency_hz: f64,
        damping_ratio: f64,
        max_force: f64,
    ) -> Result<Self, BodyError> {
        check_finite_vec(&target.coords, "string target")?;
        check_finite_vec(&attachment.coords, "string attachment")?;
        if !(frequency_hz.is_finite() && frequency_hz > 0.0) {
            return Err(BodyError::OutOfRange {
                name: "string frequency",
                requirement: "finite and positive",
                value: frequency_hz,
            });
        }
        if max_force.is_nan() || max_force < 0.0 {
            return Err(BodyError::OutOfRange {
                name: "string force cap",
                requirement: "non-negative",
                value: max_force,
            });
        }
        Ok(Self {
            target,
            attachment,
            frequency_hz,
            damping_ratio: check_nonneg("string damping ratio", damping_ratio)?,
            max_force,
        })
    }
    /// Moves the target (the mouse).
    ///
    /// # Errors
    /// Non-finite input.
    pub fn set_target(&mut self, target: Point3<f64>) -> Result<(), BodyError> {
        check_finite_vec(&target.coords, "string target")?;
        self.target = target;
        Ok(())
    }
    /// The world target.
    pub fn target(&self) -> Point3<f64> {
        self.target
    }
    /// The attachment point in body coordinates.
    pub fn attachment(&self) -> Point3<f64> {
        self.attachment
    }
    /// The impulse to apply at the attachment point's world position for a step of length `h`.
    /// Returns zero if the effective-mass matrix cannot be inverted (it is always SPD for a valid
    /// body, so that only guards against overflow).
    pub fn impulse(&self, body: &Body, h: f64) -> Vector3<f64> {
        let x = body.point_to_world(&self.attachment);
        let r = x - body.position();
        let rx = r.cross_matrix();
        let k = Matrix3::identity() / body.mass() - rx * body.inverse_inertia_world() * rx;
        let omega = 2.0 * std::f64::consts::PI * self.frequency_hz;
        let a1 = 2.0 * self.damping_ratio + h * omega;
        let a2 = h * omega * a1;
        let bias_rate = omega / a1;
        let mass_scale = a2 / (1.0 + a2);
        let c = x - self.target;
        let cdot = body.point_velocity(&x);
        let Some(chol) = k.cholesky() else {
            return Vector3::zeros();
        };
        let j = -mass_scale * chol.solve(&(cdot + c * bias_rate));
        let cap = self.max_force * h;
        let n = j.norm();
        if !n.is_finite() {
            Vector3::zeros()
        } else if n > cap {
            j * (cap / n)
        } else {
            j
        }
    }
    /// Energy of the equivalent spring `½ m (2πf)² |C|²` (Catto's `k = m ω²` with the body mass),
    /// reported in diagnostics; the constraint itself is dissipative.
    pub(crate) fn potential(&self, body: &Body) -> f64 {
        let omega = 2.0 * std::f64::consts::PI * self.frequency_hz;
        let c = body.point_to_world(&self.attachment) - self.target;
        0.5 * body.mass() * omega * omega * c.norm_squared()
    }
}

/// Optional exponential damping: `dp/dt = −c_lin p`, `dL/dt = −c_ang L` (rates in 1/s), applied
/// exactly as factors `exp(−c h)`, so no rate can overshoot or produce NaN.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Damping {
    /// Linear damping rate (1/s), ≥ 0.
    pub linear: f64,
    /// Angular damping rate (1/s), ≥ 0.
    pub angular: f64,
}

impl Damping {
    /// Checks both rates are finite and non-negative.
    ///
    /// # Errors
    /// A rate out of range.
    pub(crate) fn validate(&self) -> Result<(), BodyError> {
        check_nonneg("linear damping", self.linear)?;
        check_nonneg("angular damping", self.angular)?;
        Ok(())
    }
    /// Applies the exact decay over time `h`.
    pub(crate) fn apply(&self, body: &mut Body, h: f64) {
        if self.linear > 0.0 {
            body.momentum *= (-self.linear * h).exp();
        }
        if self.angular > 0.0 {
            body.angular_momentum *= (-self.angular * h).exp();
        }
    }
}

/// The forces evaluated inside a step (the soft string and pokes act as impulses instead).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ForceModel {
    pub gravity: Vector3<f64>,
    pub spring: Option<Spring>,
}

impl ForceModel {
    /// Total wrench on `body` in its current state.
    pub fn wrench(&self, body: &Body) -> Wrench {
        let mut w = gravity(body, &self.gravity);
        if let Some(s) = &self.spring {
            let ws = s.wrench(body);
            w.force += ws.force;
            w.torque += ws.torque;
        }
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn torque_is_lever_arm_cross_force() {
        let w = Wrench::at_point(
            Vector3::new(0.0, 2.0, 0.0),
            &Point3::new(3.0, 0.0, 0.0),
            &Point3::new(1.0, 0.0, 0.0),
        );
        assert_eq!(w.torque, Vector3::new(0.0, 0.0, 4.0));
    }

    #[test]
    fn soft_string_rejects_bad_parameters() {
        let o = Point3::origin();
        assert!(SoftString::new(o, o, 0.0, 1.0, 1.0).is_err());
        assert!(SoftString::new(o, o, f64::NAN, 1.0, 1.0).is_err());
        assert!(SoftString::new(o, o, 5.0, -1.0, 1.0).is_err());
        assert!(SoftString::new(o, o, 5.0, 1.0, f64::NAN).is_err());
        assert!(SoftString::new(o, o, 5.0, 0.0, f64::INFINITY).is_ok());
        assert!(Spring::new(o, o, -1.0, 0.0).is_err());
    }

    #[test]
    fn soft_string_at_infinite_stiffness_is_a_rigid_projection() {
        // Point mass limit: a body pulled at its centre. With f → ∞, one step must move the point
        // exactly onto the target: J = −m (v + C/h).
        let mut b = crate::Body::from_moments(2.0, Vector3::new(1.0, 1.0, 1.0)).expect("valid");
        b.set_velocity(Vector3::new(0.5, 0.0, 0.0)).expect("finite");
        let s = SoftString::new(
            Point3::new(1.0, 0.0, 0.0),
            Point3::origin(),
            1e12,
            1.0,
            f64::INFINITY,
        )
        .expect("valid");
        let h = 0.01;
        let j = s.impulse(&b, h);
        let expect = -2.0 * (Vector3::new(0.5, 0.0, 0.0) + Vector3::new(-1.0, 0.0, 0.0) / h);
        assert!((j - expect).norm() < 1e-6 * expect.norm());
        let capped = SoftString::new(Point3::new(1.0, 0.0, 0.0), Point3::origin(), 1e12, 1.0, 3.0)
            .expect("valid");
        assert!((capped.impulse(&b, h).norm() - 3.0 * h).abs() < 1e-15);
    }
}
