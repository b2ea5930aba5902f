"""A Blender mesh object's exact mass properties through ``inertialab``, in metres and kilograms.

The object's mesh is read in its local axes with the object's scale applied (Blender scales in
local axes before it rotates), times the scene's unit scale (``unit_settings.scale_length``,
metres per Blender unit): the "metric local frame", in which the add-on computes and bakes.
Blender's own rotation and location then put that frame in the world.
"""

from __future__ import annotations

import numpy as np

import inertialab as il


def metres_per_unit(scene) -> float:
    """Metres per Blender unit in `scene` (1 unless the scene's unit scale says otherwise)."""
    return float(scene.unit_settings.scale_length) or 1.0


def object_arrays(obj, scale_length: float) -> tuple[np.ndarray, list[list[int]]]:
    """The vertices of `obj`'s mesh (n, 3) in the metric local frame, and its polygons as
    index lists (counter-clockwise seen from outside, as Blender winds them)."""
    mesh = obj.data
    co = np.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", co)
    vertices = co.reshape(-1, 3) * np.asarray(obj.scale, dtype=float) * scale_length
    counts = np.empty(len(mesh.polygons), dtype=np.int64)
    mesh.polygons.foreach_get("loop_total", counts)
    corners = np.empty(len(mesh.loops), dtype=np.int64)
    mesh.loops.foreach_get("vertex_index", corners)
    ends = np.cumsum(counts)
    faces = [corners[e - n:e].tolist() for n, e in zip(counts, ends)]
    return vertices, faces


def measure(obj, scene, density: float) -> il.MassResult:
    """`obj`'s solid at `density` kg/m³, analysed as ``inertia-lab props`` analyses a mesh: its
    defects repaired and named in ``warnings``."""
    vertices, faces = object_arrays(obj, metres_per_unit(scene))
    return il.mass_properties(vertices, faces, density=density)


def warning_lines(result: il.MassResult) -> list[str]:
    """The result's warnings in ``props``' words, one line each (code: message)."""
    return [f"{w['code']}: {w['message']}" for w in (result.warnings or [])]
