//! `urdf`: the `<inertial>` element of a URDF `<link>`.
//!
//! ROS URDF spec (wiki.ros.org/urdf/XML/link): `<origin xyz rpy>` is "the pose of the inertial
//! reference frame, relative to the link reference frame. The origin of the inertial reference
//! frame needs to be at the center of gravity"; rpy are fixed-axis roll, pitch, yaw in radians
//! (`R = Rz(yaw)·Ry(pitch)·Rx(roll)`); `<inertia ixx ixy ixz iyy iyz izz>` are the six
//! above-diagonal entries of "the 3x3 rotational inertia matrix, represented in the inertia
//! frame", i.e. tensor entries (`ixy = −∑m·x·y`, our convention; urdfdom and MuJoCo's URDF
//! reader build the matrix from them unchanged). Units m, kg, kg·m²; ROS is right-handed Z-up
//! (REP 103).

use std::fmt::Write as _;

use super::Frame;
use super::frames::{Converted, num, roll_pitch_yaw};

/// The `<inertial>` element, preceded by a comment stating the conventions.
pub fn render(body: &Converted, frame: Frame) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<!-- {} URDF: lengths m, mass kg, inertia kg*m^2 about the centre of mass, in the frame \
         of origin (xyz = centre of mass, rpy = fixed-axis roll pitch yaw in radians, \
         R = Rz(yaw) Ry(pitch) Rx(roll)); ixx..izz are inertia matrix entries, ixy = -sum(m*x*y). \
         Frame: {}. If your visual uses the mesh file as is, give it the same up-axis rotation. -->",
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
    let (rpy, i) = axes(body, frame);
    let c = &body.center_of_mass;
    let mut s = String::new();
    let _ = writeln!(s, "<inertial>");
    let _ = writeln!(
        s,
        "  <origin xyz=\"{} {} {}\" rpy=\"{} {} {}\"/>",
        num(c.x),
        num(c.y),
        num(c.z),
        num(rpy[0]),
        num(rpy[1]),
        num(rpy[2])
    );
    let _ = writeln!(s, "  <mass value=\"{}\"/>", num(body.mass));
    let _ = writeln!(
        s,
        "  <inertia ixx=\"{}\" ixy=\"{}\" ixz=\"{}\" iyy=\"{}\" iyz=\"{}\" izz=\"{}\"/>",
        num(i[(0, 0)]),
        num(i[(0, 1)]),
        num(i[(0, 2)]),
        num(i[(1, 1)]),
        num(i[(1, 2)]),
        num(i[(2, 2)])
    );
    let _ = writeln!(s, "</inertial>");
    s
}

/// The origin's rpy and the tensor written, for `frame`.
fn axes(body: &Converted, frame: Frame) -> ([f64; 3], nalgebra::Matrix3<f64>) {
    match frame {
        Frame::Origin => ([0.0; 3], body.inertia),
        Frame::ComPrincipal => (
            roll_pitch_yaw(&body.principal),
            nalgebra::Matrix3::from_diagonal(&body.moments),
        ),
    }
}
