//! Helpers shared by the integration tests: tolerances, closed forms written out here (never
//! taken from the crate), and an independent signed-tetrahedron integrator.
#![allow(dead_code)]

use massprops::PolyMesh;
use nalgebra::{Matrix3, Point2, Point3, Vector3};

/// |a − b| / |b| (absolute when b is zero).
pub fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        (a - b).abs() / b.abs()
    }
}

/// Largest entry of |a − b| over the largest entry of |b|.
pub fn mat_rel(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).amax() / b.amax()
}

/// Asserts two tensors agree to `tol` relative to the larger's largest entry.
#[track_caller]
pub fn assert_mat(a: &Matrix3<f64>, b: &Matrix3<f64>, tol: f64, what: &str) {
    let r = mat_rel(a, b);
    assert!(
        r <= tol,
        "{what}: relative difference {r:e} > {tol:e}\n got {a}\n want {b}"
    );
}

/// Asserts two scalars agree to `tol` relative.
#[track_caller]
pub fn assert_rel(a: f64, b: f64, tol: f64, what: &str) {
    let r = rel(a, b);
    assert!(
        r <= tol,
        "{what}: {a:e} vs {b:e}, relative difference {r:e} > {tol:e}"
    );
}

/// Asserts two points agree to `tol` times `scale`.
#[track_caller]
pub fn assert_point(a: &Point3<f64>, b: &Point3<f64>, scale: f64, tol: f64, what: &str) {
    let d = (a - b).amax();
    assert!(
        d <= tol * scale,
        "{what}: {a} vs {b}, |Δ| = {d:e} > {tol:e} × {scale:e}"
    );
}

/// Inertia tensor about the centre of a solid box of mass `m` and edges a, b, c along x, y, z.
pub fn box_tensor(m: f64, a: f64, b: f64, c: f64) -> Matrix3<f64> {
    Matrix3::from_diagonal(&Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b)) * (m / 12.0)
}

/// What a point mass `m` at offset `d` adds to the inertia about the origin of `d`
/// (tensor convention: diagonal m(|d|² − dᵢ²), off-diagonal −m dᵢ dⱼ), written entry by entry.
pub fn steiner(m: f64, d: &Vector3<f64>) -> Matrix3<f64> {
    let (x, y, z) = (d.x, d.y, d.z);
    Matrix3::new(
        m * (y * y + z * z),
        -m * x * y,
        -m * x * z,
        -m * x * y,
        m * (x * x + z * z),
        -m * y * z,
        -m * x * z,
        -m * y * z,
        m * (x * x + y * y),
    )
}

/// Inertia tensor (unit density) from the covariance C = ∫r rᵀ dV: I = tr(C)·E − C.
pub fn inertia_from_covariance(c: &Matrix3<f64>) -> Matrix3<f64> {
    Matrix3::identity() * c.trace() - c
}

/// Unit-density volume, centre of mass and central inertia of a closed mesh by an independent
/// method: fan-triangulate every face, and sum signed tetrahedra (o, p₀, p₁, p₂) with o the mean
/// of the positions. Each tetrahedron's covariance is det(A)·A·C₀·Aᵀ, A = [p₀ p₁ p₂] (relative
/// to o), C₀ = 1/120·[[2,1,1],[1,2,1],[1,1,2]] being that of the canonical tetrahedron
/// (0, e₁, e₂, e₃), whose ∫x² = 1/60 and ∫xy = 1/120.
pub fn tetra_sum(mesh: &PolyMesh) -> (f64, Point3<f64>, Matrix3<f64>) {
    let n = mesh.positions().len() as f64;
    let o = Point3::from(
        mesh.positions()
            .iter()
            .map(|p| p.coords)
            .sum::<Vector3<f64>>()
            / n,
    );
    let c0 = Matrix3::new(2.0, 1.0, 1.0, 1.0, 2.0, 1.0, 1.0, 1.0, 2.0) / 120.0;
    let mut volume = 0.0;
    let mut first = Vector3::zeros();
    let mut cov = Matrix3::zeros();
    for f in 0..mesh.face_count() {
        let pts: Vec<Vector3<f64>> = mesh.face_points(f).map(|p| p - o).collect();
        for w in pts[1..].windows(2) {
            let a = Matrix3::from_columns(&[pts[0], w[0], w[1]]);
            let det = a.determinant();
            volume += det / 6.0;
            first += (pts[0] + w[0] + w[1]) * (det / 24.0);
            cov += a * c0 * a.transpose() * det;
        }
    }
    let com = first / volume;
    let about_o = inertia_from_covariance(&cov);
    let central = about_o - steiner(volume, &com);
    (volume, o + com, central)
}

/// Unit-density inertia tensor about the origin of a closed mesh, integrated about the origin
/// itself (no shift theorem): signed tetrahedra (0, p₀, p₁, p₂) over a fan triangulation, each
/// of covariance det(A)·A·C₀·Aᵀ (see [`tetra_sum`]), and I = tr(C)·E − C.
pub fn inertia_about_origin(mesh: &PolyMesh) -> Matrix3<f64> {
    let c0 = Matrix3::new(2.0, 1.0, 1.0, 1.0, 2.0, 1.0, 1.0, 1.0, 2.0) / 120.0;
    let mut cov = Matrix3::zeros();
    for f in 0..mesh.face_count() {
        let pts: Vec<Vector3<f64>> = mesh.face_points(f).map(|p| p.coords).collect();
        for w in pts[1..].windows(2) {
            let a = Matrix3::from_columns(&[pts[0], w[0], w[1]]);
            cov += a * c0 * a.transpose() * a.determinant();
        }
    }
    inertia_from_covariance(&cov)
}

/// Area, centroid and second area moments ∫x², ∫y², ∫xy (about the origin) of a simple
/// polygon given counter-clockwise, by the shoelace-type sums over its edges.
pub struct PolygonMoments {
    /// Area.
    pub area: f64,
    /// Centroid.
    pub centroid: Point2<f64>,
    /// ∫x² dA about the origin.
    pub xx: f64,
    /// ∫y² dA about the origin.
    pub yy: f64,
    /// ∫xy dA about the origin.
    pub xy: f64,
}

/// See [`PolygonMoments`].
pub fn polygon_moments(outline: &[Point2<f64>]) -> PolygonMoments {
    let (mut a, mut cx, mut cy, mut xx, mut yy, mut xy) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for i in 0..outline.len() {
        let p = outline[i];
        let q = outline[(i + 1) % outline.len()];
        let cross = p.x * q.y - q.x * p.y;
        a += cross;
        cx += (p.x + q.x) * cross;
        cy += (p.y + q.y) * cross;
        xx += (p.x * p.x + p.x * q.x + q.x * q.x) * cross;
        yy += (p.y * p.y + p.y * q.y + q.y * q.y) * cross;
        xy += (p.x * q.y + 2.0 * p.x * p.y + 2.0 * q.x * q.y + q.x * p.y) * cross;
    }
    let area = a / 2.0;
    PolygonMoments {
        area,
        centroid: Point2::new(cx / (6.0 * area), cy / (6.0 * area)),
        xx: xx / 12.0,
        yy: yy / 12.0,
        xy: xy / 24.0,
    }
}

/// Volume, centre of mass and inertia about the origin (unit density) of the right prism of
/// `outline` from z0 to z1, from the polygon's moments:
/// ∫x²dV = h∫x²dA, ∫y²dV = h∫y²dA, ∫xy dV = h∫xy dA, ∫z²dV = A(z1³ − z0³)/3,
/// ∫xz dV = A·cx·(z1² − z0²)/2, ∫yz dV = A·cy·(z1² − z0²)/2.
pub fn prism_closed_form(
    outline: &[Point2<f64>],
    z0: f64,
    z1: f64,
) -> (f64, Point3<f64>, Matrix3<f64>) {
    let pm = polygon_moments(outline);
    let h = z1 - z0;
    let zz = pm.area * (z1.powi(3) - z0.powi(3)) / 3.0;
    let z1st = (z1 * z1 - z0 * z0) / 2.0;
    let xz = pm.area * pm.centroid.x * z1st;
    let yz = pm.area * pm.centroid.y * z1st;
    let cov = Matrix3::new(
        h * pm.xx,
        h * pm.xy,
        xz,
        h * pm.xy,
        h * pm.yy,
        yz,
        xz,
        yz,
        zz,
    );
    let com = Point3::new(pm.centroid.x, pm.centroid.y, (z0 + z1) / 2.0);
    (pm.area * h, com, inertia_from_covariance(&cov))
}

/// A tetrahedron as a closed, outward-wound mesh (whatever the order of the corners).
pub fn tetrahedron(p: [Point3<f64>; 4]) -> PolyMesh {
    let positive = (p[1] - p[0]).cross(&(p[2] - p[0])).dot(&(p[3] - p[0])) > 0.0;
    let faces: [[usize; 3]; 4] = if positive {
        [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    } else {
        [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
    };
    PolyMesh::new(p.to_vec(), &faces).expect("a tetrahedron is a valid mesh")
}

/// A ten-pointed star (non-convex), counter-clockwise, centred on `c`.
pub fn star(c: Point2<f64>, outer: f64, inner: f64, points: usize) -> Vec<Point2<f64>> {
    (0..2 * points)
        .map(|i| {
            let t = std::f64::consts::PI * i as f64 / points as f64 + 0.1;
            let r = if i % 2 == 0 { outer } else { inner };
            Point2::new(c.x + r * t.cos(), c.y + r * t.sin())
        })
        .collect()
}

/// A comb (an "E" with `teeth` teeth pointing +y), counter-clockwise; origin at its lower left.
pub fn comb(teeth: usize, tooth_w: f64, gap: f64, spine: f64, tooth_h: f64) -> Vec<Point2<f64>> {
    let width = teeth as f64 * tooth_w + (teeth - 1) as f64 * gap;
    let mut v = vec![Point2::new(0.0, 0.0), Point2::new(width, 0.0)];
    // Walk back along the top from right to left, up and down each tooth.
    for k in (0..teeth).rev() {
        let x0 = k as f64 * (tooth_w + gap);
        let x1 = x0 + tooth_w;
        if k + 1 < teeth {
            v.push(Point2::new(x1, spine));
        }
        v.push(Point2::new(x1, spine + tooth_h));
        v.push(Point2::new(x0, spine + tooth_h));
        if k > 0 {
            v.push(Point2::new(x0, spine));
        }
    }
    v
}
