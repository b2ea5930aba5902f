//! `simulate_motion`: a body (a file through the input path, or a box of principal moments) spun
//! from rest where its mesh lies and sampled at a frame rate, as `inertia-lab simulate
//! --animation` does it ([`inertia_io::bake`]): the keyframes come back as arrays, and with a
//! path the same `.glb` or `.usda` file is written.

use std::path::{Path, PathBuf};

use inertia_io::bake::{self, BakeError, Shape, Spin};
use inertia_io::choice;
use inertia_io::export::{LengthUnit, UpAxis};
use inertia_io::input::{Request, Resolved, Source, resolve};
use massprops::MassSpec;
use nalgebra::Vector3;
use numpy::{IntoPyArray, ndarray::Array2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rbcore::{Integrator, RotationModel, Settings};

use crate::RepairArgs;
use crate::result::MassResult;
use crate::threads::{self, CallFailure};

/// Where `simulate_motion`'s body comes from: a file, a result already computed, or principal
/// moments.
pub enum Given<'a> {
    /// A mesh or body file.
    Path(&'a Path),
    /// Mass properties computed already (no surface: no file is written of it).
    Result(&'a MassResult),
    /// Principal moments, ascending.
    Moments(f64, f64, f64),
}

/// The body `simulate_motion` spins: a file's (density or mass as given), a result's, or the
/// box of the moments at `mass`.
fn shape(
    py: Python<'_>,
    given: Given<'_>,
    density: Option<f64>,
    mass: Option<f64>,
    repairs: RepairArgs,
) -> PyResult<Shape> {
    match given {
        Given::Result(result) => {
            if density.is_some() || mass.is_some() {
                return Err(PyValueError::new_err(
                    "a MassResult has its mass already: density and mass do not apply",
                ));
            }
            Ok(Shape {
                properties: *result.properties(),
                surface: inertia_io::export::Surface::default(),
            })
        }
        Given::Moments(a, b, c) => {
            if density.is_some() {
                return Err(PyValueError::new_err(
                    "density applies to a file: the moments' box takes a mass",
                ));
            }
            if !(a <= b && b <= c) {
                return Err(PyValueError::new_err(format!(
                    "inertia takes the principal moments in ascending order, got ({a}, {b}, {c})"
                )));
            }
            Ok(Shape::principal_box(
                mass.unwrap_or(1.0),
                &Vector3::new(a, b, c),
            ))
        }
        Given::Path(path) => {
            if massprops::io::is_body_file(path) && (density.is_some() || mass.is_some()) {
                return Err(PyValueError::new_err(
                    "a body file gives each part's material: density and mass do not apply",
                ));
            }
            let request = Request {
                spec: MassSpec::Density(density.unwrap_or(1.0)),
                repairs: crate::repairs_of(repairs)?,
                ..Request::default()
            };
            let resolved = py
                .detach(|| resolve(Source::Path(path), &request))
                .map_err(|e| threads::raise(py, CallFailure::Input(e)))?;
            let mut properties = match &resolved {
                Resolved::Mesh { analysis, .. } => analysis.properties,
                Resolved::Parts(parts) => parts.composite.properties,
            };
            if let Some(m) = mass {
                properties = properties
                    .with_mass(m)
                    .map_err(|e| PyValueError::new_err(format!("mass: {e}")))?;
            }
            Ok(Shape::of(&resolved, path, properties))
        }
    }
}

/// Simulates and samples the motion; returns a dict of the keyframes (`time` (n,), `position`
/// (n, 3) the centre of mass, `orientation` (n, 4) w x y z mesh axes → world, `translation`
/// (n, 3) the mesh origin's place) and the run's `dt`, `fps`, `l_change`, `energy_change`;
/// writes `animation` (.glb or .usda) when given.
#[pyfunction]
#[pyo3(signature = (path, result, inertia, density, mass, omega, duration, fps, dt, integrator, model, animation, units, up, repairs))]
#[allow(clippy::too_many_arguments)]
pub fn simulate_motion<'py>(
    py: Python<'py>,
    path: Option<PathBuf>,
    result: Option<PyRef<'py, MassResult>>,
    inertia: Option<(f64, f64, f64)>,
    density: Option<f64>,
    mass: Option<f64>,
    omega: (f64, f64, f64),
    duration: f64,
    fps: f64,
    dt: f64,
    integrator: &str,
    model: &str,
    animation: Option<PathBuf>,
    units: &str,
    up: &str,
    repairs: RepairArgs,
) -> PyResult<Bound<'py, PyDict>> {
    let integrator: Integrator = integrator
        .parse()
        .map_err(|e| PyValueError::new_err(format!("integrator: {e}")))?;
    let model: RotationModel = model
        .parse()
        .map_err(|e| PyValueError::new_err(format!("model: {e}")))?;
    let units: LengthUnit = units
        .parse()
        .map_err(|e| PyValueError::new_err(format!("units: {e}")))?;
    let up: UpAxis = choice::parse(up).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let format = animation
        .as_deref()
        .map(|p| {
            bake::format_of(p).ok_or_else(|| {
                PyValueError::new_err(format!(
                    "animation writes .glb (glTF) or .usda (USD), not {}",
                    p.display()
                ))
            })
        })
        .transpose()?;
    let given = match (path.as_deref(), result.as_deref(), inertia) {
        (Some(path), None, None) => Given::Path(path),
        (None, Some(result), None) => Given::Result(result),
        (None, None, Some((a, b, c))) => Given::Moments(a, b, c),
        _ => {
            return Err(PyValueError::new_err(
                "give one body: a mesh or body file, a MassResult, or the principal moments \
                 (inertia=)",
            ));
        }
    };
    if format.is_some() && matches!(given, Given::Result(_)) {
        return Err(PyValueError::new_err(
            "animation= writes the body's mesh: give its file (a MassResult has no mesh)",
        ));
    }
    let shape = shape(py, given, density, mass, repairs)?;
    let spin = Spin {
        omega: Vector3::new(omega.0, omega.1, omega.2),
        duration,
        fps,
        settings: Settings {
            dt,
            integrator,
            model,
            ..Settings::default()
        },
    };
    let baked = py
        .detach(|| bake::bake(&shape, &spin))
        .map_err(|e: BakeError| PyValueError::new_err(e.to_string()))?;
    if let (Some(out), Some(format)) = (&animation, format) {
        let name = path
            .as_deref()
            .and_then(Path::file_stem)
            .map_or_else(|| "box".to_owned(), |s| s.to_string_lossy().into_owned());
        let file = bake::write(&shape, &baked, &name, format, units, up)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        std::fs::write(out, &file.bytes).map_err(|e| {
            pyo3::exceptions::PyOSError::new_err(format!("cannot write {}: {e}", out.display()))
        })?;
    }
    let poses = &baked.keyframes.poses;
    let rows = |n: usize, f: &dyn Fn(usize) -> Vec<f64>| {
        let flat: Vec<f64> = (0..poses.len()).flat_map(f).collect();
        Array2::from_shape_vec((poses.len(), n), flat).expect("n values a row")
    };
    let position = rows(3, &|k| poses[k].position.coords.as_slice().to_vec());
    let orientation = rows(4, &|k| {
        let q = poses[k].orientation;
        vec![q.w, q.i, q.j, q.k]
    });
    let translation = rows(3, &|k| {
        baked.motion.frames[k]
            .translation
            .vector
            .as_slice()
            .to_vec()
    });
    let time: Vec<f64> = poses.iter().map(|p| p.time).collect();
    let out = PyDict::new(py);
    out.set_item("time", time.into_pyarray(py))?;
    out.set_item("position", position.into_pyarray(py))?;
    out.set_item("orientation", orientation.into_pyarray(py))?;
    out.set_item("translation", translation.into_pyarray(py))?;
    out.set_item("dt", baked.keyframes.dt)?;
    out.set_item("fps", baked.keyframes.fps)?;
    out.set_item("l_change", baked.l_change)?;
    out.set_item("energy_change", baked.energy_change)?;
    let moments = shape.properties.principal.moments;
    out.set_item("moments", (moments.x, moments.y, moments.z))?;
    Ok(out)
}
