//! `mjcf`: the `<inertial>` element of a MuJoCo `<body>`.
//!
//! MuJoCo XML reference (`body/inertial`): `pos` is the centre of mass in the body frame; the
//! frame orientation is `quat` "w x y z" (MuJoCo's quaternion order, scalar first);
//! `diaginertia` is the "diagonal inertia matrix, expressing the body inertia relative to the
//! inertial frame"; `fullinertia` is the "full inertia matrix M … specified using only 6 numbers
//! in the following order: M(1,1), M(2,2), M(3,3), M(1,2), M(1,3), M(2,3)", i.e. xx yy zz xy
//! xz yz, tensor entries (`M(1,2) = −∑m·x·y`); "the compiler computes the eigenvalue
//! decomposition of M and sets the frame orientation and diagonal inertia accordingly", and an
//! orientation may not be given with it (MuJoCo 4.0: "at most one of 'fullinertia', 'quat', …").
//! Units m, kg, kg·m² (MuJoCo is unit-agnostic; SI keeps gravity 9.81 right); Z-up.
//! MuJoCo refuses a moving body whose mass or principal moments are below `mjMINVAL` = 1e-15
//! ("inertia must have positive eigenvalues", "mass and inertia of moving bodies must be larger
//! than mjMINVAL", MuJoCo 4.0), so such a body gets a warning.

use super::Frame;
use super::frames::{Converted, num};

/// MuJoCo's `mjMINVAL`: the smallest mass or moment a moving body may have.
const MJ_MINVAL: f64 = 1e-15;

/// The `<inertial>` element, preceded by a comment stating the conventions; warns when MuJoCo
/// would refuse the body as too small.
pub fn render(body: &Converted, frame: Frame, warnings: &mut Vec<String>) -> String {
    if body.mass < MJ_MINVAL || body.moments[0] < MJ_MINVAL {
        warnings.push(format!(
            "mjcf: mass {:e} kg, smallest principal moment {:e} kg*m^2: MuJoCo refuses a moving \
             body with either below 1e-15 (mjMINVAL). Check --units (a mesh in metres read as \
             mm has 1e-15 of its inertia at the same mass ratio) or model the part as part of a \
             larger body",
            body.mass, body.moments[0]
        ));
    }
    let (note, element) = note_and_element(body, frame);
    format!(
        "<!-- {} MJCF: lengths m, mass kg, inertia kg*m^2 about the centre of mass (pos, body \
         frame); {note}. If your geom uses the mesh file as is, give it the same up-axis \
         rotation. -->\n{element}\n",
        super::provenance(body)
    )
}

/// The `<inertial>` element alone, ending with a newline.
pub fn element(body: &Converted, frame: Frame) -> String {
    format!("{}\n", note_and_element(body, frame).1)
}

/// What the comment says of the frame, and the element.
fn note_and_element(body: &Converted, frame: Frame) -> (&'static str, String) {
    let c = &body.center_of_mass;
    let pos = format!("{} {} {}", num(c.x), num(c.y), num(c.z));
    match frame {
        Frame::Origin => {
            let i = &body.inertia;
            (
                "fullinertia = xx yy zz xy xz yz of the inertia matrix in body axes, \
                 xy = -sum(m*x*y); MuJoCo diagonalises it when compiling",
                format!(
                    "<inertial pos=\"{pos}\" mass=\"{}\" fullinertia=\"{} {} {} {} {} {}\"/>",
                    num(body.mass),
                    num(i[(0, 0)]),
                    num(i[(1, 1)]),
                    num(i[(2, 2)]),
                    num(i[(0, 1)]),
                    num(i[(0, 2)]),
                    num(i[(1, 2)])
                ),
            )
        }
        Frame::ComPrincipal => {
            let [w, x, y, z] = body.principal_quaternion();
            let m = &body.moments;
            (
                "quat = w x y z rotating principal-axes coordinates into body axes; \
                 diaginertia = principal moments in that frame",
                format!(
                    "<inertial pos=\"{pos}\" quat=\"{} {} {} {}\" mass=\"{}\" \
                     diaginertia=\"{} {} {}\"/>",
                    num(w),
                    num(x),
                    num(y),
                    num(z),
                    num(body.mass),
                    num(m.x),
                    num(m.y),
                    num(m.z)
                ),
            )
        }
    }
}
