//! The orbit camera, in f64 world coordinates: orbit, pan, zoom, frame the body, and the pixel ↔
//! ray mapping that picking and the overlays use. The 3D renderer receives the same eye, target and
//! projection (converted in `view3d::convert`), so what is drawn and what is picked agree.

use nalgebra::{Isometry3, Matrix4, Perspective3, Point2, Point3, Vector2, Vector3};

use crate::lab::picking::Ray;

/// Radians of orbit per pixel dragged.
const ORBIT_RATE: f64 = 0.008;
/// Pitch stays short of the poles so the `up` vector never aligns with the view direction.
const PITCH_LIMIT: f64 = 1.54;

/// A camera orbiting a target point, y up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrbitCamera {
    /// The point looked at and orbited around.
    pub target: Point3<f64>,
    /// Angle about world y (rad); 0 looks along −z.
    pub yaw: f64,
    /// Elevation (rad), within ±`PITCH_LIMIT`.
    pub pitch: f64,
    /// Eye-to-target distance.
    pub distance: f64,
    /// Vertical field of view (rad).
    pub fov_y: f64,
}

impl Default for OrbitCamera {
    fn default() -> Self {
        Self {
            target: Point3::origin(),
            yaw: 0.6,
            pitch: 0.35,
            distance: 3.0,
            fov_y: 45f64.to_radians(),
        }
    }
}

impl OrbitCamera {
    /// The eye position.
    pub fn eye(&self) -> Point3<f64> {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        self.target + Vector3::new(cp * sy, sp, cp * cy) * self.distance
    }

    /// World up for the view.
    pub fn up(&self) -> Vector3<f64> {
        Vector3::y()
    }

    /// Unit vector from the eye towards the target.
    pub fn forward(&self) -> Vector3<f64> {
        (self.target - self.eye()).normalize()
    }

    /// Unit vector to the screen's right, horizontal in the world.
    pub fn right(&self) -> Vector3<f64> {
        self.forward().cross(&self.up()).normalize()
    }

    /// Turns the view by a pointer drag of `(dx, dy)` pixels.
    pub fn orbit(&mut self, dx: f64, dy: f64) {
        if dx.is_finite() && dy.is_finite() {
            self.yaw -= dx * ORBIT_RATE;
            self.pitch = (self.pitch + dy * ORBIT_RATE).clamp(-PITCH_LIMIT, PITCH_LIMIT);
        }
    }

    /// Moves the target so the scene follows a drag of `(dx, dy)` pixels in a view `height` pixels
    /// tall (the point under the pointer at the target's depth stays under it).
    pub fn pan(&mut self, dx: f64, dy: f64, height: f64) {
        if !(dx.is_finite() && dy.is_finite() && height > 0.0) {
            return;
        }
        let per_pixel = 2.0 * self.distance * (self.fov_y / 2.0).tan() / height;
        let right = self.right();
        let up = right.cross(&self.forward());
        self.target += (-right * dx + up * dy) * per_pixel;
    }

    /// Multiplies the distance by `factor` (> 1 moves away), within sane bounds.
    pub fn zoom(&mut self, factor: f64) {
        if factor.is_finite() && factor > 0.0 {
            self.distance = (self.distance * factor).clamp(1e-6, 1e9);
        }
    }

    /// Centres the view on a sphere and backs off until it fits the vertical field of view.
    pub fn frame(&mut self, center: Point3<f64>, radius: f64) {
        if center.coords.iter().all(|x| x.is_finite()) && radius.is_finite() && radius > 0.0 {
            self.target = center;
            self.distance = 1.15 * radius / (self.fov_y / 2.0).sin();
        }
    }

    /// Near and far clip distances: a fixed ratio around the target keeps depth precision.
    pub fn clip(&self) -> (f64, f64) {
        (self.distance * 0.01, self.distance * 100.0)
    }

    /// World → camera.
    pub fn view(&self) -> Isometry3<f64> {
        Isometry3::look_at_rh(&self.eye(), &self.target, &self.up())
    }

    /// Camera → clip space for a viewport of the given aspect (width / height).
    pub fn projection(&self, aspect: f64) -> Perspective3<f64> {
        let (near, far) = self.clip();
        Perspective3::new(aspect.max(1e-6), self.fov_y, near, far)
    }

    /// World → clip space.
    pub fn view_projection(&self, size: Vector2<f64>) -> Matrix4<f64> {
        self.projection(size.x / size.y).as_matrix() * self.view().to_homogeneous()
    }

    /// The ray from the eye through `pixel` (origin top-left, y down) of a view of `size`.
    pub fn ray(&self, pixel: Point2<f64>, size: Vector2<f64>) -> Ray {
        let ndc_x = 2.0 * pixel.x / size.x - 1.0;
        let ndc_y = 1.0 - 2.0 * pixel.y / size.y;
        let half_h = (self.fov_y / 2.0).tan();
        let half_w = half_h * size.x / size.y;
        let forward = self.forward();
        let right = forward.cross(&self.up()).normalize();
        let up = right.cross(&forward);
        Ray {
            origin: self.eye(),
            dir: (forward + right * (ndc_x * half_w) + up * (ndc_y * half_h)).normalize(),
        }
    }

    /// The pixel (origin top-left) where a world point appears, `None` behind the eye.
    pub fn project(&self, world: &Point3<f64>, size: Vector2<f64>) -> Option<Point2<f64>> {
        let clip = self.view_projection(size) * world.to_homogeneous();
        if clip.w <= 1e-12 {
            return None;
        }
        let (x, y) = (clip.x / clip.w, clip.y / clip.w);
        Some(Point2::new(
            (x + 1.0) * 0.5 * size.x,
            (1.0 - y) * 0.5 * size.y,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SIZE: Vector2<f64> = Vector2::new(800.0, 600.0);

    #[test]
    fn centre_ray_points_at_the_target_and_projection_inverts_rays() {
        let cam = OrbitCamera::default();
        let ray = cam.ray(Point2::new(400.0, 300.0), SIZE);
        assert!((ray.dir - cam.forward()).norm() < 1e-12);
        for (px, py) in [(10.0, 20.0), (790.0, 580.0), (400.0, 1.0)] {
            let ray = cam.ray(Point2::new(px, py), SIZE);
            let p = cam.project(&ray.at(2.5), SIZE).expect("in front");
            assert!((p - Point2::new(px, py)).norm() < 1e-9, "{p} vs {px},{py}");
        }
        let behind = cam.eye() - cam.forward();
        assert_eq!(cam.project(&behind, SIZE), None);
    }

    #[test]
    fn framing_fits_the_sphere_and_orbit_keeps_distance() {
        let mut cam = OrbitCamera::default();
        cam.frame(Point3::new(1.0, 2.0, 3.0), 0.5);
        assert_eq!(cam.target, Point3::new(1.0, 2.0, 3.0));
        // The sphere's silhouette subtends less than the vertical field of view.
        assert!((0.5 / cam.distance).asin() < cam.fov_y / 2.0);
        let d = cam.distance;
        cam.orbit(120.0, -4000.0);
        assert!(((cam.eye() - cam.target).norm() - d).abs() < 1e-12);
        assert!(cam.pitch >= -PITCH_LIMIT);
        cam.orbit(f64::NAN, 1.0);
        cam.zoom(f64::NAN);
        cam.frame(Point3::origin(), -1.0);
        assert!(cam.eye().coords.iter().all(|x| x.is_finite()));
    }

    #[test]
    fn pan_keeps_the_target_point_under_the_pointer() {
        let mut cam = OrbitCamera::default();
        let before = cam.project(&cam.target, SIZE).expect("visible");
        let world = cam.target;
        cam.pan(30.0, -12.0, SIZE.y);
        let after = cam.project(&world, SIZE).expect("visible");
        assert!((after - before - Vector2::new(30.0, -12.0)).norm() < 1e-9);
        cam.zoom(2.0);
        assert!((cam.distance - 6.0).abs() < 1e-12);
    }
}
