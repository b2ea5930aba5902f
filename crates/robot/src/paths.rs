//! Where the files a description names are, found as the engines find them: `package://NAME/…`
//! (ROS) and `model://NAME/…` (Gazebo) in a folder NAME given by the user, on the resource
//! path, or found by searching upwards from the description; `file://…` and plain paths beside
//! the description (a relative `file://meshes/…` too, as Gazebo and yourdfpy take it, not in
//! the working folder).

use std::path::{Path, PathBuf};

use crate::ReadOptions;

/// The folders that `package://NAME` or `model://NAME` may mean for a description in `dir`, in
/// the order tried.
pub fn model_folders(name: &str, dir: &Path, options: &ReadOptions) -> Vec<PathBuf> {
    let mut folders: Vec<PathBuf> = options
        .packages
        .iter()
        .filter(|(n, _)| n == name)
        .map(|(_, root)| root.clone())
        .collect();
    folders.extend(options.resource_paths.iter().map(|p| p.join(name)));
    for ancestor in dir.ancestors() {
        if ancestor.file_name().is_some_and(|n| n == name) {
            folders.push(ancestor.to_owned());
        }
        folders.push(ancestor.join(name));
    }
    folders
}

/// Where a mesh file is: the first of the candidates that exists, or every path tried.
pub fn resolve_mesh(
    written: &str,
    dir: &Path,
    options: &ReadOptions,
) -> Result<PathBuf, Vec<PathBuf>> {
    let mut tried = Vec::new();
    if let Some(rest) = written
        .strip_prefix("package://")
        .or_else(|| written.strip_prefix("model://"))
    {
        let (package, inner) = rest.split_once('/').unwrap_or((rest, ""));
        tried.extend(
            model_folders(package, dir, options)
                .into_iter()
                .map(|f| f.join(inner)),
        );
        // Descriptions copied out of their package often keep the package-relative path.
        tried.push(dir.join(inner));
    } else if let Some(path) = written.strip_prefix("file://") {
        tried.push(dir.join(path));
    } else {
        tried.push(dir.join(written));
    }
    match tried.iter().find(|p| p.is_file()) {
        Some(found) => Ok(found.clone()),
        None => Err(tried),
    }
}
