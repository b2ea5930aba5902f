"""Measure a folder of meshes on Spark: ``DataFrame.mapInArrow`` with ``inertialab.measure_table``.

Inertia Lab has no scheduler of its own beyond ``measure_files``' threads: at dataset scale the
engine you already run does the scheduling. Here a local Spark (``local[N]``) gets a DataFrame
of the files' absolute paths in partitions; ``mapInArrow`` hands each partition's Arrow record
batches to ``measure_table`` (which reads each file itself, so on a cluster the files must be on
a filesystem every executor sees), and ``write.parquet`` writes the folder.

    python spark_batch.py MESHES OUT [--workers 2]

The rows are ``measure_files``' rows, in the columns of ``inertialab.batch_schema()`` (as Spark
types: double, bigint, boolean, string; Spark writes its own schema metadata, so the
``inertialab.batch_schema_version`` key is not in the files). Paths are given to Spark as plain
absolute paths: Spark's own ``binaryFile`` reader would name them ``file:/…``, which is not a
path ``measure_table`` can find a body file's meshes beside.

Needs ``pip install 'inertialab[batch]' pyspark`` and a Java runtime (Spark 4 wants Java 17 or
later); the Python workers are this interpreter (``PYSPARK_PYTHON``, when unset).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import Any, Iterator, Union

import inertialab
from inertialab import mesh_files


def measure_batches(batches: Iterator[Any]) -> Iterator[Any]:
    """``mapInArrow``'s function: the batch table of each record batch of paths, one thread (a
    Spark task has one core)."""
    for batch in batches:
        yield from inertialab.measure_table(batch, threads=1).to_batches()


def partitions(files: int, workers: int) -> int:
    """Partitions of at most 256 files and at least four a worker (as ``measure_files`` does)."""
    return max(1, min(files, max(4 * workers, -(-files // 256))))


def main(
    folder: Union[str, os.PathLike[str]],
    out: Union[str, os.PathLike[str]],
    workers: int = 2,
    files: Union[list[str], None] = None,
) -> int:
    """Measures the mesh files of ``folder`` (or the list ``files``) into Parquet files in the
    folder ``out`` on a local Spark of ``workers`` cores; returns the rows written
    (those of every Parquet file in ``out``: give a new or empty folder)."""
    import pyarrow.parquet as pq

    paths = [os.path.abspath(p) for p in (files if files is not None else mesh_files(folder))]
    out = Path(out)
    if not paths:
        out.mkdir(parents=True, exist_ok=True)
        return 0
    os.environ.setdefault("PYSPARK_PYTHON", sys.executable)
    from pyspark.sql import SparkSession
    from pyspark.sql.pandas.types import from_arrow_schema

    spark = (
        SparkSession.builder.master(f"local[{workers}]")
        .appName("inertialab")
        .config("spark.ui.enabled", "false")
        .config("spark.ui.showConsoleProgress", "false")
        # One record batch a partition: one native call a task.
        .config("spark.sql.execution.arrow.maxRecordsPerBatch", "1000000")
        .getOrCreate()
    )
    try:
        spark.sparkContext.setLogLevel("ERROR")
        if __name__ != "__main__":
            # Imported (a test, a notebook), this file is a module the Python workers cannot
            # import (run as a script, its functions travel by value): send it to them.
            spark.sparkContext.addPyFile(__file__)
        n = partitions(len(paths), workers)
        # Contiguous slices of the sorted list, as measure_files and the Dask example chunk it.
        frame = spark.createDataFrame([(p,) for p in paths], "path string").repartitionByRange(n, "path")
        measured = frame.mapInArrow(measure_batches, from_arrow_schema(inertialab.batch_schema()))
        measured.write.parquet(str(out))
    finally:
        spark.stop()
    return sum(pq.ParquetFile(p).metadata.num_rows for p in sorted(out.glob("*.parquet")))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="a folder of .obj, .stl and .toml files (searched recursively)")
    parser.add_argument("out", help="the folder the Parquet files are written to (must not exist)")
    parser.add_argument("--workers", type=int, default=2, help="Spark cores (default 2)")
    args = parser.parse_args()
    rows = main(args.folder, args.out, workers=args.workers)
    print(f"{rows} rows written to {args.out}", file=sys.stderr)
