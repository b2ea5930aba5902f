//! The human `props` table: one mesh ([`single`]) or a body of parts ([`composite`]), numbers to
//! `TABLE_DIGITS` significant digits.

use std::fmt::Write as _;

use massprops::defects::Orientation;
use massprops::properties::Comparison;
use massprops::{Analysis, Composite, MassProperties, Method};
use nalgebra::Matrix3;

use super::json::axes_rows;
use super::significant;
use super::words::warning_text;
use crate::conventions::TENSOR;

/// The human table of a body made of parts: the whole, then one row per part.
pub fn composite(file: &str, units: &str, c: &Composite) -> String {
    let p = &c.properties;
    let mut s = String::new();
    let _ = writeln!(s, "{file}: a body of {} parts ({units})", c.parts.len());
    let _ = writeln!(s, "  mass              {}", num(p.mass).trim_start());
    // Its size: the parts' boxes are not kept; the root-mean-square distance of its mass from
    // the centre (tr I = 2∫r² dm), never more than the box diagonal, is.
    inertia_lines(
        &mut s,
        p,
        "body",
        (p.inertia_com.trace() / (2.0 * p.mass)).abs().sqrt(),
    );
    let _ = writeln!(
        s,
        "\nParts (a void's mass is negative; share = part of each principal moment):"
    );
    let _ = writeln!(
        s,
        "  {:<16} {:>12} {:>12} {:>12}   {:<32} share of I1 I2 I3",
        "name", "density", "mass", "volume", "centre of mass"
    );
    for q in &c.parts {
        let c = q.center_of_mass;
        let _ = writeln!(
            s,
            "  {:<16} {:>12} {:>12} {:>12}   {:<32} {:>5.1} % {:>5.1} % {:>5.1} %",
            q.name,
            significant(q.density, 5),
            significant(q.mass, 6),
            significant(q.volume, 6),
            format!(
                "{} {} {}",
                significant(c.x, 5),
                significant(c.y, 5),
                significant(c.z, 5)
            ),
            100.0 * q.share.x,
            100.0 * q.share.y,
            100.0 * q.share.z,
        );
    }
    let warned: Vec<_> = c.parts.iter().filter(|q| !q.warnings.is_empty()).collect();
    if warned.is_empty() {
        let _ = writeln!(s, "\nNo warnings.");
    } else {
        let _ = writeln!(s, "\nWarnings (faces count within each part):");
        for q in warned {
            for w in &q.warnings {
                let _ = writeln!(s, "  - {}: {}", q.name, warning_text(w, &[]));
            }
        }
    }
    s
}

/// Significant digits of the human table (JSON keeps every digit).
const TABLE_DIGITS: usize = 10;

/// A matrix entry smaller than this fraction of the matrix's largest entry is round-off of a
/// zero (e.g. `-4.9e-27` beside `7e-11`) and is printed as 0.
const TABLE_ZERO: f64 = 1e-12;

/// `v` to [`TABLE_DIGITS`] significant digits without trailing zeros, right-aligned: plain
/// notation for moderate magnitudes, exponent notation for very small or large ones.
fn num(v: f64) -> String {
    format!("{:>17}", significant(v, TABLE_DIGITS))
}

fn matrix_lines(out: &mut String, m: &Matrix3<f64>) {
    let largest = m.amax();
    let entry = |v: f64| {
        num(if v.abs() < TABLE_ZERO * largest {
            0.0
        } else {
            v
        })
    };
    for r in 0..3 {
        let _ = writeln!(
            out,
            "    [{} {} {} ]",
            entry(m[(r, 0)]),
            entry(m[(r, 1)]),
            entry(m[(r, 2)])
        );
    }
}

fn comparison_line(out: &mut String, name: &str, c: &Comparison, approx: &MassProperties) {
    let angles: Vec<String> = c
        .axis_angle
        .iter()
        .map(|a| {
            a.map_or("n/a (equal moments)".into(), |a| {
                format!("{:.3}°", a.to_degrees())
            })
        })
        .collect();
    let _ = writeln!(
        out,
        "  {name}\n    principal moments {} {} {}\n    moment error       {:+.2}% {:+.2}% {:+.2}%\n    axis angles        {}\n    centre offset      {}",
        num(approx.principal.moments.x),
        num(approx.principal.moments.y),
        num(approx.principal.moments.z),
        c.moment_error.x * 100.0,
        c.moment_error.y * 100.0,
        c.moment_error.z * 100.0,
        angles.join(", "),
        num(c.com_offset).trim_start(),
    );
}

/// The human-readable `props` table.
pub fn single(file: &str, scale: f64, a: &Analysis, lines: &[u32]) -> String {
    let p = &a.properties;
    let d = &a.diagnostics;
    let mut s = String::new();
    let method = match a.method {
        Method::Volume => "volume (solid of uniform density, Mirtich 1996)",
        Method::Shell => "shell (thin wall of uniform surface density)",
        Method::Points => "points (equal masses at the vertices; approximation)",
        Method::BoundingBox => "bbox (solid cuboid filling the bounding box; approximation)",
    };
    let _ = writeln!(s, "Mass properties of {file}");
    let _ = writeln!(s, "  method            {method}");
    if scale != 1.0 {
        let _ = writeln!(
            s,
            "  scale             {scale} (applied to every coordinate)"
        );
    }
    let opt = |v: Option<f64>| v.map_or("n/a".to_string(), |v| num(v).trim_start().to_string());
    let _ = writeln!(s, "  density           {}", opt(a.density));
    let _ = writeln!(s, "  volume            {}", opt(a.volume));
    let _ = writeln!(s, "  mass              {}", num(p.mass).trim_start());
    let _ = writeln!(
        s,
        "  surface area      {}",
        num(d.surface_area).trim_start()
    );
    let (lo, hi) = d.bounding_box;
    inertia_lines(&mut s, p, "mesh", (hi - lo).norm());
    let _ = writeln!(
        s,
        "\nBounding box  min {} {} {}",
        num(lo.x),
        num(lo.y),
        num(lo.z)
    );
    let _ = writeln!(
        s,
        "              max {} {} {}",
        num(hi.x),
        num(hi.y),
        num(hi.z)
    );
    let _ = writeln!(
        s,
        "\nApproximations with the same mass, compared with the {} result:",
        a.method.name()
    );
    comparison_line(
        &mut s,
        "bounding-box cuboid (about the box centre)",
        &a.bounding_box.compare_to(p),
        &a.bounding_box,
    );
    comparison_line(
        &mut s,
        "vertex point masses (about their centre)",
        &a.point_masses.compare_to(p),
        &a.point_masses,
    );
    let yes = |b: bool| if b { "yes" } else { "no" };
    let _ = writeln!(
        s,
        "\nMesh: {} vertices, {} faces, {} triangles, {} edges\n  closed {}, consistently oriented {}, flipped {}\n  open edges {}, non-manifold edges {}, inconsistent edges {}, degenerate faces {}, non-planar faces {}",
        d.vertices,
        d.faces,
        d.triangles,
        d.edges,
        yes(d.is_closed()),
        yes(d.is_consistently_oriented()),
        yes(a.flipped),
        d.open_edges,
        d.nonmanifold_edges,
        d.inconsistent_edges,
        d.degenerate_faces,
        d.nonplanar_faces
    );
    shell_lines(&mut s, a);
    if a.warnings.is_empty() {
        let _ = writeln!(s, "\nNo warnings.");
    } else {
        let _ = writeln!(s, "\nWarnings:");
        for w in &a.warnings {
            let _ = writeln!(s, "  - {}", warning_text(w, lines));
        }
    }
    s
}

/// The centre of mass, the tensors about it and about the origin of `frame` ("mesh", "body"),
/// the principal moments and axes: the table's lines for one set of mass properties.
/// `size` is the body's size (the bounding box's diagonal): a centre-of-mass coordinate below
/// [`TABLE_ZERO`] of it is round-off and prints as 0, as tensor entries below that of the
/// largest do.
fn inertia_lines(s: &mut String, p: &MassProperties, frame: &str, size: f64) {
    let c = p
        .center_of_mass
        .map(|x| if x.abs() < TABLE_ZERO * size { 0.0 } else { x });
    let _ = writeln!(
        s,
        "  centre of mass    {} {} {}",
        num(c.x),
        num(c.y),
        num(c.z)
    );
    let _ = writeln!(s, "\nConvention: {TENSOR}; {frame} axes.");
    let _ = writeln!(s, "  inertia about the centre of mass");
    matrix_lines(s, &p.inertia_com);
    let _ = writeln!(s, "  inertia about the {frame} origin");
    matrix_lines(s, &p.inertia_origin());
    let m = p.principal.moments;
    let _ = writeln!(
        s,
        "  principal moments (ascending) {} {} {}",
        num(m.x),
        num(m.y),
        num(m.z)
    );
    let _ = writeln!(s, "    {}", p.principal.degeneracy.describe());
    let _ = writeln!(
        s,
        "  principal axes (row i = axis of moment i, right-handed)"
    );
    matrix_lines(s, &axes_rows(p));
}

/// How many shells the table lists one by one.
const TABLE_SHELLS: usize = 8;

/// "Shells: 2" and a line for each of the first few.
fn shell_lines(s: &mut String, a: &Analysis) {
    let _ = writeln!(s, "  shells {}", a.shells.len());
    if a.shells.len() < 2 {
        return;
    }
    for (i, shell) in a.shells.iter().take(TABLE_SHELLS).enumerate() {
        let depth = shell
            .depth
            .map_or_else(|| "depth not known".to_owned(), |d| format!("depth {d}"));
        let _ = writeln!(
            s,
            "    shell {i}: {} faces, {}, {}, {depth}, volume {}",
            shell.faces,
            if shell.closed {
                "closed"
            } else {
                "open (capped)"
            },
            match shell.orientation {
                Orientation::Outward => "outward",
                Orientation::Inward => "inward",
            },
            significant(shell.volume, TABLE_DIGITS)
        );
    }
    if a.shells.len() > TABLE_SHELLS {
        let _ = writeln!(s, "    … and {} more", a.shells.len() - TABLE_SHELLS);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ten_significant_digits_without_trailing_zeros() {
        assert_eq!(significant(0.20000000000000004, 10), "0.2");
        assert_eq!(significant(6.999999999999999e-11, 10), "7e-11");
        assert_eq!(significant(-1234.5678901234, 10), "-1234.56789");
        assert_eq!(significant(123456789012.0, 10), "123456789000");
        assert_eq!(significant(1.0 / 3.0, 10), "0.3333333333");
        assert_eq!(significant(-2.5e20, 10), "-2.5e20");
        assert_eq!(significant(0.0, 10), "0");
        assert_eq!(significant(f64::NAN, 10), "NaN");
    }

    #[test]
    fn round_off_beside_large_entries_prints_as_zero() {
        let m = Matrix3::new(
            7e-11, -4.9e-27, 0.0, -4.9e-27, 7e-11, 2e-13, 0.0, 2e-13, 5e-11,
        );
        let mut out = String::new();
        matrix_lines(&mut out, &m);
        let rows: Vec<Vec<&str>> = out
            .lines()
            .map(|l| {
                l.trim_matches(|c| c == ' ' || c == '[' || c == ']')
                    .split_whitespace()
                    .collect()
            })
            .collect();
        assert_eq!(rows[0], ["7e-11", "0", "0"]);
        // 2e-13 is 3e-3 of the largest entry: a real product of inertia, kept.
        assert_eq!(rows[1], ["0", "7e-11", "2e-13"]);
    }
}
