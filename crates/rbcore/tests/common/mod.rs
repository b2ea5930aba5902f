//! Helpers shared by the integration tests: the canonical body and an independent AGM.
#![allow(dead_code)] // each test binary uses a different subset

use nalgebra::Vector3;
use rbcore::{Body, Diagnostics, Integrator, RotationModel, Settings, Simulation};

/// Principal moments of the canonical case.
pub const MOMENTS: [f64; 3] = [1.0, 2.0, 3.0];
/// Initial principal-frame ω of the canonical case.
pub const OMEGA0: [f64; 3] = [0.001, 10.0, 0.001];

/// A free body with the given moments and principal-frame ω.
pub fn simulation(
    moments: [f64; 3],
    omega: [f64; 3],
    integrator: Integrator,
    model: RotationModel,
    dt: f64,
) -> Simulation {
    let mut body = Body::from_moments(1.0, Vector3::from(moments)).expect("valid body");
    body.set_omega_principal(Vector3::from(omega))
        .expect("finite");
    let settings = Settings {
        dt,
        integrator,
        model,
        ..Settings::default()
    };
    Simulation::new(body, settings).expect("valid settings")
}

/// Runs `duration` seconds and returns the diagnostics at t = 0 and after every step.
pub fn run(sim: &mut Simulation, duration: f64) -> Vec<Diagnostics> {
    let n = (duration / sim.settings().dt).round() as usize;
    let mut out = Vec::with_capacity(n + 1);
    out.push(sim.diagnostics());
    for _ in 0..n {
        sim.step().expect("no divergence");
        out.push(sim.diagnostics());
    }
    out
}

/// Arithmetic-geometric mean, written here independently of the crate.
pub fn agm(mut a: f64, mut b: f64) -> f64 {
    while (a - b).abs() > 1e-15 * a {
        let next = (0.5 * (a + b), (a * b).sqrt());
        a = next.0;
        b = next.1;
    }
    a
}

/// Flip period `4K(k)/λ` of the torque-free motion with body angular momentum `l` near the major
/// axis side of the separatrix (`|L|² > 2EI₂`), from Landau & Lifshitz §37; `K = π/(2 AGM(1, k'))`.
pub fn flip_period(i: [f64; 3], l: [f64; 3]) -> f64 {
    let m2 = l.iter().map(|x| x * x).sum::<f64>();
    let e2 = (0..3).map(|j| l[j] * l[j] / i[j]).sum::<f64>();
    assert!(m2 > e2 * i[1], "formula below is for |L|² > 2EI₂");
    let lambda = ((i[2] - i[1]) * (m2 - e2 * i[0]) / (i[0] * i[1] * i[2])).sqrt();
    // k'² = (I₃ − I₁)(M² − 2EI₂)/((I₃ − I₂)(M² − 2EI₁)), with M² − 2EI₂ summed term by term.
    let d2 = l[0] * l[0] * (1.0 - i[1] / i[0]) + l[2] * l[2] * (1.0 - i[1] / i[2]);
    let kp = ((i[2] - i[0]) * d2 / ((i[2] - i[1]) * (m2 - e2 * i[0]))).sqrt();
    let k = std::f64::consts::PI / (2.0 * agm(1.0, kp));
    4.0 * k / lambda
}

/// Interpolated times where component `c` of principal ω changes sign.
pub fn crossings(d: &[Diagnostics], c: usize) -> Vec<f64> {
    d.windows(2)
        .filter(|w| (w[0].omega_principal[c] > 0.0) != (w[1].omega_principal[c] > 0.0))
        .map(|w| {
            let (t0, y0, t1, y1) = (
                w[0].time,
                w[0].omega_principal[c],
                w[1].time,
                w[1].omega_principal[c],
            );
            t0 + (t1 - t0) * y0 / (y0 - y1)
        })
        .collect()
}
