"""The one-machine batch: ``measure_files`` measures a folder, a glob or a list of files into a
folder of Parquet shards, resumably.

Workers are threads: each native call releases the GIL and runs on one thread, so ``workers``
threads keep ``workers`` cores busy with no process to start and nothing to pickle. A shard is
written to a temporary name and renamed, so a killed run leaves only whole shards; a run
started again skips the files whose ``id`` (the SHA-256 of their bytes) a shard already has.
"""

from __future__ import annotations

import glob
import os
import sys
import time
import uuid
from concurrent.futures import FIRST_COMPLETED, ThreadPoolExecutor, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Union

from . import _native
from ._api import Method, Repairs, _threads
from ._table import _pyarrow, measure_table

#: The extensions a folder is searched for: every mesh format the native readers take, and body
#: files (from the native module's table, the one the app's dialogs use).
MESH_EXTENSIONS: tuple[str, ...] = _native.MESH_EXTENSIONS


@dataclass(frozen=True)
class Summary:
    """What a ``measure_files`` run did."""

    #: Files found.
    files: int
    #: Files skipped because a shard already has their id (``resume``).
    skipped: int
    #: Rows written by this run, by status.
    ok: int
    warn: int
    error: int
    #: Shards written by this run.
    shards: int
    #: Wall-clock seconds of this run.
    seconds: float
    #: Bytes of the files measured.
    bytes: int

    def __str__(self) -> str:
        rate = (self.ok + self.warn + self.error) / self.seconds if self.seconds > 0 else 0.0
        return (
            f"{self.files} files: {self.ok} ok, {self.warn} with warnings, {self.error} errors"
            f"{f', {self.skipped} already measured' if self.skipped else ''}; "
            f"{self.shards} shards in {self.seconds:.1f} s ({rate:.0f} files/s, "
            f"{self.bytes / 1e6 / max(self.seconds, 1e-9):.1f} MB/s)"
        )


def mesh_files(paths_or_glob: Union[str, os.PathLike[str], Iterable[Union[str, os.PathLike[str]]]]) -> list[str]:
    """The files of a folder (searched for ``MESH_EXTENSIONS``: every mesh format, and .toml), a glob pattern (``**``
    recursive) or a list of paths, sorted for folders and globs, as given for lists."""
    if isinstance(paths_or_glob, (str, os.PathLike)):
        text = os.fspath(paths_or_glob)
        if os.path.isdir(text):
            return sorted(
                str(p) for p in Path(text).rglob("*") if p.is_file() and p.suffix.lower() in MESH_EXTENSIONS
            )
        if glob.has_magic(text):
            return sorted(p for p in glob.glob(text, recursive=True) if os.path.isfile(p))
        return [text]
    return [os.fspath(p) for p in paths_or_glob]


def _done_ids(out: Path) -> set[str]:
    _pyarrow()
    import pyarrow.parquet as pq

    done: set[str] = set()
    for shard in sorted(out.glob("part-*.parquet")):
        ids = pq.read_table(shard, columns=["id"]).column("id")
        done.update(i for i in ids.to_pylist() if i is not None)
    return done


def _progress(total: int, enabled: bool) -> Any:
    if not enabled:
        return None
    try:
        from tqdm import tqdm
    except ImportError:
        return None
    return tqdm(total=total, unit="file", file=sys.stderr)


def measure_files(
    paths_or_glob: Union[str, os.PathLike[str], Iterable[Union[str, os.PathLike[str]]]],
    out: Union[str, os.PathLike[str]],
    *,
    workers: Union[int, None] = None,
    progress: bool = True,
    resume: bool = True,
    shard_rows: int = 256,
    method: Method = "volume",
    repairs: Union[Repairs, dict[str, Any], None] = None,
) -> Summary:
    """Measures every file into the folder ``out`` as Parquet shards (``part-*.parquet``, each
    in ``batch_schema()``), one row per file whatever the file holds.

    ``workers``: threads measuring at once (default: the CPUs). ``shard_rows``: the most rows
    a shard holds (fewer when there are few files, so that every worker has work to the end).
    ``progress``: a tqdm bar on
    stderr (when tqdm is installed) and the summary printed at the end. ``resume``: skip the
    files whose id a shard in ``out`` has already; ``resume=False`` measures everything again
    (and the folder may then hold a file twice). Returns the ``Summary``.
    """
    pa = _pyarrow()
    import pyarrow.parquet as pq

    start = time.perf_counter()
    workers = _threads(workers) or os.cpu_count() or 1
    if shard_rows < 1:
        raise ValueError(f"shard_rows must be at least 1, not {shard_rows}")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    files = mesh_files(paths_or_glob)
    todo = files
    skipped = 0
    if resume and files:
        done = _done_ids(out)
        if done:
            ids = _native.file_ids(files, threads=workers)
            todo = [f for f, i in zip(files, ids) if i is None or i not in done]
            skipped = len(files) - len(todo)
    run = uuid.uuid4().hex[:8]
    counts = {"ok": 0, "warn": 0, "error": 0}
    measured_bytes = 0
    shards = 0
    bar = _progress(len(todo), progress)

    def shard(k: int, chunk: list[str]) -> Any:
        table = measure_table(pa.table({"path": chunk}), method=method, repairs=repairs, threads=1)
        name = out / f"part-{run}-{k:06d}.parquet"
        temporary = out / f".{name.name}.tmp"
        pq.write_table(table, temporary)
        os.replace(temporary, name)
        return table

    # One shard per task; at least four tasks per worker, so that none waits idle at the end.
    size = max(1, min(shard_rows, -(-len(todo) // (4 * workers))))
    chunks = [todo[i : i + size] for i in range(0, len(todo), size)]
    with ThreadPoolExecutor(max_workers=workers) as pool:
        pending = {pool.submit(shard, k, chunk): len(chunk) for k, chunk in enumerate(chunks)}
        while pending:
            finished, _ = wait(pending, return_when=FIRST_COMPLETED)
            for future in finished:
                n = pending.pop(future)
                table = future.result()
                shards += 1
                for status in table.column("status").to_pylist():
                    counts[status] += 1
                measured_bytes += sum(b or 0 for b in table.column("size_bytes").to_pylist())
                if bar is not None:
                    bar.update(n)
    if bar is not None:
        bar.close()
    summary = Summary(
        files=len(files),
        skipped=skipped,
        ok=counts["ok"],
        warn=counts["warn"],
        error=counts["error"],
        shards=shards,
        seconds=time.perf_counter() - start,
        bytes=measured_bytes,
    )
    if progress:
        print(summary, file=sys.stderr)
    return summary
