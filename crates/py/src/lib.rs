//! `inertialab._native`: the Rust side of the `inertialab` Python package, a thin layer over
//! massprops and the app's input path (the same readers, analysis, JSON and exports as
//! `inertia-lab props`), in the way of polars and pydantic-core: the Python modules beside it
//! (`python/inertialab/`) check and convert their arguments and build the Arrow tables; this
//! crate does the work with the GIL released.
//!
//! - `arrays`: numpy arrays → meshes, in place where the dtype and layout allow;
//! - `result`: `MassResult`, one body's numbers with `to_dict()` (`props --json`'s object) and
//!   the exports;
//! - `simulate`: a body spun and its keyframes, as `simulate --animation` bakes them;
//! - `threads`: how many threads a call uses (one by default, `threads=` or
//!   `RAYON_NUM_THREADS`), and the errors raised in Python;
//! - here: the module's functions (meshes and body files as `props`, robot descriptions as
//!   `audit --json`).

mod arrays;
mod result;
mod simulate;
mod threads;

use std::path::PathBuf;

use inertia_io::batch::{self, ColumnData};
use inertia_io::input::{Request, Resolved, Source, resolve};
use massprops::defects::{Holes, Weld};
use massprops::{MassSpec, Method, Repairs};
use numpy::{PyReadonlyArray1, PyReadonlyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList, PyTuple};

use arrays::{BadArrays, Faces, views};
use result::{MassResult, Measured};
use threads::{CallFailure, on_threads};

/// The options every call shares, as the Python layer passes them: a density or a mass, the
/// method, the repairs and the threads.
#[derive(Clone, Copy)]
struct Options {
    spec: MassSpec,
    method: Method,
    repairs: Repairs,
    threads: usize,
}

/// `Repairs` as the Python layer passes it: `(weld, weld_distance, holes, max_cap_share,
/// overlap_budget)`, `weld` `"auto"`, `"exact"` or `"distance"`.
#[derive(FromPyObject)]
struct RepairArgs(String, f64, String, f64, u64);

fn options(
    density: Option<f64>,
    mass: Option<f64>,
    method: &str,
    repairs: RepairArgs,
    threads: Option<usize>,
) -> PyResult<Options> {
    let spec = match (density, mass) {
        (Some(_), Some(_)) => {
            return Err(PyValueError::new_err("give a density or a mass, not both"));
        }
        (_, Some(m)) => MassSpec::Mass(m),
        (Some(d), None) => MassSpec::Density(d),
        (None, None) => MassSpec::Density(1.0),
    };
    let method = match method {
        "volume" => Method::Volume,
        "shell" => Method::Shell,
        "points" => Method::Points,
        "bbox" => Method::BoundingBox,
        other => {
            return Err(PyValueError::new_err(format!(
                "method must be \"volume\", \"shell\", \"points\" or \"bbox\", not {other:?}"
            )));
        }
    };
    Ok(Options {
        spec,
        method,
        repairs: repairs_of(repairs)?,
        threads: threads::count(threads)?,
    })
}

/// `Repairs` from the Python layer's tuple, each value checked.
fn repairs_of(repairs: RepairArgs) -> PyResult<Repairs> {
    let RepairArgs(weld, weld_distance, holes, max_cap_share, overlap_budget) = repairs;
    let weld = match weld.as_str() {
        "auto" => Weld::Auto,
        "exact" => Weld::Exact,
        "distance" if weld_distance.is_finite() && weld_distance > 0.0 => {
            Weld::Distance(weld_distance)
        }
        _ => {
            return Err(PyValueError::new_err(format!(
                "weld must be \"auto\", \"exact\" or a positive distance, not {weld:?} \
                 ({weld_distance})"
            )));
        }
    };
    let holes = match holes.as_str() {
        "cap" => Holes::Cap,
        "refuse" => Holes::Refuse,
        other => {
            return Err(PyValueError::new_err(format!(
                "holes must be \"cap\" or \"refuse\", not {other:?}"
            )));
        }
    };
    if !(max_cap_share > 0.0 && max_cap_share <= 1.0) {
        return Err(PyValueError::new_err(format!(
            "max_cap_share must be above 0 and at most 1, not {max_cap_share}"
        )));
    }
    Ok(Repairs {
        weld,
        holes,
        max_cap_share,
        overlap_budget,
    })
}

impl Options {
    fn request(&self) -> Request {
        Request {
            method: self.method,
            spec: self.spec,
            repairs: self.repairs,
            ..Request::default()
        }
    }
}

/// Mass properties of the mesh `vertices` (n, 3) float64 C-contiguous and `faces`; `check`:
/// the full analysis (weld, diagnostics, defects, warnings) or the integrals alone.
#[pyfunction]
#[pyo3(signature = (vertices, faces, sizes, density, mass, method, repairs, check, threads))]
#[allow(clippy::too_many_arguments)]
fn analyze_arrays(
    py: Python<'_>,
    vertices: PyReadonlyArray2<'_, f64>,
    faces: Faces<'_>,
    sizes: Option<PyReadonlyArray1<'_, i64>>,
    density: Option<f64>,
    mass: Option<f64>,
    method: &str,
    repairs: RepairArgs,
    check: bool,
    threads: Option<usize>,
) -> PyResult<MassResult> {
    let o = options(density, mass, method, repairs, threads)?;
    let v = views(&vertices, &faces, sizes.as_ref())?;
    if !check && o.method != Method::Volume {
        return Err(PyValueError::new_err(
            "check=False integrates the solid only: use method=\"volume\", or check=True",
        ));
    }
    let body = py
        .detach(|| {
            if check {
                let mesh = v.welded_mesh()?;
                on_threads(o.threads, || {
                    massprops::analyze_with(&mesh, o.method, o.spec, &o.repairs)
                })
                .map(|analysis| Measured::Mesh {
                    analysis: Box::new(analysis),
                    file: None,
                    lines: Vec::new(),
                })
                .map_err(BadArrays::from)
            } else {
                unchecked(&v, o.spec)
            }
        })
        .map_err(|e| threads::raise(py, CallFailure::from(e)))?;
    Ok(MassResult::new(body))
}

/// The solid of the arrays alone (no copy for triangles; polygons by Mirtich's integrals).
fn unchecked(v: &arrays::Views<'_>, spec: MassSpec) -> Result<Measured, BadArrays> {
    let solid = match v.triangle_corners() {
        Some(corners) => {
            massprops::solid::triangles_solid(v.positions, bytemuck::cast_slice(&corners?))?
        }
        None => massprops::solid::solid_properties(
            &v.mesh()?,
            massprops::integrals::IntegrationPath::Polygon,
        )?,
    };
    let density = match spec {
        MassSpec::Density(d) => d,
        MassSpec::Mass(m) => m / solid.volume,
    };
    Ok(Measured::Unchecked {
        properties: solid.with_density(density)?,
        density,
        volume: solid.volume,
        flipped: solid.flipped,
    })
}

/// Reads an OBJ, STL or body file with the project's readers and analyses it as `props` does.
#[pyfunction]
#[pyo3(signature = (path, density, mass, method, repairs, threads))]
fn analyze_path(
    py: Python<'_>,
    path: PathBuf,
    density: Option<f64>,
    mass: Option<f64>,
    method: &str,
    repairs: RepairArgs,
    threads: Option<usize>,
) -> PyResult<MassResult> {
    let o = options(density, mass, method, repairs, threads)?;
    if massprops::io::is_body_file(&path) && (density.is_some() || mass.is_some()) {
        return Err(PyValueError::new_err(
            "a body file gives each part's material: density and mass do not apply",
        ));
    }
    let file = path.display().to_string();
    let resolved = py
        .detach(|| on_threads(o.threads, || resolve(Source::Path(&path), &o.request())))
        .map_err(|e| threads::raise(py, CallFailure::Input(e)))?;
    Ok(MassResult::new(match resolved {
        Resolved::Mesh {
            file: read,
            analysis,
        } => Measured::Mesh {
            analysis,
            file: Some(file),
            lines: read.face_lines,
        },
        Resolved::Parts(parts) => Measured::Parts {
            units: match parts.body_file_units {
                Some(unit) => format!("metres, from a body file in {unit}"),
                None => "the mesh's units".to_owned(),
            },
            composite: parts.composite,
            file,
        },
    }))
}

/// A masses entry as Python passes it: link, mass (kg), and the centre (m, link frame) if any.
type MassEntry = (String, f64, Option<(f64, f64, f64)>);

/// Audits a robot description as `inertia-lab audit --json` does and returns that JSON's text
/// (the Python layer parses it and builds the per-link table). Measured masses come from a file
/// (`masses_file`) or as entries, not both.
#[pyfunction]
#[pyo3(signature = (path, geometry, density, assumed_density, packages, xacro_args, masses_file, masses, max_moment_error, max_com_offset, nearest, repairs, threads))]
#[allow(clippy::too_many_arguments)]
fn audit_json(
    py: Python<'_>,
    path: PathBuf,
    geometry: &str,
    density: Option<f64>,
    assumed_density: f64,
    packages: Vec<(String, PathBuf)>,
    xacro_args: Vec<(String, String)>,
    masses_file: Option<PathBuf>,
    masses: Vec<MassEntry>,
    max_moment_error: Option<f64>,
    max_com_offset: Option<f64>,
    nearest: bool,
    repairs: RepairArgs,
    threads: Option<usize>,
) -> PyResult<String> {
    let o = options(None, None, "volume", repairs, threads)?;
    let geometry = match geometry {
        "collision" => robot::GeometryKind::Collision,
        "visual" => robot::GeometryKind::Visual,
        other => {
            return Err(PyValueError::new_err(format!(
                "geometry is \"collision\" or \"visual\", not {other:?}"
            )));
        }
    };
    let positive = |name: &str, v: f64| {
        if v > 0.0 && v.is_finite() {
            Ok(v)
        } else {
            Err(PyValueError::new_err(format!(
                "{name} must be positive, not {v}"
            )))
        }
    };
    let mut measured = match masses_file {
        Some(file) => {
            robot::read_masses(&file).map_err(|e| PyValueError::new_err(e.to_string()))?
        }
        None => robot::MeasuredMasses::new(),
    };
    for (link, mass, center) in masses {
        let mass = positive(&format!("the measured mass of {link:?}"), mass)?;
        measured.insert(
            link,
            robot::Measured {
                mass,
                center_of_mass: center.map(|(x, y, z)| nalgebra::Point3::new(x, y, z)),
            },
        );
    }
    let options = robot::AuditOptions {
        geometry,
        density: density.map(|d| positive("density", d)).transpose()?,
        assumed_density: positive("assumed_density", assumed_density)?,
        max_moment_error: max_moment_error
            .map(|t| positive("max_moment_error", t))
            .transpose()?,
        max_com_offset: max_com_offset
            .map(|t| positive("max_com_offset", t))
            .transpose()?,
        repairs: o.repairs,
        nearest,
        measured,
    };
    let file = path.display().to_string();
    let (description, report) = py
        .detach(|| {
            on_threads(o.threads, || {
                let description = robot::read(
                    &path,
                    &robot::ReadOptions {
                        packages,
                        resource_paths: robot::resource_paths_from_env(),
                        xacro_args,
                    },
                )?;
                let report = robot::audit(&description, &options);
                Ok::<_, robot::RobotError>((description, report))
            })
        })
        .map_err(|e| match &e {
            robot::RobotError::Io { source, .. }
                if source.kind() == std::io::ErrorKind::NotFound =>
            {
                pyo3::exceptions::PyFileNotFoundError::new_err(e.to_string())
            }
            robot::RobotError::Io { .. } => pyo3::exceptions::PyOSError::new_err(e.to_string()),
            _ => PyValueError::new_err(e.to_string()),
        })?;
    if let Some(unknown) = options
        .measured
        .keys()
        .find(|n| !description.links.iter().any(|l| &l.name == *n))
    {
        return Err(PyValueError::new_err(format!(
            "masses: the robot has no link named {unknown:?}"
        )));
    }
    let json = inertia_io::report::audit::json_report(&file, &description, &report);
    Ok(json.to_string())
}

/// The batch table's rows for `paths` (with their bytes when `contents` has them, and a density
/// each when `densities` has one), as columns: `{name: list}` in the schema's order. Never
/// raises for a row.
#[pyfunction]
#[pyo3(signature = (paths, contents, densities, method, repairs, threads))]
fn measure_rows<'py>(
    py: Python<'py>,
    paths: Vec<PathBuf>,
    contents: Option<Vec<Option<Bound<'py, PyBytes>>>>,
    densities: Option<Vec<Option<f64>>>,
    method: &str,
    repairs: RepairArgs,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let o = options(None, None, method, repairs, threads)?;
    let bytes: Vec<Option<&[u8]>> = match &contents {
        Some(c) => {
            if c.len() != paths.len() {
                return Err(PyValueError::new_err(format!(
                    "{} paths but {} contents",
                    paths.len(),
                    c.len()
                )));
            }
            c.iter().map(|b| b.as_ref().map(|b| b.as_bytes())).collect()
        }
        None => vec![None; paths.len()],
    };
    let densities = densities.unwrap_or_else(|| vec![None; paths.len()]);
    if densities.len() != paths.len() {
        return Err(PyValueError::new_err(format!(
            "{} paths but {} densities",
            paths.len(),
            densities.len()
        )));
    }
    let rows = py.detach(|| {
        on_threads(o.threads, || {
            use rayon::prelude::*;
            (0..paths.len())
                .into_par_iter()
                .with_max_len(1)
                .map(|k| {
                    let mut request = o.request();
                    if let Some(d) = densities[k] {
                        request.spec = MassSpec::Density(d);
                    }
                    batch::measure(&paths[k], bytes[k], &request)
                })
                .collect::<Vec<_>>()
        })
    });
    columns_dict(py, &batch::columns(&rows))
}

/// The batch table's columns and their types (`float64`, `int64`, `bool`, `string`), in order.
#[pyfunction]
fn batch_schema() -> Vec<(String, &'static str)> {
    batch::columns(&[])
        .into_iter()
        .map(|c| {
            let kind = match c.data {
                ColumnData::Float(_) => "float64",
                ColumnData::Int(_) => "int64",
                ColumnData::Bool(_) => "bool",
                ColumnData::Text(_) => "string",
            };
            (c.name, kind)
        })
        .collect()
}

/// SHA-256 of each file's bytes (None where it cannot be read), with the GIL released: what a
/// resumed batch compares with the ids already written.
#[pyfunction]
#[pyo3(signature = (paths, threads=None))]
fn file_ids(
    py: Python<'_>,
    paths: Vec<PathBuf>,
    threads: Option<usize>,
) -> PyResult<Vec<Option<String>>> {
    let threads = threads::count(threads)?;
    Ok(py.detach(|| {
        on_threads(threads, || {
            use rayon::prelude::*;
            paths
                .par_iter()
                .map(|p| std::fs::read(p).ok().map(|b| batch::sha256_hex(&b)))
                .collect()
        })
    }))
}

fn columns_dict<'py>(py: Python<'py>, columns: &[batch::Column]) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for c in columns {
        let list = match &c.data {
            ColumnData::Float(v) => PyList::new(py, v)?,
            ColumnData::Int(v) => PyList::new(py, v)?,
            ColumnData::Bool(v) => PyList::new(py, v)?,
            ColumnData::Text(v) => PyList::new(py, v)?,
        };
        out.set_item(&c.name, list)?;
    }
    Ok(out)
}

/// The extension module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(analyze_arrays, m)?)?;
    m.add_function(wrap_pyfunction!(analyze_path, m)?)?;
    m.add_function(wrap_pyfunction!(measure_rows, m)?)?;
    m.add_function(wrap_pyfunction!(batch_schema, m)?)?;
    m.add_function(wrap_pyfunction!(file_ids, m)?)?;
    m.add_function(wrap_pyfunction!(audit_json, m)?)?;
    m.add_function(wrap_pyfunction!(simulate::simulate_motion, m)?)?;
    m.add_class::<MassResult>()?;
    m.add("MeshError", m.py().get_type::<threads::MeshError>())?;
    m.add("SCHEMA_VERSION", inertia_io::report::SCHEMA_VERSION)?;
    m.add("BATCH_SCHEMA_VERSION", batch::SCHEMA_VERSION)?;
    m.add("OVERLAP_BUDGET", massprops::defects::OVERLAP_BUDGET)?;
    // The files a folder is searched for: every mesh format the readers take and body files,
    // from the one table the app's dialogs read (never a copy in Python).
    let openable = inertia_io::kind::Openable { robots: false };
    let extensions: Vec<String> = openable
        .extensions()
        .iter()
        .map(|e| format!(".{e}"))
        .collect();
    m.add("MESH_EXTENSIONS", PyTuple::new(m.py(), extensions)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
