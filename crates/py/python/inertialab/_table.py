"""The batch table: ``measure_table`` takes an Arrow table of files and gives one row per row.

The columns are defined once, in Rust (``inertia_lab::batch``); ``BATCH_SCHEMA`` is their Arrow
schema, versioned by ``BATCH_SCHEMA_VERSION`` and documented in docs/python.md ("Batch table").
"""

from __future__ import annotations

from typing import Any, Union

from . import _native
from ._api import Method, Repairs, _repairs, _threads

_ARROW_TYPES = {"float64": "float64", "int64": "int64", "bool": "bool_", "string": "string"}


def _pyarrow() -> Any:
    try:
        import pyarrow
    except ImportError:
        raise ImportError(
            "measure_table and measure_files need pyarrow: pip install 'inertialab[batch]'"
        ) from None
    return pyarrow


def batch_schema() -> Any:
    """The Arrow schema of the batch table (``pyarrow.Schema``), with its version in the
    metadata (``inertialab.batch_schema_version``)."""
    pa = _pyarrow()
    fields = [pa.field(name, getattr(pa, _ARROW_TYPES[kind])()) for name, kind in _native.batch_schema()]
    return pa.schema(
        fields, metadata={"inertialab.batch_schema_version": str(_native.BATCH_SCHEMA_VERSION)}
    )


def _column(batch: Any, name: str) -> list[Any]:
    if name not in batch.schema.names:
        raise KeyError(f"the table has no column {name!r} (its columns: {', '.join(batch.schema.names)})")
    return batch.column(name).to_pylist()


def measure_table(
    batch: Any,
    *,
    path_col: str = "path",
    bytes_col: Union[str, None] = None,
    density_col: Union[str, None] = None,
    method: Method = "volume",
    repairs: Union[Repairs, dict[str, Any], None] = None,
    threads: Union[int, None] = None,
) -> Any:
    """One row of the batch table for each row of ``batch`` (a ``pyarrow.Table`` or
    ``RecordBatch``), in the same order, never raising for a row: a file that cannot be read or
    gives no body is a row with ``status`` ``"error"``, ``error_kind`` and ``error_message``.

    ``path_col``: the files' paths (their extension chooses the reader; a body file's meshes are
    found beside it). ``bytes_col``: the files' bytes when they have been read already (Ray's
    ``read_binary_files``); else each file is read from its path. ``density_col``: a density for
    each row (null: 1). Returns a ``pyarrow.Table`` in ``batch_schema()``.
    """
    pa = _pyarrow()
    if isinstance(batch, dict):
        batch = pa.table(batch)
    paths = _column(batch, path_col)
    contents = _column(batch, bytes_col) if bytes_col is not None else None
    densities = _column(batch, density_col) if density_col is not None else None
    if any(p is None for p in paths):
        raise ValueError(f"column {path_col!r} has a null path")
    columns = _native.measure_rows(
        [str(p) for p in paths],
        contents,
        None if densities is None else [None if d is None else float(d) for d in densities],
        method,
        _repairs(repairs),
        _threads(threads),
    )
    schema = batch_schema()
    return pa.table({f.name: pa.array(columns[f.name], type=f.type) for f in schema}, schema=schema)
