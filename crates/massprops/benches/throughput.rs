//! Triangles per second of each integration path, side by side with parry3d-f64's
//! `MassProperties::from_trimesh` on the same data, for 10k to 4M-triangle tori.
//!
//! Run with `cargo bench -p massprops --bench throughput`; criterion prints the throughput of
//! each (path, size) in Melem/s (= million triangles per second). The `cold_call` group times
//! single calls made after a pause, the way a program that loads one mesh makes them. The
//! `read` group parses the same 1M-triangle torus from memory as GLB, MuJoCo MSH, binary STL,
//! binary PLY and ASCII PLY (the readers' cost per triangle, beside each other).

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

/// The torus's triangles as a binary STL, as PLY (binary little-endian floats, and ASCII), as
/// GLB (float positions, u32 indices, one node) and as MuJoCo's `.msh`, each as a writer other
/// than ours would write them.
fn files(mesh: &PolyMesh) -> [(&'static str, &'static str, Vec<u8>); 5] {
    let triangles = mesh.as_triangles().expect("triangulated");
    let points = mesh.positions();
    let mut stl = vec![0u8; 80];
    stl.extend_from_slice(&(triangles.len() as u32).to_le_bytes());
    for t in triangles {
        stl.extend_from_slice(&[0u8; 12]);
        for &i in t {
            for c in points[i as usize].iter() {
                stl.extend_from_slice(&(*c as f32).to_le_bytes());
            }
        }
        stl.extend_from_slice(&[0, 0]);
    }
    let header = |format: &str| {
        format!(
            "ply\nformat {format} 1.0\nelement vertex {}\nproperty float x\nproperty float y\n\
             property float z\nelement face {}\nproperty list uchar int vertex_indices\n\
             end_header\n",
            points.len(),
            triangles.len()
        )
    };
    let mut binary = header("binary_little_endian").into_bytes();
    for p in points {
        for c in p.iter() {
            binary.extend_from_slice(&(*c as f32).to_le_bytes());
        }
    }
    for t in triangles {
        binary.push(3);
        for &i in t {
            binary.extend_from_slice(&(i as i32).to_le_bytes());
        }
    }
    let mut ascii = header("ascii");
    for p in points {
        ascii += &format!("{} {} {}\n", p.x as f32, p.y as f32, p.z as f32);
    }
    for t in triangles {
        ascii += &format!("3 {} {} {}\n", t[0], t[1], t[2]);
    }
    let coordinates: Vec<u8> = points
        .iter()
        .flat_map(|p| p.iter().map(|&c| c as f32).collect::<Vec<_>>())
        .flat_map(f32::to_le_bytes)
        .collect();
    let corners: Vec<u8> = triangles
        .iter()
        .flatten()
        .flat_map(|i| i.to_le_bytes())
        .collect();
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1}}]}}],"accessors":[{{"bufferView":0,"componentType":5126,"count":{},"type":"VEC3"}},{{"bufferView":1,"componentType":5125,"count":{},"type":"SCALAR"}}],"bufferViews":[{{"buffer":0,"byteLength":{}}},{{"buffer":0,"byteOffset":{},"byteLength":{}}}],"buffers":[{{"byteLength":{}}}]}}    "#,
        points.len(),
        3 * triangles.len(),
        coordinates.len(),
        coordinates.len(),
        corners.len(),
        coordinates.len() + corners.len()
    );
    let json = &json.as_bytes()[..json.len() / 4 * 4];
    let bin_length = coordinates.len() + corners.len();
    let mut glb = b"glTF".to_vec();
    glb.extend_from_slice(&2u32.to_le_bytes());
    glb.extend_from_slice(&((12 + 8 + json.len() + 8 + bin_length) as u32).to_le_bytes());
    glb.extend_from_slice(&(json.len() as u32).to_le_bytes());
    glb.extend_from_slice(b"JSON");
    glb.extend_from_slice(json);
    glb.extend_from_slice(&(bin_length as u32).to_le_bytes());
    glb.extend_from_slice(b"BIN\0");
    glb.extend_from_slice(&coordinates);
    glb.extend_from_slice(&corners);
    let counts = [points.len(), 0, 0, triangles.len()].map(|n| n as i32);
    let mut msh: Vec<u8> = counts.iter().flat_map(|n| n.to_le_bytes()).collect();
    msh.extend_from_slice(&coordinates);
    msh.extend_from_slice(&corners);
    [
        ("binary_stl", "t.stl", stl),
        ("binary_ply", "t.ply", binary),
        ("ascii_ply", "t.ply", ascii.into_bytes()),
        ("glb", "t.glb", glb),
        ("msh", "t.msh", msh),
    ]
}

fn read(c: &mut Criterion) {
    let mut group = short_group(c, "read");
    let mesh = torus_mesh(1_000_000);
    let triangles = mesh.triangle_count();
    group.throughput(Throughput::Elements(triangles as u64));
    for (name, file, bytes) in files(&mesh) {
        let path = std::path::Path::new(file);
        group.bench_with_input(BenchmarkId::new(name, "1000k"), &bytes, |b, bytes| {
            b.iter(|| massprops::parse_mesh(black_box(bytes), path).expect("reads"))
        });
    }
    group.finish();
}

criterion_group!(benches, throughput, cold_call, read);
criterion_main!(benches);
