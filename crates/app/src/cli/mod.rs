//! The command-line entry points: `props` (mass properties of a mesh and the report as a table or
//! JSON), `simulate` (headless simulation as CSV in the [`crate::timeseries`] schema) and
//! `export` (engine and robot formats), `audit` (a robot description's links against their
//! geometry), with their exit codes ([`error`]).

pub mod animation;
pub mod audit;
mod choice;
pub mod error;
pub mod export;
pub mod parts;
pub mod props;
pub mod repair;
pub mod simulate;

pub use error::CliError;
