//! A mesh's mass properties, as a user of the crate gets them: an OBJ read from text, then one
//! of the crate's sample shapes. Prints mass, centre of mass, the tensor and the principal
//! moments, and checks them against the closed forms of a box.
//!
//! `cargo run -p massprops --example mesh_inertia`

use std::path::Path;

use massprops::{MassSpec, Method, analyze, parse_mesh, shapes};

/// A 2 × 1 × 0.5 box (metres) with a corner at the origin, quads wound counter-clockwise seen
/// from outside.
const BOX_OBJ: &str = "\
o box
v 0 0 0
v 2 0 0
v 2 1 0
v 0 1 0
v 0 0 0.5
v 2 0 0.5
v 2 1 0.5
v 0 1 0.5
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 3 4 8 7
f 1 5 8 4
f 2 3 7 6
";

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // The path only names the format (by extension) and the file in messages.
    let file = parse_mesh(BOX_OBJ.as_bytes(), Path::new("box.obj"))?;
    let a = analyze(&file.mesh, Method::Volume, MassSpec::Density(1000.0))?;
    let p = &a.properties;
    println!("box.obj, 1000 kg/m³");
    println!("  volume          {:?} m³", a.volume);
    println!("  mass            {} kg", p.mass);
    println!(
        "  centre of mass  {:?} m",
        p.center_of_mass.coords.as_slice()
    );
    println!(
        "  inertia about the centre of mass (kg·m²):{}",
        p.inertia_com
    );
    println!("  inertia about the origin (kg·m²):{}", p.inertia_origin());
    println!(
        "  principal moments {:?} kg·m² ({})",
        p.principal.moments.as_slice(),
        p.principal.degeneracy.describe()
    );
    println!("  warnings: {}", a.warnings.len());

    // Closed forms of a uniform a × b × c box: m = ρabc, I_xx = m(b² + c²)/12, …, and about
    // the origin the parallel-axis products −m·cₓ·c_y (off-diagonals are −∑m·x·y).
    let (sx, sy, sz) = (2.0, 1.0, 0.5);
    let m = 1000.0 * sx * sy * sz;
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * m;
    assert!(close(p.mass, m));
    assert!((p.center_of_mass - nalgebra::Point3::new(1.0, 0.5, 0.25)).norm() < 1e-15);
    assert!(close(p.inertia_com[(0, 0)], m * (sy * sy + sz * sz) / 12.0));
    assert!(close(p.inertia_com[(1, 1)], m * (sx * sx + sz * sz) / 12.0));
    assert!(close(p.inertia_com[(2, 2)], m * (sx * sx + sy * sy) / 12.0));
    assert!(close(p.inertia_com[(0, 1)], 0.0));
    let origin = p.inertia_origin();
    assert!(close(origin[(0, 1)], -m * 1.0 * 0.5));
    assert!(close(origin[(0, 2)], -m * 1.0 * 0.25));
    assert!(close(origin[(1, 2)], -m * 0.5 * 0.25));
    // Ascending: about x (the shortest sides), then y, then z.
    let moments = p.principal.moments;
    assert!(close(moments.x, p.inertia_com[(0, 0)]) && close(moments.z, p.inertia_com[(2, 2)]));
    // A box is its own bounding box.
    assert!(a.bounding_box.compare_to(p).moment_error.amax() < 1e-12);
    assert!(a.warnings.is_empty());

    // A sample shape: the T-handle (metres), in aluminium.
    let t = shapes::t_handle().build();
    let a = analyze(&t, Method::Volume, MassSpec::Density(2700.0))?;
    let p = &a.properties;
    println!("\nT-handle, 2700 kg/m³");
    println!("  mass            {:.6} kg", p.mass);
    println!(
        "  centre of mass  {:?} m",
        p.center_of_mass.coords.as_slice()
    );
    println!(
        "  principal moments {:?} kg·m²",
        p.principal.moments.as_slice()
    );
    println!(
        "  principal axes (columns):{}",
        p.principal.rotation.matrix()
    );
    let bbox = a.bounding_box.compare_to(p);
    println!(
        "  bounding box as the body: moment errors {:+.1?} %, centre of mass {:.1} mm off",
        (bbox.moment_error * 100.0).as_slice(),
        bbox.com_offset * 1e3
    );
    // An 80 × 12 mm bar on a 50 × 12 mm stem, 12 mm deep.
    let volume = (0.08 * 0.012 + 0.05 * 0.012) * 0.012;
    assert!((p.mass - 2700.0 * volume).abs() < 1e-12 * p.mass);
    Ok(())
}
