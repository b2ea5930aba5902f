//! THE one place where frames, handedness, units and sign conventions are converted.
//!
//! Every exporter receives a [`Converted`] body built here and only formats its numbers.
//!
//! **Source frame.** The mesh's own coordinates: right-handed, lengths in the declared
//! [`LengthUnit`], "up" the declared [`UpAxis`]. `massprops` gives the mass in kg (the caller
//! chose the density per mesh unit³ with [`density_per_cubic_unit`], or a mass), the centre of
//! mass in mesh units and the tensor about it in kg·unit², tensor convention (off-diagonals
//! −∑m·x·y).
//!
//! **Target frames** ([`Axes`]), each reached from the source by one orthogonal matrix `A`
//! (`p_target = A · p_mesh`):
//!
//! 1. *Up axis*: a Y-up mesh goes to a Z-up target by the +90° rotation about x, `(x, y, z) →
//!    (x, −z, y)`; a Z-up mesh goes to a Y-up target by the inverse, `(x, y, z) → (x, z, −y)`,
//!    the mapping Blender's glTF and OBJ exporters use (glTF 2.0 §3.4: "+Y is up").
//! 2. *Handedness*: a left-handed target mirrors one axis after that, the one its own model
//!    importer mirrors, so the numbers land on the mesh as the engine imported it. Unity negates
//!    **x** when it converts right-handed FBX/OBJ files (LightWave's Unity mode switch notes:
//!    "Unity uses the X axis, which results in an apparent 180 degree rotation"); Unreal negates
//!    **y** (`FFbxDataConverter::ConvertPos`: "flip Y, then the right-handed axis system is
//!    converted to LHS").
//!
//! **Tensors.** `I = ∫ρ(|r|²E − r rᵀ)dV` is quadratic in `r`, so for any orthogonal `A`, proper
//! or a mirror, the tensor in the target frame is exactly `A I Aᵀ`, with no extra signs; the
//! mirrored products of inertia change sign through `A` alone. The principal axes become `A R`;
//! when `det A = −1` the third axis is negated so they stay a proper rotation of the target
//! frame (the moments are unchanged, since `S D S = D` for `S = diag(1, 1, −1)`).
//!
//! **Units.** Lengths scale by `s = mesh unit / target unit` (metres per unit from
//! [`LengthUnit::metres`]), the mass is already in kg, so the centre of mass scales by `s` and
//! the tensor by `s²` (kg·m² for SI targets, kg·cm² for Unreal).
//!
//! **Rotations out.** Quaternions are Hamilton quaternions with `w ≥ 0` whose rotation maps
//! principal-axes coordinates to body coordinates (`R = quat_to_matrix(q)`, column i = axis i);
//! each format writes the components in its own order. Roll-pitch-yaw angles are URDF's and
//! SDFormat's fixed-axis convention `R = Rz(yaw) · Ry(pitch) · Rx(roll)`.
//!
//! **Sign conventions of the products of inertia.** Every target here stores tensor entries
//! (`ixy = I₁₂ = −∑m·x·y`): URDF (`<inertia>` "the 3x3 rotational inertia matrix"), SDFormat
//! (the same six `<ixx>…<izz>` of the matrix), MJCF `fullinertia` ("full inertia matrix M …
//! M(1,1), M(2,2), M(3,3), M(1,2), M(1,3), M(2,3)"). No format here takes the positive
//! product-of-inertia convention (∑m·x·y) some CAD tools print, so no sign flip is applied.

use massprops::{LengthUnit, MassProperties};
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use super::ExportError;
use crate::choice::Choice;

/// Which mesh axis points up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UpAxis {
    /// +Y is up (OBJ from most tools, glTF, Unity, Godot).
    Y,
    /// +Z is up (CAD, Blender's own frame, ROS, Gazebo, MuJoCo, Unreal).
    Z,
}

impl Choice for UpAxis {
    const OPTION: &'static str = "up";
    const ALL: &'static [Self] = &[UpAxis::Y, UpAxis::Z];

    fn name(self) -> &'static str {
        match self {
            UpAxis::Y => "y",
            UpAxis::Z => "z",
        }
    }

    fn help(self) -> &'static str {
        match self {
            UpAxis::Y => "+Y is up (OBJ from most tools, glTF, Unity, Godot)",
            UpAxis::Z => "+Z is up (CAD, Blender's own frame, ROS, Gazebo, MuJoCo, Unreal)",
        }
    }
}

/// A density in kg/m³ turned into kg per cubic mesh unit, for integrating the mesh as it is.
pub fn density_per_cubic_unit(kg_per_m3: f64, unit: LengthUnit) -> f64 {
    kg_per_m3 * unit.metres().powi(3)
}

/// The coordinate system a target reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axes {
    /// The mesh's own axes, whatever its up axis (our JSON).
    Mesh,
    /// Right-handed, +Y up (glTF, Godot, Bevy/rapier).
    RightYUp,
    /// Right-handed, +Z up (URDF/ROS, SDFormat/Gazebo, MuJoCo).
    RightZUp,
    /// Unity: left-handed, +Y up, the mesh mirrored in x as Unity's importer does.
    UnityLeftYUp,
    /// Unreal: left-handed, +Z up, the mesh mirrored in y as Unreal's importer does.
    UnrealLeftZUp,
}

impl Axes {
    fn up(self, source_up: UpAxis) -> UpAxis {
        match self {
            Axes::Mesh => source_up,
            Axes::RightYUp | Axes::UnityLeftYUp => UpAxis::Y,
            Axes::RightZUp | Axes::UnrealLeftZUp => UpAxis::Z,
        }
    }

    /// The axis negated after the up conversion, for left-handed targets.
    fn mirrored_axis(self) -> Option<usize> {
        match self {
            Axes::Mesh | Axes::RightYUp | Axes::RightZUp => None,
            Axes::UnityLeftYUp => Some(0),
            Axes::UnrealLeftZUp => Some(1),
        }
    }

    /// One phrase for output comments.
    pub fn describe(self) -> &'static str {
        match self {
            Axes::Mesh => "the mesh's own (right-handed)",
            Axes::RightYUp => "right-handed, +Y up",
            Axes::RightZUp => "right-handed, +Z up",
            Axes::UnityLeftYUp => {
                "Unity's left-handed, +Y up (x mirrored, as Unity's importer does)"
            }
            Axes::UnrealLeftZUp => {
                "Unreal's left-handed, +Z up (y mirrored, as Unreal's importer does)"
            }
        }
    }
}

/// The orthogonal matrix taking mesh coordinates to target coordinates (`det = ±1`).
pub fn axis_map(source_up: UpAxis, target: Axes) -> Matrix3<f64> {
    let up = match (source_up, target.up(source_up)) {
        (UpAxis::Y, UpAxis::Y) | (UpAxis::Z, UpAxis::Z) => Matrix3::identity(),
        // (x, y, z) → (x, −z, y): +90° about x.
        (UpAxis::Y, UpAxis::Z) => Matrix3::new(1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0),
        // (x, y, z) → (x, z, −y): −90° about x.
        (UpAxis::Z, UpAxis::Y) => Matrix3::new(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0),
    };
    let mut mirror = Matrix3::identity();
    if let Some(i) = target.mirrored_axis() {
        mirror[(i, i)] = -1.0;
    }
    mirror * up
}

/// How target coordinates read in mesh coordinates, e.g. `(x, -z, y)`.
pub fn describe_map(a: &Matrix3<f64>) -> String {
    let names = ["x", "y", "z"];
    let parts: Vec<String> = (0..3)
        .map(|row| {
            (0..3)
                .find(|&col| a[(row, col)] != 0.0)
                .map(|col| {
                    let sign = if a[(row, col)] < 0.0 { "-" } else { "" };
                    format!("{sign}{}", names[col])
                })
                .unwrap_or_default()
        })
        .collect();
    format!("({})", parts.join(", "))
}

/// What a conversion starts from and aims at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Conversion {
    /// The mesh's length unit.
    pub source_unit: LengthUnit,
    /// The mesh's up axis.
    pub source_up: UpAxis,
    /// The target's axes.
    pub target: Axes,
    /// The target's length unit (metres everywhere but Unreal).
    pub target_unit: LengthUnit,
}

/// A body in a target's frame and units: everything an exporter writes.
#[derive(Debug, Clone, PartialEq)]
pub struct Converted {
    /// What was converted.
    pub conversion: Conversion,
    /// Mesh coordinates → target coordinates.
    pub map: Matrix3<f64>,
    /// kg.
    pub mass: f64,
    /// Centre of mass, target axes and length unit.
    pub center_of_mass: Vector3<f64>,
    /// Tensor about the centre of mass, target axes, kg·(target unit)², off-diagonals −∑m·x·y.
    pub inertia: Matrix3<f64>,
    /// Tensor about the target frame's origin (the mesh origin), same axes and units.
    pub inertia_origin: Matrix3<f64>,
    /// Principal moments, ascending, kg·(target unit)².
    pub moments: Vector3<f64>,
    /// Proper rotation of the target frame whose column i is the axis of `moments[i]`.
    pub principal: Rotation3<f64>,
}

impl Converted {
    /// The principal rotation as a unit quaternion `[w, x, y, z]` with `w ≥ 0`.
    pub fn principal_quaternion(&self) -> [f64; 4] {
        quaternion_wxyz(&self.principal)
    }

    /// Largest |off-diagonal| of the body-axes tensor relative to the largest moment.
    pub fn off_diagonal_ratio(&self) -> f64 {
        let i = &self.inertia;
        let off = i[(0, 1)].abs().max(i[(0, 2)].abs()).max(i[(1, 2)].abs());
        off / self.moments[2]
    }
}

/// Products of inertia smaller than this times the largest moment count as zero.
pub const AXIS_ALIGNED_TOLERANCE: f64 = 1e-10;

/// Relative slack of the triangle test, for bodies that are (nearly) flat laminae.
const TRIANGLE_TOLERANCE: f64 = 1e-12;

/// Checks `props` and converts it into the target frame and units.
pub fn convert(props: &MassProperties, conversion: Conversion) -> Result<Converted, ExportError> {
    check_physical(props)?;
    let map = axis_map(conversion.source_up, conversion.target);
    let s = conversion.source_unit.metres() / conversion.target_unit.metres();
    let center_of_mass = map * props.center_of_mass.coords * s;
    let inertia = map * props.inertia_com * map.transpose() * (s * s);
    let mut axes = map * props.principal.rotation.matrix();
    if axes.determinant() < 0.0 {
        axes.column_mut(2).neg_mut();
    }
    let parallel = (Matrix3::identity() * center_of_mass.norm_squared()
        - center_of_mass * center_of_mass.transpose())
        * props.mass;
    Ok(Converted {
        conversion,
        map,
        mass: props.mass,
        center_of_mass,
        inertia,
        inertia_origin: inertia + parallel,
        moments: props.principal.moments * (s * s),
        principal: Rotation3::from_matrix_unchecked(axes),
    })
}

/// Refuses what no engine can simulate: a non-positive or non-finite mass, a tensor that is not
/// positive definite, or principal moments that break the triangle inequality.
pub fn check_physical(props: &MassProperties) -> Result<(), ExportError> {
    let m = props.principal.moments;
    let finite = props.mass.is_finite()
        && props.center_of_mass.coords.iter().all(|v| v.is_finite())
        && props.inertia_com.iter().all(|v| v.is_finite());
    if !finite || props.mass <= 0.0 {
        return Err(ExportError::NotFinite { mass: props.mass });
    }
    if m[0] <= 0.0 {
        return Err(ExportError::NotPositiveDefinite {
            moments: [m[0], m[1], m[2]],
        });
    }
    if m[0] + m[1] < m[2] * (1.0 - TRIANGLE_TOLERANCE) {
        return Err(ExportError::TriangleInequality {
            moments: [m[0], m[1], m[2]],
            excess: (m[2] - m[0] - m[1]) / m[2],
        });
    }
    Ok(())
}

/// A proper rotation as `[w, x, y, z]` with `w ≥ 0`.
pub fn quaternion_wxyz(rotation: &Rotation3<f64>) -> [f64; 4] {
    let q = UnitQuaternion::from_rotation_matrix(rotation);
    let c = q.coords; // nalgebra stores [x, y, z, w]
    let sign = if c.w < 0.0 { -1.0 } else { 1.0 };
    // Adding 0.0 turns a -0.0 into 0.0.
    [
        c.w * sign + 0.0,
        c.x * sign + 0.0,
        c.y * sign + 0.0,
        c.z * sign + 0.0,
    ]
}

/// Fixed-axis roll, pitch, yaw (URDF, SDFormat): `R = Rz(yaw) · Ry(pitch) · Rx(roll)`.
///
/// At gimbal lock (pitch = ±π/2) roll is set to zero and yaw carries the whole turn.
pub fn roll_pitch_yaw(rotation: &Rotation3<f64>) -> [f64; 3] {
    let r = rotation.matrix();
    let cos_pitch = r[(0, 0)].hypot(r[(1, 0)]);
    let pitch = (-r[(2, 0)]).atan2(cos_pitch);
    if cos_pitch > 1e-9 {
        [
            r[(2, 1)].atan2(r[(2, 2)]),
            pitch,
            r[(1, 0)].atan2(r[(0, 0)]),
        ]
    } else {
        // R = Rz(yaw)·Ry(±π/2): r01 = −sin(yaw), r11 = cos(yaw).
        [0.0, pitch, (-r[(0, 1)]).atan2(r[(1, 1)])]
    }
}

/// A number as the shortest decimal that reads back as the same `f64` (no `-0`).
pub fn num(v: f64) -> String {
    if v == 0.0 {
        "0.0".to_owned()
    } else {
        format!("{v:?}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use massprops::{MassProperties, shapes};
    use nalgebra::{Isometry3, Point3, Translation3};

    fn asymmetric() -> MassProperties {
        let motion = Isometry3::from_parts(
            Translation3::new(0.3, -0.2, 0.7),
            UnitQuaternion::from_euler_angles(0.4, -1.1, 2.3),
        );
        let mesh = shapes::l_bracket().transformed(&motion).build();
        massprops::mass_properties(&mesh, 2700.0).expect("closed mesh")
    }

    fn rpy_matrix(rpy: [f64; 3]) -> Matrix3<f64> {
        let [r, p, y] = rpy;
        *(Rotation3::from_axis_angle(&Vector3::z_axis(), y)
            * Rotation3::from_axis_angle(&Vector3::y_axis(), p)
            * Rotation3::from_axis_angle(&Vector3::x_axis(), r))
        .matrix()
    }

    #[test]
    fn maps_are_orthogonal_with_the_documented_handedness() {
        for up in [UpAxis::Y, UpAxis::Z] {
            for (axes, det) in [
                (Axes::Mesh, 1.0),
                (Axes::RightYUp, 1.0),
                (Axes::RightZUp, 1.0),
                (Axes::UnityLeftYUp, -1.0),
                (Axes::UnrealLeftZUp, -1.0),
            ] {
                let a = axis_map(up, axes);
                assert_eq!(a * a.transpose(), Matrix3::identity());
                assert_eq!(a.determinant(), det);
            }
        }
        // The mesh's up goes to the target's up.
        let a = axis_map(UpAxis::Y, Axes::RightZUp);
        assert_eq!(a * Vector3::y(), Vector3::z());
        assert_eq!(describe_map(&a), "(x, -z, y)");
        let a = axis_map(UpAxis::Z, Axes::RightYUp);
        assert_eq!(a * Vector3::z(), Vector3::y());
        assert_eq!(describe_map(&a), "(x, z, -y)");
        assert_eq!(
            describe_map(&axis_map(UpAxis::Y, Axes::UnityLeftYUp)),
            "(-x, y, z)"
        );
        assert_eq!(
            describe_map(&axis_map(UpAxis::Y, Axes::UnrealLeftZUp)),
            "(x, z, y)"
        );
    }

    #[test]
    fn conversion_keeps_the_tensor_and_the_principal_decomposition() {
        let p = asymmetric();
        for target in [
            Axes::Mesh,
            Axes::RightYUp,
            Axes::RightZUp,
            Axes::UnityLeftYUp,
            Axes::UnrealLeftZUp,
        ] {
            let c = convert(
                &p,
                Conversion {
                    source_unit: LengthUnit::Mm,
                    source_up: UpAxis::Y,
                    target,
                    target_unit: LengthUnit::Cm,
                },
            )
            .expect("physical");
            let r = c.principal.matrix();
            assert!((r.determinant() - 1.0).abs() < 1e-14);
            let rebuilt = r * Matrix3::from_diagonal(&c.moments) * r.transpose();
            assert!((rebuilt - c.inertia).amax() <= 1e-13 * c.inertia.amax());
            // Back to the mesh frame in mesh units: mm → cm is ×0.1, so I × 0.01.
            let back = c.map.transpose() * c.inertia * c.map * 100.0;
            assert!((back - p.inertia_com).amax() <= 1e-13 * p.inertia_com.amax());
            let com = c.map.transpose() * c.center_of_mass * 10.0;
            assert!((com - p.center_of_mass.coords).amax() < 1e-15);
            let origin = p.inertia_about(&Point3::origin());
            let back = c.map.transpose() * c.inertia_origin * c.map * 100.0;
            assert!((back - origin).amax() <= 1e-12 * origin.amax());
        }
    }

    #[test]
    fn rpy_and_quaternion_round_trip_including_gimbal_lock() {
        for rpy in [
            [0.3, -0.4, 2.9],
            [-3.0, 1.2, -0.1],
            [0.0, std::f64::consts::FRAC_PI_2, 0.7],
            [0.5, -std::f64::consts::FRAC_PI_2, -2.0],
        ] {
            let r = Rotation3::from_matrix_unchecked(rpy_matrix(rpy));
            let back = rpy_matrix(roll_pitch_yaw(&r));
            assert!((back - r.matrix()).amax() < 1e-12, "{rpy:?}");
            let [w, x, y, z] = quaternion_wxyz(&r);
            assert!(w >= 0.0);
            let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(w, x, y, z));
            assert!((q.to_rotation_matrix().matrix() - r.matrix()).amax() < 1e-14);
        }
    }

    #[test]
    fn refuses_unphysical_tensors() {
        let bad = MassProperties::new(
            1.0,
            Point3::origin(),
            Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 3.0)),
        );
        assert!(matches!(
            check_physical(&bad),
            Err(ExportError::TriangleInequality { .. })
        ));
        let bad = MassProperties::new(
            1.0,
            Point3::origin(),
            Matrix3::new(1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0),
        );
        assert!(matches!(
            check_physical(&bad),
            Err(ExportError::NotPositiveDefinite { .. })
        ));
        let bad = MassProperties::new(f64::NAN, Point3::origin(), Matrix3::identity());
        assert!(matches!(
            check_physical(&bad),
            Err(ExportError::NotFinite { .. })
        ));
        // A lamina (I1 + I2 = I3 up to round-off) is physical.
        let plate = MassProperties::new(
            1.0,
            Point3::origin(),
            Matrix3::from_diagonal(&Vector3::new(0.1, 0.2, 0.3)),
        );
        assert!(check_physical(&plate).is_ok());
        assert_eq!(num(-0.0), "0.0");
        assert_eq!(num(1e-20), "1e-20");
        assert_eq!(num(0.5), "0.5");
        assert!((density_per_cubic_unit(1000.0, LengthUnit::Cm) - 1e-3).abs() < 1e-18);
    }
}
