//! Inertia Lab: exact mass properties of any mesh, and how they shape its rotation.
//!
//! The library behind the `inertia-lab` binary, over the `inertia-io` crate (the input path,
//! the reports, the exports, the batch table), in parts that depend in one direction:
//! - [`timeseries`]: the one time-series schema (CSV columns) of `simulate` and the app's plots;
//! - [`platform`]: what the system tells about the process (its memory);
//! - [`cli`]: the `props`, `simulate`, `export` and `audit` commands: their flags and exit codes;
//! - [`i18n`]: the words of the window, the page and the live description, in the user's
//!   language (Fluent message files in `messages/`);
//! - [`lab`]: the app's headless model (specimens, commands, loader, bodies of parts, picking);
//! - `gui` (feature `gui`, default on): the desktop app drawing the lab with eframe and three-d.
//!
//! `ARCHITECTURE.md` gives the allowed dependencies of each folder.

// The page never runs the command line: it is not compiled into the WebAssembly module (nor is
// clap, a desktop-only dependency).
#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
#[cfg(feature = "gui")]
pub mod gui;
pub mod i18n;
pub mod lab;
pub mod platform;
pub mod timeseries;
