//! The rendering boundary: the only place where the model's f64/nalgebra values become f32 —
//! three-d's GPU types and egui's screen coordinates. Mesh positions are shifted to the mesh's
//! bounding-box centre before the cast (and the shift folded back into the f64 model matrix), so
//! a mesh far from its own origin keeps its f32 precision.

use nalgebra::{Matrix4, Point2, Point3, Translation3, Vector2};
use three_d::{CpuMesh, Indices, Mat4, Positions, Srgba, Vec3};

use super::camera::OrbitCamera;
use crate::lab::geometry::TriMesh;

/// f64 point → three-d vector.
pub fn vec3(p: &Point3<f64>) -> Vec3 {
    Vec3::new(p.x as f32, p.y as f32, p.z as f32)
}

/// f64 matrix → three-d matrix (both column-major).
pub fn mat4(m: &Matrix4<f64>) -> Mat4 {
    Mat4::from(<[[f32; 4]; 4]>::from(m.cast::<f32>()))
}

/// Screen pixel of the view (f64, origin at the view's top-left) → egui position.
pub fn screen(p: &Point2<f64>, view_min: egui::Pos2) -> egui::Pos2 {
    egui::pos2(view_min.x + p.x as f32, view_min.y + p.y as f32)
}

/// egui position → view pixel (f64, origin at the view's top-left).
pub fn view_pixel(p: egui::Pos2, view_min: egui::Pos2) -> Point2<f64> {
    Point2::new(f64::from(p.x - view_min.x), f64::from(p.y - view_min.y))
}

/// egui size → f64 size.
pub fn size(v: egui::Vec2) -> Vector2<f64> {
    Vector2::new(f64::from(v.x), f64::from(v.y))
}

/// Above this many triangles a single-colour mesh is drawn with shared, smooth-shaded vertices
/// (a scan: triangles far smaller than a pixel's worth of shading detail), below it flat-shaded
/// with unshared vertices (a model: crisp edges).
pub const SMOOTH_ABOVE: usize = 100_000;

/// The body's GPU mesh in coordinates relative to `origin`. With `colors` (one per triangle;
/// `None` leaves the triangle out), each triangle gets its own colour, flat-shaded; without,
/// see [`SMOOTH_ABOVE`].
pub fn cpu_mesh(mesh: &TriMesh, origin: &Point3<f64>, colors: &[Option<[u8; 3]>]) -> CpuMesh {
    if colors.is_empty() && mesh.triangles.len() > SMOOTH_ABOVE {
        smooth_mesh(mesh, origin)
    } else {
        flat_mesh(mesh, origin, colors)
    }
}

/// Shared vertices with area-weighted vertex normals and an index buffer: one GPU vertex per
/// mesh vertex (a closed triangle mesh has about half as many vertices as triangles, so a sixth
/// of the flat mesh's vertices to shade and store).
fn smooth_mesh(mesh: &TriMesh, origin: &Point3<f64>) -> CpuMesh {
    let mut sums = vec![nalgebra::Vector3::<f64>::zeros(); mesh.positions.len()];
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        // The cross product is twice the area along the normal: larger faces weigh more.
        let n = (b - a).cross(&(c - a));
        for &i in t {
            sums[i as usize] += n;
        }
    }
    let normals = sums
        .iter()
        .map(|n| {
            let n = n.try_normalize(0.0).unwrap_or_else(nalgebra::Vector3::z);
            Vec3::new(n.x as f32, n.y as f32, n.z as f32)
        })
        .collect();
    let positions = mesh
        .positions
        .iter()
        .map(|p| {
            let p = p - origin;
            Vec3::new(p.x as f32, p.y as f32, p.z as f32)
        })
        .collect();
    CpuMesh {
        positions: Positions::F32(positions),
        indices: Indices::U32(mesh.triangles.iter().flatten().copied().collect()),
        normals: Some(normals),
        ..Default::default()
    }
}

/// Flat shading: vertices unshared so every triangle has its face normal (the T-handle's edges
/// stay crisp).
fn flat_mesh(mesh: &TriMesh, origin: &Point3<f64>, colors: &[Option<[u8; 3]>]) -> CpuMesh {
    let mut positions = Vec::with_capacity(mesh.triangles.len() * 3);
    let mut normals = Vec::with_capacity(mesh.triangles.len() * 3);
    let mut vertex_colors = Vec::new();
    for (k, t) in mesh.triangles.iter().enumerate() {
        if !colors.is_empty() {
            let Some([r, g, b]) = colors.get(k).copied().flatten() else {
                continue;
            };
            vertex_colors.extend([Srgba::new_opaque(r, g, b); 3]);
        }
        let [a, b, c] = t.map(|i| mesh.positions[i as usize] - origin);
        let n = (b - a).cross(&(c - a));
        let n = n.try_normalize(0.0).unwrap_or_else(nalgebra::Vector3::z);
        for p in [a, b, c] {
            positions.push(Vec3::new(p.x as f32, p.y as f32, p.z as f32));
            normals.push(Vec3::new(n.x as f32, n.y as f32, n.z as f32));
        }
    }
    CpuMesh {
        positions: Positions::F32(positions),
        indices: Indices::None,
        normals: Some(normals),
        colors: (!colors.is_empty()).then_some(vertex_colors),
        ..Default::default()
    }
}

/// Everything a frame of the 3D view needs, already in f32.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameParams {
    /// Eye position.
    pub eye: Vec3,
    /// Look-at target.
    pub target: Vec3,
    /// Up vector.
    pub up: Vec3,
    /// Vertical field of view (degrees).
    pub fov_y_degrees: f32,
    /// Near clip distance.
    pub near: f32,
    /// Far clip distance.
    pub far: f32,
    /// Mesh (relative to its upload origin) → world.
    pub model: Mat4,
    /// Body colour (linear RGB 0–255).
    pub color: [u8; 3],
    /// Compared copies drawn translucent: their mesh → world matrices and colours (RGBA).
    pub ghosts: Vec<(Mat4, [u8; 4])>,
}

impl FrameParams {
    /// Camera values plus `model`, the f64 mesh → world matrix, composed with the translation to
    /// the upload `origin` before the cast.
    pub fn new(camera: &OrbitCamera, model: &Matrix4<f64>, origin: &Point3<f64>) -> Self {
        let (near, far) = camera.clip();
        let full = model * Translation3::from(origin.coords).to_homogeneous();
        Self {
            eye: vec3(&camera.eye()),
            target: vec3(&camera.target),
            up: vec3(&Point3::from(camera.up())),
            fov_y_degrees: camera.fov_y.to_degrees() as f32,
            near: near as f32,
            far: far as f32,
            model: mat4(&full),
            color: [200, 160, 90],
            ghosts: Vec::new(),
        }
    }

    /// Adds a translucent copy of the mesh at `model` (mesh → world, like [`FrameParams::new`]'s).
    pub fn add_ghost(&mut self, model: &Matrix4<f64>, origin: &Point3<f64>, color: [u8; 4]) {
        let full = model * Translation3::from(origin.coords).to_homogeneous();
        self.ghosts.push((mat4(&full), color));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use three_d::InnerSpace;

    #[test]
    fn matrices_keep_column_major_order_and_origin_shift() {
        let m = Matrix4::new_translation(&nalgebra::Vector3::new(1.0, 2.0, 3.0));
        let t = mat4(&m);
        assert_eq!((t.w.x, t.w.y, t.w.z), (1.0, 2.0, 3.0));
        let p = FrameParams::new(&OrbitCamera::default(), &m, &Point3::new(10.0, 0.0, 0.0));
        assert_eq!((p.model.w.x, p.model.w.y), (11.0, 2.0));
    }

    #[test]
    fn a_scan_is_drawn_with_one_shared_vertex_per_mesh_vertex_and_outward_normals() {
        let mesh = TriMesh::from_poly(
            &massprops::shapes::torus(1.0, 0.3, 400, 200)
                .triangulated()
                .build(),
        );
        assert!(mesh.triangles.len() > SMOOTH_ABOVE);
        let cpu = cpu_mesh(&mesh, &Point3::origin(), &[]);
        let Positions::F32(ps) = &cpu.positions else {
            panic!("f32 positions")
        };
        assert_eq!(ps.len(), mesh.positions.len());
        let Indices::U32(indices) = &cpu.indices else {
            panic!("u32 indices")
        };
        assert_eq!(indices.len(), 3 * mesh.triangles.len());
        // On a torus the outward normal at a point is its offset from the tube's centre circle.
        let normals = cpu.normals.expect("normals");
        for (p, n) in ps.iter().zip(&normals) {
            let ring = Vec3::new(p.x, p.y, 0.0).normalize();
            let outward = (*p - ring).normalize();
            assert!(n.dot(outward) > 0.999, "{n:?} at {p:?}");
        }
    }

    #[test]
    fn flat_mesh_has_unit_face_normals() {
        let mesh = TriMesh::from_poly(&massprops::shapes::cube().build());
        let cpu = cpu_mesh(&mesh, &Point3::new(0.5, 0.0, 0.0), &[]);
        let normals = cpu.normals.expect("normals");
        assert_eq!(normals.len(), 36);
        assert!(normals.iter().all(|n| (n.magnitude() - 1.0).abs() < 1e-6));
        let Positions::F32(ps) = cpu.positions else {
            panic!("f32 positions")
        };
        assert!(ps.iter().all(|p| p.x <= 0.0 && p.x >= -1.0));
    }
}
