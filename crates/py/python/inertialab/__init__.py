"""inertialab: exact mass properties of meshes, with every defect named and its effect on the
mass, from Python.

- ``mass_properties(vertices, faces, ...)``: one mesh from numpy arrays or a ``trimesh.Trimesh``;
- ``analyze_file(path, ...)``: a mesh file (``MESH_EXTENSIONS``: OBJ, STL, PLY, OFF, glTF/GLB, MuJoCo MSH, COLLADA, 3MF) or a body file,
  as ``inertia-lab props`` reads it;
- ``measure_table(batch, ...)``: an Arrow table of files in, the batch table out, one row each;
- ``measure_files(paths, out, ...)``: a folder of files into resumable Parquet shards;
- ``mesh_files(folder_or_glob)``: the files ``measure_files`` would measure, for an engine;
- ``audit(path, ...)`` / ``audit_table(paths, ...)``: robot descriptions (URDF, MJCF, SDFormat) as
  ``inertia-lab audit --json`` audits them, as a dict or one Arrow row per link;
- ``simulate(path, ...)``: a body spun from rest, its keyframes as arrays (``Motion``) and, with
  ``animation=``, the same ``.glb`` or ``.usda`` file as ``inertia-lab simulate --animation``;
- ``MassResult``: one body's numbers, ``to_dict()`` (``props --json``'s object) and exports.

Conventions: lengths in the mesh's unit, mass in the unit of density times length³; the inertia
tensor is about the centre of mass in the mesh's axes, I = ∑ m (|r|² E − r rᵀ), so the
off-diagonals are −∑ m·x·y; principal moments ascending, principal axes as rows.
"""

from ._api import Repairs, analyze_file, mass_properties
from ._audit import audit, audit_table
from ._files import Summary, measure_files, mesh_files
from ._simulate import Motion, simulate
from ._native import (
    BATCH_SCHEMA_VERSION,
    MESH_EXTENSIONS,
    SCHEMA_VERSION,
    MassResult,
    MeshError,
    __version__,
)
from ._table import batch_schema, measure_table

__all__ = [
    "BATCH_SCHEMA_VERSION",
    "MESH_EXTENSIONS",
    "MassResult",
    "MeshError",
    "Motion",
    "Repairs",
    "SCHEMA_VERSION",
    "Summary",
    "__version__",
    "analyze_file",
    "audit",
    "audit_table",
    "batch_schema",
    "mass_properties",
    "measure_files",
    "measure_table",
    "mesh_files",
    "simulate",
]
