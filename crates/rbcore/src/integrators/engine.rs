//! Engine comparisons: how game physics engines treat the gyroscopic term, reproduced so a learner
//! can see why they fail. Both are symplectic-Euler style: full force kick, gyroscopic update of
//! body-frame L, then `q ← normalise(q + ½h ω q)` with the new ω.

use nalgebra::{Matrix3, Point3, UnitQuaternion, Vector3};

use super::{RotationModel, quaternion_rate};
use crate::body::Body;
use crate::forces::ForceModel;

/// Newton iterations cap for the backward Euler solve.
const MAX_NEWTON: usize = 30;

/// Which gyroscopic update.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Gyroscopic {
    /// `L ← L + h L×ω`, then rescaled to the old |L| (Jolt's
    /// `MotionProperties::ApplyGyroscopicForceInternal`; PhysX, Rapier and Avian do the same idea).
    ExplicitRescaled,
    /// Backward Euler `L' = L + h L'×ω'` (Bullet's `computeGyroscopicImpulseImplicit_Body` takes one
    /// Newton step of this; we solve it to round-off so its dissipation law holds exactly).
    BackwardEuler,
}

fn backward_euler(l: &Vector3<f64>, w: &Vector3<f64>, h: f64) -> Vector3<f64> {
    let wm = Matrix3::from_diagonal(w);
    let mut x = *l;
    let tol = 4.0 * f64::EPSILON * l.norm();
    for _ in 0..MAX_NEWTON {
        let wx = w.component_mul(&x);
        let g = x - l - x.cross(&wx) * h;
        let jac = Matrix3::identity() - (x.cross_matrix() * wm - wx.cross_matrix()) * h;
        let Some(delta) = jac.lu().solve(&g) else {
            break;
        };
        x -= delta;
        if delta.norm() <= tol || delta.norm().is_nan() {
            break;
        }
    }
    x
}

/// One engine-style step.
pub(crate) fn step(
    body: &mut Body,
    forces: &ForceModel,
    h: f64,
    model: RotationModel,
    gyro: Gyroscopic,
) {
    let w = forces.wrench(body);
    body.momentum += w.force * h;
    body.angular_momentum += w.torque * h;
    let l = body.angular_momentum_principal();
    let l_new = match model {
        RotationModel::Textbook => l,
        RotationModel::Full => match gyro {
            Gyroscopic::ExplicitRescaled => {
                let trial = l + l.cross(&body.inv_moments.component_mul(&l)) * h;
                let n = trial.norm();
                if n > 0.0 {
                    trial * (l.norm() / n)
                } else {
                    trial
                }
            }
            Gyroscopic::BackwardEuler => backward_euler(&l, &body.inv_moments, h),
        },
    };
    let omega_world = body
        .orientation
        .transform_vector(&body.inv_moments.component_mul(&l_new));
    let q = body.orientation.into_inner();
    body.orientation = UnitQuaternion::new_normalize(q + quaternion_rate(&q, &omega_world) * h);
    body.angular_momentum = body.orientation.transform_vector(&l_new);
    body.position = Point3::from(body.position.coords + body.momentum * (h / body.mass));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backward_euler_dissipates_energy_and_momentum_norm() {
        // From L' − L = h L'×ω': (L'−L)·ω' = 0 gives E' − E = −½ ΔL·WΔL and |L'|² − |L|² = −|ΔL|².
        let l = Vector3::new(0.1, 20.0, 0.3);
        let w = Vector3::new(1.0, 0.5, 1.0 / 3.0);
        let l2 = backward_euler(&l, &w, 1.0 / 60.0);
        let d = l2 - l;
        let e = |v: &Vector3<f64>| 0.5 * v.component_mul(v).dot(&w);
        assert!((e(&l2) - e(&l) + 0.5 * d.component_mul(&d).dot(&w)).abs() < 1e-12);
        assert!((l2.norm_squared() - l.norm_squared() + d.norm_squared()).abs() < 1e-11);
    }
}
