//! Errors of the command-line entry points, mapped to the documented exit codes.

use std::process::ExitCode;

/// What went wrong in a command; each variant has its own exit code.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// The arguments are inconsistent or out of range (exit code 2, like clap's own usage errors).
    #[error("{0}")]
    Usage(String),
    /// The input file or mesh cannot be used (exit code 3).
    #[error("{0}")]
    Input(String),
    /// Writing the output failed, or a simulation diverged (exit code 1).
    #[error("{0}")]
    Runtime(String),
}

impl CliError {
    /// The process exit code documented in docs/props.md.
    pub fn exit_code(&self) -> ExitCode {
        match self {
            CliError::Usage(_) => ExitCode::from(2),
            CliError::Input(_) => ExitCode::from(3),
            CliError::Runtime(_) => ExitCode::from(1),
        }
    }
}

/// A command-line number that must be finite and greater than zero (a usage error otherwise).
pub fn positive(name: &str, v: f64) -> Result<f64, CliError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(CliError::Usage(format!(
            "{name} must be a finite number greater than zero, got {v}"
        )))
    }
}

impl From<inertia_io::input::InputError> for CliError {
    fn from(e: inertia_io::input::InputError) -> Self {
        use inertia_io::input::InputError;
        match e {
            InputError::UnknownPart { .. } | InputError::MassOfParts => {
                CliError::Usage(e.to_string())
            }
            InputError::Mesh { .. } | InputError::Read(_) => CliError::Input(e.to_string()),
        }
    }
}
