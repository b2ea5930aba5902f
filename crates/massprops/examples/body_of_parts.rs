//! A body made of parts with `massprops::composite`: a dumbbell whose bar is given by its mass,
//! its weights by their density, one of them hollowed by a void; then a thin-walled crate.
//! Each result is checked against the closed form (parallel-axis theorem over boxes).
//!
//! `cargo run -p massprops --example body_of_parts`

use massprops::{Fill, Part, Repairs, composite, shapes};
use nalgebra::{Isometry3, Point3, Vector3};

const STEEL: f64 = 7850.0; // kg/m³

/// A cube of side `s` centred on its own origin.
fn cube(s: f64) -> massprops::PolyMesh {
    shapes::cuboid(Vector3::repeat(s), Point3::origin()).build()
}

fn part(name: &str, mesh: massprops::PolyMesh, fill: Fill, x: f64) -> Part {
    Part {
        name: name.to_owned(),
        mesh,
        fill,
        placement: Isometry3::translation(x, 0.0, 0.0),
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (bar, side, hole, arm) = (0.03, 0.1, 0.06, 0.3); // metres
    let bar_mesh = shapes::cuboid(Vector3::new(0.5, bar, bar), Point3::origin()).build();
    let parts = [
        part("bar", bar_mesh, Fill::Mass { mass: 0.4 }, 0.0),
        part(
            "left weight",
            cube(side),
            Fill::Solid { density: STEEL },
            -arm,
        ),
        part(
            "right weight",
            cube(side),
            Fill::Solid { density: STEEL },
            arm,
        ),
        part("cavity", cube(hole), Fill::Void { density: STEEL }, arm),
    ];
    let body = composite(&parts, &Repairs::default())?;
    let p = &body.properties;
    println!(
        "dumbbell: {:.6} kg, centre of mass x = {:.6} m",
        p.mass, p.center_of_mass.x
    );
    println!(
        "  principal moments {:?} kg·m²",
        p.principal.moments.as_slice()
    );
    for part in &body.parts {
        println!(
            "  {:<12} {:>9.5} kg, share of I₁ I₂ I₃: {:>6.1?} %",
            part.name,
            part.mass,
            (part.share * 100.0).as_slice()
        );
    }

    // Closed form: masses add (a void counts negative), the centre is the mass-weighted mean,
    // and each box's own tensor m(b² + c²)/12 gains m·d² about the common centre.
    let (mb, mc, mv) = (0.4, STEEL * side.powi(3), STEEL * hole.powi(3));
    let m = mb + 2.0 * mc - mv;
    let c = (arm * (mc - mv) - arm * mc) / m;
    let along =
        mb * (2.0 * bar * bar) / 12.0 + 2.0 * mc * side * side / 6.0 - mv * hole * hole / 6.0;
    let across = mb * (0.25 + bar * bar) / 12.0
        + mb * c * c
        + mc * side * side / 6.0
        + mc * (-arm - c).powi(2)
        + mc * side * side / 6.0
        + mc * (arm - c).powi(2)
        - (mv * hole * hole / 6.0 + mv * (arm - c).powi(2));
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * y.abs();
    assert!(close(p.mass, m) && close(p.center_of_mass.x, c));
    let i = p.principal.moments;
    assert!(close(i.x, along) && close(i.y, across) && close(i.z, across));
    // The parts' shares of each principal moment add up to 1.
    let total: Vector3<f64> = body.parts.iter().map(|q| q.share).sum();
    assert!((total - Vector3::repeat(1.0)).amax() < 1e-12);

    // A thin-walled crate: a 0.5 m cube's faces as 2 mm of plywood (600 kg/m³). The six
    // faces of a cube of side a and mass m give I = 5/18 · m·a² about every axis.
    let a = 0.5;
    let wall = Fill::ThinWall {
        density: 600.0,
        thickness: 0.002,
    };
    let crate_body = composite(&[part("crate", cube(a), wall, 0.0)], &Repairs::default())?;
    let p = &crate_body.properties;
    println!(
        "crate: {:.3} kg, moments {:?} kg·m²",
        p.mass,
        p.principal.moments.as_slice()
    );
    let m = 600.0 * 0.002 * 6.0 * a * a;
    assert!(close(p.mass, m));
    assert!(close(p.principal.moments.z, 5.0 / 18.0 * m * a * a));
    assert!(close(p.principal.moments.x, 5.0 / 18.0 * m * a * a));
    Ok(())
}
