"""Shared helpers of the package's tests: the repository's files, `props --json` of the binary
built by the same `cargo test`, named skips, and meshes made with numpy."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[3]
ASSETS = REPO / "assets"
REAL = REPO / "crates" / "massprops" / "tests" / "data" / "real"


def skip_or_fail(test: str, missing: str, install: str) -> None:
    """Skips with `SKIPPED <test>: <missing> (<install>)`, or fails under CI=true, where every
    test must really run."""
    message = f"SKIPPED {test}: {missing} ({install})"
    print(message)
    if os.environ.get("CI", "").strip() not in ("", "0", "false"):
        pytest.fail(message.replace("SKIPPED", "CI: not run", 1))
    pytest.skip(message)


def props_binary(test: str) -> str:
    binary = os.environ.get("INERTIA_LAB_BIN")
    if not binary or not os.path.exists(binary):
        skip_or_fail(
            test,
            "the inertia-lab binary (INERTIA_LAB_BIN is not set)",
            "run through `cargo test --workspace`, which sets it",
        )
    return binary


def props_json(test: str, path: Path, *args: str) -> dict:
    out = subprocess.run(
        [props_binary(test), "props", str(path), "--json", *args],
        check=True,
        capture_output=True,
        text=True,
    )
    return json.loads(out.stdout)


def torus(major: float, minor: float, around: int, tube: int) -> tuple[np.ndarray, np.ndarray]:
    """A faceted torus about z: `around` meridians of `tube`-gons of circumradius `minor` whose
    centres are `major` from the axis; triangles wound outward."""
    phi = 2 * np.pi * np.arange(around) / around
    theta = 2 * np.pi * np.arange(tube) / tube
    rho = major + minor * np.cos(theta)
    z = minor * np.sin(theta)
    v = np.empty((around, tube, 3))
    v[..., 0] = np.cos(phi)[:, None] * rho[None, :]
    v[..., 1] = np.sin(phi)[:, None] * rho[None, :]
    v[..., 2] = z[None, :]
    k, j = np.meshgrid(np.arange(around), np.arange(tube), indexing="ij")
    a = k * tube + j
    b = ((k + 1) % around) * tube + j
    c = ((k + 1) % around) * tube + (j + 1) % tube
    d = k * tube + (j + 1) % tube
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    return v.reshape(-1, 3), faces.astype(np.int64)


def torus_closed_form(major: float, minor: float, around: int, tube: int) -> tuple[float, float]:
    """Volume and I_zz (density 1) of `torus(...)` exactly, for an even `tube`.

    Between two meridians at angle a the solid is swept by the chords joining each point of the
    meridian polygon P to its copy: at height z its section is the difference of two isosceles
    triangles with apex on the axis, of area sin(a)/2 · rho² and polar moment
    sin(a)(2 + cos a)/12 · rho⁴. So V = around · sin a · ∫∫_P rho dA and
    I_zz = around · sin(a)(2 + cos a)/3 · ∫∫_P rho³ dA, with rho = major + u over the regular
    tube-gon: ∫∫ u dA = ∫∫ u³ dA = 0 (even tube), ∫∫ u² dA = A·minor²·(2 + cos b)/12.
    """
    a = 2 * np.pi / around
    b = 2 * np.pi / tube
    area = tube / 2 * minor**2 * np.sin(b)
    second = area * minor**2 * (2 + np.cos(b)) / 12
    volume = around * np.sin(a) * area * major
    izz = around * np.sin(a) * (2 + np.cos(a)) / 3 * (major**3 * area + 3 * major * second)
    return volume, izz


def box(size=(1.0, 2.0, 3.0), at=(0.0, 0.0, 0.0)) -> tuple[np.ndarray, np.ndarray]:
    """An axis-aligned box of `size` centred at `at`, 12 outward triangles."""
    s = np.asarray(size) / 2
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
    v = corners * s + np.asarray(at, dtype=float)
    f = np.array(
        [
            [0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
            [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3],
        ],
        dtype=np.int64,
    )
    return v, f
