//! Numerics: bodies far from the origin, tiny and huge bodies, zero-area faces, the principal
//! frame's handedness, and degenerate (equal) moments.

use crate::common;

use common::{assert_mat, assert_rel, box_tensor, tetra_sum};
use massprops::diagnostics::diagnose;
use massprops::integrals::IntegrationPath;
use massprops::principal::Degeneracy;
use massprops::principal::principal_inertia;
use massprops::shapes::{self, MeshBuilder};
use massprops::solid::solid_properties;
use massprops::{MassProperties, MassSpec, MeshError, Method, PolyMesh, analyze, mass_properties};
use nalgebra::{Isometry3, Matrix3, Point2, Point3, Translation3, UnitQuaternion, Vector3};

fn props(mesh: &PolyMesh, path: IntegrationPath) -> MassProperties {
    solid_properties(mesh, path)
        .and_then(|s| s.with_density(1.0))
        .expect("test bodies enclose volume")
}

/// An irregular body whose coordinates are small dyadic rationals, so moving it by 1e6 (or any
/// integer) is exact and any difference is the integrator's: a T prism with a tilted lid.
fn dyadic_body() -> MeshBuilder {
    let outline = [
        Point2::new(-0.375, -3.0),
        Point2::new(0.5, -3.0),
        Point2::new(0.5, 0.0),
        Point2::new(2.25, 0.0),
        Point2::new(2.25, 0.75),
        Point2::new(-2.5, 0.75),
        Point2::new(-2.5, 0.0),
        Point2::new(-0.375, 0.0),
    ];
    let mut b = shapes::prism(&outline, 0.0, 0.625).triangulated();
    let n = outline.len();
    for (i, p) in b.positions[n..].iter_mut().enumerate() {
        p.z += 0.125 * (i % 3) as f64; // an uneven lid: still planar triangles
    }
    b
}

#[test]
fn a_body_moved_1e6_from_the_origin_keeps_its_central_inertia_to_1e_12() {
    let b = dyadic_body();
    let quads_too = shapes::cuboid(Vector3::new(1.5, 0.25, 3.0), Point3::new(0.5, -0.75, 0.25));
    for body in [b, quads_too] {
        let mesh = body.build();
        for offset in [
            Vector3::new(1e6, 0.0, 0.0),
            Vector3::new(1e6, -1e6, 1e6),
            Vector3::new(-3e6, 2e6, 1e6),
        ] {
            let far = mesh.map_positions(|p| p + offset).expect("finite");
            for path in [IntegrationPath::Polygon, IntegrationPath::Auto] {
                let near = props(&mesh, path);
                let away = props(&far, path);
                let what = format!("moved {offset:?}, {path:?}");
                assert_rel(away.mass, near.mass, 1e-12, &what);
                assert_mat(&away.inertia_com, &near.inertia_com, 1e-12, &what);
                // The centre is exact to a few ulps of 1e6 (~1.2e-10).
                let d = (away.center_of_mass - (near.center_of_mass + offset)).amax();
                assert!(d < 1e-9, "{what}: COM off by {d:e}");
            }
        }
    }
}

#[test]
fn the_ten_integrals_of_a_far_body_are_those_of_the_near_one() {
    // The ten integrals are taken about the bounding-box centre, so moving the body moves the
    // reference point with it and leaves the values unchanged up to round-off.
    let mesh = dyadic_body().build();
    let far = mesh
        .map_positions(|p| p + Vector3::new(1e6, 1e6, -1e6))
        .expect("finite");
    let a = massprops::integrals::volume_integrals(&mesh, IntegrationPath::Triangle);
    let b = massprops::integrals::volume_integrals(&far, IntegrationPath::Triangle);
    for (x, y) in a.values.iter().zip(b.values) {
        assert!(
            (x - y).abs() <= 1e-13 * a.values[4].abs().max(a.values[0].abs()),
            "{x} vs {y}"
        );
    }
}

#[test]
fn a_stray_unused_vertex_far_away_costs_no_digits() {
    // OBJ files may carry vertices no face uses; the reference point ignores them.
    let mesh = dyadic_body().build();
    let mut positions = mesh.positions().to_vec();
    positions.push(Point3::new(1e12, -1e12, 1e12));
    let faces: Vec<Vec<usize>> = mesh
        .faces()
        .map(|f| f.iter().map(|&i| i as usize).collect())
        .collect();
    let stray = PolyMesh::new(positions, &faces).expect("valid");
    for path in [IntegrationPath::Polygon, IntegrationPath::Triangle] {
        let clean = props(&mesh, path);
        let with_stray = props(&stray, path);
        let what = format!("{path:?}");
        assert_rel(with_stray.mass, clean.mass, 1e-14, &what);
        assert_mat(&with_stray.inertia_com, &clean.inertia_com, 1e-14, &what);
        assert!(
            (with_stray.center_of_mass - clean.center_of_mass).amax() < 1e-14,
            "{what}"
        );
    }
}

#[test]
fn tiny_and_huge_bodies_have_correct_principal_axes() {
    let rot = UnitQuaternion::from_euler_angles(0.3, -0.8, 1.9);
    let r = *rot.to_rotation_matrix().matrix();
    // Unequal edges so the axes are unique; sorted moments belong to edges (c, b, a) in turn.
    let (a, b, c) = (1.0, 2.0, 3.0);
    for (scale, rho, offset) in [
        (1e-3, 7850.0, Vector3::new(0.2, -0.1, 0.05)), // a 1 × 2 × 3 mm part, in metres
        (1e-6, 1.0, Vector3::new(1e-6, 0.0, 0.0)),     // micrometres: moments ~1e-29
        (1.0, 1.0, Vector3::zeros()),
        (1e6, 1.0, Vector3::new(5e6, 0.0, -2e6)), // 1000 km: moments ~1e31
    ] {
        let size = Vector3::new(a, b, c) * scale;
        let motion = Isometry3::from_parts(Translation3::from(offset), rot);
        let mesh = shapes::cuboid(size, Point3::origin())
            .transformed(&motion)
            .triangulated()
            .build();
        let p = mass_properties(&mesh, rho).expect("closed box");
        let m = rho * size.x * size.y * size.z;
        let what = format!("box at scale {scale:e}");
        assert_rel(p.mass, m, 1e-13, &what);
        assert_mat(
            &p.inertia_com,
            &(r * box_tensor(m, size.x, size.y, size.z) * r.transpose()),
            1e-12,
            &what,
        );
        assert_eq!(p.principal.degeneracy, Degeneracy::Distinct, "{what}");
        let axes = p.principal.rotation.matrix();
        // Smallest moment about the longest edge (z before rotation), largest about the shortest.
        for (i, edge) in [2, 1, 0].into_iter().enumerate() {
            let cos = axes.column(i).dot(&r.column(edge)).abs();
            assert!(cos > 1.0 - 1e-13, "{what}: axis {i} |cos| = {cos}");
        }
        let want = box_tensor(m, size.x, size.y, size.z).diagonal();
        assert_rel(p.principal.moments[0], want.z, 1e-12, &what);
        assert_rel(p.principal.moments[2], want.x, 1e-12, &what);
    }
}

#[test]
fn a_mm_part_in_metres_has_the_axes_of_the_same_part_in_millimetres() {
    let mm = shapes::t_handle()
        .build()
        .map_positions(|p| p * 1000.0)
        .expect("finite");
    let turned = |m: &PolyMesh| {
        let q = UnitQuaternion::from_euler_angles(0.7, 0.2, -0.4);
        m.map_positions(|p| q * p).expect("finite")
    };
    let in_mm = mass_properties(&turned(&mm), 1.0).expect("closed");
    let in_m = mass_properties(&turned(&shapes::t_handle().build()), 1.0).expect("closed");
    assert!(
        in_m.principal.moments.amax() < 1e-6,
        "moments are tiny in metres"
    );
    let (a, b) = (
        in_mm.principal.rotation.matrix(),
        in_m.principal.rotation.matrix(),
    );
    for i in 0..3 {
        assert!(
            a.column(i).dot(&b.column(i)) > 1.0 - 1e-12,
            "axis {i}: {a} vs {b}"
        );
    }
    // Moments scale by 1000⁵ (lengths) at fixed density.
    assert!(
        (in_m.principal.moments * 1e15 - in_mm.principal.moments).amax()
            < 1e-12 * in_mm.principal.moments.amax()
    );
}

/// A unit cube whose top-front edge 4–5 is split by its midpoint 8 on one side, closed by a
/// zero-area sliver triangle (5, 4, 8): closed, consistently wound, with one degenerate face.
fn cube_with_sliver() -> (MeshBuilder, usize) {
    let mut b = shapes::cuboid(Vector3::repeat(1.0), Point3::new(0.5, 0.5, 0.5));
    let side = b
        .faces
        .iter()
        .position(|f| f == &vec![0, 1, 5, 4])
        .expect("the prism's first side");
    let mid = Point3::from((b.positions[4].coords + b.positions[5].coords) / 2.0);
    b.positions.push(mid);
    b.faces[side] = vec![0, 1, 5, 8, 4];
    b.faces.push(vec![5, 4, 8]);
    let sliver = b.faces.len() - 1;
    (b, sliver)
}

#[test]
fn a_zero_area_face_in_a_closed_mesh_contributes_zero_and_no_nan() {
    let (b, sliver) = cube_with_sliver();
    for (name, mesh) in [
        ("polygons", b.build()),
        ("triangles", b.clone().triangulated().build()),
    ] {
        let d = diagnose(&mesh);
        assert!(
            d.is_closed() && d.is_consistently_oriented(),
            "{name}: {d:?}"
        );
        assert!(d.degenerate_faces >= 1, "{name}: {d:?}");
        for path in [
            IntegrationPath::Polygon,
            IntegrationPath::Triangle,
            IntegrationPath::TriangleParallel,
        ] {
            let p = props(&mesh, path);
            assert!(
                p.inertia_com.iter().all(|x| x.is_finite()),
                "{name} {path:?}"
            );
            assert_rel(p.mass, 1.0, 1e-15, name);
            assert!((p.center_of_mass - Point3::new(0.5, 0.5, 0.5)).amax() < 1e-15);
            assert_mat(&p.inertia_com, &(Matrix3::identity() / 6.0), 1e-15, name);
        }
    }
    let d = diagnose(&b.build());
    assert_eq!(d.degenerate_faces, 1);
    assert_eq!(d.degenerate_face_examples, vec![sliver]);
    // A face whose corners all coincide: zero Newell normal on both paths.
    let mut c = shapes::cuboid(Vector3::repeat(1.0), Point3::origin()).triangulated();
    c.faces.push(vec![0, 0, 0]);
    let mesh = c.build();
    for path in [IntegrationPath::Polygon, IntegrationPath::Triangle] {
        let p = props(&mesh, path);
        assert_mat(
            &p.inertia_com,
            &(Matrix3::identity() / 6.0),
            1e-15,
            "collapsed face",
        );
    }
}

#[test]
fn principal_axes_are_right_handed_and_orthonormal() {
    let mut bodies: Vec<(String, PolyMesh)> = shapes::samples()
        .into_iter()
        .map(|(n, _, b)| (n.to_string(), b.build()))
        .collect();
    for (k, q) in [(0.3, 0.1, 2.0), (-1.0, 1.4, 0.2), (3.0, -0.5, -2.5)]
        .into_iter()
        .enumerate()
    {
        let rot = UnitQuaternion::from_euler_angles(q.0, q.1, q.2);
        let m = shapes::l_bracket()
            .build()
            .map_positions(|p| rot * p)
            .expect("finite");
        bodies.push((format!("turned L-bracket {k}"), m));
    }
    for (name, mesh) in bodies {
        let p = mass_properties(&mesh, 1.0).expect("closed");
        let r = p.principal.rotation.matrix();
        assert!(
            (r.transpose() * r - Matrix3::identity()).amax() < 1e-14,
            "{name}: orthonormal"
        );
        assert!(
            (r.determinant() - 1.0).abs() < 1e-14,
            "{name}: right-handed"
        );
        assert!(
            (r.column(0).cross(&r.column(1)) - r.column(2)).amax() < 1e-14,
            "{name}: e1 × e2 = e3"
        );
        let m = p.principal.moments;
        assert!(m[0] <= m[1] && m[1] <= m[2], "{name}: ascending");
        // Each axis is an eigenvector: I a = λ a.
        for i in 0..3 {
            let a = r.column(i);
            assert!(
                (p.inertia_com * a - a * m[i]).amax() < 1e-12 * m[2],
                "{name}: axis {i}"
            );
        }
    }
}

#[test]
fn degenerate_moments_are_reported() {
    let cube = mass_properties(&shapes::cube().build(), 1.0).expect("closed");
    assert_eq!(cube.principal.degeneracy, Degeneracy::Spherical);
    // A turned cube is still spherical: every axis is principal.
    let rot = UnitQuaternion::from_euler_angles(0.4, 0.9, -1.3);
    let turned = shapes::cube()
        .build()
        .map_positions(|p| rot * p)
        .expect("finite");
    assert_eq!(
        mass_properties(&turned, 1.0)
            .expect("closed")
            .principal
            .degeneracy,
        Degeneracy::Spherical
    );

    // A long cylinder (rod): the axial moment is the unique smallest, I2 = I3.
    let rod = mass_properties(&shapes::cylinder(0.5, 0.0, 6.0, 48).build(), 1.0).expect("closed");
    assert_eq!(rod.principal.degeneracy, Degeneracy::Moments23);
    assert!(rod.principal.rotation.matrix().column(0).z.abs() > 1.0 - 1e-14);
    // A disc: the axial moment is the unique largest, I1 = I2.
    let disc = mass_properties(&shapes::cylinder(2.0, 0.0, 0.3, 48).build(), 1.0).expect("closed");
    assert_eq!(disc.principal.degeneracy, Degeneracy::Moments12);
    assert!(disc.principal.rotation.matrix().column(2).z.abs() > 1.0 - 1e-14);
    // A tilted rod: the unique axis follows the tilt.
    let tilt = UnitQuaternion::from_euler_angles(0.6, -0.3, 0.2);
    let tilted = shapes::cylinder(0.5, 0.0, 6.0, 48)
        .build()
        .map_positions(|p| tilt * p)
        .expect("finite");
    let t = mass_properties(&tilted, 1.0).expect("closed");
    assert_eq!(t.principal.degeneracy, Degeneracy::Moments23);
    let axis = tilt * Vector3::z();
    assert!(t.principal.rotation.matrix().column(0).dot(&axis).abs() > 1.0 - 1e-13);
    // Book: three distinct moments along the mesh axes.
    let book = mass_properties(&shapes::book().build(), 1.0).expect("closed");
    assert_eq!(book.principal.degeneracy, Degeneracy::Distinct);
    // Nearly equal but distinct moments (relative gap 1e-6 ≫ tolerance) are not degenerate.
    let near = principal_inertia(&Matrix3::from_diagonal(&Vector3::new(1.0, 1.0 + 1e-6, 2.0)));
    assert_eq!(near.degeneracy, Degeneracy::Distinct);
}

#[test]
fn the_independent_tetrahedron_sum_agrees_far_from_the_origin() {
    // Cross-check of the test's own reference method with a body away from the origin.
    let mesh = dyadic_body()
        .build()
        .map_positions(|p| p + Vector3::new(1e3, -2e3, 5e2))
        .expect("finite");
    let (v, c, i) = tetra_sum(&mesh);
    let p = props(&mesh, IntegrationPath::Polygon);
    assert_rel(p.mass, v, 1e-12, "volume");
    assert!((p.center_of_mass - c).amax() < 1e-10);
    assert_mat(&p.inertia_com, &i, 1e-10, "tensor");
}

#[test]
fn extreme_scales_keep_full_relative_accuracy_on_both_paths() {
    let base = shapes::l_bracket();
    let reference = props(&base.build(), IntegrationPath::Polygon);
    for s in [1e-45, 1e-30, 1e-12, 1e12, 1e30, 1e45] {
        let scaled = base.build().map_positions(|p| p * s).expect("finite");
        let tri = base
            .clone()
            .triangulated()
            .build()
            .map_positions(|p| p * s)
            .expect("finite");
        for (what, mesh, path) in [
            ("polygon", &scaled, IntegrationPath::Polygon),
            ("triangle", &tri, IntegrationPath::Triangle),
        ] {
            let p = props(mesh, path);
            let what = format!("L-bracket × {s:e}, {what}");
            assert_rel(p.mass, reference.mass * s.powi(3), 1e-13, &what);
            assert_mat(
                &p.inertia_com,
                &(reference.inertia_com * s.powi(5)),
                1e-12,
                &what,
            );
        }
    }
}

#[test]
fn sizes_beyond_f64_are_refused_never_reported_as_nan_or_zero() {
    let base = shapes::book().build();
    let unit = analyze(&base, Method::Volume, MassSpec::Density(1.0)).expect("closed");
    let unit_shell = analyze(&base, Method::Shell, MassSpec::Density(1.0)).expect("area");
    let mut refused = Vec::new();
    for k in (-120..=120).step_by(5) {
        let s = 10f64.powi(k);
        let mesh = base.map_positions(|p| p * s).expect("finite");
        // Each result is the unit book's by the scaling laws, or a refusal naming the range.
        let cases = [
            (
                Method::Volume,
                MassSpec::Density(1.0),
                &unit,
                s.powi(3),
                s.powi(5),
            ),
            (Method::Volume, MassSpec::Mass(28.0), &unit, 1.0, s * s),
            (
                Method::Shell,
                MassSpec::Density(1.0),
                &unit_shell,
                s * s,
                s.powi(4),
            ),
            (Method::Points, MassSpec::Mass(28.0), &unit, 1.0, s * s),
        ];
        for (method, spec, unit, mass_factor, inertia_factor) in cases {
            let what = format!("book × 1e{k}, {method:?}, {spec:?}");
            match analyze(&mesh, method, spec) {
                Ok(r) => {
                    let want = if method == Method::Points {
                        &unit.point_masses
                    } else {
                        &unit.properties
                    };
                    assert_rel(r.properties.mass, want.mass * mass_factor, 1e-14, &what);
                    assert_mat(
                        &r.properties.inertia_com,
                        &(want.inertia_com * inertia_factor),
                        1e-13,
                        &what,
                    );
                    assert!(r.diagnostics.surface_area.is_finite(), "{what}");
                    assert_eq!(r.diagnostics.degenerate_faces, 0, "{what}");
                }
                Err(MeshError::OutOfRange { quantity, .. }) => refused.push((k, quantity)),
                Err(e) => panic!("{what}: {e}"),
            }
        }
    }
    // Everything from 1e-45 to 1e45 works (density 1: inertia 1e±225); far beyond, lengths
    // themselves are refused.
    assert!(
        refused.iter().all(|&(k, _)| !(-45..=45).contains(&k)),
        "{refused:?}"
    );
    assert!(refused.contains(&(-120, "size".into())) && refused.contains(&(120, "size".into())));
    // Size 7 with density 1e-260: mass ~ 3e-258. Mass 1e249: inertia ~ 5e250.
    for (spec, quantity) in [
        (MassSpec::Density(1e-260), "mass"),
        (MassSpec::Mass(1e249), "inertia"),
    ] {
        match analyze(&base, Method::Volume, spec) {
            Err(e @ MeshError::OutOfRange { .. }) => {
                assert!(e.to_string().contains(&format!("the {quantity} of")), "{e}");
            }
            other => panic!("{spec:?}: {other:?}"),
        }
    }
}
