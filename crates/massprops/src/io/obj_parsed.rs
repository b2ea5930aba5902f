//! What either OBJ path reads (the fast one of `obj_fast.rs` and `tobj`'s in `obj.rs`), in one
//! shape, so that the two can be compared bit for bit and finished into a mesh the same way:
//! the welded positions, the faces with their file lines, and the objects and groups.

use nalgebra::Point3;

/// What either path read: the welded positions, the kept faces with their file lines and
/// records, and the lines of the faces skipped for having fewer than three corners.
pub(super) struct Parsed {
    pub positions: Vec<Point3<f64>>,
    pub indices: Vec<u32>,
    pub arities: Vec<usize>,
    pub face_lines: Vec<u32>,
    /// The object and group names (its `elements` only the general path's scratch).
    pub records: Records,
    /// The object and group of the kept faces, as runs.
    pub runs: Vec<PartRun>,
    pub two_corner: Vec<usize>,
}

/// Kept faces from `first` on (up to the next run) are in this object and group (indices into
/// [`Records::objects`] and [`Records::groups`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct PartRun {
    pub first: usize,
    pub object: u32,
    pub group: u32,
}

/// Adds the run of face `face` when its object or group differs from the last run's.
pub(super) fn extend_runs(runs: &mut Vec<PartRun>, face: usize, object: u32, group: u32) {
    if runs
        .last()
        .is_none_or(|r| (r.object, r.group) != (object, group))
    {
        runs.push(PartRun {
            first: face,
            object,
            group,
        });
    }
}

/// One `f` or `l` record: its one-based line, whether it is a polyline, and the object and group
/// (indices into [`Records::objects`] and [`Records::groups`]) in force there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Record {
    pub line: usize,
    pub polyline: bool,
    pub object: u32,
    pub group: u32,
}

/// The elements tobj returns (each `f` or `l` record, in order) and the object and group names.
#[derive(Debug, PartialEq)]
pub(super) struct Records {
    pub elements: Vec<Record>,
    /// Names of `o` statements; index 0 is the unnamed part before the first.
    pub objects: Vec<String>,
    /// Names of `g` statements, likewise.
    pub groups: Vec<String>,
}

impl Records {
    /// No element yet, the unnamed object and group in force.
    pub fn new() -> Self {
        Self {
            elements: Vec::new(),
            objects: vec![UNNAMED.to_owned()],
            groups: vec![UNNAMED.to_owned()],
        }
    }
}

/// The name of the faces before a file's first `o` (or `g`).
const UNNAMED: &str = "unnamed";

/// The parts of the kept faces (objects, or groups when the file has no `o`): the names, and
/// for each face its part; both empty when the file names neither. Parts of the same name are
/// one part, and names without faces are dropped.
pub(super) fn parts(records: &Records, runs: &[PartRun], faces: usize) -> (Vec<String>, Vec<u32>) {
    let by_object = records.objects.len() > 1;
    if !by_object && records.groups.len() <= 1 {
        return (Vec::new(), Vec::new());
    }
    let mut names: Vec<String> = Vec::new();
    let mut out = Vec::with_capacity(faces);
    for (k, r) in runs.iter().enumerate() {
        let end = runs.get(k + 1).map_or(faces, |next| next.first);
        let name = if by_object {
            &records.objects[r.object as usize]
        } else {
            &records.groups[r.group as usize]
        };
        let part = match names.iter().position(|n| n == name) {
            Some(i) => i as u32,
            None => {
                names.push(name.clone());
                (names.len() - 1) as u32
            }
        };
        out.resize(end, part);
    }
    (names, out)
}
