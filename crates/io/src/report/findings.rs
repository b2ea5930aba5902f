//! A robot audit's findings in words, shared by the command line's report and the app's Robot
//! section (each passes its own words for mesh warnings). The numbers come from
//! `robot::Finding`; what is said around them is ours.

use massprops::Warning;
use robot::{Finding, PlaceholderReason, Region, Unweighed};

/// A number to four significant digits.
pub fn num(v: f64) -> String {
    crate::wording::significant(v, 4)
}

/// One finding as a sentence, naming its evidence; `geometry` is the kind audited
/// ("collision"), and `mesh_words` the front end's own words for a mesh warning.
pub fn finding_text(
    f: &Finding,
    geometry: &str,
    mesh_words: impl Fn(&Warning) -> String,
) -> String {
    match f {
        Finding::MissingInertial {
            moving,
            incomplete: Some(missing),
        } => format!(
            "an <inertial> without its <{missing}> (urdfdom refuses the file, yourdfpy reads it){}",
            if *moving {
                ": a moving link whose mass properties are not all stated"
            } else {
                ""
            }
        ),
        Finding::MissingInertial {
            moving: true,
            incomplete: None,
        } => "no <inertial>: a moving link without mass, so every dynamics call treats it as \
              weightless (simulators substitute a default, Gazebo 1 kg and 1 kg*m^2, or refuse \
              it)"
        .to_owned(),
        Finding::MissingInertial {
            moving: false,
            incomplete: None,
        } => "no <inertial> on a link with geometry: its mass is left out of the robot's (or, \
              in Gazebo, is a default 1 kg)"
            .to_owned(),
        Finding::NonpositiveMass { mass } => {
            format!(
                "stated mass {} kg: a moving link needs a positive mass",
                num(*mass)
            )
        }
        Finding::NotPositiveDefinite { moments } => format!(
            "stated principal moments {}, {}, {} kg*m^2: not all positive, which no body has",
            num(moments[0]),
            num(moments[1]),
            num(moments[2])
        ),
        Finding::TriangleInequality { moments } => format!(
            "stated principal moments {} + {} < {} kg*m^2 break I1 + I2 >= I3, which every body \
             obeys",
            num(moments[0]),
            num(moments[1]),
            num(moments[2])
        ),
        Finding::ImpossibleMoment { region, mass, axes } => {
            let region = region_text(*region);
            let each: Vec<String> = axes
                .iter()
                .map(|a| {
                    format!(
                        "I{} = {} > m*r^2 = {} ({}x, r = {} m)",
                        a.rank + 1,
                        num(a.moment),
                        num(a.bound),
                        num(a.moment / a.bound),
                        num(a.radius)
                    )
                })
                .collect();
            format!(
                "impossible: {} kg*m^2, with m = {} kg the stated mass and r the farthest any \
                 point of the {region} lies from that principal axis through the stated centre \
                 of mass. A proof, not an estimate: no distribution of that mass inside that \
                 geometry has a larger moment",
                each.join("; "),
                num(*mass)
            )
        }
        Finding::ComOutsideGeometry {
            region,
            center_of_mass: c,
            distance,
        } => format!(
            "impossible: the stated centre of mass ({}, {}, {}) m lies at least {} m outside the \
             convex hull of the {}; a centre of mass is a weighted mean of the \
             mass's points, so mass inside the geometry cannot put it there",
            num(c.x),
            num(c.y),
            num(c.z),
            num(*distance),
            region_text(*region)
        ),
        Finding::Placeholder { reasons } => {
            let why: Vec<String> = reasons
                .iter()
                .map(|r| match r {
                    PlaceholderReason::EqualMoments {
                        moment,
                        weighed: true,
                    } => format!(
                        "all three moments are {} kg*m^2 with no products (only a round body \
                         has that, and this link's geometry is not round)",
                        num(*moment)
                    ),
                    PlaceholderReason::EqualMoments {
                        moment,
                        weighed: false,
                    } => format!(
                        "all three moments are {} kg*m^2 with no products (only a round body \
                         has that)",
                        num(*moment)
                    ),
                    PlaceholderReason::RoundNumbers { written } => format!(
                        "every non-zero entry is a power of ten ({})",
                        written.join(" ")
                    ),
                    PlaceholderReason::SharedTensor { links } => {
                        let named = match links.len() {
                            0..=3 => links.join(", "),
                            n => format!("{} and {} more", links[..3].join(", "), n - 3),
                        };
                        format!("the same tensor as {named}, whose geometry differs")
                    }
                })
                .collect();
            format!("placeholder inertia: {}", why.join("; "))
        }
        Finding::CenterInGeometryFrame {
            geometry: g,
            stated,
            would_be,
        } => format!(
            "likely frame slip: the stated centre of mass ({}, {}, {}) m is the geometry's centre \
             in the frame of its {g}, not in the link's; placed by that geometry's origin it is \
             ({}, {}, {}) m, the geometry's centre",
            num(stated.x),
            num(stated.y),
            num(stated.z),
            num(would_be.x),
            num(would_be.y),
            num(would_be.z)
        ),
        Finding::LikelyUnitError {
            slip,
            stated,
            would_be,
        } => match slip {
            robot::UnitSlip::MassInGrams => format!(
                "likely unit error: the stated mass {} kg looks like grams; as {} kg its density \
                 is that of a real part",
                num(*stated),
                num(*would_be)
            ),
            robot::UnitSlip::MassDecimalPoint { power } => format!(
                "likely typing slip: the stated mass {} kg looks like {} kg with its decimal \
                 point {power} place(s) to the right; as {} kg its density is that of a real part",
                num(*stated),
                num(*would_be),
                num(*would_be)
            ),
            robot::UnitSlip::MeshInMillimetres => format!(
                "likely unit error: the {geometry} mesh looks like millimetres read as metres \
                 (density {} kg/m^3; with a mesh scale of 0.001 it would be {} kg/m^3)",
                num(*stated),
                num(*would_be)
            ),
            robot::UnitSlip::MomentsInKgMm2 | robot::UnitSlip::MomentsInGMm2 => {
                let unit = if *slip == robot::UnitSlip::MomentsInKgMm2 {
                    "kg*mm^2"
                } else {
                    "g*mm^2"
                };
                format!(
                    "likely unit error: the stated moments look like {unit} (largest {}); in \
                     kg*m^2 ({}) they are within 50 % of the geometry's",
                    num(*stated),
                    num(*would_be)
                )
            }
        },
        Finding::DiffersFromMeasured {
            stated_mass,
            measured_mass,
            measured_center,
        } => {
            let mut parts = Vec::new();
            if let Some(m) = measured_mass {
                parts.push(format!(
                    "the stated mass {} kg is {:+.1} % from the measured {} kg",
                    num(*stated_mass),
                    (stated_mass / m - 1.0) * 100.0,
                    num(*m)
                ));
            }
            if let Some((c, d)) = measured_center {
                parts.push(format!(
                    "the stated centre of mass is {} m from the measured ({}, {}, {}) m",
                    num(*d),
                    num(c.x),
                    num(c.y),
                    num(c.z)
                ));
            }
            parts.join("; ")
        }
        Finding::ImplausibleDensity {
            density,
            volume,
            mass,
        } => format!(
            "implausible density: the stated {} kg in {} m^3 of {geometry} geometry is {} kg/m^3 \
             (plausible: {}-{})",
            num(*mass),
            num(*volume),
            num(*density),
            robot::PLAUSIBLE_DENSITY.0,
            robot::PLAUSIBLE_DENSITY.1
        ),
        Finding::MomentsFar { error, threshold } => format!(
            "the stated tensor differs from the uniform-density one by {:.1} % (threshold {:.1} \
             %)",
            error * 100.0,
            threshold * 100.0
        ),
        Finding::ComFar {
            fraction,
            threshold,
        } => format!(
            "the stated centre of mass is {:.1} % of the link's size from the uniform-density \
             one (threshold {:.1} %)",
            fraction * 100.0,
            threshold * 100.0
        ),
        Finding::MeshMissing { written, tried } => format!(
            "mesh {written} not found; tried {}{}",
            tried
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", "),
            robot::unexpanded_substitution(written).map_or(String::new(), |s| format!(
                ". Its name holds xacro's substitution {s}, left unexpanded: run xacro on the \
                 description's source, or write the file's name"
            ))
        ),
        Finding::MeshUnreadable { file, error } => {
            format!("mesh {} cannot be weighed: {error}", file.display())
        }
        Finding::GeometryUnsupported { what } => {
            format!("{what} — not integrated, so the link is not weighed")
        }
        Finding::MeshDefect { geometry, warning } => {
            format!("{geometry}: {}", mesh_words(warning))
        }
    }
}

/// Why a link has no computed inertia, in words.
pub fn unweighed_text(u: &Unweighed, geometry: &str) -> String {
    match u {
        Unweighed::NoGeometry => format!("no {geometry} geometry"),
        Unweighed::Incomplete => format!("some {geometry} geometry cannot be weighed"),
        Unweighed::Massless => "its geoms have no mass (density or mass 0)".to_owned(),
        Unweighed::Sum(e) => e.to_string(),
    }
}

/// The geometry a proof takes the mass to lie in, in words.
fn region_text(region: Region) -> String {
    match region {
        Region::Both => "collision and visual geometry".to_owned(),
        Region::Only(kind) => format!("{} geometry", kind.name()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reason a shape is not integrated and the consequence read as two clauses, never as
    /// one ("must be positive is not integrated").
    #[test]
    fn an_unintegrated_shape_keeps_its_reason_apart() {
        let urdf = r#"<robot name="t"><link name="toe">
  <collision><geometry><sphere radius="0.00"/></geometry></collision></link></robot>"#;
        let robot = robot::read_str(urdf, std::path::Path::new("t.urdf"), &Default::default())
            .expect("read");
        let report = robot::audit(&robot, &Default::default());
        let words: Vec<String> = report.links[0]
            .findings
            .iter()
            .filter(|f| f.code() == "geometry_unsupported")
            .map(|f| finding_text(f, "collision", |_| String::new()))
            .collect();
        assert_eq!(
            words,
            [
                "t.urdf:2:24: <sphere radius=\"0.00\">: must be positive — not integrated, so the \
              link is not weighed"
            ]
        );
    }
}
