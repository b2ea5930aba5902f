//! README's claims about the results, held against closed forms: what
//! `MassProperties::compare_to` reports, the principal-axes convention on a body whose axes are
//! not the mesh axes, and boxes of every scale, shape and place.

use crate::common;

use std::f64::consts::PI;

use common::{assert_mat, assert_point, assert_rel, box_tensor, tetra_sum};
use massprops::integrals::IntegrationPath;
use massprops::principal::Degeneracy;
use massprops::shapes;
use massprops::solid::solid_properties;
use massprops::{MassProperties, PolyMesh, mass_properties};
use nalgebra::{Matrix3, Point3, Rotation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

/// A solid box of edges `sides` along x, y, z, centred on the origin, at density 1.
fn box_mesh(sides: Vector3<f64>) -> PolyMesh {
    shapes::cuboid(sides, Point3::origin()).build()
}

fn unit_density(mesh: &PolyMesh) -> MassProperties {
    mass_properties(mesh, 1.0).expect("a box encloses volume")
}

#[test]
fn compare_to_reports_moment_errors_axis_angles_and_centre_offset_of_a_moved_box() {
    // Exact: the 1 × 2 × 3 box at the origin, mass 6, moments m(b² + c²)/12 …: about z 2.5,
    // about y 5, about x 6.5, so axis 1 is z, axis 2 is y, axis 3 is x.
    let exact = unit_density(&box_mesh(Vector3::new(1.0, 2.0, 3.0)));
    // Approximation: a 1 × 2 × 3.5 box (mass 7), turned by θ about z and moved by (3, 4, 12),
    // 13 away. Its moments: about z 7·5/12, about y 7·13.25/12, about x 7·16.25/12.
    let want_errors = Vector3::new(
        (35.0 / 12.0 - 2.5) / 2.5,        // 1/6
        (7.0 * 13.25 / 12.0 - 5.0) / 5.0, // 32.75/60
        (7.0 * 16.25 / 12.0 - 6.5) / 6.5, // 35.75/78
    );
    for (theta, folded) in [(0.3, 0.3), (2.0, PI - 2.0), (-1.0, 1.0)] {
        let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), theta);
        let offset = Vector3::new(3.0, 4.0, 12.0);
        let moved = box_mesh(Vector3::new(1.0, 2.0, 3.5))
            .map_positions(|p| turn * p + offset)
            .expect("finite");
        let c = unit_density(&moved).compare_to(&exact);
        for i in 0..3 {
            assert!(
                (c.moment_error[i] - want_errors[i]).abs() < 1e-14,
                "θ {theta}: moment {i}: {} vs {}",
                c.moment_error[i],
                want_errors[i]
            );
        }
        // Axis 1 (z) is the turning axis; axes 2 and 3 turn by θ, folded into [0, π/2] as an
        // axis has no sign.
        let angles = c
            .axis_angle
            .map(|a| a.expect("distinct moments: unique axes"));
        assert!(angles[0].abs() < 1e-14, "θ {theta}: {angles:?}");
        assert!((angles[1] - folded).abs() < 1e-13, "θ {theta}: {angles:?}");
        assert!((angles[2] - folded).abs() < 1e-13, "θ {theta}: {angles:?}");
        assert!((c.com_offset - 13.0).abs() < 1e-13, "{}", c.com_offset);
    }

    // A 1 × 1 × 3 box has I₂ = I₃ (about x and y, 10/12 m each): only its axis 1 is unique, so
    // only that angle is reported; here it is the long edge turned 0.25 rad about x.
    let turn = Rotation3::from_axis_angle(&Vector3::x_axis(), 0.25);
    let top = unit_density(
        &box_mesh(Vector3::new(1.0, 1.0, 3.0))
            .map_positions(|p| turn * p)
            .expect("finite"),
    );
    assert_eq!(top.principal.degeneracy, Degeneracy::Moments23);
    let c = top.compare_to(&exact);
    assert!(c.axis_angle[1].is_none() && c.axis_angle[2].is_none());
    let angle = c.axis_angle[0].expect("axis 1 unique in both");
    assert!((angle - 0.25).abs() < 1e-13, "{angle}");
    // Mass 3, moments 3·2/12 = 0.5 and 3·10/12 = 2.5 twice, against 2.5, 5, 6.5.
    let want = Vector3::new(-0.8, -0.5, 2.5 / 6.5 - 1.0);
    assert!((c.moment_error - want).amax() < 1e-14, "{}", c.moment_error);
    assert!(c.com_offset < 1e-15);
}

/// The unit axis of each principal moment, ascending, of a box with edges `sides` (distinct)
/// turned by `r`: the smallest moment is about the longest edge.
fn box_axes(sides: Vector3<f64>, r: &Rotation3<f64>) -> [Vector3<f64>; 3] {
    let moments = Vector3::new(
        sides.y.powi(2) + sides.z.powi(2),
        sides.x.powi(2) + sides.z.powi(2),
        sides.x.powi(2) + sides.y.powi(2),
    );
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| moments[i].total_cmp(&moments[j]));
    order.map(|k| r * Vector3::ith(k, 1.0))
}

#[test]
fn principal_axes_of_a_turned_box_are_the_columns_of_a_proper_rotation() {
    // README, Conventions: moments ascending; axis i (row i of JSON's `principal_axes`, which is
    // column i of `PrincipalInertia::rotation`, the principal → mesh rotation) is the unit axis
    // of moment i; the three are right-handed. A turn with no symmetry, so rows and columns of
    // the rotation differ and a mix-up fails.
    let r = Rotation3::from_euler_angles(0.4, -0.7, 1.1);
    let sides = Vector3::new(2.0, 3.0, 1.0);
    let mesh = box_mesh(sides)
        .map_positions(|p| r * p + Vector3::new(0.5, -2.0, 7.0))
        .expect("finite");
    let p = unit_density(&mesh);
    let m = 6.0;
    // About x: m(9 + 1)/12 = 5, about y: m(4 + 1)/12 = 2.5, about z: m(4 + 9)/12 = 6.5.
    let want = Vector3::new(2.5, 5.0, 6.5);
    assert!(
        (p.principal.moments - want).amax() < 1e-13 * m,
        "{}",
        p.principal.moments
    );
    assert_eq!(p.principal.degeneracy, Degeneracy::Distinct);
    let axes = box_axes(sides, &r);
    let rot = p.principal.rotation.matrix();
    for (i, axis) in axes.iter().enumerate() {
        let column = rot.column(i).into_owned();
        assert!(
            column.dot(axis).abs() > 1.0 - 1e-13,
            "column {i} = {column} is not ±{axis}"
        );
        // The same axis read as a row of the principal → mesh rotation would be wrong here.
        let row = rot.row(i).transpose();
        assert!(
            row.dot(axis).abs() < 0.99,
            "row {i} = {row} is also ±{axis}"
        );
        // Rotating the principal frame's i-th unit vector gives axis i.
        let image = p.principal.rotation * Vector3::ith(i, 1.0);
        assert!((image - column).amax() < 1e-15);
    }
    // Right-handed orthonormal: a proper rotation, axis 3 = axis 1 × axis 2.
    assert!((rot.transpose() * rot - Matrix3::identity()).amax() < 1e-14);
    assert!((rot.determinant() - 1.0).abs() < 1e-14);
    let cross = rot.column(0).cross(&rot.column(1));
    assert!((cross - rot.column(2)).amax() < 1e-14, "{cross}");
    // And the frame diagonalises the tensor: Rᵀ I R = diag(I₁, I₂, I₃).
    let diagonal = rot.transpose() * p.inertia_com * rot;
    assert_mat(&diagonal, &Matrix3::from_diagonal(&want), 1e-14, "Rᵀ I R");
}

/// 10^u for u uniform in [lo, hi]: a log-uniform scale.
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..=hi).prop_map(|u| 10f64.powf(u))
}

/// Edge ratios of a box: general, symmetric tops (prolate and oblate), a needle, thin plates
/// and a cube.
fn shape() -> impl Strategy<Value = Vector3<f64>> {
    prop_oneof![
        (0.3..3.0f64, 0.3..3.0f64, 0.3..3.0f64).prop_map(|(a, b, c)| Vector3::new(a, b, c)),
        (0.3..3.0f64, 0.3..3.0f64).prop_map(|(r, h)| Vector3::new(r, r, h)),
        log_uniform(2.0, 4.0).prop_map(|l| Vector3::new(1.0, 1.0, l)),
        log_uniform(-4.0, -2.0).prop_map(|t| Vector3::new(1.0, 1.7, t)),
        log_uniform(-4.0, -2.0).prop_map(|t| Vector3::new(t, 1.0, 1.0)),
        Just(Vector3::repeat(1.0)),
    ]
}

/// A translation of each coordinate up to 10⁶ in magnitude, signs mixed, log-uniform.
fn translation() -> impl Strategy<Value = Vector3<f64>> {
    fn coordinate() -> impl Strategy<Value = f64> {
        (log_uniform(-3.0, 6.0), any::<bool>()).prop_map(|(v, neg)| if neg { -v } else { v })
    }
    (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| Vector3::new(x, y, z))
}

/// `t` shortened, where needed, to 10⁶ times the box's smallest edge: farther, rounding the
/// corners to f64 would change a thin body's thickness by more than 1e-10 of itself (or erase
/// it), and no mass property of that body is defined to 12 digits.
fn within_reach(t: Vector3<f64>, sides: &Vector3<f64>) -> Vector3<f64> {
    t * (1e6 * sides.amin() / t.amax()).min(1.0)
}

fn rotation() -> impl Strategy<Value = UnitQuaternion<f64>> {
    (-3.2..3.2f64, -1.6..1.6f64, -3.2..3.2f64)
        .prop_map(|(r, p, y)| UnitQuaternion::from_euler_angles(r, p, y))
}

/// Closed-form moments (ascending) of a box of `mass` and edges `e`.
fn box_moments(mass: f64, e: &Vector3<f64>) -> Vector3<f64> {
    let mut m: Vec<f64> = box_tensor(mass, e.x, e.y, e.z)
        .diagonal()
        .iter()
        .copied()
        .collect();
    m.sort_by(f64::total_cmp);
    Vector3::new(m[0], m[1], m[2])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Axis-aligned boxes from 1e-6 to 1e6 (times their shape), up to 10⁶ from the origin, on
    /// both paths. Expected values come from the corners as f64 holds them (a moved box is still
    /// a box, with edges hi − lo), so the numerics of the crate are held to 1e-12 however far
    /// the body is; the degeneracy is checked where the closed form is unambiguous.
    #[test]
    fn boxes_of_every_scale_shape_and_place_match_the_closed_form(
        s in log_uniform(-6.0, 6.0), ratios in shape(), t in translation(), rho in log_uniform(-2.0, 4.0),
        triangulated in any::<bool>(),
    ) {
        let sides = ratios * s;
        let t = within_reach(t, &sides);
        let centre = Point3::from(t);
        let mut b = shapes::cuboid(sides, centre);
        if triangulated {
            b = b.triangulated();
        }
        let mesh = b.build();
        let (lo, hi) = mesh.bounding_box();
        let edges = hi - lo;
        let mass = rho * edges.x * edges.y * edges.z;
        let com = Point3::from((lo.coords + hi.coords) / 2.0);
        let want = box_tensor(mass, edges.x, edges.y, edges.z);
        for path in [IntegrationPath::Polygon, IntegrationPath::Auto] {
            let p = solid_properties(&mesh, path)
                .and_then(|solid| solid.with_density(rho))
                .expect("a box encloses volume");
            assert_rel(p.mass, mass, 1e-13, "mass");
            assert_point(&p.center_of_mass, &com, edges.amax() + t.amax(), 1e-15, "COM");
            assert_mat(&p.inertia_com, &want, 1e-12, "central tensor");
            let moments = box_moments(mass, &edges);
            prop_assert!((p.principal.moments - moments).amax() <= 1e-12 * moments[2]);
            // Where the closed form has equal moments exactly, or clearly distinct ones.
            let gap = |i: usize| (moments[i + 1] - moments[i]) / moments[2];
            let equal = |i: usize| {
                let g = gap(i);
                if g == 0.0 {
                    Some(true)
                } else if g > 1e-8 {
                    Some(false)
                } else {
                    None
                }
            };
            let expected = match (equal(0), equal(1)) {
                (Some(true), Some(true)) => Some(Degeneracy::Spherical),
                (Some(true), Some(false)) => Some(Degeneracy::Moments12),
                (Some(false), Some(true)) => Some(Degeneracy::Moments23),
                (Some(false), Some(false)) => Some(Degeneracy::Distinct),
                _ => None,
            };
            if let Some(d) = expected {
                prop_assert_eq!(p.principal.degeneracy, d, "moments {}", moments);
            }
        }
    }

    /// Turned boxes of every scale and shape up to 10⁶ from the origin: against an independent
    /// signed-tetrahedron sum on the very same (rounded) vertices to 1e-13 (more for long or thin
    /// boxes, whose tetrahedra cancel), and against the
    /// exact box to within what rounding the corners costs (ε·|t|/s); unique principal axes are
    /// the box's edges.
    #[test]
    fn turned_boxes_of_every_scale_match_the_closed_form_and_an_independent_sum(
        s in log_uniform(-6.0, 6.0), ratios in shape(), t in translation(), q in rotation(),
    ) {
        let sides = ratios * s;
        let t = within_reach(t, &sides);
        let mesh = shapes::cuboid(sides, Point3::origin())
            .triangulated()
            .build()
            .map_positions(|p| q * p + t)
            .expect("finite");
        let p = unit_density(&mesh);
        // A long or thin box's tetrahedra cancel: each determinant loses about ε × (longest /
        // shortest edge) of itself, in either sum.
        let aspect = sides.amax() / sides.amin();
        let cancellation = 1e-13 + 256.0 * f64::EPSILON * aspect;
        let (volume, com, central) = tetra_sum(&mesh);
        assert_rel(p.mass, volume, cancellation, "mass vs tetrahedra");
        assert_point(&p.center_of_mass, &com, sides.amax() + t.amax(), cancellation, "COM vs tetrahedra");
        assert_mat(&p.inertia_com, &central, cancellation, "tensor vs tetrahedra");

        // Moving the corners rounds each by up to ½ulp of its coordinates (|t| + the longest
        // edge), a relative change of the body of that over the smallest edge; mass and moments
        // move by a few times that.
        let rounding =
            cancellation + 16.0 * f64::EPSILON * (t.amax() + sides.amax()) / sides.amin();
        let mass = sides.x * sides.y * sides.z;
        assert_rel(p.mass, mass, rounding, "mass vs closed form");
        let r = *q.to_rotation_matrix().matrix();
        let want = r * box_tensor(mass, sides.x, sides.y, sides.z) * r.transpose();
        assert_mat(&p.inertia_com, &want, rounding, "tensor vs closed form");
        assert_point(&p.center_of_mass, &Point3::from(t), sides.amax(), rounding, "COM");
        if rounding < 1e-9 {
            // Each unique axis is ± the turned edge of its moment (closest by the closed form).
            let moments = box_tensor(1.0, sides.x, sides.y, sides.z).diagonal();
            let mut order = [0usize, 1, 2];
            order.sort_by(|&i, &j| moments[i].total_cmp(&moments[j]));
            let sorted = order.map(|k| moments[k]);
            let rot = p.principal.rotation.matrix();
            for i in 0..3 {
                let separated = |j: usize| (sorted[i] - sorted[j]).abs() > 1e-2 * sorted[2];
                if (0..3).filter(|&j| j != i).all(separated) {
                    let axis = r * Vector3::ith(order[i], 1.0);
                    let dot = rot.column(i).dot(&axis).abs();
                    prop_assert!(dot > 1.0 - 1e-9, "axis {}: |cos| = {}", i, dot);
                }
            }
        }
    }
}
