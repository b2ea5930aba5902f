//! The 2D panels: the side panel (body, mass properties, motion, interaction), the toolbar of
//! view toggles, the plot panel and the F1 help. Each reads the model, edits the frame's one
//! settings draft and records [`Command`]s; none changes the model itself.
//!
//! Every panel is a [`Panel`] (the egui demo's `Demo` trait): each is a file here and owns its
//! own state. The window's panels are registered once, in [`Panels`] (the app places each); the
//! side panel's sections, in `side::SidePanel`'s list.

use super::platform::DialogPurpose;
use crate::i18n::tr;
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

/// A panel of the window (the toolbar, the plots, the sphere, the side panel, the help) or a
/// section of the side panel (its header and contents, or nothing when it does not apply to the
/// body shown: Robot without a robot).
pub trait Panel {
    /// Shows the panel in `ui`.
    fn show(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>);
}

/// Every panel of the window, each with its own state: the one list that registers them (the
/// app places each: the side panel left, the plots below, the toolbar and the sphere over the
/// 3D view, the help over everything).
#[derive(Default)]
pub struct Panels {
    /// The side panel and its sections.
    pub side: side::SidePanel,
    /// The toolbar over the 3D view.
    pub toolbar: toolbar::Toolbar,
    /// The plots of ω, L and the energies.
    pub plots: plots::PlotsPanel,
    /// The momentum sphere.
    pub sphere: sphere::SpherePanel,
    /// The F1 help.
    pub help: help::HelpWindow,
    /// The lessons, beside the 3D view.
    pub lessons: lessons::LessonsPanel,
}

pub mod body;
pub mod compare;
pub mod diagnostics;
pub mod display;
pub mod help;
pub mod interaction;
pub mod lessons;
pub mod motion;
pub mod parts;
pub mod plots;
pub mod robot;
pub mod side;
pub mod sphere;
pub mod table;
pub mod toolbar;

/// UI-only state the panels share with each other, the app and the 3D view (text being typed,
/// plot following, dialogs, selections), not persisted.
#[derive(Debug, Clone)]
pub struct PanelState {
    /// Path typed in the "open" field.
    pub path: String,
    /// Whether the F1 help is shown.
    pub help_open: bool,
    /// Whether the Lessons panel is shown (it is, too, while a lesson is open).
    pub lessons_open: bool,
    /// The embedded layout (`?embed=1`): no side panel.
    pub embed: bool,
    /// A file dialog a panel asked for this frame (the app opens it).
    pub dialog_request: Option<DialogPurpose>,
    /// Whether a file dialog is open (its buttons are disabled meanwhile).
    pub dialog_open: bool,
    /// "Frame" was clicked this frame (the app centres the camera on the body).
    pub frame_request: bool,
    /// How long the Record button records (s).
    pub record_seconds: f64,
    /// Record was pressed this frame (the app starts the recording).
    pub record_request: bool,
    /// Stop was pressed this frame.
    pub record_stop: bool,
    /// Where "Export motion" writes (.glb or .usda).
    pub motion_path: String,
    /// How many seconds "Export motion" bakes.
    pub motion_seconds: f64,
    /// Keyframes a second "Export motion" bakes.
    pub motion_fps: f64,
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
            help_open: false,
            lessons_open: false,
            embed: false,
            dialog_request: None,
            dialog_open: false,
            frame_request: false,
            record_seconds: 5.0,
            record_request: false,
            record_stop: false,
            motion_path: "motion.glb".to_owned(),
            motion_seconds: 10.0,
            motion_fps: 30.0,
            recording: None,
            selected_warning: None,
            selected_part: None,
        }
    }
}

/// The Run / Pause button (in the side panel and over the plots).
pub(crate) fn pause_button(ui: &mut egui::Ui, lab: &Lab, commands: &mut Vec<Command>) {
    let label = if lab.is_paused() {
        tr!("panels-run")
    } else {
        tr!("panels-pause")
    };
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
            localized(egui::DragValue::new(value))
                .range(range)
                .speed(speed)
                .suffix(suffix)
                .max_decimals(6),
        )
        .labelled_by(l.id)
    })
    .inner
}

/// A number field that shows and reads numbers with the language's decimal separator (3,5 in
/// German; a point is read too).
pub(crate) fn localized(field: egui::DragValue<'_>) -> egui::DragValue<'_> {
    field
        .custom_formatter(|value, decimals| {
            crate::i18n::localize(egui::emath::format_with_decimals_in_range(value, decimals))
        })
        .custom_parser(crate::i18n::parse_number)
}

const HEADING_CHARS: usize = 28;

/// `text` shortened to at most `max` characters by an ellipsis in the middle, keeping the start
/// and the end (where file names differ).
fn elide(text: &str, max: usize) -> String {
    let n = text.chars().count();
    if n <= max {
        return text.to_owned();
    }
    let keep = max.saturating_sub(1);
    let head: String = text.chars().take(keep - keep / 2).collect();
    let tail: String = text.chars().skip(n - keep / 2).collect();
    format!("{head}…{tail}")
}

/// The choice beside "Simulation uses" and "Rotation model" (one setting, shown at both).
fn restart_on_switch(ui: &mut egui::Ui, s: &mut AppSettings) {
    ui.checkbox(
        &mut s.physics.restart_on_switch,
        tr!("panels-restart-on-switch"),
    )
    .on_hover_text(tr!("panels-restart-on-switch-hover"));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_names_lose_their_middle() {
        assert_eq!(elide("T-handle", 28), "T-handle");
        let long = "scanned_turbine_blade_with_holes_final.obj";
        let short = elide(long, 28);
        assert_eq!(short.chars().count(), 28);
        assert_eq!(short, "scanned_turbin…les_final.obj");
        assert_eq!(elide("αβγδε", 3), "α…ε");
    }
}
