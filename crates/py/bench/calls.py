"""Benchmark of the package's calls against trimesh, side by side in one run; prints a markdown
table (docs/python.md's figures). Not a test: run it by hand, on an idle machine.

    python crates/py/bench/calls.py [--files FOLDER] [--runs 5]

1. ``mass_properties`` on a 1M-triangle numpy mesh (a faceted torus, int64 and uint32 faces),
   without and with the checks, against trimesh's ``mass_properties`` on the same arrays (a fresh
   ``Trimesh(process=False)`` each run, so that nothing is cached);
2. a 12-triangle cube, microseconds per call from Python;
3. ``measure_files`` with 2 workers over a folder of real meshes, with the full defect analysis
   and with no shell comparison (``overlap_budget=0``, trimesh's work), against a trimesh loop
   (``trimesh.load`` + ``mass_properties``) in a ``multiprocessing.Pool(2)``.
Each measurement alternates with its rival; the figure is the median (and range) of the runs.
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import statistics
import sys
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np

import inertialab as il

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from conftest import box, torus  # noqa: E402


def median_range(xs):
    return statistics.median(xs), min(xs), max(xs)


def fmt(xs, unit="ms", scale=1e3):
    m, lo, hi = median_range([x * scale for x in xs])
    return f"{m:,.2f} {unit} ({lo:,.2f}–{hi:,.2f})"


def trimesh_mass(v, f):
    import trimesh

    mesh = trimesh.Trimesh(v, f, process=False)
    start = time.perf_counter()
    mesh.mass_properties
    return time.perf_counter() - start


def timed(call):
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


def big_mesh(runs):
    v, f = torus(1.0, 0.3, 1000, 500)
    n = len(f)
    f32 = f.astype(np.uint32)
    cases = {
        "inertialab check=False, uint32 faces": lambda: il.mass_properties(v, f32, check=False),
        "inertialab check=False, int64 faces": lambda: il.mass_properties(v, f, check=False),
        "inertialab check=True (full analysis)": lambda: il.mass_properties(v, f),
    }
    times = {k: [] for k in cases}
    times["trimesh mass_properties"] = []
    for _ in range(runs):
        for k, call in cases.items():
            times[k].append(timed(call))
            times["trimesh mass_properties"].append(trimesh_mass(v, f))
    trimesh_median = statistics.median(times["trimesh mass_properties"])
    rows = []
    for k, xs in times.items():
        m = statistics.median(xs)
        ratio = "" if k.startswith("trimesh") else f"{trimesh_median / m:,.1f}×"
        rows.append((k, fmt(xs), f"{n / m / 1e6:,.1f}", ratio))
    return n, rows


def small_mesh():
    v, f = box((1.0, 1.0, 1.0))
    rows = []
    for check in (False, True):
        number = 20000 if not check else 2000
        per = [
            t / number
            for t in timeit.repeat(lambda: il.mass_properties(v, f, check=check), number=number, repeat=7)
        ]
        rows.append((f"cube, check={check}", fmt(per, "µs", 1e6)))
    return rows


def _trimesh_one(path):
    import trimesh

    try:
        m = trimesh.load(path, force="mesh")
        p = m.mass_properties
        return p["mass"]
    except Exception:
        return None


def trimesh_files(files, workers):
    with multiprocessing.get_context("fork").Pool(workers) as pool:
        return pool.map(_trimesh_one, files, chunksize=8)


def folder(files_dir, runs, workers=2):
    files = il.mesh_files(files_dir)
    mb = sum(os.path.getsize(p) for p in files) / 1e6
    budgets = {
        f"inertialab measure_files, {workers} workers": il.Repairs(),
        f"inertialab measure_files, {workers} workers, overlap_budget=0": il.Repairs(overlap_budget=0),
    }
    ours = {k: [] for k in budgets}
    theirs = []
    for _ in range(runs):
        for k, repairs in budgets.items():
            with tempfile.TemporaryDirectory() as out:
                ours[k].append(
                    timed(lambda: il.measure_files(files, out, workers=workers, progress=False, repairs=repairs))
                )
            theirs.append(timed(lambda: trimesh_files(files, workers)))
    m_theirs = statistics.median(theirs)
    rows = []
    for k, xs in ours.items():
        m = statistics.median(xs)
        rows.append((k, fmt(xs, "s", 1), f"{len(files) / m:,.0f}", f"{mb / m:,.1f}", f"{m_theirs / m:,.1f}×"))
    rows.append(
        (f"trimesh load + mass_properties, Pool({workers})", fmt(theirs, "s", 1), f"{len(files) / m_theirs:,.0f}", f"{mb / m_theirs:,.1f}", "")
    )
    return len(files), mb, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--files", default="/tmp/survey/pb", help="a folder of real OBJ/STL meshes")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--skip-files", action="store_true")
    args = parser.parse_args()
    print(f"inertialab {il.__version__}, numpy {np.__version__}, {os.cpu_count()} CPUs, {args.runs} runs, medians (range)\n")
    n, rows = big_mesh(args.runs)
    print(f"| {n:,}-triangle numpy mesh | time | M triangles/s | vs trimesh |\n|---|---|---|---|")
    for r in rows:
        print("| " + " | ".join(r) + " |")
    print("\n| 12 triangles | per call |\n|---|---|")
    for r in small_mesh():
        print("| " + " | ".join(r) + " |")
    if not args.skip_files and os.path.isdir(args.files):
        count, mb, rows = folder(args.files, max(1, args.runs // 2))
        print(f"\n| {count:,} files, {mb:,.0f} MB ({args.files}) | time | files/s | MB/s | vs trimesh |\n|---|---|---|---|---|")
        for r in rows:
            print("| " + " | ".join(r) + " |")


if __name__ == "__main__":
    main()
