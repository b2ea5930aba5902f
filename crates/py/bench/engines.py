"""What an engine costs: ``measure_files`` (threads) against the Dask and Ray examples on the
same files and the same number of cores, end to end (the engine started and stopped each run,
the Parquet written), runs alternating, the median and range printed as a Markdown table.

    python crates/py/bench/engines.py [FOLDER] [--limit N] [--runs 3] [--workers 2]
        [--engines measure_files,dask,ray]    (spark too, when pyspark and Java are there)

FOLDER defaults to /tmp/survey/pb (the meshes of the pybullet_data wheel). The goal is an
engine within 15 % of ``measure_files``: the work is the same native call on the same chunks,
so what is left is the engine's start, scheduling and transfers. Each run is followed by the
same engine on the smallest file alone, its fixed cost (start, one task, write, stop), and the
table gives the overhead with and without it. Not a test: it takes minutes.
"""

from __future__ import annotations

import argparse
import hashlib
import importlib.util
import os
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Callable

import inertialab
from inertialab import mesh_files

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def example(name: str) -> Any:
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def sha256(path: str) -> str:
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def runners(workers: int) -> dict[str, Callable[[list[str], Path], int]]:
    def files(paths: list[str], out: Path) -> int:
        return inertialab.measure_files(paths, out, workers=workers, progress=False, resume=False).files

    def dask(paths: list[str], out: Path) -> int:
        return example("dask_batch").main(None, out, workers=workers, files=paths)

    def ray(paths: list[str], out: Path) -> int:
        return example("ray_batch").main(None, out, workers=workers, files=paths)

    def spark(paths: list[str], out: Path) -> int:  # not by default: pyspark and Java
        return example("spark_batch").main(None, out, workers=workers, files=paths)

    return {"measure_files": files, "dask": dask, "ray": ray, "spark": spark}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", nargs="?", default="/tmp/survey/pb")
    parser.add_argument("--limit", type=int, default=None, help="the first N files only")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--workers", type=int, default=2, help="threads, Dask workers, Ray CPUs")
    parser.add_argument("--engines", default="measure_files,dask,ray")
    args = parser.parse_args()

    paths = [os.path.abspath(p) for p in mesh_files(args.folder)][: args.limit]
    if not paths:
        sys.exit(f"no .obj, .stl or .toml file in {args.folder}")
    megabytes = sum(os.path.getsize(p) for p in paths) / 1e6
    for p in paths:  # the page cache warm for every run alike
        with open(p, "rb") as f:
            while f.read(1 << 24):
                pass
    # The workers of Dask and Ray load the package afresh: a reinstall during the runs (a
    # `cargo test` elsewhere) would compare two builds.
    native = inertialab._native.__file__
    built = sha256(native)
    # An engine may change this process's environment for the processes started after it
    # (Dask's nanny does, in the process that runs it): printed at the end.
    environment = dict(os.environ)
    run = runners(args.workers)
    engines = args.engines.split(",")
    for e in engines:
        if e not in run:
            sys.exit(f"unknown engine {e!r} (known: {', '.join(run)})")
    # The fixed cost: the same run on the smallest file alone (start, one task, write, stop).
    smallest = [min(paths, key=os.path.getsize)]
    seconds: dict[str, list[float]] = {e: [] for e in engines}
    fixed: dict[str, list[float]] = {e: [] for e in engines}
    scratch = Path(tempfile.mkdtemp(prefix="inertialab-engines-"))

    def timed(e: str, files: list[str], out: Path) -> float:
        start = time.perf_counter()
        rows = run[e](files, out)
        took = time.perf_counter() - start
        if rows != len(files):
            sys.exit(f"{e}: {rows} rows for {len(files)} files")
        shutil.rmtree(out)
        return took

    try:
        for k in range(args.runs):
            for e in engines:
                seconds[e].append(timed(e, paths, scratch / f"{e}-{k}"))
                fixed[e].append(timed(e, smallest, scratch / f"{e}-{k}-one"))
                print(
                    f"run {k + 1}/{args.runs} {e}: {seconds[e][-1]:.2f} s, one file {fixed[e][-1]:.2f} s",
                    file=sys.stderr,
                    flush=True,
                )
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    changed = {k: v for k, v in os.environ.items() if environment.get(k) != v}
    if changed:
        print(f"(the engines set in this process: {changed})", file=sys.stderr)
    if sha256(native) != built:
        sys.exit(f"{native} changed during the runs: the timings compare two builds; run again")

    median = {e: statistics.median(seconds[e]) for e in engines}
    start = {e: statistics.median(fixed[e]) for e in engines}
    base = "measure_files" if "measure_files" in engines else None
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(
        f"\n{len(paths)} files, {megabytes:.1f} MB ({args.folder}"
        f"{f', first {args.limit}' if args.limit else ''}); {args.workers} workers, "
        f"{args.runs} runs each, alternating; {os.cpu_count()} CPUs, load {load:.1f} at the end\n"
    )
    print(
        "| engine | files | MB | median s (range) | files/s | MB/s | overhead vs measure_files "
        "| one file s (fixed cost) | overhead less the fixed cost |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for e in engines:
        m = median[e]
        over = less = "—"
        if base is not None and e != base:
            over = f"{(m / median[base] - 1) * 100:+.1f} %"
            less = f"{((m - start[e]) / (median[base] - start[base]) - 1) * 100:+.1f} %"
        print(
            f"| {e} | {len(paths)} | {megabytes:.1f} | {m:.2f} ({min(seconds[e]):.2f}–{max(seconds[e]):.2f}) "
            f"| {len(paths) / m:.1f} | {megabytes / m:.2f} | {over} | {start[e]:.2f} | {less} |"
        )

if __name__ == "__main__":
    main()
