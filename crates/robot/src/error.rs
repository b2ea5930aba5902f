//! Why a robot description cannot be read, and where in which file.

use std::fmt;
use std::path::PathBuf;
use std::sync::Arc;

/// A place in a description's files: the file, and the one-based line and column of an element.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// The file, as it was reached (the description or a file it includes).
    pub file: PathBuf,
    /// One-based line.
    pub line: u32,
    /// One-based column.
    pub column: u32,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file.display(), self.line, self.column)
    }
}

/// Why a description cannot be read. Each names the file and, inside it, the line and element.
#[derive(Debug, Clone, thiserror::Error)]
pub enum RobotError {
    /// The file cannot be read.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What the system said.
        source: Arc<std::io::Error>,
    },
    /// The text is not well-formed XML.
    #[error("{at}: not well-formed XML: {message}")]
    Xml {
        /// Where the parser stopped.
        at: Box<Location>,
        /// The parser's words.
        message: String,
    },
    /// A xacro file read from its text alone: only a file on disk can be expanded.
    #[error(
        "{}:{line}: {what} is xacro's: read the file itself, which xacro expands, or run xacro \
         first, `xacro {} > robot.urdf`",
        file.display(),
        file.display()
    )]
    Xacro {
        /// The file.
        file: PathBuf,
        /// The line of the first xacro element or `${…}`/`$(…)` substitution.
        line: u32,
        /// What it is.
        what: String,
    },
    /// A xacro file, and the `xacro` tool is not installed.
    #[error(
        "{}: a xacro file, and the xacro tool that expands it is not installed: `{}` installs \
         it (it runs without ROS)",
        file.display(),
        crate::xacro::INSTALL
    )]
    XacroMissing {
        /// The file.
        file: PathBuf,
    },
    /// xacro refused the file.
    #[error("{}: xacro cannot expand it: {message}", file.display())]
    XacroFailed {
        /// The file.
        file: PathBuf,
        /// What xacro said.
        message: String,
    },
    /// Neither `<robot>` (URDF), `<mujoco>` (MJCF) nor `<sdf>` (SDFormat) at the root.
    #[error(
        "{}: the root element is <{root}>; a robot description is a URDF (<robot>), an MJCF \
         (<mujoco>) or an SDFormat (<sdf>) file",
        file.display()
    )]
    UnknownFormat {
        /// The file.
        file: PathBuf,
        /// The root element's name.
        root: String,
    },
    /// An attribute whose value cannot be used.
    #[error("{at}: <{element} {attribute}=\"{value}\">: {problem}")]
    Attribute {
        /// The element's place.
        at: Box<Location>,
        /// The element's name.
        element: String,
        /// The attribute's name.
        attribute: String,
        /// Its value as written.
        value: String,
        /// What is wrong with it.
        problem: String,
    },
    /// Something the format requires is not there, or the elements contradict each other.
    #[error("{at}: <{element}>: {problem}")]
    Element {
        /// The element's place.
        at: Box<Location>,
        /// The element's name.
        element: String,
        /// What is wrong.
        problem: String,
    },
}
