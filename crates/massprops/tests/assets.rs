//! The sample files in `assets/` are the generator's shapes, and their mass properties are
//! pinned by closed forms computed here (parallel axis over parts, polygon moments, and an exact
//! formula for the polygonal torus).

use crate::common;

use std::f64::consts::{FRAC_PI_2, TAU};
use std::path::Path;

use common::{
    assert_mat, assert_point, assert_rel, box_tensor, polygon_moments, prism_closed_form, steiner,
};
use massprops::diagnostics::diagnose;
use massprops::{MassProperties, load_mesh, mass_properties, shapes};
use nalgebra::{Matrix3, Point2, Point3, Rotation3, Vector3};

fn asset(name: &str) -> MassProperties {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../assets")
        .join(format!("{name}.obj"));
    let mesh = load_mesh(&path)
        .unwrap_or_else(|e| panic!("{name}: {e}"))
        .mesh;
    let d = diagnose(&mesh);
    assert!(
        d.is_closed() && d.is_consistently_oriented(),
        "{name}: {d:?}"
    );
    assert_eq!(d.degenerate_faces + d.nonplanar_faces, 0, "{name}");
    mass_properties(&mesh, 1.0).expect("closed")
}

/// (mass, centre, central tensor) at unit density, by parts: each part's tensor about the
/// origin summed, then moved to the common centre.
fn combine(parts: &[(f64, Point3<f64>, Matrix3<f64>)]) -> (f64, Point3<f64>, Matrix3<f64>) {
    let m: f64 = parts.iter().map(|p| p.0).sum();
    let c = parts.iter().map(|p| p.1.coords * p.0).sum::<Vector3<f64>>() / m;
    let about_origin: Matrix3<f64> = parts.iter().map(|p| p.2).sum();
    (m, Point3::from(c), about_origin - steiner(m, &c))
}

fn cuboid_part(size: Vector3<f64>, centre: Point3<f64>) -> (f64, Point3<f64>, Matrix3<f64>) {
    let m = size.x * size.y * size.z;
    (
        m,
        centre,
        box_tensor(m, size.x, size.y, size.z) + steiner(m, &centre.coords),
    )
}

fn prism_part(outline: &[Point2<f64>], z0: f64, z1: f64) -> (f64, Point3<f64>, Matrix3<f64>) {
    prism_closed_form(outline, z0, z1)
}

fn ellipse(a: f64, b: f64, n: usize) -> Vec<Point2<f64>> {
    (0..n)
        .map(|i| TAU * i as f64 / n as f64)
        .map(|t| Point2::new(a * t.cos(), b * t.sin()))
        .collect()
}

#[track_caller]
fn check(name: &str, got: &MassProperties, want: (f64, Point3<f64>, Matrix3<f64>), size: f64) {
    assert_rel(got.mass, want.0, 1e-12, name);
    assert_point(&got.center_of_mass, &want.1, size, 1e-13, name);
    assert_mat(&got.inertia_com, &want.2, 1e-12, name);
}

#[test]
fn asset_files_are_the_generated_shapes() {
    for (name, _, builder) in shapes::samples() {
        let from_file = asset(name);
        let generated = mass_properties(&builder.build(), 1.0).expect("closed");
        // Coordinates are written as shortest round-trip decimals, so they read back exactly.
        assert_eq!(from_file.mass, generated.mass, "{name}");
        assert_mat(&from_file.inertia_com, &generated.inertia_com, 1e-15, name);
    }
}

#[test]
fn t_handle_book_cube_and_l_bracket_files() {
    let t = combine(&[
        cuboid_part(
            Vector3::new(0.08, 0.012, 0.012),
            Point3::new(0.0, 0.006, 0.0),
        ),
        cuboid_part(
            Vector3::new(0.012, 0.05, 0.012),
            Point3::new(0.0, -0.025, 0.0),
        ),
    ]);
    check("t_handle", &asset("t_handle"), t, 0.08);
    check(
        "book",
        &asset("book"),
        cuboid_part(Vector3::new(1.0, 4.0, 7.0), Point3::origin()),
        7.0,
    );
    check(
        "cube",
        &asset("cube"),
        cuboid_part(Vector3::repeat(1.0), Point3::origin()),
        1.0,
    );
    let l = [
        (0.0, 0.0),
        (0.1, 0.0),
        (0.1, 0.01),
        (0.01, 0.01),
        (0.01, 0.06),
        (0.0, 0.06),
    ]
    .map(|(x, y)| Point2::new(x, y));
    let (v, c, i) = prism_part(&l, 0.0, 0.03);
    check(
        "l_bracket",
        &asset("l_bracket"),
        (v, c, i - steiner(v, &c.coords)),
        0.1,
    );
}

#[test]
fn hammer_file_by_parts() {
    // Handle: a 24-gon prism along z, r = 15 mm, 0..300 mm, turned z → y by −90° about x.
    let (v, c, i) = prism_part(&ellipse(0.015, 0.015, 24), 0.0, 0.3);
    let r = Rotation3::from_axis_angle(&Vector3::x_axis(), -FRAC_PI_2);
    let handle = (v, r * c, r.matrix() * i * r.matrix().transpose());
    let head = cuboid_part(
        Vector3::new(0.12, 0.03, 0.03),
        Point3::new(0.02, 0.315, 0.0),
    );
    check("hammer", &asset("hammer"), combine(&[handle, head]), 0.33);
}

#[test]
fn tennis_racket_file_by_parts() {
    let (a, b, w, n) = (0.135, 0.165, 0.012, 64);
    // Frame = outer elliptic prism minus the inner one (integrals subtract).
    let outer = prism_part(&ellipse(a, b, n), -0.01, 0.01);
    let inner = prism_part(&ellipse(a - w, b - w, n), -0.01, 0.01);
    let frame = (
        outer.0 - inner.0,
        Point3::from((outer.1.coords * outer.0 - inner.1.coords * inner.0) / (outer.0 - inner.0)),
        outer.2 - inner.2,
    );
    let strings = prism_part(&ellipse(a - w, b - w, n), -0.001, 0.001);
    let handle = cuboid_part(
        Vector3::new(0.03, 0.27, 0.025),
        Point3::new(0.0, -b - 0.135, 0.0),
    );
    check(
        "tennis_racket",
        &asset("tennis_racket"),
        combine(&[frame, strings, handle]),
        0.6,
    );
}

#[test]
fn torus_file_by_an_exact_formula_for_the_polygonal_torus() {
    // The mesh sweeps the tube's 48-gon P (in the (ρ, z) half-plane, centred at ρ = R) linearly
    // between consecutive meridian planes Δ = 2π/96 apart. The map (ρ, z, t) ↦ (ρ((1−t)eᵢ +
    // t eᵢ₊₁), z) has Jacobian ρ sin Δ, and |(1−t)eᵢ + t eᵢ₊₁|² integrates over t to (2 + cos Δ)/3:
    // V = N sin Δ ∫_P ρ dA, ∫(x² + y²) = N sin Δ (2 + cos Δ)/3 ∫_P ρ³ dA, ∫z² = N sin Δ ∫_P ρ z² dA.
    // With ρ = R + u and P symmetric in u and z: ∫ρ = R·A, ∫ρ³ = R³A + 3R∫u², ∫ρz² = R∫z².
    let (big_r, small_r, around, tube) = (1.0, 0.3, 96usize, 48usize);
    let p = polygon_moments(&ellipse(small_r, small_r, tube));
    let delta = TAU / around as f64;
    let k = around as f64 * delta.sin();
    let volume = k * big_r * p.area;
    let radial = k * (2.0 + delta.cos()) / 3.0 * (big_r.powi(3) * p.area + 3.0 * big_r * p.xx);
    let zz = k * big_r * p.yy;
    let want = Matrix3::from_diagonal(&Vector3::new(radial / 2.0 + zz, radial / 2.0 + zz, radial));
    check(
        "torus",
        &asset("torus"),
        (volume, Point3::origin(), want),
        2.6,
    );
    // Against the smooth torus, 2π²Rr²: the 96 × 48 mesh is 0.36% smaller.
    let smooth = TAU * std::f64::consts::PI * big_r * small_r * small_r;
    assert!(volume < smooth && volume > 0.995 * smooth);
}
