//! Triangles per second of each integration path, side by side with parry3d-f64's
//! `MassProperties::from_trimesh` on the same data, for 10k to 4M-triangle tori.
//!
//! Run with `cargo bench -p massprops --bench throughput`; criterion prints the throughput of
//! each (path, size) in Melem/s (= million triangles per second). The `cold_call` group times
//! single calls made after a pause, the way a program that loads one mesh makes them.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::measurement::WallTime;
use criterion::{
    BenchmarkGroup, BenchmarkId, Criterion, Throughput, criterion_group, criterion_main,
};
use massprops::integrals::IntegrationPath;
use massprops::integrals::volume_integrals;
use massprops::{PolyMesh, shapes};

/// A closed triangulated torus of 4·t² triangles.
fn torus_mesh(triangles: usize) -> PolyMesh {
    let t = ((triangles / 4) as f64).sqrt().round() as usize;
    shapes::torus(1.0, 0.3, 2 * t, t).triangulated().build()
}

/// A group of 10 samples over 2 s each: enough to separate the paths, which differ by 2–20×.
fn short_group<'a>(c: &'a mut Criterion, name: &str) -> BenchmarkGroup<'a, WallTime> {
    let mut group = c.benchmark_group(name);
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    group
}

fn throughput(c: &mut Criterion) {
    let mut group = short_group(c, "volume_integrals");
    for size in [10_000, 100_000, 1_000_000, 4_000_000] {
        let mesh = torus_mesh(size);
        let triangles = mesh.as_triangles().expect("triangulated").to_vec();
        let parry_vertices: Vec<parry3d_f64::math::Vector> = mesh
            .positions()
            .iter()
            .map(|p| parry3d_f64::math::Vector::new(p.x, p.y, p.z))
            .collect();
        group.throughput(Throughput::Elements(triangles.len() as u64));
        let label = format!("{}k", triangles.len() / 1000);
        for (name, path) in [
            ("polygon", IntegrationPath::Polygon),
            ("triangle", IntegrationPath::Triangle),
            ("triangle_parallel", IntegrationPath::TriangleParallel),
        ] {
            group.bench_with_input(BenchmarkId::new(name, &label), &mesh, |b, m| {
                b.iter(|| volume_integrals(black_box(m), path))
            });
        }
        group.bench_with_input(
            BenchmarkId::new("parry3d_f64", &label),
            &triangles,
            |b, t| {
                b.iter(|| {
                    parry3d_f64::mass_properties::MassProperties::from_trimesh(
                        1.0,
                        black_box(&parry_vertices),
                        black_box(t),
                    )
                })
            },
        );
    }
    group.finish();
}

/// One call after the pool has gone idle, as `props` and the app make it: each timed call
/// follows a 3 ms pause, long enough for rayon's threads to fall asleep.
fn cold_call(c: &mut Criterion) {
    let mut group = short_group(c, "cold_call");
    for size in [100_000, 1_000_000] {
        let mesh = torus_mesh(size);
        let triangles = mesh.as_triangles().expect("triangulated").len();
        group.throughput(Throughput::Elements(triangles as u64));
        let label = format!("{}k", triangles / 1000);
        for (name, path) in [
            ("triangle", IntegrationPath::Triangle),
            ("triangle_parallel", IntegrationPath::TriangleParallel),
        ] {
            group.bench_with_input(BenchmarkId::new(name, &label), &mesh, |b, m| {
                b.iter_custom(|iterations| {
                    (0..iterations)
                        .map(|_| {
                            std::thread::sleep(Duration::from_millis(3));
                            let start = Instant::now();
                            black_box(volume_integrals(black_box(m), path));
                            start.elapsed()
                        })
                        .sum()
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, throughput, cold_call);
criterion_main!(benches);
