//! `--weld` and `--holes`: how `props`, `export` and `simulate` handle cracks and holes in a mesh (the
//! command line's face of `massprops::Repairs`).

use clap::{Args, ValueEnum};
use massprops::Repairs;
use massprops::defects::Holes;
use massprops::defects::Weld;

use super::error::CliError;

/// What to do with the holes that remain after cracks are closed.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum HolesArg {
    /// Close each hole with a fan of triangles from its centre; the output says how much the
    /// caps add.
    Cap,
    /// Refuse an open mesh (exit code 3, naming the holes).
    Refuse,
}

/// Mesh repair options shared by `props`, `export` and `simulate`.
#[derive(Args, Debug)]
pub struct RepairArgs {
    /// Which vertices on open edges are merged to close cracks: `exact` (identical coordinates
    /// only), `auto` (within 1e-6 of the bounding-box diagonal: float32 rounding), or a distance
    /// in the mesh's units (before --scale).
    #[arg(long, default_value = "auto", value_name = "exact|auto|DIST")]
    pub weld: String,
    /// What to do with holes (for the volume and for approximations at a given density).
    #[arg(long, value_enum, default_value_t = HolesArg::Cap)]
    pub holes: HolesArg,
    /// With --holes cap: the largest share of the closed surface the caps may make, caps /
    /// (surface + caps); a mesh whose caps make more is refused (a sheet, a terrain, a mesh with
    /// large parts missing). 1 caps anything.
    #[arg(long, default_value_t = massprops::defects::MAX_CAP_SHARE, value_name = "SHARE")]
    pub max_cap_share: f64,
}

impl RepairArgs {
    /// The options for massprops; `scale` converts a weld distance to the scaled mesh.
    pub fn repairs(&self, scale: f64) -> Result<Repairs, CliError> {
        let weld = match self.weld.as_str() {
            "exact" => Weld::Exact,
            "auto" => Weld::Auto,
            text => match text.parse::<f64>() {
                Ok(d) if d.is_finite() && d > 0.0 => Weld::Distance(d * scale),
                _ => {
                    return Err(CliError::Usage(format!(
                        "--weld takes exact, auto or a positive distance, not {text:?}"
                    )));
                }
            },
        };
        let holes = match self.holes {
            HolesArg::Cap => Holes::Cap,
            HolesArg::Refuse => Holes::Refuse,
        };
        if !(self.max_cap_share > 0.0 && self.max_cap_share <= 1.0) {
            return Err(CliError::Usage(format!(
                "--max-cap-share takes a share above 0 and at most 1, not {}",
                self.max_cap_share
            )));
        }
        Ok(Repairs {
            weld,
            holes,
            max_cap_share: self.max_cap_share,
            ..Repairs::default()
        })
    }
}
