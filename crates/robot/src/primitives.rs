//! The primitives of robot descriptions in closed form, at unit density in their own frame
//! (centred, axis along z): volume, and the inertia tensor about the centre (for mass m = ρV):
//! box of half-sides a, b, c: Ixx = m(b² + c²)/3; sphere of radius r: 2mr²/5; ellipsoid:
//! Ixx = m(b² + c²)/5; cylinder of radius r, half-length h: Izz = mr²/2, Ixx = m(r²/4 + h²/3);
//! capsule: that cylinder plus two hemispheres of mass m_s/2 each, whose own moment about a
//! diameter of the flat face is 2(m_s/2)r²/5 and whose centre lies 3r/8 from it, so
//! Ixx = m_c(r²/4 + h²/3) + m_s(2r²/5 + h² + 3hr/4), Izz = m_c r²/2 + 2m_s r²/5
//! (Steiner's theorem; e.g. the tables of Goldstein, Classical Mechanics, and of MuJoCo's
//! `mjCGeom::SetInertia`).
//!
//! Also what the impossibility bound and the hull test need of a primitive, exactly or as an
//! upper bound that keeps them proofs: its support function h(n) = max over the solid of n·x,
//! and the farthest its points lie from a line; and, for a bounding ellipsoid, points whose
//! convex hull contains it.

use std::f64::consts::PI;

use nalgebra::{Matrix3, Point3, Vector3};

use massprops::MassProperties;

use crate::model::Shape;

/// A primitive's solid at density 1 (mass = volume), about its centre, in its own frame;
/// `None` for a mesh or an unsupported shape.
pub fn unit_properties(shape: &Shape) -> Option<MassProperties> {
    let (volume, moments) = match *shape {
        Shape::Box { half_extents: h } => {
            let v = 8.0 * h.x * h.y * h.z;
            let (x, y, z) = (h.x * h.x, h.y * h.y, h.z * h.z);
            (v, Vector3::new(y + z, x + z, x + y) * (v / 3.0))
        }
        Shape::Sphere { radius: r } => {
            let v = 4.0 / 3.0 * PI * r.powi(3);
            (v, Vector3::repeat(0.4 * v * r * r))
        }
        Shape::Ellipsoid { radii: a } => {
            let v = 4.0 / 3.0 * PI * a.x * a.y * a.z;
            let (x, y, z) = (a.x * a.x, a.y * a.y, a.z * a.z);
            (v, Vector3::new(y + z, x + z, x + y) * (v / 5.0))
        }
        Shape::Cylinder {
            radius: r,
            half_length: h,
        } => {
            let v = 2.0 * PI * r * r * h;
            let side = v * (r * r / 4.0 + h * h / 3.0);
            (v, Vector3::new(side, side, v * r * r / 2.0))
        }
        Shape::Capsule {
            radius: r,
            half_length: h,
        } => {
            let vc = 2.0 * PI * r * r * h;
            let vs = 4.0 / 3.0 * PI * r.powi(3);
            let side = vc * (r * r / 4.0 + h * h / 3.0) + vs * (0.4 * r * r + h * h + 0.75 * h * r);
            let axial = vc * r * r / 2.0 + vs * 0.4 * r * r;
            (vc + vs, Vector3::new(side, side, axial))
        }
        Shape::Mesh { .. } | Shape::MissingMesh { .. } | Shape::Unsupported { .. } => return None,
    };
    Some(MassProperties::new(
        volume,
        Point3::origin(),
        Matrix3::from_diagonal(&moments),
    ))
}

/// max over the solid of n·x, in its own frame; `None` for a mesh or an unsupported shape.
pub fn support(shape: &Shape, n: &Vector3<f64>) -> Option<f64> {
    Some(match *shape {
        Shape::Box { half_extents: h } => n.abs().dot(&h),
        Shape::Sphere { radius } => radius * n.norm(),
        Shape::Ellipsoid { radii } => n.component_mul(&radii).norm(),
        Shape::Cylinder {
            radius,
            half_length,
        } => radius * n.xy().norm() + half_length * n.z.abs(),
        Shape::Capsule {
            radius,
            half_length,
        } => radius * n.norm() + half_length * n.z.abs(),
        Shape::Mesh { .. } | Shape::MissingMesh { .. } | Shape::Unsupported { .. } => return None,
    })
}

/// An upper bound of the distance from the line through `point` along unit `direction` to the
/// farthest point of the solid (all in its own frame): exact for a box, a sphere and a capsule,
/// for a cylinder the bound below (exact when the line crosses its axis at a right angle or
/// runs along it), for an ellipsoid its centre's distance plus its largest radius. `None` for a
/// mesh or an unsupported shape.
pub fn farthest_from_line(
    shape: &Shape,
    point: &Point3<f64>,
    direction: &Vector3<f64>,
) -> Option<f64> {
    let off_line = |q: Point3<f64>| {
        let d = q - point;
        (d - direction * direction.dot(&d)).norm()
    };
    let axis_ends = |h: f64| [Point3::new(0.0, 0.0, -h), Point3::new(0.0, 0.0, h)];
    Some(match *shape {
        Shape::Box { half_extents: h } => (0..8)
            .map(|k| {
                let s = |bit: usize| if k & bit == 0 { -1.0 } else { 1.0 };
                off_line(Point3::new(s(1) * h.x, s(2) * h.y, s(4) * h.z))
            })
            .fold(0.0, f64::max),
        Shape::Sphere { radius } => off_line(Point3::origin()) + radius,
        Shape::Ellipsoid { radii } => off_line(Point3::origin()) + radii.amax(),
        Shape::Capsule {
            radius,
            half_length,
        } => {
            let [a, b] = axis_ends(half_length);
            off_line(a).max(off_line(b)) + radius
        }
        Shape::Cylinder {
            radius,
            half_length,
        } => {
            // A rim point is e + R·w, w a unit vector across the axis z. With P the projection
            // off the line, |P(e − p) + R·Pw|² ≤ |q|² + 2R·|q − z(z·q)| + R² for q = P(e − p)
            // (q·Pw = q·w, at most the part of q across the axis; |Pw| ≤ 1): exact when the
            // line crosses the axis at a right angle.
            axis_ends(half_length)
                .iter()
                .map(|&e| {
                    let d = e - point;
                    let q = d - direction * direction.dot(&d);
                    let across = (q - Vector3::z() * q.z).norm();
                    (q.norm_squared() + 2.0 * radius * across + radius * radius).sqrt()
                })
                .fold(0.0, f64::max)
        }
        Shape::Mesh { .. } | Shape::MissingMesh { .. } | Shape::Unsupported { .. } => return None,
    })
}

/// Points whose convex hull contains the primitive (its own frame); `None` for a mesh or an
/// unsupported shape. A box gives its corners. A round shape gives points on a larger sphere or
/// circle: a hull of points on a sphere of radius R whose every direction lies within angle ρ of
/// one of them contains the ball of radius R·cos ρ (each face of the hull cuts from the sphere
/// a cap with no point inside, whose angular radius is therefore at most ρ), and a regular
/// n-gon of circumradius r / cos(π/n) contains its inscribed circle of radius r.
pub fn hull_points(shape: &Shape) -> Option<Vec<Point3<f64>>> {
    Some(match *shape {
        Shape::Box { half_extents: h } => (0..8)
            .map(|k| {
                let sign = |bit: usize| if k >> bit & 1 == 0 { -1.0 } else { 1.0 };
                Point3::new(sign(0) * h.x, sign(1) * h.y, sign(2) * h.z)
            })
            .collect(),
        Shape::Sphere { radius } => covering_sphere()
            .map(|d| Point3::from(d * radius))
            .collect(),
        Shape::Ellipsoid { radii } => covering_sphere()
            .map(|d| Point3::from(d.component_mul(&radii)))
            .collect(),
        Shape::Capsule {
            radius,
            half_length,
        } => covering_sphere()
            .flat_map(|d| {
                let p = d * radius;
                [-1.0, 1.0].map(|s| Point3::new(p.x, p.y, p.z + s * half_length))
            })
            .collect(),
        Shape::Cylinder {
            radius,
            half_length,
        } => {
            let r = radius / (PI / f64::from(RING)).cos();
            (0..RING)
                .flat_map(|k| {
                    let a = 2.0 * PI * f64::from(k) / f64::from(RING);
                    [-1.0, 1.0].map(|s| Point3::new(r * a.cos(), r * a.sin(), s * half_length))
                })
                .collect()
        }
        Shape::Mesh { .. } | Shape::MissingMesh { .. } | Shape::Unsupported { .. } => return None,
    })
}

/// Corners of the polygon around a cylinder's circle.
const RING: u32 = 64;
/// Latitude bands of the points around a sphere (longitudes: twice as many).
const BANDS: u32 = 24;

/// Points on a sphere whose hull contains the unit ball: a latitude-longitude grid of step
/// δ = π/BANDS, where any direction lies within δ/2 of a grid latitude and then within δ/2
/// along it of a grid longitude, so within δ of a point; the grid's radius is 1 / cos δ.
fn covering_sphere() -> impl Iterator<Item = Vector3<f64>> {
    let step = PI / f64::from(BANDS);
    let radius = 1.0 / step.cos();
    (0..=BANDS).flat_map(move |i| {
        let latitude = -PI / 2.0 + step * f64::from(i);
        let longitudes = if i == 0 || i == BANDS { 1 } else { 2 * BANDS };
        (0..longitudes).map(move |j| {
            let longitude = step * f64::from(j);
            radius
                * Vector3::new(
                    latitude.cos() * longitude.cos(),
                    latitude.cos() * longitude.sin(),
                    latitude.sin(),
                )
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The hull of a primitive's points contains it (their support function is at least the
    /// shape's in every direction, tried on a dense spiral of directions) and is within 1 % of
    /// it. Points on the shape itself (radius factor 1) fall short between the grid's points.
    #[test]
    fn hull_points_contain_the_shape() {
        let shapes = [
            Shape::Box {
                half_extents: Vector3::new(0.1, 0.2, 0.3),
            },
            Shape::Sphere { radius: 0.3 },
            Shape::Ellipsoid {
                radii: Vector3::new(0.1, 0.2, 0.4),
            },
            Shape::Cylinder {
                radius: 0.05,
                half_length: 0.2,
            },
            Shape::Capsule {
                radius: 0.05,
                half_length: 0.2,
            },
        ];
        // A Fibonacci spiral: 20 000 directions spread evenly over the sphere.
        let n = 20_000;
        let golden = PI * (3.0 - 5f64.sqrt());
        let directions: Vec<Vector3<f64>> = (0..n)
            .map(|k| {
                let z = 1.0 - 2.0 * (f64::from(k) + 0.5) / f64::from(n);
                let r = (1.0 - z * z).sqrt();
                let a = golden * f64::from(k);
                Vector3::new(r * a.cos(), r * a.sin(), z)
            })
            .collect();
        for shape in &shapes {
            let points = hull_points(shape).expect("a primitive");
            let mut worst: f64 = 0.0;
            for d in &directions {
                let hull = points
                    .iter()
                    .map(|p| d.dot(&p.coords))
                    .fold(f64::NEG_INFINITY, f64::max);
                let exact = support(shape, d).expect("a primitive");
                assert!(hull >= exact * (1.0 - 1e-12), "{shape:?} along {d:?}");
                worst = worst.max(hull / exact);
            }
            assert!(worst < 1.01, "{shape:?}: {worst}");
        }
    }

    /// A box's tensor by the general formula of a mesh: the closed forms agree with massprops'
    /// exact integrals of a tessellation where one is exact (the box), and the curved ones with
    /// fine tessellations to their discretisation error.
    #[test]
    fn closed_forms_match_integrated_meshes() {
        let h = Vector3::new(0.3, 0.5, 0.7);
        let exact = unit_properties(&Shape::Box { half_extents: h }).expect("present");
        let mesh = massprops::shapes::cuboid(h * 2.0, Point3::origin()).build();
        let integrated = massprops::mass_properties(&mesh, 1.0).expect("present");
        assert!((exact.mass - integrated.mass).abs() < 1e-14);
        assert!((exact.inertia_com - integrated.inertia_com).amax() < 1e-14);

        // A cylinder against a 4000-sided prism: the polygon's area is (n/2π)·sin(2π/n) of
        // the circle's, so the two agree to about 4e-7.
        let (r, h) = (0.4, 0.6);
        let exact = unit_properties(&Shape::Cylinder {
            radius: r,
            half_length: h,
        })
        .expect("present");
        let prism = massprops::shapes::cylinder(r, -h, h, 4000).build();
        let fine = massprops::mass_properties(&prism, 1.0).expect("present");
        assert!((exact.mass / fine.mass - 1.0).abs() < 1e-6);
        for k in 0..3 {
            let ratio = exact.inertia_com[(k, k)] / fine.inertia_com[(k, k)];
            assert!((ratio - 1.0).abs() < 2e-6, "axis {k}: {ratio}");
        }
    }

    /// A capsule of zero half-length is a sphere; of zero radius nothing; the sum of its parts
    /// (cylinder + sphere moved apart) by Steiner's theorem done numerically.
    #[test]
    fn capsule_is_a_cylinder_and_two_hemispheres() {
        let r = 0.2;
        let sphere = unit_properties(&Shape::Sphere { radius: r }).expect("present");
        let tiny = unit_properties(&Shape::Capsule {
            radius: r,
            half_length: 0.0,
        })
        .expect("present");
        assert!((tiny.inertia_com - sphere.inertia_com).amax() < 1e-15);

        // Hemisphere about its flat face's centre: 2/5 (m/2) r² about a diameter; its centre of
        // mass 3r/8 from the face. Integrated directly here by slicing along z.
        let h = 0.5;
        let slices = 200_000;
        let (mut m, mut ixx) = (0.0, 0.0);
        for k in 0..slices {
            // Slices of the whole capsule along its axis: discs of radius ρ(z).
            let z = -h - r + (2.0 * (h + r)) * (k as f64 + 0.5) / slices as f64;
            let dz = 2.0 * (h + r) / slices as f64;
            let rho2 = if z.abs() <= h {
                r * r
            } else {
                r * r - (z.abs() - h).powi(2)
            };
            let dm = PI * rho2 * dz;
            m += dm;
            ixx += dm * (rho2 / 4.0 + z * z);
        }
        let capsule = unit_properties(&Shape::Capsule {
            radius: r,
            half_length: h,
        })
        .expect("present");
        assert!(
            (capsule.mass / m - 1.0).abs() < 1e-9,
            "{} {}",
            capsule.mass,
            m
        );
        assert!((capsule.inertia_com[(0, 0)] / ixx - 1.0).abs() < 1e-9);
    }

    /// A wheel (radius 0.1, half-width 0.02) seen from a line through its centre across its
    /// axis: its farthest rim point is √(0.1² + 0.02²) away, not 0.1 + 0.02; along its axis, 0.1.
    #[test]
    fn a_cylinder_is_bounded_exactly_across_and_along_its_axis() {
        let wheel = Shape::Cylinder {
            radius: 0.1,
            half_length: 0.02,
        };
        let across =
            farthest_from_line(&wheel, &Point3::origin(), &Vector3::x()).expect("a primitive");
        assert!(
            (across - (0.01f64 + 0.0004).sqrt()).abs() < 1e-15,
            "{across}"
        );
        let along =
            farthest_from_line(&wheel, &Point3::origin(), &Vector3::z()).expect("a primitive");
        assert!((along - 0.1).abs() < 1e-15);
        // An oblique line: still above every sampled rim point's distance.
        let d = Vector3::new(1.0, 2.0, 3.0).normalize();
        let p = Point3::new(0.05, -0.3, 0.1);
        let bound = farthest_from_line(&wheel, &p, &d).expect("a primitive");
        let worst = (0..3600)
            .flat_map(|k| {
                let t = std::f64::consts::TAU * k as f64 / 3600.0;
                [-0.02, 0.02].map(|z| {
                    let v = Point3::new(0.1 * t.cos(), 0.1 * t.sin(), z) - p;
                    (v - d * d.dot(&v)).norm()
                })
            })
            .fold(0.0, f64::max);
        assert!(bound >= worst && bound < worst * 1.2, "{bound} vs {worst}");
    }

    #[test]
    fn supports_and_line_distances_of_a_box() {
        let b = Shape::Box {
            half_extents: Vector3::new(1.0, 2.0, 3.0),
        };
        assert_eq!(support(&b, &Vector3::new(1.0, -1.0, 0.0)), Some(3.0));
        // From the z axis through the centre the farthest corner is √(1 + 4) away.
        let d = farthest_from_line(&b, &Point3::origin(), &Vector3::z()).expect("present");
        assert!((d - 5f64.sqrt()).abs() < 1e-15);
    }
}
