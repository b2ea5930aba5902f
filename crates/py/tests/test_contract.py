"""The input contract: dtypes, layouts, lists and trimesh accepted; bad input is a Python error
naming the problem, never a crash; arrays are read in place."""

import threading
import time
import tracemalloc

import numpy as np
import pytest

import inertialab as il
from conftest import box, torus


def reference():
    v, f = torus(1.0, 0.3, 48, 24)
    return v, f, il.mass_properties(v, f)


def same(a, b, tol=1e-12):
    assert abs(a.mass - b.mass) <= tol * b.mass
    assert np.allclose(a.center_of_mass, b.center_of_mass, rtol=0, atol=tol)
    assert np.allclose(a.inertia, b.inertia, rtol=0, atol=tol * np.abs(b.inertia).max())


@pytest.mark.parametrize("dtype", [np.int32, np.int64, np.uint32, np.uint16, np.int8, np.uint64])
def test_face_dtypes(dtype):
    v, f, ref = reference()
    if np.iinfo(dtype).max < len(v):
        v, f = box()
        ref = il.mass_properties(v, f)
    for check in (True, False):
        same(il.mass_properties(v, f.astype(dtype), check=check), ref)


def test_vertex_dtypes_orders_and_views():
    v, f, ref = reference()
    same(il.mass_properties(v.astype(np.float32), f), il.mass_properties(v.astype(np.float32).astype(float), f))
    same(il.mass_properties(np.asfortranarray(v), f), ref)
    same(il.mass_properties(v, np.asfortranarray(f)), ref)
    wide = np.zeros((len(v), 6))
    wide[:, ::2] = v
    same(il.mass_properties(wide[:, ::2], f), ref)  # a strided view
    same(il.mass_properties(v.tolist(), f.tolist()), ref)
    same(il.mass_properties(v, f.astype(float)), ref)  # whole numbers as floats


def test_trimesh_mesh_as_is():
    trimesh = pytest.importorskip("trimesh")
    m = trimesh.creation.box(extents=(1, 2, 3))
    r = il.mass_properties(m, density=2.0)
    assert abs(r.mass - 12.0) < 1e-12 and r.warnings == []


def test_polygons_and_ragged_faces():
    # A unit cube of quads, and the same with one face split into two triangles (ragged).
    v = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    quads = np.array([[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]])
    for check in (True, False):
        r = il.mass_properties(v, quads, check=check)
        assert abs(r.mass - 1) < 1e-15 and np.allclose(r.inertia, np.eye(3) / 6, atol=1e-15)
    ragged = [list(q) for q in quads[:5]] + [[1, 5, 7], [1, 7, 3]]
    r = il.mass_properties(v, ragged)
    assert abs(r.mass - 1) < 1e-15 and r.warnings == []


@pytest.mark.parametrize(
    "vertices, faces, error, words",
    [
        (np.zeros((8, 2)), box()[1], ValueError, r"shape \(n, 3\)"),
        (box()[0], box()[1][:, :2], ValueError, "k >= 3"),
        (box()[0], box()[1].ravel(), ValueError, "faces"),
        (box()[0][:5], box()[1], IndexError, "refers to vertex [5-7], but the mesh has only 5"),
        (box()[0], box()[1] - 1, IndexError, "vertex -1"),
        (np.where(np.arange(24).reshape(8, 3) == 13, np.nan, box()[0]), box()[1], ValueError, "vertex 4 .*non-finite"),
        (box()[0], box()[1] + 0.5, TypeError, "integer"),
        (box()[0], np.zeros((0, 3), dtype=np.int64), ValueError, "empty"),
        ("not a mesh", box()[1], ValueError, "vertices"),
        (box()[0], [[0, 1, 2], [0, 1]], il.MeshError if False else ValueError, "corner"),
    ],
)
def test_bad_input_is_an_error_naming_it(vertices, faces, error, words):
    for check in (True, False):
        with pytest.raises(error, match=words):
            il.mass_properties(vertices, faces, check=check)


def test_no_body_is_a_mesh_error_with_its_kind():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
    sheet = np.array([[0, 1, 2], [1, 3, 2]])
    with pytest.raises(il.MeshError) as e:
        il.mass_properties(v, sheet)
    assert e.value.kind in ("zero_volume", "caps_too_large")
    with pytest.raises(il.MeshError) as e:
        il.mass_properties(v, sheet, check=False)
    assert e.value.kind == "zero_volume"
    with pytest.raises(ValueError, match="method"):
        il.mass_properties(*box(), method="voxel")
    with pytest.raises(ValueError, match="check=False"):
        il.mass_properties(*box(), method="shell", check=False)


def test_arrays_are_read_in_place():
    # 1M vertices of float64 (24 MB) and their faces: Python allocates nothing the size of them.
    v, f = torus(1.0, 0.3, 1000, 500)
    assert v.nbytes == 12_000_000
    for faces in (f, f.astype(np.uint32), f.astype(np.int32)):
        for check in (False, True):
            tracemalloc.start()
            il.mass_properties(v, faces, check=check)
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
            assert peak < 100_000, (faces.dtype, check, peak)
    # A conversion is seen by the same measure: float32 vertices are copied to float64.
    tracemalloc.start()
    il.mass_properties(v.astype(np.float32), f, check=False)
    assert tracemalloc.get_traced_memory()[1] > v.nbytes
    tracemalloc.stop()


def test_the_gil_is_released():
    # 4M triangles; a Python thread counts while the call runs.
    v, f = torus(1.0, 0.3, 2000, 1000)
    assert len(f) == 4_000_000
    counted = []
    running = threading.Event()
    stop = threading.Event()

    def count():
        n = 0
        running.set()
        while not stop.is_set():
            n += 1
        counted.append(n)

    thread = threading.Thread(target=count)
    thread.start()
    running.wait()
    start = time.perf_counter()
    r = il.mass_properties(v, f)
    seconds = time.perf_counter() - start
    stop.set()
    thread.join()
    assert r.warnings == []
    # A free Python thread counts ~10⁷ a second here; with the GIL held it would count only in
    # the few interpreter switches before the call (well under 10⁵).
    assert seconds > 0.2, seconds
    assert counted[0] > 1_000_000 * seconds, (counted, seconds)


def test_threads_give_the_same_numbers():
    v, f = torus(1.0, 0.3, 400, 200)
    one = il.mass_properties(v, f, threads=1)
    two = il.mass_properties(v, f, threads=2)
    assert one.to_dict() == two.to_dict()
    with pytest.raises(ValueError, match="threads"):
        il.mass_properties(v, f, threads=0)


def test_repairs():
    # A box with one face missing: capped by default (with a warning), refused when asked.
    v, f = box()
    r = il.mass_properties(v, f[2:])
    assert [w["code"] for w in r.warnings] == ["holes_capped"]
    assert abs(r.mass - 6.0) < 1e-12
    with pytest.raises(il.MeshError) as e:
        il.mass_properties(v, f[2:], repairs=il.Repairs(holes="refuse"))
    assert e.value.kind == "open_mesh"
    with pytest.raises(il.MeshError):
        il.mass_properties(v, f[2:], repairs={"max_cap_share": 0.01})
    with pytest.raises(ValueError, match="weld"):
        il.mass_properties(v, f, repairs={"weld": -1.0})


def test_the_stubs_name_everything_the_native_module_has():
    import inspect
    import re
    from pathlib import Path

    from inertialab import _native

    stub = (Path(il.__file__).parent / "_native.pyi").read_text()
    declared = set(re.findall(r"^(?:def|class) (\w+)|^(\w+):", stub, re.M))
    declared = {a or b for a, b in declared}
    public = {n for n in dir(_native) if not n.startswith("_") or n == "__version__"}
    assert public == declared, (public - declared, declared - public)
    methods = {n for n in dir(_native.MassResult) if not n.startswith("_")}
    body = stub.split("class MassResult", 1)[1].split("\ndef ", 1)[0]
    assert methods == set(re.findall(r"def (\w+)", body)) - {"__init__"}
    assert (Path(il.__file__).parent / "py.typed").exists()
    assert inspect.signature(il.mass_properties).parameters["check"].default is True
