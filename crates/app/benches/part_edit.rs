//! What an edit of a body made of parts costs in the lab, on a 1M-triangle part: a material
//! change (masses re-summed), a placement change (one part's vertices moved) and, for scale,
//! adding the part (a topology change: integrate, triangulate, index).
//!
//! `cargo bench -p inertia-lab --bench part_edit`

use std::path::{Path, PathBuf};

use criterion::{Criterion, criterion_group, criterion_main};
use inertia_lab::lab::settings::AppSettings;
use inertia_lab::lab::{Command, Lab};
use massprops::{MaterialEntry, shapes};

/// A torus of 1000 × 500 quads split into 1 000 000 triangles, written once to a temporary OBJ.
fn big_part() -> PathBuf {
    let path = std::env::temp_dir().join("inertia-lab-bench-torus-1m.obj");
    if !path.is_file() {
        let torus = shapes::torus(1.0, 0.3, 1000, 500).triangulated();
        std::fs::write(&path, shapes::to_obj("torus", "benchmark part", &torus))
            .expect("temp file");
    }
    path
}

/// The default T-handle with the big torus added as a second part.
fn lab_with_big_part(path: &Path) -> Lab {
    let mut lab = Lab::new(AppSettings::default()).expect("lab");
    lab.apply(Command::AddPart(path.to_path_buf()));
    assert!(
        lab.message().is_none_or(|m| !m.error),
        "{:?}",
        lab.message()
    );
    lab
}

fn part_edits(c: &mut Criterion) {
    let path = big_part();
    let mut group = c.benchmark_group("part edit, 1M-triangle part");
    group.sample_size(10);
    let mut lab = lab_with_big_part(&path);
    let composition = |lab: &Lab| {
        lab.primary()
            .body()
            .composition
            .clone()
            .expect("a body of parts")
    };
    let torus = composition(&lab).parts[1].entry.clone();
    let mut k = 0u32;
    group.bench_function("material", |b| {
        b.iter(|| {
            k += 1;
            let mut entry = torus.clone();
            entry.material = MaterialEntry::Density(1000.0 + f64::from(k % 7));
            lab.apply(Command::EditPart {
                index: 1,
                entry: Box::new(entry),
                visible: true,
            });
        });
    });
    group.bench_function("placement", |b| {
        b.iter(|| {
            k += 1;
            let mut entry = torus.clone();
            entry.translation = [f64::from(k % 5) * 0.01, 0.0, 0.0];
            lab.apply(Command::EditPart {
                index: 1,
                entry: Box::new(entry),
                visible: true,
            });
        });
    });
    group.bench_function("add part (topology)", |b| {
        b.iter_batched(
            || Lab::new(AppSettings::default()).expect("lab"),
            |mut lab| lab.apply(Command::AddPart(path.clone())),
            criterion::BatchSize::PerIteration,
        );
    });
    group.finish();
    assert!(
        lab.message().is_none_or(|m| !m.error),
        "{:?}",
        lab.message()
    );
}

criterion_group!(benches, part_edits);
criterion_main!(benches);
