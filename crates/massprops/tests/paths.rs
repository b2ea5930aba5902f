//! Mirtich's polygon path, the triangle path, the parallel triangle path and an independent
//! signed-tetrahedron sum (written here) agree on every sample shape and on irregular meshes;
//! polygons agree with their triangulation.

use crate::common;

use common::{assert_mat, assert_point, assert_rel, tetra_sum};
use massprops::PolyMesh;
use massprops::integrals::IntegrationPath;
use massprops::integrals::volume_integrals;
use massprops::shapes::{self, MeshBuilder};
use massprops::solid::Solid;
use massprops::solid::solid_properties;
use nalgebra::{Point3, Vector3};

const TOL: f64 = 1e-13;

fn solid(mesh: &PolyMesh, path: IntegrationPath) -> Solid {
    solid_properties(mesh, path).expect("closed test meshes enclose volume")
}

#[track_caller]
fn assert_same(a: &Solid, b: &Solid, scale: f64, what: &str) {
    assert_eq!(a.flipped, b.flipped, "{what}");
    assert_rel(a.volume, b.volume, TOL, what);
    assert_point(
        &a.unit_density.center_of_mass,
        &b.unit_density.center_of_mass,
        scale,
        TOL,
        what,
    );
    assert_mat(
        &a.unit_density.inertia_com,
        &b.unit_density.inertia_com,
        TOL,
        what,
    );
}

/// A deterministic pseudo-random jitter in [−1, 1) (a 64-bit LCG; no dependency needed).
fn jitter(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    ((*state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

/// The triangulated `builder` with every vertex moved by up to `amount` in each coordinate:
/// an irregular closed triangle mesh (moving vertices keeps triangles planar and the mesh closed).
fn jittered(builder: &MeshBuilder, amount: f64, seed: u64) -> MeshBuilder {
    let mut b = builder.clone().triangulated();
    let mut state = seed;
    for p in &mut b.positions {
        *p += Vector3::new(jitter(&mut state), jitter(&mut state), jitter(&mut state)) * amount;
    }
    b
}

fn size(mesh: &PolyMesh) -> f64 {
    let (lo, hi) = mesh.bounding_box();
    (hi - lo).norm()
}

#[test]
fn samples_agree_on_every_path_and_with_their_triangulation() {
    for (name, _, builder) in shapes::samples() {
        let poly = builder.build();
        let tri = builder.clone().triangulated().build();
        assert!(poly.as_triangles().is_none(), "{name} has polygons");
        assert_eq!(tri.triangle_count(), poly.triangle_count(), "{name}");
        let scale = size(&poly);
        let reference = solid(&poly, IntegrationPath::Polygon);
        for (what, s) in [
            (
                "polygon path on the triangulation",
                solid(&tri, IntegrationPath::Polygon),
            ),
            ("triangle path", solid(&tri, IntegrationPath::Triangle)),
            (
                "parallel triangle path",
                solid(&tri, IntegrationPath::TriangleParallel),
            ),
            ("auto", solid(&tri, IntegrationPath::Auto)),
        ] {
            assert_same(&s, &reference, scale, &format!("{name}: {what}"));
        }
        // The triangle paths fall back to Mirtich for polygon meshes.
        assert_same(
            &solid(&poly, IntegrationPath::Triangle),
            &reference,
            scale,
            name,
        );

        let (v, c, i) = tetra_sum(&tri);
        assert_rel(
            reference.volume,
            v,
            TOL,
            &format!("{name}: tetrahedra volume"),
        );
        assert_point(&reference.unit_density.center_of_mass, &c, scale, TOL, name);
        assert_mat(
            &reference.unit_density.inertia_com,
            &i,
            TOL,
            &format!("{name}: tetrahedra tensor"),
        );
    }
}

#[test]
fn irregular_triangle_meshes_agree_on_every_path() {
    let cases = [
        ("torus", shapes::torus(2.0, 0.7, 24, 12), 0.05),
        ("t_handle", shapes::t_handle(), 0.001),
        ("hammer", shapes::hammer(), 0.002),
        (
            "star prism",
            shapes::prism(
                &common::star(nalgebra::Point2::new(1.0, 2.0), 2.0, 0.6, 7),
                -1.0,
                3.0,
            ),
            0.1,
        ),
    ];
    for (k, (name, builder, amount)) in cases.into_iter().enumerate() {
        let b = jittered(&builder, amount, 17 + k as u64);
        let mesh = b.build();
        let scale = size(&mesh);
        let mirtich = solid(&mesh, IntegrationPath::Polygon);
        let triangle = solid(&mesh, IntegrationPath::Triangle);
        assert_same(
            &triangle,
            &mirtich,
            scale,
            &format!("jittered {name}: triangle vs polygon"),
        );
        let (v, c, i) = tetra_sum(&mesh);
        assert_rel(
            mirtich.volume,
            v,
            TOL,
            &format!("jittered {name}: tetrahedra volume"),
        );
        assert_point(&mirtich.unit_density.center_of_mass, &c, scale, TOL, name);
        assert_mat(
            &mirtich.unit_density.inertia_com,
            &i,
            TOL,
            &format!("jittered {name}: tetrahedra"),
        );
    }
}

#[test]
fn parallel_triangle_path_is_bit_identical_to_the_sequential_one() {
    // Enough triangles for many blocks of the fixed summation order, and an irregular mesh so the
    // partial sums are not all alike.
    for (builder, seed) in [
        (shapes::sample_torus(), 1),
        (shapes::torus(1.0, 0.4, 200, 100), 2),
    ] {
        let mesh = jittered(&builder, 0.01, seed).build();
        assert!(mesh.triangle_count() > 8 * 512);
        let seq = volume_integrals(&mesh, IntegrationPath::Triangle);
        let par = volume_integrals(&mesh, IntegrationPath::TriangleParallel);
        assert_eq!(seq, par);
        assert_eq!(
            solid(&mesh, IntegrationPath::Triangle),
            solid(&mesh, IntegrationPath::TriangleParallel)
        );
    }
}

#[test]
fn auto_above_the_parallel_threshold_is_bit_identical_to_one_thread() {
    // 256 × 130 quads = 66 560 triangles, just above the size from which `Auto` shares the
    // triangles with the rayon pool (what `props` and the app use on large meshes).
    let mesh = jittered(&shapes::torus(1.0, 0.3, 256, 130), 0.002, 3).build();
    assert!(mesh.triangle_count() > massprops::integrals::PARALLEL_ABOVE);
    let seq = volume_integrals(&mesh, IntegrationPath::Triangle);
    assert_eq!(volume_integrals(&mesh, IntegrationPath::Auto), seq);
    assert_eq!(
        volume_integrals(&mesh, IntegrationPath::TriangleParallel),
        seq
    );
    // And the polygon path, another algorithm, agrees to round-off: the blocks summed are real.
    let polygon = volume_integrals(&mesh, IntegrationPath::Polygon);
    assert_rel(polygon.volume(), seq.volume(), TOL, "volume");
    // A torus of R = 1, r = 0.3 encloses about 2π²Rr² = 1.78 (less the polygons' deficit).
    assert!((1.7..1.78).contains(&seq.volume()), "{}", seq.volume());
}

#[test]
fn quads_match_their_triangulation_in_both_directions() {
    // A planar quad split along either diagonal is the same region.
    let b = shapes::cuboid(Vector3::new(1.5, 0.25, 3.0), Point3::new(0.5, -2.0, 1.0));
    let fan_from_first = b.clone().triangulated();
    let mut fan_from_second = b.clone();
    for f in &mut fan_from_second.faces {
        f.rotate_left(1);
    }
    let fan_from_second = fan_from_second.triangulated();
    let quads = solid(&b.build(), IntegrationPath::Polygon);
    for t in [fan_from_first, fan_from_second] {
        let mesh = t.build();
        assert!(mesh.as_triangles().is_some());
        for path in [IntegrationPath::Polygon, IntegrationPath::Triangle] {
            assert_same(&solid(&mesh, path), &quads, 3.5, &format!("{path:?}"));
        }
    }
}
