//! Body-file text through the parser and back: whatever parses must write text that parses to
//! the same parts.
#![no_main]

use libfuzzer_sys::fuzz_target;

mod common;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        common::body_round_trip(text);
    }
});
