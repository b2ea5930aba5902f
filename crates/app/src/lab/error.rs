//! What can go wrong in the lab, as data: each variant names the thing at fault (a part, a body,
//! a file, a specimen) and keeps the library error beneath it. The lab turns a failed command
//! into the message line; the GUI decides how to show it.

use std::path::PathBuf;

use massprops::MeshError;
use rbcore::{BodyError, SimError};

/// Why a command, a load or an edit could not be carried out. Nothing changed when it is
/// returned: the model stays as it was.
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum LabError {
    /// A mesh or body file that cannot be read or gives no body.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// A file that gives no body through the one input path.
    #[error(transparent)]
    Input(#[from] inertia_io::input::InputError),
    /// A lesson that cannot be read or found.
    #[error(transparent)]
    Lesson(#[from] super::lessons::LessonError),
    /// A lesson command that does not fit where the lesson is.
    #[error("{0}")]
    LessonStep(&'static str),
    /// A mesh or body named for the message (a file name, a sample's label, a body's name).
    #[error("{name}: {source}")]
    Named {
        /// Whose.
        name: String,
        /// What is wrong.
        #[source]
        source: Box<LabError>,
    },
    /// One part of a body made of parts cannot give its mass.
    #[error("part \"{part}\": {source}")]
    Part {
        /// The part's name.
        part: String,
        /// Why.
        #[source]
        source: MeshError,
    },
    /// A part's mass or material needs a volume its mesh does not enclose.
    #[error("part \"{part}\": encloses no volume to give a mass to")]
    NoDensity {
        /// The part's name.
        part: String,
    },
    /// A part that encloses no volume was made a solid or a void.
    #[error("part \"{part}\": encloses no volume; give it a thin wall instead")]
    NoVolume {
        /// The part's name.
        part: String,
    },
    /// A file could not be written.
    #[error("cannot write {}: {message}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// What the operating system said.
        message: String,
    },
    /// No built-in sample has this label.
    #[error("no sample called '{0}'")]
    UnknownSample(String),
    /// Split into parts was asked of a body that has them already.
    #[error("{0} is already made of parts")]
    AlreadyParts(String),
    /// A mesh file where a body file of parts was expected.
    #[error("{}: not a body file of parts (.toml)", .0.display())]
    NotBodyFile(PathBuf),
    /// A part index that the body does not have.
    #[error("no part number {0}")]
    NoPart(usize),
    /// A robot description that cannot be read or drawn (the message names file and line).
    #[error("{0}")]
    Robot(String),
    /// A link index out of range.
    #[error("the robot has no link {0}")]
    NoLink(usize),
    /// Hiding the last part shown.
    #[error("the last part shown stays shown")]
    LastShown,
    /// Removing the last part.
    #[error("a body keeps at least one part")]
    LastPart,
    /// A specimen id that is gone.
    #[error("no body number {0}")]
    NoSpecimen(u32),
    /// More copies than a comparison runs.
    #[error("at most {max} copies can be compared, not {asked}")]
    TooManyCopies {
        /// The limit.
        max: usize,
        /// How many were asked for.
        asked: usize,
    },
    /// A compared copy could not start.
    #[error("{variant}: {source}")]
    Copy {
        /// The copy's variant, in words.
        variant: String,
        /// Why.
        #[source]
        source: Box<LabError>,
    },
    /// A state rbcore refuses (a mass, an inertia, an orientation, a position).
    #[error(transparent)]
    RigidBody(#[from] BodyError),
    /// Settings rbcore's simulation refuses.
    #[error(transparent)]
    Sim(#[from] SimError),
    /// A body rbcore refuses (mass, inertia, a state it cannot take), with what was being set.
    #[error("{what}: {source}")]
    Body {
        /// What was being set: "spin rate", "mass properties rejected", "string", "poke", ….
        what: &'static str,
        /// rbcore's reason.
        #[source]
        source: BodyError,
    },
    /// The simulation refuses a setting, or diverged.
    #[error("{what}: {source}")]
    Simulation {
        /// What was being done.
        what: &'static str,
        /// rbcore's reason.
        #[source]
        source: SimError,
    },
    /// The mass properties cannot be rescaled to the settings (size or mass out of range).
    #[error("{what}: {source}")]
    Rescale {
        /// "size" or "mass".
        what: &'static str,
        /// massprops' reason.
        #[source]
        source: MeshError,
    },
    /// A simulation that diverged mid-run.
    #[error("simulation stopped: {0}. Press Reset.")]
    Stopped(SimError),
    /// A poke without a direction.
    #[error("poke: the view ray has no direction")]
    NoPokeDirection,
    /// A robot description among files given by their bytes (its meshes are named by paths).
    #[error(
        "{}: a robot description needs its meshes where it names them; open it in the desktop app",
        .0.display()
    )]
    RobotFromFiles(PathBuf),
    /// The loader thread ended without a result.
    #[error("{}: the loader stopped unexpectedly", .0.display())]
    LoaderStopped(PathBuf),
    /// What went wrong in work done elsewhere (the page's worker), in that place's words.
    #[error("{0}")]
    Relayed(String),
    /// A baked motion's file is named with an extension it is not written as.
    #[error("{}: a motion is written as .glb (glTF) or .usda (USD)", path.display())]
    MotionFormat {
        /// The path asked for.
        path: PathBuf,
    },
    /// The motion could not be baked.
    #[error("export motion: {0}")]
    Bake(#[from] inertia_io::bake::BakeError),
    /// The body was edited or replaced while new parts were read for it.
    #[error("the body changed while {0} was read: add it again")]
    ChangedWhileAdding(String),
}

impl LabError {
    /// This error, named `name` for the message (a file or a body).
    pub fn named(self, name: impl Into<String>) -> Self {
        LabError::Named {
            name: name.into(),
            source: Box::new(self),
        }
    }
}
