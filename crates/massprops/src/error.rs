//! The one error type of the crate: every way a mesh or a file can be unusable.

use std::borrow::Cow;
use std::path::PathBuf;

/// Why a mesh, a file or a parameter cannot give mass properties.
///
/// Variants name the problem and where it is (file, line, face, vertex) so a user can fix it.
#[derive(Debug, Clone, thiserror::Error)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum MeshError {
    /// The mesh has no faces (or no vertices).
    #[error("the mesh is empty: it has no faces")]
    Empty,
    /// A vertex coordinate is NaN or infinite.
    #[error("vertex {vertex} (counting from 0) has a non-finite coordinate {value}")]
    NonFiniteVertex {
        /// Zero-based vertex index.
        vertex: usize,
        /// The offending coordinate.
        value: f64,
    },
    /// A face refers to a vertex that does not exist.
    #[error(
        "face {face} refers to vertex {index}, but the mesh has only {vertex_count} vertices \
         (indices count from 0)"
    )]
    IndexOutOfRange {
        /// Zero-based face index.
        face: usize,
        /// The offending zero-based vertex index.
        index: usize,
        /// How many vertices the mesh has.
        vertex_count: usize,
    },
    /// A face has fewer than three corners.
    #[error("face {face} (counting from 0) has {corners} corner(s); a face needs at least 3")]
    TooFewCorners {
        /// Zero-based face index.
        face: usize,
        /// How many corners it has.
        corners: usize,
    },
    /// The mesh is too large for 32-bit indices.
    #[error("the mesh has {count} {what}; at most 4294967295 are supported")]
    TooLarge {
        /// What overflowed ("vertices", "corners").
        what: Cow<'static, str>,
        /// How many there are.
        count: usize,
    },
    /// The surface encloses (numerically) no volume, so the volume method has nothing to integrate.
    #[error(
        "the mesh encloses zero volume (signed volume {volume:e} for a bounding box of diagonal {diagonal:e}); \
         {cause}"
    )]
    ZeroVolume {
        /// The signed volume found.
        volume: f64,
        /// Bounding-box diagonal, for scale.
        diagonal: f64,
        /// The likely cause, from the mesh diagnostics where they were computed.
        cause: String,
    },
    /// A parameter (density, mass, scale, point) is not a positive finite number.
    #[error("invalid {name}: {value} (it must be a finite number greater than zero)")]
    InvalidParameter {
        /// Parameter name.
        name: Cow<'static, str>,
        /// The value given.
        value: f64,
    },
    /// The body's size, mass or inertia is too large or too small for f64 arithmetic to keep
    /// full precision (the integrals multiply up to five coordinates).
    #[error(
        "the {quantity} of this body is of the order of {estimate:e}, outside {low:e} to {high:e}, \
         where f64 arithmetic keeps full precision: {advice}"
    )]
    OutOfRange {
        /// "size" (the bounding box's longest side), "mass" or "inertia".
        quantity: Cow<'static, str>,
        /// Its order of magnitude.
        estimate: f64,
        /// The least accepted.
        low: f64,
        /// The greatest accepted.
        high: f64,
        /// What would bring it into range.
        advice: Cow<'static, str>,
    },
    /// The mesh has holes and capping them was refused ([`Holes::Refuse`](crate::defects::Holes)).
    #[error(
        "the mesh is open: {boundary_edges} edge(s) used by only one face, in {loops} hole(s){}; \
         the volume it encloses is not defined (cap the holes, or use the shell method for sheets)",
        examples(faces)
    )]
    OpenMesh {
        /// Edges used by one face.
        boundary_edges: usize,
        /// Boundary loops (holes).
        loops: usize,
        /// Some faces on the holes' edges (zero-based).
        faces: Vec<usize>,
    },
    /// The caps that would close the holes make too much of the closed surface
    /// ([`Repairs::max_cap_share`](crate::Repairs)).
    #[error(
        "its {holes} hole(s) would be closed by caps that make {:.1} % of the closed surface \
         (at most {:.1} % is allowed): the volume would be more the caps' than the file's. It is a \
         sheet, a terrain or a mesh with large parts missing: use the shell method for its mass, \
         or allow larger caps",
        share * 100.0,
        threshold * 100.0
    )]
    CapsTooLarge {
        /// caps / (surface + caps).
        share: f64,
        /// The largest share allowed.
        threshold: f64,
        /// How many holes.
        holes: usize,
    },
    /// A part of a composite body cannot be used.
    #[error("part \"{part}\": {source}")]
    InPart {
        /// The part's name.
        part: String,
        /// Why.
        source: Box<MeshError>,
    },
    /// The voids of a composite body remove as much material as there is, or more, or leave an
    /// inertia tensor no body has.
    #[error(
        "the voids remove more than there is: {}",
        match moments {
            None => format!("the total mass is {mass:e}, not positive"),
            Some(m) => format!(
                "the total mass is {mass:e} but the principal moments {m:?} are not those of a \
                 body (each must be positive and I1 + I2 ≥ I3)"
            ),
        }
    )]
    VoidTooLarge {
        /// The total mass found.
        mass: f64,
        /// The principal moments found, when the mass was positive.
        moments: Option<[f64; 3]>,
    },
    /// The solid's mass properties break a law every real body satisfies (a positive mass,
    /// positive moments with I1 + I2 ≥ I3, the centre of mass inside the hull): the defects of
    /// the mesh, counted as they are, make them impossible, so they are not reported.
    #[error("no real body has these mass properties: {law}; {cause}")]
    Impossible {
        /// Which law is broken, with the numbers.
        law: String,
        /// The defects found that can cause it, and what to do.
        cause: String,
    },
    /// The shell method found no surface area.
    #[error("the mesh has zero surface area")]
    ZeroArea,
    /// The file could not be read.
    #[error("{}: cannot read the file: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What the operating system said (shared, so that an error can be kept and cloned).
        #[cfg_attr(feature = "serde", serde(with = "io_words"))]
        source: std::sync::Arc<std::io::Error>,
    },
    /// The file extension is not one we can load.
    #[error("{}: unsupported file type (expected {expected})", path.display())]
    UnsupportedFormat {
        /// The file.
        path: PathBuf,
        /// The extensions there are, in words (".obj or .stl").
        expected: String,
    },
    /// The file's text or bytes do not follow its format.
    #[error("{}{}: {message}", path.display(), line.map(|l| format!(", line {l}")).unwrap_or_default())]
    Malformed {
        /// The file.
        path: PathBuf,
        /// One-based line number where known.
        line: Option<usize>,
        /// What is wrong.
        message: String,
    },
    /// A mesh problem found in a file, with the line that causes it where known.
    #[error("{}{}: {source}", path.display(), line.map(|l| format!(", line {l}")).unwrap_or_default())]
    InFile {
        /// The file.
        path: PathBuf,
        /// One-based line number where known.
        line: Option<usize>,
        /// The mesh problem.
        source: Box<MeshError>,
    },
}

impl MeshError {
    /// A stable snake_case identifier of the problem, for machine-readable output (the Python
    /// package's batch table): the variant's name, that of the error inside for an error placed in
    /// a file or a part.
    pub fn kind(&self) -> &'static str {
        match self {
            MeshError::Empty => "empty",
            MeshError::NonFiniteVertex { .. } => "non_finite_vertex",
            MeshError::IndexOutOfRange { .. } => "index_out_of_range",
            MeshError::TooFewCorners { .. } => "too_few_corners",
            MeshError::TooLarge { .. } => "too_large",
            MeshError::ZeroVolume { .. } => "zero_volume",
            MeshError::InvalidParameter { .. } => "invalid_parameter",
            MeshError::OutOfRange { .. } => "out_of_range",
            MeshError::OpenMesh { .. } => "open_mesh",
            MeshError::CapsTooLarge { .. } => "caps_too_large",
            MeshError::VoidTooLarge { .. } => "void_too_large",
            MeshError::Impossible { .. } => "impossible",
            MeshError::ZeroArea => "zero_area",
            MeshError::Io { .. } => "io",
            MeshError::UnsupportedFormat { .. } => "unsupported_format",
            MeshError::Malformed { .. } => "malformed",
            MeshError::InPart { source, .. } | MeshError::InFile { source, .. } => source.kind(),
        }
    }
}

/// ", around faces 3, 7 (counting from 0)", or nothing for no faces.
fn examples(faces: &[usize]) -> String {
    if faces.is_empty() {
        return String::new();
    }
    let list: Vec<String> = faces.iter().map(usize::to_string).collect();
    format!(", around faces {} (counting from 0)", list.join(", "))
}

/// An I/O error as its words on the wire (`io::Error` is not data): what a page's worker read
/// wrongly reaches the page as the system said it.
#[cfg(feature = "serde")]
mod io_words {
    use std::sync::Arc;

    pub fn serialize<S: serde::Serializer>(
        e: &Arc<std::io::Error>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        s.serialize_str(&e.to_string())
    }

    pub fn deserialize<'de, D: serde::Deserializer<'de>>(
        d: D,
    ) -> Result<Arc<std::io::Error>, D::Error> {
        let words: String = serde::Deserialize::deserialize(d)?;
        Ok(Arc::new(std::io::Error::other(words)))
    }
}
