//! Inertia Lab's input path and outputs, shared by every front end (the command line, the app,
//! the page and the Python package), in parts that depend in one direction:
//! - [`wording`]: how numbers, faces, lines and lists are written;
//! - [`conventions`]: what every output says of its numbers (the tensor's signs, the axes);
//! - [`choice`]: options with a fixed list of values (format, frame, up axis), listed once;
//! - [`kind`]: what a file holds (mesh, body, robot), and the extension lists every front end
//!   offers, written from massprops' mesh-format table;
//! - [`input`]: the one input path, a file and the mass and repair flags → a body;
//! - [`export`]: mass properties written for engines and robot formats (pure functions), and
//!   whole files with the body's mesh;
//! - [`bake`]: a body spun by rbcore and its keyframes written as a glTF or USD animation;
//! - [`report`]: `props`' and `audit`'s reports, as a table and as JSON, and their words;
//! - [`batch`]: the batch table, one row per file whatever it holds (the Python package's).
//!
//! Nothing here knows a command line or a window (the dynamics are rbcore's, which `bake` only
//! runs): ripgrep keeps its printer in a library crate under a thin binary, and polars' Python
//! layer depends on library crates only.

pub mod bake;
pub mod batch;
pub mod choice;
pub mod conventions;
pub mod export;
pub mod input;
pub mod kind;
pub mod report;
pub mod wording;
