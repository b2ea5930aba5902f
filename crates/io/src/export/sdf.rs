//! `sdf`: the `<inertial>` element of an SDFormat `<link>` (Gazebo).
//!
//! SDFormat spec (sdformat.org/spec, `link/inertial`): `<pose>x y z roll pitch yaw</pose>` is
//! "the pose of the inertial reference frame, relative to the specified reference frame. The
//! origin of the inertial reference frame needs to be at the center of gravity. The axes of the
//! inertial reference frame do not need to be aligned with the principal axes of the inertia";
//! the angles are radians in the same fixed-axis order as URDF (gz-math `Pose3`/`Quaternion`
//! from roll, pitch, yaw = `Rz·Ry·Rx`). `<inertia>` holds `<ixx> <ixy> <ixz> <iyy> <iyz> <izz>`,
//! the entries of the 3x3 rotational inertia matrix (gz-math `MassMatrix3`), so `ixy = −∑m·x·y`.
//! Units m, kg, kg·m²; right-handed Z-up.

use std::fmt::Write as _;
use std::path::Path;

use nalgebra::Rotation3;

use super::Frame;
use super::frames::{Converted, num, roll_pitch_yaw};
use super::surface::Surface;

/// The `<inertial>` element, preceded by a comment stating the conventions.
pub fn render(body: &Converted, frame: Frame) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<!-- {} SDFormat: lengths m, mass kg, inertia kg*m^2 about the centre of mass in the \
         inertial frame of pose (x y z = centre of mass in the link frame, then roll pitch yaw in \
         radians, fixed axes, R = Rz(yaw) Ry(pitch) Rx(roll)); ixx..izz are inertia matrix \
         entries, ixy = -sum(m*x*y). Frame: {}. -->",
        super::provenance(body),
        match frame {
            Frame::Origin => "link axes (full tensor)",
            Frame::ComPrincipal => "principal axes (diagonal tensor)",
        }
    );
    s.push_str(&element(body, frame));
    s
}

/// The `<inertial>` element alone, ending with a newline.
pub fn element(body: &Converted, frame: Frame) -> String {
    let (rpy, i) = match frame {
        Frame::Origin => ([0.0; 3], body.inertia),
        Frame::ComPrincipal => (
            roll_pitch_yaw(&body.principal),
            nalgebra::Matrix3::from_diagonal(&body.moments),
        ),
    };
    let c = &body.center_of_mass;
    let mut s = String::new();
    let _ = writeln!(s, "<inertial>");
    let _ = writeln!(s, "  {}", pose(c, rpy));
    let _ = writeln!(s, "  <mass>{}</mass>", num(body.mass));
    let _ = writeln!(s, "  <inertia>");
    for (name, (r, k)) in ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"].iter().zip([
        (0, 0),
        (0, 1),
        (0, 2),
        (1, 1),
        (1, 2),
        (2, 2),
    ]) {
        let _ = writeln!(s, "    <{name}>{}</{name}>", num(i[(r, k)]));
    }
    let _ = writeln!(s, "  </inertia>");
    let _ = writeln!(s, "</inertial>");
    s
}

/// A whole SDFormat 1.9 file: a `<model>` of one `<link>` with the `<inertial>`, and a visual and a
/// collision for each mesh file the surface came from, by `<uri>` (relative to `folder`, the
/// output's, when the mesh lies under it), placed (`<pose>`) and scaled (`<scale>`) into the
/// link frame, as libsdformat reads them.
pub fn model(
    body: &Converted,
    frame: Frame,
    surface: &Surface,
    name: &str,
    folder: Option<&Path>,
) -> String {
    let s = body.conversion.source_unit.metres() / body.conversion.target_unit.metres();
    let mut out = String::new();
    let _ = writeln!(out, "<?xml version=\"1.0\"?>");
    let _ = writeln!(
        out,
        "<!-- {} SDFormat model: lengths m, mass kg, inertia kg*m^2 about the centre of mass in \
         the inertial frame of pose (roll pitch yaw in radians, fixed axes); ixy = -sum(m*x*y). \
         Each mesh is placed in the link frame by its pose and scale. -->",
        super::provenance(body)
    );
    let _ = writeln!(out, "<sdf version=\"1.9\">");
    let _ = writeln!(out, "  <model name=\"{}\">", xml_text(name));
    let _ = writeln!(out, "    <link name=\"body\">");
    for line in element(body, frame).lines() {
        let _ = writeln!(out, "      {line}");
    }
    for (k, file) in surface.files.iter().enumerate() {
        let rotation = Rotation3::from_matrix_unchecked(
            body.map * file.placement.rotation.to_rotation_matrix().matrix(),
        );
        let t = body.map * file.placement.translation.vector * s;
        let rpy = roll_pitch_yaw(&rotation);
        let scale = num(file.scale * s);
        let uri = xml_text(&file.named_from(folder));
        for tag in ["visual", "collision"] {
            let _ = writeln!(out, "      <{tag} name=\"{tag}_{k}\">");
            let _ = writeln!(out, "        {}", pose(&t, rpy));
            let _ = writeln!(
                out,
                "        <geometry><mesh><uri>{uri}</uri><scale>{scale} {scale} {scale}</scale></mesh></geometry>"
            );
            let _ = writeln!(out, "      </{tag}>");
        }
    }
    let _ = writeln!(out, "    </link>");
    let _ = writeln!(out, "  </model>");
    let _ = writeln!(out, "</sdf>");
    out
}

/// A `<pose>`: the position `t`, then roll, pitch and yaw.
fn pose(t: &nalgebra::Vector3<f64>, rpy: [f64; 3]) -> String {
    format!(
        "<pose>{} {} {} {} {} {}</pose>",
        num(t.x),
        num(t.y),
        num(t.z),
        num(rpy[0]),
        num(rpy[1]),
        num(rpy[2])
    )
}

/// Text for an XML attribute or element.
fn xml_text(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
