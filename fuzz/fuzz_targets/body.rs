//! Body-file text through the parser and back: whatever parses must write text that parses to
//! the same parts.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;
use massprops::BodyFile;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(body) = BodyFile::parse(text, Path::new("fuzz.toml")) {
        let again = BodyFile::parse(&body.to_toml(), Path::new("fuzz.toml"))
            .expect("written text reads back");
        assert_eq!(again.parts.len(), body.parts.len());
        for (a, b) in again.parts.iter().zip(&body.parts) {
            assert_eq!((&a.name, &a.mesh, &a.object), (&b.name, &b.mesh, &b.object));
            assert_eq!((&a.material, a.void, a.thin_wall), (&b.material, b.void, b.thin_wall));
            assert_eq!((a.rotation, a.translation), (b.rotation, b.translation));
        }
    }
});
