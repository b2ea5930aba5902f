//! Property tests of the laws mass properties obey: translation, rotation, uniform scaling at
//! fixed density, the parallel-axis theorem and winding reversal.

use crate::common;

use common::{assert_mat, assert_point, assert_rel};
use massprops::integrals::IntegrationPath;
use massprops::shapes::{self, MeshBuilder};
use massprops::solid::solid_properties;
use massprops::{MassProperties, PolyMesh};
use nalgebra::{Point2, Point3, Rotation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

/// Small test bodies, polygonal and triangulated, none with special symmetry except the box.
fn body(kind: usize) -> MeshBuilder {
    match kind {
        0 => shapes::t_handle(),
        1 => shapes::l_bracket().triangulated(),
        2 => shapes::cuboid(Vector3::new(1.0, 2.5, 0.4), Point3::new(0.3, -0.2, 0.9)),
        3 => shapes::prism(&common::star(Point2::new(0.5, 0.2), 1.0, 0.4, 5), 0.0, 0.7)
            .triangulated(),
        _ => {
            let mut b =
                shapes::cuboid(Vector3::new(1.0, 1.0, 1.0), Point3::origin()).triangulated();
            // Pull one corner out: an irregular closed triangle mesh.
            b.positions[6] += Vector3::new(0.4, 0.3, 0.7);
            b
        }
    }
}

fn props(mesh: &PolyMesh, path: IntegrationPath, rho: f64) -> MassProperties {
    solid_properties(mesh, path)
        .and_then(|s| s.with_density(rho))
        .expect("test bodies enclose volume")
}

fn path(k: usize) -> IntegrationPath {
    [IntegrationPath::Polygon, IntegrationPath::Auto][k]
}

fn size(mesh: &PolyMesh) -> f64 {
    let (lo, hi) = mesh.bounding_box();
    (hi - lo).norm()
}

fn rotation() -> impl Strategy<Value = UnitQuaternion<f64>> {
    (-3.2..3.2f64, -1.6..1.6f64, -3.2..3.2f64)
        .prop_map(|(r, p, y)| UnitQuaternion::from_euler_angles(r, p, y))
}

fn vector(r: f64) -> impl Strategy<Value = Vector3<f64>> {
    (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| Vector3::new(x, y, z))
}

/// A number drawn log-uniformly between `lo` and `hi` (every decade equally likely).
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.log10()..hi.log10()).prop_map(|e| 10f64.powf(e))
}

/// A vector of length drawn log-uniformly in [`lo`, `hi`], in any direction.
fn far_vector(lo: f64, hi: f64) -> impl Strategy<Value = Vector3<f64>> {
    (log_uniform(lo, hi), rotation()).prop_map(|(r, q)| q * Vector3::new(r, 0.0, 0.0))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn translation_moves_the_centre_and_keeps_the_central_tensor(
        kind in 0..5usize, p in 0..2usize, t in far_vector(1e-3, 1e6), rho in log_uniform(0.1, 1e4),
    ) {
        let mesh = body(kind).build();
        let moved = mesh.map_positions(|q| q + t).expect("finite");
        let a = props(&mesh, path(p), rho);
        let b = props(&moved, path(p), rho);
        let s = size(&mesh);
        // Vertex coordinates themselves round by ~ulp(|t|) when moved: far away the moved mesh
        // is a slightly different body, by about ε·|t|/size.
        let moved_by = 16.0 * f64::EPSILON * t.amax() / s;
        assert_rel(b.mass, a.mass, 1e-12 + moved_by, "mass");
        assert_point(&b.center_of_mass, &(a.center_of_mass + t), s + t.amax(), 1e-13, "COM");
        assert_mat(&b.inertia_com, &a.inertia_com, 1e-12 * (1.0 + t.amax() / s), "central tensor");
        // About the origin: the moved mesh integrated about the origin itself, not shifted,
        // which loses about (distance / size)² of ε to the cancelling tetrahedra.
        let expect = common::inertia_about_origin(&moved) * rho;
        let far = (t.amax() + s) / s;
        assert_mat(&b.inertia_origin(), &expect, 1e-13 + 64.0 * f64::EPSILON * far * far, "tensor about origin");
    }

    #[test]
    fn rotation_rotates_the_tensor_and_keeps_the_moments(
        kind in 0..5usize, p in 0..2usize, q in rotation(),
    ) {
        let mesh = body(kind).build();
        let turned = mesh.map_positions(|x| q * x).expect("finite");
        let a = props(&mesh, path(p), 1.0);
        let b = props(&turned, path(p), 1.0);
        let r = *q.to_rotation_matrix().matrix();
        let s = size(&mesh);
        assert_rel(b.mass, a.mass, 1e-13, "mass");
        assert_point(&b.center_of_mass, &(q * a.center_of_mass), s, 1e-13, "COM");
        assert_mat(&b.inertia_com, &(r * a.inertia_com * r.transpose()), 1e-12, "R I Rᵀ");
        assert!((b.principal.moments - a.principal.moments).amax() <= 1e-12 * a.principal.moments.amax());
        // MassProperties::transformed predicts the same body.
        let predicted = a.transformed(&nalgebra::Isometry3::from_parts(Vector3::zeros().into(), q));
        assert_mat(&predicted.inertia_com, &b.inertia_com, 1e-12, "transformed()");
        // Distinct principal axes rotate with the body (up to sign).
        if a.principal.degeneracy == massprops::principal::Degeneracy::Distinct {
            let ra = a.principal.rotation.matrix();
            let rb = b.principal.rotation.matrix();
            for i in 0..3 {
                let dot = (r * ra.column(i)).dot(&rb.column(i)).abs();
                prop_assert!(dot > 1.0 - 1e-9, "axis {} turned: |cos| = {}", i, dot);
            }
        }
    }

    #[test]
    fn scaling_at_fixed_density_gives_s_cubed_and_s_to_the_fifth(
        kind in 0..5usize, p in 0..2usize, s in log_uniform(1e-3, 1e3), rho in log_uniform(0.5, 2e4),
    ) {
        let mesh = body(kind).build();
        let scaled = mesh.map_positions(|x| x * s).expect("finite");
        let a = props(&mesh, path(p), rho);
        let b = props(&scaled, path(p), rho);
        assert_rel(b.mass, a.mass * s.powi(3), 1e-12, "m s³");
        assert_point(&b.center_of_mass, &(a.center_of_mass * s), size(&scaled), 1e-13, "COM s");
        assert_mat(&b.inertia_com, &(a.inertia_com * s.powi(5)), 1e-12, "I s⁵");
        let law = a.scaled_at_fixed_density(s).expect("positive scale");
        assert_mat(&law.inertia_com, &b.inertia_com, 1e-12, "scaled_at_fixed_density");
        assert_rel(law.mass, b.mass, 1e-12, "scaled_at_fixed_density mass");
        let fixed_mass = a.scaled_at_fixed_mass(s).expect("positive scale");
        assert_mat(&fixed_mass.inertia_com, &(b.inertia_com / s.powi(3)), 1e-12, "fixed mass: I s²");
    }

    #[test]
    fn parallel_axis_matches_the_body_moved_to_the_point(
        kind in 0..5usize, point in vector(20.0),
    ) {
        let mesh = body(kind).build();
        let a = props(&mesh, IntegrationPath::Auto, 3.0);
        // The tensor about `point` is the tensor about the origin once `point` is the origin,
        // there integrated directly (tetrahedra with their apex at the origin), not shifted.
        let moved = mesh.map_positions(|x| x - point).expect("finite");
        let direct = common::inertia_about_origin(&moved) * 3.0;
        let about = a.inertia_about(&Point3::from(point));
        // The direct sum loses about (distance / size)² of ε to cancelling tetrahedra.
        let s = size(&mesh);
        let far = (point.amax() + a.center_of_mass.coords.amax() + s) / s;
        assert_mat(&about, &direct, 1e-13 + 64.0 * f64::EPSILON * far * far, "inertia_about");
    }

    #[test]
    fn reversing_the_winding_changes_nothing_but_the_flag(
        kind in 0..5usize, p in 0..2usize, q in rotation(), t in vector(5.0),
    ) {
        let mesh = body(kind).build().map_positions(|x| q * x + t).expect("finite");
        let out = solid_properties(&mesh, path(p)).expect("volume");
        let inv = solid_properties(&mesh.flipped(), path(p)).expect("volume");
        prop_assert!(!out.flipped);
        prop_assert!(inv.flipped);
        assert_rel(inv.volume, out.volume, 1e-14, "volume");
        assert_point(&inv.unit_density.center_of_mass, &out.unit_density.center_of_mass, 1.0, 1e-13, "COM");
        assert_mat(&inv.unit_density.inertia_com, &out.unit_density.inertia_com, 1e-13, "tensor");
    }
}

#[test]
fn principal_frame_rebuilds_the_tensor_for_every_law_body() {
    for kind in 0..5 {
        let p = props(&body(kind).build(), IntegrationPath::Auto, 1.0);
        let r: Rotation3<f64> = p.principal.rotation;
        let rebuilt = r.matrix()
            * nalgebra::Matrix3::from_diagonal(&p.principal.moments)
            * r.matrix().transpose();
        assert_mat(&rebuilt, &p.inertia_com, 1e-13, "R diag(I) Rᵀ");
    }
}
