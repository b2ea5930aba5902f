//! The tests that read files outside this crate (the workspace's assets/ and fuzz/ corpora) or
//! third-party meshes (tests/data/real): one binary, left out of the package with its files.

#[path = "assets.rs"]
mod assets;
mod common;
#[path = "fuzz_regressions.rs"]
mod fuzz_regressions;
#[path = "real_meshes.rs"]
mod real_meshes;
