//! Inertia Lab: exact mass properties of any mesh, and how they shape its rotation.
//!
//! The library behind the `inertia-lab` binary, in four parts that depend in one direction:
//! - [`export`]: mass properties written for engines and robot formats (pure functions);
//! - [`timeseries`]: the one time-series schema (CSV columns) of `simulate` and the app's plots;
//! - [`cli`]: the `props`, `simulate` and `export` commands and their reports;
//! - [`lab`]: the app's headless model (specimens, commands, loader, picking, camera maths);
//! - `gui` (feature `gui`, default on): the desktop app drawing the lab with eframe and three-d.
//!
//! `ARCHITECTURE.md` gives the allowed dependencies of each folder.

pub mod cli;
pub mod export;
#[cfg(feature = "gui")]
pub mod gui;
pub mod lab;
pub mod timeseries;
