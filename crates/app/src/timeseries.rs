//! The time-series schema: one row per simulation step, written as CSV by `inertia-lab simulate`
//! and by the app's plot export, and kept in memory by the app's plot history. The columns are
//! documented in docs/simulate.md: time, ω in the principal body frame, ω and L in world, the
//! Hamilton quaternion (w, x, y, z) taking the principal body frame to world, and the energies.

use std::io::{self, Write};

use rbcore::Diagnostics;

/// The CSV header, one column per field of [`Sample`], in [`Sample::values`] order.
pub const CSV_HEADER: &str = "t,w1,w2,w3,wx,wy,wz,Lx,Ly,Lz,qw,qx,qy,qz,T,U,E";

/// One step's quantities (the CSV columns).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Simulated time (s).
    pub t: f64,
    /// ω in the principal body frame (rad/s), moments ascending.
    pub omega_principal: [f64; 3],
    /// ω in world (rad/s).
    pub omega_world: [f64; 3],
    /// World angular momentum about the centre of mass.
    pub l: [f64; 3],
    /// |L|.
    pub l_norm: f64,
    /// Orientation quaternion (w, x, y, z), principal → world; see [`QuaternionSign`].
    pub q: [f64; 4],
    /// Kinetic energy T.
    pub kinetic: f64,
    /// Potential energy U (gravity and string).
    pub potential: f64,
    /// Total energy E = T + U.
    pub energy: f64,
}

impl Sample {
    /// The sample of `d`, as the simulation reports it (the quaternion's sign is rbcore's).
    pub fn new(d: &Diagnostics) -> Self {
        let q = d.orientation.into_inner();
        Self {
            t: d.time,
            omega_principal: d.omega_principal.into(),
            omega_world: d.omega_world.into(),
            l: d.angular_momentum.into(),
            l_norm: d.angular_momentum_norm,
            q: [q.w, q.i, q.j, q.k],
            kinetic: d.kinetic,
            potential: d.potential,
            energy: d.energy,
        }
    }

    /// Whether every value is finite (a diverged step is never plotted).
    pub fn is_finite(&self) -> bool {
        self.values().iter().all(|v| v.is_finite())
    }

    /// All values in CSV column order.
    pub fn values(&self) -> [f64; 17] {
        let [w1, w2, w3] = self.omega_principal;
        let [wx, wy, wz] = self.omega_world;
        let [lx, ly, lz] = self.l;
        let [qw, qx, qy, qz] = self.q;
        [
            self.t,
            w1,
            w2,
            w3,
            wx,
            wy,
            wz,
            lx,
            ly,
            lz,
            qw,
            qx,
            qy,
            qz,
            self.kinetic,
            self.potential,
            self.energy,
        ]
    }

    /// Writes the sample as one CSV row (shortest round-trip decimal of each value).
    ///
    /// # Errors
    /// Writing to `out` failed.
    pub fn write_csv_row(&self, out: &mut dyn Write) -> io::Result<()> {
        let mut first = true;
        for v in self.values() {
            if !first {
                out.write_all(b",")?;
            }
            first = false;
            write!(out, "{v}")?;
        }
        out.write_all(b"\n")
    }
}

/// Keeps the quaternion's sign continuous along a series: q and −q are the same orientation, and
/// a sign jump would draw a spurious step in a plot or a spreadsheet.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct QuaternionSign {
    last: Option<[f64; 4]>,
}

impl QuaternionSign {
    /// Negates `s.q` if it points away from the previous sample's quaternion, and remembers it.
    pub fn apply(&mut self, s: &mut Sample) {
        if let Some(last) = self.last {
            let dot: f64 = s.q.iter().zip(last).map(|(a, b)| a * b).sum();
            if dot < 0.0 {
                s.q = s.q.map(|x| -x);
            }
        }
        self.last = Some(s.q);
    }

    /// Forgets the previous sample (a new series starts).
    pub fn reset(&mut self) {
        self.last = None;
    }
}

/// Writes the header and then `samples` as CSV rows.
///
/// # Errors
/// Writing to `out` failed.
pub fn write_csv<'a>(
    out: &mut dyn Write,
    samples: impl IntoIterator<Item = &'a Sample>,
) -> io::Result<()> {
    writeln!(out, "{CSV_HEADER}")?;
    for s in samples {
        s.write_csv_row(out)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{UnitQuaternion, Vector3};
    use rbcore::{Body, Settings, Simulation};

    #[test]
    fn row_has_one_value_per_header_column_and_round_trips() {
        let mut b = Body::from_moments(2.0, Vector3::new(1.0, 2.0, 3.0)).expect("valid");
        b.set_omega_principal(Vector3::new(0.1, 4.0, 0.1))
            .expect("finite");
        let mut sim = Simulation::new(b, Settings::default()).expect("valid");
        sim.step().expect("stable");
        let s = Sample::new(&sim.diagnostics());
        let mut out = Vec::new();
        write_csv(&mut out, [&s]).expect("in memory");
        let text = String::from_utf8(out).expect("utf-8");
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 2);
        assert_eq!(lines[0], CSV_HEADER);
        let parsed: Vec<f64> = lines[1]
            .split(',')
            .map(|v| v.parse().expect("number"))
            .collect();
        assert_eq!(parsed, s.values().to_vec());
    }

    /// The CSV quaternion is the rotation taking the principal body frame to world: rotating the
    /// principal-frame ω by it gives the world ω of the same row.
    #[test]
    fn quaternion_takes_principal_omega_to_world_omega() {
        let mut b = Body::from_moments(1.0, Vector3::new(1.0, 2.0, 3.0)).expect("valid");
        b.set_orientation(UnitQuaternion::from_euler_angles(0.3, -1.1, 2.0))
            .expect("unit");
        b.set_omega_principal(Vector3::new(0.7, -3.0, 1.3))
            .expect("finite");
        let mut sim = Simulation::new(b, Settings::default()).expect("valid");
        for _ in 0..100 {
            sim.step().expect("stable");
        }
        let s = Sample::new(&sim.diagnostics());
        let [w, x, y, z] = s.q;
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(w, x, y, z));
        let world = q * Vector3::from(s.omega_principal);
        assert!((world - Vector3::from(s.omega_world)).norm() < 1e-12 * world.norm());
    }

    #[test]
    fn sign_continuity_flips_only_opposite_quaternions() {
        let sample = |q: [f64; 4]| Sample {
            t: 0.0,
            omega_principal: [0.0; 3],
            omega_world: [0.0; 3],
            l: [0.0; 3],
            l_norm: 0.0,
            q,
            kinetic: 0.0,
            potential: 0.0,
            energy: 0.0,
        };
        let mut sign = QuaternionSign::default();
        let mut a = sample([1.0, 0.0, 0.0, 0.0]);
        sign.apply(&mut a);
        assert_eq!(a.q, [1.0, 0.0, 0.0, 0.0]);
        let mut b = sample([-0.6, -0.8, 0.0, 0.0]);
        sign.apply(&mut b);
        assert_eq!(b.q, [0.6, 0.8, 0.0, 0.0]);
        let mut c = sample([0.0, 1.0, 0.0, 0.0]);
        sign.apply(&mut c);
        assert_eq!(c.q, [0.0, 1.0, 0.0, 0.0]);
        sign.reset();
        let mut d = sample([-1.0, 0.0, 0.0, 0.0]);
        sign.apply(&mut d);
        assert_eq!(d.q, [-1.0, 0.0, 0.0, 0.0]);
    }
}
