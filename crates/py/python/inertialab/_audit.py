"""Robot descriptions audited from Python: ``audit`` gives ``inertia-lab audit --json``'s object
as a dict, ``audit_table`` one Arrow row per link, for pipelines that audit descriptions by the
thousand (on the same engines as ``measure_table``)."""

from __future__ import annotations

import json
import os
from typing import Any, Literal, Mapping, Union

from . import _native
from ._api import Repairs, _repairs, _threads
from ._table import _pyarrow

PathLike = Union[str, "os.PathLike[str]"]
# A link's measured mass: kg, or (kg, (x, y, z) m in the link's frame).
MeasuredMass = Union[float, tuple[float, tuple[float, float, float]]]


def _masses(masses: Union[PathLike, Mapping[str, MeasuredMass], None]) -> tuple[Any, list]:
    if masses is None:
        return None, []
    if isinstance(masses, Mapping):
        entries = []
        for link, value in masses.items():
            if isinstance(value, (int, float)):
                entries.append((str(link), float(value), None))
            else:
                mass, center = value
                x, y, z = (float(c) for c in center)
                entries.append((str(link), float(mass), (x, y, z)))
        return None, entries
    return os.fspath(masses), []


def audit(
    path: PathLike,
    *,
    geometry: Literal["collision", "visual"] = "collision",
    density: Union[float, None] = None,
    assumed_density: float = 1000.0,
    packages: Union[Mapping[str, PathLike], None] = None,
    xacro_args: Union[Mapping[str, str], None] = None,
    masses: Union[PathLike, Mapping[str, MeasuredMass], None] = None,
    max_moment_error: Union[float, None] = None,
    max_com_offset: Union[float, None] = None,
    nearest: bool = False,
    repairs: Union[Repairs, dict[str, Any], None] = None,
    threads: Union[int, None] = None,
) -> dict:
    """Audits a URDF, MJCF or SDFormat file as ``inertia-lab audit --json`` does and returns its object
    (schema ``inertia-lab/audit``, docs/audit.md): each link's stated inertial beside the one
    its geometry gives, with findings (two of them proofs that the stated inertia is impossible).

    ``packages`` maps ``package://NAME`` (and ``model://NAME``, ``$(find NAME)``) to a folder;
    a xacro file is expanded by the ``xacro`` tool with ``xacro_args`` (``{name: value}``);
    ``masses`` is a CSV or TOML file, or a dict
    ``{link: kg}`` / ``{link: (kg, (x, y, z))}``, of measured masses; ``nearest=True`` adds each
    link's nearest valid inertial. Raises ``FileNotFoundError`` / ``OSError`` when the file
    cannot be read and ``ValueError`` when it is not a description that can be read.
    """
    masses_file, entries = _masses(masses)
    text = _native.audit_json(
        os.fspath(path),
        geometry,
        None if density is None else float(density),
        float(assumed_density),
        [(str(k), os.fspath(v)) for k, v in (packages or {}).items()],
        [(str(k), str(v)) for k, v in (xacro_args or {}).items()],
        masses_file,
        entries,
        None if max_moment_error is None else float(max_moment_error),
        None if max_com_offset is None else float(max_com_offset),
        bool(nearest),
        _repairs(repairs),
        _threads(threads),
    )
    return json.loads(text)


def _link_row(file: str, robot: str, link: dict) -> dict:
    findings = link["findings"]
    stated, computed, comparison = link["stated"], link["computed"], link["comparison"]
    nearest = link.get("nearest") or {}
    return {
        "file": file,
        "robot": robot,
        "link": link["name"],
        "parent": link["parent"],
        "moving": link["moving"],
        "stated_mass": stated and stated["mass"],
        "computed_mass": computed and computed["mass"],
        "density": computed and computed["density"],
        "basis": computed and computed["basis"],
        "com_offset": comparison and comparison["com_offset"],
        "tensor_error": comparison and comparison["tensor_error"],
        "findings": [f["code"] for f in findings],
        "flagged": any(f["flags_inertial"] for f in findings),
        "impossible": any(f.get("proof", False) for f in findings),
        "nearest_moved_fraction": nearest.get("moved_fraction"),
        "not_weighed": link["not_weighed"],
    }


def audit_table(paths: Union[PathLike, list], **options: Any):
    """``audit`` of each description in ``paths`` as one ``pyarrow.Table``, a row per link:
    file, robot, link, parent, moving, stated and computed mass, density, basis, centre offset
    (m), tensor error, finding codes, whether any finding flags the inertial, whether one
    proves it impossible, the nearest fix's move (with ``nearest=True``), and why a link was not
    weighed. ``options`` are ``audit``'s. A description that cannot be read raises."""
    pa = _pyarrow()
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    rows = []
    for path in paths:
        report = audit(path, **options)
        rows.extend(_link_row(report["file"], report["robot"], link) for link in report["links"])
    schema = pa.schema(
        [
            ("file", pa.string()),
            ("robot", pa.string()),
            ("link", pa.string()),
            ("parent", pa.string()),
            ("moving", pa.bool_()),
            ("stated_mass", pa.float64()),
            ("computed_mass", pa.float64()),
            ("density", pa.float64()),
            ("basis", pa.string()),
            ("com_offset", pa.float64()),
            ("tensor_error", pa.float64()),
            ("findings", pa.list_(pa.string())),
            ("flagged", pa.bool_()),
            ("impossible", pa.bool_()),
            ("nearest_moved_fraction", pa.float64()),
            ("not_weighed", pa.string()),
        ]
    )
    return pa.Table.from_pylist(rows, schema=schema)
