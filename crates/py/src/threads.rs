//! How many threads a call uses, and the errors a call raises in Python.
//!
//! A pipeline runs one call per worker process or thread, so a call uses **one thread** unless
//! told otherwise (`threads=`, else `RAYON_NUM_THREADS`): a worker that spawned a pool as large
//! as the machine would fight its siblings. One thread is the caller's own; larger counts have
//! one rayon pool each, made on first use and kept.

use std::sync::{Arc, Mutex};

use inertia_io::input::InputError;
use massprops::MeshError as Mesh;
use pyo3::exceptions::{PyFileNotFoundError, PyIndexError, PyOSError, PyValueError};
use pyo3::prelude::*;

use crate::arrays::BadArrays;

pyo3::create_exception!(
    inertialab,
    MeshError,
    PyValueError,
    "The mesh or file gives no body: it cannot be read or parsed, it encloses no volume, it is \
     open and refused, its caps are too large, or its numbers would be impossible. `kind` names \
     the problem (as the batch table's `error_kind`); the message says where."
);

/// The threads a call runs on: `threads`, else `RAYON_NUM_THREADS`, else 1.
pub fn count(threads: Option<usize>) -> PyResult<usize> {
    let n = match threads {
        Some(n) => n,
        None => std::env::var("RAYON_NUM_THREADS")
            .ok()
            .and_then(|v| v.trim().parse().ok())
            .filter(|&n| n > 0)
            .unwrap_or(1),
    };
    if n == 0 {
        return Err(PyValueError::new_err("threads must be at least 1"));
    }
    Ok(n)
}

/// Runs `work` on `threads` threads (rayon calls inside it stay on them).
///
/// One thread is the calling thread itself, made the only worker of a pool of its own (kept per
/// thread): no other thread is woken, and two Python threads calling at once run side by side.
/// More threads share one pool per count in the process.
pub fn on_threads<T: Send>(threads: usize, work: impl FnOnce() -> T + Send) -> T {
    if threads == 1 {
        thread_local! {
            // rayon leaks the registry of a pool that uses its creating thread (a few hundred
            // bytes per Python thread that calls, never a thread).
            static OWN: Option<rayon::ThreadPool> = rayon::ThreadPoolBuilder::new()
                .num_threads(1)
                .use_current_thread()
                .build()
                .ok();
        }
        return OWN.with(|pool| match pool {
            Some(pool) => pool.install(work),
            None => work(),
        });
    }
    static POOLS: Mutex<Vec<(usize, Arc<rayon::ThreadPool>)>> = Mutex::new(Vec::new());
    let pool = {
        let mut pools = POOLS.lock().unwrap_or_else(|e| e.into_inner());
        match pools.iter().find(|(n, _)| *n == threads) {
            Some((_, pool)) => Some(Arc::clone(pool)),
            None => rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .thread_name(|i| format!("inertialab-{i}"))
                .build()
                .ok()
                .map(|pool| {
                    let pool = Arc::new(pool);
                    pools.push((threads, Arc::clone(&pool)));
                    pool
                }),
        }
    };
    match pool {
        Some(pool) => pool.install(work),
        // The system refused a thread: the global pool still gives a result.
        None => work(),
    }
}

/// What went wrong in a call, turned into a Python exception by [`raise`].
pub enum CallFailure {
    /// The arrays give no mesh.
    Arrays(BadArrays),
    /// The file gives no body.
    Input(InputError),
}

impl From<BadArrays> for CallFailure {
    fn from(e: BadArrays) -> Self {
        CallFailure::Arrays(e)
    }
}

/// The exception of `failure`: `IndexError` for an index out of range, `ValueError` for arrays
/// that are not a valid mesh (non-finite coordinates, faces of fewer than three corners),
/// `FileNotFoundError` / `OSError` for a file that cannot be read, and [`MeshError`] with its
/// `kind` for everything that has no body.
pub fn raise(py: Python<'_>, failure: CallFailure) -> PyErr {
    let mesh = |e: &Mesh, message: String| -> PyErr {
        match e {
            Mesh::IndexOutOfRange { .. } => PyIndexError::new_err(message),
            Mesh::NonFiniteVertex { .. }
            | Mesh::TooFewCorners { .. }
            | Mesh::TooLarge { .. }
            | Mesh::InvalidParameter { .. }
            | Mesh::Empty => PyValueError::new_err(message),
            Mesh::Io { source, .. } if source.kind() == std::io::ErrorKind::NotFound => {
                PyFileNotFoundError::new_err(message)
            }
            Mesh::Io { .. } => PyOSError::new_err(message),
            _ => {
                let err = MeshError::new_err(message);
                // Setting an attribute on a fresh exception object cannot fail in practice; if it
                // did, the exception without `kind` is still the right one to raise.
                let _ = err.value(py).setattr("kind", e.kind());
                err
            }
        }
    };
    match failure {
        CallFailure::Arrays(BadArrays::Index {
            face,
            index,
            vertex_count,
        }) => PyIndexError::new_err(format!(
            "face {face} refers to vertex {index}, but the mesh has only {vertex_count} \
             vertices (indices count from 0; negative indices are not allowed)"
        )),
        CallFailure::Arrays(BadArrays::Sizes { total, corners }) => PyValueError::new_err(format!(
            "the face sizes add up to {total} corners, but {corners} corners were given"
        )),
        CallFailure::Arrays(BadArrays::Mesh(e)) => mesh(&e, e.to_string()),
        CallFailure::Input(e) => match &e {
            InputError::Mesh { source, .. } | InputError::Read(source) => {
                mesh(innermost(source), e.to_string())
            }
            InputError::UnknownPart { .. } | InputError::MassOfParts => {
                PyValueError::new_err(e.to_string())
            }
        },
    }
}

/// The error inside the file and part that place it.
fn innermost(e: &Mesh) -> &Mesh {
    match e {
        Mesh::InFile { source, .. } | Mesh::InPart { source, .. } => innermost(source),
        e => e,
    }
}
