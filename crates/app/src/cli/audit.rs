//! `inertia-lab audit ROBOT.urdf|ROBOT.xml`: every link's stated inertia beside the one its
//! geometry gives, with findings (a table worst first, or `--json`), and `--fix -o FIXED` to
//! write the description back with the chosen links' `<inertial>` replaced.

use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::{Args, ValueEnum};
use inertia_io::export;
use inertia_io::report::audit::{basis_text, held_text, json_report, table};
use inertia_io::report::findings::unweighed_text;
use inertia_io::wording::significant;
use massprops::MassProperties;
use robot::Measured;
use robot::fix::{Replacement, splice};
use robot::nearest::Nearest;
use robot::xacro::Xacro;
use robot::{
    Audit, AuditOptions, DescriptionFormat, GeometryKind, LinkAudit, ReadOptions, Robot, audit,
};
use serde_json::json;

use super::error::{CliError, positive};
use super::repair::RepairArgs;

/// Which geometry stands for a link's shape, as named on the command line.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum GeometryArg {
    /// URDF `<collision>`; MJCF geoms that can collide.
    Collision,
    /// URDF `<visual>`; MJCF geoms with contype and conaffinity 0.
    Visual,
}

/// What `--fix` writes for a chosen link.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FixMode {
    /// The exact mass properties of the link's geometry at the stated mass.
    Geometry,
    /// The valid inertial nearest to the stated one: its mass, its centre where that lies
    /// inside the geometry, the tensor changed least (Frobenius norm).
    Nearest,
}

/// Arguments of `audit`.
#[derive(Args, Debug)]
pub struct AuditArgs {
    /// The robot: a URDF (.urdf), MJCF (.xml) or SDFormat (.sdf) file; a xacro file is
    /// expanded by the xacro tool first (pip install xacro).
    pub file: PathBuf,
    /// Which geometry a link's shape is taken from.
    #[arg(long, value_enum, default_value_t = GeometryArg::Collision)]
    pub geometry: GeometryArg,
    /// Weigh every link at this density (kg/m³) instead of its stated mass.
    #[arg(long, allow_negative_numbers = true)]
    pub density: Option<f64>,
    /// The density of a link with no mass stated anywhere (kg/m³).
    #[arg(long, default_value_t = 1000.0, allow_negative_numbers = true)]
    pub assumed_density: f64,
    /// Where a URDF's `package://NAME/` is: NAME=DIR (repeatable); otherwise a folder NAME is
    /// searched for upwards from the URDF.
    #[arg(long = "package", value_name = "NAME=DIR")]
    pub packages: Vec<String>,
    /// An argument for xacro, NAME:=VALUE (repeatable), when the description is a xacro file.
    #[arg(long = "xacro-arg", value_name = "NAME:=VALUE")]
    pub xacro_args: Vec<String>,
    /// Flag a stated tensor whose relative error against the uniform-density one exceeds this
    /// fraction (off by default: uniform density is only an estimate for a link full of motors).
    #[arg(long, value_name = "FRACTION")]
    pub max_moment_error: Option<f64>,
    /// Flag a stated centre of mass farther than this fraction of the link's size from the
    /// uniform-density one (off by default).
    #[arg(long, value_name = "FRACTION")]
    pub max_com_offset: Option<f64>,
    /// Links' measured masses (and centres): CSV, a line link,mass or link,mass,x,y,z each, or
    /// TOML, a table links.NAME with mass and center_of_mass each. The geometry is weighed at
    /// them, a stated inertial that differs is a finding, and both fix modes keep them.
    #[arg(long, value_name = "FILE")]
    pub masses: Option<PathBuf>,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Write the description with the chosen links' `<inertial>` replaced (needs -o).
    #[arg(long, requires = "output")]
    pub fix: bool,
    /// Which links --fix changes: flagged (those whose stated inertial has a finding), all, or
    /// a comma-separated list of names.
    #[arg(long, default_value = "flagged", value_name = "flagged|all|NAME,…")]
    pub fix_links: String,
    /// What --fix writes: the geometry's inertial, or the valid one nearest to the stated one.
    #[arg(long, value_enum, default_value_t = FixMode::Geometry)]
    pub fix_mode: FixMode,
    /// Where --fix writes the fixed description.
    #[arg(short = 'o', long, value_name = "FIXED")]
    pub output: Option<PathBuf>,
    /// Print the time spent reading and auditing to stderr.
    #[arg(long)]
    pub timings: bool,
    /// How cracks and holes in each mesh are handled.
    #[command(flatten)]
    pub repair: RepairArgs,
}

/// Runs `audit`.
pub fn run(args: &AuditArgs) -> Result<(), CliError> {
    let options = AuditOptions {
        geometry: match args.geometry {
            GeometryArg::Collision => GeometryKind::Collision,
            GeometryArg::Visual => GeometryKind::Visual,
        },
        density: args.density.map(|d| positive("--density", d)).transpose()?,
        assumed_density: positive("--assumed-density", args.assumed_density)?,
        max_moment_error: args
            .max_moment_error
            .map(|t| positive("--max-moment-error", t))
            .transpose()?,
        max_com_offset: args
            .max_com_offset
            .map(|t| positive("--max-com-offset", t))
            .transpose()?,
        repairs: args.repair.repairs(1.0)?,
        nearest: args.fix_mode == FixMode::Nearest,
        measured: match &args.masses {
            Some(path) => robot::read_masses(path).map_err(|e| CliError::Input(e.to_string()))?,
            None => Default::default(),
        },
    };
    let read_options = ReadOptions {
        packages: args
            .packages
            .iter()
            .map(|p| {
                p.split_once('=')
                    .map(|(n, d)| (n.to_owned(), PathBuf::from(d)))
                    .ok_or_else(|| CliError::Usage(format!("--package takes NAME=DIR, not {p:?}")))
            })
            .collect::<Result<_, _>>()?,
        resource_paths: robot::resource_paths_from_env(),
        xacro_args: args
            .xacro_args
            .iter()
            .map(|a| {
                a.split_once(":=")
                    .map(|(n, v)| (n.to_owned(), v.to_owned()))
                    .ok_or_else(|| {
                        CliError::Usage(format!("--xacro-arg takes NAME:=VALUE, not {a:?}"))
                    })
            })
            .collect::<Result<_, _>>()?,
    };
    if args.fix
        && let Some(out) = &args.output
        && same_file(out, &args.file)
    {
        return Err(CliError::Usage(format!(
            "-o {} is the description itself; write the fix to another file",
            out.display()
        )));
    }
    let started = Instant::now();
    let robot =
        robot::read(&args.file, &read_options).map_err(|e| CliError::Input(e.to_string()))?;
    let read_time = started.elapsed();
    let unknown: Vec<&String> = options
        .measured
        .keys()
        .filter(|n| !robot.links.iter().any(|l| &l.name == *n))
        .collect();
    if !unknown.is_empty() {
        return Err(CliError::Input(format!(
            "{}: the robot has no link named {} (its links: {})",
            args.masses
                .as_deref()
                .unwrap_or(Path::new("--masses"))
                .display(),
            unknown
                .iter()
                .map(|n| format!("{n:?}"))
                .collect::<Vec<_>>()
                .join(", "),
            link_names(&robot)
        )));
    }
    let report = audit(&robot, &options);
    if args.timings {
        eprintln!(
            "read {:.3} s, audit {:.3} s ({} links)",
            read_time.as_secs_f64(),
            (started.elapsed() - read_time).as_secs_f64(),
            robot.links.len()
        );
    }
    let file = args.file.display().to_string();
    let fixed = if args.fix {
        let out = args
            .output
            .as_ref()
            .ok_or_else(|| CliError::Usage("--fix needs -o FIXED".to_owned()))?;
        Some(write_fix(
            &robot,
            &report,
            &args.fix_links,
            args.fix_mode,
            out,
        )?)
    } else {
        None
    };
    if args.json {
        let mut v = json_report(&file, &robot, &report);
        if let Some((path, links)) = &fixed {
            v["fixed"] = json!({
                "file": path.display().to_string(),
                "links": links,
                "xacro_note": robot.xacro.is_some(),
            });
        }
        println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
    } else {
        print!("{}", table(&file, &robot, &report));
        if let Some((path, links)) = &fixed {
            println!(
                "\n{} {} link(s) ({}) written to {}",
                if robot.xacro.is_some() {
                    "A note for the xacro sources fixing"
                } else {
                    "Fixed"
                },
                links.len(),
                links.join(", "),
                path.display()
            );
        }
    }
    Ok(())
}

/// The robot's link names, for a message naming one it lacks.
fn link_names(robot: &Robot) -> String {
    robot
        .links
        .iter()
        .map(|l| l.name.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}

fn same_file(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(x), Ok(y)) => x == y,
        _ => a == b,
    }
}

/// Writes the fixed description; returns its path and the links changed.
fn write_fix(
    robot: &Robot,
    report: &Audit,
    which: &str,
    mode: FixMode,
    out: &Path,
) -> Result<(PathBuf, Vec<String>), CliError> {
    let names: Vec<&str> = match which {
        "flagged" | "all" => Vec::new(),
        list => list
            .split(',')
            .map(str::trim)
            .filter(|n| !n.is_empty())
            .collect(),
    };
    for n in &names {
        if !robot.links.iter().any(|l| l.name == *n) {
            return Err(CliError::Usage(format!(
                "--fix-links: the robot has no link named {n:?} (its links: {})",
                link_names(robot)
            )));
        }
    }
    let chosen = |l: &LinkAudit| match which {
        "flagged" => l.flagged(),
        "all" => true,
        _ => names.contains(&robot.links[l.link].name.as_str()),
    };
    let format = match robot.format {
        DescriptionFormat::Urdf => export::Format::Urdf,
        DescriptionFormat::Mjcf => export::Format::Mjcf,
        DescriptionFormat::Sdf => export::Format::Sdf,
    };
    let kind = report.options.geometry.name();
    let mut replacements = Vec::new();
    let mut changed = Vec::new();
    for l in report.links.iter().filter(|l| chosen(l)) {
        let name = &robot.links[l.link].name;
        if robot.links[l.link].auto_inertial.is_some() {
            eprintln!(
                "warning: link {name:?} is not fixed: its <inertial auto=\"true\"> is computed \
                 by the simulator from its collisions"
            );
            continue;
        }
        let c = match &l.computed {
            Ok(c) => c,
            Err(why) => {
                eprintln!(
                    "warning: link {name:?} is not fixed: {}",
                    unweighed_text(why, kind)
                );
                continue;
            }
        };
        let link = &robot.links[l.link];
        let file = link
            .stated
            .as_ref()
            .map_or(link.element.file, |s| s.span.file);
        if file != 0 {
            eprintln!(
                "warning: link {name:?} is not fixed: it is written in {}, which the description \
                 includes (fix that file, or copy the body into the model)",
                robot.sources[file].path.display()
            );
            continue;
        }
        let measured_center = report
            .options
            .measured
            .get(name)
            .and_then(|m| m.center_of_mass);
        let geometry_fix;
        let (properties, comment) = match (mode, &l.nearest) {
            (FixMode::Geometry, _) => {
                // A measured centre is kept; the tensor stays the geometry's about its own.
                geometry_fix = match measured_center {
                    Some(center) => {
                        MassProperties::new(c.properties.mass, center, c.properties.inertia_com)
                    }
                    None => c.properties,
                };
                let mut comment = fix_comment(robot, l, c, report.options.geometry);
                if measured_center.is_some() {
                    comment = comment.replace(
                        " -->",
                        " The centre of mass is the measured one (the masses file); the tensor is the \
                         geometry's about its own centre. -->",
                    );
                }
                (&geometry_fix, comment)
            }
            (FixMode::Nearest, Some(Ok(n))) if n.moved == 0.0 && n.center_kept => {
                eprintln!(
                    "warning: link {name:?} is left as stated: its inertial is valid already \
                     (the nearest valid one is itself)"
                );
                continue;
            }
            (FixMode::Nearest, Some(Ok(n))) => {
                let from_geometry = relative_distance(&n.properties, &c.properties);
                let uncertainty = report
                    .options
                    .max_moment_error
                    .unwrap_or(NEAREST_UNCERTAINTY);
                if from_geometry > uncertainty {
                    eprintln!(
                        "warning: link {name:?}: the nearest valid inertial is {:.0} % from the \
                         geometry's (Frobenius), more than the {:.0} % allowed{}",
                        from_geometry * 100.0,
                        uncertainty * 100.0,
                        if report.options.max_moment_error.is_none() {
                            " by default (--max-moment-error sets it); the stated values may be \
                             far from the link's, --fix-mode geometry writes the geometry's"
                        } else {
                            ""
                        }
                    );
                }
                (
                    &n.properties,
                    nearest_comment(l, n, report.options.measured.get(name)),
                )
            }
            (FixMode::Nearest, Some(Err(why))) => {
                eprintln!(
                    "warning: link {name:?} is not fixed: there is no nearest valid inertial: \
                     {why} (--fix-mode geometry writes the geometry's)"
                );
                continue;
            }
            (FixMode::Nearest, None) => {
                eprintln!(
                    "warning: link {name:?} is not fixed: it states no inertial to be near to \
                     (--fix-mode geometry writes the geometry's)"
                );
                continue;
            }
        };
        let element = export::inertial_element(properties, format)
            .map_err(|e| CliError::Input(format!("link {name:?}: {e}")))?;
        replacements.push(Replacement {
            link: l.link,
            text: format!("{comment}\n{element}"),
        });
        changed.push(name.clone());
    }
    if robot.inertia_from_geoms && !replacements.is_empty() {
        eprintln!(
            "warning: the model's <compiler inertiafromgeom=\"true\"> makes MuJoCo ignore every \
             <inertial>, the fixed ones too; set it to \"auto\" for them to count"
        );
    }
    let text = match &robot.xacro {
        Some(x) => xacro_note(robot, x, &replacements),
        None => splice(robot, &replacements).map_err(|e| CliError::Input(e.to_string()))?,
    };
    std::fs::write(out, text)
        .map_err(|e| CliError::Runtime(format!("cannot write {}: {e}", out.display())))?;
    Ok((out.to_owned(), changed))
}

/// The fix of a xacro description, as a note: the expansion is not the user's file, so each
/// link's new `<inertial>` is given with the place in the `.xacro` sources that writes it.
fn xacro_note(robot: &Robot, x: &Xacro, replacements: &[Replacement]) -> String {
    let main = x
        .sources
        .first()
        .map_or_else(String::new, |p| p.display().to_string());
    let args = if x.args.is_empty() {
        String::new()
    } else {
        format!(
            " with {}",
            x.args
                .iter()
                .map(|(k, v)| format!("{k}:={v}"))
                .collect::<Vec<_>>()
                .join(" ")
        )
    };
    let mut note = format!(
        "inertia-lab audit --fix: {main} is a xacro file, audited as xacro expands it{args}.\n\
         The expansion is not a file of yours, so this note gives each fixed link's new \
         <inertial> and where the .xacro sources write the link: change it there.\n"
    );
    let names: Vec<&str> = robot.links.iter().map(|l| l.name.as_str()).collect();
    for r in replacements {
        let name = &robot.links[r.link].name;
        let place = match robot::xacro::origins(&x.sources, name).as_slice() {
            [] => "not found in the sources by its name: a macro builds it; search for the \
                   macro that writes this link"
                .to_owned(),
            found => found
                .iter()
                .map(|o| {
                    let shared: Vec<&str> = names
                        .iter()
                        .copied()
                        .filter(|n| robot::xacro::pattern_matches(&o.written_name, n))
                        .collect();
                    let what = match &o.inertial {
                        Some(at) => format!("its <inertial> is at {at}"),
                        None => format!(
                            "the link at {} writes no <inertial> of its own (a macro call \
                             inside it does: give the call these values)",
                            o.link
                        ),
                    };
                    if shared.len() > 1 {
                        format!(
                            "{what}, in <link name=\"{}\">, which writes {} links: {}",
                            o.written_name,
                            shared.len(),
                            shared.join(", ")
                        )
                    } else {
                        what
                    }
                })
                .collect::<Vec<_>>()
                .join("; or "),
        };
        note.push_str(&format!(
            "\nlink \"{name}\": {place}\n{}\n",
            r.text.trim_end()
        ));
    }
    note
}

/// How far apart two tensors are: ‖I_a − I_b‖_F / ‖I_b‖_F.
fn relative_distance(a: &MassProperties, b: &MassProperties) -> f64 {
    (a.inertia_com - b.inertia_com).norm() / b.inertia_com.norm()
}

/// How far the nearest valid inertial may be from the geometry's before a warning, when
/// --max-moment-error does not say.
const NEAREST_UNCERTAINTY: f64 = 0.5;

/// The comment above a nearest-fixed inertial: what was kept, how far the tensor moved, and
/// what holds it there.
fn nearest_comment(l: &LinkAudit, n: &Nearest, measured: Option<&Measured>) -> String {
    let held: Vec<String> = n.held_by.iter().map(held_text).collect();
    let mass = match measured {
        Some(_) => "mass as measured (the masses file; the stated tensor scaled to it)",
        None => "mass kept",
    };
    let center = if n.center_kept {
        if measured.is_some_and(|m| m.center_of_mass.is_some()) {
            "the measured centre kept"
        } else {
            "centre kept"
        }
    } else {
        "centre moved to the geometry's (the stated one is outside it)"
    };
    let was = l.stated.as_ref().map_or(String::new(), |s| {
        format!(
            " Before, moments {} {} {} kg*m^2.",
            significant(s.principal.moments.x, 6),
            significant(s.principal.moments.y, 6),
            significant(s.principal.moments.z, 6)
        )
    });
    let text = format!(
        "inertia-lab audit, fixed (nearest): the valid inertial nearest to the stated one within \
         all of the link's geometry: {mass}, {center}, tensor moved by {} kg*m^2 ({:.1} % of \
         it, Frobenius norm), held by {}. SI units, about the centre of mass, link axes, \
         off-diagonals -sum(m*x*y).{was}",
        significant(n.moved, 4),
        n.moved_fraction * 100.0,
        held.join(" and ")
    );
    format!("<!-- {} -->", text.replace("--", "- -"))
}

/// The comment above a fixed inertial: where its numbers came from, and what was there.
fn fix_comment(
    robot: &Robot,
    l: &LinkAudit,
    c: &robot::Computed,
    geometry: GeometryKind,
) -> String {
    let kind = geometry.name();
    let link = &robot.links[l.link];
    let shapes: Vec<String> = link
        .geometry(geometry)
        .iter()
        .map(|g| g.shape.label())
        .collect();
    let basis = basis_text(c);
    let was = match &l.stated {
        Some(s) => format!(
            "it stated mass {} kg, centre ({}, {}, {}) m, moments {} {} {} kg*m^2",
            significant(s.mass, 6),
            significant(s.center_of_mass.x, 6),
            significant(s.center_of_mass.y, 6),
            significant(s.center_of_mass.z, 6),
            significant(s.principal.moments.x, 6),
            significant(s.principal.moments.y, 6),
            significant(s.principal.moments.z, 6)
        ),
        None => "it had no inertial".to_owned(),
    };
    let codes: Vec<&str> = l
        .findings
        .iter()
        .filter(|f| f.flags_inertial())
        .map(|f| f.code())
        .collect();
    let findings = if codes.is_empty() {
        String::new()
    } else {
        format!("; findings: {}", codes.join(", "))
    };
    // XML forbids "--" inside a comment.
    let text = format!(
        "inertia-lab audit, fixed: exact mass properties of the {kind} geometry ({}) at {basis}; \
         SI units, about the centre of mass, link axes, off-diagonals -sum(m*x*y). Before, {was}{findings}.",
        shapes.join(", ")
    );
    format!("<!-- {} -->", text.replace("--", "- -"))
}
