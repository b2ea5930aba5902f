//! What the 3D view draws over the shaded mesh, as world-space segments, markers and labels:
//! wireframe, bounding box, centre of mass, principal axes, the equivalent box or ellipsoid, the
//! ω and L arrows, the poke's ΔL and the string with its force. Plain f64 geometry (tested
//! without a GPU); `view3d` projects it with the camera and paints it with egui.

use crate::platform::Instant;

use egui::{Align2, Color32};
use massprops::approximations::{EquivalentShape, equivalent_half_extents};
use nalgebra::{Point3, Vector3};

use crate::i18n::{fixed, sci, tr};
use crate::lab::placement::Placement;
use crate::lab::settings::{Equivalent, InertiaSource, ViewSettings};
use crate::lab::{Lab, Specimen};

/// A straight line in world space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Start.
    pub a: Point3<f64>,
    /// End.
    pub b: Point3<f64>,
    /// Colour.
    pub color: Color32,
    /// Width in points.
    pub width: f32,
    /// Draw an arrow head at `b`.
    pub arrow: bool,
}

/// Text at a world point.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    /// Anchor.
    pub at: Point3<f64>,
    /// Text.
    pub text: String,
    /// Colour.
    pub color: Color32,
    /// Which corner of the text sits at the anchor.
    pub align: Align2,
}

/// Everything to draw.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overlay {
    /// Lines and arrows.
    pub segments: Vec<Segment>,
    /// Dots (world point, colour).
    pub markers: Vec<(Point3<f64>, Color32)>,
    /// Labels.
    pub labels: Vec<Label>,
}

/// Axis colours 1, 2, 3 (moments ascending).
pub const AXIS_COLORS: [Color32; 3] = [
    Color32::from_rgb(235, 80, 80),
    Color32::from_rgb(90, 200, 90),
    Color32::from_rgb(90, 140, 255),
];
const OMEGA_COLOR: Color32 = Color32::from_rgb(255, 160, 40);
const L_COLOR: Color32 = Color32::from_rgb(220, 90, 255);
const STRING_COLOR: Color32 = Color32::from_rgb(250, 230, 120);
const FORCE_COLOR: Color32 = Color32::from_rgb(255, 110, 110);
const GUIDE_COLOR: Color32 = Color32::from_rgb(200, 200, 200);
const EQUIVALENT_COLOR: Color32 = Color32::from_rgb(80, 220, 230);
const EXACT_COM_COLOR: Color32 = Color32::from_rgb(120, 220, 255);
const HIGHLIGHT_COLOR: Color32 = Color32::from_rgb(255, 60, 200);

impl Overlay {
    fn line(&mut self, a: Point3<f64>, b: Point3<f64>, color: Color32, width: f32) {
        self.segments.push(Segment {
            a,
            b,
            color,
            width,
            arrow: false,
        });
    }

    fn arrow(
        &mut self,
        from: Point3<f64>,
        v: Vector3<f64>,
        color: Color32,
        label: &str,
        align: Align2,
    ) {
        if !(v.iter().all(|x| x.is_finite()) && v.norm() > 0.0) {
            return;
        }
        self.segments.push(Segment {
            a: from,
            b: from + v,
            color,
            width: 3.0,
            arrow: true,
        });
        self.labels.push(Label {
            at: from + v,
            text: label.to_owned(),
            color,
            align,
        });
    }

    /// The overlay for the lab's current state: every layer of `LAYERS` in order, over the
    /// primary specimen, with what the panels have selected outlined.
    pub fn build(lab: &Lab, now: Instant, selection: Selection) -> Self {
        let specimen = lab.primary();
        let body = specimen.sim().body();
        let ctx = Context {
            lab,
            view: &lab.settings().view,
            specimen,
            placement: specimen.placement(),
            com: body.position(),
            radius: specimen.bounding_sphere().1,
            now,
            selection,
        };
        let mut o = Overlay::default();
        for layer in LAYERS {
            layer(&mut o, &ctx);
        }
        o
    }
}

/// What every layer reads.
struct Context<'a> {
    lab: &'a Lab,
    view: &'a ViewSettings,
    specimen: &'a Specimen,
    /// The one mesh → world transform (the renderer draws with the same).
    placement: Placement,
    /// The body's centre of mass (world).
    com: Point3<f64>,
    /// Bounding-sphere radius of the scaled body: the length scale of guides and arrows.
    radius: f64,
    now: Instant,
    /// What the panels have selected.
    selection: Selection,
}

/// What the panels have selected, for the overlay to outline.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Selection {
    /// A mesh warning, whose example faces are outlined.
    pub warning: Option<usize>,
    /// A part of a body made of parts, whose box is outlined and named.
    pub part: Option<usize>,
}

impl Context<'_> {
    /// Arrow length for a vector of size `reference` (the preset spin's ω or L), so arrows keep
    /// their size across bodies and units; longer vectors grow up to 2.5×.
    fn scaled(&self, v: Vector3<f64>, reference: f64) -> Vector3<f64> {
        let len = self.arrow_len() * (v.norm() / reference).min(2.5);
        v.try_normalize(0.0).map(|u| u * len).unwrap_or_default()
    }
    fn arrow_len(&self) -> f64 {
        1.3 * self.radius
    }
    /// The preset spin rate, the ω arrow's reference.
    fn rate(&self) -> f64 {
        self.lab.settings().body.spin_rate.abs().max(1e-9)
    }
    /// The angular momentum of the preset spin about the intermediate axis, L's reference.
    fn l_reference(&self) -> f64 {
        self.specimen.sim().body().moments()[1] * self.rate()
    }
}

/// A layer adds its segments, markers and labels.
type Layer = fn(&mut Overlay, &Context<'_>);

/// The layers, bottom first.
const LAYERS: [Layer; 13] = [
    wireframe,
    bounding_box,
    principal_axes,
    equivalent,
    poinsot,
    center_of_mass,
    omega_arrow,
    l_arrow,
    poke,
    string,
    highlighted_faces,
    selected_part,
    link_ellipsoids,
];

/// Colours of a robot link's equivalent ellipsoids: from its geometry, and as its file states.
pub const COMPUTED_LINK_COLOR: Color32 = Color32::from_rgb(120, 230, 140);
/// See [`COMPUTED_LINK_COLOR`].
pub const STATED_LINK_COLOR: Color32 = Color32::from_rgb(255, 150, 70);

/// A whole robot's links: each one's uniform ellipsoid with its computed and with its stated
/// mass and moments, where one exists (stated moments that break I₁ + I₂ ≥ I₃ have none).
fn link_ellipsoids(o: &mut Overlay, c: &Context<'_>) {
    let mut too_large = 0;
    let mut largest: f64 = 0.0;
    for mark in &c.specimen.body().links {
        for (p, color) in [
            (&mark.computed, COMPUTED_LINK_COLOR),
            (&mark.stated, STATED_LINK_COLOR),
        ] {
            let Some(p) = p else { continue };
            let shape = EquivalentShape::Ellipsoid;
            let half = equivalent_half_extents(shape, p.mass, &p.principal.moments);
            if p.mass <= 0.0 || half.iter().any(|&x| x.is_nan() || x <= 0.0) {
                continue;
            }
            // Drawn where it fits the view: a placeholder's can be metres across a finger.
            let scaled = half.amax() * c.placement.scale;
            if scaled > 2.0 * c.radius {
                too_large += 1;
                largest = largest.max(2.0 * scaled);
                continue;
            }
            let axes = p.principal.rotation;
            let to_world = |q: Vector3<f64>| c.placement.to_world(&(p.center_of_mass + axes * q));
            principal_sections(o, &half, to_world, 32, color, 1.0);
        }
    }
    if too_large > 0 {
        o.labels.push(Label {
            at: c.com + Vector3::new(0.0, c.radius, 0.0),
            text: tr!(
                "view3d-ellipsoids-too-large",
                count = too_large,
                across = fixed(largest, 2)
            ),
            color: STATED_LINK_COLOR,
            align: Align2::CENTER_BOTTOM,
        });
    }
}

/// The selected part of a body made of parts: its bounding box (in the body's axes) and name.
fn selected_part(o: &mut Overlay, c: &Context<'_>) {
    let body = c.specimen.body();
    let (Some(k), Some(comp)) = (c.selection.part, body.composition.as_ref()) else {
        return;
    };
    let (Some(part), Some(range)) = (comp.parts.get(k), comp.triangles.get(k)) else {
        return;
    };
    let mut lo = Point3::from([f64::INFINITY; 3]);
    let mut hi = Point3::from([f64::NEG_INFINITY; 3]);
    for t in &body.mesh.triangles[range.clone()] {
        for &v in t {
            let p = body.mesh.positions[v as usize];
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        }
    }
    if range.is_empty() {
        return;
    }
    let top = outline_box(o, c, lo, hi, HIGHLIGHT_COLOR, 2.0);
    o.labels.push(Label {
        at: top,
        text: part.entry.name.clone(),
        color: HIGHLIGHT_COLOR,
        align: Align2::LEFT_BOTTOM,
    });
}

/// The example faces of the selected mesh warning: outlined, with a dot and their number, drawn
/// over everything (they may be small or hidden behind other faces). Faces whose centres lie
/// close together (around one small hole) share one label.
fn highlighted_faces(o: &mut Overlay, c: &Context<'_>) {
    let body = c.specimen.body();
    let Some(faces) = c.selection.warning.and_then(|i| body.warning_faces.get(i)) else {
        return;
    };
    let positions = &body.mesh.positions;
    let mut labelled: Vec<(Point3<f64>, Vec<usize>)> = Vec::new();
    for (f, corners) in faces {
        let world: Vec<Point3<f64>> = corners
            .iter()
            .map(|&v| c.placement.to_world(&positions[v as usize]))
            .collect();
        for (k, &a) in world.iter().enumerate() {
            o.line(a, world[(k + 1) % world.len()], HIGHLIGHT_COLOR, 3.0);
        }
        let centre =
            Point3::from(world.iter().map(|p| p.coords).sum::<Vector3<f64>>() / world.len() as f64);
        o.markers.push((centre, HIGHLIGHT_COLOR));
        match labelled
            .iter_mut()
            .find(|(at, _)| (at - centre).norm() < LABEL_MERGE * c.radius)
        {
            Some((_, list)) => list.push(*f),
            None => labelled.push((centre, vec![*f])),
        }
    }
    for (at, list) in labelled {
        let names: Vec<String> = list.iter().map(usize::to_string).collect();
        let text = match names.len() {
            1 => tr!("view3d-face", face = &names[0]),
            _ => tr!("view3d-faces", faces = names.join(", ")),
        };
        o.labels.push(Label {
            at,
            text,
            color: HIGHLIGHT_COLOR,
            align: Align2::LEFT_BOTTOM,
        });
    }
}

/// Highlighted faces whose centres are closer than this fraction of the body's radius share a
/// label.
const LABEL_MERGE: f64 = 0.3;

fn wireframe(o: &mut Overlay, c: &Context<'_>) {
    let mesh = &c.specimen.body().mesh;
    if !c.view.wireframe {
        return;
    }
    let color = Color32::from_rgba_unmultiplied(20, 20, 20, 200);
    for [a, b] in &mesh.edges {
        o.line(
            c.placement.to_world(&mesh.positions[*a as usize]),
            c.placement.to_world(&mesh.positions[*b as usize]),
            color,
            1.0,
        );
    }
}

fn bounding_box(o: &mut Overlay, c: &Context<'_>) {
    if !c.view.bounding_box {
        return;
    }
    let (lo, hi) = c.specimen.body().analysis.diagnostics.bounding_box;
    let top = outline_box(o, c, lo, hi, GUIDE_COLOR, 1.5);
    o.labels.push(Label {
        at: top,
        text: tr!("view3d-bounding-box"),
        color: GUIDE_COLOR,
        align: Align2::LEFT_BOTTOM,
    });
}

fn principal_axes(o: &mut Overlay, c: &Context<'_>) {
    if !c.view.principal_axes {
        return;
    }
    let principal = c.specimen.sim().body().orientation();
    for (i, color) in AXIS_COLORS.iter().enumerate() {
        let axis = principal * Vector3::ith(i, 0.8 * c.radius);
        o.line(c.com - axis, c.com + axis, *color, 2.0);
        o.labels.push(Label {
            at: c.com + axis * 1.05,
            text: format!("{}", i + 1),
            color: *color,
            align: Align2::LEFT_BOTTOM,
        });
    }
}

/// An ellipsoid of semi-axes `half` as its three principal sections, `n` segments each, its
/// principal-frame points placed by `to_world`.
fn principal_sections(
    o: &mut Overlay,
    half: &Vector3<f64>,
    to_world: impl Fn(Vector3<f64>) -> Point3<f64>,
    n: usize,
    color: Color32,
    width: f32,
) {
    for plane in 0..3 {
        let (u, v) = ((plane + 1) % 3, (plane + 2) % 3);
        let point = |s: usize| {
            let t = std::f64::consts::TAU * s as f64 / n as f64;
            let mut p = Vector3::zeros();
            p[u] = half[u] * t.cos();
            p[v] = half[v] * t.sin();
            to_world(p)
        };
        for s in 0..n {
            o.line(point(s), point(s + 1), color, width);
        }
    }
}

/// The uniform box or ellipsoid with the same mass and principal moments
/// (`massprops::approximations::equivalent_half_extents`).
fn equivalent(o: &mut Overlay, c: &Context<'_>) {
    let shape = match c.view.equivalent {
        Equivalent::None => return,
        Equivalent::Box => EquivalentShape::Box,
        Equivalent::Ellipsoid => EquivalentShape::Ellipsoid,
    };
    let body = c.specimen.sim().body();
    let half = equivalent_half_extents(shape, body.mass(), &body.moments());
    let principal = body.orientation();
    let to_world = |p: Vector3<f64>| c.com + principal * p;
    if shape == EquivalentShape::Box {
        let corner =
            |k: usize| Vector3::from_fn(|a, _| if k >> a & 1 == 0 { -half[a] } else { half[a] });
        for (a, b) in cube_edges() {
            o.line(
                to_world(corner(a)),
                to_world(corner(b)),
                EQUIVALENT_COLOR,
                1.5,
            );
        }
        return;
    }
    principal_sections(o, &half, to_world, 48, EQUIVALENT_COLOR, 1.5);
    o.labels.push(Label {
        at: to_world(Vector3::new(half[0], 0.0, 0.0)),
        text: tr!("view3d-equivalent-ellipsoid"),
        color: EQUIVALENT_COLOR,
        align: Align2::LEFT_BOTTOM,
    });
}

/// Seconds of ω's path drawn as the herpolhode.
const HERPOLHODE_SECONDS: f64 = 12.0;
const POINSOT_COLOR: Color32 = Color32::from_rgb(255, 200, 120);

/// Poinsot's construction (`rbcore::poinsot`), drawn with ω at `k` world lengths per rad/s from
/// the centre of mass: the ellipsoid ωᵀIω = 2T through ω's tip, the invariable plane it rolls on,
/// and the herpolhode ω's tip traces on the plane.
fn poinsot(o: &mut Overlay, c: &Context<'_>) {
    if !c.view.poinsot {
        return;
    }
    let body = c.specimen.sim().body();
    let Some(construction) = rbcore::poinsot(body) else {
        return;
    };
    let n = construction.normal;
    let k = c.arrow_len() / c.rate();
    let tip = c.com + body.omega_world() * k;
    let principal = body.orientation();
    let semi = construction.semi_axes * k;
    principal_sections(
        o,
        &semi,
        |p| c.com + principal * p,
        64,
        POINSOT_COLOR.gamma_multiply(0.6),
        1.0,
    );
    // The invariable plane: a square about the contact point, as large as the ellipsoid.
    let half = semi.max();
    let e1 = n
        .cross(&Vector3::x())
        .try_normalize(1e-9)
        .unwrap_or_else(|| n.cross(&Vector3::y()).normalize());
    let e2 = n.cross(&e1);
    let centre = c.com + n * (construction.distance * k);
    let corner = |a: f64, b: f64| centre + (e1 * a + e2 * b) * half;
    let square = [
        corner(-1.0, -1.0),
        corner(1.0, -1.0),
        corner(1.0, 1.0),
        corner(-1.0, 1.0),
    ];
    for i in 0..4 {
        o.line(square[i], square[(i + 1) % 4], POINSOT_COLOR, 1.5);
    }
    o.labels.push(Label {
        at: square[2],
        text: tr!("view3d-invariable-plane"),
        color: POINSOT_COLOR,
        align: Align2::LEFT_BOTTOM,
    });
    // The herpolhode: ω's tip over the last seconds, drawn from today's centre of mass.
    let history = c.specimen.history();
    if let Some(last) = history.last() {
        // Only since the last disturbance: before it ω moved on another plane.
        let since = (last.t - HERPOLHODE_SECONDS).max(history.disturbed_at());
        let start = history.samples().partition_point(|s| s.t < since);
        let samples: Vec<_> = history.samples().range(start..).collect();
        let stride = (samples.len() / 400).max(1);
        let path: Vec<Point3<f64>> = samples
            .iter()
            .step_by(stride)
            .map(|s| c.com + Vector3::from(s.omega_world) * k)
            .collect();
        for pair in path.windows(2) {
            o.line(pair[0], pair[1], Color32::WHITE, 1.5);
        }
    }
    o.markers.push((tip, POINSOT_COLOR));
}

/// The centre of mass in use, and the exact one where an approximation moves it.
fn center_of_mass(o: &mut Overlay, c: &Context<'_>) {
    if !c.view.center_of_mass {
        return;
    }
    o.markers.push((c.com, Color32::WHITE));
    let exact = c.specimen.properties(InertiaSource::Exact);
    let used = c.specimen.used_properties();
    if (exact.center_of_mass - used.center_of_mass).norm() > 1e-9 * c.radius {
        let mesh_point = Point3::from(exact.center_of_mass.coords / c.placement.scale);
        let at = c.placement.to_world(&mesh_point);
        o.markers.push((at, EXACT_COM_COLOR));
        o.labels.push(Label {
            at,
            text: tr!("view3d-exact-com"),
            color: EXACT_COM_COLOR,
            align: Align2::LEFT_BOTTOM,
        });
    }
}

fn omega_arrow(o: &mut Overlay, c: &Context<'_>) {
    if c.view.omega_arrow {
        let w = c.specimen.sim().body().omega_world();
        o.arrow(
            c.com,
            c.scaled(w, c.rate()),
            OMEGA_COLOR,
            "ω",
            Align2::LEFT_TOP,
        );
    }
}

fn l_arrow(o: &mut Overlay, c: &Context<'_>) {
    if !c.view.l_arrow {
        return;
    }
    // Without torque about the centre of mass (gravity acts at it) L is conserved: say so where
    // the user sees the arrow stand still.
    let torque_free =
        c.lab.settings().physics.angular_damping == 0.0 && c.specimen.string_view().is_none();
    let label = if torque_free {
        tr!("view3d-l-fixed")
    } else {
        "L".to_owned()
    };
    let l = c.specimen.sim().body().angular_momentum();
    o.arrow(
        c.com,
        c.scaled(l, c.l_reference()),
        L_COLOR,
        &label,
        Align2::RIGHT_BOTTOM,
    );
}

/// The last poke's impulse and the ΔL it caused, while the flash lasts.
fn poke(o: &mut Overlay, c: &Context<'_>) {
    let Some(p) = c.specimen.poke_flash().filter(|p| p.until > c.now) else {
        return;
    };
    let j_len = 0.6 * c.radius;
    let dir = p.impulse.try_normalize(0.0).unwrap_or_default();
    o.segments.push(Segment {
        a: p.point - dir * j_len,
        b: p.point,
        color: FORCE_COLOR,
        width: 3.0,
        arrow: true,
    });
    o.labels.push(Label {
        at: p.point - dir * j_len,
        text: format!("J = {} N·s", sci(p.impulse.norm(), 3)),
        color: FORCE_COLOR,
        align: Align2::LEFT_BOTTOM,
    });
    o.arrow(
        c.com,
        c.scaled(p.delta_l, c.l_reference()),
        Color32::from_rgb(255, 255, 255),
        &format!("ΔL = r × J ({})", sci(p.delta_l.norm(), 3)),
        Align2::LEFT_BOTTOM,
    );
}

/// The string and the force it applies.
fn string(o: &mut Overlay, c: &Context<'_>) {
    let Some(s) = c.specimen.string_view() else {
        return;
    };
    o.line(s.attachment, s.target, STRING_COLOR, 2.0);
    o.markers.push((s.target, STRING_COLOR));
    let cap = c
        .specimen
        .string_max_force(c.lab.settings())
        .max(f64::MIN_POSITIVE);
    // Square-root scale: a weak pull stays visible next to one at the cap.
    let f = s
        .force
        .try_normalize(0.0)
        .map(|u| u * c.arrow_len() * (s.force.norm() / cap).min(1.0).sqrt())
        .unwrap_or_default();
    o.arrow(
        s.attachment,
        f,
        FORCE_COLOR,
        &format!("|F| = {} N", fixed(s.force.norm(), 3)),
        Align2::LEFT_TOP,
    );
}

/// The 12 edges of a cube whose corners are numbered by bits (x = 1, y = 2, z = 4).
/// Outlines the box `lo`–`hi` (mesh coordinates) as placed; returns its corner of largest
/// coordinates (world), where a label goes.
fn outline_box(
    o: &mut Overlay,
    c: &Context<'_>,
    lo: Point3<f64>,
    hi: Point3<f64>,
    color: Color32,
    width: f32,
) -> Point3<f64> {
    let corner = |i: usize| {
        c.placement.to_world(&Point3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        ))
    };
    for (a, b) in cube_edges() {
        o.line(corner(a), corner(b), color, width);
    }
    corner(7)
}

fn cube_edges() -> impl Iterator<Item = (usize, usize)> {
    (0..8usize).flat_map(|c| {
        [1usize, 2, 4]
            .into_iter()
            .filter(move |bit| c & bit == 0)
            .map(move |bit| (c, c | bit))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lab::Command;
    use crate::lab::settings::AppSettings;

    /// The herpolhode lies in the invariable plane (L is conserved), and ω's tip is on the
    /// drawn ellipsoid ωᵀIω = 2T.
    #[test]
    fn poinsot_herpolhode_lies_in_the_invariable_plane() {
        let mut lab = Lab::new(AppSettings::default()).expect("lab");
        let mut settings = lab.settings().clone();
        settings.view.poinsot = true;
        lab.apply(Command::Settings(Box::new(settings)));
        lab.advance_for(6.0);
        let o = Overlay::build(&lab, Instant::now(), Selection::default());
        let body = lab.primary().sim().body();
        let n = body.angular_momentum().normalize();
        let &(tip, _) = o
            .markers
            .iter()
            .find(|(_, col)| *col == POINSOT_COLOR)
            .expect("the contact point");
        let herpolhode: Vec<&Segment> = o
            .segments
            .iter()
            .filter(|s| s.color == Color32::WHITE && !s.arrow)
            .collect();
        assert!(herpolhode.len() > 100, "{}", herpolhode.len());
        let scale = (tip - body.position()).norm();
        for s in herpolhode {
            for p in [s.a, s.b] {
                let off = (p - tip).dot(&n);
                assert!(off.abs() < 1e-9 * scale, "{off} off the plane");
            }
        }
        // In principal coordinates the tip satisfies Σ xᵢ²/aᵢ² = 1 with aᵢ = k√(2T/Iᵢ).
        let k = (tip - body.position()).norm() / body.omega_world().norm();
        let x = body.orientation().inverse() * (tip - body.position());
        let two_t = body.omega_world().dot(&body.angular_momentum());
        let on: f64 = (0..3)
            .map(|i| x[i] * x[i] / (k * k * two_t / body.moments()[i]))
            .sum();
        assert!((on - 1.0).abs() < 1e-9, "{on}");
    }

    #[test]
    fn cube_has_twelve_unit_edges() {
        let edges: Vec<_> = cube_edges().collect();
        assert_eq!(edges.len(), 12);
        assert!(edges.iter().all(|(a, b)| (a ^ b).count_ones() == 1));
    }

    #[test]
    fn equivalent_box_of_a_box_is_the_box_and_everything_is_finite() {
        let mut lab = Lab::new(AppSettings::default()).expect("lab");
        lab.apply(Command::LoadSample("Book".to_owned()));
        let mut settings = lab.settings().clone();
        settings.view = ViewSettings {
            wireframe: true,
            bounding_box: true,
            equivalent: Equivalent::Box,
            ..ViewSettings::default()
        };
        lab.apply(Command::Settings(Box::new(settings)));
        let o = Overlay::build(&lab, Instant::now(), Selection::default());
        let com = lab.primary().sim().body().position();
        // The book is a 1 × 4 × 7 box: its equivalent box has half-diagonal √(0.25+4+12.25).
        let box_edges = o
            .segments
            .iter()
            .filter(|s| s.color == EQUIVALENT_COLOR)
            .collect::<Vec<_>>();
        assert_eq!(box_edges.len(), 12);
        for s in box_edges {
            assert!(((s.a - com).norm() - 16.5f64.sqrt()).abs() < 1e-9);
        }
        let all_finite = |p: &Point3<f64>| p.iter().all(|x| x.is_finite());
        assert!(
            o.segments
                .iter()
                .all(|s| all_finite(&s.a) && all_finite(&s.b))
        );
        assert!(o.labels.iter().any(|l| l.text.starts_with("L")));
    }
}
