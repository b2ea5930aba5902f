"""Types of the Rust extension module (crates/py/src); the Python modules beside it are the API."""

from typing import Any, Optional, Sequence

import numpy as np
import numpy.typing as npt

SCHEMA_VERSION: int
BATCH_SCHEMA_VERSION: int
MESH_EXTENSIONS: tuple[str, ...]
OVERLAP_BUDGET: int
__version__: str

class MeshError(ValueError):
    """The mesh or file gives no body; ``kind`` names why (the batch table's ``error_kind``)."""

    kind: str

class MassResult:
    """Mass properties of one body (mesh axes; the tensor about the centre of mass,
    off-diagonals -sum m*x*y)."""

    @property
    def mass(self) -> float: ...
    @property
    def volume(self) -> Optional[float]: ...
    @property
    def density(self) -> Optional[float]: ...
    @property
    def center_of_mass(self) -> npt.NDArray[np.float64]: ...
    @property
    def inertia(self) -> npt.NDArray[np.float64]: ...
    @property
    def inertia_origin(self) -> npt.NDArray[np.float64]: ...
    @property
    def principal_moments(self) -> npt.NDArray[np.float64]: ...
    @property
    def principal_axes(self) -> npt.NDArray[np.float64]: ...
    @property
    def principal_quaternion(self) -> npt.NDArray[np.float64]: ...
    @property
    def checked(self) -> bool: ...
    @property
    def warnings(self) -> Optional[list[dict[str, Any]]]: ...
    def to_dict(self) -> dict[str, Any]: ...
    def to_json(self) -> str: ...
    def export(
        self, format: str, *, units: str = "m", up: str = "y", frame: Optional[str] = None
    ) -> str: ...
    def to_mjcf(self, *, units: str = "m", up: str = "y", frame: Optional[str] = None) -> str: ...
    def to_urdf(self, *, units: str = "m", up: str = "y", frame: Optional[str] = None) -> str: ...

def analyze_arrays(
    vertices: npt.NDArray[np.float64],
    faces: npt.NDArray[Any],
    sizes: Optional[npt.NDArray[np.int64]],
    density: Optional[float],
    mass: Optional[float],
    method: str,
    repairs: tuple[str, float, str, float, int],
    check: bool,
    threads: Optional[int],
) -> MassResult: ...
def analyze_path(
    path: str,
    density: Optional[float],
    mass: Optional[float],
    method: str,
    repairs: tuple[str, float, str, float, int],
    threads: Optional[int],
) -> MassResult: ...
def audit_json(
    path: str,
    geometry: str,
    density: Optional[float],
    assumed_density: float,
    packages: Sequence[tuple[str, str]],
    masses_file: Optional[str],
    masses: Sequence[tuple[str, float, Optional[tuple[float, float, float]]]],
    max_moment_error: Optional[float],
    max_com_offset: Optional[float],
    nearest: bool,
    repairs: tuple[str, float, str, float, int],
    threads: Optional[int],
) -> str: ...
def simulate_motion(
    path: Optional[str],
    result: Optional[MassResult],
    inertia: Optional[tuple[float, float, float]],
    density: Optional[float],
    mass: Optional[float],
    omega: tuple[float, float, float],
    duration: float,
    fps: float,
    dt: float,
    integrator: str,
    model: str,
    animation: Optional[str],
    units: str,
    up: str,
    repairs: tuple[str, float, str, float, int],
) -> dict[str, Any]: ...
def measure_rows(
    paths: Sequence[str],
    contents: Optional[Sequence[Optional[bytes]]],
    densities: Optional[Sequence[Optional[float]]],
    method: str,
    repairs: tuple[str, float, str, float, int],
    threads: Optional[int],
) -> dict[str, list[Any]]: ...
def batch_schema() -> list[tuple[str, str]]: ...
def file_ids(paths: Sequence[str], threads: Optional[int] = None) -> list[Optional[str]]: ...
