//! `MassResult`: one body's numbers as Python reads them. The attributes are computed when read
//! (numpy arrays, fresh each time); `to_dict()` is `props --json`'s object, built by the same
//! code (`inertia_io::report::json`), so the two never disagree.

use inertia_io::choice;
use inertia_io::export::{ExportOptions, Format, Frame, LengthUnit, UpAxis, quaternion_wxyz};
use inertia_io::report::json;
use massprops::{Analysis, Composite, MassProperties};
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;

/// What a result holds.
pub enum Measured {
    /// A mesh, analysed in full.
    Mesh {
        /// The analysis.
        analysis: Box<Analysis>,
        /// The file it was read from (`None` for arrays).
        file: Option<String>,
        /// The file line of each face (empty for arrays and binary STL).
        lines: Vec<u32>,
    },
    /// A body of parts (a body file).
    Parts {
        /// The sums and each part.
        composite: Composite,
        /// The body file.
        file: String,
        /// The units the numbers are in, in words.
        units: String,
    },
    /// A solid integrated without looking for defects (`check=False`).
    Unchecked {
        /// Its mass properties.
        properties: MassProperties,
        /// Mass per volume.
        density: f64,
        /// Enclosed volume.
        volume: f64,
        /// The faces wound inwards (the numbers are the outward-wound mesh's).
        flipped: bool,
    },
}

/// Mass properties of one body: mass, volume, centre of mass, inertia about the centre of mass
/// in the mesh's axes (off-diagonals −∑m·x·y), principal moments and axes, and the warnings.
#[pyclass(frozen, module = "inertialab", name = "MassResult")]
pub struct MassResult {
    body: Measured,
}

impl MassResult {
    /// The result of `body`.
    pub fn new(body: Measured) -> Self {
        Self { body }
    }

    /// The body's mass properties (whatever the method that gave them).
    pub fn properties(&self) -> &MassProperties {
        match &self.body {
            Measured::Mesh { analysis, .. } => &analysis.properties,
            Measured::Parts { composite, .. } => &composite.properties,
            Measured::Unchecked { properties, .. } => properties,
        }
    }

    /// `props --json`'s object.
    fn json(&self) -> Value {
        match &self.body {
            Measured::Mesh {
                analysis,
                file,
                lines,
            } => {
                let mut value = json::single(file.as_deref().unwrap_or(""), 1.0, analysis, lines);
                if file.is_none() {
                    value["file"] = Value::Null;
                }
                value
            }
            Measured::Parts {
                composite,
                file,
                units,
            } => json::composite(file, units, composite),
            Measured::Unchecked {
                properties,
                density,
                volume,
                flipped,
            } => json::unchecked(*density, *volume, *flipped, properties),
        }
    }
}

fn matrix<'py>(py: Python<'py>, m: &nalgebra::Matrix3<f64>) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows: Vec<f64> = (0..3)
        .flat_map(|i| (0..3).map(move |j| m[(i, j)]))
        .collect();
    PyArray1::from_vec(py, rows).reshape([3, 3])
}

#[pymethods]
impl MassResult {
    /// Mass, in the unit of density times length³ (length² for the shell method).
    #[getter]
    fn mass(&self) -> f64 {
        self.properties().mass
    }

    /// Enclosed volume; `None` for a body of parts and for a shell that encloses none.
    #[getter]
    fn volume(&self) -> Option<f64> {
        match &self.body {
            Measured::Mesh { analysis, .. } => analysis.volume,
            Measured::Parts { .. } => None,
            Measured::Unchecked { volume, .. } => Some(*volume),
        }
    }

    /// The density used (per volume; per area for the shell method); `None` for a body of parts.
    #[getter]
    fn density(&self) -> Option<f64> {
        match &self.body {
            Measured::Mesh { analysis, .. } => analysis.density,
            Measured::Parts { .. } => None,
            Measured::Unchecked { density, .. } => Some(*density),
        }
    }

    /// Centre of mass, shape (3,), mesh coordinates.
    #[getter]
    fn center_of_mass<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.properties().center_of_mass.coords.as_slice())
    }

    /// Inertia tensor about the centre of mass in the mesh's axes, shape (3, 3); diagonal =
    /// moments, off-diagonals = −∑m·x·y.
    #[getter]
    fn inertia<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        matrix(py, &self.properties().inertia_com)
    }

    /// Inertia tensor about the mesh origin, same axes and convention.
    #[getter]
    fn inertia_origin<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        matrix(py, &self.properties().inertia_origin())
    }

    /// Principal moments, ascending, shape (3,).
    #[getter]
    fn principal_moments<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.properties().principal.moments.as_slice())
    }

    /// Principal axes as rows, shape (3, 3): row i is the unit axis of moment i; the rows are a
    /// right-handed orthonormal set.
    #[getter]
    fn principal_axes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        matrix(
            py,
            &self.properties().principal.rotation.matrix().transpose(),
        )
    }

    /// The rotation from the principal axes to the mesh's as a unit quaternion `[w, x, y, z]`,
    /// w ≥ 0.
    #[getter]
    fn principal_quaternion<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &quaternion_wxyz(&self.properties().principal.rotation))
    }

    /// Whether defects were looked for (`check=True`, and every file).
    #[getter]
    fn checked(&self) -> bool {
        !matches!(self.body, Measured::Unchecked { .. })
    }

    /// The warnings as `props --json` gives them (`code`, `message`, `count`, `faces`,
    /// `effect_on_mass` and the defect's own data), each part's for a body of parts (with its
    /// `part`); `None` when not looked for (`check=False`).
    #[getter]
    fn warnings<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let value = self.json();
        let warnings = match &self.body {
            Measured::Unchecked { .. } => Value::Null,
            Measured::Parts { .. } => Value::Array(
                value["parts"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .flat_map(|part| {
                        part["warnings"].as_array().into_iter().flatten().map(|w| {
                            let mut w = w.clone();
                            w["part"] = part["name"].clone();
                            w
                        })
                    })
                    .collect(),
            ),
            Measured::Mesh { .. } => value["warnings"].clone(),
        };
        to_python(py, &warnings)
    }

    /// `props --json`'s object (schema `SCHEMA_VERSION`, documented in docs/props.md).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.json())
    }

    /// `props --json`'s text.
    fn to_json(&self) -> String {
        self.json().to_string()
    }

    /// The body in `format` (`json`, `urdf`, `mjcf`, `sdf`, `unity`, `godot`, `unreal`,
    /// `rapier`, `gltf`), as `inertia-lab export` writes it, with its defaults: `units` the
    /// mesh's length unit (`m`, `cm`, `mm`, `in`, `ft`), `up` its up axis (`y` or `z`), `frame`
    /// `com-principal` or `origin` (None: the format's). The mass is taken to be in kg: for a
    /// mesh in millimetres, compute with the density in kg/mm³.
    #[pyo3(signature = (format, *, units="m", up="y", frame=None))]
    fn export(&self, format: &str, units: &str, up: &str, frame: Option<&str>) -> PyResult<String> {
        let format: Format = choice::parse(format).map_err(value_error)?;
        let units: LengthUnit = units
            .parse()
            .map_err(|e| PyValueError::new_err(format!("units: {e}")))?;
        let up: UpAxis = choice::parse(up).map_err(value_error)?;
        let frame: Option<Frame> = frame.map(choice::parse).transpose().map_err(value_error)?;
        let options = ExportOptions {
            format,
            units,
            up,
            frame,
        };
        inertia_io::export::export(self.properties(), &options)
            .map(|out| String::from_utf8_lossy(&out.bytes).into_owned())
            .map_err(value_error)
    }

    /// MuJoCo MJCF `<inertial>` text (`export("mjcf", …)`).
    #[pyo3(signature = (*, units="m", up="y", frame=None))]
    fn to_mjcf(&self, units: &str, up: &str, frame: Option<&str>) -> PyResult<String> {
        self.export("mjcf", units, up, frame)
    }

    /// URDF `<inertial>` text (`export("urdf", …)`).
    #[pyo3(signature = (*, units="m", up="y", frame=None))]
    fn to_urdf(&self, units: &str, up: &str, frame: Option<&str>) -> PyResult<String> {
        self.export("urdf", units, up, frame)
    }

    fn __repr__(&self) -> String {
        let p = self.properties();
        let m = p.principal.moments;
        let warnings = match &self.body {
            Measured::Mesh { analysis, .. } => format!("{} warnings", analysis.warnings.len()),
            Measured::Parts { composite, .. } => format!("{} parts", composite.parts.len()),
            Measured::Unchecked { .. } => "not checked".to_owned(),
        };
        format!(
            "MassResult(mass={:.6e}, center_of_mass=[{:.6e}, {:.6e}, {:.6e}], \
             principal_moments=[{:.6e}, {:.6e}, {:.6e}], {warnings})",
            p.mass, p.center_of_mass.x, p.center_of_mass.y, p.center_of_mass.z, m[0], m[1], m[2]
        )
    }
}

/// A JSON value as Python objects (what `json.loads` of its text gives).
fn to_python<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_u64()) {
            (Some(i), _) => i.into_pyobject(py)?.into_any(),
            (None, Some(u)) => u.into_pyobject(py)?.into_any(),
            (None, None) => n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any(),
        },
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(to_python(py, item)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (k, v) in map {
                dict.set_item(k, to_python(py, v)?)?;
            }
            dict.into_any()
        }
    })
}

/// A `ValueError` carrying the library's own message.
fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}
