//! `inertia-lab audit ROBOT.urdf|ROBOT.xml`: every link's stated inertia beside the one its
//! geometry gives, with findings (a table worst first, or `--json`), and `--fix -o FIXED` to
//! write the description back with the chosen links' `<inertial>` replaced.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::{Args, ValueEnum};
use massprops::MassProperties;
use robot::fix::{Replacement, splice};
use robot::{
    Audit, AuditOptions, Format, GeometryKind, LinkAudit, MassBasis, ReadOptions, Robot, audit,
};
use serde_json::{Value, json};

use super::error::{CliError, positive};
use super::repair::RepairArgs;
use super::report::json::{point, rows, vector};
use super::report::{significant, warning_text};
use crate::export::{self, TENSOR_CONVENTION};
use crate::findings::{finding_text, unweighed_text};

/// Version of the `audit --json` schema; bumped on any incompatible change.
pub const AUDIT_SCHEMA_VERSION: u32 = 1;

/// Which geometry stands for a link's shape, as named on the command line.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum GeometryArg {
    /// URDF `<collision>`; MJCF geoms that can collide.
    Collision,
    /// URDF `<visual>`; MJCF geoms with contype and conaffinity 0.
    Visual,
}

/// Arguments of `audit`.
#[derive(Args, Debug)]
pub struct AuditArgs {
    /// The robot: a URDF (.urdf) or MJCF (.xml) file. Run xacro first on a .xacro file.
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
    /// Flag a stated tensor whose relative error against the uniform-density one exceeds this
    /// fraction (off by default: uniform density is only an estimate for a link full of motors).
    #[arg(long, value_name = "FRACTION")]
    pub max_moment_error: Option<f64>,
    /// Flag a stated centre of mass farther than this fraction of the link's size from the
    /// uniform-density one (off by default).
    #[arg(long, value_name = "FRACTION")]
    pub max_com_offset: Option<f64>,
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
        Some(write_fix(&robot, &report, &args.fix_links, out)?)
    } else {
        None
    };
    if args.json {
        let mut v = json_report(&file, &robot, &report);
        if let Some((path, links)) = &fixed {
            v["fixed"] = json!({"file": path.display().to_string(), "links": links});
        }
        println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
    } else {
        print!("{}", table(&file, &robot, &report));
        if let Some((path, links)) = &fixed {
            println!(
                "\nFixed {} link(s) ({}) written to {}",
                links.len(),
                links.join(", "),
                path.display()
            );
        }
    }
    Ok(())
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
                robot
                    .links
                    .iter()
                    .map(|l| l.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            )));
        }
    }
    let chosen = |l: &LinkAudit| match which {
        "flagged" => l.flagged(),
        "all" => true,
        _ => names.contains(&robot.links[l.link].name.as_str()),
    };
    let format = match robot.format {
        Format::Urdf => export::Format::Urdf,
        Format::Mjcf => export::Format::Mjcf,
    };
    let kind = report.options.geometry.name();
    let mut replacements = Vec::new();
    let mut changed = Vec::new();
    for l in report.links.iter().filter(|l| chosen(l)) {
        let name = &robot.links[l.link].name;
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
        let element = export::inertial_element(&c.properties, format)
            .map_err(|e| CliError::Input(format!("link {name:?}: {e}")))?;
        let comment = fix_comment(robot, l, c, report.options.geometry);
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
    let text = splice(robot, &replacements).map_err(|e| CliError::Input(e.to_string()))?;
    std::fs::write(out, text)
        .map_err(|e| CliError::Runtime(format!("cannot write {}: {e}", out.display())))?;
    Ok((out.to_owned(), changed))
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

fn basis_text(c: &robot::Computed) -> String {
    match c.basis {
        MassBasis::StatedMass => format!(
            "uniform density {} kg/m^3 for the stated mass",
            significant(c.density, 6)
        ),
        MassBasis::FileMasses => {
            "the geoms' own masses and densities (every geom, visual ones too, as MuJoCo weighs a body without an inertial)".to_owned()
        }
        MassBasis::GivenDensity(d) => format!("the density given, {} kg/m^3", significant(d, 6)),
        MassBasis::AssumedDensity(d) => {
            format!(
                "an assumed density of {} kg/m^3 (no mass stated)",
                significant(d, 6)
            )
        }
    }
}

fn num(v: f64) -> String {
    significant(v, 4)
}

/// The terminal report: a line per link worst first, then each finding in words.
fn table(file: &str, robot: &Robot, report: &Audit) -> String {
    let kind = report.options.geometry.name();
    let mut s = String::new();
    let flagged = report.links.iter().filter(|l| l.flagged()).count();
    let _ = writeln!(
        s,
        "{file}: {} \"{}\", {} links, {flagged} with findings on their inertial; geometry: {kind}",
        robot.format.name().to_uppercase(),
        robot.name,
        robot.links.len()
    );
    let _ = writeln!(
        s,
        "SI units; tensors about each centre of mass in the link's axes ({TENSOR_CONVENTION}).\n\
         The computed values assume uniform density over the geometry: exact for that body, \
         only an estimate for a link full of motors.\n"
    );
    let _ = writeln!(
        s,
        "  {:<24} {:>10} {:>10} {:>10} {:>11} {:>9}  findings",
        "link", "mass kg", "density", "COM off m", "COM off %", "tensor err"
    );
    for l in report.worst_first() {
        let name = &robot.links[l.link].name;
        let mass = l.stated.as_ref().map_or("-".to_owned(), |p| num(p.mass));
        let density = l
            .computed
            .as_ref()
            .map_or("-".to_owned(), |c| num(c.density));
        let (off, frac, err) =
            l.comparison
                .as_ref()
                .map_or(("-".to_owned(), "-".to_owned(), "-".to_owned()), |c| {
                    (
                        num(c.com_offset),
                        format!("{:.1}", c.com_offset_fraction * 100.0),
                        format!("{:.1} %", c.tensor_error * 100.0),
                    )
                });
        let mut codes: Vec<&str> = l.findings.iter().map(|f| f.code()).collect();
        codes.dedup();
        let _ = writeln!(
            s,
            "  {:<24} {:>10} {:>10} {:>10} {:>11} {:>9}  {}",
            name,
            mass,
            density,
            off,
            frac,
            err,
            if codes.is_empty() {
                "-".to_owned()
            } else {
                codes.join(", ")
            }
        );
    }
    let with_findings: Vec<&LinkAudit> = report
        .worst_first()
        .into_iter()
        .filter(|l| !l.findings.is_empty())
        .collect();
    if !with_findings.is_empty() {
        let _ = writeln!(s, "\nFindings:");
    }
    for l in with_findings {
        let link = &robot.links[l.link];
        let _ = writeln!(s, "  {}:", link.name);
        if let (Some(st), Ok(c)) = (&l.stated, &l.computed) {
            let _ = writeln!(
                s,
                "    stated   principal moments {} {} {} kg*m^2\n    computed principal moments {} {} {} kg*m^2 ({})",
                num(st.principal.moments.x),
                num(st.principal.moments.y),
                num(st.principal.moments.z),
                num(c.properties.principal.moments.x),
                num(c.properties.principal.moments.y),
                num(c.properties.principal.moments.z),
                basis_text(c)
            );
            if let Some(cmp) = &l.comparison {
                let angles: Vec<String> = cmp
                    .axis_angles
                    .iter()
                    .map(|a| a.map_or("free".to_owned(), |a| format!("{:.1} deg", a.to_degrees())))
                    .collect();
                let _ = writeln!(
                    s,
                    "    between their principal axes 1, 2, 3: {} (free: equal moments leave \
                     the axis free)",
                    angles.join(", ")
                );
            }
        } else if let Err(why) = &l.computed {
            let _ = writeln!(s, "    not weighed: {}", unweighed_text(why, kind));
        }
        for f in &l.findings {
            let _ = writeln!(
                s,
                "    [{}] {}",
                f.code(),
                finding_text(f, kind, |w| warning_text(w, &[]))
            );
        }
    }
    if !robot.unsupported.is_empty() {
        let _ = writeln!(s, "\nNot modelled (named, not skipped):");
        for u in &robot.unsupported {
            let _ = writeln!(s, "  {} <{}>: {}", u.at, u.element, u.what);
        }
    }
    s
}

fn properties_json(p: &MassProperties) -> Value {
    json!({
        "mass": p.mass,
        "center_of_mass": point(&p.center_of_mass),
        "inertia": rows(&p.inertia_com),
        "principal_moments": vector(&p.principal.moments),
        "principal_axes": rows(&p.principal.rotation.matrix().transpose()),
    })
}

fn region_name(region: robot::Region) -> &'static str {
    match region {
        robot::Region::Both => "collision_and_visual",
        robot::Region::Only(kind) => kind.name(),
    }
}

/// The finding as `{code, message, …its evidence}`.
fn finding_json(f: &robot::Finding, kind: &str) -> Value {
    use robot::Finding as F;
    let mut v =
        json!({"code": f.code(), "message": finding_text(f, kind, |w| warning_text(w, &[]))});
    let evidence = match f {
        F::MissingInertial { moving } => json!({"moving": moving}),
        F::NonpositiveMass { mass } => json!({"mass": mass}),
        F::NotPositiveDefinite { moments } | F::TriangleInequality { moments } => {
            json!({"moments": moments})
        }
        F::ImpossibleMoment { region, mass, axes } => json!({
            "region": region_name(*region),
            "mass": mass,
            "proof": true,
            "moments": axes.iter().map(|a| json!({
                "moment_index": a.rank + 1, "moment": a.moment, "bound": a.bound,
                "radius": a.radius, "axis": vector(&a.axis),
            })).collect::<Vec<_>>(),
        }),
        F::ComOutsideGeometry {
            region,
            center_of_mass,
            distance,
        } => json!({
            "region": region_name(*region),
            "center_of_mass": point(center_of_mass), "distance_outside": distance, "proof": true,
        }),
        F::Placeholder { reasons } => json!({"reasons": reasons.iter().map(|r| match r {
            robot::PlaceholderReason::EqualMoments { moment, weighed } => json!({"kind": "equal_moments", "moment": moment, "geometry_weighed": weighed}),
            robot::PlaceholderReason::RoundNumbers { written } => json!({"kind": "round_numbers", "written": written}),
            robot::PlaceholderReason::SharedTensor { links } => json!({"kind": "shared_tensor", "links": links}),
        }).collect::<Vec<_>>()}),
        F::ImplausibleDensity {
            density,
            volume,
            mass,
        } => {
            json!({"density": density, "volume": volume, "mass": mass})
        }
        F::MomentsFar { error, threshold } => json!({"error": error, "threshold": threshold}),
        F::ComFar {
            fraction,
            threshold,
        } => json!({"fraction": fraction, "threshold": threshold}),
        F::MeshMissing { written, tried } => json!({
            "written": written,
            "tried": tried.iter().map(|p| p.display().to_string()).collect::<Vec<_>>(),
        }),
        F::MeshUnreadable { file, .. } => json!({"file": file.display().to_string()}),
        F::GeometryUnsupported { what } => json!({"what": what}),
        F::MeshDefect { geometry, warning } => json!({
            "geometry": geometry, "count": warning.count, "effect_on_mass": warning.effect_on_mass,
        }),
        _ => json!({}),
    };
    if let (Some(o), Value::Object(e)) = (v.as_object_mut(), evidence) {
        o.extend(e);
    }
    v
}

/// The `audit --json` object (schema [`AUDIT_SCHEMA_VERSION`], documented in README).
pub fn json_report(file: &str, robot: &Robot, report: &Audit) -> Value {
    let kind = report.options.geometry.name();
    let links: Vec<Value> = report
        .links
        .iter()
        .map(|l| {
            let link = &robot.links[l.link];
            let computed = match &l.computed {
                Ok(c) => {
                    let mut v = properties_json(&c.properties);
                    v["volume"] = json!(c.volume);
                    v["density"] = json!(c.density);
                    v["basis"] = json!(match c.basis {
                        MassBasis::StatedMass => "stated_mass",
                        MassBasis::FileMasses => "file_masses",
                        MassBasis::GivenDensity(_) => "given_density",
                        MassBasis::AssumedDensity(_) => "assumed_density",
                    });
                    v
                }
                Err(_) => Value::Null,
            };
            json!({
                "name": link.name,
                "parent": link.parent.map(|p| robot.links[p].name.clone()),
                "moving": link.moving,
                "line": link.element.at.line,
                "stated": l.stated.as_ref().map(properties_json),
                "computed": computed,
                "not_weighed": l.computed.as_ref().err().map(|u| unweighed_text(u, kind)),
                "size": l.size,
                "comparison": l.comparison.as_ref().map(|c| json!({
                    "com_offset": c.com_offset,
                    "com_offset_fraction": c.com_offset_fraction,
                    "tensor_error": c.tensor_error,
                    "principal_axis_angle_deg": c.axis_angles.map(|a| a.map(f64::to_degrees)),
                })),
                "findings": l.findings.iter().map(|f| finding_json(f, kind)).collect::<Vec<_>>(),
            })
        })
        .collect();
    json!({
        "schema": "inertia-lab/audit",
        "schema_version": AUDIT_SCHEMA_VERSION,
        "file": file,
        "format": robot.format.name(),
        "robot": robot.name,
        "geometry": kind,
        "conventions": {
            "units": "SI: m, kg, kg*m^2",
            "tensor": TENSOR_CONVENTION,
            "frame": "about each centre of mass, in the link's own axes",
            "computed": "uniform density over the geometry (an estimate for a real link)",
        },
        "links": links,
        "unsupported": robot.unsupported.iter().map(|u| json!({
            "file": u.at.file.display().to_string(),
            "line": u.at.line,
            "column": u.at.column,
            "element": u.element,
            "message": u.what,
        })).collect::<Vec<_>>(),
    })
}
