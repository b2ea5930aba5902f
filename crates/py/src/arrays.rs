//! numpy arrays → meshes. Vertices are read in place when they are C-contiguous float64 (the
//! Python layer converts anything else first); faces are read in place when they are uint32
//! triangles, else converted once to the u32 indices massprops works on, with their range
//! checked in the same pass.

use std::borrow::Cow;

use massprops::{MeshError, PolyMesh};
use nalgebra::Point3;
use numpy::{PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::FromPyObject;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

/// Why the arrays give no mesh: an index (which may be negative, which [`MeshError`]'s unsigned
/// indices cannot say), face sizes that do not add up, or what massprops finds.
#[derive(Debug)]
pub enum BadArrays {
    /// A corner's index is negative or past the last vertex.
    Index {
        /// Its face (counting from 0).
        face: usize,
        /// The index.
        index: i64,
        /// The number of vertices.
        vertex_count: usize,
    },
    /// The face sizes add up to another number of corners than the faces have.
    Sizes {
        /// The sum of the sizes.
        total: usize,
        /// The corners given.
        corners: usize,
    },
    /// The mesh is not valid, or gives no body.
    Mesh(MeshError),
}

impl From<MeshError> for BadArrays {
    fn from(e: MeshError) -> Self {
        BadArrays::Mesh(e)
    }
}

/// A face array as numpy holds it: (m, k) rows of k ≥ 3 corners, or a flat array of corners with
/// the faces' sizes given apart (ragged faces).
#[derive(FromPyObject)]
pub enum Faces<'py> {
    /// int64 (numpy's and trimesh's default).
    I64(PyReadonlyArray2<'py, i64>),
    /// int32.
    I32(PyReadonlyArray2<'py, i32>),
    /// uint32 (read in place for triangles).
    U32(PyReadonlyArray2<'py, u32>),
    /// Flat int64 corners, with `sizes`.
    Flat(PyReadonlyArray1<'py, i64>),
}

/// Borrowed views of the arrays, safe to use with the GIL released.
pub struct Views<'a> {
    /// The vertices, in place.
    pub positions: &'a [Point3<f64>],
    /// The corners, in place (uint32) or as numpy gave them.
    pub corners: Corners<'a>,
    /// Corners per face: `Some(k)` for a (m, k) array, `None` for ragged faces (`sizes`).
    pub arity: Option<usize>,
    /// The sizes of ragged faces.
    pub sizes: Option<&'a [i64]>,
}

/// The face corners in the dtype they came in.
pub enum Corners<'a> {
    /// int64.
    I64(&'a [i64]),
    /// int32.
    I32(&'a [i32]),
    /// uint32.
    U32(&'a [u32]),
}

/// The views of `vertices` (n, 3) and `faces`; shape and layout errors are `ValueError`s and
/// `TypeError`s naming the array.
pub fn views<'a>(
    vertices: &'a PyReadonlyArray2<'_, f64>,
    faces: &'a Faces<'_>,
    sizes: Option<&'a PyReadonlyArray1<'_, i64>>,
) -> PyResult<Views<'a>> {
    if vertices.shape()[1] != 3 {
        return Err(PyValueError::new_err(format!(
            "vertices must have shape (n, 3), got {:?}",
            vertices.shape()
        )));
    }
    let positions = bytemuck::cast_slice::<f64, Point3<f64>>(c_slice(vertices, "vertices")?);
    let (corners, arity) = match faces {
        Faces::I64(a) => (Corners::I64(c_slice(a, "faces")?), Some(a.shape()[1])),
        Faces::I32(a) => (Corners::I32(c_slice(a, "faces")?), Some(a.shape()[1])),
        Faces::U32(a) => (Corners::U32(c_slice(a, "faces")?), Some(a.shape()[1])),
        Faces::Flat(a) => (Corners::I64(c_slice(a, "faces")?), None),
    };
    if let Some(k) = arity
        && k < 3
    {
        return Err(PyValueError::new_err(format!(
            "faces must have shape (m, k) with k >= 3 corners, got (m, {k})"
        )));
    }
    let sizes = match (arity, sizes) {
        (None, Some(s)) => Some(c_slice(s, "face sizes")?),
        (None, None) => {
            return Err(PyValueError::new_err(
                "flat faces need their sizes (ragged faces)",
            ));
        }
        (Some(_), _) => None,
    };
    Ok(Views {
        positions,
        corners,
        arity,
        sizes,
    })
}

/// The array's elements in memory order, if that is C order.
fn c_slice<'a, T: numpy::Element, D: numpy::ndarray::Dimension>(
    a: &'a numpy::PyReadonlyArray<'_, T, D>,
    name: &str,
) -> PyResult<&'a [T]> {
    if !a.is_c_contiguous() {
        return Err(PyTypeError::new_err(format!(
            "{name} must be C-contiguous (numpy.ascontiguousarray)"
        )));
    }
    a.as_slice()
        .map_err(|e| PyTypeError::new_err(format!("{name}: {e}")))
}

impl Views<'_> {
    /// The corners as u32 when every face is a triangle (three to a triangle, for
    /// `bytemuck::cast_slice` to `[[u32; 3]]`): in place for uint32, else converted once (an
    /// index below 0 or past the vertices is an error naming its face).
    pub fn triangle_corners(&self) -> Option<Result<Cow<'_, [u32]>, BadArrays>> {
        if self.arity != Some(3) {
            return None;
        }
        let n = self.positions.len();
        let owned = |c: Result<Vec<u32>, (usize, i64)>| {
            c.map(Cow::Owned)
                .map_err(|(corner, index)| self.bad_index(corner, index))
        };
        Some(match self.corners {
            Corners::U32(c) => Ok(Cow::Borrowed(c)),
            Corners::I64(c) => owned(convert(c, n)),
            Corners::I32(c) => owned(convert(c, n)),
        })
    }

    /// The error of an index out of range at `corner`, naming its face.
    fn bad_index(&self, corner: usize, index: i64) -> BadArrays {
        let face = match (self.arity, self.sizes) {
            (Some(k), _) => corner / k,
            (None, Some(sizes)) => {
                let mut end = 0usize;
                sizes
                    .iter()
                    .position(|&s| {
                        end += usize::try_from(s).unwrap_or(0);
                        corner < end
                    })
                    .unwrap_or(sizes.len())
            }
            (None, None) => 0,
        };
        BadArrays::Index {
            face,
            index,
            vertex_count: self.positions.len(),
        }
    }

    /// The corners as u32 with every index checked, and the size of each face.
    pub fn flat(&self) -> Result<(Vec<u32>, Vec<usize>), BadArrays> {
        let n = self.positions.len();
        let corners = match self.corners {
            Corners::U32(c) => convert(c, n),
            Corners::I64(c) => convert(c, n),
            Corners::I32(c) => convert(c, n),
        }
        .map_err(|(corner, index)| self.bad_index(corner, index))?;
        let arities = match (self.arity, self.sizes) {
            (Some(k), _) => vec![k; corners.len() / k],
            (None, Some(sizes)) => {
                let mut arities = Vec::with_capacity(sizes.len());
                for (face, &s) in sizes.iter().enumerate() {
                    let corners = usize::try_from(s).unwrap_or(0);
                    if corners < 3 {
                        return Err(MeshError::TooFewCorners { face, corners }.into());
                    }
                    arities.push(corners);
                }
                let total: usize = arities.iter().sum();
                if total != corners.len() {
                    return Err(BadArrays::Sizes {
                        total,
                        corners: corners.len(),
                    });
                }
                arities
            }
            (None, None) => Vec::new(),
        };
        Ok((corners, arities))
    }

    /// The mesh as massprops builds it from a file: bit-identical positions welded into one
    /// vertex (as the OBJ and STL readers do), so a triangle soup has shared edges.
    pub fn welded_mesh(&self) -> Result<PolyMesh, BadArrays> {
        let (corners, arities) = self.flat()?;
        let (positions, map) = massprops::mesh::weld_exact(self.positions);
        let corners = corners.into_iter().map(|i| map[i as usize]).collect();
        Ok(PolyMesh::from_flat(positions, corners, &arities)?)
    }

    /// The mesh as given, not welded.
    pub fn mesh(&self) -> Result<PolyMesh, BadArrays> {
        let (corners, arities) = self.flat()?;
        Ok(PolyMesh::from_flat(
            self.positions.to_vec(),
            corners,
            &arities,
        )?)
    }
}

/// Indices of any integer type as u32 below `n`, in one pass that the compiler vectorises (the
/// bad index is looked for only when there is one). Err: the first bad corner and its index.
fn convert<I: Copy + Into<i64>>(corners: &[I], n: usize) -> Result<Vec<u32>, (usize, i64)> {
    let limit = n as u64;
    let mut out = vec![0u32; corners.len()];
    let mut bad = 0u64;
    for (o, &i) in out.iter_mut().zip(corners) {
        let i: i64 = i.into();
        // A negative index wraps to a huge one: one unsigned comparison finds both. No branch,
        // so that the loop runs in SIMD lanes.
        bad |= u64::from((i as u64) >= limit);
        *o = i as u32;
    }
    if bad != 0 {
        let found = corners
            .iter()
            .map(|&i| i.into())
            .enumerate()
            .find(|&(_, i): &(usize, i64)| (i as u64) >= limit);
        return Err(found.unwrap_or((0, -1)));
    }
    Ok(out)
}
