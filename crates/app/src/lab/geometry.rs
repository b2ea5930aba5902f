//! The render and picking mesh: a [`massprops::PolyMesh`] split into triangles, plus the polygon
//! edges for the wireframe overlay. Plain f64 data in the mesh's own coordinates; the 3D view
//! converts it to GPU buffers and `picking` indexes it.

use massprops::PolyMesh;
use nalgebra::{Point3, Vector3};

/// Triangles and polygon edges of a mesh, in the mesh's own coordinates.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct TriMesh {
    /// Vertex positions (as in the source mesh).
    pub positions: Vec<Point3<f64>>,
    /// Triangles, counter-clockwise seen from outside like the source faces.
    pub triangles: Vec<[u32; 3]>,
    /// The source polygons' edges, each once (triangulation diagonals excluded), for the
    /// wireframe; empty when there are more than [`WIREFRAME_MAX_EDGES`] (never drawn, so
    /// never kept).
    pub edges: Vec<[u32; 2]>,
}

/// Above this many polygon edges the wireframe is not drawn (egui would spend more time on it
/// than the whole frame budget), and the edges are not kept.
pub const WIREFRAME_MAX_EDGES: usize = 60_000;

impl TriMesh {
    /// Triangulates every face of `mesh` (ear clipping, so non-convex planar faces such as the
    /// T-handle's caps come out right; a fan would cover the notches).
    pub fn from_poly(mesh: &PolyMesh) -> Self {
        let positions = mesh.positions().to_vec();
        let mut triangles = Vec::with_capacity(mesh.triangle_count());
        // Each edge is one or two face sides on all but non-manifold edges: past twice the
        // limit in sides the wireframe is off.
        let sides = mesh.triangle_count() + 2 * mesh.face_count();
        let keep_edges = sides <= 2 * WIREFRAME_MAX_EDGES;
        let mut edges = Vec::new();
        for face in mesh.faces() {
            if keep_edges {
                for (k, &a) in face.iter().enumerate() {
                    let b = face[(k + 1) % face.len()];
                    edges.push([a.min(b), a.max(b)]);
                }
            }
            if face.len() == 3 {
                triangles.push([face[0], face[1], face[2]]);
            } else {
                ear_clip(&positions, face, &mut triangles);
            }
        }
        edges.sort_unstable();
        edges.dedup();
        if edges.len() > WIREFRAME_MAX_EDGES {
            edges = Vec::new();
        }
        Self {
            positions,
            triangles,
            edges,
        }
    }

    /// Centre and radius of the bounding sphere about the bounding-box centre.
    pub fn bounding_sphere(&self) -> (Point3<f64>, f64) {
        let mut lo = Vector3::repeat(f64::INFINITY);
        let mut hi = Vector3::repeat(f64::NEG_INFINITY);
        for p in &self.positions {
            lo = lo.inf(&p.coords);
            hi = hi.sup(&p.coords);
        }
        let c = Point3::from((lo + hi) * 0.5);
        let r = self
            .positions
            .iter()
            .map(|p| (p - c).norm())
            .fold(0.0, f64::max);
        (c, r)
    }
}

/// The most triangles the 3D view draws of a body: above it, a software renderer (Mesa's
/// llvmpipe: about 100 ns a triangle on 2 cores) would draw under 10 frames a second, so the view
/// draws a simplified copy ([`Drawn`]) and says so; every number and every pick uses the whole
/// mesh.
pub const DRAW_BUDGET: usize = 1_000_000;

/// A simplified copy of a big mesh, for drawing only: vertex clustering on a uniform grid (J.
/// Rossignac and P. Borrel, "Multi-resolution 3D approximations for rendering complex scenes",
/// 1993): each cell's vertices become one at their mean, and triangles whose corners fall in
/// fewer than three cells vanish.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Drawn {
    /// The simplified triangles (no edges).
    pub mesh: TriMesh,
    /// For each simplified triangle, the mesh triangle it comes from (for part colours).
    pub from: Vec<u32>,
}

impl Drawn {
    /// The copy to draw for `mesh`: `None` when it has at most `budget` triangles (drawn whole).
    pub fn of(mesh: &TriMesh, budget: usize) -> Option<Self> {
        let n = mesh.triangles.len();
        if n <= budget || mesh.positions.is_empty() {
            return None;
        }
        let (lo, hi) = mesh.positions.iter().fold(
            (
                Vector3::repeat(f64::INFINITY),
                Vector3::repeat(f64::NEG_INFINITY),
            ),
            |(lo, hi), p| (lo.inf(&p.coords), hi.sup(&p.coords)),
        );
        // A closed surface has about two triangles per vertex, and a cell of side h about
        // area / h² vertices on it: start from the cell giving `budget` triangles, and shrink the
        // grid while the result is still over budget.
        let area: f64 = mesh
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
                0.5 * (b - a).cross(&(c - a)).norm()
            })
            .sum();
        let mut cell = (2.0 * area / budget as f64)
            .sqrt()
            .max((hi - lo).max() / 2e6);
        loop {
            let drawn = Self::clustered(mesh, &lo, cell);
            if drawn.mesh.triangles.len() <= budget {
                return Some(drawn);
            }
            cell *= (drawn.mesh.triangles.len() as f64 / budget as f64)
                .sqrt()
                .max(1.05);
        }
    }

    /// The clustering on cells of side `cell` from `lo`.
    fn clustered(mesh: &TriMesh, lo: &Vector3<f64>, cell: f64) -> Self {
        let key = |p: &Point3<f64>| {
            let c = ((p.coords - lo) / cell).map(|x| x.floor().clamp(0.0, 2e6) as u64);
            (c.x << 42) | (c.y << 21) | c.z
        };
        let mut cluster_of = std::collections::HashMap::with_capacity(mesh.positions.len() / 4);
        let mut sums: Vec<(Vector3<f64>, u32)> = Vec::new();
        let vertex_cluster: Vec<u32> = mesh
            .positions
            .iter()
            .map(|p| {
                let id = *cluster_of.entry(key(p)).or_insert_with(|| {
                    sums.push((Vector3::zeros(), 0));
                    (sums.len() - 1) as u32
                });
                let s = &mut sums[id as usize];
                s.0 += p.coords;
                s.1 += 1;
                id
            })
            .collect();
        let positions = sums
            .iter()
            .map(|(sum, k)| Point3::from(sum / f64::from(*k)))
            .collect();
        let mut triangles = Vec::new();
        let mut from = Vec::new();
        for (k, t) in mesh.triangles.iter().enumerate() {
            let [a, b, c] = t.map(|i| vertex_cluster[i as usize]);
            if a != b && b != c && c != a {
                triangles.push([a, b, c]);
                from.push(k as u32);
            }
        }
        Self {
            mesh: TriMesh {
                positions,
                triangles,
                edges: Vec::new(),
            },
            from,
        }
    }
}

/// Ear clipping of one planar polygon, projected onto the plane of its dominant Newell-normal
/// axis (Eberly, "Triangulation by Ear Clipping", 2002). A face with no ear left (self-
/// intersecting or degenerate) falls back to a fan for the rest, so every face yields triangles.
fn ear_clip(positions: &[Point3<f64>], face: &[u32], out: &mut Vec<[u32; 3]>) {
    let mut normal = Vector3::zeros();
    for (k, &a) in face.iter().enumerate() {
        let p = positions[a as usize];
        let q = positions[face[(k + 1) % face.len()] as usize];
        normal += Vector3::new(
            (p.y - q.y) * (p.z + q.z),
            (p.z - q.z) * (p.x + q.x),
            (p.x - q.x) * (p.y + q.y),
        );
    }
    let axis = normal.iamax();
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    // Projecting along the dominant axis flips the orientation when that component is negative.
    let sign = normal[axis].signum();
    let flat = |i: u32| {
        let p = positions[i as usize];
        (p[u], p[v])
    };
    let cross = |a: (f64, f64), b: (f64, f64), c: (f64, f64)| {
        sign * ((b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0))
    };
    let mut ring: Vec<u32> = face.to_vec();
    while ring.len() > 3 {
        let n = ring.len();
        let ear = (0..n).find(|&k| {
            let (ia, ib, ic) = (ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]);
            let (a, b, c) = (flat(ia), flat(ib), flat(ic));
            if cross(a, b, c) <= 0.0 {
                return false;
            }
            ring.iter().all(|&j| {
                if j == ia || j == ib || j == ic {
                    return true;
                }
                let p = flat(j);
                !(cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0)
            })
        });
        match ear {
            Some(k) => {
                out.push([ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]]);
                ring.remove(k);
            }
            None => break,
        }
    }
    for w in ring[1..].windows(2) {
        out.push([ring[0], w[0], w[1]]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sum of triangle areas equals the polygon area only if no triangle covers a notch.
    fn area(m: &TriMesh) -> f64 {
        m.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| m.positions[i as usize]);
                0.5 * (b - a).cross(&(c - a)).norm()
            })
            .sum()
    }

    #[test]
    fn t_handle_caps_are_clipped_not_fanned() {
        let poly = massprops::shapes::t_handle().build();
        let m = TriMesh::from_poly(&poly);
        let d = massprops::diagnostics::diagnose(&poly);
        assert!((area(&m) - d.surface_area).abs() < 1e-12 * d.surface_area.max(1.0));
        // 8 sides + 2 octagon caps of 6 triangles each.
        assert_eq!(m.triangles.len(), 8 * 2 + 2 * 6);
        // Each triangle keeps the face's outward winding: the signed volume is positive.
        let vol: f64 = m
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| m.positions[i as usize].coords);
                a.dot(&b.cross(&c)) / 6.0
            })
            .sum();
        let exact = massprops::mass_properties(&poly, 1.0).expect("closed").mass;
        assert!((vol - exact).abs() < 1e-12);
        assert_eq!(m.edges.len(), d.edges);
    }

    /// A torus of 1.6 M triangles drawn within a budget of 200 000: the copy has at most that
    /// many triangles but keeps the shape (each vertex within a cell of the true surface) and
    /// its enclosed volume (the closed form 2π²Rr², to 2 %).
    #[test]
    fn a_mesh_over_the_drawing_budget_is_drawn_simplified_close_to_its_surface() {
        let (big_r, r) = (1.0, 0.3);
        let poly = massprops::shapes::torus(big_r, r, 1600, 500)
            .triangulated()
            .build();
        let mesh = TriMesh::from_poly(&poly);
        assert!(
            Drawn::of(&mesh, mesh.triangles.len()).is_none(),
            "within budget"
        );
        let drawn = Drawn::of(&mesh, 200_000).expect("over budget");
        let t = drawn.mesh.triangles.len();
        assert!((100_000..=200_000).contains(&t), "{t}");
        assert_eq!(drawn.from.len(), t);
        for p in &drawn.mesh.positions {
            let ring = Vector3::new(p.x, p.y, 0.0).normalize() * big_r;
            let off = ((p.coords - ring).norm() - r).abs();
            assert!(off < 0.01, "{off}");
        }
        let volume: f64 = drawn
            .mesh
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| drawn.mesh.positions[i as usize].coords);
                a.dot(&b.cross(&c)) / 6.0
            })
            .sum();
        let exact = 2.0 * std::f64::consts::PI.powi(2) * big_r * r * r;
        assert!((volume / exact - 1.0).abs() < 0.02, "{volume} vs {exact}");
    }

    #[test]
    fn bounding_sphere_of_a_cube() {
        let m = TriMesh::from_poly(&massprops::shapes::cube().build());
        let (c, r) = m.bounding_sphere();
        assert!(c.coords.norm() < 1e-15);
        assert!((r - 0.75f64.sqrt()).abs() < 1e-15);
    }
}
