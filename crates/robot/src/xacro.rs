//! xacro descriptions: expanded by ROS's own `xacro` tool (PyPI `xacro` 2.1.1, which runs
//! without ROS), and each expanded link traced back to where the `.xacro` sources write it, so
//! that a fix can say which `<inertial>` to change in which file (the expanded URDF is not the
//! user's file).
//!
//! `$(find NAME)` needs ROS's package index (`ament_index_python`), which a machine without ROS
//! lacks: the tool runs with a small module of that name of ours on `PYTHONPATH`
//! ([`PACKAGE_INDEX`]), which answers with the folders given as `--package NAME=DIR`, or else a
//! folder NAME found upwards from the description, as `package://NAME` is found.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::ReadOptions;
use crate::error::{Location, RobotError};
use crate::paths::model_folders;

/// The command that installs the tool.
pub const INSTALL: &str = "pip install xacro==2.1.1";

/// A description expanded by xacro.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Expanded {
    /// The URDF xacro wrote.
    pub text: String,
    /// What it was made from.
    pub xacro: Xacro,
}

/// What xacro expanded a description from ([`crate::Robot::xacro`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Xacro {
    /// The `.xacro` files: the description first, then what it includes.
    pub sources: Vec<PathBuf>,
    /// The arguments given (`NAME:=VALUE`).
    pub args: Vec<(String, String)>,
}

/// Where a link of the expanded URDF is written in the sources.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Origin {
    /// The `<link>` element (in a macro, where the macro writes it).
    pub link: Location,
    /// Its `<inertial>` child, when the link writes one itself (not through a macro call).
    pub inertial: Option<Location>,
    /// The `name` as written (`${prefix}finger`).
    pub written_name: String,
}

/// `ament_index_python.packages` for xacro's `$(find NAME)`: the folder from the packages given
/// (JSON in `INERTIA_LAB_PACKAGES`), else a folder NAME found upwards from the description
/// (`INERTIA_LAB_DESCRIPTION_DIR`).
pub const PACKAGE_INDEX: &str = r#"# Inertia Lab's stand-in for ROS's package index, for xacro's $(find NAME) outside ROS.
import json
import os


class PackageNotFoundError(KeyError):
    pass


def get_package_share_directory(package_name, print_warning=True):
    given = json.loads(os.environ.get("INERTIA_LAB_PACKAGES", "{}"))
    for folder in given.get(package_name, []):
        if os.path.isdir(folder):
            return folder
    raise PackageNotFoundError(
        "package '%s' not found: give its folder as --package %s=DIR" % (package_name, package_name)
    )
"#;

/// Runs xacro on `path` with `options.xacro_args`.
pub fn expand(path: &Path, options: &ReadOptions) -> Result<Expanded, RobotError> {
    let dir = path.parent().map(Path::to_owned).unwrap_or_default();
    let index = PackageIndex::write().map_err(|e| RobotError::XacroFailed {
        file: path.to_owned(),
        message: format!("cannot write the package index for $(find): {e}"),
    })?;
    let shim = index.0.clone();
    // Every folder each package may be, nearest first; the stand-in takes the first that exists.
    let mut packages = String::from("{");
    let names = package_names(path);
    for (k, name) in names.iter().enumerate() {
        let folders: Vec<String> = model_folders(name, &dir, options)
            .iter()
            .map(|f| json_string(&f.to_string_lossy()))
            .collect();
        if k > 0 {
            packages.push(',');
        }
        packages.push_str(&format!("{}:[{}]", json_string(name), folders.join(",")));
    }
    packages.push('}');
    let python_path = std::env::var_os("PYTHONPATH").map_or_else(
        || shim.clone().into_os_string(),
        |p| {
            let mut all = vec![shim.clone()];
            all.extend(std::env::split_paths(&p));
            std::env::join_paths(all).unwrap_or_else(|_| shim.clone().into_os_string())
        },
    );
    let run = |extra: &[&str]| {
        Command::new("xacro")
            .args(extra)
            .arg(path)
            .args(options.xacro_args.iter().map(|(k, v)| format!("{k}:={v}")))
            .env("PYTHONPATH", &python_path)
            .env("INERTIA_LAB_PACKAGES", &packages)
            .current_dir(&dir)
            .output()
    };
    let out = run(&[]).map_err(|e| match e.kind() {
        std::io::ErrorKind::NotFound => RobotError::XacroMissing {
            file: path.to_owned(),
        },
        _ => RobotError::XacroFailed {
            file: path.to_owned(),
            message: e.to_string(),
        },
    })?;
    if !out.status.success() {
        return Err(RobotError::XacroFailed {
            file: path.to_owned(),
            message: String::from_utf8_lossy(&out.stderr).trim().to_owned(),
        });
    }
    let mut sources = vec![path.to_owned()];
    if let Ok(deps) = run(&["--deps"])
        && deps.status.success()
    {
        sources.extend(
            String::from_utf8_lossy(&deps.stdout)
                .split_whitespace()
                .map(|d| dir.join(d))
                .filter(|d| d != path),
        );
    }
    Ok(Expanded {
        text: String::from_utf8_lossy(&out.stdout).into_owned(),
        xacro: Xacro {
            sources,
            args: options.xacro_args.clone(),
        },
    })
}

/// The package names `$(find NAME)` asks for in the description and the files it includes (as
/// far as they can be read before expansion: the names are plain text in the calls).
fn package_names(path: &Path) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    let mut seen = vec![path.to_owned()];
    let mut k = 0;
    while k < seen.len() && k < 256 {
        let text = std::fs::read_to_string(&seen[k]).unwrap_or_default();
        let here = seen[k].parent().map(Path::to_owned).unwrap_or_default();
        for (i, _) in text.match_indices("$(find ") {
            let rest = &text[i + 7..];
            let end = rest.find(')').unwrap_or(rest.len());
            let name = rest[..end].trim().to_owned();
            if !name.is_empty() && !names.contains(&name) {
                names.push(name);
            }
        }
        // Plain relative includes, whose own `$(find …)` count too.
        for (i, _) in text.match_indices("filename=\"") {
            let rest = &text[i + 10..];
            let file = &rest[..rest.find('"').unwrap_or(rest.len())];
            if !file.contains("$(") && !file.contains("${") && file.ends_with(".xacro") {
                let p = here.join(file);
                if !seen.contains(&p) {
                    seen.push(p);
                }
            }
        }
        k += 1;
    }
    names
}

fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A folder holding the stand-in package index, removed when dropped.
struct PackageIndex(PathBuf);

impl PackageIndex {
    /// Writes one for a single run of xacro (unique per call, so that threads do not share).
    fn write() -> std::io::Result<Self> {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir =
            std::env::temp_dir().join(format!("inertia-lab-xacro-{}-{n}", std::process::id()));
        let module = dir.join("ament_index_python");
        std::fs::create_dir_all(&module)?;
        std::fs::write(module.join("__init__.py"), "")?;
        std::fs::write(module.join("packages.py"), PACKAGE_INDEX)?;
        Ok(PackageIndex(dir))
    }
}

impl Drop for PackageIndex {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Where the `.xacro` sources write the expanded link `name`: every `<link>` whose `name`,
/// with each `${…}` taken as any text, matches it.
pub fn origins(sources: &[PathBuf], name: &str) -> Vec<Origin> {
    let mut found = Vec::new();
    for path in sources {
        let Ok(text) = std::fs::read_to_string(path) else {
            continue;
        };
        let Ok(doc) = roxmltree::Document::parse(&text) else {
            continue;
        };
        let at = |n: roxmltree::Node<'_, '_>| {
            let pos = doc.text_pos_at(n.range().start);
            Location {
                file: path.clone(),
                line: pos.row,
                column: pos.col,
            }
        };
        for link in doc
            .descendants()
            .filter(|n| n.is_element() && n.tag_name().name() == "link")
        {
            let Some(written) = link.attribute("name") else {
                continue;
            };
            if pattern_matches(written, name) {
                found.push(Origin {
                    link: at(link),
                    inertial: link
                        .children()
                        .find(|c| c.is_element() && c.tag_name().name() == "inertial")
                        .map(at),
                    written_name: written.to_owned(),
                });
            }
        }
    }
    found
}

/// Whether `name` is what `written` can expand to, each `${…}`/`$(…)` standing for any text.
pub fn pattern_matches(written: &str, name: &str) -> bool {
    let mut parts: Vec<&str> = Vec::new();
    let mut rest = written;
    while let Some(start) = rest.find("${").or_else(|| rest.find("$(")) {
        parts.push(&rest[..start]);
        let close = if rest[start + 1..].starts_with('{') {
            '}'
        } else {
            ')'
        };
        rest = rest[start..]
            .find(close)
            .map_or("", |e| &rest[start + e + 1..]);
        parts.push("\u{0}");
    }
    parts.push(rest);
    let literal: Vec<&str> = parts.iter().copied().filter(|p| *p != "\u{0}").collect();
    if parts.len() == 1 {
        return written == name;
    }
    // Literal pieces in order: the first at the start, the last at the end, the rest between.
    let (first, last) = (literal[0], literal[literal.len() - 1]);
    if !name.starts_with(first) || !name[first.len()..].ends_with(last) {
        return false;
    }
    let mut middle = &name[first.len()..name.len() - last.len()];
    for piece in &literal[1..literal.len() - 1] {
        match middle.find(piece) {
            Some(i) => middle = &middle[i + piece.len()..],
            None => return false,
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::pattern_matches;

    #[test]
    fn substitutions_in_a_link_name_match_any_text() {
        assert!(pattern_matches("${prefix}finger", "left_finger"));
        assert!(pattern_matches("${prefix}_link${n}", "arm_link3"));
        assert!(pattern_matches("base", "base"));
        assert!(!pattern_matches("base", "base2"));
        assert!(!pattern_matches("${p}finger", "left_thumb"));
        assert!(!pattern_matches("${a}_x_${b}", "a_y_b"));
    }
}
