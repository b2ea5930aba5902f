//! A measured-masses file (`audit --masses`), as CSV and as TOML, through its readers: any
//! panic is a bug; a refusal must name the file. What reads holds only finite positive masses
//! and finite centres.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for (read, name) in [
        (robot::parse_csv as fn(&str, &Path) -> _, "fuzz/masses.csv"),
        (robot::parse_toml, "fuzz/masses.toml"),
    ] {
        match read(text, Path::new(name)) {
            Ok(masses) => {
                for m in masses.values() {
                    assert!(m.mass.is_finite() && m.mass > 0.0, "{}", m.mass);
                    if let Some(c) = m.center_of_mass {
                        assert!(c.coords.iter().all(|x| x.is_finite()), "{c}");
                    }
                }
            }
            Err(e) => assert!(e.to_string().contains(name), "{e}"),
        }
    }
});
