"""The motion baked: ``simulate`` spins a body from rest where its mesh lies with the lab's own
integrator and returns its keyframes as numpy arrays, writing the same ``.glb`` or ``.usda``
file as ``inertia-lab simulate --animation``."""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, Literal, Union

import numpy as np
import numpy.typing as npt

from . import _native
from ._api import Repairs, _repairs
from ._native import MassResult

PathLike = Union[str, "os.PathLike[str]"]
Integrator = Literal[
    "midpoint-cayley", "splitting", "rk4", "euler", "midpoint", "exact", "engine-style",
    "implicit-euler",
]


@dataclass(frozen=True)
class Motion:
    """A body's motion, one keyframe a frame (n frames), in the mesh's frame: at frame 0 the mesh
    lies where its file puts it.

    - ``time`` (n,): seconds, frame k at k / ``fps``;
    - ``position`` (n, 3): the centre of mass, in the mesh's axes and unit;
    - ``orientation`` (n, 4): Hamilton quaternions (w, x, y, z) taking the mesh's axes to the
      world's, consecutive ones in one hemisphere;
    - ``translation`` (n, 3): where the mesh's origin is, so that a mesh point p is at
      ``R(orientation) @ p + translation`` (the node transform the files carry);
    - ``dt``: the step the simulation ran at (shortened from the one asked for when that did not
      divide a frame); ``moments``: the principal moments, ascending;
    - ``l_change``, ``energy_change``: the relative change of |L| and of the energy from the first
      frame to the last.
    """

    time: npt.NDArray[np.float64]
    position: npt.NDArray[np.float64]
    orientation: npt.NDArray[np.float64]
    translation: npt.NDArray[np.float64]
    fps: float
    dt: float
    moments: tuple[float, float, float]
    l_change: float
    energy_change: float


def _triple(name: str, value: Any) -> tuple[float, float, float]:
    try:
        a, b, c = (float(v) for v in value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be three numbers, not {value!r}") from None
    return a, b, c


def simulate(
    body: Union[PathLike, MassResult, None] = None,
    *,
    inertia: Union[tuple[float, float, float], None] = None,
    density: Union[float, None] = None,
    mass: Union[float, None] = None,
    omega: tuple[float, float, float] = (0.001, 10.0, 0.001),
    duration: float = 10.0,
    fps: float = 30.0,
    dt: float = 1.0 / 240.0,
    integrator: Integrator = "midpoint-cayley",
    model: Literal["full", "textbook"] = "full",
    animation: Union[PathLike, None] = None,
    units: str = "m",
    up: Literal["y", "z"] = "y",
    repairs: Union[Repairs, dict[str, Any], None] = None,
) -> Motion:
    """Spins a body from rest and samples its motion ``fps`` times a second for ``duration``
    seconds, as ``inertia-lab simulate --animation`` does.

    The body is a mesh or body file (weighed as ``analyze_file`` weighs it: ``density`` or
    ``mass``), a ``MassResult`` already computed (``mass_properties`` of arrays, say) or, with
    ``inertia``, the box of those principal moments (ascending) at ``mass`` (default 1). ``omega`` is the angular velocity at the start in the principal frame
    (moments ascending), rad/s; ``integrator`` and ``model`` are ``simulate``'s. Each keyframe is
    a state of the simulation (``exact``: the elliptic solution itself).

    With ``animation`` (a ``.glb`` or ``.usda`` path) the motion is also written there with the
    body's mesh (a file's, or the box's: a ``MassResult`` has none), the mesh's coordinates taken to be in ``units`` with ``up`` up (the file's axes:
    +Y up for glTF, +Z for USD).

    Raises ``ValueError`` for arguments out of range (and ``inertialab.MeshError`` for a file
    that gives no body, as ``analyze_file``).
    """
    result = body if isinstance(body, MassResult) else None
    path = None if body is None or result is not None else os.fspath(body)
    out = _native.simulate_motion(
        path,
        result,
        None if inertia is None else _triple("inertia", inertia),
        None if density is None else float(density),
        None if mass is None else float(mass),
        _triple("omega", omega),
        float(duration),
        float(fps),
        float(dt),
        integrator,
        model,
        None if animation is None else os.fspath(animation),
        units,
        up,
        _repairs(repairs),
    )
    return Motion(**out)
