//! Length units: the one list a body file, the exporters and the command line share. Each is an
//! exact number of metres (the inch and foot by their 1959 international definitions).

use std::fmt;
use std::str::FromStr;

/// A length unit of a mesh, a body file or a target format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum LengthUnit {
    /// Metre.
    #[default]
    M,
    /// Centimetre.
    Cm,
    /// Millimetre.
    Mm,
    /// International inch, 25.4 mm.
    In,
    /// International foot, 304.8 mm.
    Ft,
}

impl LengthUnit {
    /// Every unit, in the order messages list them.
    pub const ALL: [LengthUnit; 5] = [
        LengthUnit::M,
        LengthUnit::Cm,
        LengthUnit::Mm,
        LengthUnit::In,
        LengthUnit::Ft,
    ];

    /// Metres per unit (exact by definition of each unit).
    ///
    /// ```
    /// assert_eq!(massprops::LengthUnit::In.metres(), 0.0254);
    /// ```
    pub fn metres(self) -> f64 {
        match self {
            LengthUnit::M => 1.0,
            LengthUnit::Cm => 0.01,
            LengthUnit::Mm => 0.001,
            LengthUnit::In => 0.0254,
            LengthUnit::Ft => 0.3048,
        }
    }

    /// The unit's symbol, as files and the command line write it.
    pub fn symbol(self) -> &'static str {
        match self {
            LengthUnit::M => "m",
            LengthUnit::Cm => "cm",
            LengthUnit::Mm => "mm",
            LengthUnit::In => "in",
            LengthUnit::Ft => "ft",
        }
    }

    /// The symbols, comma-separated, for messages.
    pub fn symbols() -> String {
        Self::ALL.map(Self::symbol).join(", ")
    }
}

impl fmt::Display for LengthUnit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.symbol())
    }
}

/// A symbol that is not one of [`LengthUnit::ALL`]'s.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown unit {0:?} (use one of {units})", units = LengthUnit::symbols())]
pub struct UnknownUnit(pub String);

impl FromStr for LengthUnit {
    type Err = UnknownUnit;

    /// Reads a symbol, in any case.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|u| u.symbol().eq_ignore_ascii_case(s))
            .ok_or_else(|| UnknownUnit(s.to_owned()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbols_read_back_in_any_case() {
        for u in LengthUnit::ALL {
            assert_eq!(u.symbol().parse::<LengthUnit>(), Ok(u));
            assert_eq!(u.symbol().to_uppercase().parse::<LengthUnit>(), Ok(u));
        }
        let e = "yd".parse::<LengthUnit>().expect_err("no yards");
        assert_eq!(
            e.to_string(),
            "unknown unit \"yd\" (use one of m, cm, mm, in, ft)"
        );
    }
}
