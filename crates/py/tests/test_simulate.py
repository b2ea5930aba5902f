"""`inertialab.simulate`: the keyframes against closed forms (a steady spin, the flip period
4K(k)/λ of Landau & Lifshitz §37) and the file against `inertia-lab simulate --animation`."""

import subprocess

import numpy as np
import pytest
from scipy.special import ellipk

import inertialab as il
from conftest import ASSETS, props_binary


def rotate(q, v):
    """The Hamilton quaternions q (n, 4: w, x, y, z) applied to the vector v."""
    w, u = q[:, :1], q[:, 1:]
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def flip_period(moments, omega):
    """4K(k)/λ for a spin about the intermediate axis (L² > 2E·I2 or below: the same formula with
    I1 and I3 swapped)."""
    i1, i2, i3 = moments
    l = np.asarray(moments) * np.asarray(omega)
    l2, e2 = float(l @ l), float(l @ np.asarray(omega))
    if l2 < e2 * i2:
        i1, i3 = i3, i1
    lam = np.sqrt((i3 - i2) * (l2 - e2 * i1) / (i1 * i2 * i3))
    m = (i2 - i1) * (e2 * i3 - l2) / ((i3 - i2) * (l2 - e2 * i1))
    return 4.0 * ellipk(m) / lam


def test_a_steady_spin_turns_steadily():
    m = il.simulate(inertia=(1.0, 2.0, 3.0), omega=(0.0, 0.0, 2.0), duration=3.0, fps=10,
                    integrator="exact")
    assert m.time.shape == (31,) and m.orientation.shape == (31, 4)
    np.testing.assert_allclose(m.time, np.arange(31) / 10, atol=1e-12)
    angle = 2.0 * m.time
    expected = np.stack([np.cos(angle / 2), 0 * angle, 0 * angle, np.sin(angle / 2)], axis=1)
    np.testing.assert_allclose(m.orientation, expected, atol=1e-12)
    np.testing.assert_allclose(m.position, 0.0, atol=1e-15)
    assert abs(m.l_change) < 1e-14 and abs(m.energy_change) < 1e-14
    assert m.moments == (1.0, 2.0, 3.0)


def test_the_racket_flips_at_the_closed_form_period():
    omega = (0.001, 10.0, 0.001)
    period = flip_period((1.0, 2.0, 3.0), omega)
    m = il.simulate(inertia=(1.0, 2.0, 3.0), omega=omega, duration=1.2 * period, fps=240)
    y = rotate(m.orientation, np.array([0.0, 1.0, 0.0]))[:, 1]
    at = lambda t: y[int(round(t * 240))]
    assert at(0.0) == pytest.approx(1.0)
    assert at(period / 2) < -0.9999 and at(period) > 0.9999
    # Between, the axis is perpendicular to where it began a quarter period after the start.
    first_crossing = m.time[np.argmax(y < 0)]
    assert abs(first_crossing - period / 4) < 0.05 * period


def test_a_mesh_is_placed_where_its_file_puts_it_and_spins_about_its_centre():
    m = il.simulate(ASSETS / "hammer.obj", omega=(0.0, 0.0, 1.0), duration=2.0, fps=5,
                    integrator="exact")
    com = il.analyze_file(ASSETS / "hammer.obj").center_of_mass
    np.testing.assert_allclose(m.position, np.tile(com, (len(m.time), 1)), atol=1e-15)
    np.testing.assert_allclose(m.translation[0], 0.0, atol=1e-15)
    # The centre of mass stays put: R·c + t = c at every frame.
    np.testing.assert_allclose(rotate(m.orientation, com) + m.translation,
                               np.tile(com, (len(m.time), 1)), atol=1e-14)


def test_the_file_is_the_command_lines(tmp_path):
    binary = props_binary("test_the_file_is_the_command_lines")
    for name in ("t.usda", "t.glb"):
        ours = tmp_path / f"py-{name}"
        theirs = tmp_path / f"cli-{name}"
        il.simulate(ASSETS / "t_handle.obj", duration=2.0, fps=24, animation=ours, up="z")
        subprocess.run(
            [binary, "simulate", "--mesh", str(ASSETS / "t_handle.obj"), "--duration", "2",
             "--fps", "24", "--up", "z", "--animation", str(theirs)],
            check=True, capture_output=True)
        assert ours.read_bytes() == theirs.read_bytes(), name


def test_bad_arguments_are_named(tmp_path):
    cases = [
        (dict(inertia=(3.0, 2.0, 1.0)), "ascending"),
        (dict(inertia=(1.0, 2.0, 3.0), fps=0.0), "fps"),
        (dict(inertia=(1.0, 2.0, 3.0), animation=tmp_path / "x.fbx"), ".glb"),
        (dict(inertia=(1.0, 2.0, 3.0), integrator="verlet"), "integrator"),
        (dict(inertia=(1.0, 2.0, 3.0), omega=(1.0, 2.0)), "omega"),
        (dict(), "one body"),
        (dict(inertia=(1.0, 2.0, 4.0)), "triangle"),
    ]
    for kwargs, words in cases:
        with pytest.raises(ValueError, match=words):
            il.simulate(**kwargs)


def test_a_computed_result_spins_as_its_file_does(tmp_path):
    from_file = il.simulate(ASSETS / "hammer.obj", duration=1.0, fps=10)
    from_result = il.simulate(il.analyze_file(ASSETS / "hammer.obj"), duration=1.0, fps=10)
    np.testing.assert_array_equal(from_result.orientation, from_file.orientation)
    np.testing.assert_array_equal(from_result.translation, from_file.translation)
    with pytest.raises(ValueError, match="has no mesh"):
        il.simulate(il.analyze_file(ASSETS / "hammer.obj"), animation=tmp_path / "h.glb")
