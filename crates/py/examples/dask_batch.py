"""Measure a folder of meshes on Dask: one ``inertialab.measure_table`` call per partition.

Inertia Lab has no scheduler of its own beyond ``measure_files``' threads: at dataset scale the
engine you already run does the scheduling. Here a ``dask.distributed.LocalCluster`` of worker
processes (one thread each) gets the file list in chunks; each partition is the batch table of
one chunk, and ``to_parquet`` writes the folder.

    python dask_batch.py MESHES OUT [--workers 2] [--chunk 64]

The rows are ``measure_files``' rows (the same code measures each file), in the columns of
``inertialab.batch_schema()``. The partitions are pandas frames of Arrow-backed dtypes
(``pd.ArrowDtype``), so the Parquet keeps the Arrow types exactly: a plain ``to_pandas()``
would turn an int64 column with nulls (``triangles`` of a body file) into float64 and a bool
column with nulls (``closed``) into object. Paths are made absolute before the workers see them
(a worker process need not share the driver's working directory; a body file's meshes are
found beside it).

Needs ``pip install 'inertialab[batch]' 'dask[dataframe,distributed]'``.
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
from pathlib import Path
from typing import Any, Union

import inertialab
from inertialab import mesh_files


def measure_chunk(paths: list[str]) -> Any:
    """The batch table of ``paths`` as a pandas frame of Arrow dtypes (one Dask partition).

    ``threads=1``: the worker process has one thread, and Dask runs one task per thread."""
    import pandas as pd
    import pyarrow as pa

    table = inertialab.measure_table(pa.table({"path": pa.array(paths, pa.string())}), threads=1)
    return table.to_pandas(types_mapper=pd.ArrowDtype)


def meta() -> Any:
    """The empty frame Dask is told each partition looks like (so it never runs a task to see)."""
    import pandas as pd

    return inertialab.batch_schema().empty_table().to_pandas(types_mapper=pd.ArrowDtype)


def chunks(files: list[str], workers: int, chunk: Union[int, None] = None) -> list[list[str]]:
    """The files in chunks of at most ``chunk`` (default: 256, and at least four chunks a worker,
    as ``measure_files`` does, so that no worker waits idle at the end)."""
    size = chunk or max(1, min(256, -(-len(files) // (4 * workers))))
    return [files[i : i + size] for i in range(0, len(files), size)]


def main(
    folder: Union[str, os.PathLike[str]],
    out: Union[str, os.PathLike[str]],
    workers: int = 2,
    chunk: Union[int, None] = None,
    files: Union[list[str], None] = None,
) -> int:
    """Measures the mesh files of ``folder`` (or the list ``files``) into Parquet files in the
    folder ``out`` on a local Dask cluster of ``workers`` processes; returns the rows written
    (those of every Parquet file in ``out``: give a new or empty folder)."""
    import dask
    import dask.dataframe as dd
    import pyarrow.parquet as pq
    from dask.distributed import Client, LocalCluster

    paths = [os.path.abspath(p) for p in (files if files is not None else mesh_files(folder))]
    out = Path(out)
    if not paths:
        # from_map needs at least one partition; an empty folder is an empty result.
        out.mkdir(parents=True, exist_ok=True)
        return 0
    # Dask's nanny starts each worker with MALLOC_TRIM_THRESHOLD_=65536 (to hand pandas' freed
    # memory back to the OS). Setting it turns off glibc's adaptive thresholds: every array over
    # 128 KiB is then a fresh mmap, page-faulted in again for each file, and the measuring is
    # 1.3-1.5x slower (a 6 s STL: 8-10 s). The batch frees its arrays after each file anyway.
    with dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}), LocalCluster(
        n_workers=workers,
        threads_per_worker=1,
        processes=True,
        dashboard_address=None,
        silence_logs=logging.ERROR,
    ) as cluster, Client(cluster) as client:
        if __name__ != "__main__":
            # Imported (a test, a notebook), this file is a module the workers cannot import
            # (run as a script, its functions travel by value): send it to them.
            client.upload_file(__file__)
        frame = dd.from_map(measure_chunk, chunks(paths, workers, chunk), meta=meta())
        frame.to_parquet(out, write_index=False, schema=inertialab.batch_schema())
    return sum(pq.ParquetFile(p).metadata.num_rows for p in sorted(out.glob("*.parquet")))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="a folder of .obj, .stl and .toml files (searched recursively)")
    parser.add_argument("out", help="the folder the Parquet files are written to")
    parser.add_argument("--workers", type=int, default=2, help="worker processes (default 2)")
    parser.add_argument("--chunk", type=int, default=None, help="files a partition (default: automatic)")
    args = parser.parse_args()
    rows = main(args.folder, args.out, workers=args.workers, chunk=args.chunk)
    print(f"{rows} rows written to {args.out}", file=sys.stderr)
