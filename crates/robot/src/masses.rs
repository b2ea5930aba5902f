//! Measured masses: a file that gives some links' masses as weighed (and, optionally, their
//! centres of mass as measured), which the audit weighs their geometry at and both fixes keep.
//!
//! Two forms, told apart by the file's extension:
//! - CSV (`.csv`): `link,mass` or `link,mass,x,y,z` per line, kg and m in the link's frame; a
//!   first line whose mass is not a number is a header; blank lines and lines starting with `#`
//!   are skipped.
//! - TOML (`.toml`): a table per link, `[links.NAME]` with `mass = …` and optionally
//!   `center_of_mass = [x, y, z]`, or a bare `NAME = mass` under `[links]`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use nalgebra::Point3;

/// A link's measured mass and, when measured too, its centre of mass (link frame).
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// kg.
    pub mass: f64,
    /// m, link frame.
    pub center_of_mass: Option<Point3<f64>>,
}

/// Measured values by link name.
pub type MeasuredMasses = BTreeMap<String, Measured>;

/// Why a masses file cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MassesError {
    /// The file cannot be read.
    #[error("{file}: cannot be read: {why}")]
    Io {
        /// The file.
        file: PathBuf,
        /// The system's words.
        why: String,
    },
    /// A line or entry is wrong.
    #[error("{file}:{line}: {what}")]
    Entry {
        /// The file.
        file: PathBuf,
        /// Its line (1-based; 0 where the TOML reader gives none).
        line: usize,
        /// What is wrong.
        what: String,
    },
    /// Neither `.csv` nor `.toml`.
    #[error("{0}: a masses file is .csv or .toml")]
    Format(PathBuf),
}

/// Reads a masses file.
pub fn read_masses(path: &Path) -> Result<MeasuredMasses, MassesError> {
    let text = std::fs::read_to_string(path).map_err(|e| MassesError::Io {
        file: path.to_owned(),
        why: e.to_string(),
    })?;
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("csv") => parse_csv(&text, path),
        Some("toml") => parse_toml(&text, path),
        _ => Err(MassesError::Format(path.to_owned())),
    }
}

fn entry(file: &Path, line: usize, what: impl Into<String>) -> MassesError {
    MassesError::Entry {
        file: file.to_owned(),
        line,
        what: what.into(),
    }
}

/// A measured mass must be a positive, finite number of kilograms.
fn checked(
    file: &Path,
    line: usize,
    link: &str,
    measured: Measured,
) -> Result<Measured, MassesError> {
    if !(measured.mass > 0.0 && measured.mass.is_finite()) {
        return Err(entry(
            file,
            line,
            format!(
                "link {link:?}: a measured mass must be positive, not {}",
                measured.mass
            ),
        ));
    }
    if let Some(c) = measured.center_of_mass
        && !c.iter().all(|v| v.is_finite())
    {
        return Err(entry(
            file,
            line,
            format!("link {link:?}: the centre is not finite"),
        ));
    }
    Ok(measured)
}

fn insert(
    masses: &mut MeasuredMasses,
    file: &Path,
    line: usize,
    link: &str,
    measured: Measured,
) -> Result<(), MassesError> {
    let measured = checked(file, line, link, measured)?;
    if masses.insert(link.to_owned(), measured).is_some() {
        return Err(entry(file, line, format!("link {link:?} is given twice")));
    }
    Ok(())
}

/// The CSV form.
pub fn parse_csv(text: &str, file: &Path) -> Result<MeasuredMasses, MassesError> {
    let mut masses = MeasuredMasses::new();
    let mut first = true;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let row = raw.trim();
        if row.is_empty() || row.starts_with('#') {
            continue;
        }
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        let numbers: Result<Vec<f64>, _> = cells[1..].iter().map(|c| c.parse::<f64>()).collect();
        let header = first && numbers.is_err();
        first = false;
        if header {
            continue;
        }
        let numbers = numbers.map_err(|_| {
            entry(
                file,
                line,
                format!("{row:?}: expected link,mass or link,mass,x,y,z with numbers"),
            )
        })?;
        let measured = match numbers[..] {
            [mass] => Measured {
                mass,
                center_of_mass: None,
            },
            [mass, x, y, z] => Measured {
                mass,
                center_of_mass: Some(Point3::new(x, y, z)),
            },
            _ => {
                return Err(entry(
                    file,
                    line,
                    format!(
                        "{row:?}: expected link,mass or link,mass,x,y,z ({} cells)",
                        cells.len()
                    ),
                ));
            }
        };
        if cells[0].is_empty() {
            return Err(entry(file, line, "the link's name is empty"));
        }
        insert(&mut masses, file, line, cells[0], measured)?;
    }
    Ok(masses)
}

/// The TOML form.
pub fn parse_toml(text: &str, file: &Path) -> Result<MeasuredMasses, MassesError> {
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        let line = e.span().map_or(0, |s| {
            text[..s.start.min(text.len())].lines().count().max(1)
        });
        entry(file, line, e.message().to_owned())
    })?;
    let line_of = |name: &str| {
        text.lines()
            .position(|l| l.contains(name))
            .map_or(0, |i| i + 1)
    };
    let links = table
        .get("links")
        .and_then(toml::Value::as_table)
        .ok_or_else(|| entry(file, 1, "no [links] table"))?;
    let number = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
    let mut masses = MeasuredMasses::new();
    for (name, value) in links {
        let line = line_of(name);
        let measured = match value {
            toml::Value::Table(t) => {
                let mass = t.get("mass").and_then(number).ok_or_else(|| {
                    entry(file, line, format!("link {name:?}: no number \"mass\""))
                })?;
                let center_of_mass = match t.get("center_of_mass") {
                    None => None,
                    Some(v) => {
                        let xyz: Option<Vec<f64>> = v
                            .as_array()
                            .map(|a| a.iter().map(number).collect::<Option<Vec<f64>>>())
                            .unwrap_or(None);
                        match xyz.as_deref() {
                            Some([x, y, z]) => Some(Point3::new(*x, *y, *z)),
                            _ => {
                                return Err(entry(
                                    file,
                                    line,
                                    format!("link {name:?}: center_of_mass must be [x, y, z]"),
                                ));
                            }
                        }
                    }
                };
                if let Some(key) = t.keys().find(|k| *k != "mass" && *k != "center_of_mass") {
                    return Err(entry(
                        file,
                        line,
                        format!("link {name:?}: unknown key {key:?} (mass, center_of_mass)"),
                    ));
                }
                Measured {
                    mass,
                    center_of_mass,
                }
            }
            v => Measured {
                mass: number(v).ok_or_else(|| {
                    entry(
                        file,
                        line,
                        format!("link {name:?}: the mass must be a number"),
                    )
                })?,
                center_of_mass: None,
            },
        };
        insert(&mut masses, file, line, name, measured)?;
    }
    Ok(masses)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_and_toml_give_the_same_masses() {
        let csv =
            "# weighed 2026-12-03\nlink,mass_kg,x,y,z\nhand, 0.73\nfinger,0.0152,0.01,0,0.03\n";
        let toml = "[links]\nhand = 0.73\n[links.finger]\nmass = 0.0152\ncenter_of_mass = [0.01, 0, 0.03]\n";
        let a = parse_csv(csv, Path::new("m.csv")).expect("CSV");
        let b = parse_toml(toml, Path::new("m.toml")).expect("TOML");
        assert_eq!(a, b);
        assert_eq!(
            a["finger"],
            Measured {
                mass: 0.0152,
                center_of_mass: Some(Point3::new(0.01, 0.0, 0.03))
            }
        );
        assert_eq!(a["hand"].center_of_mass, None);
    }

    #[test]
    fn bad_entries_name_their_line() {
        let said = |csv: &str| parse_csv(csv, Path::new("m.csv")).map_err(|e| e.to_string());
        assert_eq!(
            said("hand,0.7\nfinger,heavy\n"),
            Err(
                "m.csv:2: \"finger,heavy\": expected link,mass or link,mass,x,y,z with numbers"
                    .into()
            )
        );
        assert_eq!(
            said("hand,0.7\nhand,0.8\n"),
            Err("m.csv:2: link \"hand\" is given twice".into())
        );
        assert_eq!(
            said("hand,-1\n"),
            Err("m.csv:1: link \"hand\": a measured mass must be positive, not -1".into())
        );
        assert_eq!(
            said("hand,1,2\n"),
            Err("m.csv:1: \"hand,1,2\": expected link,mass or link,mass,x,y,z (3 cells)".into())
        );
        let toml =
            parse_toml("[links.hand]\nmas = 1\n", Path::new("m.toml")).map_err(|e| e.to_string());
        assert_eq!(
            toml,
            Err("m.toml:1: link \"hand\": no number \"mass\"".into())
        );
    }
}
