"""Closed forms: the numbers the package gives are the bodies' own, to 1e-12."""

import numpy as np
import pytest

import inertialab as il
from conftest import box, torus, torus_closed_form


def rel(a, b):
    return np.max(np.abs(np.asarray(a) - np.asarray(b))) / max(np.max(np.abs(np.asarray(b))), 1e-300)


@pytest.mark.parametrize("check", [True, False])
def test_box(check):
    a, b, c = 1.0, 2.0, 3.0
    v, f = box((a, b, c), at=(0.5, -0.25, 2.0))
    r = il.mass_properties(v, f, density=7.0, check=check)
    m = 7.0 * a * b * c
    assert rel(r.mass, m) < 1e-12
    assert rel(r.volume, a * b * c) < 1e-12
    assert rel(r.center_of_mass, [0.5, -0.25, 2.0]) < 1e-12
    expected = np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12])
    assert rel(r.inertia, expected) < 1e-12
    assert rel(r.principal_moments, np.sort(np.diag(expected))) < 1e-12
    assert r.checked is check
    assert r.warnings == ([] if check else None)


@pytest.mark.parametrize("check", [True, False])
def test_tetrahedron(check):
    # The corner tetrahedron of the unit cube: V = 1/6, COM = (1/4, 1/4, 1/4), and about the
    # origin ∫x² = 1/60, ∫xy = 1/120 (Tonon 2004); moved to the COM by the parallel-axis rule.
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    r = il.mass_properties(v, f, check=check)
    V = 1 / 6
    c = np.full(3, 0.25)
    second = np.full((3, 3), 1 / 120) + np.eye(3) * (1 / 60 - 1 / 120)  # ∫ x_i x_j about the origin
    about_origin = np.eye(3) * np.trace(second) - second
    expected = about_origin - V * (np.eye(3) * (c @ c) - np.outer(c, c))
    assert rel(r.mass, V) < 1e-12
    assert rel(r.center_of_mass, c) < 1e-12
    assert rel(r.inertia, expected) < 1e-12
    # Its off-diagonals are +V/80: the tensor's off-diagonals are -∑ m·x·y about the COM.
    assert rel(r.inertia[0, 1], V / 80) < 1e-12


@pytest.mark.parametrize("check", [True, False])
def test_refined_torus(check):
    R, r, n, m = 1.5, 0.4, 256, 64
    v, f = torus(R, r, n, m)
    res = il.mass_properties(v, f, check=check)
    volume, izz = torus_closed_form(R, r, n, m)
    assert rel(res.volume, volume) < 1e-12
    assert rel(res.inertia[2, 2], izz) < 1e-12
    assert np.max(np.abs(res.center_of_mass)) < 1e-12
    assert rel(res.inertia[0, 0], res.inertia[1, 1]) < 1e-12
    # And near the smooth torus: 2π²Rr².
    assert abs(res.volume / (2 * np.pi**2 * R * r * r) - 1) < 2e-3


def test_far_from_the_origin():
    v, f = box((1.0, 1.0, 1.0), at=(1e6, -1e6, 1e6))
    for check in (True, False):
        r = il.mass_properties(v, f, check=check)
        assert rel(r.mass, 1.0) < 1e-12
        assert rel(r.center_of_mass, [1e6, -1e6, 1e6]) < 1e-12
        assert rel(r.inertia, np.eye(3) / 6) < 1e-12


def test_reversed_winding():
    v, f = torus(1.0, 0.3, 64, 32)
    outward = il.mass_properties(v, f)
    inward = il.mass_properties(v, f[:, ::-1])
    assert rel(inward.mass, outward.mass) < 1e-15
    assert rel(inward.inertia, outward.inertia) < 1e-14
    assert [w["code"] for w in inward.warnings] == ["flipped"]
    assert outward.warnings == []
    unchecked = il.mass_properties(v, f[:, ::-1], check=False)
    assert rel(unchecked.inertia, outward.inertia) < 1e-14
    assert unchecked.to_dict()["flipped"] is True


def test_mass_instead_of_density():
    v, f = box((1.0, 2.0, 3.0))
    r = il.mass_properties(v, f, mass=12.0)
    assert rel(r.mass, 12.0) < 1e-15 and rel(r.density, 2.0) < 1e-15
    with pytest.raises(ValueError, match="not both"):
        il.mass_properties(v, f, mass=1.0, density=1.0)


def test_shell_method():
    # The thin-walled unit cube of mass 6: about its centre I = 5/18 · m · a² = 5/3 per axis.
    v, f = box((1.0, 1.0, 1.0))
    r = il.mass_properties(v, f, mass=6.0, method="shell")
    assert rel(r.principal_moments, [5 / 3] * 3) < 1e-12
