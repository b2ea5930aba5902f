"""Measure a folder of meshes on Ray Data: ``read_binary_files`` → ``measure_table`` →
``write_parquet``.

Inertia Lab has no scheduler of its own beyond ``measure_files``' threads: at dataset scale the
engine you already run does the scheduling. Ray reads each file's bytes (``bytes`` and ``path``
columns), ``map_batches`` hands each block to ``inertialab.measure_table`` as a pyarrow table
with ``bytes_col="bytes"`` (no second read of the file), and the batch tables are written as
Parquet.

    python ray_batch.py MESHES OUT [--cpus 2] [--blocks N]

The rows are ``measure_files``' rows, in the columns of ``inertialab.batch_schema()``. Ray's
``path`` column is the path as it was given (``file://`` stripped, a relative path left
relative), so the paths are made absolute first: the output's ``path`` is then the file's
absolute path, and a body file (``.toml``) given as bytes still finds the meshes it names
beside it, whatever the worker's working directory.

Needs ``pip install 'inertialab[batch]' 'ray[data]'``.
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
from pathlib import Path
from typing import Union

import inertialab
from inertialab import mesh_files


def blocks(files: int, cpus: int) -> int:
    """Read tasks: blocks of at most 256 files and at least four a CPU (as ``measure_files``
    does), so that no worker waits idle at the end."""
    return max(1, min(files, max(4 * cpus, -(-files // 256))))


def init(workers: int = 2) -> None:
    """Starts a local Ray of ``workers`` CPUs, quietly: no dashboard, no worker logs in this
    console, no Ray Data progress bars or INFO lines (its log file in the session folder still
    has them)."""
    import ray
    import ray.data

    ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False, logging_level=logging.WARNING)
    context = ray.data.DataContext.get_current()
    context.enable_progress_bars = False
    context.print_on_execution_start = False
    for handler in logging.getLogger("ray.data").handlers:
        if not isinstance(handler, logging.FileHandler) and type(handler).__name__ != "SessionFileHandler":
            handler.setLevel(logging.WARNING)
    # Its one message is a warning that the progress bars are off.
    logging.getLogger("ray.data._internal.progress").setLevel(logging.ERROR)


def main(
    folder: Union[str, os.PathLike[str]],
    out: Union[str, os.PathLike[str]],
    workers: int = 2,
    num_blocks: Union[int, None] = None,
    files: Union[list[str], None] = None,
) -> int:
    """Measures the mesh files of ``folder`` (or the list ``files``) into Parquet files in the
    folder ``out`` on a local Ray of ``workers`` CPUs (one task a CPU, one thread a task);
    returns the rows written (those of every Parquet file in ``out``: give a new or empty
    folder). A Ray already started (``init``, ``ray.init``) is used as it is and left running;
    else one is started and shut down at the end, error or not."""
    import pyarrow.parquet as pq
    import ray
    import ray.data

    paths = [os.path.abspath(p) for p in (files if files is not None else mesh_files(folder))]
    out = Path(out)
    if not paths:
        out.mkdir(parents=True, exist_ok=True)
        return 0
    started = not ray.is_initialized()
    if started:
        init(workers)
    try:
        dataset = ray.data.read_binary_files(
            paths,
            include_paths=True,
            override_num_blocks=num_blocks or blocks(len(paths), workers),
        )
        measured = dataset.map_batches(
            inertialab.measure_table,
            batch_format="pyarrow",
            batch_size=None,  # the whole block: one native call a read task
            fn_kwargs={"bytes_col": "bytes", "threads": 1},
            # One CPU a task on a Ray of `workers` CPUs: `workers` tasks at once. No `compute`
            # (or `concurrency`) pool: that would stop Ray fusing read, measure and write into
            # one task, and the bytes would go through the object store.
            num_cpus=1,
        )
        measured.write_parquet(str(out))
    finally:
        if started:
            ray.shutdown()
    return sum(pq.ParquetFile(p).metadata.num_rows for p in sorted(out.glob("*.parquet")))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="a folder of .obj, .stl and .toml files (searched recursively)")
    parser.add_argument("out", help="the folder the Parquet files are written to")
    parser.add_argument("--cpus", type=int, default=2, help="CPUs Ray may use (default 2)")
    parser.add_argument("--blocks", type=int, default=None, help="read tasks (default: automatic)")
    args = parser.parse_args()
    rows = main(args.folder, args.out, workers=args.cpus, num_blocks=args.blocks)
    print(f"{rows} rows written to {args.out}", file=sys.stderr)
