//! Closed forms: boxes at any size, offset and rotation; tetrahedra by Tonon's formulas; prisms
//! with non-convex caps by the polygon's own moments; the T-handle by the parallel-axis theorem.

use crate::common;

use common::{
    assert_mat, assert_point, assert_rel, box_tensor, comb, prism_closed_form, star, steiner,
    tetrahedron,
};
use massprops::integrals::IntegrationPath;
use massprops::principal::Degeneracy;
use massprops::solid::solid_properties;
use massprops::{PolyMesh, mass_properties, shapes};
use nalgebra::{Isometry3, Matrix3, Point2, Point3, Translation3, UnitQuaternion, Vector3};

/// Every path a closed mesh can be integrated by: Mirtich on the polygons, and Mirtich and the
/// triangle paths on its fan triangulation.
fn all_paths(b: &shapes::MeshBuilder) -> Vec<(&'static str, PolyMesh, IntegrationPath)> {
    let tri = b.clone().triangulated().build();
    vec![
        ("polygon", b.build(), IntegrationPath::Polygon),
        (
            "polygon on triangles",
            tri.clone(),
            IntegrationPath::Polygon,
        ),
        ("triangle", tri.clone(), IntegrationPath::Triangle),
        ("triangle parallel", tri, IntegrationPath::TriangleParallel),
    ]
}

#[test]
fn boxes_of_any_size_offset_and_rotation() {
    let cases = [
        (
            Vector3::new(1.0, 1.0, 1.0),
            Vector3::zeros(),
            Vector3::zeros(),
            1.0,
        ),
        (
            Vector3::new(1.0, 4.0, 7.0),
            Vector3::new(3.0, -2.0, 5.0),
            Vector3::zeros(),
            2.5,
        ),
        (
            Vector3::new(0.3, 0.02, 5.0),
            Vector3::new(-7.0, 0.5, 11.0),
            Vector3::new(0.4, 1.2, -0.3),
            7850.0,
        ),
        (
            Vector3::new(2e-3, 1e-3, 3e-3),
            Vector3::new(0.1, 0.2, -0.05),
            Vector3::new(-1.0, 0.2, 2.0),
            2700.0,
        ),
        (
            Vector3::new(300.0, 40.0, 90.0),
            Vector3::new(1e3, -5e2, 2e3),
            Vector3::new(2.0, -0.7, 0.1),
            0.5,
        ),
    ];
    for (size, offset, euler, rho) in cases {
        let rot = UnitQuaternion::from_euler_angles(euler.x, euler.y, euler.z);
        let motion = Isometry3::from_parts(Translation3::from(offset), rot);
        let r = *rot.to_rotation_matrix().matrix();
        let builder = shapes::cuboid(size, Point3::origin()).transformed(&motion);
        let m = rho * size.x * size.y * size.z;
        let central = r * box_tensor(m, size.x, size.y, size.z) * r.transpose();
        let about_origin = central + steiner(m, &offset);
        for (name, mesh, path) in all_paths(&builder) {
            let what = format!("box {size:?} at {offset:?}, {name}");
            let s = solid_properties(&mesh, path).expect("a box encloses volume");
            assert!(!s.flipped, "{what}");
            let p = s.with_density(rho).expect("positive density");
            assert_rel(p.mass, m, 1e-13, &what);
            assert_point(
                &p.center_of_mass,
                &Point3::from(offset),
                size.amax() + offset.amax(),
                1e-14,
                &what,
            );
            assert_mat(&p.inertia_com, &central, 1e-13, &what);
            assert_mat(&p.inertia_origin(), &about_origin, 1e-13, &what);
            // Principal moments are the box's, ascending.
            let mut want = box_tensor(m, size.x, size.y, size.z).diagonal();
            want.as_mut_slice().sort_by(f64::total_cmp);
            assert!(
                (p.principal.moments - want).amax() <= 1e-13 * want.amax(),
                "{what}"
            );
        }
    }
}

#[test]
fn rotated_box_product_of_inertia_has_the_tensor_sign() {
    // A box a × b × c (a > b) turned by θ about z: x = u cosθ − v sinθ, y = u sinθ + v cosθ, so
    // ∫xy = cosθ sinθ (∫u² − ∫v²) = cosθ sinθ m (a² − b²)/12 > 0 and Ixy = −∫xy < 0.
    let (a, b, c, theta) = (4.0, 1.0, 2.0, 0.5_f64);
    let motion = Isometry3::rotation(Vector3::z() * theta);
    let mesh = shapes::cuboid(Vector3::new(a, b, c), Point3::origin())
        .transformed(&motion)
        .build();
    let p = mass_properties(&mesh, 1.0).expect("closed box");
    let m = a * b * c;
    let ixy = -theta.cos() * theta.sin() * m * (a * a - b * b) / 12.0;
    assert!(ixy < 0.0);
    assert_rel(p.inertia_com[(0, 1)], ixy, 1e-13, "Ixy");
    assert_rel(p.inertia_com[(1, 0)], ixy, 1e-13, "Iyx");
    assert!(p.inertia_com[(0, 2)].abs() < 1e-14 * m && p.inertia_com[(1, 2)].abs() < 1e-14 * m);
    // Ixx = cos²θ·Iuu + sin²θ·Ivv.
    let (iu, iv) = (m * (b * b + c * c) / 12.0, m * (a * a + c * c) / 12.0);
    let ixx = theta.cos().powi(2) * iu + theta.sin().powi(2) * iv;
    assert_rel(p.inertia_com[(0, 0)], ixx, 1e-13, "Ixx");
    // The smallest moment's axis is the long edge, u = (cosθ, sinθ, 0), up to sign.
    let axis = p.principal.rotation.matrix().column(0).into_owned();
    assert!(
        axis.dot(&Vector3::new(theta.cos(), theta.sin(), 0.0)).abs() > 1.0 - 1e-14,
        "{axis}"
    );
}

/// Tonon (2004), "Explicit exact formulas for the 3-D tetrahedron inertia tensor in terms of its
/// vertex coordinates", with coordinates relative to the centroid and |J| = 6V:
/// a = μ|J|/60·Σᵢ≤ⱼ(yᵢyⱼ + zᵢzⱼ), b likewise in x, z, c in x, y;
/// a′ = μ|J|/120·(2Σᵢ yᵢzᵢ + Σᵢ≠ⱼ yᵢzⱼ), b′ likewise in x, z, c′ in x, y;
/// a′ pairs y with z, b′ x with z, c′ x with y, so in the tensor convention
/// I = [[a, −c′, −b′], [−c′, b, −a′], [−b′, −a′, c]] (the paper's printed example, checked below,
/// confirms which product goes where).
fn tonon(p: &[Point3<f64>; 4], mu: f64) -> (f64, Point3<f64>, Matrix3<f64>) {
    let centroid = Point3::from((p[0].coords + p[1].coords + p[2].coords + p[3].coords) / 4.0);
    let q: Vec<Vector3<f64>> = p.iter().map(|v| v - centroid).collect();
    let j = (q[1] - q[0])
        .cross(&(q[2] - q[0]))
        .dot(&(q[3] - q[0]))
        .abs();
    let square_sum = |k: usize| {
        let mut s = 0.0;
        for i in 0..4 {
            for l in i..4 {
                s += q[i][k] * q[l][k];
            }
        }
        s
    };
    let product_sum = |k: usize, l: usize| {
        let mut s = 0.0;
        for i in 0..4 {
            for m in 0..4 {
                s += if i == m { 2.0 } else { 1.0 } * q[i][k] * q[m][l];
            }
        }
        s
    };
    let (sx, sy, sz) = (square_sum(0), square_sum(1), square_sum(2));
    let a = mu * j * (sy + sz) / 60.0;
    let b = mu * j * (sx + sz) / 60.0;
    let c = mu * j * (sx + sy) / 60.0;
    let a_ = mu * j * product_sum(1, 2) / 120.0;
    let b_ = mu * j * product_sum(0, 2) / 120.0;
    let c_ = mu * j * product_sum(0, 1) / 120.0;
    let tensor = Matrix3::new(a, -c_, -b_, -c_, b, -a_, -b_, -a_, c);
    (mu * j / 6.0, centroid, tensor)
}

#[test]
fn tetrahedra_by_tonon() {
    let tets = [
        // The worked example of Tonon's paper.
        [
            Point3::new(8.33220, -11.86875, 0.93355),
            Point3::new(0.75523, 5.00000, 16.37072),
            Point3::new(52.61236, 5.00000, -5.38580),
            Point3::new(2.00000, 5.00000, 3.00000),
        ],
        [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.0, 0.0, 1.0),
        ],
        [
            Point3::new(-3.1, 2.2, 0.7),
            Point3::new(4.0, -1.5, 2.9),
            Point3::new(0.3, 5.5, -2.2),
            Point3::new(1.7, 0.4, 6.1),
        ],
        // Long and thin, far from the origin.
        [
            Point3::new(100.0, 200.0, 300.0),
            Point3::new(110.0, 200.5, 300.1),
            Point3::new(100.2, 201.0, 299.8),
            Point3::new(100.1, 200.3, 300.9),
        ],
    ];
    for (k, p) in tets.iter().enumerate() {
        let (v, c, tensor) = tonon(p, 1.0);
        for flip in [false, true] {
            let mesh = if flip {
                tetrahedron(*p).flipped()
            } else {
                tetrahedron(*p)
            };
            for path in [IntegrationPath::Polygon, IntegrationPath::Triangle] {
                let what = format!("tetrahedron {k}, {path:?}, flipped {flip}");
                let s = solid_properties(&mesh, path).expect("a tetrahedron has volume");
                assert_eq!(s.flipped, flip, "{what}");
                assert_rel(s.volume, v, 1e-13, &what);
                let scale = (p[1] - p[0]).norm();
                assert_point(&s.unit_density.center_of_mass, &c, scale, 1e-13, &what);
                assert_mat(&s.unit_density.inertia_com, &tensor, 1e-12, &what);
            }
        }
    }
    // The paper's results for its example (μ = 1). They agree with the formulas above to ~1e-8
    // relative (not to every printed decimal): enough to pin which product of inertia is which.
    let (_, c, t) = tonon(&tets[0], 1.0);
    assert_point(
        &c,
        &Point3::new(15.92492, 0.78281, 3.72962),
        1.0,
        1e-4,
        "Tonon's centroid",
    );
    let printed = [
        (t[(0, 0)], 43520.33257),
        (t[(1, 1)], 194711.28938),
        (t[(2, 2)], 191168.76173),
        (-t[(1, 2)], 4417.66150),
        (-t[(0, 2)], -46343.16662),
        (-t[(0, 1)], 11996.20119),
    ];
    for (got, want) in printed {
        assert_rel(got, want, 1e-7, "Tonon's example");
    }
}

#[test]
fn prisms_with_non_convex_caps() {
    let l = vec![
        Point2::new(0.0, 0.0),
        Point2::new(5.0, 0.0),
        Point2::new(5.0, 1.0),
        Point2::new(1.0, 1.0),
        Point2::new(1.0, 3.0),
        Point2::new(0.0, 3.0),
    ];
    let t = vec![
        Point2::new(-0.5, -4.0),
        Point2::new(0.5, -4.0),
        Point2::new(0.5, 0.0),
        Point2::new(3.0, 0.0),
        Point2::new(3.0, 1.0),
        Point2::new(-3.0, 1.0),
        Point2::new(-3.0, 0.0),
        Point2::new(-0.5, 0.0),
    ];
    let star = star(Point2::new(2.0, -1.0), 3.0, 1.1, 5);
    let comb = comb(5, 0.4, 0.7, 0.5, 2.5);
    let shapes_ = [
        ("L", l, 0.0, 2.0),
        ("T", t, -0.5, 0.5),
        ("star", star, 1.0, 1.25),
        ("comb", comb, -3.0, 4.0),
    ];
    for (name, outline, z0, z1) in shapes_ {
        let rho = 3.0;
        let (v, com, about_origin) = prism_closed_form(&outline, z0, z1);
        let (m, about_origin) = (rho * v, about_origin * rho);
        let central = about_origin - steiner(m, &com.coords);
        let builder = shapes::prism(&outline, z0, z1);
        for (path_name, mesh, path) in all_paths(&builder) {
            let what = format!("{name} prism, {path_name}");
            let p = solid_properties(&mesh, path)
                .and_then(|s| s.with_density(rho))
                .expect("a prism has volume");
            assert_rel(p.mass, m, 1e-13, &what);
            assert_point(&p.center_of_mass, &com, 10.0, 1e-14, &what);
            assert_mat(&p.inertia_origin(), &about_origin, 1e-13, &what);
            assert_mat(&p.inertia_com, &central, 1e-13, &what);
        }
    }
}

#[test]
fn t_handle_by_the_parallel_axis_theorem_over_its_two_boxes() {
    // Crossbar 80 × 12 × 12 mm centred (0, 6 mm, 0); stem 12 × 50 × 12 mm centred (0, −25 mm, 0).
    let rho = 7850.0;
    let bar = (
        Vector3::new(0.08, 0.012, 0.012),
        Vector3::new(0.0, 0.006, 0.0),
    );
    let stem = (
        Vector3::new(0.012, 0.05, 0.012),
        Vector3::new(0.0, -0.025, 0.0),
    );
    let parts: Vec<(f64, Vector3<f64>, Matrix3<f64>)> = [bar, stem]
        .iter()
        .map(|(s, c)| {
            let m = rho * s.x * s.y * s.z;
            (m, *c, box_tensor(m, s.x, s.y, s.z))
        })
        .collect();
    let mass: f64 = parts.iter().map(|p| p.0).sum();
    let com = parts.iter().map(|p| p.1 * p.0).sum::<Vector3<f64>>() / mass;
    let central: Matrix3<f64> = parts
        .iter()
        .map(|(m, c, i)| i + steiner(*m, &(c - com)))
        .sum();

    let p = mass_properties(&shapes::t_handle().build(), rho).expect("closed");
    assert_rel(p.mass, mass, 1e-13, "T-handle mass");
    assert_rel(mass, rho * 1.872e-5, 1e-12, "T-handle volume 18.72 cm³");
    assert_point(
        &p.center_of_mass,
        &Point3::from(com),
        0.08,
        1e-13,
        "T-handle COM",
    );
    assert_mat(&p.inertia_com, &central, 1e-13, "T-handle tensor");
    // A symmetric body: no products of inertia; three distinct moments, axes the mesh axes.
    assert_eq!(p.principal.degeneracy, Degeneracy::Distinct);
    let mut want = central.diagonal();
    want.as_mut_slice().sort_by(f64::total_cmp);
    assert!((p.principal.moments - want).amax() < 1e-13 * want.amax());
    let r = p.principal.rotation.matrix();
    for i in 0..3 {
        assert!(
            r.column(i).amax() > 1.0 - 1e-14,
            "axis {i} is a mesh axis: {r}"
        );
    }
    // Axis i is the mesh axis whose closed-form moment is the i-th smallest.
    for i in 0..3 {
        let k = (0..3)
            .find(|&k| (central[(k, k)] - want[i]).abs() < 1e-12 * want.amax())
            .expect("each moment is a diagonal entry");
        assert!(
            r[(k, i)].abs() > 1.0 - 1e-14,
            "axis {i} should be mesh axis {k}: {r}"
        );
    }
}

#[test]
fn book_and_cube_samples() {
    let p = mass_properties(&shapes::book().build(), 2.0).expect("closed");
    assert_rel(p.mass, 56.0, 1e-15, "book mass");
    assert_mat(
        &p.inertia_com,
        &box_tensor(56.0, 1.0, 4.0, 7.0),
        1e-14,
        "book tensor",
    );
    let c = mass_properties(&shapes::cube().build(), 1.0).expect("closed");
    assert_mat(
        &c.inertia_com,
        &(Matrix3::identity() / 6.0),
        1e-14,
        "cube tensor",
    );
    assert_eq!(c.principal.degeneracy, Degeneracy::Spherical);
}
