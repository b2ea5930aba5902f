//! `json`: our schema, every number in SI (m, kg, kg·m²), in the mesh's own axes.
//!
//! Both frames are present: `inertia_com` (full tensor about the centre of mass, mesh axes),
//! `inertia_origin` (about the mesh origin) and the principal decomposition. JSON has no
//! comments, so the conventions are the `conventions` object.

use serde_json::json;

use super::frames::Converted;
use crate::conventions::{self, PRINCIPAL_AXES};

/// Version of this export schema; bumped on any incompatible change.
pub const SCHEMA_VERSION: u32 = 1;

/// The JSON document.
pub fn render(body: &Converted) -> String {
    let rows = |m: &nalgebra::Matrix3<f64>| {
        json!([
            [m[(0, 0)], m[(0, 1)], m[(0, 2)]],
            [m[(1, 0)], m[(1, 1)], m[(1, 2)]],
            [m[(2, 0)], m[(2, 1)], m[(2, 2)]]
        ])
    };
    let c = &body.center_of_mass;
    let m = &body.moments;
    let [w, x, y, z] = body.principal_quaternion();
    let doc = json!({
        "schema": "inertia-lab-mass-properties",
        "schema_version": SCHEMA_VERSION,
        "conventions": conventions::block(&[
            ("source", &super::provenance(body)),
            ("units", "SI: lengths in m, mass in kg, inertia in kg*m^2"),
            ("axes", "the mesh's own axes (right-handed), lengths converted to metres"),
            ("inertia_com", "about the centre of mass"),
            ("inertia_origin", "about the mesh origin"),
            ("principal_axes", PRINCIPAL_AXES),
            ("principal_quaternion_xyzw", "unit quaternion [x, y, z, w], w >= 0, rotating principal-axes coordinates into mesh axes: inertia_com = R diag(principal_moments) R^T"),
        ]),
        "mass": body.mass,
        "center_of_mass": [c.x, c.y, c.z],
        "inertia_com": rows(&body.inertia),
        "inertia_origin": rows(&body.inertia_origin),
        "principal_moments": [m.x, m.y, m.z],
        "principal_axes": rows(&body.principal.matrix().transpose()),
        "principal_quaternion_xyzw": [x, y, z, w],
    });
    format!("{doc:#}\n")
}
