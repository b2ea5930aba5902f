//! The tennis-racket (Dzhanibekov) flip of a free body: an aluminium T-handle, its inertia from
//! its mesh by `massprops`, spun about its intermediate axis with a small perturbation. The
//! flips of ω₂ are counted and their period compared with `rbcore::polhode`'s prediction and
//! with the closed form 4K(k)/λ (Landau & Lifshitz, *Mechanics* §37), computed here.
//!
//! `cargo run -p rbcore --example tennis_racket_flip`

use nalgebra::Vector3;
use rbcore::{Body, FlipCounter, Polhode, Settings, Simulation, polhode, stability};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mesh = massprops::shapes::t_handle().build();
    let props = massprops::mass_properties(&mesh, 2700.0)?;
    let mut body = Body::from_inertia_tensor(props.mass, &props.inertia_com)?;
    let i = body.moments();
    println!(
        "T-handle: {:.4} kg, moments {:?} kg·m²",
        props.mass,
        i.as_slice()
    );
    println!("spin about axis 2 is {:?}", stability(&i, 1));

    // 10 rad/s about the intermediate axis, a little about the others.
    let omega = Vector3::new(0.001, 10.0, 0.01);
    body.set_omega_principal(omega)?;
    let l = body.angular_momentum_principal();
    let Polhode::Circles { axis, period, .. } = polhode(&i, &l) else {
        return Err(format!("not a flip: {:?}", polhode(&i, &l)).into());
    };
    println!(
        "predicted: L circles axis {}, ω₂ reverses every {:.4} s",
        axis + 1,
        period / 2.0
    );

    let mut sim = Simulation::new(body, Settings::default())?; // midpoint-Cayley, 240 Hz
    let start = sim.diagnostics();
    let mut flips = FlipCounter::new();
    let mut worst_energy: f64 = 0.0;
    while sim.time() < 30.0 {
        sim.step()?;
        let d = sim.diagnostics();
        flips.observe(d.time, d.omega_principal.y);
        worst_energy = worst_energy.max(((d.energy - start.energy) / start.energy).abs());
    }
    let measured = flips.mean_period().ok_or("fewer than three flips")?;
    let end = sim.diagnostics();
    println!(
        "measured: {} flips in {:.0} s, period {:.4} s ({:+.1e} from predicted)",
        flips.flips(),
        sim.time(),
        measured,
        measured / period - 1.0
    );
    println!(
        "drift: energy {worst_energy:.1e}, world L {:.1e}",
        (end.angular_momentum - start.angular_momentum).norm() / start.angular_momentum.norm()
    );

    // The closed form for |L|² > 2E·I₂ (L circles axis 3): T = 4K(k)/λ with
    // λ² = (I₃ − I₂)(|L|² − 2E·I₁)/(I₁I₂I₃), k'² = (I₃ − I₁)(|L|² − 2E·I₂)/((I₃ − I₂)(|L|² − 2E·I₁))
    // and K = π/(2·AGM(1, k')).
    assert_eq!(axis, 2);
    let l2 = l.norm_squared();
    let e2 = (0..3).map(|k| l[k] * l[k] / i[k]).sum::<f64>(); // 2E
    let beyond = (0..3)
        .map(|k| (i[k] - i.y) * l[k] * l[k] / i[k])
        .sum::<f64>(); // |L|² − 2E·I₂
    let lambda = ((i.z - i.y) * (l2 - e2 * i.x) / (i.x * i.y * i.z)).sqrt();
    let kp = ((i.z - i.x) * beyond / ((i.z - i.y) * (l2 - e2 * i.x))).sqrt();
    let (mut a, mut b) = (1.0, kp);
    while (a - b).abs() > 1e-15 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    let closed_form = 4.0 * (std::f64::consts::PI / (2.0 * a)) / lambda;
    assert!((period - closed_form).abs() < 1e-9 * closed_form);
    // The default integrator: the flip period to 1e-3, E to 1e-12, world L to round-off.
    assert!(flips.flips() >= 3);
    assert!((measured - period).abs() < 1e-3 * period);
    assert!(worst_energy < 1e-12);
    Ok(())
}
