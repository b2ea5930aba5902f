//! Writes a mesh with each triangle cut into six (its centroid joined to its corners and to the
//! midpoints of its edges), as OBJ: the same surface and the same mass properties, six times the
//! triangles — the 5-million-triangle scan of the big-mesh benchmark is the Stanford dragon
//! (871 414 triangles) cut once:
//! `cargo run --release -p massprops --example subdivide -- dragon.obj dragon-5m.obj`.
//!
//! Midpoints are shared between the two triangles of an edge (computed from the edge's
//! endpoints in a fixed order), so the result is as closed as the input; triangles on a repeated
//! corner (no area) are left out.

use std::collections::HashMap;
use std::io::Write as _;

use nalgebra::Point3;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let usage = "usage: subdivide INPUT.obj|stl OUTPUT.obj";
    let input = args.next().ok_or(usage)?;
    let output = args.next().ok_or(usage)?;
    let file = massprops::load_mesh(std::path::Path::new(&input))?;
    let mesh = &file.mesh;
    let mut positions: Vec<Point3<f64>> = mesh.positions().to_vec();
    let mut midpoints: HashMap<(u32, u32), u32> = HashMap::new();
    let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(6 * mesh.triangle_count());
    for face in mesh.faces() {
        for w in face[1..].windows(2) {
            let corners = [face[0], w[0], w[1]];
            // A triangle on a repeated corner has no area; its cut would make internal walls.
            if corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0] {
                continue;
            }
            let p = corners.map(|i| positions[i as usize]);
            let centroid = Point3::from((p[0].coords + p[1].coords + p[2].coords) / 3.0);
            positions.push(centroid);
            let c = (positions.len() - 1) as u32;
            let mut mid = [0u32; 3];
            for k in 0..3 {
                let (a, b) = (corners[k], corners[(k + 1) % 3]);
                let key = (a.min(b), a.max(b));
                mid[k] = *midpoints.entry(key).or_insert_with(|| {
                    let (lo, hi) = (positions[key.0 as usize], positions[key.1 as usize]);
                    positions.push(nalgebra::center(&lo, &hi));
                    (positions.len() - 1) as u32
                });
            }
            for k in 0..3 {
                let (a, b) = (corners[k], corners[(k + 1) % 3]);
                triangles.push([a, mid[k], c]);
                triangles.push([mid[k], b, c]);
            }
        }
    }
    let mut out = std::io::BufWriter::new(std::fs::File::create(&output)?);
    writeln!(out, "# {input} with each triangle cut into six")?;
    for p in &positions {
        writeln!(out, "v {} {} {}", p.x, p.y, p.z)?;
    }
    for t in &triangles {
        writeln!(out, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1)?;
    }
    out.flush()?;
    println!(
        "wrote {output}: {} vertices, {} triangles",
        positions.len(),
        triangles.len()
    );
    Ok(())
}
