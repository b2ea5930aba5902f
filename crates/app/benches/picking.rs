//! CPU ray picking (`lab::picking`): time per ray on tori of 10k, 100k and 1M triangles.
//!
//! Two sets of rays: `framed_grid`, what `--bench-frames` times after its frames (a 20 × 20 grid
//! of pixels, 15 px apart, over an 800 × 600 view framed on the body, hits and misses), and
//! `grazing`, rays from outside that all hit, at shallow angles (the picking unit test's rays).
//! Criterion reports the time for the whole set; divide by the ray count (400 and 200) for the
//! time per ray, or read the throughput in rays (elements) per second.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use nalgebra::{Point2, Point3, Vector2, Vector3};

use inertia_lab::gui::view3d::camera::OrbitCamera;
use inertia_lab::lab::geometry::TriMesh;
use inertia_lab::lab::picking::{Bvh, Ray};

/// A closed torus (R = 1, r = 0.3) of `2 × major × minor` triangles.
fn torus(major: usize, minor: usize) -> TriMesh {
    TriMesh::from_poly(&massprops::shapes::torus(1.0, 0.3, major, minor).build())
}

/// The 400 rays of the app's own picking measurement: the default orbit camera framed on the
/// body's bounding sphere, pixels (250 + 15i, 150 + 15j) of an 800 × 600 view.
fn framed_grid(mesh: &TriMesh) -> Vec<Ray> {
    let (mut lo, mut hi) = (
        Vector3::repeat(f64::INFINITY),
        Vector3::repeat(f64::NEG_INFINITY),
    );
    for p in &mesh.positions {
        lo = lo.inf(&p.coords);
        hi = hi.sup(&p.coords);
    }
    let mut camera = OrbitCamera::default();
    camera.frame(Point3::from((lo + hi) / 2.0), (hi - lo).norm() / 2.0);
    let size = Vector2::new(800.0, 600.0);
    (0..400u32)
        .map(|k| {
            let pixel = Point2::new(
                250.0 + f64::from(k % 20) * 15.0,
                150.0 + f64::from(k / 20) * 15.0,
            );
            camera.ray(pixel, size)
        })
        .collect()
}

/// 200 rays from a circle of radius 4 about the x axis towards the torus, each a hit.
fn grazing() -> Vec<Ray> {
    (0..200u32)
        .map(|i| {
            let a = f64::from(i) * 0.031;
            Ray {
                origin: Point3::new(0.0, 4.0 * a.cos(), 4.0 * a.sin()),
                dir: Vector3::new(1.0, -4.0 * a.cos(), -4.0 * a.sin()),
            }
        })
        .collect()
}

fn picking(c: &mut Criterion) {
    let mut group = c.benchmark_group("pick");
    group.sample_size(30);
    for (major, minor) in [(100, 50), (316, 158), (1000, 500)] {
        let mesh = torus(major, minor);
        let bvh = Bvh::build(&mesh);
        let n = mesh.triangles.len();
        for (name, rays) in [("framed_grid", framed_grid(&mesh)), ("grazing", grazing())] {
            let hits = rays.iter().filter(|r| bvh.pick(&mesh, r).is_some()).count();
            assert!(hits > 0, "{name} on {n} triangles: no ray hits");
            eprintln!("{name} on {n} triangles: {hits} of {} rays hit", rays.len());
            group.throughput(Throughput::Elements(rays.len() as u64));
            group.bench_with_input(BenchmarkId::new(name, n), &rays, |b, rays| {
                b.iter(|| {
                    rays.iter()
                        .filter(|r| bvh.pick(&mesh, black_box(r)).is_some())
                        .count()
                });
            });
        }
    }
    group.finish();
}

criterion_group!(benches, picking);
criterion_main!(benches);
