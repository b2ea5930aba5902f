#!/usr/bin/env python3
"""Big meshes end to end, side by side in one run: `inertia-lab props` (this build and, if
given, an older binary) and trimesh (load + mass_properties) on the same files, runs
alternating, medians and ranges printed as a Markdown table.

    python3 bench/big_meshes.py --runs 5 --before OLD_BINARY --python VENV/bin/python \
        dragon.obj dragon.stl dragon-ascii.stl dragon-5m.obj

Each `props` run is a fresh process with `--timings` (its stages: read + parse + weld, and the
full analysis, each timed alone by the binary); wall time and peak resident memory come from
the operating system (wait4). trimesh runs in its own process too, timed inside it (load and
mass properties, the numbers a user of it waits for) and as a whole process.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import time

TIMINGS = re.compile(
    r"read\+parse\+weld ([0-9.]+) ms.*full analysis \(.*\) ([0-9.]+) ms"
)

TRIMESH = """
import sys, time
t = time.perf_counter()
import trimesh
m = trimesh.load(sys.argv[1], force="mesh")
load = time.perf_counter() - t
p = m.mass_properties
total = time.perf_counter() - t
print(f"{load * 1e3:.1f} {total * 1e3:.1f} {p['mass']:.12g}")
"""


def run_measured(argv):
    """Runs a process; returns (wall seconds, its own peak resident MB, stdout, stderr)."""
    start = time.perf_counter()
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    # Read the pipes to the end, then reap with wait4 for this child's rusage.
    out = proc.stdout.read()
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{argv[0]} failed on {argv[-1]}: {err.strip()[:300]}")
    return wall, usage.ru_maxrss / 1024.0, out, err


def props(binary, path):
    wall, rss, _, err = run_measured([binary, "props", "--timings", path])
    m = TIMINGS.search(err)
    if not m:
        sys.exit(f"no timings from {binary}: {err[-300:]}")
    # --timings runs the stages again after the report: the wall time covers both.
    return {"read": float(m.group(1)), "analysis": float(m.group(2)), "rss": rss, "wall": wall}


def props_plain(binary, path):
    wall, rss, _, _ = run_measured([binary, "props", path])
    return {"wall": wall * 1e3, "rss": rss}


def trimesh(python, path):
    wall, rss, out, _ = run_measured([python, "-c", TRIMESH, path])
    load, total, _mass = out.split()
    return {"load": float(load), "total": float(total), "wall": wall * 1e3, "rss": rss}


def med(values):
    return statistics.median(values)


def span(values, digits=0):
    f = f"{{:.{digits}f}}"
    return f"{f.format(med(values))} ({f.format(min(values))}–{f.format(max(values))})"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("files", nargs="+")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--after", default="target/release/inertia-lab")
    ap.add_argument("--before", help="an older inertia-lab binary to compare with")
    ap.add_argument("--python", help="a Python with trimesh installed")
    args = ap.parse_args()
    rows = []
    for path in args.files:
        size = os.path.getsize(path) / 1e6
        samples = {k: [] for k in ("after", "after_t", "before", "before_t", "trimesh")}
        for _ in range(args.runs):
            # Alternating, so a slow minute of the machine falls on every contender alike.
            samples["after"].append(props_plain(args.after, path))
            samples["after_t"].append(props(args.after, path))
            if args.before:
                samples["before"].append(props_plain(args.before, path))
                samples["before_t"].append(props(args.before, path))
            if args.python:
                samples["trimesh"].append(trimesh(args.python, path))
        rows.append((path, size, samples))
    print("| file | MB | | read + parse + weld ms | full analysis ms | `props` end to end ms | peak MB |")
    print("|---|---|---|---|---|---|---|")
    for path, size, s in rows:
        name = os.path.basename(path)
        for label, plain, timed in (("this build", "after", "after_t"), ("before", "before", "before_t")):
            if not s[plain]:
                continue
            read = [x["read"] for x in s[timed]]
            analysis = [x["analysis"] for x in s[timed]]
            wall = [x["wall"] for x in s[plain]]
            rss = [x["rss"] for x in s[plain]]
            print(f"| {name} | {size:.0f} | {label} | {span(read)} | {span(analysis)} | {span(wall)} | {med(rss):.0f} |")
        if s["trimesh"]:
            load = [x["load"] for x in s["trimesh"]]
            total = [x["total"] for x in s["trimesh"]]
            wall = [x["wall"] for x in s["trimesh"]]
            rss = [x["rss"] for x in s["trimesh"]]
            print(f"| {name} | {size:.0f} | trimesh | load {span(load)} | mass_properties {span([t - l for t, l in zip(total, load)])} | {span(total)} in process, {span(wall)} as a process | {med(rss):.0f} |")
    print()
    print("Ratios of medians (end to end):")
    for path, size, s in rows:
        name = os.path.basename(path)
        after = med([x["wall"] for x in s["after"]])
        parts = []
        if s["before"]:
            parts.append(f"before ÷ this build {med([x['wall'] for x in s['before']]) / after:.1f}×")
        if s["trimesh"]:
            parts.append(f"trimesh in process ÷ this build {med([x['total'] for x in s['trimesh']]) / after:.1f}×")
            parts.append(f"trimesh as a process ÷ this build {med([x['wall'] for x in s['trimesh']]) / after:.1f}×")
        read_mb_s = size / (med([x["read"] for x in s["after_t"]]) / 1e3)
        parts.append(f"read + parse + weld {read_mb_s:.0f} MB/s")
        print(f"- {name}: " + ", ".join(parts))


if __name__ == "__main__":
    main()
