//! How the app starts, whatever opens it: the file and link asked for (a window's arguments), a
//! scene's commands (a page's link), and a measuring (`--bench-frames`, `?bench=N`) or capturing
//! (`--screenshot`) run, turned into the lab's first commands.
//! The platform modules only open the window or the page and hand over a [`Start`].

use std::path::PathBuf;
use std::sync::Arc;

use super::LabApp;
use super::bench::Bench;
use super::capture::Capture;
use crate::lab::settings::AppSettings;
use crate::lab::{Command, LabError, Variant};

/// What the app is to do first.
#[derive(Debug, Default)]
pub struct Start {
    /// A mesh, body file or robot description to open.
    pub file: Option<PathBuf>,
    /// With a robot description: the link to show as the body.
    pub link: Option<String>,
    /// Commands to apply then (a page's link: the body, its spin, the comparison).
    pub commands: Vec<Command>,
    /// Measure frame times (with the copies compared and the seconds simulated first).
    pub bench: Option<Bench>,
    /// Copies compared while measuring.
    pub ghosts: Vec<Variant>,
    /// Simulated seconds before measuring, so the plots hold that much history.
    pub history: f64,
    /// Take a picture (after `after` simulated seconds, paused there), then close.
    pub capture: Option<Capture>,
    /// Simulated seconds before the picture.
    pub after: f64,
    /// The embedded layout (`?embed=1`): the 3D view, the plots and the lessons.
    pub embed: bool,
    /// A link's settings, applied again after `commands` (a lesson's step sets some up).
    pub tweaks: super::link::Tweaks,
    /// The language asked for (`--lang`, `?lang=`), over the saved one.
    pub language: Option<crate::i18n::Language>,
}

impl Start {
    /// Whether the run is measured or captured: default settings, nothing persisted.
    pub fn scripted(&self) -> bool {
        self.bench.is_some() || self.capture.is_some()
    }

    /// The app on `settings` (the saved ones, or the defaults for a scripted run), with the
    /// start carried out.
    ///
    /// # Errors
    /// The built-in body cannot be set up (a bug).
    pub fn app(
        self,
        settings: AppSettings,
        gl: Option<Arc<three_d::context::Context>>,
        ctx: &egui::Context,
    ) -> Result<LabApp, LabError> {
        let scripted = self.scripted();
        let mut settings = settings;
        if let Some(language) = self.language {
            settings.display.language = Some(language);
        }
        let mut app = LabApp::new(settings, gl, ctx)?;
        app.shared.embed = self.embed;
        app.shared.lessons_open = self.embed;
        if let Some(path) = self.file {
            app.command(Command::LoadFile(path));
            if scripted || self.link.is_some() {
                // Every measured frame, and the picture, must show the mesh.
                app.lab.wait_for_load();
            }
            if let Some(name) = &self.link {
                app.command(app.lab.link_named(name));
            }
        }
        for command in self.commands {
            app.command(command);
        }
        if self.tweaks != super::link::Tweaks::default() {
            let settings = self.tweaks.apply(app.lab.settings().clone());
            app.command(Command::Settings(Box::new(settings)));
        }
        if self.bench.is_some() {
            if !self.ghosts.is_empty() {
                app.command(Command::Compare(self.ghosts));
            }
            if self.history > 0.0 {
                app.lab.advance_for(self.history);
            }
            app.bench = self.bench;
        }
        if let Some(capture) = self.capture {
            // A file that did not load must not give a picture of the default body.
            if let Some(m) = app.lab.message().filter(|m| m.error) {
                capture.fail(m.text.clone());
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
                return Ok(app);
            }
            app.lab.advance_for(self.after);
            // The picture shows the state at exactly `after` seconds.
            app.command(Command::TogglePause);
            app.capture = Some(capture);
        }
        Ok(app)
    }
}
