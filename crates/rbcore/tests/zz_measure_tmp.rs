mod common;
use common::{MOMENTS, OMEGA0, crossings, flip_period, run, simulation};
use rbcore::{Integrator, RotationModel, torque_free_period};
use nalgebra::Vector3;

fn figures(integrator: Integrator, dt: f64, omega: [f64; 3], secs: f64) {
    let mut sim = simulation(MOMENTS, omega, integrator, RotationModel::Full, dt);
    let d = run(&mut sim, secs);
    let l0 = d[0].angular_momentum;
    let e0 = d[0].energy;
    let (mut de, mut dn, mut dv) = (0.0f64, 0.0f64, 0.0f64);
    for s in &d {
        de = de.max(((s.energy - e0) / e0).abs());
        dn = dn.max(((s.angular_momentum_norm - l0.norm()) / l0.norm()).abs());
        dv = dv.max((s.angular_momentum - l0).norm() / l0.norm());
    }
    let z = crossings(&d, 1);
    let (pe1, pe2) = if z.len() >= 3 {
        let n = z.len();
        let period = 2.0 * (z[n - 1] - z[0]) / (n - 1) as f64;
        let lp = Vector3::new(MOMENTS[0]*omega[0], MOMENTS[1]*omega[1], MOMENTS[2]*omega[2]);
        let r = torque_free_period(&Vector3::from(MOMENTS), &lp).unwrap_or(f64::NAN);
        let f = if lp.norm_squared() > 0.0 && z.len() > 2 { flip_period(MOMENTS, [lp.x, lp.y, lp.z]) } else { f64::NAN };
        ((period - r) / r, (period - f) / f)
    } else { (f64::NAN, f64::NAN) };
    println!("{integrator} dt={dt:.5} w={omega:?}: dE {de:.3e} d|L| {dn:.3e} dL {dv:.3e} flips {} period err {pe1:+.3e} (common {pe2:+.3e})", z.len());
}

#[test]
fn measure() {
    figures(Integrator::MidpointCayley, 1.0 / 240.0, OMEGA0, 60.0);
    figures(Integrator::Exact, 1.0 / 240.0, OMEGA0, 60.0);
    figures(Integrator::Splitting, 1.0 / 240.0, OMEGA0, 60.0);
    figures(Integrator::MidpointCayley, 1.0 / 60.0, OMEGA0, 60.0);
    for w in [[0.01, 0.01, 10.0], [10.0, 0.01, 0.01]] {
        for i in [Integrator::MidpointCayley, Integrator::Splitting, Integrator::Exact] {
            figures(i, 1.0 / 240.0, w, 120.0);
        }
    }
    figures(Integrator::MidpointCayley, 1.0 / 240.0, [1.0, 1.0, 10.0], 60.0);
    figures(Integrator::MidpointCayley, 1.0 / 240.0, [1.0, 1.0, 1.0], 10.0);
}
