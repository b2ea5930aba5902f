//! The 2D panels: the side panel (body, mass properties, motion, interaction), the toolbar of
//! view toggles, the plot panel and the F1 help. Each reads the model, edits the frame's one
//! settings draft and records [`Command`]s; none changes the model itself.
//!
//! The side panel is a list of [`Section`]s (the egui demo's `Demo` trait): each is a file here,
//! owns its own state, and is registered once, in `side::SidePanel`'s list.

use super::platform::DialogPurpose;
use crate::lab::settings::AppSettings;
use crate::lab::{Command, Lab};

/// What a section is given each frame: the lab to read, the frame's one settings draft to edit,
/// the commands it records, and the state the panels share with the app and the 3D view.
pub struct Frame<'a> {
    /// The model, read only.
    pub lab: &'a Lab,
    /// The frame's settings draft (one command at the end of the frame).
    pub settings: &'a mut AppSettings,
    /// The commands recorded this frame.
    pub commands: &'a mut Vec<Command>,
    /// The state shared across panels (the Path field, dialogs, the selected warning or part).
    pub shared: &'a mut PanelState,
}

/// One section of the side panel: its header and contents, or nothing when it does not apply
/// to the body shown (Robot without a robot).
pub trait Section {
    /// Shows the section.
    fn show(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>);
}

pub mod compare;
pub mod diagnostics;
pub mod help;
pub mod parts;
pub mod plots;
pub mod robot;
pub mod side;
pub mod sphere;
pub mod toolbar;

/// UI-only state the panels share with each other, the app and the 3D view (text being typed,
/// plot following, dialogs, selections), not persisted.
#[derive(Debug, Clone)]
pub struct PanelState {
    /// Path typed in the "open" field.
    pub path: String,
    /// Where "Export CSV" writes.
    pub csv_path: String,
    /// Whether the plots follow the latest time (sliding window) or stay where the user put them.
    pub follow: bool,
    /// Whether the F1 help is shown.
    pub help_open: bool,
    /// A file dialog a panel asked for this frame (the app opens it).
    pub dialog_request: Option<DialogPurpose>,
    /// Whether a file dialog is open (its buttons are disabled meanwhile).
    pub dialog_open: bool,
    /// The momentum sphere's orbit.
    pub sphere: sphere::SphereView,
    /// How long the Record button records (s).
    pub record_seconds: f64,
    /// Record was pressed this frame (the app starts the recording).
    pub record_request: bool,
    /// Stop was pressed this frame.
    pub record_stop: bool,
    /// Seconds left of the running recording (set by the app each frame).
    pub recording: Option<f64>,
    /// The mesh warning whose faces the 3D view highlights (an index into the primary body's
    /// warnings).
    pub selected_warning: Option<usize>,
    /// The part the Parts section edits and the 3D view outlines.
    pub selected_part: Option<usize>,
}

impl Default for PanelState {
    fn default() -> Self {
        Self {
            path: String::new(),
            csv_path: "inertia-lab.csv".to_owned(),
            follow: true,
            help_open: false,
            dialog_request: None,
            dialog_open: false,
            sphere: sphere::SphereView::default(),
            record_seconds: 5.0,
            record_request: false,
            record_stop: false,
            recording: None,
            selected_warning: None,
            selected_part: None,
        }
    }
}

/// The Run / Pause button (in the side panel and over the plots).
pub(crate) fn pause_button(ui: &mut egui::Ui, lab: &Lab, commands: &mut Vec<Command>) {
    let label = if lab.is_paused() { "Run" } else { "Pause" };
    if ui.button(label).clicked() {
        commands.push(Command::TogglePause);
    }
}

/// A label and a number field tied to it (screen readers and the UI tests find it by the label).
pub(crate) fn number(
    ui: &mut egui::Ui,
    label: &str,
    value: &mut f64,
    range: std::ops::RangeInclusive<f64>,
    speed: f64,
    suffix: &str,
) -> egui::Response {
    ui.horizontal(|ui| {
        let l = ui.label(label);
        ui.add(
            egui::DragValue::new(value)
                .range(range)
                .speed(speed)
                .suffix(suffix)
                .max_decimals(6),
        )
        .labelled_by(l.id)
    })
    .inner
}
