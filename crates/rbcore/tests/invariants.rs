//! Property tests: conservation laws over random bodies and spins, and the poke law.

use nalgebra::{Matrix3, Point3, Rotation3, Vector3};
use proptest::prelude::*;
use rbcore::{Body, Integrator, RotationModel, Settings, Simulation};

/// Principal moments of a realisable body: any a, b and c between |a − b| and a + b.
fn moments() -> impl Strategy<Value = Vector3<f64>> {
    (0.1..10.0f64, 0.1..10.0f64, 0.0..1.0f64).prop_map(|(a, b, t)| {
        let lo = (a - b).abs();
        Vector3::new(a, b, lo + t * (a + b - lo))
    })
}

fn vec3(r: f64) -> impl Strategy<Value = Vector3<f64>> {
    (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| Vector3::new(x, y, z))
}

fn free_body(m: Vector3<f64>, w: Vector3<f64>) -> Body {
    let mut b = Body::from_moments(1.5, m).expect("realisable moments");
    b.set_omega_world(w).expect("finite");
    b
}

/// Runs `n` steps, returning the worst relative deviations of E, |L| and the world L vector.
fn drift(body: Body, integrator: Integrator, n: usize) -> (f64, f64, f64) {
    let settings = Settings {
        integrator,
        model: RotationModel::Full,
        ..Settings::default()
    };
    let mut sim = Simulation::new(body, settings).expect("valid");
    let d0 = sim.diagnostics();
    let (mut de, mut dn, mut dv): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for _ in 0..n {
        sim.step().expect("no divergence");
        let d = sim.diagnostics();
        de = de.max((d.energy / d0.energy - 1.0).abs());
        dn = dn.max((d.angular_momentum_norm / d0.angular_momentum_norm - 1.0).abs());
        dv = dv.max((d.angular_momentum - d0.angular_momentum).norm() / d0.angular_momentum_norm);
    }
    (de, dn, dv)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn default_integrator_conserves_energy_and_angular_momentum(m in moments(), w in vec3(20.0)) {
        prop_assume!(w.norm() > 1e-3);
        let (de, dn, dv) = drift(free_body(m, w), Integrator::MidpointCayley, 400);
        prop_assert!(de < 1e-11, "E drift {}", de);
        prop_assert!(dn < 1e-12, "|L| drift {}", dn);
        prop_assert!(dv < 1e-12, "L drift {}", dv);
    }

    #[test]
    fn exact_and_splitting_keep_world_l_and_bounded_energy(m in moments(), w in vec3(20.0)) {
        prop_assume!(w.norm() > 1e-3);
        let (de, _, dv) = drift(free_body(m, w), Integrator::Exact, 200);
        prop_assert!(de < 1e-9, "exact E drift {}", de);
        prop_assert!(dv < 1e-12, "exact L drift {}", dv);
        let (_, dn, dv) = drift(free_body(m, w), Integrator::Splitting, 200);
        prop_assert!(dn < 1e-12 && dv < 1e-12);
    }

    #[test]
    fn poke_changes_momenta_by_exactly_j_and_r_cross_j(
        m in moments(), w in vec3(5.0), r in vec3(10.0), x in vec3(10.0), j in vec3(3.0),
    ) {
        let mut b = free_body(m, w);
        b.set_position(Point3::from(r)).expect("finite");
        b.set_velocity(Vector3::new(0.1, -0.2, 0.3)).expect("finite");
        let (p0, l0) = (b.momentum(), b.angular_momentum());
        // Angular momentum about the world origin, r × p + L.
        let lo0 = r.cross(&p0) + l0;
        b.apply_impulse_at(&Point3::from(x), &j).expect("finite");
        prop_assert!((b.momentum() - p0 - j).norm() <= 1e-15 * (1.0 + p0.norm() + j.norm()));
        prop_assert!((b.angular_momentum() - l0 - (x - r).cross(&j)).norm() <= 1e-13 * (1.0 + l0.norm()));
        let lo1 = r.cross(&b.momentum()) + b.angular_momentum();
        prop_assert!((lo1 - lo0 - x.cross(&j)).norm() <= 1e-12 * (1.0 + lo0.norm() + x.norm() * j.norm()));
    }

    #[test]
    fn inertia_tensor_round_trips_through_the_principal_frame(
        m in moments(), a in -3.0..3.0f64, b in -3.0..3.0f64, c in -3.0..3.0f64,
    ) {
        let rot = Rotation3::from_euler_angles(a, b, c);
        let tensor = rot.matrix() * Matrix3::from_diagonal(&m) * rot.matrix().transpose();
        let body = Body::from_inertia_tensor(2.0, &tensor).expect("valid");
        let mut sorted = [m.x, m.y, m.z];
        sorted.sort_by(f64::total_cmp);
        for i in 0..3 {
            prop_assert!((body.moments()[i] - sorted[i]).abs() < 1e-12 * sorted[2]);
        }
        let ax = body.principal_axes();
        prop_assert!((ax.matrix().determinant() - 1.0).abs() < 1e-12);
        let back = ax.matrix() * Matrix3::from_diagonal(&body.moments()) * ax.matrix().transpose();
        prop_assert!((back - tensor).amax() < 1e-12 * sorted[2]);
    }
}
