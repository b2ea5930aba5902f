//! Material presets: names a user can give instead of a density, in kg/m³.

/// A named density.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// The name used on the command line and in body files (lower case).
    pub name: &'static str,
    /// Density in kg/m³.
    pub density: f64,
    /// Where the value comes from, or what it stands for.
    pub note: &'static str,
}

/// Every preset, lightest first.
pub const MATERIALS: [Material; 9] = [
    Material {
        name: "foam",
        density: 30.0,
        note: "expanded polystyrene (15–45)",
    },
    Material {
        name: "wood",
        density: 600.0,
        note: "a mid value: balsa 150, pine 500, oak 750, ebony 1100",
    },
    Material {
        name: "water",
        density: 1000.0,
        note: "999.97 at 4 °C",
    },
    Material {
        name: "pla",
        density: 1240.0,
        note: "PLA filament, solid (datasheets give 1210–1250)",
    },
    Material {
        name: "rubber",
        density: 1500.0,
        note: "vulcanised (1100–1800)",
    },
    Material {
        name: "aluminium",
        density: 2700.0,
        note: "pure 2699; 6061 alloy 2700",
    },
    Material {
        name: "steel",
        density: 7850.0,
        note: "carbon steel",
    },
    Material {
        name: "brass",
        density: 8500.0,
        note: "8400–8730",
    },
    Material {
        name: "lead",
        density: 11340.0,
        note: "pure",
    },
];

/// The preset of that name (case-insensitive; `aluminum` is `aluminium`).
pub fn material(name: &str) -> Option<Material> {
    let name = name.to_ascii_lowercase();
    let name = if name == "aluminum" {
        "aluminium"
    } else {
        &name
    };
    MATERIALS.iter().copied().find(|m| m.name == name)
}

/// The presets' names, for messages: "foam, wood, water, …".
pub fn material_names() -> String {
    MATERIALS.map(|m| m.name).join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_found_by_name_and_sorted_by_density() {
        assert_eq!(material("Steel").map(|m| m.density), Some(7850.0));
        assert_eq!(material("aluminum").map(|m| m.name), Some("aluminium"));
        assert!(material("unobtainium").is_none());
        assert!(MATERIALS.windows(2).all(|w| w[0].density < w[1].density));
        assert!(material_names().starts_with("foam, wood, water"));
    }
}
