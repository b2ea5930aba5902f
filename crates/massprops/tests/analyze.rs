//! `massprops::analyze` for every method, with a density or a mass, against closed forms, and
//! the warnings it gives.

use crate::common;

use common::{assert_mat, assert_rel, box_tensor, prism_closed_form, steiner};
use massprops::shapes;
use massprops::{Defect, MassSpec, Method, Warning, analyze};
use nalgebra::{Matrix3, Point2, Point3, Vector3};

/// The book 1 × 4 × 7 centred on the origin: every method has a closed form.
#[test]
fn every_method_on_the_book_with_density_and_with_mass() {
    let mesh = shapes::book().build();
    let (a, b, c) = (1.0, 4.0, 7.0);
    let volume = a * b * c;
    let area = 2.0 * (a * b + b * c + a * c);
    for spec in [MassSpec::Density(2.0), MassSpec::Mass(56.0)] {
        // Volume.
        let r = analyze(&mesh, Method::Volume, spec).expect("closed");
        assert_eq!(r.method, Method::Volume);
        assert_rel(r.volume.expect("closed"), volume, 1e-15, "volume");
        assert_rel(r.density.expect("known"), 2.0, 1e-15, "density");
        assert_rel(r.properties.mass, 56.0, 1e-15, "mass");
        assert_mat(
            &r.properties.inertia_com,
            &box_tensor(56.0, a, b, c),
            1e-14,
            "volume tensor",
        );
        assert!(r.warnings.is_empty(), "{:?}", r.warnings);
        assert!(!r.flipped);
        assert_rel(r.diagnostics.surface_area, area, 1e-15, "area");
        // The approximations come along at the same mass: the box is its own bounding box, and
        // its 8 corners at (±a/2, ±b/2, ±c/2) carry m/8 each: Ixx = m((b/2)² + (c/2)²).
        assert_mat(
            &r.bounding_box.inertia_com,
            &box_tensor(56.0, a, b, c),
            1e-14,
            "bbox",
        );
        let corners =
            Matrix3::from_diagonal(&Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b))
                * (56.0 / 4.0);
        assert_mat(&r.point_masses.inertia_com, &corners, 1e-14, "corners");

        // Points and bounding box as the chosen method: same mass as the solid.
        let p = analyze(&mesh, Method::Points, spec).expect("closed");
        assert_rel(p.properties.mass, 56.0, 1e-15, "points mass");
        assert_mat(&p.properties.inertia_com, &corners, 1e-14, "points tensor");
        let bb = analyze(&mesh, Method::BoundingBox, spec).expect("closed");
        assert_mat(
            &bb.properties.inertia_com,
            &box_tensor(56.0, a, b, c),
            1e-14,
            "bbox tensor",
        );
    }
    // Shell: six plates. Each plate of sides (u, v) in its plane and mass σuv contributes, about
    // the centre, its own plate tensor plus the parallel-axis term of its offset.
    let sigma = 0.5;
    let plate = |size: Vector3<f64>, offset: Vector3<f64>| {
        let sides: Vec<f64> = size.iter().copied().filter(|&x| x > 0.0).collect();
        let m = sigma * sides[0] * sides[1];
        // A plate is a box with one zero edge.
        box_tensor(m, size.x, size.y, size.z) + steiner(m, &offset)
    };
    let mut want = Matrix3::zeros();
    for sign in [-1.0, 1.0] {
        want += plate(
            Vector3::new(0.0, b, c),
            Vector3::new(sign * a / 2.0, 0.0, 0.0),
        );
        want += plate(
            Vector3::new(a, 0.0, c),
            Vector3::new(0.0, sign * b / 2.0, 0.0),
        );
        want += plate(
            Vector3::new(a, b, 0.0),
            Vector3::new(0.0, 0.0, sign * c / 2.0),
        );
    }
    let s = analyze(&mesh, Method::Shell, MassSpec::Density(sigma)).expect("area");
    assert_rel(s.properties.mass, sigma * area, 1e-15, "shell mass");
    assert_rel(s.density.expect("given"), sigma, 1e-15, "shell density");
    assert_mat(&s.properties.inertia_com, &want, 1e-14, "shell tensor");
    let by_mass = analyze(&mesh, Method::Shell, MassSpec::Mass(sigma * area)).expect("area");
    assert_rel(
        by_mass.density.expect("derived"),
        sigma,
        1e-15,
        "σ = m / area",
    );
    assert_mat(
        &by_mass.properties.inertia_com,
        &want,
        1e-14,
        "shell by mass",
    );
}

/// The L-bracket: centre of mass far from the bounding-box centre, so the approximations differ.
#[test]
fn l_bracket_solid_versus_its_approximations() {
    let outline = [
        Point2::new(0.0, 0.0),
        Point2::new(0.1, 0.0),
        Point2::new(0.1, 0.01),
        Point2::new(0.01, 0.01),
        Point2::new(0.01, 0.06),
        Point2::new(0.0, 0.06),
    ];
    let (v, com, about_origin) = prism_closed_form(&outline, 0.0, 0.03);
    let rho = 2700.0;
    let m = rho * v;
    let central = (about_origin - steiner(v, &com.coords)) * rho;
    let mesh = shapes::l_bracket().build();
    let r = analyze(&mesh, Method::Volume, MassSpec::Mass(m)).expect("closed");
    assert_rel(r.density.expect("derived"), rho, 1e-13, "density from mass");
    assert!((r.properties.center_of_mass - com).amax() < 1e-15);
    assert_mat(&r.properties.inertia_com, &central, 1e-13, "L-bracket");
    // Bounding box: 0.1 × 0.06 × 0.03 at its centre, same mass.
    assert!((r.bounding_box.center_of_mass - Point3::new(0.05, 0.03, 0.015)).amax() < 1e-16);
    assert_mat(
        &r.bounding_box.inertia_com,
        &box_tensor(m, 0.1, 0.06, 0.03),
        1e-14,
        "bbox",
    );
    assert!(
        (r.bounding_box.center_of_mass - com).norm() > 0.01,
        "the bbox centre is far off"
    );
    // Points: 12 corners, m/12 each, written out.
    let mut centre = Vector3::zeros();
    let mut corners = Vec::new();
    for z in [0.0, 0.03] {
        for p in &outline {
            corners.push(Vector3::new(p.x, p.y, z));
            centre += Vector3::new(p.x, p.y, z) / 12.0;
        }
    }
    let want: Matrix3<f64> = corners
        .iter()
        .map(|p| steiner(m / 12.0, &(p - centre)))
        .sum();
    let pts = analyze(&mesh, Method::Points, MassSpec::Density(rho)).expect("closed");
    assert_rel(pts.properties.mass, m, 1e-13, "points mass");
    assert!((pts.properties.center_of_mass.coords - centre).amax() < 1e-16);
    assert_mat(&pts.properties.inertia_com, &want, 1e-13, "points");
}

#[test]
fn warnings_say_what_is_wrong() {
    let clean = analyze(
        &shapes::sample_torus().build(),
        Method::Volume,
        MassSpec::Density(1.0),
    )
    .expect("closed");
    assert!(clean.warnings.is_empty(), "{:?}", clean.warnings);
    assert!(clean.diagnostics.is_closed());

    let inside_out = analyze(
        &shapes::cube().build().flipped(),
        Method::Volume,
        MassSpec::Density(1.0),
    )
    .expect("closed");
    assert!(inside_out.flipped);
    assert_eq!(
        inside_out.warnings,
        vec![Warning {
            defect: Defect::Flipped {
                shells: vec![0],
                whole: true
            },
            count: 1,
            faces: vec![0, 1, 2, 3, 4],
            effect_on_mass: Some(0.0),
        }]
    );
    // For a shell, winding is irrelevant: no flip warning.
    let shell = analyze(
        &shapes::cube().build().flipped(),
        Method::Shell,
        MassSpec::Density(1.0),
    )
    .expect("area");
    assert!(shell.warnings.is_empty(), "{:?}", shell.warnings);
    assert_rel(shell.properties.mass, 6.0, 1e-15, "six faces");

    let mut open = shapes::cube();
    open.faces.remove(0);
    let r = analyze(&open.build(), Method::Points, MassSpec::Density(1.0)).expect("some volume");
    // The cube's first face (z = 0) is gone: one hole of four edges, capped by four triangles
    // that fill the square exactly (1 of the 5 remaining unit faces' area). About the centre, the
    // cap carries the pyramid from the centre to that face: a sixth of the cube.
    assert_eq!(r.volume, Some(1.0));
    assert_eq!(r.warnings.len(), 1, "{:?}", r.warnings);
    let w = &r.warnings[0];
    assert_eq!(w.code(), "holes_capped");
    assert_eq!(w.count, 1);
    assert_eq!(w.faces, vec![1, 2, 3, 4]);
    let Defect::HolesCapped {
        boundary_edges,
        cap_area_fraction,
    } = w.defect
    else {
        panic!("{w:?}")
    };
    assert_eq!(boundary_edges, 4);
    assert_rel(cap_area_fraction, 0.2, 1e-15, "cap area");
    assert_rel(
        w.effect_on_mass.expect("known"),
        -1.0 / 6.0,
        1e-15,
        "cap volume",
    );
}

#[test]
fn a_flipped_face_is_turned_to_agree_with_its_neighbours() {
    // A unit cube with its +x face wound inwards: taken literally ∫x·nₓ cancels exactly and the
    // volume is 0 (this was refused as "4 inconsistently wound edges"). The face is turned to
    // agree with its four neighbours: the unit cube, and the warning names the one face turned
    // and what it took away (its cone from the reference point, the cube's centre: a sixth,
    // counted negative instead of positive).
    let p = |x: f64, y: f64, z: f64| nalgebra::Point3::new(x, y, z);
    let pts = vec![
        p(0., 0., 0.),
        p(1., 0., 0.),
        p(1., 1., 0.),
        p(0., 1., 0.),
        p(0., 0., 1.),
        p(1., 0., 1.),
        p(1., 1., 1.),
        p(0., 1., 1.),
    ];
    let faces = [
        [0, 3, 2, 1],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [3, 7, 6, 2],
        [0, 4, 7, 3],
        [1, 5, 6, 2], // outward would be [1, 2, 6, 5]
    ];
    let mesh = massprops::PolyMesh::new(pts, &faces).expect("valid");
    let a = massprops::analyze(
        &mesh,
        massprops::Method::Volume,
        massprops::MassSpec::Density(1.0),
    )
    .expect("the cube");
    assert_eq!(a.volume, Some(1.0));
    assert_eq!(a.properties.center_of_mass, Point3::new(0.5, 0.5, 0.5));
    assert_eq!(a.diagnostics.inconsistent_edges, 4, "the file as it is");
    let w: Vec<_> = a.warnings.iter().map(|w| w.code()).collect();
    assert_eq!(w, ["inconsistent_winding"]);
    let w = &a.warnings[0];
    assert_eq!((w.count, w.faces.as_slice()), (1, [5].as_slice()));
    let effect = w.effect_on_mass.expect("known");
    assert!((effect + 1.0 / 3.0).abs() < 1e-15, "{effect}");
}

#[test]
fn approximations_of_a_sheet_need_only_its_mass() {
    // A 2 × 3 rectangle in z = 0 encloses no volume; its four corners and its flat bounding box
    // still have closed forms at a given mass m = 4.
    let corners = vec![
        Point3::new(-1.0, -1.5, 0.0),
        Point3::new(1.0, -1.5, 0.0),
        Point3::new(1.0, 1.5, 0.0),
        Point3::new(-1.0, 1.5, 0.0),
    ];
    let sheet = massprops::PolyMesh::new(corners, &[[0, 1, 2, 3]]).expect("valid");
    let m = 4.0;
    let points = analyze(&sheet, Method::Points, MassSpec::Mass(m)).expect("mass given");
    // Each corner m/4 at (±1, ±1.5): Ixx = m·1.5², Iyy = m·1², Izz = their sum, ∑xy = 0.
    let want = Matrix3::from_diagonal(&Vector3::new(m * 2.25, m, m * 3.25));
    assert_mat(&points.properties.inertia_com, &want, 1e-15, "corners");
    assert_eq!((points.volume, points.density), (None, None));
    // The numbers do not depend on the missing volume: no open-mesh warning.
    assert!(points.warnings.is_empty(), "{:?}", points.warnings);
    let bbox = analyze(&sheet, Method::BoundingBox, MassSpec::Mass(m)).expect("mass given");
    assert_mat(
        &bbox.properties.inertia_com,
        &box_tensor(m, 2.0, 3.0, 0.0),
        1e-15,
        "flat box",
    );
    // A density needs the volume to give a mass.
    let e = analyze(&sheet, Method::Points, MassSpec::Density(1.0)).expect_err("no volume");
    assert!(e.to_string().contains("zero volume"), "{e}");

    // A unit cube without its top encloses a volume that depends on the hole; at a given mass
    // its eight corners (m/8 at (±½, ±½, ±½): I = m/2 on each axis) do not, so no warning.
    let mut open = shapes::cube();
    open.faces.remove(0);
    let r = analyze(&open.build(), Method::Points, MassSpec::Mass(m)).expect("mass given");
    assert_mat(
        &r.properties.inertia_com,
        &(Matrix3::identity() * (m / 2.0)),
        1e-15,
        "open cube corners",
    );
    assert_eq!(r.density, None);
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);

    // Four copies of one point are no body, whatever the method.
    let point = massprops::PolyMesh::new(vec![Point3::new(1.0, 1.0, 1.0); 4], &[[0, 1, 2, 3]])
        .expect("valid indices");
    for method in [Method::Points, Method::BoundingBox] {
        let e = analyze(&point, method, MassSpec::Mass(m)).expect_err("a point");
        assert!(matches!(e, massprops::MeshError::ZeroArea), "{e:?}");
    }
}
