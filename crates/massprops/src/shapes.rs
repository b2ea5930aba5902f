//! Procedural closed meshes: the sample bodies of `assets/` and the benchmark meshes.
//!
//! Every shape winds its faces counter-clockwise seen from outside. Multi-part bodies (a hammer's
//! head and handle) are separate closed parts that touch; their mass properties add.

use std::f64::consts::TAU;
use std::fmt::Write as _;

use nalgebra::{Isometry3, Point2, Point3, Vector3};

use crate::PolyMesh;

/// A mesh under construction: positions and face loops, optionally in named parts.
#[derive(Debug, Clone, Default)]
pub struct MeshBuilder {
    /// Vertex positions.
    pub positions: Vec<Point3<f64>>,
    /// Faces as vertex-index loops.
    pub faces: Vec<Vec<usize>>,
    /// Named parts, each from its first face to the next part's: written as OBJ objects.
    pub objects: Vec<(String, usize)>,
}

impl MeshBuilder {
    /// Validates and freezes the mesh.
    ///
    /// # Panics
    /// Never for the shapes of this module, whose indices are in range by construction.
    pub fn build(&self) -> PolyMesh {
        PolyMesh::new(self.positions.clone(), &self.faces)
            .expect("generated shapes are valid by construction")
    }

    /// Appends another part under a name (an OBJ object when written), keeping both.
    pub fn append_named(&mut self, name: &str, other: &MeshBuilder) -> &mut Self {
        self.objects.push((name.to_owned(), self.faces.len()));
        self.append(other)
    }

    /// Appends another part, keeping both (no welding).
    pub fn append(&mut self, other: &MeshBuilder) -> &mut Self {
        let base = self.positions.len();
        self.positions.extend_from_slice(&other.positions);
        self.faces.extend(
            other
                .faces
                .iter()
                .map(|f| f.iter().map(|i| i + base).collect()),
        );
        self
    }

    /// Moves every vertex by a rigid motion.
    pub fn transformed(mut self, motion: &Isometry3<f64>) -> Self {
        for p in &mut self.positions {
            *p = motion * *p;
        }
        self
    }

    /// Splits every face into a triangle fan from its first corner (named parts keep their
    /// faces).
    pub fn triangulated(mut self) -> Self {
        let mut first_triangle = Vec::with_capacity(self.faces.len());
        let mut triangles = Vec::new();
        for f in &self.faces {
            first_triangle.push(triangles.len());
            triangles.extend(f[1..].windows(2).map(|w| vec![f[0], w[0], w[1]]));
        }
        for (_, first) in &mut self.objects {
            *first = first_triangle
                .get(*first)
                .copied()
                .unwrap_or(triangles.len());
        }
        self.faces = triangles;
        self
    }
}

/// A right prism: the simple polygon `outline` (counter-clockwise in the xy plane, convex or not)
/// extruded from z = `z0` to z = `z1` (`z1` > `z0`). Caps are single n-gons.
pub fn prism(outline: &[Point2<f64>], z0: f64, z1: f64) -> MeshBuilder {
    let n = outline.len();
    let mut positions: Vec<Point3<f64>> =
        outline.iter().map(|p| Point3::new(p.x, p.y, z0)).collect();
    positions.extend(outline.iter().map(|p| Point3::new(p.x, p.y, z1)));
    let mut faces = vec![(0..n).rev().collect(), (n..2 * n).collect()];
    faces.extend((0..n).map(|i| {
        let j = (i + 1) % n;
        vec![i, j, n + j, n + i]
    }));
    MeshBuilder {
        positions,
        faces,
        objects: Vec::new(),
    }
}

/// An axis-aligned box of edge lengths `size` centred on `center`, six quads.
pub fn cuboid(size: Vector3<f64>, center: Point3<f64>) -> MeshBuilder {
    let h = size / 2.0;
    let rect = [
        Point2::new(center.x - h.x, center.y - h.y),
        Point2::new(center.x + h.x, center.y - h.y),
        Point2::new(center.x + h.x, center.y + h.y),
        Point2::new(center.x - h.x, center.y + h.y),
    ];
    prism(&rect, center.z - h.z, center.z + h.z)
}

/// Points of an ellipse (semi-axes `a` along x, `b` along y), counter-clockwise, from angle 0.
pub fn ellipse(a: f64, b: f64, segments: usize) -> Vec<Point2<f64>> {
    (0..segments)
        .map(|i| {
            let t = TAU * i as f64 / segments as f64;
            Point2::new(a * t.cos(), b * t.sin())
        })
        .collect()
}

/// A cylinder of `radius` along z from `z0` to `z1`, as a prism of a regular `segments`-gon.
pub fn cylinder(radius: f64, z0: f64, z1: f64, segments: usize) -> MeshBuilder {
    prism(&ellipse(radius, radius, segments), z0, z1)
}

/// A flat elliptical ring (like a racket frame): the region between the ellipses (`a`, `b`) and
/// (`a` − `width`, `b` − `width`), extruded from `z0` to `z1`. Genus one, all quads.
pub fn elliptic_ring(a: f64, b: f64, width: f64, z0: f64, z1: f64, segments: usize) -> MeshBuilder {
    let outer = ellipse(a, b, segments);
    let inner = ellipse(a - width, b - width, segments);
    let n = segments;
    // Four rings of vertices: outer bottom, outer top, inner bottom, inner top.
    let mut positions = Vec::with_capacity(4 * n);
    for (ring, z) in [(&outer, z0), (&outer, z1), (&inner, z0), (&inner, z1)] {
        positions.extend(ring.iter().map(|p| Point3::new(p.x, p.y, z)));
    }
    let (ob, ot, ib, it) = (0, n, 2 * n, 3 * n);
    let mut faces = Vec::with_capacity(4 * n);
    for i in 0..n {
        let j = (i + 1) % n;
        faces.push(vec![ot + i, ot + j, it + j, it + i]);
        faces.push(vec![ob + j, ob + i, ib + i, ib + j]);
        faces.push(vec![ob + i, ob + j, ot + j, ot + i]);
        faces.push(vec![ib + j, ib + i, it + i, it + j]);
    }
    MeshBuilder {
        positions,
        faces,
        objects: Vec::new(),
    }
}

/// A torus about the z axis: major radius `major`, tube radius `minor`, quads.
pub fn torus(major: f64, minor: f64, around: usize, tube: usize) -> MeshBuilder {
    let mut positions = Vec::with_capacity(around * tube);
    for i in 0..around {
        let u = TAU * i as f64 / around as f64;
        for j in 0..tube {
            let v = TAU * j as f64 / tube as f64;
            let r = major + minor * v.cos();
            positions.push(Point3::new(r * u.cos(), r * u.sin(), minor * v.sin()));
        }
    }
    let at = |i: usize, j: usize| (i % around) * tube + (j % tube);
    let faces = (0..around)
        .flat_map(|i| {
            (0..tube).map(move |j| vec![at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)])
        })
        .collect();
    MeshBuilder {
        positions,
        faces,
        objects: Vec::new(),
    }
}

/// The T-handle ("Dzhanibekov wing nut"): an 80 mm crossbar along x on top of a 50 mm stem along
/// −y, both of 12 mm square section, one prism of a T-shaped octagon (metres).
pub fn t_handle() -> MeshBuilder {
    let (bar, stem, s) = (0.08, 0.05, 0.012);
    let outline = [
        Point2::new(-s / 2.0, -stem),
        Point2::new(s / 2.0, -stem),
        Point2::new(s / 2.0, 0.0),
        Point2::new(bar / 2.0, 0.0),
        Point2::new(bar / 2.0, s),
        Point2::new(-bar / 2.0, s),
        Point2::new(-bar / 2.0, 0.0),
        Point2::new(-s / 2.0, 0.0),
    ];
    prism(&outline, -s / 2.0, s / 2.0)
}

/// An L-bracket: 100 × 60 mm legs, 10 mm thick, 30 mm deep; its centre of mass lies far from
/// its bounding-box centre (metres).
pub fn l_bracket() -> MeshBuilder {
    let outline = [
        Point2::new(0.0, 0.0),
        Point2::new(0.1, 0.0),
        Point2::new(0.1, 0.01),
        Point2::new(0.01, 0.01),
        Point2::new(0.01, 0.06),
        Point2::new(0.0, 0.06),
    ];
    prism(&outline, 0.0, 0.03)
}

/// A 1 × 4 × 7 book (a box centred on the origin): the classic stable/unstable-axis demo.
pub fn book() -> MeshBuilder {
    cuboid(Vector3::new(1.0, 4.0, 7.0), Point3::origin())
}

/// A unit cube centred on the origin.
pub fn cube() -> MeshBuilder {
    cuboid(Vector3::repeat(1.0), Point3::origin())
}

/// A hammer: a 300 mm cylindrical handle (radius 15 mm, 24 sides) along y, topped by a
/// 120 × 30 × 30 mm head offset towards +x (metres). Two touching parts, objects `handle` and
/// `head`.
pub fn hammer() -> MeshBuilder {
    let handle = cylinder(0.015, 0.0, 0.3, 24).transformed(&y_up());
    let head = cuboid(
        Vector3::new(0.12, 0.03, 0.03),
        Point3::new(0.02, 0.315, 0.0),
    );
    let mut m = MeshBuilder::default();
    m.append_named("handle", &handle)
        .append_named("head", &head);
    m
}

/// A tennis racket (metres): an elliptical frame (outer semi-axes 135 × 165 mm, 12 mm wide,
/// 20 mm deep), a 2 mm string bed filling it, and a 270 mm handle of 30 × 25 mm along −y.
/// Objects `frame`, `strings` and `handle`.
pub fn tennis_racket() -> MeshBuilder {
    let (a, b, width, depth, segments) = (0.135, 0.165, 0.012, 0.02, 64);
    let mut m = MeshBuilder::default();
    m.append_named(
        "frame",
        &elliptic_ring(a, b, width, -depth / 2.0, depth / 2.0, segments),
    );
    m.append_named(
        "strings",
        &prism(&ellipse(a - width, b - width, segments), -0.001, 0.001),
    );
    let handle_length = 0.27;
    m.append_named(
        "handle",
        &cuboid(
            Vector3::new(0.03, handle_length, 0.025),
            Point3::new(0.0, -b - handle_length / 2.0, 0.0),
        ),
    );
    m
}

/// Two 0.3 m boxes for the hollow-box sample: `outer` and, inside it, `cavity` (0.26 m, wound
/// outward like any solid: the body file makes it a void).
pub fn hollow_box_parts() -> MeshBuilder {
    let mut m = MeshBuilder::default();
    m.append_named("outer", &cuboid(Vector3::repeat(0.3), Point3::origin()));
    m.append_named("cavity", &cuboid(Vector3::repeat(0.26), Point3::origin()));
    m
}

/// The sample torus: major radius 1, tube radius 0.3, 96 × 48 quads.
pub fn sample_torus() -> MeshBuilder {
    torus(1.0, 0.3, 96, 48)
}

/// Rotation taking the z axis to the y axis (and y to −z), for shapes built along z.
fn y_up() -> Isometry3<f64> {
    Isometry3::rotation(Vector3::x() * (-std::f64::consts::FRAC_PI_2))
}

/// The sample bodies of `assets/`: (file stem, description, mesh).
pub fn samples() -> Vec<(&'static str, &'static str, MeshBuilder)> {
    vec![
        (
            "t_handle",
            "T-handle (Dzhanibekov wing nut), metres",
            t_handle(),
        ),
        (
            "tennis_racket",
            "tennis racket: frame, string bed, handle; metres",
            tennis_racket(),
        ),
        ("book", "1 x 4 x 7 book", book()),
        ("hammer", "hammer: handle and offset head; metres", hammer()),
        ("l_bracket", "L-bracket, metres", l_bracket()),
        ("cube", "unit cube", cube()),
        (
            "torus",
            "torus R = 1, r = 0.3, 96 x 48 quads",
            sample_torus(),
        ),
    ]
}

/// Meshes of parts for the body files of `assets/` (not bodies by themselves): (file stem,
/// description, mesh).
pub fn part_samples() -> Vec<(&'static str, &'static str, MeshBuilder)> {
    vec![(
        "hollow_box",
        "a 0.3 m box and its 0.26 m cavity, for hollow_box.toml; metres",
        hollow_box_parts(),
    )]
}

/// Writes a mesh as OBJ text (shortest round-trip decimal coordinates): one `o` object called
/// `name`, or one per named part.
pub fn to_obj(name: &str, comment: &str, mesh: &MeshBuilder) -> String {
    let mut s = String::new();
    // Writing into a String cannot fail.
    let _ = writeln!(
        s,
        "# {comment}\n# generated by `cargo run -p massprops --example generate_assets`"
    );
    if mesh.objects.is_empty() {
        let _ = writeln!(s, "o {name}");
    }
    for p in &mesh.positions {
        let _ = writeln!(s, "v {} {} {}", p.x, p.y, p.z);
    }
    for (k, f) in mesh.faces.iter().enumerate() {
        if let Some((object, _)) = mesh.objects.iter().find(|(_, first)| *first == k) {
            let _ = writeln!(s, "o {object}");
        }
        s.push('f');
        for i in f {
            let _ = write!(s, " {}", i + 1);
        }
        s.push('\n');
    }
    s
}
