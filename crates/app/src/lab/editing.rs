//! The lab's edits of a body made of parts, one method per command: split a mesh into its
//! parts, add a part, edit one (a material, void or thin wall re-sums the masses; a placement
//! moves one part; see [`LoadedBody::edit_part`]), remove one, save the body file. Each leaves
//! every specimen running with p and L kept, or changes nothing and says why.

use crate::i18n::tr;
use std::path::Path;
use std::sync::Arc;

use massprops::PartEntry;

use super::Lab;
use super::body::{EditEffect, LoadedBody};
use super::error::LabError;
use super::loader::Purpose;
use super::parts::{self, PartModel};
use inertia_io::kind::FileKind;

impl Lab {
    /// [`Command::SplitIntoParts`](super::Command::SplitIntoParts).
    pub(super) fn split_into_parts(&mut self) -> Result<(), LabError> {
        let parts = self.current_parts(false)?;
        let n = parts.len();
        self.rebody(parts)?;
        self.info(tr!("lab-split", parts = n));
        Ok(())
    }

    /// Whether files dropped on the lab join the body as parts: meshes dropped on a body made of
    /// parts do; anything else (a mesh on a single mesh, a body file, a robot) replaces the body.
    pub fn drop_adds_parts(&self, names: &[&Path]) -> bool {
        self.drop_may_add_parts()
            && names
                .iter()
                .all(|n| matches!(FileKind::of(n), Some(FileKind::Mesh(_))))
    }

    /// Whether meshes dropped now would join the body as parts (before their names are known:
    /// what the window says while files are dragged over it).
    pub fn drop_may_add_parts(&self) -> bool {
        self.primary().body().composition.is_some()
    }

    /// What new parts join: the body's name and its parts now (a single mesh as one part, whole).
    ///
    /// # Errors
    /// The body cannot be made of parts (a robot's).
    pub(super) fn adding_parts(&self) -> Result<Purpose, LabError> {
        Ok(Purpose::AddParts {
            body: self.primary().body().name.clone(),
            parts: self.current_parts(true)?,
        })
    }

    /// [`Command::EditPart`](super::Command::EditPart).
    pub(super) fn edit_part(
        &mut self,
        index: usize,
        entry: PartEntry,
        visible: bool,
    ) -> Result<(), LabError> {
        let body = self.primary().body();
        if body.composition.is_none() {
            // A single mesh becomes a body of one part: a change of topology.
            let mut parts = self.current_parts(true)?;
            let part = parts.get_mut(index).ok_or(LabError::NoPart(index))?;
            part.entry = entry;
            part.visible = visible;
            if !parts.iter().any(|p| p.visible) {
                return Err(LabError::LastShown);
            }
            return self.rebody(parts);
        }
        let (edited, effect) = body.edit_part(index, entry, visible)?;
        self.set_body(Arc::new(edited), effect == EditEffect::Drawing)
    }

    /// [`Command::RemovePart`](super::Command::RemovePart).
    pub(super) fn remove_part(&mut self, index: usize) -> Result<(), LabError> {
        let mut parts = self.current_parts(true)?;
        if index >= parts.len() {
            return Err(LabError::NoPart(index));
        }
        if parts.len() == 1 {
            return Err(LabError::LastPart);
        }
        parts.remove(index);
        self.rebody(parts)
    }

    /// [`Command::SaveBody`](super::Command::SaveBody).
    pub(super) fn save_body(&mut self, path: &Path) -> Result<(), LabError> {
        let parts = self.current_parts(true)?;
        let written = parts::save(&parts, path)?;
        self.info(tr!(
            "lab-saved",
            path = path.display().to_string(),
            what = written
        ));
        Ok(())
    }

    /// The body's parts: its own, or for a single mesh at the current density, the whole mesh
    /// as one part (`whole`) or its file's parts.
    pub(super) fn current_parts(&self, whole: bool) -> Result<Vec<PartModel>, LabError> {
        let body = self.primary().body();
        if let Some(c) = &body.composition {
            return Ok(c.parts.clone());
        }
        let Some((path, file)) = &body.file else {
            return Err(LabError::AlreadyParts(body.name.clone()));
        };
        parts::from_single(&body.name, path, file, self.primary().density(), whole)
    }

    /// Every specimen goes on with the body `parts` make, p and L kept (a change of topology:
    /// the body is assembled again). Nothing changes if the parts make no body or one specimen
    /// cannot take it.
    fn rebody(&mut self, parts: Vec<PartModel>) -> Result<(), LabError> {
        let name = self.primary().body().name.clone();
        let body = Arc::new(LoadedBody::from_parts(&name, parts)?);
        self.set_body(body, true)
    }
}
