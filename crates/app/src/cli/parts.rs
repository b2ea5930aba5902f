//! Bodies made of parts on the command line: a body file (`BODY.toml`), or a mesh file whose
//! parts get their own material (`--density-of NAME=RHO`, `--material-of NAME=steel`,
//! `--mass-of NAME=M`). Shared by `props` and `export`.

use std::path::Path;

use clap::Args;
use massprops::{BodyFile, Fill, Material, MeshFile, Part};
use nalgebra::Isometry3;

use super::error::CliError;

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
}

/// The parts of a body file, in metres.
pub fn body_parts(path: &Path) -> Result<(BodyFile, Vec<Part>), CliError> {
    let input = |e: massprops::MeshError| CliError::Input(e.to_string());
    let body = BodyFile::read(path).map_err(input)?;
    let parts = body.load().map_err(input)?;
    Ok((body, parts))
}

/// The parts of a mesh file, each with the material `args` gives it or `default`; `density`
/// converts a density in kg/m³ to the mesh's units.
pub fn mesh_parts(
    file: &MeshFile,
    args: &PartArgs,
    default: Fill,
    density: &dyn Fn(f64) -> f64,
) -> Result<Vec<Part>, CliError> {
    let found = file.parts();
    let names: Vec<&str> = found.iter().map(|(n, _)| n.as_str()).collect();
    let mut fills: Vec<Fill> = vec![default; found.len()];
    let mut assign = |flag: &str, entry: &str, fill: &dyn Fn(&str) -> Result<Fill, String>| {
        let Some((name, value)) = entry.split_once('=') else {
            return Err(CliError::Usage(format!(
                "{flag} takes NAME=VALUE, not {entry:?}"
            )));
        };
        let Some(k) = names.iter().position(|n| *n == name) else {
            return Err(CliError::Usage(format!(
                "{flag}: the file has no part {name:?} (its parts: {})",
                names.join(", ")
            )));
        };
        fills[k] = fill(value).map_err(|e| CliError::Usage(format!("{flag} {name}: {e}")))?;
        Ok(())
    };
    let number = |v: &str| match v.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
        _ => Err(format!("{v:?} is not a positive number")),
    };
    for e in &args.density_of {
        assign("--density-of", e, &|v| {
            Ok(Fill::Solid {
                density: density(number(v)?),
            })
        })?;
    }
    for e in &args.material_of {
        assign("--material-of", e, &|v| {
            let m = preset(v)?;
            Ok(Fill::Solid {
                density: density(m.density),
            })
        })?;
    }
    for e in &args.mass_of {
        assign("--mass-of", e, &|v| Ok(Fill::Mass { mass: number(v)? }))?;
    }
    found
        .iter()
        .zip(fills)
        .map(|((name, faces), fill)| {
            let mesh = file
                .mesh
                .subset(faces)
                .map_err(|e| CliError::Input(format!("part {name:?}: {e}")))?;
            Ok(Part {
                name: name.clone(),
                mesh,
                fill,
                placement: Isometry3::identity(),
            })
        })
        .collect()
}

/// A material preset by name, or a message listing them.
pub fn preset(name: &str) -> Result<Material, String> {
    massprops::material(name).ok_or_else(|| {
        format!(
            "unknown material {name:?} (the presets: {})",
            massprops::material_names()
        )
    })
}
