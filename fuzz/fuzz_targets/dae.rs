//! COLLADA text (node trees, instances, every primitive kind) through the reader and every analysis.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

mod common;

fuzz_target!(|data: &[u8]| {
    if let Ok(file) = massprops::parse_mesh(data, Path::new("fuzz.dae")) {
        common::analyze_every_way(&file);
    }
});
