//! Classical fourth-order Runge-Kutta on (position, quaternion, linear momentum, world L), with
//! the quaternion renormalised at the end of the step.

use nalgebra::{Point3, Quaternion, UnitQuaternion, Vector3};

use super::{RotationModel, quaternion_rate};
use crate::body::Body;
use crate::forces::ForceModel;

#[derive(Clone, Copy)]
struct State {
    r: Vector3<f64>,
    q: Quaternion<f64>,
    p: Vector3<f64>,
    l: Vector3<f64>,
}

fn derivative(body: &Body, s: &State, forces: &ForceModel, model: RotationModel) -> State {
    let mut b = *body;
    b.position = Point3::from(s.r);
    b.orientation = UnitQuaternion::new_normalize(s.q);
    b.momentum = s.p;
    b.angular_momentum = s.l;
    let w = forces.wrench(&b);
    let omega = b.omega_world();
    let gyro = match model {
        RotationModel::Full => Vector3::zeros(),
        RotationModel::Textbook => omega.cross(&s.l),
    };
    State {
        r: s.p / body.mass,
        q: quaternion_rate(&b.orientation.into_inner(), &omega),
        p: w.force,
        l: w.torque + gyro,
    }
}

fn axpy(s: &State, h: f64, d: &State) -> State {
    State {
        r: s.r + d.r * h,
        q: s.q + d.q * h,
        p: s.p + d.p * h,
        l: s.l + d.l * h,
    }
}

/// One RK4 step.
pub(crate) fn step(body: &mut Body, forces: &ForceModel, h: f64, model: RotationModel) {
    let s = State {
        r: body.position.coords,
        q: body.orientation.into_inner(),
        p: body.momentum,
        l: body.angular_momentum,
    };
    let k1 = derivative(body, &s, forces, model);
    let k2 = derivative(body, &axpy(&s, 0.5 * h, &k1), forces, model);
    let k3 = derivative(body, &axpy(&s, 0.5 * h, &k2), forces, model);
    let k4 = derivative(body, &axpy(&s, h, &k3), forces, model);
    let sixth = h / 6.0;
    body.position = Point3::from(s.r + (k1.r + (k2.r + k3.r) * 2.0 + k4.r) * sixth);
    body.orientation =
        UnitQuaternion::new_normalize(s.q + (k1.q + (k2.q + k3.q) * 2.0 + k4.q) * sixth);
    body.momentum = s.p + (k1.p + (k2.p + k3.p) * 2.0 + k4.p) * sixth;
    body.angular_momentum = s.l + (k1.l + (k2.l + k3.l) * 2.0 + k4.l) * sixth;
}
