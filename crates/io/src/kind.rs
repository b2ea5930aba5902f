//! What a file holds, decided from its name in one place for every front end: a mesh of one of
//! massprops' [`MESH_FORMATS`], a body file of parts, or a robot description. The dialogs'
//! filters, the drop hints, the help texts and the Python package's folder listing are all
//! written from these lists, so a mesh format added to the readers' table is offered everywhere.

use std::path::Path;

use massprops::io::{BODY_FILE_EXTENSION, MESH_FORMATS, MeshFormat};

use crate::wording::alternatives;

/// The extensions of robot descriptions: URDF (and xacro, which the `xacro` tool expands),
/// MuJoCo's MJCF as `.xml` (or `.mjcf`), and Gazebo's
/// SDFormat (`.sdf`).
pub const ROBOT_EXTENSIONS: &[&str] = &["urdf", "xacro", "xml", "mjcf", "sdf"];

/// What a file holds.
#[derive(Debug, Clone, Copy)]
pub enum FileKind {
    /// A mesh, read by its format's reader.
    Mesh(&'static MeshFormat),
    /// A body file of parts (TOML naming meshes, materials and placements).
    Body,
    /// A robot description (URDF, MJCF or SDFormat).
    Robot,
}

impl FileKind {
    /// The kind of the file named `path`, by its extension (any case); `None` for a file the
    /// lab does not read.
    pub fn of(path: &Path) -> Option<FileKind> {
        if let Some(format) = MeshFormat::of(path) {
            return Some(FileKind::Mesh(format));
        }
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        if extension == BODY_FILE_EXTENSION {
            Some(FileKind::Body)
        } else if ROBOT_EXTENSIONS.contains(&extension.as_str()) {
            Some(FileKind::Robot)
        } else {
            None
        }
    }

    /// Whether `path` names a robot description.
    pub fn is_robot(path: &Path) -> bool {
        matches!(FileKind::of(path), Some(FileKind::Robot))
    }
}

/// What a front end opens: meshes and body files always, robot descriptions where it reads
/// them (the page does not: a description names mesh files it cannot fetch).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Openable {
    /// Whether robot descriptions are opened.
    pub robots: bool,
}

impl Openable {
    /// The extensions of every file opened, lower case, without the dot.
    pub fn extensions(self) -> Vec<&'static str> {
        let mut all: Vec<&'static str> = MeshFormat::all_extensions().collect();
        all.push(BODY_FILE_EXTENSION);
        if self.robots {
            all.extend(ROBOT_EXTENSIONS);
        }
        all
    }

    /// A file dialog's label for them ("Meshes, bodies and robots (OBJ, STL, TOML, URDF, xacro, MJCF, SDF)").
    pub fn label(self) -> String {
        let meshes = MeshFormat::names(", ");
        if self.robots {
            format!("Meshes, bodies and robots ({meshes}, TOML, URDF, xacro, MJCF, SDF)")
        } else {
            format!("Meshes and bodies ({meshes}, TOML with its meshes)")
        }
    }

    /// What may be dropped, for a hint ("a mesh, a body .toml or a robot .urdf/.sdf/.xml"). The
    /// mesh formats are not listed in it, so that the hint (and the panel laid out around it)
    /// stays the same as formats are added: [`mesh_formats_hint`] lists them.
    pub fn words(self) -> &'static str {
        if self.robots {
            "a mesh, a body .toml or a robot .urdf/.sdf/.xml"
        } else {
            "a mesh, or a body .toml with its meshes"
        }
    }
}

/// The mesh formats with their extensions, for a tooltip ("Meshes: OBJ (.obj), STL (.stl)").
pub fn mesh_formats_hint() -> String {
    let formats: Vec<String> = MESH_FORMATS
        .iter()
        .map(|f| {
            let extensions: Vec<String> = f.extensions.iter().map(|e| format!(".{e}")).collect();
            format!("{} ({})", f.name, extensions.join(", "))
        })
        .collect();
    format!("Meshes: {}", formats.join(", "))
}

/// The extensions of a part's mesh, lower case, without the dot.
pub fn part_extensions() -> Vec<&'static str> {
    MeshFormat::all_extensions().collect()
}

/// A dialog's label for a part's mesh ("Meshes (OBJ, STL)").
pub fn part_label() -> String {
    format!("Meshes ({})", MeshFormat::names(", "))
}

/// The mesh formats in words for help texts ("OBJ or STL").
pub fn mesh_format_words() -> String {
    let names: Vec<&str> = MESH_FORMATS.iter().map(|f| f.name).collect();
    alternatives(&names)
}

/// The mesh files' extensions in words for help texts (".obj or .stl").
pub fn mesh_extension_words() -> String {
    let extensions: Vec<String> = MeshFormat::all_extensions()
        .map(|e| format!(".{e}"))
        .collect();
    alternatives(&extensions)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every extension opened is classified as what it is, in any case, and the kinds' lists
    /// share no extension.
    #[test]
    fn each_extension_names_one_kind() {
        for ext in (Openable { robots: true }).extensions() {
            for name in [format!("f.{ext}"), format!("F.{}", ext.to_uppercase())] {
                let kind = FileKind::of(Path::new(&name));
                let expected = if MeshFormat::all_extensions().any(|m| m == ext) {
                    matches!(kind, Some(FileKind::Mesh(f)) if f.extensions.contains(&ext))
                } else if ext == BODY_FILE_EXTENSION {
                    matches!(kind, Some(FileKind::Body))
                } else {
                    matches!(kind, Some(FileKind::Robot))
                };
                assert!(expected, "{name}: {kind:?}");
            }
        }
        let mut all = Openable { robots: true }.extensions();
        let count = all.len();
        all.sort_unstable();
        all.dedup();
        assert_eq!(all.len(), count, "an extension of two kinds");
        assert!(FileKind::of(Path::new("notes.txt")).is_none());
        assert!(FileKind::is_robot(Path::new("panda.URDF")));
    }

    /// The words name every format of the table.
    #[test]
    fn the_words_name_every_format() {
        assert_eq!(
            mesh_format_words(),
            "OBJ, STL, PLY, OFF, glTF, MuJoCo MSH, COLLADA or 3MF"
        );
        assert_eq!(
            mesh_extension_words(),
            ".obj, .stl, .ply, .off, .glb, .gltf, .msh, .dae or .3mf"
        );
        assert_eq!(
            part_label(),
            "Meshes (OBJ, STL, PLY, OFF, glTF, MuJoCo MSH, COLLADA, 3MF)"
        );
        assert_eq!(
            mesh_formats_hint(),
            "Meshes: OBJ (.obj), STL (.stl), PLY (.ply), OFF (.off), glTF (.glb, .gltf), \
             MuJoCo MSH (.msh), COLLADA (.dae), 3MF (.3mf)"
        );
        assert_eq!(
            Openable { robots: false }.extensions(),
            [
                "obj", "stl", "ply", "off", "glb", "gltf", "msh", "dae", "3mf", "toml"
            ]
        );
    }
}
