//! The batch table: one row for each file of a batch, whatever the file holds. What the Python
//! package's `measure_table` and `measure_files` write, in the versioned schema docs/python.md documents
//! ("Batch table", [`SCHEMA_VERSION`]).
//!
//! A row never fails: a file that cannot be read, parsed or integrated, or whose reading panics,
//! is a row with `status` `error`, its [`massprops::MeshError::kind`] and the message `props`
//! would print. Each file is made into a body as `props` makes it: a mesh file by the project's
//! readers and [`massprops::MeshFile::analyze`], a body file by [`crate::input::resolve`], so a
//! row's numbers are `props --json`'s. The row's `id` is the SHA-256 of the file's bytes, so that
//! a batch can be resumed and a file found again under another name.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;
use std::time::Instant;

use massprops::{Analysis, Composite, Defect, MassProperties, MassSpec, MeshError, Warning};
use sha2::{Digest, Sha256};

use crate::export::quaternion_wxyz;
use crate::input::{InputError, Request, Resolved, Source, resolve, resolve_mesh};

/// Version of the batch table's columns; bumped on any incompatible change.
pub const SCHEMA_VERSION: u32 = 1;

/// How a file fared.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Numbers and no warning.
    Ok,
    /// Numbers, with warnings to read before trusting them.
    Warn,
    /// No numbers: `error_kind` and `error_message` say why.
    Error,
}

impl Status {
    /// The name in the table.
    pub fn name(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Warn => "warn",
            Status::Error => "error",
        }
    }
}

/// One file's row.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The file's path as given.
    pub path: String,
    /// SHA-256 of its bytes, lowercase hex; `None` when it cannot be read.
    pub id: Option<String>,
    /// Its size in bytes, when it can be read.
    pub size_bytes: Option<u64>,
    /// The density asked for (per volume; per area for the shell method); `None` for a body
    /// file, whose parts give their own.
    pub density: Option<f64>,
    /// The numbers, or why there are none.
    pub outcome: Result<Measured, Failure>,
    /// Reading and parsing the file (a body file: reading its text), in milliseconds.
    pub parse_ms: f64,
    /// Everything after parsing (a body file: its meshes read, integrated and summed).
    pub compute_ms: f64,
}

/// Why a row has no numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    /// [`MeshError::kind`], `unknown_part` or `mass_of_parts` (options that do not fit the
    /// file), or `panic`.
    pub kind: &'static str,
    /// What `props` would print.
    pub message: String,
}

/// A row's numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// `volume`, `shell`, … or `composite` for a body file.
    pub method: &'static str,
    /// The mass properties (mesh axes, about the centre of mass for the tensor).
    pub properties: MassProperties,
    /// The enclosed volume, when there is one.
    pub volume: Option<f64>,
    /// The mesh is closed (every edge shared by two faces); `None` for a body file.
    pub closed: Option<bool>,
    /// Its faces agree on their winding across every edge; `None` for a body file.
    pub consistent: Option<bool>,
    /// Triangles after splitting polygons; `None` for a body file.
    pub triangles: Option<u64>,
    /// Connected shells; `None` for a body file.
    pub shells: Option<u64>,
    /// The warnings (a body file: every part's).
    pub warnings: Vec<Warning>,
}

impl Row {
    /// The row's status.
    pub fn status(&self) -> Status {
        match &self.outcome {
            Err(_) => Status::Error,
            Ok(m) if m.warnings.is_empty() => Status::Ok,
            Ok(_) => Status::Warn,
        }
    }
}

impl Measured {
    /// The sum of the `count`s of the warnings with this code (0 when there is none).
    pub fn count_of(&self, code: &str) -> u64 {
        self.warnings
            .iter()
            .filter(|w| w.code() == code)
            .map(|w| w.count as u64)
            .sum()
    }

    /// The `effect_on_mass` of largest size among the warnings, with its sign.
    pub fn largest_effect(&self) -> Option<f64> {
        self.warnings
            .iter()
            .filter_map(|w| w.effect_on_mass)
            .max_by(|a, b| a.abs().total_cmp(&b.abs()))
    }

    fn of_mesh(a: &Analysis) -> Self {
        let d = &a.diagnostics;
        Self {
            method: a.method.name(),
            properties: a.properties,
            volume: a.volume,
            closed: Some(d.is_closed()),
            consistent: Some(d.is_consistently_oriented()),
            triangles: Some(d.triangles as u64),
            shells: Some(a.shells.len() as u64),
            warnings: a.warnings.clone(),
        }
    }

    fn of_parts(c: &Composite) -> Self {
        Self {
            method: "composite",
            properties: c.properties,
            volume: None,
            closed: None,
            consistent: None,
            triangles: None,
            shells: None,
            warnings: c.parts.iter().flat_map(|p| p.warnings.clone()).collect(),
        }
    }
}

/// Measures one file: `bytes` when the caller has read them already (a Ray or Dask task), else
/// the file at `path`. Never panics: a panic while measuring is the row's error.
pub fn measure(path: &Path, bytes: Option<&[u8]>, request: &Request) -> Row {
    let start = Instant::now();
    let mut row = Row {
        path: path.display().to_string(),
        id: None,
        size_bytes: None,
        density: match request.spec {
            MassSpec::Density(d) if !massprops::io::is_body_file(path) => Some(d),
            _ => None,
        },
        outcome: Err(Failure {
            kind: "io",
            message: String::new(),
        }),
        parse_ms: 0.0,
        compute_ms: 0.0,
    };
    let owned;
    let bytes = match bytes {
        Some(b) => b,
        None => match std::fs::read(path) {
            Ok(b) => {
                owned = b;
                owned.as_slice()
            }
            Err(e) => {
                let e = MeshError::Io {
                    path: path.to_path_buf(),
                    source: std::sync::Arc::new(e),
                };
                row.outcome = Err(failure(&e));
                row.parse_ms = ms(start);
                return row;
            }
        },
    };
    row.id = Some(sha256_hex(bytes));
    row.size_bytes = Some(bytes.len() as u64);
    let read_ms = ms(start);
    let caught = catch_unwind(AssertUnwindSafe(|| body_of(path, bytes, request)));
    let (outcome, parse_ms, compute_ms) = caught.unwrap_or_else(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without a message".to_owned());
        let message = format!(
            "{}: the reader or the analysis panicked (a bug: please report it with the file): \
             {message}",
            path.display()
        );
        let failure = Failure {
            kind: "panic",
            message,
        };
        (Err(failure), 0.0, ms(start) - read_ms)
    });
    row.outcome = outcome;
    row.parse_ms = read_ms + parse_ms;
    row.compute_ms = compute_ms;
    row
}

/// The body of one file's bytes, with the time spent parsing and computing (ms): the error
/// messages are `props`'s, each naming the file.
fn body_of(path: &Path, bytes: &[u8], request: &Request) -> (Result<Measured, Failure>, f64, f64) {
    if massprops::io::is_body_file(path) {
        let start = Instant::now();
        let outcome = measured(resolve(Source::Bytes(bytes, path), request));
        return (outcome, 0.0, ms(start));
    }
    let start = Instant::now();
    let file = massprops::parse_mesh(bytes, path);
    let parse = ms(start);
    let file = match file {
        Ok(file) => file,
        Err(e) => return (Err(failure(&e)), parse, 0.0),
    };
    let start = Instant::now();
    let outcome = measured(resolve_mesh(path, file, request));
    (outcome, parse, ms(start))
}

/// The numbers of a resolved body, or why there are none.
fn measured(resolved: Result<Resolved, InputError>) -> Result<Measured, Failure> {
    match resolved {
        Ok(Resolved::Parts(parts)) => Ok(Measured::of_parts(&parts.composite)),
        Ok(Resolved::Mesh { analysis, .. }) => Ok(Measured::of_mesh(&analysis)),
        Err(e) => Err(input_failure(&e)),
    }
}

fn failure(e: &MeshError) -> Failure {
    Failure {
        kind: e.kind(),
        message: e.to_string(),
    }
}

fn input_failure(e: &InputError) -> Failure {
    let kind = match e {
        InputError::Mesh { source, .. } | InputError::Read(source) => source.kind(),
        InputError::UnknownPart { .. } => "unknown_part",
        InputError::MassOfParts => "mass_of_parts",
    };
    Failure {
        kind,
        message: e.to_string(),
    }
}

fn ms(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

/// SHA-256 of `bytes` in lowercase hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The type of a column's values.
#[derive(Debug, Clone, PartialEq)]
pub enum ColumnData {
    /// 64-bit floats (`null` where `None`).
    Float(Vec<Option<f64>>),
    /// 64-bit integers.
    Int(Vec<Option<i64>>),
    /// Booleans.
    Bool(Vec<Option<bool>>),
    /// UTF-8 text.
    Text(Vec<Option<String>>),
}

/// A named column of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Its name.
    pub name: String,
    /// Its values, one per row.
    pub data: ColumnData,
}

/// The table of `rows`, column by column in the schema's order: the one definition of the
/// columns, which the Python package turns into Arrow arrays.
pub fn columns(rows: &[Row]) -> Vec<Column> {
    let measured = |f: &dyn Fn(&Measured) -> Option<f64>| -> ColumnData {
        ColumnData::Float(
            rows.iter()
                .map(|r| r.outcome.as_ref().ok().and_then(f))
                .collect(),
        )
    };
    let props = |f: &dyn Fn(&MassProperties) -> f64| -> ColumnData {
        measured(&|m| Some(f(&m.properties)))
    };
    let text = |f: &dyn Fn(&Row) -> Option<String>| ColumnData::Text(rows.iter().map(f).collect());
    let mut out = vec![
        ("id", text(&|r| r.id.clone())),
        ("path", text(&|r| Some(r.path.clone()))),
        (
            "size_bytes",
            ColumnData::Int(
                rows.iter()
                    .map(|r| r.size_bytes.map(|b| b as i64))
                    .collect(),
            ),
        ),
        ("status", text(&|r| Some(r.status().name().to_owned()))),
        (
            "error_kind",
            text(&|r| r.outcome.as_ref().err().map(|f| f.kind.to_owned())),
        ),
        (
            "error_message",
            text(&|r| r.outcome.as_ref().err().map(|f| f.message.clone())),
        ),
        (
            "method",
            text(&|r| r.outcome.as_ref().ok().map(|m| m.method.to_owned())),
        ),
        (
            "density",
            ColumnData::Float(rows.iter().map(|r| r.density).collect()),
        ),
        ("mass", props(&|p| p.mass)),
        ("volume", measured(&|m| m.volume)),
    ]
    .into_iter()
    .map(|(n, d)| (n.to_owned(), d))
    .collect::<Vec<_>>();
    for (k, axis) in ["x", "y", "z"].iter().enumerate() {
        out.push((format!("com_{axis}"), props(&|p| p.center_of_mass[k])));
    }
    for (i, a) in ["x", "y", "z"].iter().enumerate() {
        for (j, b) in ["x", "y", "z"].iter().enumerate() {
            out.push((format!("i_{a}{b}"), props(&|p| p.inertia_com[(i, j)])));
        }
    }
    for k in 0..3 {
        out.push((format!("i{}", k + 1), props(&|p| p.principal.moments[k])));
    }
    for (k, name) in ["q_w", "q_x", "q_y", "q_z"].iter().enumerate() {
        out.push((
            (*name).to_owned(),
            props(&|p| quaternion_wxyz(&p.principal.rotation)[k]),
        ));
    }
    let flag = |f: &dyn Fn(&Measured) -> Option<bool>| {
        ColumnData::Bool(
            rows.iter()
                .map(|r| r.outcome.as_ref().ok().and_then(f))
                .collect(),
        )
    };
    let count = |f: &dyn Fn(&Measured) -> Option<u64>| {
        ColumnData::Int(
            rows.iter()
                .map(|r| r.outcome.as_ref().ok().and_then(f).map(|c| c as i64))
                .collect(),
        )
    };
    out.push(("closed".to_owned(), flag(&|m| m.closed)));
    out.push(("consistent".to_owned(), flag(&|m| m.consistent)));
    out.push(("triangles".to_owned(), count(&|m| m.triangles)));
    out.push(("shells".to_owned(), count(&|m| m.shells)));
    for code in Defect::CODES {
        out.push((format!("w_{code}"), count(&|m| Some(m.count_of(code)))));
    }
    out.push((
        "max_effect_on_mass".to_owned(),
        measured(&|m| m.largest_effect()),
    ));
    out.push((
        "parse_ms".to_owned(),
        ColumnData::Float(rows.iter().map(|r| Some(r.parse_ms)).collect()),
    ));
    out.push((
        "compute_ms".to_owned(),
        ColumnData::Float(rows.iter().map(|r| Some(r.compute_ms)).collect()),
    ));
    out.into_iter()
        .map(|(name, data)| Column { name, data })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const CUBE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
                        f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

    fn row(name: &str, text: &str, request: &Request) -> Row {
        measure(Path::new(name), Some(text.as_bytes()), request)
    }

    #[test]
    fn the_id_is_the_sha256_of_the_bytes() {
        // FIPS 180-2's first example.
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
        let r = row("cube.obj", CUBE, &Request::default());
        assert_eq!(r.id.as_deref(), Some(sha256_hex(CUBE.as_bytes()).as_str()));
        assert_eq!(r.size_bytes, Some(CUBE.len() as u64));
    }

    #[test]
    fn a_closed_cube_is_ok_with_its_numbers() {
        let request = Request {
            spec: MassSpec::Density(3.0),
            ..Request::default()
        };
        let r = row("cube.obj", CUBE, &request);
        assert_eq!(r.status(), Status::Ok);
        let m = r.outcome.as_ref().expect("numbers");
        assert!((m.properties.mass - 3.0).abs() < 1e-15);
        assert!((m.properties.inertia_com[(0, 0)] - 0.5).abs() < 1e-15);
        assert_eq!(
            (m.closed, m.shells, m.triangles),
            (Some(true), Some(1), Some(12))
        );
        assert_eq!((r.density, m.largest_effect()), (Some(3.0), None));
    }

    #[test]
    fn an_open_cube_warns_with_the_count_and_effect() {
        let open = CUBE.replace("f 1 4 3 2\n", "");
        let r = row("open.obj", &open, &Request::default());
        assert_eq!(r.status(), Status::Warn);
        let m = r.outcome.as_ref().expect("capped");
        assert_eq!(m.count_of("holes_capped"), 1);
        assert_eq!(m.count_of("duplicate_faces"), 0);
        // The holes_capped effect is minus what the cap adds: the pyramid on the missing face
        // with its apex at the box centre, 1/3 · 1 · 1/2 of the unit cube.
        let effect = m.largest_effect().expect("an effect");
        assert!((effect + 1.0 / 6.0).abs() < 1e-12, "{effect}");
    }

    #[test]
    fn failures_are_rows_naming_the_file() {
        let r = row("broken.obj", "v 0 0 0\nf 1 2 x\n", &Request::default());
        let f = r.outcome.as_ref().expect_err("malformed");
        assert_eq!((r.status(), f.kind), (Status::Error, "malformed"));
        assert!(f.message.starts_with("broken.obj"), "{}", f.message);
        let sheet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        let f = row("sheet.obj", sheet, &Request::default())
            .outcome
            .expect_err("no volume");
        assert_eq!(f.kind, "zero_volume");
        assert!(f.message.starts_with("sheet.obj: "), "{}", f.message);
        let missing = measure(Path::new("/no/such/file.stl"), None, &Request::default());
        let f = missing.outcome.as_ref().expect_err("missing");
        assert_eq!((f.kind, missing.id.as_ref()), ("io", None));
    }

    #[test]
    fn every_row_has_every_column_once() {
        let rows = [
            row("cube.obj", CUBE, &Request::default()),
            row("broken.obj", "f 1 2\n", &Request::default()),
        ];
        let columns = columns(&rows);
        let mut names: Vec<&str> = columns.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(
            names.len(),
            10 + 3 + 9 + 3 + 4 + 4 + Defect::CODES.len() + 3
        );
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), columns.len(), "a column named twice");
        for c in &columns {
            let len = match &c.data {
                ColumnData::Float(v) => v.len(),
                ColumnData::Int(v) => v.len(),
                ColumnData::Bool(v) => v.len(),
                ColumnData::Text(v) => v.len(),
            };
            assert_eq!(len, 2, "{}", c.name);
        }
        let status = columns.iter().find(|c| c.name == "status").expect("status");
        assert_eq!(
            status.data,
            ColumnData::Text(vec![Some("ok".into()), Some("error".into())])
        );
    }
}
