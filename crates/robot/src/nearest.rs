//! The physically valid inertial nearest to a stated one: the stated mass kept, the stated
//! centre kept where it lies inside the geometry, and the tensor changed as little as possible.
//!
//! **The set.** With the mass m and the centre c held, what is left of an inertial is the
//! second moment of its mass about the centre, Σ = ∫(x−c)(x−c)ᵀ dm, and the tensor is
//! I = tr(Σ)·𝟙 − Σ. Parameters that a non-negative density within a region can have satisfy
//! (Wensing, Kim and Slotine, "Linear matrix inequalities for physically consistent inertial
//! parameter identification", IEEE RA-L 3(1), 2017):
//! - the pseudo-inertia [[Σ + m·c·cᵀ, m·c], [m·cᵀ, m]] is positive semidefinite, which for
//!   m > 0 is Σ ⪰ 0 (the triangle inequality of the principal moments);
//! - for an ellipsoid {x : (x−e)ᵀA(x−e) ≤ 1} that holds the region, the mean over the mass of
//!   1 − (x−e)ᵀA(x−e) is not negative: tr(A·Σ) ≤ m·(1 − (c−e)ᵀA(c−e)). The ellipsoid here is
//!   the smallest one about the geometry's hull (Khachiyan's algorithm, then scaled so that
//!   every point is inside).
//!
//! Added, and as linear: about each axis u through c, uᵀIu = tr((𝟙 − u·uᵀ)Σ) ≤ m·r(u)², r(u)
//! the geometry's farthest distance from that axis (the audit's own `impossible_moment` bound,
//! which the ellipsoid does not imply, since the ellipsoid is larger than the geometry).
//!
//! **The metric.** The Frobenius norm of the tensor's change, ‖I − I_stated‖_F in kg·m²
//! (both about their centres, link axes). In Σ, with Δ = Σ − Σ_stated, it is
//! ‖Δ‖_F² + tr(Δ)².
//!
//! **The solution.** A semidefinite program in six unknowns. It is solved as a sequence of
//! quadratic programs (clarabel's interior-point solver) in which the semidefinite cone and
//! the per-axis bound, each an infinity of linear constraints, are represented by the few that
//! matter: every round adds the plane vᵀΣv ≥ 0 of an eigenvector the last answer violates and
//! the bound about each principal axis it violates (Kelley's cutting planes), until none is
//! violated by more than 10⁻¹² of m·R² (R the ellipsoid's largest semi-axis). The answer is
//! then moved exactly inside: its negative eigenvalues (if any remain) set to zero and the
//! whole scaled down to its linear bounds. clarabel's own semidefinite cones are not used
//! because they need a system BLAS and LAPACK, which a fresh Debian lacks.

use nalgebra::{Matrix3, Point3, SymmetricEigen, Vector3};

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettings, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus};

use massprops::MassProperties;

use crate::audit::directions;

/// The ellipsoid {x : (x − center)ᵀ·shape·(x − center) ≤ 1}.
#[derive(Debug, Clone, PartialEq)]
pub struct Ellipsoid {
    /// Its centre, link frame, m.
    pub center: Point3<f64>,
    /// Its quadratic form, 1/m² (positive definite).
    pub shape: Matrix3<f64>,
}

impl Ellipsoid {
    /// Its semi-axes' lengths, m, smallest first.
    pub fn semi_axes(&self) -> Vector3<f64> {
        let mut axes: Vec<f64> = self
            .shape
            .symmetric_eigenvalues()
            .iter()
            .map(|l| 1.0 / l.sqrt())
            .collect();
        axes.sort_by(f64::total_cmp);
        Vector3::new(axes[0], axes[1], axes[2])
    }

    /// (p − center)ᵀ·shape·(p − center): below 1 inside, 1 on the surface.
    pub fn level(&self, p: &Point3<f64>) -> f64 {
        let d = p - self.center;
        d.dot(&(self.shape * d))
    }
}

/// The smallest-volume ellipsoid about `points` (to within 0.1 % in volume), scaled so that
/// every point is inside; `None` for fewer than four points or points in a plane.
///
/// Khachiyan's algorithm ("Rounding of polytopes in the real number model of computation",
/// Math. Oper. Res. 21(2), 1996; the form of Todd and Yıldırım, 2007) on a subset: the points
/// farthest along 26 directions and an even sample, to which the points the last ellipsoid
/// leaves outside are added until none is (only hull points can be outside, so this ends with
/// the ellipsoid of all of them).
pub fn bounding_ellipsoid(points: &[Point3<f64>]) -> Option<Ellipsoid> {
    if points.len() < 4 {
        return None;
    }
    let mut subset: Vec<usize> = Vec::new();
    for d in directions() {
        for sign in [-1.0, 1.0] {
            let best = (0..points.len()).max_by(|&a, &b| {
                (sign * d.dot(&points[a].coords)).total_cmp(&(sign * d.dot(&points[b].coords)))
            })?;
            subset.push(best);
        }
    }
    let stride = (points.len() / SAMPLE).max(1);
    subset.extend((0..points.len()).step_by(stride));
    subset.sort_unstable();
    subset.dedup();
    let mut ellipsoid = khachiyan(&subset.iter().map(|&i| points[i]).collect::<Vec<_>>())?;
    for _ in 0..ROUNDS {
        let mut outside: Vec<(f64, usize)> = (0..points.len())
            .map(|i| (ellipsoid.level(&points[i]), i))
            .filter(|(level, _)| *level > 1.0 + KHACHIYAN_TOLERANCE)
            .collect();
        if outside.is_empty() {
            break;
        }
        outside.sort_by(|a, b| b.0.total_cmp(&a.0));
        subset.extend(outside.iter().take(SAMPLE).map(|(_, i)| *i));
        subset.sort_unstable();
        subset.dedup();
        ellipsoid = khachiyan(&subset.iter().map(|&i| points[i]).collect::<Vec<_>>())?;
    }
    let widest = points
        .iter()
        .map(|p| ellipsoid.level(p))
        .fold(0.0, f64::max);
    // The last bit of slack covers round-off in later comparisons against the surface.
    ellipsoid.shape /= widest * (1.0 + 1e-12);
    Some(ellipsoid)
}

/// How many points an even sample, and an addition of outside points, holds at most.
const SAMPLE: usize = 2000;
/// Rounds of adding the points left outside.
const ROUNDS: usize = 8;
/// Khachiyan's stopping step, and the level past 1 that counts as outside.
const KHACHIYAN_TOLERANCE: f64 = 1e-3;

/// Khachiyan's algorithm on `points`: weights u on the points, the lifted q = (p, 1), and at
/// each step the weight moved towards the point of largest qᵀX⁻¹q, X = Σ u·q·qᵀ.
fn khachiyan(points: &[Point3<f64>]) -> Option<Ellipsoid> {
    let n = points.len();
    let lifted: Vec<nalgebra::Vector4<f64>> = points
        .iter()
        .map(|p| nalgebra::Vector4::new(p.x, p.y, p.z, 1.0))
        .collect();
    let mut u = vec![1.0 / n as f64; n];
    let d = 3.0;
    for _ in 0..100_000 {
        let mut x = nalgebra::Matrix4::zeros();
        for (q, w) in lifted.iter().zip(&u) {
            x += *w * q * q.transpose();
        }
        let inverse = x.try_inverse()?;
        let (j, largest) = lifted
            .iter()
            .map(|q| q.dot(&(inverse * q)))
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))?;
        let step = (largest - d - 1.0) / ((d + 1.0) * (largest - 1.0));
        if !step.is_finite() || step < KHACHIYAN_TOLERANCE {
            break;
        }
        for w in &mut u {
            *w *= 1.0 - step;
        }
        u[j] += step;
    }
    let center = points
        .iter()
        .zip(&u)
        .fold(Vector3::zeros(), |c, (p, w)| c + *w * p.coords);
    let mut spread = Matrix3::zeros();
    for (p, w) in points.iter().zip(&u) {
        spread += *w * p.coords * p.coords.transpose();
    }
    spread -= center * center.transpose();
    let shape = (spread * d).try_inverse()?;
    (shape.symmetric_eigenvalues().min() > 0.0 && shape.iter().all(|v| v.is_finite())).then(|| {
        Ellipsoid {
            center: Point3::from(center),
            shape,
        }
    })
}

/// Which constraint holds the nearest inertial where it is.
#[derive(Debug, Clone, PartialEq)]
pub enum Held {
    /// A principal moment equals the sum of the other two (the pseudo-inertia is singular:
    /// all mass in a plane through the centre).
    TriangleInequality,
    /// The mass reaches the bounding ellipsoid's surface on average: no more can be spread.
    Ellipsoid,
    /// The moment about a principal axis is m·r², r the geometry's farthest reach from it.
    AxisBound {
        /// The axis, link frame, unit.
        axis: Vector3<f64>,
        /// r, m.
        radius: f64,
    },
}

impl Held {
    /// Its code, as in JSON.
    pub fn code(&self) -> &'static str {
        match self {
            Held::TriangleInequality => "triangle_inequality",
            Held::Ellipsoid => "bounding_ellipsoid",
            Held::AxisBound { .. } => "axis_bound",
        }
    }
}

/// The nearest valid inertial to a stated one.
#[derive(Debug, Clone, PartialEq)]
pub struct Nearest {
    /// The inertial: the stated mass, the centre below, the nearest tensor (link frame, SI).
    pub properties: MassProperties,
    /// Whether the stated centre was kept (else the geometry's centre was taken, the stated
    /// one lying outside the geometry or its ellipsoid).
    pub center_kept: bool,
    /// ‖I − I_stated‖_F, kg·m².
    pub moved: f64,
    /// `moved` / ‖I_stated‖_F.
    pub moved_fraction: f64,
    /// The constraints it lies on (none when the stated inertial was valid already).
    pub held_by: Vec<Held>,
    /// The ellipsoid used.
    pub ellipsoid: Ellipsoid,
}

/// Why no nearest inertial is given.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NearestError {
    /// The stated mass is not positive.
    #[error("its stated mass ({0} kg) is not positive, so there is no stated inertial to keep")]
    NoMass(f64),
    /// The stated centre or tensor holds a number that is not finite.
    #[error("its stated centre or tensor holds a number that is not finite")]
    NotFinite,
    /// Its geometry gives no ellipsoid (fewer than four points, or all in a plane).
    #[error(
        "its geometry is flat or has fewer than four points, so it holds no volume to spread mass in"
    )]
    FlatGeometry,
    /// The solver did not solve.
    #[error("the solver stopped without a solution ({0})")]
    Solver(String),
}

/// What [`nearest`] needs of the link's geometry.
pub struct Region<'a> {
    /// Points whose hull contains the geometry (link frame).
    pub hull: &'a [Point3<f64>],
    /// The geometry's farthest distance from the line through a point along a unit direction.
    pub farthest_from_line: &'a dyn Fn(&Point3<f64>, &Vector3<f64>) -> f64,
    /// Whether a point lies inside the geometry (the audit's hull test).
    pub contains: &'a dyn Fn(&Point3<f64>) -> bool,
    /// The geometry's own centre of mass, taken when the stated one lies outside.
    pub center: Point3<f64>,
}

/// Relative slack of the cuts, the final checks and the test of what is held.
const CUT_SLACK: f64 = 1e-12;
/// How far inside the triangle inequality the answer lands: Σ's smallest eigenvalue at least
/// this fraction of its trace (A + B − C ≥ 2·10⁻⁶·tr Σ). On the boundary itself the body is a
/// flat sheet, and a simulator that checks A + B ≥ C after its own round-off refuses it
/// (MuJoCo 4.0.0 did, on a Panda link fixed without the margin).
const TRIANGLE_MARGIN: f64 = 1e-6;
const HELD_SLACK: f64 = 1e-7;
/// Cutting-plane rounds at most (each adds up to four planes; 3×3 cones need few).
const MAX_ROUNDS: usize = 200;

/// The valid inertial nearest to `stated` within `region`.
pub fn nearest(stated: &MassProperties, region: &Region<'_>) -> Result<Nearest, NearestError> {
    let m = stated.mass;
    if !(m > 0.0 && m.is_finite()) {
        return Err(NearestError::NoMass(m));
    }
    if !stated
        .inertia_com
        .iter()
        .chain(stated.center_of_mass.iter())
        .all(|v| v.is_finite())
    {
        return Err(NearestError::NotFinite);
    }
    let ellipsoid = bounding_ellipsoid(region.hull).ok_or(NearestError::FlatGeometry)?;
    let inside = |c: &Point3<f64>| (region.contains)(c) && ellipsoid.level(c) < 1.0;
    let center_kept = inside(&stated.center_of_mass);
    let center = if center_kept {
        stated.center_of_mass
    } else {
        region.center
    };
    let reach = ellipsoid.semi_axes().z;
    let scale = m * reach * reach;
    let target = second_moment(&stated.inertia_com) / scale;
    let spread = region
        .hull
        .iter()
        .map(|p| (p - center).norm())
        .fold(0.0, f64::max)
        / reach;
    let problem = Problem {
        target,
        spread,
        ellipsoid_bound: (1.0 - ellipsoid.level(&center)).max(0.0),
        ellipsoid: ellipsoid.shape * (reach * reach),
        axis_bound: |u: &Vector3<f64>| {
            let r = (region.farthest_from_line)(&center, u);
            r * r / (reach * reach)
        },
    };
    // A valid inertial is its own nearest, to the bit.
    let (inertia, held_by) = if problem.violations(&target).is_empty() {
        (stated.inertia_com, Vec::new())
    } else {
        let sigma = problem.exactly_inside(problem.solve()?);
        let held = problem.held(&sigma, &|u| (region.farthest_from_line)(&center, u));
        (tensor(&(sigma * scale)), held)
    };
    let moved = (inertia - stated.inertia_com).norm();
    Ok(Nearest {
        properties: MassProperties::new(m, center, inertia),
        center_kept,
        moved,
        moved_fraction: moved / stated.inertia_com.norm(),
        held_by,
        ellipsoid,
    })
}

/// Σ from I: Σ = ½·tr(I)·𝟙 − I.
fn second_moment(inertia: &Matrix3<f64>) -> Matrix3<f64> {
    Matrix3::identity() * (inertia.trace() / 2.0) - inertia
}

/// I from Σ: I = tr(Σ)·𝟙 − Σ.
fn tensor(sigma: &Matrix3<f64>) -> Matrix3<f64> {
    Matrix3::identity() * sigma.trace() - sigma
}

/// The program in units of m·R²: the target Σ, the ellipsoid's form and bound, the axis bound.
struct Problem<F: Fn(&Vector3<f64>) -> f64> {
    target: Matrix3<f64>,
    /// The geometry's farthest point from the centre, in units of R: how fast r(u) can change
    /// as the axis u turns (|dr| ≤ spread·|du|).
    spread: f64,
    ellipsoid: Matrix3<f64>,
    ellipsoid_bound: f64,
    /// r(u)² in units of R².
    axis_bound: F,
}

/// A linear constraint a·x ≤ b on the six unknowns (Σ11, Σ22, Σ33, Σ12, Σ13, Σ23).
type Cut = ([f64; 6], f64);

/// ⟨M, Σ⟩ = tr(M·Σ) for symmetric M, as coefficients of the six unknowns.
fn pairing(m: &Matrix3<f64>) -> [f64; 6] {
    [
        m[(0, 0)],
        m[(1, 1)],
        m[(2, 2)],
        2.0 * m[(0, 1)],
        2.0 * m[(0, 2)],
        2.0 * m[(1, 2)],
    ]
}

fn unpack(x: &[f64]) -> Matrix3<f64> {
    Matrix3::new(x[0], x[3], x[4], x[3], x[1], x[5], x[4], x[5], x[2])
}

impl<F: Fn(&Vector3<f64>) -> f64> Problem<F> {
    /// The plane vᵀΣv ≥ margin·tr(Σ).
    fn cone_cut(v: &Vector3<f64>) -> Cut {
        (
            pairing(&(Matrix3::identity() * TRIANGLE_MARGIN - v * v.transpose())),
            0.0,
        )
    }

    /// uᵀIu ≤ m·r(u)², that is tr((𝟙 − u·uᵀ)Σ) ≤ r(u)² in these units.
    fn axis_cut(&self, u: &Vector3<f64>) -> Cut {
        (
            pairing(&(Matrix3::identity() - u * u.transpose())),
            (self.axis_bound)(u),
        )
    }

    /// The cuts that `sigma` violates: an eigenvector of a negative eigenvalue, a principal
    /// axis past its bound, the ellipsoid.
    fn violations(&self, sigma: &Matrix3<f64>) -> Vec<Cut> {
        let mut cuts = Vec::new();
        let eigen = SymmetricEigen::new(*sigma);
        for k in 0..3 {
            let v: Vector3<f64> = eigen.eigenvectors.column(k).into();
            if eigen.eigenvalues[k] < TRIANGLE_MARGIN * sigma.trace() - CUT_SLACK {
                cuts.push(Self::cone_cut(&v));
            }
        }
        // The bound about the principal axes as the audit finds them (massprops' own
        // decomposition of I), and about Σ's eigenvectors.
        let audited = principal_axes(sigma);
        for v in (0..3)
            .map(|k| eigen.eigenvectors.column(k).into_owned())
            .chain(audited)
        {
            let (a, b) = self.axis_cut(&v);
            if dot(&a, sigma) > b + CUT_SLACK {
                cuts.push((a, b));
            }
        }
        if (self.ellipsoid * sigma).trace() > self.ellipsoid_bound + CUT_SLACK {
            cuts.push((pairing(&self.ellipsoid), self.ellipsoid_bound));
        }
        cuts
    }

    /// The cutting-plane rounds.
    fn solve(&self) -> Result<Matrix3<f64>, NearestError> {
        let mut cuts: Vec<Cut> = vec![(pairing(&self.ellipsoid), self.ellipsoid_bound)];
        let stated_axes = SymmetricEigen::new(self.target).eigenvectors;
        let mut seeds: Vec<Vector3<f64>> = directions();
        seeds.extend((0..3).map(|k| stated_axes.column(k).into_owned()));
        for u in &seeds {
            cuts.push(Self::cone_cut(u));
            cuts.push(self.axis_cut(u));
        }
        let mut sigma = self.target;
        for _ in 0..MAX_ROUNDS {
            sigma = self.quadratic_program(&cuts)?;
            let more = self.violations(&sigma);
            if more.is_empty() {
                return Ok(sigma);
            }
            cuts.extend(more);
        }
        // Rounds spent: the last answer is within the cuts' slack of the set and is moved
        // exactly inside by the caller.
        Ok(sigma)
    }

    /// min ‖M(x − t)‖² (the tensor's Frobenius change) subject to the cuts, by clarabel.
    fn quadratic_program(&self, cuts: &[Cut]) -> Result<Matrix3<f64>, NearestError> {
        // Rows of M: ΔI's diagonal is tr(Δ) − Δii; its off-diagonals, counted twice, −√2·Δij.
        let r2 = std::f64::consts::SQRT_2;
        let rows: [[f64; 6]; 6] = [
            [0.0, 1.0, 1.0, 0.0, 0.0, 0.0],
            [1.0, 0.0, 1.0, 0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, -r2, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0, -r2, 0.0],
            [0.0, 0.0, 0.0, 0.0, 0.0, -r2],
        ];
        let mut p = [[0.0; 6]; 6];
        for (i, row) in p.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                // The upper triangle of 2·MᵀM (clarabel reads only that).
                if j >= i {
                    *v = 2.0 * rows.iter().map(|r| r[i] * r[j]).sum::<f64>();
                }
            }
        }
        let t = [
            self.target[(0, 0)],
            self.target[(1, 1)],
            self.target[(2, 2)],
            self.target[(0, 1)],
            self.target[(0, 2)],
            self.target[(1, 2)],
        ];
        let q: Vec<f64> = (0..6)
            .map(|j| -(0..6).map(|i| (p[i.min(j)][i.max(j)]) * t[i]).sum::<f64>())
            .collect();
        let a: Vec<[f64; 6]> = cuts.iter().map(|c| c.0).collect();
        let b: Vec<f64> = cuts.iter().map(|c| c.1).collect();
        let hessian = nalgebra::SMatrix::<f64, 6, 6>::from_fn(|i, j| p[i.min(j)][i.max(j)]);
        let p = CscMatrix::from(&p);
        let a = CscMatrix::from(&a);
        let settings = DefaultSettings {
            verbose: false,
            tol_gap_abs: 1e-13,
            tol_gap_rel: 1e-13,
            tol_feas: 1e-13,
            ..DefaultSettings::default()
        };
        let cones = [NonnegativeConeT(b.len())];
        let mut solver = DefaultSolver::new(&p, &q, &a, &b, &cones, settings)
            .map_err(|e| NearestError::Solver(e.to_string()))?;
        solver.solve();
        match solver.solution.status {
            SolverStatus::Solved | SolverStatus::AlmostSolved => {}
            other => return Err(NearestError::Solver(format!("{other:?}"))),
        }
        let x = &solver.solution.x;
        Ok(unpack(
            &polish(&hessian, &q, cuts, x, &solver.solution.z).unwrap_or_else(|| x.clone()),
        ))
    }

    /// `sigma` moved exactly inside: negative eigenvalues set to zero, then scaled down to the
    /// ellipsoid and to the axis bound about its principal axes (scaling down keeps Σ ⪰ 0 and
    /// lowers every bounded quantity, all of which are non-negative for Σ ⪰ 0).
    fn exactly_inside(&self, sigma: Matrix3<f64>) -> Matrix3<f64> {
        let mut eigen = SymmetricEigen::new(sigma);
        // Raising one eigenvalue raises the trace: the floor is the margin of the new trace,
        // λ ≥ margin·(t + λ − λ_old) solved for λ, with t the trace of the rest.
        let trace: f64 = eigen.eigenvalues.iter().map(|l| l.max(0.0)).sum();
        let floor = TRIANGLE_MARGIN * trace / (1.0 - 2.0 * TRIANGLE_MARGIN);
        for l in eigen.eigenvalues.iter_mut() {
            *l = l.max(floor);
        }
        let clipped = eigen.recompose();
        let mut factor: f64 = 1.0;
        let e = (self.ellipsoid * clipped).trace();
        if e > self.ellipsoid_bound {
            factor = factor.min(self.ellipsoid_bound / e);
        }
        for (u, bound) in self.certified_axes(&clipped) {
            let value = dot(&self.axis_cut(&u).0, &clipped);
            if value > bound {
                factor = factor.min(bound / value);
            }
        }
        if factor < 1.0 {
            clipped * factor
        } else {
            clipped
        }
    }

    /// The axes whose bound must hold for the audit to find nothing, each with a bound on
    /// r(u)² that is certain: the principal axes as the audit finds them with their own r(u)²;
    /// where two moments are equal (to 1e-6) the audit's axes in their plane are any, so the
    /// whole plane, sampled every 0.05° with r lowered by spread × the angle to the nearest
    /// sample (the most r can change over it).
    fn certified_axes(&self, sigma: &Matrix3<f64>) -> Vec<(Vector3<f64>, f64)> {
        let inertia = tensor(sigma);
        let principal = MassProperties::new(1.0, Point3::origin(), inertia).principal;
        let axes: Vec<Vector3<f64>> = (0..3)
            .map(|k| principal.rotation.matrix().column(k).into_owned())
            .collect();
        let moments = principal.moments;
        let mut certified: Vec<(Vector3<f64>, f64)> =
            axes.iter().map(|u| (*u, (self.axis_bound)(u))).collect();
        for (i, j) in [(0, 1), (1, 2), (0, 2)] {
            if (moments[j] - moments[i]).abs() > 1e-6 * moments.amax() {
                continue;
            }
            let samples = 3600;
            let half_step = std::f64::consts::PI / f64::from(samples) / 2.0;
            for s in 0..samples {
                let angle = std::f64::consts::PI * f64::from(s) / f64::from(samples);
                let u = axes[i] * angle.cos() + axes[j] * angle.sin();
                let r = (self.axis_bound)(&u).sqrt() - self.spread * half_step;
                certified.push((u, r.max(0.0).powi(2)));
            }
        }
        certified
    }

    /// The constraints `sigma` lies on.
    fn held(&self, sigma: &Matrix3<f64>, farthest: &dyn Fn(&Vector3<f64>) -> f64) -> Vec<Held> {
        let mut held = Vec::new();
        let eigen = SymmetricEigen::new(*sigma);
        if eigen.eigenvalues.min()
            <= (TRIANGLE_MARGIN + HELD_SLACK) * sigma.trace().max(f64::MIN_POSITIVE)
        {
            held.push(Held::TriangleInequality);
        }
        if (self.ellipsoid * sigma).trace() >= self.ellipsoid_bound * (1.0 - HELD_SLACK) {
            held.push(Held::Ellipsoid);
        }
        // Against the bounds the answer was scaled to (certain ones, lowered in a plane of
        // equal moments), the tightest axis only: in such a plane many are equally tight.
        let tightest = self
            .certified_axes(sigma)
            .into_iter()
            .map(|(u, bound)| (u, dot(&self.axis_cut(&u).0, sigma) / bound))
            .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((u, ratio)) = tightest
            && ratio >= 1.0 - HELD_SLACK
        {
            held.push(Held::AxisBound {
                axis: u,
                radius: farthest(&u),
            });
        }
        held
    }
}

/// An interior-point answer made exact: the quadratic minimised with the constraints it rests
/// on (those with a clearly positive multiplier, independent ones) held as equalities, by the
/// KKT equations. An interior-point method stops within a tolerance of the optimal *value*,
/// and where the target lies far outside the set the value is flat along the face it reaches,
/// so its point can be off by the square root of that tolerance (1e-2 of m·R² was seen); the
/// face's own optimum is exact. `None` (keep the interior-point answer) where the polished
/// point leaves the cuts or needs a negative multiplier.
fn polish(
    hessian: &nalgebra::SMatrix<f64, 6, 6>,
    q: &[f64],
    cuts: &[Cut],
    x: &[f64],
    z: &[f64],
) -> Option<Vec<f64>> {
    let largest = z.iter().copied().fold(0.0, f64::max);
    let mut order: Vec<usize> = (0..cuts.len()).filter(|&k| z[k] > 1e-6 * largest).collect();
    order.sort_by(|&a, &b| z[b].total_cmp(&z[a]));
    let mut active: Vec<usize> = Vec::new();
    for k in order {
        let rows = nalgebra::DMatrix::from_fn(active.len() + 1, 6, |r, c| {
            cuts[*active.get(r).unwrap_or(&k)].0[c]
        });
        if rows.rank(1e-9 * rows.amax()) == active.len() + 1 {
            active.push(k);
        }
    }
    let n = 6 + active.len();
    let mut kkt = nalgebra::DMatrix::zeros(n, n);
    let mut rhs = nalgebra::DVector::zeros(n);
    for i in 0..6 {
        for j in 0..6 {
            kkt[(i, j)] = hessian[(i, j)];
        }
        rhs[i] = -q[i];
    }
    for (r, &k) in active.iter().enumerate() {
        for c in 0..6 {
            kkt[(6 + r, c)] = cuts[k].0[c];
            kkt[(c, 6 + r)] = cuts[k].0[c];
        }
        rhs[6 + r] = cuts[k].1;
    }
    let solution = kkt.lu().solve(&rhs)?;
    let polished: Vec<f64> = solution.iter().take(6).copied().collect();
    let multipliers_ok = solution
        .iter()
        .skip(6)
        .all(|l| *l >= -1e-9 * largest.max(1.0));
    let scale = x.iter().map(|v| v.abs()).fold(1.0, f64::max);
    let inside = cuts.iter().all(|(a, b)| {
        a.iter().zip(&polished).map(|(a, x)| a * x).sum::<f64>() <= b + 1e-12 * scale
    });
    (multipliers_ok && inside && polished.iter().all(|v| v.is_finite())).then_some(polished)
}

/// The principal axes of Σ's tensor as massprops finds them (what the audit checks).
fn principal_axes(sigma: &Matrix3<f64>) -> Vec<Vector3<f64>> {
    let principal = MassProperties::new(1.0, Point3::origin(), tensor(sigma)).principal;
    (0..3)
        .map(|k| principal.rotation.matrix().column(k).into_owned())
        .collect()
}

fn dot(a: &[f64; 6], sigma: &Matrix3<f64>) -> f64 {
    let x = [
        sigma[(0, 0)],
        sigma[(1, 1)],
        sigma[(2, 2)],
        sigma[(0, 1)],
        sigma[(0, 2)],
        sigma[(1, 2)],
    ];
    a.iter().zip(x).map(|(a, x)| a * x).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points spread evenly on a sphere of radius `r` about the origin (a Fibonacci spiral).
    fn sphere_points(r: f64, n: u32) -> Vec<Point3<f64>> {
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        (0..n)
            .map(|k| {
                let z = 1.0 - 2.0 * (f64::from(k) + 0.5) / f64::from(n);
                let s = (1.0 - z * z).sqrt();
                let a = golden * f64::from(k);
                Point3::new(r * s * a.cos(), r * s * a.sin(), r * z)
            })
            .collect()
    }

    fn farthest(points: &[Point3<f64>]) -> impl Fn(&Point3<f64>, &Vector3<f64>) -> f64 + '_ {
        move |c, u| {
            points
                .iter()
                .map(|p| {
                    let v = p - c;
                    (v - u * u.dot(&v)).norm()
                })
                .fold(0.0, f64::max)
        }
    }

    fn box_corners(h: Vector3<f64>) -> Vec<Point3<f64>> {
        crate::primitives::hull_points(&crate::model::Shape::Box { half_extents: h })
            .expect("a box")
    }

    fn nearest_in(points: &[Point3<f64>], stated: &MassProperties) -> Nearest {
        let far = farthest(points);
        let region = Region {
            hull: points,
            farthest_from_line: &far,
            contains: &|_| true,
            center: Point3::origin(),
        };
        nearest(stated, &region).expect("a nearest inertial")
    }

    /// The smallest ellipsoid about a box is √3 times its half-sides (the cube's circumscribed
    /// sphere, stretched), and holds every corner.
    #[test]
    fn the_ellipsoid_of_a_box_has_semi_axes_root_three_half_sides() {
        let h = Vector3::new(0.05, 0.1, 0.2);
        let e = bounding_ellipsoid(&box_corners(h)).expect("an ellipsoid");
        let axes = e.semi_axes();
        for k in 0..3 {
            assert!(
                (axes[k] / (3f64.sqrt() * h[k]) - 1.0).abs() < 1e-9,
                "{axes:?}"
            );
        }
        assert!(e.center.coords.norm() < 1e-15);
        assert!(box_corners(h).iter().all(|p| e.level(p) <= 1.0));
        assert!(bounding_ellipsoid(&box_corners(Vector3::new(0.1, 0.1, 0.0))).is_none());
    }

    /// A ball of radius R holds at most the moments of its surface, 2/3·m·R² (a thin shell:
    /// the ellipsoid bound tr(Σ) ≤ m·R² with Σ = s·𝟙 gives I = 2s ≤ 2/3·m·R²); by symmetry the
    /// nearest to a too-large equal tensor is that. The ball is given by an icosahedron's
    /// corners on it, whose smallest ellipsoid is the ball itself (equal weights are already
    /// Khachiyan's optimum for them), and its exact reach from any axis, R.
    #[test]
    fn the_nearest_in_a_ball_is_the_thin_shell() {
        let (m, r) = (2.0, 0.1);
        let phi = (1.0 + 5f64.sqrt()) / 2.0;
        let mut points = Vec::new();
        for a in [-1.0, 1.0] {
            for b in [-phi, phi] {
                for v in [[0.0, a, b], [a, b, 0.0], [b, 0.0, a]] {
                    points.push(Point3::from(Vector3::from(v).normalize() * r));
                }
            }
        }
        let stated = MassProperties::new(m, Point3::origin(), Matrix3::identity() * 0.5);
        let region = Region {
            hull: &points,
            farthest_from_line: &|_, _| r,
            contains: &|_| true,
            center: Point3::origin(),
        };
        let n = nearest(&stated, &region).expect("a nearest inertial");
        let shell = 2.0 / 3.0 * m * r * r;
        for k in 0..3 {
            let moment = n.properties.principal.moments[k];
            assert!((moment / shell - 1.0).abs() < 1e-9, "{moment} vs {shell}");
        }
        assert!(n.held_by.contains(&Held::Ellipsoid), "{:?}", n.held_by);
        assert!(n.center_kept);
        assert!((n.moved - (stated.inertia_com - n.properties.inertia_com).norm()).abs() < 1e-15);
    }

    /// Moments 1, 1, 3 break the triangle inequality by 1; with room enough, the nearest
    /// tensor in the Frobenius norm is the projection onto I₁ + I₂ = I₃ along (1, 1, −1)/√3:
    /// 4/3, 4/3, 8/3, moved by 1/√3; with the margin ε, onto Σ₃₃ = ε·tr(Σ). In Σ the metric
    /// is W = 𝟙 + 𝟏𝟏ᵀ on the diagonal, so the step onto the plane aᵀΔ = c is
    /// c·W⁻¹a / (aᵀW⁻¹a), W⁻¹ = 𝟙 − 𝟏𝟏ᵀ/4.
    #[test]
    fn a_broken_triangle_inequality_is_projected_onto_it() {
        let points = box_corners(Vector3::new(10.0, 10.0, 10.0));
        let stated = MassProperties::new(
            1.0,
            Point3::origin(),
            Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 3.0)),
        );
        let n = nearest_in(&points, &stated);
        let e = TRIANGLE_MARGIN;
        let sigma = Vector3::new(1.5, 1.5, -0.5);
        let a = Vector3::new(-e, -e, 1.0 - e);
        let c = -a.dot(&sigma);
        let w_inverse = Matrix3::identity() - Matrix3::repeat(0.25);
        let step = w_inverse * a * (c / a.dot(&(w_inverse * a)));
        let expected = tensor(&Matrix3::from_diagonal(&(sigma + step)));
        assert!(
            (n.properties.inertia_com - expected).amax() < 1e-9,
            "{} vs {expected}",
            n.properties.inertia_com
        );
        // Without the margin: 4/3, 4/3, 8/3 and 1/√3.
        let bare = Matrix3::from_diagonal(&Vector3::new(4.0, 4.0, 8.0)) / 3.0;
        assert!((expected - bare).amax() < 1e-5);
        assert!((n.moved - 1.0 / 3f64.sqrt()).abs() < 1e-5);
        assert_eq!(n.held_by, vec![Held::TriangleInequality]);
    }

    /// A valid inertial is its own nearest.
    #[test]
    fn a_valid_inertial_stays() {
        let h = Vector3::new(0.1, 0.2, 0.3);
        let solid =
            crate::primitives::unit_properties(&crate::model::Shape::Box { half_extents: h })
                .expect("a box");
        let n = nearest_in(&box_corners(h), &solid);
        assert_eq!(n.properties.inertia_com, solid.inertia_com);
        assert_eq!((n.moved, n.held_by.clone()), (0.0, Vec::new()));
    }

    /// On a tilted box and a stated tensor far outside (too large, skewed), the answer is in
    /// the set and no valid tensor is nearer: the gradient of the distance at the answer
    /// points into the half-space of every valid Σ' tried (the first-order condition of a
    /// convex program), for random Σ' spread over the set and near the answer.
    #[test]
    fn nothing_valid_is_nearer() {
        let rotation = nalgebra::Rotation3::from_euler_angles(0.3, -0.7, 1.1);
        let points: Vec<Point3<f64>> = box_corners(Vector3::new(0.1, 0.05, 0.025))
            .iter()
            .map(|p| rotation * p)
            .collect();
        let m = 3.0;
        let stated = MassProperties::new(
            m,
            Point3::origin(),
            Matrix3::new(
                0.02, 0.004, -0.003, 0.004, 0.001, 0.002, -0.003, 0.002, 0.03,
            ),
        );
        let n = nearest_in(&points, &stated);
        let sigma = second_moment(&n.properties.inertia_com);
        let e = &n.ellipsoid;
        let far = farthest(&points);
        let valid = |s: &Matrix3<f64>| {
            let i = tensor(s);
            s.symmetric_eigenvalues().min() >= -1e-15
                && (e.shape * s).trace() <= m * (1.0 - e.level(&Point3::origin())) * (1.0 + 1e-12)
                && sphere_points(1.0, 2000).iter().all(|u| {
                    let u = u.coords;
                    let r = far(&Point3::origin(), &u);
                    u.dot(&(i * u)) <= m * r * r * (1.0 + 1e-9)
                })
        };
        assert!(valid(&sigma), "{sigma}");
        assert!(n.moved > 0.0 && !n.held_by.is_empty());
        let delta = sigma - second_moment(&stated.inertia_com);
        let gradient = (delta + Matrix3::identity() * delta.trace()) * 2.0;
        // Random valid Σ': B·Bᵀ scaled into the set, and steps from the answer towards them.
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut random = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let mut tried = 0;
        for _ in 0..400 {
            let b = Matrix3::from_fn(|_, _| random());
            let mut other = b * b.transpose();
            while !valid(&other) {
                other *= 0.5;
            }
            for t in [1.0, 0.1, 0.01] {
                let candidate = sigma + (other - sigma) * t;
                let slope = (gradient.transpose() * (candidate - sigma)).trace();
                assert!(slope >= -1e-9 * m * 0.01 * t, "slope {slope} at t = {t}");
                tried += 1;
            }
        }
        assert_eq!(tried, 1200);
    }

    /// A stated centre outside the geometry is not kept: the geometry's is taken.
    #[test]
    fn a_centre_outside_is_replaced() {
        let points = box_corners(Vector3::new(0.1, 0.1, 0.1));
        let far = farthest(&points);
        let region = Region {
            hull: &points,
            farthest_from_line: &far,
            contains: &|c| c.coords.amax() <= 0.1,
            center: Point3::new(0.01, 0.0, 0.0),
        };
        let stated = MassProperties::new(1.0, Point3::new(0.5, 0.0, 0.0), Matrix3::identity());
        let n = nearest(&stated, &region).expect("a nearest inertial");
        assert!(!n.center_kept);
        assert_eq!(n.properties.center_of_mass, Point3::new(0.01, 0.0, 0.0));
    }
}
