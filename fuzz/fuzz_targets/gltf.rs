//! glTF or GLB bytes (node trees, quantized and sparse accessors) through the reader and every
//! analysis; a buffer in a file of its own is never read.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

mod common;

fuzz_target!(|data: &[u8]| {
    let none = |_: &str| Err("no files beside it".to_owned());
    if let Ok(file) = massprops::io::parse_gltf_with(data, Path::new("fuzz.gltf"), &none) {
        common::analyze_every_way(&file);
    }
});
