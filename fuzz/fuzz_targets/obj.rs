//! OBJ text through the reader and every analysis, and the fast path against tobj's.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

mod common;

fuzz_target!(|data: &[u8]| {
    // Where the fast path reads a file at all, it reads it as tobj does.
    assert!(massprops::io::fast_path_agrees(data), "the two OBJ paths differ");
    if let Ok(file) = massprops::parse_mesh(data, Path::new("fuzz.obj")) {
        common::analyze_every_way(&file);
    }
});
