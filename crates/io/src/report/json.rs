//! The `props --json` object: one mesh ([`single`]) or a body of parts ([`composite`]), in the
//! versioned schema docs/props.md documents.

use massprops::defects::Orientation;
use massprops::principal::Degeneracy;
use massprops::{Analysis, Composite, Defect, MassProperties, Method, Warning};
use nalgebra::{Matrix3, Point3, Vector3};
use serde_json::{Value, json};

use super::words::warning_text;
use crate::conventions::{self, PRINCIPAL_AXES};

/// Version of the JSON schema printed by `props --json`; bumped on any incompatible change.
/// 2: each warning is an object `{code, message, …its data}` instead of a sentence.
/// 3: each warning has `count`, `faces` (and `face_lines`) and `effect_on_mass`; the codes are
/// those of real-mesh defects (`open_mesh` became `holes_capped`; `non_manifold_edges` and
/// `non_planar_faces` lost their inner underscore); `shells` lists the connected shells.
/// 4: `inconsistent_winding` repaired: its `count` is the faces turned (the edges only when they cannot
/// agree) and it has an `effect_on_mass`; new codes `self_overlapping_shell` and
/// `stl_triangle_count`; `overlapping_shells` has `uncompared_bound`.
pub const SCHEMA_VERSION: u32 = 4;

/// A 3×3 matrix as JSON rows.
pub(crate) fn rows(m: &Matrix3<f64>) -> Value {
    json!([
        [m[(0, 0)], m[(0, 1)], m[(0, 2)]],
        [m[(1, 0)], m[(1, 1)], m[(1, 2)]],
        [m[(2, 0)], m[(2, 1)], m[(2, 2)]]
    ])
}

/// A point as `[x, y, z]`.
pub(crate) fn point(p: &Point3<f64>) -> Value {
    json!([p.x, p.y, p.z])
}

/// A vector as `[x, y, z]`.
pub(crate) fn vector(v: &Vector3<f64>) -> Value {
    json!([v.x, v.y, v.z])
}

pub(super) fn degeneracy_name(d: Degeneracy) -> &'static str {
    match d {
        Degeneracy::Distinct => "distinct",
        Degeneracy::Moments12 => "I1=I2",
        Degeneracy::Moments23 => "I2=I3",
        Degeneracy::Spherical => "I1=I2=I3",
    }
}

/// Principal axes as rows: row i is the unit axis of moment i.
pub(super) fn axes_rows(p: &MassProperties) -> Matrix3<f64> {
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
pub fn single(file: &str, scale: f64, a: &Analysis, lines: &[u32]) -> Value {
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
        "conventions": conventions::block(&[
            ("frame", "mesh axes; inertia_com about the centre of mass, inertia_origin about the mesh origin"),
            ("units", "lengths in the mesh unit times scale; mass in the unit of density times length^3"),
            ("density", density_unit),
            ("principal_axes", PRINCIPAL_AXES),
        ]),
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

/// The object of a solid integrated without looking for defects (the Python package's
/// `check=False`): the keys a single mesh and a body of parts share, with the density and the
/// volume, `file` null (arrays, not a file) and `warnings` null (not looked for).
pub fn unchecked(density: f64, volume: f64, flipped: bool, p: &MassProperties) -> Value {
    let object = json!({
        "schema_version": SCHEMA_VERSION,
        "file": null,
        "method": Method::Volume.name(),
        "checked": false,
        "conventions": conventions::block(&[
            ("frame", "mesh axes; inertia_com about the centre of mass, inertia_origin about the mesh origin"),
            ("units", "lengths in the mesh unit; mass in the unit of density times length^3"),
            ("density", "mass per volume"),
            ("principal_axes", PRINCIPAL_AXES),
        ]),
        "density": density,
        "volume": volume,
        "flipped": flipped,
        "warnings": null,
    });
    with_inertia(object, p)
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
            uncompared_bound,
        } => json!({
            "pairs": pairs.iter().map(|&(a, b)| [a, b]).collect::<Vec<_>>(),
            "overlap_volume": volume,
            "uncertainty": uncertainty,
            "compared": compared,
            "candidates": candidates,
            "uncompared_bound": uncompared_bound,
        }),
        Defect::NestedShell { shells } => json!({ "shells": shells }),
        Defect::SelfOverlappingShell {
            shells,
            volume,
            uncertainty,
            crossing_faces,
            total_effect,
            total_uncertainty,
        } => json!({
            "shells": shells,
            "overlap_volume": volume,
            "uncertainty": uncertainty,
            "crossing_faces": crossing_faces,
            "total_effect_on_mass": total_effect,
            "total_uncertainty": total_uncertainty,
        }),
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
        Defect::StlTriangleCount { header, records } => {
            json!({ "header_count": header, "records": records })
        }
        Defect::UpAxisNotApplied { axis } => json!({ "up_axis": axis }),
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
        // Their faces (above) are all there is to say.
        Defect::DuplicateFaces | Defect::OppositeDuplicateFaces | Defect::DegenerateFaces => {
            json!({})
        }
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
pub fn composite(file: &str, units: &str, c: &Composite) -> Value {
    with_inertia(parts_json(file, units, c), &c.properties)
}

/// The composite's object without the keys of [`inertia_json`].
fn parts_json(file: &str, units: &str, c: &Composite) -> Value {
    json!({
        "schema_version": SCHEMA_VERSION,
        "file": file,
        "kind": "composite",
        "conventions": conventions::block(&[
            ("frame", "body axes; inertia_com about the centre of mass, inertia_origin about the body origin"),
            ("units", units),
            ("principal_axes", PRINCIPAL_AXES),
            ("share", "each part's share of each principal moment of the whole, about its centre of mass; a void's is negative"),
        ]),
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
