//! Native file dialogs (through the XDG desktop portal, `rfd`). They block until closed, so each
//! runs on its own thread; the GUI polls for the answer and turns it into a lab command.

use std::path::PathBuf;
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::thread;

/// A native file dialog running on its own thread (they block until closed).
#[derive(Debug)]
pub struct Dialog {
    /// What the chosen path is for.
    pub purpose: DialogPurpose,
    answer: Receiver<Option<PathBuf>>,
}

/// Why a dialog was opened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DialogPurpose {
    /// Pick a mesh or body file to load.
    OpenMesh,
    /// Choose where to write the plot CSV.
    SaveCsv,
    /// Pick a mesh to add as a part.
    AddPart,
    /// Choose where to write the body file.
    SaveBody,
}

impl Dialog {
    /// Opens the dialog for `purpose`.
    pub fn open(purpose: DialogPurpose, wake: impl Fn() + Send + 'static) -> Self {
        let (tx, rx) = channel();
        thread::spawn(move || {
            let dialog = rfd::FileDialog::new();
            let path = match purpose {
                DialogPurpose::OpenMesh => dialog
                    .add_filter(
                        "Meshes, bodies and robots (OBJ, STL, TOML, URDF, MJCF)",
                        &[
                            "obj", "stl", "toml", "urdf", "xml", "OBJ", "STL", "TOML", "URDF",
                            "XML",
                        ],
                    )
                    .pick_file(),
                DialogPurpose::AddPart => dialog
                    .add_filter("Meshes (OBJ, STL)", &["obj", "stl", "OBJ", "STL"])
                    .pick_file(),
                DialogPurpose::SaveBody => dialog
                    .add_filter("Body files", &["toml"])
                    .set_file_name("body.toml")
                    .save_file(),
                DialogPurpose::SaveCsv => dialog
                    .add_filter("CSV", &["csv"])
                    .set_file_name("inertia-lab.csv")
                    .save_file(),
            };
            let _ = tx.send(path);
            wake();
        });
        Self {
            purpose,
            answer: rx,
        }
    }

    /// `Some(answer)` once closed (`None` inside: cancelled, or no dialog service available).
    pub fn poll(&self) -> Option<Option<PathBuf>> {
        match self.answer.try_recv() {
            Ok(answer) => Some(answer),
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => Some(None),
        }
    }
}
