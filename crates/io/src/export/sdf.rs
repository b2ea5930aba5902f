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

use super::Frame;
use super::frames::{Converted, num, roll_pitch_yaw};

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
    let _ = writeln!(
        s,
        "  <pose>{} {} {} {} {} {}</pose>",
        num(c.x),
        num(c.y),
        num(c.z),
        num(rpy[0]),
        num(rpy[1]),
        num(rpy[2])
    );
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
