//! The user's settings: plain structs, persisted between runs through eframe's storage (serde,
//! RON), kept apart from the model's state and from GPU resources. Every field is applied live.

use rbcore::{Damping, Integrator, RotationModel};
use serde::{Deserialize, Serialize};

use crate::i18n::tr;

/// Everything the user can set, grouped as in the side panel.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct AppSettings {
    /// What the 3D view draws.
    pub view: ViewSettings,
    /// Integrator, forces and time.
    pub physics: PhysicsSettings,
    /// Size, mass and which inertia the simulation uses.
    pub body: BodySettings,
    /// The mouse string and the poke.
    pub interaction: InteractionSettings,
    /// The plot panel.
    pub plots: PlotSettings,
    /// The language, the size of everything and how much moves by itself.
    pub display: DisplaySettings,
}

/// How the lab reads and moves for its user: the language, larger text, reduced motion and the
/// page's own voice.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct DisplaySettings {
    /// The language chosen; `None` follows the system's (the browser's in a page).
    pub language: Option<crate::i18n::Language>,
    /// Everything drawn a quarter larger (text, buttons, plots), as a browser's zoom does.
    pub larger_text: bool,
    /// Nothing moves unless the user starts it: a body opened or a lesson's step set up waits
    /// paused for Run, and panels open without sliding.
    pub reduced_motion: bool,
    /// The page reads aloud what takes the keyboard's focus (egui's own screen reader, through
    /// the browser's speech synthesis; the desktop has AccessKit for real screen readers).
    pub read_aloud: bool,
}

/// Overlays of the 3D view.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ViewSettings {
    /// Polygon edges over the shaded mesh.
    pub wireframe: bool,
    /// The mesh's bounding box (the cuboid the bounding-box approximation fills).
    pub bounding_box: bool,
    /// Centre-of-mass marker.
    pub center_of_mass: bool,
    /// Principal axes (1 red, 2 green, 3 blue; moments ascending).
    pub principal_axes: bool,
    /// The uniform box or ellipsoid with the same mass and principal moments.
    pub equivalent: Equivalent,
    /// World arrow of ω.
    pub omega_arrow: bool,
    /// World arrow of L (fixed in space while no torque acts).
    pub l_arrow: bool,
    /// The camera moves with the centre of mass (a poked body stays in view).
    pub follow_body: bool,
    /// The momentum sphere beside the 3D view: L in the principal frame on its polhode.
    pub momentum_sphere: bool,
    /// Where compared copies are drawn.
    pub ghosts: GhostLayout,
    /// Poinsot's construction: the inertia ellipsoid rolling on the invariable plane, and the
    /// herpolhode traced where they touch.
    pub poinsot: bool,
}

/// Where the compared copies' translucent ghosts are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum GhostLayout {
    /// Over the primary body, so that they drift apart in place.
    #[default]
    Overlaid,
    /// Side by side in a row along the view's right, one body width apart.
    Row,
}

impl Default for ViewSettings {
    fn default() -> Self {
        Self {
            wireframe: false,
            bounding_box: false,
            center_of_mass: true,
            principal_axes: true,
            equivalent: Equivalent::None,
            omega_arrow: true,
            l_arrow: true,
            follow_body: true,
            momentum_sphere: true,
            ghosts: GhostLayout::Overlaid,
            poinsot: false,
        }
    }
}

/// The equivalent-inertia shape drawn over the body.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Equivalent {
    /// Nothing.
    #[default]
    None,
    /// Solid box: full edge `aᵢ = √(6 (Iⱼ + Iₖ − Iᵢ) / m)`.
    Box,
    /// Solid ellipsoid: semi-axis `aᵢ = √(5 (Iⱼ + Iₖ − Iᵢ) / (2m))`.
    Ellipsoid,
}

/// Simulation settings (mapped onto [`rbcore::Settings`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PhysicsSettings {
    /// Integrator (stored by its command-line name).
    #[serde(with = "by_name")]
    pub integrator: Integrator,
    /// Rotation model (stored by name).
    #[serde(with = "by_name")]
    pub model: RotationModel,
    /// Gravity (m/s²) along world −y; 0 for the free body.
    pub gravity: f64,
    /// Linear damping rate (1/s).
    pub linear_damping: f64,
    /// Angular damping rate (1/s).
    pub angular_damping: f64,
    /// Simulated seconds per wall-clock second.
    pub time_scale: f64,
    /// Fixed time step (s).
    pub dt: f64,
    /// A switch of the inertia source or the rotation model starts every specimen again from
    /// the same start (the preset spin), so that the two runs compare fairly; off, the motion
    /// goes on from the current state with the new inertia or model.
    pub restart_on_switch: bool,
}

impl Default for PhysicsSettings {
    fn default() -> Self {
        let s = rbcore::Settings::default();
        Self {
            integrator: s.integrator,
            model: s.model,
            gravity: 0.0,
            linear_damping: 0.0,
            angular_damping: 0.0,
            time_scale: 1.0,
            dt: s.dt,
            restart_on_switch: true,
        }
    }
}

impl PhysicsSettings {
    /// The simulation settings these stand for (validated by `rbcore` when applied).
    pub fn to_sim(&self) -> rbcore::Settings {
        rbcore::Settings {
            dt: self.dt,
            integrator: self.integrator,
            model: self.model,
            gravity: nalgebra::Vector3::new(0.0, -self.gravity, 0.0),
            damping: Damping {
                linear: self.linear_damping,
                angular: self.angular_damping,
            },
            ..rbcore::Settings::default()
        }
    }
}

/// A rotation model in the user's words ([`RotationModel::name`] is the command line's).
pub fn model_words(model: RotationModel) -> String {
    match model {
        RotationModel::Full => tr!("model-full"),
        RotationModel::Textbook => tr!("model-textbook"),
    }
}

/// Which mass properties drive the simulation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum InertiaSource {
    /// The exact solid (Mirtich).
    #[default]
    Exact,
    /// A solid cuboid filling the bounding box (Bullet, Blender, older Godot).
    BoundingBox,
    /// Equal point masses at the vertices.
    PointMasses,
    /// What a robot description states for the link shown (when it states one).
    Stated,
}

impl InertiaSource {
    /// All sources, in table order.
    pub const ALL: [InertiaSource; 4] = [
        InertiaSource::Exact,
        InertiaSource::BoundingBox,
        InertiaSource::PointMasses,
        InertiaSource::Stated,
    ];

    /// Label in the UI, in the user's language.
    pub fn label(self) -> String {
        match self {
            InertiaSource::Exact => tr!("source-exact"),
            InertiaSource::BoundingBox => tr!("source-bounding-box"),
            InertiaSource::PointMasses => tr!("source-point-masses"),
            InertiaSource::Stated => tr!("source-stated"),
        }
    }
}

/// How the body's mass is given.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum MassGiven {
    /// Uniform density (kg/m³); mass follows volume.
    Density(f64),
    /// Total mass (kg); density follows.
    Mass(f64),
}

/// Size, mass and inertia source.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct BodySettings {
    /// Uniform scale applied to the mesh.
    pub scale: f64,
    /// Density or mass.
    pub mass: MassGiven,
    /// The inertia the simulation uses.
    pub source: InertiaSource,
    /// Spin rate of the presets (rad/s).
    pub spin_rate: f64,
}

impl Default for BodySettings {
    fn default() -> Self {
        Self {
            scale: 1.0,
            // Water: the T-handle comes out at about 19 g; steel would be 7800.
            mass: MassGiven::Density(1000.0),
            source: InertiaSource::Exact,
            spin_rate: 8.0,
        }
    }
}

/// The mouse string (Catto's soft constraint) and the poke.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct InteractionSettings {
    /// String stiffness as a frequency (Hz).
    pub string_frequency: f64,
    /// String damping ratio (1 = critical).
    pub string_damping: f64,
    /// Force cap as an acceleration of the whole mass (m/s²): `F_max = m·a_max`, so one setting
    /// suits a 19 g handle and a 200 kg book alike.
    pub string_max_accel: f64,
    /// How much a poke changes L, as a fraction of |L|, at most (a poke at the point of the body
    /// farthest from its centre of mass, across the lever arm); while the body is at rest, of
    /// the |L| a spin at the spin rate about axis 3 would have. Small by default, so that a
    /// stable spin stays stable: a nudge, not a new motion.
    pub poke_fraction: f64,
}

impl Default for InteractionSettings {
    fn default() -> Self {
        Self {
            string_frequency: 2.0,
            string_damping: 0.7,
            string_max_accel: 50.0,
            poke_fraction: 0.05,
        }
    }
}

/// The plot panel.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PlotSettings {
    /// Visible time window (s).
    pub window: f64,
    /// History kept (s); bounds memory and the CSV export.
    pub history: f64,
}

impl Default for PlotSettings {
    fn default() -> Self {
        Self {
            window: 20.0,
            history: 60.0,
        }
    }
}

/// Serde through `Display` / `FromStr`, for rbcore's enums (which stay serde-free).
mod by_name {
    use std::fmt::Display;
    use std::str::FromStr;

    use serde::{Deserialize, Deserializer, Serializer, de::Error};

    pub fn serialize<T: Display, S: Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(v)
    }

    pub fn deserialize<'de, T, D>(d: D) -> Result<T, D::Error>
    where
        T: FromStr,
        T::Err: Display,
        D: Deserializer<'de>,
    {
        String::deserialize(d)?.parse().map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_through_json_and_fills_missing_fields() {
        let mut s = AppSettings::default();
        s.physics.integrator = Integrator::Rk4;
        s.physics.model = RotationModel::Textbook;
        s.body.mass = MassGiven::Mass(2.5);
        s.view.equivalent = Equivalent::Ellipsoid;
        let text = serde_json::to_string(&s).expect("serialisable");
        assert!(text.contains("\"rk4\""), "{text}");
        let back: AppSettings = serde_json::from_str(&text).expect("parses");
        assert_eq!(back, s);
        let partial: AppSettings =
            serde_json::from_str(r#"{"plots":{"window":5.0}}"#).expect("parses");
        assert_eq!(partial.plots.window, 5.0);
        assert_eq!(partial.physics, PhysicsSettings::default());
        assert!(PhysicsSettings::default().to_sim().validate().is_ok());
    }
}
