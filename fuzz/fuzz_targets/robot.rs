//! URDF, MJCF and SDFormat text through the readers, the audit and the fix.
#![no_main]

use libfuzzer_sys::fuzz_target;

mod robot_common;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        robot_common::audit_and_fix(text);
    }
});
