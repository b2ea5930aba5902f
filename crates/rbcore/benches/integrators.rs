//! Cost of one step of each integrator on the canonical tennis-racket case
//! (I = 1, 2, 3; ω₀ = 0.001, 10, 0.001; dt = 1/240), in ns per step.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::Vector3;
use rbcore::{Body, Integrator, Settings, Simulation};

fn canonical(integrator: Integrator) -> Simulation {
    let mut body = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).expect("valid body");
    body.set_omega_principal(Vector3::new(0.001, 10.0, 0.001))
        .expect("finite");
    Simulation::new(
        body,
        Settings {
            integrator,
            ..Settings::default()
        },
    )
    .expect("valid settings")
}

fn step_cost(c: &mut Criterion) {
    let mut group = c.benchmark_group("step");
    for integrator in Integrator::ALL {
        let mut sim = canonical(integrator);
        group.bench_function(integrator.name(), |b| {
            b.iter(|| {
                // Implicit Euler slowly spins down and the others stay bounded: no divergence.
                black_box(&mut sim).step().expect("no divergence");
            });
        });
    }
    group.finish();
}

criterion_group!(benches, step_cost);
criterion_main!(benches);
