//! Time integrators, selectable at run time with [`Integrator`], and the [`RotationModel`] switch.
//!
//! All of them advance the same state (position, linear momentum, principal→world quaternion,
//! world angular momentum). Forces evaluated inside a step are gravity, the plain spring and
//! applied forces; impulses (poke, soft string) and damping are applied by [`crate::Simulation`]
//! around the step.

use std::fmt;
use std::str::FromStr;

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use crate::body::Body;
use crate::forces::ForceModel;

pub mod engine;
pub mod exact;
pub mod midpoint_cayley;
pub mod rk4;
pub mod splitting;
pub mod textbook;

/// Which equations of rotational motion are integrated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum RotationModel {
    /// Euler's equations: `dL/dt = τ` in world, i.e. `I ω̇ = τ_b − ω × Iω` in the body frame.
    #[default]
    Full,
    /// The textbook shortcut `I ω̇ = τ_b` without the gyroscopic term `ω × Iω`. **Wrong for
    /// torque-free motion**: a free body keeps a fixed body-frame ω, never flips, and its world
    /// angular momentum vector rotates, although E and |L| stay constant.
    Textbook,
}

impl RotationModel {
    /// The CLI name.
    pub fn name(self) -> &'static str {
        match self {
            RotationModel::Full => "full",
            RotationModel::Textbook => "textbook",
        }
    }
}

impl fmt::Display for RotationModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown integrator or model name.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown {kind} '{given}', expected one of: {expected}")]
pub struct ParseNameError {
    kind: &'static str,
    given: String,
    expected: String,
}

impl FromStr for RotationModel {
    type Err = ParseNameError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "full" => Ok(RotationModel::Full),
            "textbook" => Ok(RotationModel::Textbook),
            _ => Err(ParseNameError {
                kind: "rotation model",
                given: s.to_owned(),
                expected: "full, textbook".to_owned(),
            }),
        }
    }
}

/// The time integrators. Costs are measured by `cargo bench -p rbcore` (see README).
///
/// ```
/// use nalgebra::Vector3;
/// use rbcore::{Body, Integrator, RotationModel, Settings, Simulation};
///
/// // A symmetric top, I = (2, 2, 3), at ω = (1, 0, 3): in the body ω turns about axis 3 at
/// // Ω = (I₃ − I₁)/I₁ · ω₃ = 1.5 rad/s, so ω(t) = (cos Ωt, sin Ωt, 3).
/// let mut body = Body::from_moments(1.0, Vector3::new(2.0, 2.0, 3.0)).unwrap();
/// body.set_omega_principal(Vector3::new(1.0, 0.0, 3.0)).unwrap();
/// let after_one_second = |integrator, model| {
///     let settings = Settings { integrator, model, ..Settings::default() };
///     let mut sim = Simulation::new(body, settings).unwrap();
///     for _ in 0..240 {
///         sim.step().unwrap();
///     }
///     sim.diagnostics().omega_principal
/// };
/// let exact = Vector3::new(1.5f64.cos(), 1.5f64.sin(), 3.0);
/// let error = |i| (after_one_second(i, RotationModel::Full) - exact).norm();
/// assert!(error(Integrator::Exact) < 1e-9);
/// assert!(error(Integrator::MidpointCayley) < 1e-4); // second order at 1/240 s
/// // The textbook model, without ω × Iω, keeps ω fixed in the body (to rounding).
/// let textbook = after_one_second(Integrator::default(), RotationModel::Textbook);
/// assert!((textbook - Vector3::new(1.0, 0.0, 3.0)).norm() < 1e-10);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Integrator {
    /// **Default.** Strang splitting: force half-kick → free rotation → half-kick. The free
    /// rotation is the implicit midpoint rule on body-frame L (Newton-solved to round-off) with the
    /// orientation advanced by the Cayley map of `h ω̄`, which makes world L exactly invariant.
    /// Second order, symplectic, time-reversible; conserves E, |L| and the world L vector to
    /// round-off for a free body. One 3×3 Newton solve (2-4 iterations) per step.
    #[default]
    MidpointCayley,
    /// Symplectic splitting of the free rotor into exact rotations about the principal axes,
    /// order R3(h/2) R2(h/2) R1(h) R2(h/2) R3(h/2) (Touma & Wisdom 1994; McLachlan 1993; Dullweber,
    /// Leimkuhler & McLachlan 1997). Second order; |L| and world L exact, E bounded (no drift).
    /// Five axis rotations (sin/cos) per step.
    Splitting,
    /// Classical fourth-order Runge-Kutta on (position, quaternion, momentum, L), quaternion
    /// renormalised each step. Fourth order but not symplectic: E drifts secularly, which near the
    /// flip separatrix shifts the flip period. Four force evaluations per step.
    Rk4,
    /// Textbook explicit Euler with the orientation as a rotation matrix, `Ṙ = [ω]ₓR`,
    /// Gram-Schmidt re-orthonormalisation after every step. First order; energy grows. Cheap.
    Euler,
    /// Textbook explicit midpoint (RK2) on the same rotation-matrix state, Gram-Schmidt after
    /// every step. Second order, not symplectic; energy drifts. Two evaluations per step.
    Midpoint,
    /// The exact torque-free flow: body L by Jacobi elliptic functions (van Zon & Schofield 2007,
    /// J. Comput. Phys. 225; Celledoni, Fassò, Säfström & Zanna 2008, SIAM J. Sci. Comput.), the
    /// precession angle about L by Gauss-Legendre quadrature of its closed-form rate. Exact to
    /// round-off for a free body at any step; forces enter by Strang half-kicks. The reference
    /// the others are measured against. Costs AGM iterations and an elliptic integral per step.
    Exact,
    /// Engine comparison (Jolt, PhysX, Rapier, Avian): explicit gyroscopic step
    /// `L ← L + h L×ω`, rescaled to the old |L|, then `q ← q + ½h ω q` normalised. First order;
    /// E drifts toward `L²/2I₂`, so a major-axis spin starts tumbling and the flip period is off.
    EngineStyle,
    /// Engine comparison (Bullet, Box3D): backward Euler on the gyroscopic term,
    /// `L' = L + h L'×ω'` (Newton-solved), then `q ← q + ½h ω' q` normalised. First order;
    /// E and |L| decrease every step (numerical dissipation).
    ImplicitEuler,
}

impl Integrator {
    /// Every integrator, default first.
    pub const ALL: [Integrator; 8] = [
        Integrator::MidpointCayley,
        Integrator::Splitting,
        Integrator::Rk4,
        Integrator::Euler,
        Integrator::Midpoint,
        Integrator::Exact,
        Integrator::EngineStyle,
        Integrator::ImplicitEuler,
    ];

    /// The kebab-case name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Integrator::MidpointCayley => "midpoint-cayley",
            Integrator::Splitting => "splitting",
            Integrator::Rk4 => "rk4",
            Integrator::Euler => "euler",
            Integrator::Midpoint => "midpoint",
            Integrator::Exact => "exact",
            Integrator::EngineStyle => "engine-style",
            Integrator::ImplicitEuler => "implicit-euler",
        }
    }

    /// Advances `body` by `h` under `forces` with the given rotation model.
    pub(crate) fn step(self, body: &mut Body, forces: &ForceModel, h: f64, model: RotationModel) {
        match self {
            Integrator::MidpointCayley => {
                kick_rotate_kick(body, forces, h, model, midpoint_cayley::free_rotor)
            }
            Integrator::Splitting => {
                kick_rotate_kick(body, forces, h, model, splitting::free_rotor)
            }
            Integrator::Exact => kick_rotate_kick(body, forces, h, model, exact::free_rotor),
            Integrator::Rk4 => rk4::step(body, forces, h, model),
            Integrator::Euler => textbook::euler_step(body, forces, h, model),
            Integrator::Midpoint => textbook::midpoint_step(body, forces, h, model),
            Integrator::EngineStyle => {
                engine::step(body, forces, h, model, engine::Gyroscopic::ExplicitRescaled)
            }
            Integrator::ImplicitEuler => {
                engine::step(body, forces, h, model, engine::Gyroscopic::BackwardEuler)
            }
        }
    }
}

impl fmt::Display for Integrator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Integrator {
    type Err = ParseNameError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Integrator::ALL
            .into_iter()
            .find(|i| i.name() == s)
            .ok_or_else(|| ParseNameError {
                kind: "integrator",
                given: s.to_owned(),
                expected: Integrator::ALL.map(Integrator::name).join(", "),
            })
    }
}

/// `Δp = F h`, `ΔL = τ h` with the wrench of the current state.
fn kick(body: &mut Body, forces: &ForceModel, h: f64) {
    let w = forces.wrench(body);
    body.momentum += w.force * h;
    body.angular_momentum += w.torque * h;
}

/// Strang splitting of forces around a free-body flow (Hairer, Lubich & Wanner, *Geometric
/// Numerical Integration*, 2nd ed., §II.5 and §VII.5): half-kick, drift + free rotation, half-kick.
/// Symplectic and second order whenever the free rotation is.
fn kick_rotate_kick(
    body: &mut Body,
    forces: &ForceModel,
    h: f64,
    model: RotationModel,
    free_rotor: fn(&mut Body, f64),
) {
    kick(body, forces, 0.5 * h);
    body.position += body.momentum * (h / body.mass);
    match model {
        RotationModel::Full => free_rotor(body, h),
        RotationModel::Textbook => textbook_free_flow(body, h),
    }
    kick(body, forces, 0.5 * h);
}

/// Exact free flow of the textbook model: body-frame L (hence ω) constant, the body turns about the
/// fixed body axis ω by `|ω| h`.
pub(crate) fn textbook_free_flow(body: &mut Body, h: f64) {
    let l_b = body.angular_momentum_principal();
    body.orientation *= UnitQuaternion::from_scaled_axis(body.omega_principal() * h);
    body.angular_momentum = body.orientation.transform_vector(&l_b);
}

/// `(0, ω) ⊗ q / 2`: the quaternion rate for world angular velocity `ω`.
pub(crate) fn quaternion_rate(q: &Quaternion<f64>, omega_world: &Vector3<f64>) -> Quaternion<f64> {
    Quaternion::from_imag(*omega_world) * q * 0.5
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for i in Integrator::ALL {
            assert_eq!(i.name().parse::<Integrator>(), Ok(i));
            assert_eq!(i.to_string(), i.name());
        }
        assert_eq!(
            "textbook".parse::<RotationModel>(),
            Ok(RotationModel::Textbook)
        );
        assert!("Euler".parse::<Integrator>().is_err());
        assert_eq!(Integrator::default(), Integrator::MidpointCayley);
    }
}
