//! Typed errors: invalid bodies and settings are rejected up front, and a diverging run stops with
//! [`SimError::Diverged`] instead of producing NaN.

/// A body, force or setting that cannot be simulated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BodyError {
    /// Mass must be finite and strictly positive.
    #[error("mass must be finite and positive, got {0}")]
    InvalidMass(f64),
    /// A vector, point or scalar input was NaN or infinite.
    #[error("{0} must be finite")]
    NonFinite(&'static str),
    /// The inertia tensor is not symmetric (relative tolerance 1e-9).
    #[error("inertia tensor is not symmetric")]
    AsymmetricInertia,
    /// A principal moment is zero, negative or so small that its inverse overflows.
    #[error("principal moments must be positive, got {0:?}")]
    NonPositiveInertia([f64; 3]),
    /// No rigid body has these moments: the largest exceeds the sum of the other two.
    #[error("principal moments {0:?} break the triangle inequality I1 + I2 >= I3")]
    TriangleInequality([f64; 3]),
    /// A force parameter (stiffness, frequency, damping, cap) is out of its documented range.
    #[error("{name} must be {requirement}, got {value}")]
    OutOfRange {
        /// Which parameter.
        name: &'static str,
        /// What it must be.
        requirement: &'static str,
        /// What was given.
        value: f64,
    },
}

/// A failure while running a [`crate::Simulation`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    /// The settings are invalid (see [`crate::Settings::validate`]).
    #[error("invalid setting: {0}")]
    InvalidSetting(BodyError),
    /// The state became non-finite or absurdly large; the simulation is stopped at the last good state.
    #[error("simulation diverged at t = {time} s (step {step}): {quantity} is {value}")]
    Diverged {
        /// Simulated time of the failed step.
        time: f64,
        /// Index of the failed step.
        step: u64,
        /// Which state quantity failed the check.
        quantity: &'static str,
        /// Its magnitude (may be NaN or infinite).
        value: f64,
    },
}
