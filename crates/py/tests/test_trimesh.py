"""Differential against trimesh (an independent implementation, Eberly's polyhedral mass
properties) on random closed meshes."""

import numpy as np
import pytest

import inertialab as il
from conftest import skip_or_fail


@pytest.fixture(scope="module")
def trimesh():
    try:
        import trimesh
    except ImportError:
        skip_or_fail("test_trimesh", "trimesh is not installed", "pip install trimesh")
    return trimesh


def random_meshes(trimesh, count=40):
    rng = np.random.default_rng(20261202)
    for k in range(count):
        kind = k % 3
        if kind == 0:  # the hull of random points, a random convex polyhedron
            m = trimesh.convex.convex_hull(rng.normal(size=(int(rng.integers(8, 200)), 3)) * rng.uniform(0.1, 10, 3))
        elif kind == 1:  # a sphere squashed and sheared
            m = trimesh.creation.icosphere(subdivisions=int(rng.integers(1, 4)))
            m.apply_transform(np.vstack([np.hstack([rng.normal(size=(3, 3)), np.zeros((3, 1))]), [0, 0, 0, 1]]))
        else:  # a torus (not convex, genus 1), turned and moved
            m = trimesh.creation.torus(major_radius=rng.uniform(1, 3), minor_radius=rng.uniform(0.1, 0.9))
        m.apply_transform(trimesh.transformations.random_rotation_matrix(rng.random(3)))
        m.apply_translation(rng.normal(size=3) * 100)
        yield m


def test_random_closed_meshes_agree_with_trimesh(trimesh):
    checked = 0
    for m in random_meshes(trimesh):
        if m.volume < 0:
            m.invert()
        density = 1.0 + 10 * np.random.default_rng(checked).random()
        m.density = density
        ours = il.mass_properties(m.vertices, m.faces, density=density)
        scale = np.abs(m.moment_inertia).max()
        assert abs(ours.mass - m.mass) < 1e-9 * m.mass
        assert np.allclose(ours.center_of_mass, m.center_mass, rtol=0, atol=1e-9 * np.abs(m.bounds).max())
        # trimesh's moment_inertia is about the centre of mass, off-diagonals -∑m·x·y, as ours.
        assert np.allclose(ours.inertia, m.moment_inertia, rtol=0, atol=1e-8 * scale)
        assert np.allclose(ours.principal_moments, np.sort(m.principal_inertia_components), rtol=0, atol=1e-8 * scale)
        assert [w["code"] for w in ours.warnings] == []
        unchecked = il.mass_properties(m.vertices, m.faces, density=density, check=False)
        assert np.allclose(unchecked.inertia, ours.inertia, rtol=0, atol=1e-12 * scale)
        checked += 1
    assert checked == 40


def test_files_trimesh_writes_read_as_its_meshes(trimesh, tmp_path):
    # trimesh as the writer (float32 GLB, binary PLY, OFF) and the reference: each file read
    # back gives trimesh's numbers for the mesh as written (its float32 positions for GLB).
    checked = 0
    for k, m in enumerate(random_meshes(trimesh, count=12)):
        if m.volume < 0:
            m.invert()
        for ext in ("glb", "ply", "off"):
            path = tmp_path / f"mesh{k}.{ext}"
            m.export(path)
            # The reference reads the file back itself (float32 for GLB, as written).
            ref = trimesh.load(path, force="mesh", process=False)
            ours = il.analyze_file(path)
            scale = np.abs(ref.moment_inertia).max()
            assert abs(ours.volume - ref.volume) < 1e-9 * ref.volume, (ext, ours.volume, ref.volume)
            assert np.allclose(ours.center_of_mass, ref.center_mass, rtol=0, atol=1e-9 * np.abs(ref.bounds).max())
            assert np.allclose(ours.inertia, ref.moment_inertia, rtol=0, atol=1e-8 * scale), ext
            checked += 1
    assert checked == 36
    # A scene of one mesh in two nodes, one turned and moved: two parts, each placed as
    # trimesh places it.
    box = trimesh.creation.box(extents=(1.0, 2.0, 3.0))
    scene = trimesh.Scene()
    scene.add_geometry(box, node_name="left", geom_name="box")
    turn = trimesh.transformations.rotation_matrix(0.3, (0, 0, 1))
    turn[:3, 3] = (5.0, 0.0, 0.0)
    scene.add_geometry(box, node_name="right", geom_name="box", transform=turn)
    path = tmp_path / "two.glb"
    scene.export(path)
    ours = il.analyze_file(path)
    ref = trimesh.load(path, force="mesh")
    assert abs(ours.volume - 12.0) < 1e-12
    assert np.allclose(ours.center_of_mass, ref.center_mass, rtol=0, atol=1e-9)
    assert np.allclose(ours.inertia, ref.moment_inertia, rtol=0, atol=1e-9 * np.abs(ref.moment_inertia).max())
