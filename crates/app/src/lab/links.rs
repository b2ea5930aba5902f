//! The lab's commands on a loaded robot description: which of its links is the body (or the
//! whole robot at its zero pose), one method each, like the part commands in `editing.rs`.

use super::robot;
use super::settings::InertiaSource;
use super::{Command, Lab, LabError, Message, RunMode, SpecimenId, Variant};
use crate::i18n::tr;

impl Lab {
    /// The command that shows the loaded robot's link called `name` (a message naming the links
    /// when there is none).
    pub fn link_named(&self, name: &str) -> Command {
        let Some(model) = &self.robot else {
            return Command::Notify(Message {
                text: format!("--link {name}: no robot description is loaded"),
                error: true,
            });
        };
        match model.robot.links.iter().position(|l| l.name == name) {
            Some(i) => Command::ShowLink(Some(i)),
            None => Command::Notify(Message {
                text: format!(
                    "the robot has no link {name:?} (its links: {})",
                    model
                        .robot
                        .links
                        .iter()
                        .map(|l| l.name.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
                error: true,
            }),
        }
    }

    /// Shows link `link` of the loaded robot as the body, or the whole robot for `None`.
    pub(super) fn show_link(&mut self, link: Option<usize>) -> Result<(), LabError> {
        let model = self
            .robot
            .as_ref()
            .ok_or(LabError::NoLink(link.unwrap_or(0)))?;
        let body = match link {
            Some(i) => robot::link_body(model, i)?,
            None => robot::whole_body(model)?,
        };
        let name = body.name.clone();
        let stated = body.stated.is_some();
        self.install(body)?;
        if let Some(m) = &mut self.robot {
            m.shown = link;
        }
        // The whole robot stands still at its zero pose; a link is there to be spun (when the
        // user lets things move by themselves).
        self.run_mode = if link.is_none() || self.settings.display.reduced_motion {
            RunMode::Paused
        } else {
            RunMode::Running
        };
        let mut text = match (link, stated) {
            (None, _) => tr!("lab-whole-robot"),
            (Some(_), true) => tr!("lab-link-stated", link = &name),
            (Some(_), false) => tr!("lab-link-unstated", link = &name),
        };
        // A link that states an inertia spins beside a copy that uses it (the ghost).
        let copy = Variant::Source(InertiaSource::Stated);
        if stated
            && self.settings.body.source != InertiaSource::Stated
            && !self.plan().iter().any(|(_, v)| *v == copy)
        {
            let mut plan = self.plan();
            plan.push((SpecimenId(self.next_id), copy));
            self.next_id += 1;
            let body = self.primary().body_arc().clone();
            if let Err(e) = self.start_all(&plan, &body, self.preset_axis) {
                text = tr!(
                    "lab-link-not-simulated",
                    link = &name,
                    error = e.to_string()
                );
            }
        }
        self.info(text);
        Ok(())
    }
}
