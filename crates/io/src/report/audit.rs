//! `audit`'s report: the table a person reads (worst link first, then each finding in words) and
//! the `audit --json` object (schema [`AUDIT_SCHEMA_VERSION`], documented in docs/audit.md).

use std::fmt::Write as _;

use massprops::MassProperties;
use robot::nearest::{Held, Nearest, NearestError};
use robot::{Audit, LinkAudit, MassBasis, Robot};
use serde_json::{Value, json};

use super::findings::{finding_text, unweighed_text};
use super::json::{point, rows, vector};
use super::warning_text;
use crate::conventions::{self, TENSOR};
use crate::wording::significant;

/// Version of the `audit --json` schema; bumped on any incompatible change.
pub const AUDIT_SCHEMA_VERSION: u32 = 1;

/// How the computed mass was found, in words (the table and the fix's comment).
pub fn basis_text(c: &robot::Computed) -> String {
    match c.basis {
        MassBasis::StatedMass => format!(
            "uniform density {} kg/m^3 for the stated mass",
            significant(c.density, 6)
        ),
        MassBasis::MeasuredMass => format!(
            "uniform density {} kg/m^3 for the measured mass",
            significant(c.density, 6)
        ),
        MassBasis::FileMasses => {
            "the geoms' own masses and densities (every geom, visual ones too, as MuJoCo weighs a body without an inertial)".to_owned()
        }
        MassBasis::AutoInertial => format!(
            "<inertial auto=\"true\">, as Gazebo computes it: the collisions' densities{}",
            if (c.density - 1000.0).abs() > 1e-9 {
                format!(", {} kg/m^3 on average", significant(c.density, 6))
            } else {
                String::new()
            }
        ),
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
pub fn table(file: &str, robot: &Robot, report: &Audit) -> String {
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
        "SI units; tensors about each centre of mass in the link's axes ({TENSOR}).\n\
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
        if let Some(n) = &l.nearest {
            let _ = writeln!(s, "{}", nearest_text(n));
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
    let leniencies: Vec<_> = robot
        .sources
        .iter()
        .flat_map(|f| &f.read_leniently)
        .collect();
    if !leniencies.is_empty() {
        let _ = writeln!(
            s,
            "\nRead as MuJoCo and urdfdom read it (strict XML refuses it):"
        );
        for l in leniencies {
            let _ = writeln!(s, "  {}: {}", l.at, l.what);
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

/// A constraint that holds a nearest inertial, in words.
pub fn held_text(held: &Held) -> String {
    match held {
        Held::TriangleInequality => {
            "the triangle inequality (one moment is the sum of the other two)".to_owned()
        }
        Held::Ellipsoid => "the geometry's bounding ellipsoid".to_owned(),
        Held::AxisBound { axis, radius } => format!(
            "m*r^2 about axis ({}, {}, {}) with r = {} m",
            significant(axis.x, 3),
            significant(axis.y, 3),
            significant(axis.z, 3),
            significant(*radius, 4)
        ),
    }
}

/// A link's nearest valid inertial in words (two lines), or why it has none.
fn nearest_text(nearest: &Result<Nearest, NearestError>) -> String {
    match nearest {
        Ok(n) if n.held_by.is_empty() => {
            "    nearest valid: the stated inertial itself (it is valid)".to_owned()
        }
        Ok(n) => {
            let m = n.properties.principal.moments;
            let held: Vec<String> = n.held_by.iter().map(held_text).collect();
            format!(
                "    nearest valid principal moments {} {} {} kg*m^2 ({}), moved {} kg*m^2 \
                 ({:.1} % of the stated tensor)\n    held there by {}",
                num(m.x),
                num(m.y),
                num(m.z),
                if n.center_kept {
                    "stated mass and centre"
                } else {
                    "stated mass, the geometry's centre"
                },
                num(n.moved),
                n.moved_fraction * 100.0,
                held.join(" and ")
            )
        }
        Err(why) => format!("    no nearest valid inertial: {why}"),
    }
}

fn nearest_json(nearest: &Result<Nearest, NearestError>) -> Value {
    match nearest {
        Ok(n) => {
            let mut v = properties_json(&n.properties);
            v["center_kept"] = json!(n.center_kept);
            v["moved"] = json!(n.moved);
            v["moved_fraction"] = json!(n.moved_fraction);
            v["held_by"] = n
                .held_by
                .iter()
                .map(|h| match h {
                    Held::AxisBound { axis, radius } => json!({
                        "constraint": h.code(), "axis": vector(axis), "radius": radius,
                    }),
                    _ => json!({"constraint": h.code()}),
                })
                .collect();
            v["ellipsoid"] = json!({
                "center": point(&n.ellipsoid.center),
                "shape": rows(&n.ellipsoid.shape),
            });
            v
        }
        Err(why) => json!({"error": why.to_string()}),
    }
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
    let mut v = json!({
        "code": f.code(),
        "message": finding_text(f, kind, |w| warning_text(w, &[])),
        "severity": f.severity(),
        "flags_inertial": f.flags_inertial(),
    });
    let evidence = match f {
        F::MissingInertial { moving, incomplete } => {
            json!({"moving": moving, "incomplete": incomplete})
        }
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
        F::LikelyUnitError {
            slip,
            stated,
            would_be,
        } => json!({"slip": slip_code(*slip), "stated": stated, "would_be": would_be}),
        F::CenterInGeometryFrame {
            geometry,
            stated,
            would_be,
        } => json!({
            "geometry": geometry, "stated": point(stated), "would_be": point(would_be),
        }),
        F::ImplausibleDensity {
            density,
            volume,
            mass,
        } => {
            json!({"density": density, "volume": volume, "mass": mass})
        }
        F::DiffersFromMeasured {
            stated_mass,
            measured_mass,
            measured_center,
        } => json!({
            "stated_mass": stated_mass,
            "measured_mass": measured_mass,
            "measured_center_of_mass": measured_center.map(|(c, _)| point(&c)),
            "center_offset": measured_center.map(|(_, d)| d),
        }),
        F::MomentsFar { error, threshold } => json!({"error": error, "threshold": threshold}),
        F::ComFar {
            fraction,
            threshold,
        } => json!({"fraction": fraction, "threshold": threshold}),
        F::MeshMissing { written, tried } => json!({
            "written": written,
            "unexpanded_substitution": robot::unexpanded_substitution(written),
            "tried": tried.iter().map(|p| p.display().to_string()).collect::<Vec<_>>(),
        }),
        F::MeshUnreadable { file, .. } => json!({"file": file.display().to_string()}),
        F::GeometryUnsupported { what } => json!({"what": what}),
        F::MeshDefect { geometry, warning } => json!({
            "geometry": geometry, "count": warning.count, "effect_on_mass": warning.effect_on_mass,
        }),
    };
    if let (Some(o), Value::Object(e)) = (v.as_object_mut(), evidence) {
        o.extend(e);
    }
    v
}

/// The `audit --json` object (schema [`AUDIT_SCHEMA_VERSION`], documented in docs/audit.md).
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
                        MassBasis::MeasuredMass => "measured_mass",
                        MassBasis::FileMasses => "file_masses",
                        MassBasis::GivenDensity(_) => "given_density",
                        MassBasis::AssumedDensity(_) => "assumed_density",
                        MassBasis::AutoInertial => "auto_inertial",
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
                "pose": json!({
                    "position": vector(&link.pose.translation.vector),
                    "rotation": rows(link.pose.rotation.to_rotation_matrix().matrix()),
                }),
                "auto_inertial": link.auto_inertial.as_ref().map(|a| json!({"mass": a.mass})),
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
                "nearest": l.nearest.as_ref().map(nearest_json),
                "measured": report.options.measured.get(&link.name).map(|m| json!({
                    "mass": m.mass,
                    "center_of_mass": m.center_of_mass.as_ref().map(point),
                })),
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
        "conventions": conventions::block(&[
            ("units", "SI: m, kg, kg*m^2"),
            ("frame", "about each centre of mass, in the link's own axes"),
            ("computed", "uniform density over the geometry (an estimate for a real link)"),
        ]),
        "links": links,
        "read_leniently": robot.sources.iter().flat_map(|f| &f.read_leniently).map(|l| json!({
            "file": l.at.file.display().to_string(),
            "line": l.at.line,
            "column": l.at.column,
            "message": l.what,
        })).collect::<Vec<_>>(),
        "unsupported": robot.unsupported.iter().map(|u| json!({
            "file": u.at.file.display().to_string(),
            "line": u.at.line,
            "column": u.at.column,
            "element": u.element,
            "message": u.what,
        })).collect::<Vec<_>>(),
    })
}

/// A unit slip's stable name in `audit --json`.
fn slip_code(slip: robot::UnitSlip) -> String {
    match slip {
        robot::UnitSlip::MassInGrams => "mass_in_grams".to_owned(),
        robot::UnitSlip::MassDecimalPoint { power } => format!("mass_decimal_point_{power}"),
        robot::UnitSlip::MeshInMillimetres => "mesh_in_millimetres".to_owned(),
        robot::UnitSlip::MomentsInKgMm2 => "moments_in_kg_mm2".to_owned(),
        robot::UnitSlip::MomentsInGMm2 => "moments_in_g_mm2".to_owned(),
    }
}
