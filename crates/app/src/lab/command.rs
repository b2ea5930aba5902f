//! The lab's vocabulary: every change a user (or a test) can ask of the model, as a
//! [`Command`] that [`Lab::apply`](super::Lab::apply) carries out, and the [`Message`] line that
//! tells how it went.

use std::path::PathBuf;

use nalgebra::{Point3, Vector3};

use super::settings::AppSettings;
use super::specimen::{SpecimenId, Variant};

/// An intent recorded by the UI (or a test), applied by [`Lab::apply`](super::Lab::apply).
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// Pause or resume every specimen.
    TogglePause,
    /// One fixed step of every specimen (pauses first).
    Step,
    /// Every specimen back to the start state of the current body and preset.
    Reset,
    /// Spin about principal axis 0, 1 or 2 (moments ascending) with a small perturbation.
    Preset(usize),
    /// New settings, applied live to every specimen.
    Settings(Box<AppSettings>),
    /// Settings back to defaults, except the display's (the language, larger text, reduced
    /// motion): a person who needs those needs them after a reset too.
    ResetSettings,
    /// Load a mesh file on the worker thread; it replaces every specimen's body.
    LoadFile(PathBuf),
    /// Load files given by their bytes (the browser's): a body file with its meshes, or a mesh;
    /// it replaces every specimen's body.
    LoadFiles(inertia_io::input::FileSet),
    /// Files dropped on the window or page: meshes dropped on a body of parts join it as parts,
    /// anything else opens ([`Lab::drop_adds_parts`](super::Lab::drop_adds_parts)).
    Drop(super::loader::LoadSource),
    /// Load a built-in sample by label.
    LoadSample(String),
    /// Write a specimen's plot history as CSV.
    ExportCsv {
        /// Whose history.
        specimen: SpecimenId,
        /// Where to write.
        path: PathBuf,
    },
    /// Bake a specimen's motion from its present state into a glTF (`.glb`) or USD (`.usda`)
    /// file with its mesh ([`inertia_io::bake`]).
    ExportMotion {
        /// Whose motion.
        specimen: SpecimenId,
        /// Where to write (the format by its extension).
        path: PathBuf,
        /// Seconds baked.
        seconds: f64,
        /// Keyframes a second.
        fps: f64,
    },
    /// Poke: impulse of the set magnitude at a world point, along `direction` (the view ray).
    Poke {
        /// The specimen poked.
        specimen: SpecimenId,
        /// World point on the surface.
        point: Point3<f64>,
        /// Direction of the impulse (normalised here).
        direction: Vector3<f64>,
    },
    /// Attach the string at a world point on the surface.
    Grab {
        /// The specimen held.
        specimen: SpecimenId,
        /// World point on the surface.
        point: Point3<f64>,
    },
    /// Move the string's free end.
    Drag {
        /// The specimen held.
        specimen: SpecimenId,
        /// The new free end (world).
        target: Point3<f64>,
    },
    /// Detach the string.
    Release {
        /// The specimen held.
        specimen: SpecimenId,
    },
    /// Run the primary and up to [`MAX_COPIES`](super::MAX_COPIES) copies of it from the same start, each copy
    /// changed by its [`Variant`]; an empty list ends the comparison (the primary goes on).
    Compare(Vec<Variant>),
    /// Show a line (outcomes the GUI learns itself: a cancelled dialog, a finished recording).
    Notify(Message),
    /// Dismiss the message line.
    DismissMessage,
    /// Make the body's parts the parts of its file (objects, groups, STL solids, or connected
    /// shells), each at the body's current density.
    SplitIntoParts,
    /// Add a mesh file as a new part at the origin, of water's density (a single-mesh body
    /// becomes its first part, whole).
    AddPart(PathBuf),
    /// Add each mesh of files given by their bytes (the browser's) as a new part, as
    /// [`Command::AddPart`].
    AddPartFiles(inertia_io::input::FileSet),
    /// Change one part's settings (material, void, thin wall, placement, name) and whether it
    /// is drawn; the motion goes on with p and L kept.
    EditPart {
        /// Which part.
        index: usize,
        /// Its new settings (placement in metres).
        entry: Box<massprops::PartEntry>,
        /// Drawn in the 3D view.
        visible: bool,
    },
    /// Remove one part.
    RemovePart(usize),
    /// Write the body as a body file (and, beside it, the meshes of parts that have no file).
    SaveBody(PathBuf),
    /// Open a lesson at its first step (the one open before is left).
    OpenLesson(super::lessons::LessonSource),
    /// Commit to choice N of the present step's prediction (its checks start counting).
    Predict(usize),
    /// The next step of the lesson, once this one is done.
    NextStep,
    /// The step before, set up again.
    PreviousStep,
    /// Step N (from 0) of the open lesson, set up: where a teacher's link starts a class.
    GoToStep(usize),
    /// Leave the lesson (its progress is kept).
    CloseLesson,
    /// Show link N of the loaded robot description as the body (its stated inertia available
    /// as the "stated" source), or the whole robot at its zero pose for `None`.
    ShowLink(Option<usize>),
}

/// A line for the user: an error (red) or information.
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    /// The text.
    pub text: String,
    /// Whether something went wrong.
    pub error: bool,
}

impl Message {
    /// The line for a command that failed (the model is unchanged).
    pub fn error(e: &super::LabError) -> Self {
        Self {
            text: e.to_string(),
            error: true,
        }
    }
}
