//! The render and picking mesh: a [`massprops::PolyMesh`] split into triangles, plus the polygon
//! edges for the wireframe overlay. Plain f64 data in the mesh's own coordinates; the 3D view
//! converts it to GPU buffers and `picking` indexes it.

use std::collections::HashSet;

use massprops::PolyMesh;
use nalgebra::{Point3, Vector3};

/// Triangles and polygon edges of a mesh, in the mesh's own coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct TriMesh {
    /// Vertex positions (as in the source mesh).
    pub positions: Vec<Point3<f64>>,
    /// Triangles, counter-clockwise seen from outside like the source faces.
    pub triangles: Vec<[u32; 3]>,
    /// The source polygons' edges, each once (triangulation diagonals excluded).
    pub edges: Vec<[u32; 2]>,
}

impl TriMesh {
    /// Triangulates every face of `mesh` (ear clipping, so non-convex planar faces such as the
    /// T-handle's caps come out right; a fan would cover the notches).
    pub fn from_poly(mesh: &PolyMesh) -> Self {
        let positions = mesh.positions().to_vec();
        let mut triangles = Vec::with_capacity(mesh.triangle_count());
        let mut edges = HashSet::new();
        for face in mesh.faces() {
            for (k, &a) in face.iter().enumerate() {
                let b = face[(k + 1) % face.len()];
                edges.insert([a.min(b), a.max(b)]);
            }
            if face.len() == 3 {
                triangles.push([face[0], face[1], face[2]]);
            } else {
                ear_clip(&positions, face, &mut triangles);
            }
        }
        let mut edges: Vec<[u32; 2]> = edges.into_iter().collect();
        edges.sort_unstable();
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

    #[test]
    fn bounding_sphere_of_a_cube() {
        let m = TriMesh::from_poly(&massprops::shapes::cube().build());
        let (c, r) = m.bounding_sphere();
        assert!(c.coords.norm() < 1e-15);
        assert!((r - 0.75f64.sqrt()).abs() < 1e-15);
    }
}
