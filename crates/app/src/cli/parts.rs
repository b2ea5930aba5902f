//! Bodies made of parts on the command line: a mesh file whose parts get their own material
//! (`--density-of NAME=RHO`, `--material-of NAME=steel`, `--mass-of NAME=M`), turned into the
//! [`PartMaterial`]s of the one input path ([`inertia_io::input`]). Shared by `props` and `export`.

use clap::Args;
use massprops::{Material, MaterialEntry};

use super::error::CliError;
use inertia_io::input::PartMaterial;

/// Reads the VALUE of a NAME=VALUE flag as a material, or says why not.
type ReadMaterial<'a> = dyn Fn(&str) -> Result<MaterialEntry, String> + 'a;

/// Per-part materials for a mesh file's parts.
#[derive(Args, Debug, Default)]
pub struct PartArgs {
    /// Density of one part, NAME=RHO (repeatable). A file's parts are its objects (OBJ `o`), or
    /// its groups (`g`) when it has no objects, or its ASCII STL solids; otherwise its connected
    /// shells, named "shell 1", "shell 2", …. Parts not named take --density.
    #[arg(long = "density-of", value_name = "NAME=RHO")]
    pub density_of: Vec<String>,
    /// A preset material for one part, NAME=MATERIAL (repeatable).
    #[arg(long = "material-of", value_name = "NAME=MATERIAL")]
    pub material_of: Vec<String>,
    /// The mass of one part, NAME=M (repeatable).
    #[arg(long = "mass-of", value_name = "NAME=M")]
    pub mass_of: Vec<String>,
}

impl PartArgs {
    /// Whether any part was given its own material.
    pub fn any(&self) -> bool {
        !(self.density_of.is_empty() && self.material_of.is_empty() && self.mass_of.is_empty())
    }

    /// The materials given, in the order of the flags (densities, presets, masses; a later one
    /// for the same part wins).
    ///
    /// # Errors
    /// An entry that is not NAME=VALUE, a number that is not positive, an unknown preset.
    pub fn materials(&self) -> Result<Vec<PartMaterial>, CliError> {
        let number = |v: &str| match v.trim().parse::<f64>() {
            Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
            _ => Err(format!("{v:?} is not a positive number")),
        };
        let flags: [(&'static str, &Vec<String>, &ReadMaterial<'_>); 3] = [
            ("--density-of", &self.density_of, &|v| {
                number(v).map(MaterialEntry::Density)
            }),
            ("--material-of", &self.material_of, &|v| {
                preset(v).map(|_| MaterialEntry::Preset(v.to_owned()))
            }),
            ("--mass-of", &self.mass_of, &|v| {
                number(v).map(MaterialEntry::Mass)
            }),
        ];
        let mut out = Vec::new();
        for (flag, entries, material) in flags {
            for entry in entries {
                let Some((name, value)) = entry.split_once('=') else {
                    return Err(CliError::Usage(format!(
                        "{flag} takes NAME=VALUE, not {entry:?}"
                    )));
                };
                let material =
                    material(value).map_err(|e| CliError::Usage(format!("{flag} {name}: {e}")))?;
                out.push(PartMaterial {
                    source: flag,
                    name: name.to_owned(),
                    material,
                });
            }
        }
        Ok(out)
    }
}

/// A material preset by name, or a message listing them.
pub fn preset(name: &str) -> Result<Material, String> {
    massprops::material(name).ok_or_else(|| {
        format!(
            "unknown material {name:?} (the presets: {})",
            massprops::materials::material_names()
        )
    })
}
