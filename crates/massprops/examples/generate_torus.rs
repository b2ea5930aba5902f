//! Writes a closed triangulated torus of about N triangles as OBJ, for end-to-end timing:
//! `cargo run --release -p massprops --example generate_torus -- 1000000 /tmp/torus_1m.obj`.

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let usage = "usage: generate_torus TRIANGLES OUTPUT.obj";
    let triangles: usize = args.next().ok_or(usage)?.parse()?;
    let output = args.next().ok_or(usage)?;
    // 2·t around × t along the tube, two triangles per quad: 4·t² triangles.
    let t = ((triangles / 4) as f64).sqrt().round().max(3.0) as usize;
    let mesh = massprops::shapes::torus(1.0, 0.3, 2 * t, t).triangulated();
    std::fs::write(
        &output,
        massprops::shapes::to_obj("torus", "triangulated torus R = 1, r = 0.3", &mesh),
    )?;
    println!("wrote {output}: {} triangles", mesh.faces.len());
    Ok(())
}
