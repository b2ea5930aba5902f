//! massprops' integration tests, one file a topic, linked as one binary: thirteen binaries took
//! 78 s of a non-incremental build (user 145 s) where two take 54 s (user 101 s), each linking
//! the crate and instantiating nalgebra's generics again.

#[path = "analyze.rs"]
mod analyze;
#[path = "bad_input.rs"]
mod bad_input;
#[path = "body_files.rs"]
mod body_files;
#[path = "claims.rs"]
mod claims;
#[path = "closed_forms.rs"]
mod closed_forms;
mod common;
#[path = "composite.rs"]
mod composite;
#[path = "defects.rs"]
mod defects;
#[path = "laws.rs"]
mod laws;
#[path = "numerics.rs"]
mod numerics;
#[path = "paths.rs"]
mod paths;
