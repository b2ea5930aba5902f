//! Textbook explicit integrators with the orientation stored as a rotation matrix: `Ṙ = [ω]ₓ R`,
//! Gram-Schmidt re-orthonormalisation after every step (as in Baraff's SIGGRAPH course notes).

use nalgebra::{Matrix3, Point3, Rotation3, UnitQuaternion, Vector3};

use super::RotationModel;
use crate::body::Body;
use crate::forces::ForceModel;

/// The integrated state of a textbook step.
#[derive(Clone, Copy)]
struct State {
    r: Vector3<f64>,
    rot: Matrix3<f64>,
    p: Vector3<f64>,
    l: Vector3<f64>,
}

/// Gram-Schmidt on the columns (x, then y against x, then z = x × y keeps it right-handed).
pub(crate) fn gram_schmidt(m: &Matrix3<f64>) -> Matrix3<f64> {
    let x = m.column(0).normalize();
    let y0 = m.column(1) - x * x.dot(&m.column(1));
    let y = y0.normalize();
    let z = x.cross(&y);
    Matrix3::from_columns(&[x, y, z])
}

fn load(body: &Body) -> State {
    State {
        r: body.position.coords,
        rot: *body.orientation.to_rotation_matrix().matrix(),
        p: body.momentum,
        l: body.angular_momentum,
    }
}

fn store(body: &mut Body, s: &State) {
    body.position = Point3::from(s.r);
    body.orientation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(
        gram_schmidt(&s.rot),
    ));
    body.momentum = s.p;
    body.angular_momentum = s.l;
}

/// Time derivative of the state; forces are evaluated on a copy of `body` carrying the state.
fn derivative(body: &Body, s: &State, forces: &ForceModel, model: RotationModel) -> State {
    let mut b = *body;
    store(&mut b, s);
    let w = forces.wrench(&b);
    let omega = s.rot * Matrix3::from_diagonal(&body.inv_moments) * s.rot.transpose() * s.l;
    let gyro = match model {
        RotationModel::Full => Vector3::zeros(),
        // Body-frame L constant under no torque means world L turns with the body: L̇ = ω × L.
        RotationModel::Textbook => omega.cross(&s.l),
    };
    State {
        r: s.p / body.mass,
        rot: omega.cross_matrix() * s.rot,
        p: w.force,
        l: w.torque + gyro,
    }
}

fn axpy(s: &State, h: f64, d: &State) -> State {
    State {
        r: s.r + d.r * h,
        rot: s.rot + d.rot * h,
        p: s.p + d.p * h,
        l: s.l + d.l * h,
    }
}

/// Explicit Euler step.
pub(crate) fn euler_step(body: &mut Body, forces: &ForceModel, h: f64, model: RotationModel) {
    let s = load(body);
    let d = derivative(body, &s, forces, model);
    store(body, &axpy(&s, h, &d));
}

/// Explicit midpoint (RK2) step.
pub(crate) fn midpoint_step(body: &mut Body, forces: &ForceModel, h: f64, model: RotationModel) {
    let s = load(body);
    let d1 = derivative(body, &s, forces, model);
    let mid = axpy(&s, 0.5 * h, &d1);
    let d2 = derivative(body, &mid, forces, model);
    store(body, &axpy(&s, h, &d2));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gram_schmidt_gives_a_rotation() {
        let m = Matrix3::new(1.0, 0.1, 0.0, 0.05, 1.0, 0.2, 0.0, -0.1, 1.1);
        let g = gram_schmidt(&m);
        assert!((g.transpose() * g - Matrix3::identity()).amax() < 1e-15);
        assert!((g.determinant() - 1.0).abs() < 1e-15);
    }
}
