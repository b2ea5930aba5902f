//! Body files: a body made of parts, in TOML. Each part names a mesh file (relative to the body
//! file), optionally one of its objects, its material and where it sits:
//!
//! ```toml
//! version = 1                                   # optional: the format's version
//! units = "mm"                                  # lengths here and in the meshes: m, cm, mm, in, ft
//! [[part]]
//! name = "head"
//! mesh = "head.obj"                             # OBJ or STL
//! object = "head"                               # optional: one object or group (or STL solid)
//! density = 7850                                # kg/m³; or material = "steel", or mass = 0.8 (kg)
//! rotation = { axis = [0, 0, 1], degrees = 90 } # optional; first, about the mesh origin
//! translation = [0, 320, 0]                     # optional, in `units`
//! void = false                                  # true: removes material of `density`
//! thin_wall = 1.5                               # optional: a wall this thick (in `units`)
//! ```
//!
//! Everything is converted to SI on reading: the parts' meshes are in metres.

use std::path::{Path, PathBuf};

use nalgebra::{Isometry3, Translation3, Unit, UnitQuaternion, Vector3};
use serde::Deserialize;
use toml::Spanned;

use crate::{
    Fill, LengthUnit, MaterialEntry, MeshError, Part, load_mesh, material,
    materials::material_names,
};

/// The body-file format this program reads and writes (the optional `version` key; a file
/// without one is read as this version). Bumped on any incompatible change.
pub const BODY_FILE_VERSION: i64 = 1;

/// A body file as written: the parts and their settings, not yet loaded.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyFile {
    /// The file it was read from (meshes are relative to its folder).
    pub path: PathBuf,
    /// The length unit of its lengths and of its meshes' coordinates.
    pub units: LengthUnit,
    /// The parts, in order.
    pub parts: Vec<PartEntry>,
}

/// One `[[part]]` of a body file.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PartEntry {
    /// Its name.
    pub name: String,
    /// The mesh file, as written (relative to the body file's folder unless absolute).
    pub mesh: PathBuf,
    /// One object, group or STL solid of that file; the whole file when `None`.
    pub object: Option<String>,
    /// Its material.
    pub material: MaterialEntry,
    /// Rotation axis (any length) and angle in degrees, applied first, about the mesh origin.
    pub rotation: Option<([f64; 3], f64)>,
    /// Translation, in the file's units.
    pub translation: [f64; 3],
    /// A void: removes material of its density.
    pub void: bool,
    /// A thin wall of this thickness (in the file's units) on the faces, instead of a solid.
    pub thin_wall: Option<f64>,
    /// The line of its `[[part]]` header, for messages.
    pub line: usize,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBody {
    version: Option<Spanned<i64>>,
    units: Option<Spanned<String>>,
    #[serde(default)]
    part: Vec<Spanned<RawPart>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPart {
    name: Option<String>,
    mesh: Option<Spanned<String>>,
    object: Option<Spanned<String>>,
    density: Option<Spanned<f64>>,
    material: Option<Spanned<String>>,
    mass: Option<Spanned<f64>>,
    rotation: Option<Spanned<RawRotation>>,
    translation: Option<[f64; 3]>,
    #[serde(default)]
    void: bool,
    thin_wall: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRotation {
    axis: [f64; 3],
    degrees: f64,
}

/// A body file's extension, lower case, without the dot.
pub const BODY_FILE_EXTENSION: &str = "toml";

/// Whether `path` names a body file (by its `.toml` extension, any case).
pub fn is_body_file(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case(BODY_FILE_EXTENSION))
}

impl PartEntry {
    /// A solid part of `material` made of a mesh file (all of it, or one `object`), unturned at
    /// the origin: what a mesh file's parts are before anyone places them.
    pub fn unplaced(
        name: &str,
        mesh: &Path,
        object: Option<&str>,
        material: MaterialEntry,
    ) -> Self {
        Self {
            name: name.to_owned(),
            mesh: mesh.to_path_buf(),
            object: object.map(str::to_owned),
            material,
            rotation: None,
            translation: [0.0; 3],
            void: false,
            thin_wall: None,
            line: 0,
        }
    }

    /// Its fill for a file in `unit` metres (the thin wall converted to metres), by the one rule
    /// [`MaterialEntry::fill`].
    pub fn fill(&self, unit: f64) -> Fill {
        self.material
            .fill(self.void, self.thin_wall.map(|t| t * unit))
    }

    /// Mesh coordinates → body coordinates in metres for a file in `unit` metres: the rotation
    /// (about the mesh origin), then the translation.
    pub fn placement(&self, unit: f64) -> Isometry3<f64> {
        let rotation = self
            .rotation
            .map_or_else(UnitQuaternion::identity, |(axis, degrees)| {
                let axis = Vector3::from(axis);
                UnitQuaternion::from_axis_angle(
                    &Unit::new_normalize(axis / axis.amax()),
                    degrees.to_radians(),
                )
            });
        let translation = Vector3::from(self.translation) * unit;
        Isometry3::from_parts(Translation3::from(translation), rotation)
    }
}

impl BodyFile {
    /// Reads a body file (not its meshes).
    pub fn read(path: &Path) -> Result<Self, MeshError> {
        let text = std::fs::read_to_string(path).map_err(|source| MeshError::Io {
            path: path.to_path_buf(),
            source: source.into(),
        })?;
        Self::parse(&text, path)
    }

    /// Parses body-file text; `path` names it in messages and anchors the meshes' paths.
    pub fn parse(text: &str, path: &Path) -> Result<Self, MeshError> {
        let error = |at: Option<usize>, message: String| MeshError::Malformed {
            path: path.to_path_buf(),
            line: at.map(|offset| line_of(text, offset)),
            message,
        };
        let raw: RawBody = toml::from_str(text).map_err(|e| {
            error(
                e.span().map(|s| s.start),
                e.message().trim_end().replace('\n', " "),
            )
        })?;
        if let Some(v) = &raw.version
            && *v.get_ref() != BODY_FILE_VERSION
        {
            return Err(error(
                Some(v.span().start),
                format!(
                    "version: this program reads body files of version {BODY_FILE_VERSION}, not {}",
                    v.get_ref()
                ),
            ));
        }
        let units = match &raw.units {
            None => LengthUnit::M,
            Some(u) => u
                .get_ref()
                .parse::<LengthUnit>()
                .map_err(|e| error(Some(u.span().start), format!("units: {e}")))?,
        };
        if raw.part.is_empty() {
            return Err(error(None, "the body has no [[part]]".to_owned()));
        }
        let mut parts = Vec::with_capacity(raw.part.len());
        for (k, spanned) in raw.part.iter().enumerate() {
            let at = spanned.span().start;
            let p = spanned.get_ref();
            let name = p.name.clone().unwrap_or_else(|| format!("part {}", k + 1));
            let here = |key: &str, span: Option<usize>, message: String| {
                error(
                    Some(span.unwrap_or(at)),
                    format!("part \"{name}\": {key}: {message}"),
                )
            };
            let Some(mesh) = &p.mesh else {
                return Err(here(
                    "mesh",
                    None,
                    "missing (the part's OBJ or STL file)".into(),
                ));
            };
            let given = [p.density.is_some(), p.material.is_some(), p.mass.is_some()];
            let material = match (&p.density, &p.material, &p.mass) {
                _ if given.iter().filter(|&&g| g).count() > 1 => {
                    return Err(here(
                        "density",
                        None,
                        "give one of density, material and mass".into(),
                    ));
                }
                (Some(d), _, _) => {
                    positive_at(*d.get_ref())
                        .map_err(|m| here("density", Some(d.span().start), m))?;
                    MaterialEntry::Density(*d.get_ref())
                }
                (_, Some(m), _) => {
                    if material(m.get_ref()).is_none() {
                        return Err(here(
                            "material",
                            Some(m.span().start),
                            format!(
                                "unknown material {:?} (the presets: {})",
                                m.get_ref(),
                                material_names()
                            ),
                        ));
                    }
                    MaterialEntry::Preset(m.get_ref().clone())
                }
                (_, _, Some(m)) => {
                    positive_at(*m.get_ref()).map_err(|e| here("mass", Some(m.span().start), e))?;
                    if p.void || p.thin_wall.is_some() {
                        return Err(here(
                            "mass",
                            Some(m.span().start),
                            "a void or a thin wall takes a density or a material, not a mass"
                                .into(),
                        ));
                    }
                    MaterialEntry::Mass(*m.get_ref())
                }
                (None, None, None) => {
                    return Err(here(
                        "density",
                        None,
                        "missing (give density, material or mass)".into(),
                    ));
                }
            };
            let rotation = match &p.rotation {
                None => None,
                Some(r) => {
                    let raw = r.get_ref();
                    let axis = Vector3::from(raw.axis);
                    // Measured by its largest component: the norm of [1e200, 0, 0] overflows.
                    let valid = axis.iter().all(|c| c.is_finite())
                        && axis.amax() > 0.0
                        && raw.degrees.is_finite();
                    if !valid {
                        return Err(here(
                            "rotation",
                            Some(r.span().start),
                            "the axis must be a non-zero vector and degrees a number".into(),
                        ));
                    }
                    Some((raw.axis, raw.degrees))
                }
            };
            let thin_wall = match &p.thin_wall {
                None => None,
                Some(t) => {
                    positive_at(*t.get_ref())
                        .map_err(|m| here("thin_wall", Some(t.span().start), m))?;
                    if p.void {
                        return Err(here(
                            "thin_wall",
                            Some(t.span().start),
                            "a void has no wall".into(),
                        ));
                    }
                    Some(*t.get_ref())
                }
            };
            let translation = p.translation.unwrap_or([0.0; 3]);
            if translation.iter().any(|c| !c.is_finite()) {
                return Err(here("translation", None, "not a finite vector".into()));
            }
            parts.push(PartEntry {
                name,
                mesh: PathBuf::from(mesh.get_ref()),
                object: p.object.as_ref().map(|o| o.get_ref().clone()),
                material,
                rotation,
                translation,
                void: p.void,
                thin_wall,
                line: line_of(text, at),
            });
        }
        Ok(Self {
            path: path.to_path_buf(),
            units,
            parts,
        })
    }

    /// The size of the file's length unit in metres.
    pub fn unit(&self) -> f64 {
        self.units.metres()
    }

    /// The same body with every length in metres (translations, thin walls; the meshes are
    /// converted by [`BodyFile::load`]) and each mesh path joined to the body file's folder:
    /// the settings of the parts [`BodyFile::load`] gives.
    pub fn in_metres(&self) -> BodyFile {
        let unit = self.unit();
        let folder = self.path.parent().unwrap_or(Path::new(""));
        BodyFile {
            path: self.path.clone(),
            units: LengthUnit::M,
            parts: self
                .parts
                .iter()
                .map(|p| PartEntry {
                    mesh: folder.join(&p.mesh),
                    translation: p.translation.map(|c| c * unit),
                    thin_wall: p.thin_wall.map(|t| t * unit),
                    ..p.clone()
                })
                .collect(),
        }
    }

    /// Loads every part's mesh (each file once) and builds the parts, in metres.
    pub fn load(&self) -> Result<Vec<Part>, MeshError> {
        self.load_with(&|path: &Path| {
            if path.is_file() {
                Ok(Some(load_mesh(path)?))
            } else {
                Ok(None)
            }
        })
    }

    /// [`BodyFile::load`] with the meshes read by `read` (`None`: no such file), e.g. from
    /// files embedded in a program.
    pub fn load_with(
        &self,
        read: &dyn Fn(&Path) -> Result<Option<crate::MeshFile>, MeshError>,
    ) -> Result<Vec<Part>, MeshError> {
        let folder = self.path.parent().unwrap_or(Path::new(""));
        let unit = self.unit();
        let mut loaded: Vec<(PathBuf, crate::MeshFile)> = Vec::new();
        let mut parts = Vec::with_capacity(self.parts.len());
        for entry in &self.parts {
            let at = |message: String| MeshError::Malformed {
                path: self.path.clone(),
                line: Some(entry.line),
                message: format!("part \"{}\": {message}", entry.name),
            };
            let file_path = folder.join(&entry.mesh);
            let index = match loaded.iter().position(|(p, _)| *p == file_path) {
                Some(i) => i,
                None => {
                    let Some(file) = read(&file_path)? else {
                        return Err(at(format!("mesh: {} does not exist", file_path.display())));
                    };
                    loaded.push((file_path.clone(), file));
                    loaded.len() - 1
                }
            };
            let file = &loaded[index].1;
            let mesh = match &entry.object {
                None => file.mesh.clone(),
                Some(object) => {
                    let parts = file.parts();
                    let Some((_, faces)) = parts.iter().find(|(n, _)| n == object) else {
                        let names: Vec<&str> = parts.iter().map(|(n, _)| n.as_str()).collect();
                        return Err(at(format!(
                            "object: {} has no object {object:?} (it has: {})",
                            entry.mesh.display(),
                            names.join(", ")
                        )));
                    };
                    file.mesh.subset(faces)?
                }
            };
            let mesh = mesh.map_positions(|p| p * unit)?;
            let fill = entry.fill(unit);
            parts.push(Part {
                name: entry.name.clone(),
                mesh,
                fill,
                placement: entry.placement(unit),
            });
        }
        Ok(parts)
    }

    /// The body file's text (what [`BodyFile::parse`] reads back to the same parts).
    pub fn to_toml(&self) -> String {
        let mut s = format!(
            "version = {BODY_FILE_VERSION}\nunits = \"{}\"\n",
            self.units.symbol()
        );
        for p in &self.parts {
            s.push_str("\n[[part]]\n");
            s.push_str(&format!("name = {}\n", quoted(&p.name)));
            s.push_str(&format!("mesh = {}\n", quoted(&p.mesh.to_string_lossy())));
            if let Some(o) = &p.object {
                s.push_str(&format!("object = {}\n", quoted(o)));
            }
            match &p.material {
                MaterialEntry::Density(d) => s.push_str(&format!("density = {}\n", number(*d))),
                MaterialEntry::Preset(m) => s.push_str(&format!("material = {}\n", quoted(m))),
                MaterialEntry::Mass(m) => s.push_str(&format!("mass = {}\n", number(*m))),
            }
            if let Some((axis, degrees)) = p.rotation {
                s.push_str(&format!(
                    "rotation = {{ axis = {}, degrees = {} }}\n",
                    triple(axis),
                    number(degrees)
                ));
            }
            if p.translation != [0.0; 3] {
                s.push_str(&format!("translation = {}\n", triple(p.translation)));
            }
            if p.void {
                s.push_str("void = true\n");
            }
            if let Some(t) = p.thin_wall {
                s.push_str(&format!("thin_wall = {}\n", number(t)));
            }
        }
        s
    }
}

/// A TOML basic string: quotes, backslashes and control characters escaped (a name may hold a
/// newline; written raw it would end the string).
fn quoted(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A float TOML reads back exactly (shortest round-trip form, with a decimal point).
fn number(x: f64) -> String {
    let s = format!("{x:?}");
    if s.contains(['.', 'e', 'E', 'n', 'i']) {
        s
    } else {
        format!("{s}.0")
    }
}

fn triple(v: [f64; 3]) -> String {
    format!("[{}, {}, {}]", number(v[0]), number(v[1]), number(v[2]))
}

fn positive_at(x: f64) -> Result<(), String> {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        Err(format!("{x} is not a positive number"))
    }
}

/// The one-based line of byte `offset` of `text`.
fn line_of(text: &str, offset: usize) -> usize {
    1 + text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
}
