//! Presentation of a `massprops::Analysis`: the human table and the JSON object of `props`.

use std::fmt::Write as _;

use massprops::{
    Analysis, Comparison, Composite, Defect, Degeneracy, MassProperties, Method, Orientation,
    Warning,
};
use nalgebra::{Matrix3, Point3, Vector3};
use serde_json::{Value, json};

use crate::export::TENSOR_CONVENTION;

/// Version of the JSON schema printed by `props --json`; bumped on any incompatible change.
/// 2: each warning is an object `{code, message, …its data}` instead of a sentence.
/// 3: each warning has `count`, `faces` (and `face_lines`) and `effect_on_mass`; the codes are
/// those of real-mesh defects (`open_mesh` became `holes_capped`; `non_manifold_edges` and
/// `non_planar_faces` lost their inner underscore); `shells` lists the connected shells.
pub const SCHEMA_VERSION: u32 = 3;

fn rows(m: &Matrix3<f64>) -> Value {
    json!([
        [m[(0, 0)], m[(0, 1)], m[(0, 2)]],
        [m[(1, 0)], m[(1, 1)], m[(1, 2)]],
        [m[(2, 0)], m[(2, 1)], m[(2, 2)]]
    ])
}

fn point(p: &Point3<f64>) -> Value {
    json!([p.x, p.y, p.z])
}

fn vector(v: &Vector3<f64>) -> Value {
    json!([v.x, v.y, v.z])
}

fn degeneracy_name(d: Degeneracy) -> &'static str {
    match d {
        Degeneracy::Distinct => "distinct",
        Degeneracy::Moments12 => "I1=I2",
        Degeneracy::Moments23 => "I2=I3",
        Degeneracy::Spherical => "I1=I2=I3",
    }
}

/// Principal axes as rows: row i is the unit axis of moment i.
fn axes_rows(p: &MassProperties) -> Matrix3<f64> {
    p.principal.rotation.matrix().transpose()
}

fn approximation_json(approx: &MassProperties, exact: &MassProperties) -> Value {
    let c = approx.compare_to(exact);
    json!({
        "center": point(&approx.center_of_mass),
        "inertia": rows(&approx.inertia_com),
        "principal_moments": vector(&approx.principal.moments),
        "principal_moment_error": vector(&c.moment_error),
        "principal_axis_angle_deg": c.axis_angle.map(|a| a.map(f64::to_degrees)),
    })
}

/// The `props --json` object; `lines[f]` is face f's line in the file (empty when it has none).
pub fn json(file: &str, scale: f64, a: &Analysis, lines: &[u32]) -> Value {
    with_inertia(single_json(file, scale, a, lines), &a.properties)
}

/// `props --json` without the keys of [`inertia_json`].
fn single_json(file: &str, scale: f64, a: &Analysis, lines: &[u32]) -> Value {
    let p = &a.properties;
    let d = &a.diagnostics;
    let (lo, hi) = d.bounding_box;
    let density_unit = if a.method == Method::Shell {
        "mass per area"
    } else {
        "mass per volume"
    };
    json!({
        "schema_version": SCHEMA_VERSION,
        "file": file,
        "method": a.method.name(),
        "conventions": {
            "tensor": TENSOR_CONVENTION,
            "frame": "mesh axes; inertia_com about the centre of mass, inertia_origin about the mesh origin",
            "units": "lengths in the mesh unit times scale; mass in the unit of density times length^3",
            "density": density_unit,
            "principal_axes": "row i is the unit axis of principal_moments[i]; rows form a right-handed orthonormal set",
        },
        "scale": scale,
        "density": a.density,
        "volume": a.volume,
        "surface_area": d.surface_area,
        "bounding_box": { "min": point(&lo), "max": point(&hi) },
        "inertia_bbox": rows(&a.bounding_box.inertia_com),
        "inertia_points": rows(&a.point_masses.inertia_com),
        "approximations": {
            "bbox": approximation_json(&a.bounding_box, p),
            "points": approximation_json(&a.point_masses, p),
        },
        "mesh": {
            "vertices": d.vertices,
            "faces": d.faces,
            "triangles": d.triangles,
            "edges": d.edges,
            "closed": d.is_closed(),
            "consistently_oriented": d.is_consistently_oriented(),
            "open_edges": d.open_edges,
            "nonmanifold_edges": d.nonmanifold_edges,
            "inconsistent_edges": d.inconsistent_edges,
            "degenerate_faces": d.degenerate_faces,
            "nonplanar_faces": d.nonplanar_faces,
            "flipped": a.flipped,
        },
        "shells": shells_json(a),
        "warnings": a.warnings.iter().map(|w| warning_json(w, lines)).collect::<Vec<_>>(),
    })
}

/// The command line's wording of a massprops warning. Faces count from 0, as everywhere; where
/// the file has lines (`lines[f]` is face f's), each example face names its line too.
pub fn warning_text(w: &Warning, lines: &[u32]) -> String {
    let faces = faces_text(&w.faces, lines);
    let effect = w.effect_on_mass.map(percent).unwrap_or_default();
    let count = w.count;
    match &w.defect {
        Defect::DuplicateFaces => format!(
            "{count} duplicate face(s) (the same corners, wound the same way, as another face; \
             {faces}): each is counted once; counted twice they would have added {effect} to \
             the mass"
        ),
        Defect::OppositeDuplicateFaces => format!(
            "{count} face(s) listed together with their reverse (internal walls; {faces}): they \
             enclose nothing, so a solid leaves both out and a thin shell keeps one copy"
        ),
        Defect::OverlappingShells {
            pairs,
            volume,
            uncertainty,
            compared,
            candidates,
        } => {
            let mut text = if pairs.is_empty() {
                String::from("no overlapping closed shells were found")
            } else {
                let u = w
                    .effect_on_mass
                    .filter(|&e| e != 0.0)
                    .map(|e| percent((e * uncertainty / volume).abs()).replace('+', ""))
                    .unwrap_or_default();
                format!(
                    "{count} pair(s) of closed shells overlap (shells {}; {faces}): their common \
                     volume, {} ± {} (one standard error, mesh units cubed), is counted twice, \
                     adding {effect} ± {u} to the mass; the numbers are the sum of the shells",
                    shell_pairs(pairs),
                    significant(*volume, 3),
                    significant(*uncertainty, 2),
                )
            };
            if compared < candidates {
                let _ = write!(
                    text,
                    " (only {compared} of the {candidates} pairs of shells whose boxes meet were \
                     compared within the time budget)"
                );
            }
            text
        }
        Defect::NestedShell { shells } => format!(
            "{count} closed shell(s) wound outward inside another solid (shell {}; {faces}): each \
             is counted as solid again, adding {effect} to the mass; if it is meant as a cavity, \
             reverse its faces (it would then remove as much)",
            join(shells)
        ),
        Defect::CracksClosed { largest_gap } => format!(
            "{count} open edge(s) closed by merging vertices at most {} apart (float32 rounding \
             in the file; {faces}): the mass changed by {effect}",
            significant(*largest_gap, 3)
        ),
        Defect::HolesCapped {
            boundary_edges,
            cap_area_fraction,
        } => format!(
            "{count} hole(s) ({boundary_edges} open edges; {faces}) capped by fans from their \
             centres: the caps are {} of the surface and add {} to the mass (how much the result \
             depends on how the holes are closed)",
            percent(*cap_area_fraction),
            w.effect_on_mass.map(|e| percent(-e)).unwrap_or_default()
        ),
        Defect::NonplanarFaces { uncertainty } => format!(
            "{count} non-planar polygon(s) ({faces}), each integrated projected onto its best-fit \
             plane: triangulating them otherwise would change the mass by up to {}",
            percent(*uncertainty)
        ),
        Defect::TwoCornerFaces { lines } => format!(
            "{count} `f` record(s) of fewer than three corners skipped (line {}): segments bound \
             no volume",
            join(lines)
        ),
        Defect::InconsistentWinding { face_pairs } => format!(
            "{count} edge(s) where neighbouring faces wind in opposite senses (faces {}; one of \
             each pair is flipped): the volume method counts flipped faces as negative volume",
            face_pairs_text(face_pairs, lines)
        ),
        Defect::Flipped { whole: true, .. } => "the faces wind clockwise seen from outside \
             (negative signed volume): the results are those of the outward-wound mesh"
            .to_owned(),
        Defect::Flipped { shells, .. } => format!(
            "{count} shell(s) wound inward and inside no other (shell {}; {faces}) were turned \
             outward: counted as wound they would have changed the mass by {effect}",
            join(shells)
        ),
        Defect::DegenerateFaces => {
            format!("{count} face(s) of zero area ({faces}): they contribute nothing")
        }
        Defect::NonmanifoldEdges { edges } => format!(
            "{count} non-manifold edge(s) (shared by more than two faces; e.g. {}): the shells \
             that meet there are each counted in full, and any overlap is reported separately",
            edge_faces(edges, lines)
        ),
        // massprops may add warnings; their code still names them.
        _ => format!("{} (see the massprops documentation)", w.code()),
    }
}

/// A relative change as a signed percentage to two significant digits: "+9.4 %", "-1.2e-7 %".
fn percent(x: f64) -> String {
    let sign = if x > 0.0 { "+" } else { "" };
    format!("{sign}{} %", significant(x * 100.0, 2))
}

/// Indices as "1, 4, 9".
fn join(v: &[usize]) -> String {
    v.iter()
        .map(usize::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// One face as "12" or "12 (line 40)".
fn face_text(f: usize, lines: &[u32]) -> String {
    match lines.get(f) {
        Some(line) => format!("{f} (line {line})"),
        None => f.to_string(),
    }
}

/// "e.g. faces 12 (line 40), 13 (line 41), counting from 0", or "faces not named".
fn faces_text(faces: &[usize], lines: &[u32]) -> String {
    if faces.is_empty() {
        return "no face of the file".to_owned();
    }
    let list: Vec<String> = faces.iter().map(|&f| face_text(f, lines)).collect();
    format!("e.g. faces {}, counting from 0", list.join(", "))
}

/// Shell pairs as "0 and 1, 2 and 5".
fn shell_pairs(pairs: &[(usize, usize)]) -> String {
    pairs
        .iter()
        .map(|(a, b)| format!("{a} and {b}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Non-manifold edges as "edge 3-7 (faces 1, 4 (line 9))".
fn edge_faces(examples: &[((u32, u32), Vec<usize>)], lines: &[u32]) -> String {
    examples
        .iter()
        .map(|((a, b), faces)| {
            let faces: Vec<String> = faces.iter().map(|&f| face_text(f, lines)).collect();
            format!("edge {a}-{b} (faces {})", faces.join(", "))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// Face pairs as "4 and 9, 12 and 13", with lines where known.
fn face_pairs_text(examples: &[(usize, usize)], lines: &[u32]) -> String {
    examples
        .iter()
        .map(|&(a, b)| format!("{} and {}", face_text(a, lines), face_text(b, lines)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The mass, centre of mass, tensors and principal moments and axes: the keys a single mesh and
/// a body of parts share.
fn inertia_json(p: &MassProperties) -> Value {
    json!({
        "mass": p.mass,
        "center_of_mass": point(&p.center_of_mass),
        "inertia_com": rows(&p.inertia_com),
        "inertia_origin": rows(&p.inertia_origin()),
        "principal_moments": vector(&p.principal.moments),
        "principal_axes": rows(&axes_rows(p)),
        "principal_degeneracy": degeneracy_name(p.principal.degeneracy),
    })
}

/// `object` with the keys of [`inertia_json`] added.
fn with_inertia(mut object: Value, p: &MassProperties) -> Value {
    if let (Some(object), Value::Object(keys)) = (object.as_object_mut(), inertia_json(p)) {
        object.extend(keys);
    }
    object
}

/// A warning in JSON: `{code, message, count, faces, effect_on_mass}`, `face_lines` where the
/// file has lines, and the defect's own data.
fn warning_json(w: &Warning, lines: &[u32]) -> Value {
    let mut object = json!({
        "code": w.code(),
        "message": warning_text(w, lines),
        "count": w.count,
        "faces": w.faces,
        "effect_on_mass": w.effect_on_mass,
    });
    if !lines.is_empty() {
        object["face_lines"] = json!(
            w.faces
                .iter()
                .map(|&f| lines.get(f).copied())
                .collect::<Vec<_>>()
        );
    }
    let data = match &w.defect {
        Defect::OverlappingShells {
            pairs,
            volume,
            uncertainty,
            compared,
            candidates,
        } => json!({
            "pairs": pairs.iter().map(|&(a, b)| [a, b]).collect::<Vec<_>>(),
            "overlap_volume": volume,
            "uncertainty": uncertainty,
            "compared": compared,
            "candidates": candidates,
        }),
        Defect::NestedShell { shells } => json!({ "shells": shells }),
        Defect::CracksClosed { largest_gap } => json!({ "largest_gap": largest_gap }),
        Defect::HolesCapped {
            boundary_edges,
            cap_area_fraction,
        } => json!({
            "boundary_edges": boundary_edges,
            "cap_area_fraction": cap_area_fraction,
        }),
        Defect::NonplanarFaces { uncertainty } => json!({ "uncertainty": uncertainty }),
        Defect::TwoCornerFaces { lines } => json!({ "lines": lines }),
        Defect::InconsistentWinding { face_pairs } => json!({
            "face_pairs": face_pairs.iter().map(|&(a, b)| [a, b]).collect::<Vec<_>>(),
        }),
        Defect::Flipped { shells, whole } => json!({ "shells": shells, "whole": whole }),
        Defect::NonmanifoldEdges { edges } => json!({
            "edges": edges
                .iter()
                .map(|((a, b), faces)| json!({ "edge": [a, b], "faces": faces }))
                .collect::<Vec<_>>(),
        }),
        _ => json!({}),
    };
    if let (Some(object), Value::Object(data)) = (object.as_object_mut(), data) {
        object.extend(data);
    }
    object
}

/// The shells in JSON.
fn shells_json(a: &Analysis) -> Value {
    json!(
        a.shells
            .iter()
            .map(|s| json!({
                "faces": s.faces,
                "closed": s.closed,
                "capped": s.capped,
                "volume": s.volume,
                "orientation": match s.orientation {
                    Orientation::Outward => "outward",
                    Orientation::Inward => "inward",
                },
                "depth": s.depth,
            }))
            .collect::<Vec<_>>()
    )
}

/// The `props --json` object of a body made of parts (`kind: "composite"`): the whole, with the
/// same keys as a single mesh's where they apply, and `parts`.
pub fn composite_json(file: &str, units: &str, c: &Composite) -> Value {
    with_inertia(parts_json(file, units, c), &c.properties)
}

/// The composite's object without the keys of [`inertia_json`].
fn parts_json(file: &str, units: &str, c: &Composite) -> Value {
    json!({
        "schema_version": SCHEMA_VERSION,
        "file": file,
        "kind": "composite",
        "conventions": {
            "tensor": TENSOR_CONVENTION,
            "frame": "body axes; inertia_com about the centre of mass, inertia_origin about the body origin",
            "units": units,
            "principal_axes": "row i is the unit axis of principal_moments[i]; rows form a right-handed orthonormal set",
            "share": "each part's share of each principal moment of the whole, about its centre of mass; a void's is negative",
        },
        "parts": c.parts.iter().map(|q| json!({
            "name": q.name,
            "density": q.density,
            "mass": q.mass,
            "volume": q.volume,
            "center_of_mass": point(&q.center_of_mass),
            "inertia_com": rows(&q.inertia_com),
            "share": vector(&q.share),
            "warnings": q.warnings.iter().map(|w| warning_json(w, &[])).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
    })
}

/// The human table of a body made of parts: the whole, then one row per part.
pub fn composite_table(file: &str, units: &str, c: &Composite) -> String {
    let p = &c.properties;
    let mut s = String::new();
    let _ = writeln!(s, "{file}: a body of {} parts ({units})", c.parts.len());
    let _ = writeln!(s, "  mass              {}", num(p.mass).trim_start());
    inertia_lines(&mut s, p, "body");
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

/// `v` rounded to `digits` significant digits, trailing zeros dropped (`0.2`, `7e-11`).
fn significant(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let exponent = v.abs().log10().floor();
    if (-4.0..15.0).contains(&exponent) {
        let decimals = digits as f64 - 1.0 - exponent;
        let text = if decimals >= 0.0 {
            format!("{v:.prec$}", prec = decimals as usize)
        } else {
            // More integer digits than significant ones: round the extra ones away.
            let unit = 10f64.powf(-decimals);
            format!("{:.0}", (v / unit).round() * unit)
        };
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            text
        }
    } else {
        let text = format!("{v:.prec$e}", prec = digits - 1);
        let (mantissa, exp) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        format!("{mantissa}e{exp}")
    }
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
pub fn table(file: &str, scale: f64, a: &Analysis, lines: &[u32]) -> String {
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
    inertia_lines(&mut s, p, "mesh");
    let (lo, hi) = d.bounding_box;
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
fn inertia_lines(s: &mut String, p: &MassProperties, frame: &str) {
    let c = p.center_of_mass;
    let _ = writeln!(
        s,
        "  centre of mass    {} {} {}",
        num(c.x),
        num(c.y),
        num(c.z)
    );
    let _ = writeln!(s, "\nConvention: {TENSOR_CONVENTION}; {frame} axes.");
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
