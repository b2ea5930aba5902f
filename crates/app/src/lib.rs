//! Inertia Lab: exact mass properties of any mesh, and how they shape its rotation.
//!
//! The library behind the `inertia-lab` binary, in parts that depend in one direction:
//! - [`export`]: mass properties written for engines and robot formats (pure functions);
//! - [`timeseries`]: the one time-series schema (CSV columns) of `simulate` and the app's plots;
//! - [`input`]: the one input path, a file and the mass and repair flags → a body;
//! - [`wording`]: how faces, lines and lists are written, for every front end's words;
//! - [`platform`]: what the system tells about the process (its memory);
//! - [`batch`]: the batch table, one row per file whatever it holds (the Python package's);
//! - [`cli`]: the `props`, `simulate` and `export` commands and their reports;
//! - [`lab`]: the app's headless model (specimens, commands, loader, bodies of parts, picking);
//! - `gui` (feature `gui`, default on): the desktop app drawing the lab with eframe and three-d.
//!
//! `ARCHITECTURE.md` gives the allowed dependencies of each folder.

pub mod batch;
pub mod cli;
pub mod export;
pub mod findings;
#[cfg(feature = "gui")]
pub mod gui;
pub mod input;
pub mod lab;
pub mod platform;
pub mod timeseries;
pub mod wording;
