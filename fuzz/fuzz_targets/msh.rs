//! MuJoCo .msh bytes through the reader and every analysis.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

mod common;

fuzz_target!(|data: &[u8]| {
    if let Ok(file) = massprops::parse_mesh(data, Path::new("fuzz.msh")) {
        common::analyze_every_way(&file);
    }
});
