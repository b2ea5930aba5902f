"""One mesh: ``mass_properties`` of numpy arrays (or a ``trimesh.Trimesh``) and ``analyze_file``.

The arguments are checked and converted here (dtypes, layouts, lists, ragged faces); the work is
``_native``'s, with the GIL released.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, Literal, Union

import numpy as np

from . import _native
from ._native import MassResult

Method = Literal["volume", "shell", "points", "bbox"]

# Face dtypes the native side reads as they are; any other integer dtype is converted to int64.
_FACE_DTYPES = (np.dtype(np.int64), np.dtype(np.int32), np.dtype(np.uint32))
_F64 = np.dtype(np.float64)


@dataclass(frozen=True)
class Repairs:
    """How the defects of a mesh are handled (massprops' ``Repairs``; ``props``'s ``--weld``,
    ``--holes`` and ``--max-cap-share``).

    - ``weld``: which boundary vertices are merged to close cracks: ``"auto"`` (within 1e-6 of
      the bounding-box diagonal: float32 rounding), ``"exact"`` (identical coordinates only), or
      a distance in the mesh's units.
    - ``holes``: ``"cap"`` closes each hole with a fan of triangles (the warning says how much
      the caps add), ``"refuse"`` makes an open mesh an error.
    - ``max_cap_share``: with ``holes="cap"``, the largest share of the closed surface caps may
      make, caps / (surface + caps); a mesh whose caps make more is refused (a sheet, a terrain).
    - ``overlap_budget``: the most work spent comparing closed shells for nesting and overlap
      (and each with itself), in work units: a pair of shells whose boxes meet costs the
      triangles of both and the 4 096 lines it casts. Pairs beyond it are not compared and the
      warnings say so (``uncompared_bound``). A count of work, not a time: the same file gives
      the same row on any machine. 0 compares none, which is what trimesh does.
    """

    weld: Union[Literal["auto", "exact"], float] = "auto"
    holes: Literal["cap", "refuse"] = "cap"
    max_cap_share: float = 0.5
    overlap_budget: int = _native.OVERLAP_BUDGET

    def _native_args(self) -> tuple[str, float, str, float, int]:
        if self.overlap_budget < 0:
            raise ValueError(f"overlap_budget must be 0 or more, not {self.overlap_budget}")
        budget = int(self.overlap_budget)
        if isinstance(self.weld, str):
            return self.weld, 0.0, self.holes, float(self.max_cap_share), budget
        return "distance", float(self.weld), self.holes, float(self.max_cap_share), budget


_DEFAULT_REPAIRS = Repairs()


def _repairs(repairs: Union[Repairs, dict[str, Any], None]) -> tuple[str, float, str, float, int]:
    if repairs is None:
        return _DEFAULT_REPAIRS._native_args()
    if isinstance(repairs, dict):
        repairs = Repairs(**repairs)
    if not isinstance(repairs, Repairs):
        raise TypeError(f"repairs must be an inertialab.Repairs or a dict, not {type(repairs).__name__}")
    return repairs._native_args()


def _vertices(vertices: Any) -> np.ndarray:
    if type(vertices) is np.ndarray and vertices.dtype == _F64 and vertices.flags.c_contiguous:
        v = vertices
    else:
        try:
            v = np.ascontiguousarray(vertices, dtype=np.float64)
        except (TypeError, ValueError) as e:
            raise ValueError(f"vertices must be numbers of shape (n, 3): {e}") from None
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"vertices must have shape (n, 3), got {v.shape}")
    return v


def _faces(faces: Any) -> tuple[np.ndarray, Union[np.ndarray, None]]:
    """(faces, sizes): an (m, k) array, or flat corners and their faces' sizes when ragged."""
    if isinstance(faces, np.ndarray) and faces.ndim == 2:
        f = faces
    else:
        try:
            f = np.asarray(faces)
        except ValueError:
            f = np.asarray(faces, dtype=object)
        if f.dtype == object or f.ndim == 1:
            rows = [np.asarray(row) for row in faces]
            if any(r.ndim != 1 for r in rows):
                raise ValueError("faces must be (m, k) corner indices, or a list of index lists")
            sizes = np.fromiter((len(r) for r in rows), dtype=np.int64, count=len(rows))
            flat = np.concatenate(rows) if rows else np.zeros(0, dtype=np.int64)
            return _integers(flat, "faces").astype(np.int64, copy=False), sizes
    if f.ndim != 2:
        raise ValueError(f"faces must have shape (m, k) with k >= 3, got {f.shape}")
    if f.shape[1] < 3:
        raise ValueError(f"faces must have shape (m, k) with k >= 3 corners, got {f.shape}")
    if f.dtype in _FACE_DTYPES and f.flags.c_contiguous:
        return f, None
    return np.ascontiguousarray(_integers(f, "faces")), None


def _integers(a: np.ndarray, name: str) -> np.ndarray:
    if a.dtype in _FACE_DTYPES:
        return np.ascontiguousarray(a)
    if a.dtype.kind in "iu":
        if a.size and a.dtype.kind == "u" and a.max() > np.iinfo(np.int64).max:
            raise IndexError(f"{name}: an index is larger than any mesh can have")
        return a.astype(np.int64)
    if a.dtype.kind == "f" and a.size and np.all(np.isfinite(a)) and np.all(a == np.round(a)):
        return a.astype(np.int64)
    if a.size == 0:
        return a.astype(np.int64)
    raise TypeError(f"{name} must be integer vertex indices, got dtype {a.dtype}")


def _threads(threads: Union[int, None]) -> Union[int, None]:
    if threads is not None and (not isinstance(threads, int) or threads < 1):
        raise ValueError(f"threads must be a positive integer, not {threads!r}")
    return threads


def mass_properties(
    vertices: Any,
    faces: Any = None,
    *,
    density: Union[float, None] = None,
    mass: Union[float, None] = None,
    method: Method = "volume",
    repairs: Union[Repairs, dict[str, Any], None] = None,
    check: bool = True,
    threads: Union[int, None] = None,
) -> MassResult:
    """Mass properties of the mesh ``vertices`` (n, 3) and ``faces`` (m, k ≥ 3 corner indices,
    counting from 0, counter-clockwise seen from outside; or a list of index lists).

    ``vertices`` may be a ``trimesh.Trimesh`` (its vertices and faces are used). ``density``
    (default 1) or ``mass``; ``method`` ``"volume"`` (the solid), ``"shell"`` (a thin wall on the
    faces, density per area), ``"points"`` or ``"bbox"`` (approximations).

    ``check=True`` (default) is ``props``: identical vertices welded, the mesh diagnosed, its
    defects repaired as ``repairs`` says and named in ``warnings`` with their effect on the mass.
    ``check=False`` integrates the solid alone, reading the arrays in place (float64 vertices,
    uint32 triangles; other dtypes are converted once): ``warnings`` is ``None``, and a mesh that
    is open, doubled or inside out gives wrong numbers without a word.

    C-contiguous float64 vertices and int32 / int64 / uint32 faces are not copied by Python;
    anything else is converted first. Runs on one thread unless ``threads`` (or
    ``RAYON_NUM_THREADS``) says otherwise, with the GIL released.

    Raises ``ValueError`` for arrays of the wrong shape or non-finite coordinates, ``IndexError``
    for an index out of range, and ``inertialab.MeshError`` (a ``ValueError``, with ``kind``)
    for a mesh that has no body.
    """
    if faces is None:
        if hasattr(vertices, "vertices") and hasattr(vertices, "faces"):
            vertices, faces = vertices.vertices, vertices.faces
        else:
            raise TypeError("mass_properties needs faces, or a trimesh.Trimesh")
    v = _vertices(vertices)
    f, sizes = _faces(faces)
    return _native.analyze_arrays(
        v,
        f,
        sizes,
        None if density is None else float(density),
        None if mass is None else float(mass),
        method,
        _repairs(repairs),
        bool(check),
        _threads(threads),
    )


def analyze_file(
    path: Union[str, os.PathLike[str]],
    *,
    density: Union[float, None] = None,
    mass: Union[float, None] = None,
    method: Method = "volume",
    repairs: Union[Repairs, dict[str, Any], None] = None,
    threads: Union[int, None] = None,
) -> MassResult:
    """Mass properties of an OBJ, STL (binary or ASCII), PLY or OFF file, or of a body file (``.toml``) of
    parts with their materials and placements, read and analysed as ``inertia-lab props`` does:
    ``analyze_file(p).to_dict()`` is ``props --json p``'s object.

    Raises ``FileNotFoundError`` / ``OSError`` when the file cannot be read and
    ``inertialab.MeshError`` when it gives no body (``kind`` ``malformed``, ``zero_volume``, …).
    """
    return _native.analyze_path(
        os.fspath(path),
        None if density is None else float(density),
        None if mass is None else float(mass),
        method,
        _repairs(repairs),
        _threads(threads),
    )
