//! One simulated body: a loaded mesh with its mass properties at the current size and mass, the
//! `rbcore` simulation, the plotted history, and what the user is doing to it (poke, string).
//! The [`super::Lab`] holds one or more of them; each changes only through the lab's commands.

use std::sync::Arc;
use std::time::Duration;

use crate::i18n::tr;
use crate::platform::Instant;

use massprops::MassProperties;

use massprops::properties::Comparison;
use nalgebra::{Point3, UnitQuaternion, Vector3};
use rbcore::{
    Advance, Body, DriftTracker, Integrator, Polhode, RotationModel, SimError, Simulation,
    SoftString,
};

use super::body::LoadedBody;
use super::error::LabError;
use super::history::History;
use super::picking::{Hit, Ray};
use super::placement::Placement;
use super::settings::{AppSettings, InertiaSource, MassGiven};

/// How long the ΔL arrow of a poke stays on screen.
const POKE_FLASH: Duration = Duration::from_millis(1500);

/// Relative size of the perturbation the spin presets add on the other two axes: enough for the
/// T-handle to flip within about three seconds at the default 8 rad/s.
const PERTURBATION: f64 = 0.02;

/// A swing of L wider than this from the axis it circles turns the body over (axis 2 swings
/// round to point the other way); narrower, the body wobbles. 45°: axis 2 then points more
/// across than along where it started.
pub const TURNING_OVER: f64 = std::f64::consts::FRAC_PI_4;

/// Most samples kept (about 58 MB): 600 s at the default step; a tiny step shortens the history
/// rather than exhausting memory.
const MAX_HISTORY: usize = 400_000;

/// A specimen's name in commands; stays the same while the specimen exists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SpecimenId(pub u32);

/// What a copy changes from the lab's settings: one choice, so that a comparison shows what
/// that choice alone does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variant {
    /// Nothing: the lab's settings (the primary; a copy like this stays identical to it).
    Same,
    /// Another inertia source (exact, bounding box, point masses).
    Source(InertiaSource),
    /// Another rotation model (full or textbook).
    Model(RotationModel),
    /// Another integrator.
    Integrator(Integrator),
}

impl Variant {
    /// `settings` with this variant's one change.
    pub fn apply(self, settings: &AppSettings) -> AppSettings {
        let mut s = settings.clone();
        match self {
            Variant::Same => {}
            Variant::Source(source) => s.body.source = source,
            Variant::Model(model) => s.physics.model = model,
            Variant::Integrator(integrator) => s.physics.integrator = integrator,
        }
        s
    }

    /// A short name for legends and tables.
    pub fn label(self) -> String {
        match self {
            Variant::Same => tr!("variant-same"),
            Variant::Source(source) => tr!("variant-source", source = source.label()),
            Variant::Model(model) => {
                tr!("variant-model", model = super::settings::model_words(model))
            }
            Variant::Integrator(integrator) => integrator.name().to_owned(),
        }
    }
}

/// The last poke, for the ΔL arrow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PokeFlash {
    /// Where the impulse was applied (world).
    pub point: Point3<f64>,
    /// The impulse J (N·s).
    pub impulse: Vector3<f64>,
    /// ΔL = r × J (world).
    pub delta_l: Vector3<f64>,
    /// When to stop drawing it.
    pub until: Instant,
}

/// The string as drawn: both ends and the force it currently applies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StringView {
    /// Attachment point on the body (world).
    pub attachment: Point3<f64>,
    /// The pointer end (world).
    pub target: Point3<f64>,
    /// Force on the body (N), the step's impulse over `dt`.
    pub force: Vector3<f64>,
}

/// What a poke did to the angular momentum about the centre of mass (world axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PokeEffect {
    /// L after the poke less L before.
    pub measured: Vector3<f64>,
    /// r × J: the impulse's moment about the centre of mass.
    pub predicted: Vector3<f64>,
}

/// One simulated body.
#[derive(Debug, Clone)]
pub struct Specimen {
    id: SpecimenId,
    variant: Variant,
    body: Arc<LoadedBody>,
    /// Exact, bounding-box, point-mass and stated properties at the current scale and mass (the
    /// stated ones are the exact ones for a body that states none).
    props: [MassProperties; 4],
    source: InertiaSource,
    scale: f64,
    sim: Simulation,
    history: History,
    poke: Option<PokeFlash>,
    /// How many pokes since the start, and what the last one did to L.
    pokes: u64,
    last_poke: Option<PokeEffect>,
    /// Simulated time the frames asked for but the catch-up cap did not run, since the start.
    dropped: f64,
    /// E and L drift since the start or the last disturbance (every step observed).
    drift: DriftTracker,
}

impl Specimen {
    /// `body` at the size and mass of `settings` changed by `variant`, spinning about principal
    /// axis `axis` (moments ascending) with a small perturbation on the other two, mesh axes on
    /// the world axes.
    ///
    /// # Errors
    /// The settings give no valid body or simulation (the message says which setting).
    pub fn start(
        id: SpecimenId,
        variant: Variant,
        body: Arc<LoadedBody>,
        settings: &AppSettings,
        axis: usize,
    ) -> Result<Self, LabError> {
        let settings = &variant.apply(settings);
        let props = scaled_properties(&body, settings)?;
        let used = &props[source_index(settings.body.source)];
        let mut b =
            Body::from_principal(used.mass, used.principal.moments, used.principal.rotation)
                .map_err(|e| LabError::from(e).named(&body.name))?;
        // Orientation maps principal → world: this puts the mesh axes on the world axes.
        b.set_orientation(UnitQuaternion::from_rotation_matrix(
            &used.principal.rotation,
        ))?;
        let rate = settings.body.spin_rate;
        let mut omega = Vector3::repeat(PERTURBATION * rate);
        omega[axis.min(2)] = rate;
        b.set_omega_principal(omega)
            .map_err(|source| LabError::Body {
                what: "spin rate",
                source,
            })?;
        let sim = Simulation::new(b, settings.physics.to_sim())?;
        let d0 = sim.diagnostics();
        let mut history = History::new(capacity(settings));
        history.push(&d0);
        Ok(Self {
            id,
            variant,
            body,
            props,
            source: settings.body.source,
            scale: settings.body.scale,
            sim,
            history,
            poke: None,
            pokes: 0,
            last_poke: None,
            dropped: 0.0,
            drift: DriftTracker::new(&d0),
        })
    }

    /// Applies new settings: simulation settings, history bound, and (if size, mass or source
    /// changed) new mass properties with p and L kept, as an instantaneous change of mass
    /// distribution conserves them. The mesh stays where it is in the world.
    ///
    /// # Errors
    /// The settings are invalid; nothing has changed then.
    pub fn set_settings(&mut self, old: &AppSettings, new: &AppSettings) -> Result<(), LabError> {
        let (old, new) = (&self.variant.apply(old), &self.variant.apply(new));
        let props = scaled_properties(&self.body, new)?;
        self.reshape(props, new, old.body != new.body)?;
        if new.physics != old.physics {
            self.disturbed();
        }
        Ok(())
    }

    /// Puts a changed body in place (a part's material, placement, or a part added or
    /// removed), keeping p and L as [`Specimen::set_settings`] does; the parts that did not
    /// change stay where they are in the world.
    ///
    /// # Errors
    /// The new body cannot be simulated; nothing has changed then.
    pub fn set_body(
        &mut self,
        body: Arc<LoadedBody>,
        settings: &AppSettings,
    ) -> Result<(), LabError> {
        let settings = &self.variant.apply(settings);
        let props = scaled_properties(&body, settings)?;
        self.reshape(props, settings, true)?;
        self.body = body;
        Ok(())
    }

    /// New mass properties (when `changed`) and settings, p and L kept, the mesh kept in place.
    fn reshape(
        &mut self,
        props: [MassProperties; 4],
        new: &AppSettings,
        changed: bool,
    ) -> Result<(), LabError> {
        let used = &props[source_index(new.body.source)];
        // Checked before anything changes, so a rejected value leaves the specimen as it was.
        Body::from_principal(used.mass, used.principal.moments, used.principal.rotation)
            .map_err(rejected)?;
        // The body frame's origin is the used centre of mass. A new source, or a part changed,
        // moves it within the mesh by `shift`: the pose moves with it so the mesh stays where it
        // is on screen. A new size keeps the centre of mass in place and the body grows about it.
        let shift = if new.body.scale == self.scale {
            used.center_of_mass - self.used_properties().center_of_mass
        } else {
            used.center_of_mass - props[source_index(self.source)].center_of_mass
        };
        // The string moves with the body frame's origin; built (and checked) before anything
        // changes, like the body above.
        let moved_string = match self.sim.string() {
            Some(string) => {
                let i = &new.interaction;
                let moved = SoftString::new(
                    string.target(),
                    string.attachment() - shift,
                    i.string_frequency,
                    i.string_damping,
                    used.mass * i.string_max_accel,
                )
                .map_err(string_refused)?;
                Some(moved)
            }
            None => None,
        };
        self.sim
            .set_settings(new.physics.to_sim())
            .map_err(|source| LabError::Simulation {
                what: "setting rejected",
                source,
            })?;
        if changed {
            let b = self.sim.body_mut();
            let position = b.position() + b.body_orientation() * shift;
            b.set_mass_properties(used.mass, used.principal.moments, used.principal.rotation)
                .map_err(rejected)?;
            b.set_position(position)?;
            self.disturbed();
        }
        if moved_string.is_some() {
            self.sim.set_string(moved_string);
        }
        self.props = props;
        self.source = new.body.source;
        self.scale = new.body.scale;
        self.history.set_capacity(capacity(new));
        Ok(())
    }

    /// Advances by `frame_dt` simulated seconds through the simulation's accumulator, recording
    /// every step in the history; time beyond rbcore's catch-up cap is counted in
    /// [`Specimen::dropped`].
    ///
    /// # Errors
    /// The simulation diverged (the lab pauses); the steps before stay recorded.
    pub fn advance(&mut self, frame_dt: f64) -> Result<Advance, SimError> {
        let (history, drift) = (&mut self.history, &mut self.drift);
        self.sim
            .advance_with(frame_dt, |sim| {
                let d = sim.diagnostics();
                history.push(&d);
                drift.observe(&d);
            })
            .inspect(|a| self.dropped += a.dropped)
    }

    /// One fixed step (recorded).
    ///
    /// # Errors
    /// The simulation diverged (the lab pauses).
    pub fn step(&mut self) -> Result<(), SimError> {
        self.sim.step()?;
        let d = self.sim.diagnostics();
        self.history.push(&d);
        self.drift.observe(&d);
        Ok(())
    }

    /// Applies the impulse `magnitude · direction/|direction|` at the world point `point`.
    ///
    /// # Errors
    /// The direction has no length, or the body rejects the impulse.
    pub fn poke(
        &mut self,
        point: Point3<f64>,
        direction: Vector3<f64>,
        magnitude: f64,
        now: Instant,
    ) -> Result<(), LabError> {
        let n = direction.norm();
        if !(n.is_finite() && n > 0.0) {
            return Err(LabError::NoPokeDirection);
        }
        let j = direction * (magnitude / n);
        let r = point - self.sim.body().position();
        let before = self.sim.body().angular_momentum();
        self.sim.poke(&point, &j).map_err(|source| LabError::Body {
            what: "poke",
            source,
        })?;
        self.pokes += 1;
        self.last_poke = Some(PokeEffect {
            measured: self.sim.body().angular_momentum() - before,
            predicted: r.cross(&j),
        });
        self.poke = Some(PokeFlash {
            point,
            impulse: j,
            delta_l: r.cross(&j),
            until: now + POKE_FLASH,
        });
        self.disturbed();
        Ok(())
    }

    /// Attaches the string at the world point `point` (on the surface).
    ///
    /// # Errors
    /// The string's settings are invalid.
    pub fn grab(&mut self, point: Point3<f64>, settings: &AppSettings) -> Result<(), LabError> {
        let i = &settings.interaction;
        let attachment = self.sim.body().point_to_body(&point);
        let string = SoftString::new(
            point,
            attachment,
            i.string_frequency,
            i.string_damping,
            self.string_max_force(settings),
        )
        .map_err(string_refused)?;
        self.sim.set_string(Some(string));
        self.disturbed();
        Ok(())
    }

    /// Moves the string's free end (nothing if no string is attached).
    ///
    /// # Errors
    /// The target is not finite.
    pub fn drag(&mut self, target: Point3<f64>) -> Result<(), LabError> {
        if let Some(s) = self.sim.string_mut() {
            s.set_target(target).map_err(string_refused)?;
        }
        Ok(())
    }

    /// Detaches the string.
    pub fn release(&mut self) {
        if self.sim.string().is_some() {
            self.sim.set_string(None);
            self.disturbed();
        }
    }

    /// E, L or the inertia changed for a reason: the history's drift, flips and paths and the
    /// drift table start again from now.
    fn disturbed(&mut self) {
        self.history.mark_disturbance();
        self.drift = DriftTracker::new(&self.sim.diagnostics());
    }

    /// Forgets a poke flash that has expired at `now`.
    pub fn expire_flash(&mut self, now: Instant) {
        if self.poke.is_some_and(|p| now >= p.until) {
            self.poke = None;
        }
    }

    /// This specimen's name in commands.
    pub fn id(&self) -> SpecimenId {
        self.id
    }
    /// What this specimen changes from the lab's settings.
    pub fn variant(&self) -> Variant {
        self.variant
    }
    /// E and L drift since the start or the last poke, pull or change of body or physics.
    pub fn drift(&self) -> &DriftTracker {
        &self.drift
    }
    /// The simulation (read-only).
    pub fn sim(&self) -> &Simulation {
        &self.sim
    }
    /// The loaded body.
    pub fn body(&self) -> &LoadedBody {
        &self.body
    }
    /// The loaded body, shared.
    pub fn body_arc(&self) -> &Arc<LoadedBody> {
        &self.body
    }
    /// The plotted history.
    pub fn history(&self) -> &History {
        &self.history
    }
    /// Simulated seconds dropped by the catch-up cap since the start (the frames came too slowly
    /// for the step; 0 when the simulation kept up).
    pub fn dropped(&self) -> f64 {
        self.dropped
    }
    /// Mass properties per source (exact, bounding box, point masses, stated) at the current
    /// scale and mass.
    pub fn properties(&self, source: InertiaSource) -> &MassProperties {
        &self.props[source_index(source)]
    }
    /// The mass properties the simulation uses.
    pub fn used_properties(&self) -> &MassProperties {
        self.properties(self.source)
    }
    /// How an approximation compares with the exact properties.
    pub fn comparison(&self, source: InertiaSource) -> Comparison {
        self.properties(source)
            .compare_to(self.properties(InertiaSource::Exact))
    }
    /// The body's volume (m³) at the current size.
    pub fn volume(&self) -> f64 {
        self.body.volume() * self.scale.powi(3)
    }
    /// The body's mean density (kg/m³) at the current size and mass: its mass over its volume.
    pub fn density(&self) -> f64 {
        self.properties(InertiaSource::Exact).mass / self.volume()
    }
    /// How the body's angular momentum moves in the body now, torque-free: the axis its polhode
    /// circles and the flip period predicted from the current E and |L|.
    pub fn polhode(&self) -> Polhode {
        let b = self.sim.body();
        rbcore::polhode(&b.moments(), &b.angular_momentum_principal())
    }
    /// The widest angle (radians) between L and the axis its polhode circles, torque-free from
    /// now ([`rbcore::cone_angle`]); 0 for a steady spin or a body at rest.
    pub fn cone_angle(&self) -> f64 {
        let b = self.sim.body();
        match self.polhode() {
            Polhode::Circles { axis, .. } => {
                rbcore::cone_angle(&b.moments(), &b.angular_momentum_principal(), axis)
            }
            _ => 0.0,
        }
    }
    /// The interval (s) between turns of the body predicted from the current E and |L|: half the
    /// polhode's period when the body turns over (L swings at least [`TURNING_OVER`] from the
    /// axis it circles, a symmetric top never); `None` when it only wobbles or spins steadily,
    /// and under the textbook model, which never turns the body over.
    pub fn turn_over_interval(&self) -> Option<f64> {
        if self.sim.settings().model == RotationModel::Textbook {
            return None;
        }
        match self.polhode() {
            Polhode::Circles {
                period, separation, ..
            } if separation.is_finite() && self.cone_angle() >= TURNING_OVER => Some(period / 2.0),
            _ => None,
        }
    }
    /// How many pokes since the specimen started.
    pub fn pokes(&self) -> u64 {
        self.pokes
    }
    /// What the last poke did to L.
    pub fn last_poke(&self) -> Option<PokeEffect> {
        self.last_poke
    }
    /// The current poke flash.
    pub fn poke_flash(&self) -> Option<PokeFlash> {
        self.poke
    }
    /// Poke impulse magnitude (N·s): `J = f·|L| / reach`, so that a poke changes L by at most
    /// the fraction f of |L| (`|ΔL| = |r × J| ≤ reach·J`); at rest, the |L| of a spin at the
    /// spin rate about axis 3.
    pub fn poke_impulse(&self, settings: &AppSettings) -> f64 {
        let spinning = self.sim.body().angular_momentum().norm();
        let l = if spinning > 0.0 {
            spinning
        } else {
            settings.body.spin_rate * self.used_properties().principal.moments.max()
        };
        settings.interaction.poke_fraction * l / self.reach()
    }
    /// The farthest the body reaches from its centre of mass (m), at most: its bounding sphere's
    /// radius plus the sphere's centre's distance from the centre of mass.
    pub fn reach(&self) -> f64 {
        let (centre, radius) = self.body.sphere;
        let com = self.properties(InertiaSource::Exact).center_of_mass;
        self.scale * radius + (centre * self.scale - com).norm()
    }
    /// String force cap (N) for the current mass: `F = m·a_max`.
    pub fn string_max_force(&self, settings: &AppSettings) -> f64 {
        self.used_properties().mass * settings.interaction.string_max_accel
    }
    /// The string, if attached.
    pub fn string_view(&self) -> Option<StringView> {
        let sim = &self.sim;
        let s = sim.string()?;
        let dt = sim.settings().dt;
        Some(StringView {
            attachment: sim.body().point_to_world(&s.attachment()),
            target: s.target(),
            force: s.impulse(sim.body(), dt) / dt,
        })
    }
    /// The body as a baked file shows it: the used mass properties and the mesh at its size
    /// (the placement's mesh coordinates, `s·p`).
    pub fn shape(&self) -> inertia_io::bake::Shape {
        let mesh = &self.body.mesh;
        inertia_io::bake::Shape {
            properties: *self.used_properties(),
            surface: inertia_io::export::Surface {
                points: mesh.positions.iter().map(|p| p * self.scale).collect(),
                triangles: mesh.triangles.clone(),
                files: Vec::new(),
            },
        }
    }

    /// The mesh → world transform now.
    pub fn placement(&self) -> Placement {
        let b = self.sim.body();
        Placement {
            scale: self.scale,
            center: self.used_properties().center_of_mass,
            rotation: b.body_orientation(),
            position: b.position(),
        }
    }
    /// Ray-casts the body: the world ray is mapped into mesh coordinates (the body is rigid, so
    /// this equals intersecting the world-space mesh) and the hit mapped back.
    pub fn pick(&self, ray: &Ray) -> Option<Hit> {
        let placement = self.placement();
        let local = Ray {
            origin: placement.to_mesh(&ray.origin),
            dir: placement.vector_to_mesh(&ray.dir),
        };
        // A hidden part is not there to be poked.
        let hidden = |t: usize| {
            self.body.composition.as_ref().is_some_and(|c| {
                c.triangles
                    .iter()
                    .position(|r| r.contains(&t))
                    .is_some_and(|k| !c.parts[k].visible)
            })
        };
        let hit = self
            .body
            .bvh
            .pick_where(&self.body.mesh, &local, &|t| !hidden(t))?;
        Some(Hit {
            point: placement.to_world(&hit.point),
            ..hit
        })
    }
    /// Bounding-sphere centre (world) and radius of the scaled body.
    pub fn bounding_sphere(&self) -> (Point3<f64>, f64) {
        let (c, r) = self.body.sphere;
        (self.placement().to_world(&c), r * self.scale)
    }
}

/// History capacity for the configured seconds at the configured step.
fn capacity(settings: &AppSettings) -> usize {
    let n = settings.plots.history / settings.physics.dt;
    if n.is_finite() && n > 0.0 {
        (n.ceil() as usize).clamp(2, MAX_HISTORY)
    } else {
        2
    }
}

fn source_index(source: InertiaSource) -> usize {
    match source {
        InertiaSource::Exact => 0,
        InertiaSource::BoundingBox => 1,
        InertiaSource::PointMasses => 2,
        InertiaSource::Stated => 3,
    }
}

/// The four sources' properties for the settings' scale and mass (the analysis is at density 1
/// and scale 1: mass ∝ s³, inertia ∝ s⁵ at fixed density).
fn scaled_properties(
    body: &LoadedBody,
    settings: &AppSettings,
) -> Result<[MassProperties; 4], LabError> {
    let s = settings.body.scale;
    let a = &body.analysis;
    // A body of parts takes its mass from their materials; a single mesh from the settings.
    let whole = body.composition.as_ref().map(|c| &c.whole);
    let exact = whole
        .unwrap_or(&a.properties)
        .scaled_at_fixed_density(s)
        .map_err(|source| LabError::Rescale {
            what: "size",
            source,
        })?;
    let mass = match (whole, settings.body.mass) {
        (Some(_), _) => exact.mass,
        (None, MassGiven::Density(d)) => exact.mass * d,
        (None, MassGiven::Mass(m)) => m,
    };
    let fit = |p: &MassProperties| -> Result<MassProperties, LabError> {
        p.scaled_at_fixed_density(s)
            .and_then(|p| p.with_mass(mass))
            .map_err(|source| LabError::Rescale {
                what: "mass",
                source,
            })
    };
    let exact = fit(whole.unwrap_or(&a.properties))?;
    Ok([
        exact,
        fit(&a.bounding_box)?,
        fit(&a.point_masses)?,
        body.stated.as_ref().map_or(Ok(exact), fit)?,
    ])
}

/// rbcore's refusal of new mass properties.
fn rejected(source: rbcore::BodyError) -> LabError {
    LabError::Body {
        what: "mass properties rejected",
        source,
    }
}

/// rbcore's refusal of a string.
fn string_refused(source: rbcore::BodyError) -> LabError {
    LabError::Body {
        what: "string",
        source,
    }
}
