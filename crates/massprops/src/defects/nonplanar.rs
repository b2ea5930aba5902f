//! Non-planar polygons: a polygon whose corners leave its plane has no one surface, and each
//! triangulation of it bounds a different volume (and has a different area). The volume method
//! integrates the polygon projected onto its best-fit plane (Newell), which lies between the
//! triangulations; how far apart the fans from each corner lie bounds how much the result
//! depends on that choice.

use nalgebra::{Point3, Vector3};

use super::fan_volume;
use crate::PolyMesh;
use crate::diagnostics::face_shape;

/// The most fans tried per polygon (evenly spread corners for larger polygons).
const MAX_FANS: usize = 32;

/// The sum over non-planar faces of the range (largest − smallest) of the fan volumes (or fan
/// areas, when `volume` is false): how much the result may move with the triangulation.
pub(crate) fn spread(mesh: &PolyMesh, reference: Point3<f64>, volume: bool) -> f64 {
    let mut corners = Vec::new();
    let mut total = 0.0;
    for f in 0..mesh.face_count() {
        let face = mesh.face(f);
        if face.len() <= 3 || !face_shape(mesh, f, &mut corners).2 {
            continue;
        }
        let n = face.len();
        let step = n.div_ceil(MAX_FANS);
        let at = |i: u32| mesh.positions()[i as usize] - reference;
        let measures = (0..n).step_by(step).map(|apex| {
            if volume {
                fan_volume(face, apex, at)
            } else {
                fan_area(face, apex, at)
            }
        });
        let (lo, hi) = measures.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), m| {
            (lo.min(m), hi.max(m))
        });
        total += hi - lo;
    }
    total
}

fn fan_area(face: &[u32], apex: usize, at: impl Fn(u32) -> Vector3<f64>) -> f64 {
    let n = face.len();
    let a = at(face[apex]);
    (1..n - 1)
        .map(|k| {
            let b = at(face[(apex + k) % n]);
            let c = at(face[(apex + k + 1) % n]);
            0.5 * (b - a).cross(&(c - a)).norm()
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit square in z = 0 with one corner lifted to height h: the two fans differ by the
    /// tetrahedron between the two diagonals' triangles, of volume h/6.
    #[test]
    fn a_lifted_corner_gives_the_tetrahedron_between_the_fans() {
        let h = 0.01;
        let p = |x, y, z| Point3::new(x, y, z);
        let mesh = PolyMesh::new(
            vec![p(0., 0., 0.), p(1., 0., 0.), p(1., 1., h), p(0., 1., 0.)],
            &[vec![0, 1, 2, 3]],
        )
        .expect("valid");
        let s = spread(&mesh, Point3::new(0.3, -0.2, 5.0), true);
        assert!((s - h / 6.0).abs() < 1e-15, "{s}");
    }
}
