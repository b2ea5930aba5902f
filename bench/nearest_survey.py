#!/usr/bin/env python3
"""`audit --fix --fix-mode nearest` over a folder of robot descriptions, checked by a second audit.

Usage: bench/nearest_survey.py INERTIA_LAB_BINARY FOLDER... [--out DIR]

For every URDF and MJCF file under the folders (unpacked wheels, say), the audit writes the fix;
then the fixed file is audited again with `--fix-mode nearest`, and each link the fix changed must
have no finding that proves its inertial impossible and must be its own nearest valid inertial
(inside the set: pseudo-inertia, ellipsoid and per-axis bounds). Prints one line per robot and
a summary: links with an impossible inertial, links fixed, links left as stated (valid already), links the nearest could not fix and
why, and how far the fixed tensors moved (median and largest, as a fraction of the stated).
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile

IMPOSSIBLE = {"impossible_moment", "triangle_inequality", "not_positive_definite",
              "com_outside_geometry"}


def descriptions(folders):
    for folder in folders:
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                path = os.path.join(root, name)
                if name.endswith(".urdf"):
                    yield path
                elif name.endswith(".xml"):
                    with open(path, "rb") as f:
                        if b"<mujoco" in f.read(4096):
                            yield path


def audit(binary, args):
    out = subprocess.run([binary, "audit", *args, "--json"], capture_output=True, timeout=600)
    if out.returncode != 0:
        return None, out.stderr.decode(errors="replace")
    return json.loads(out.stdout), out.stderr.decode(errors="replace")


def main():
    args = sys.argv[1:]
    out_dir = tempfile.mkdtemp(prefix="nearest-")
    if "--out" in args:
        i = args.index("--out")
        out_dir = args[i + 1]
        del args[i:i + 2]
    binary, folders = args[0], args[1:]
    totals = {"robots": 0, "refused": 0, "impossible": 0, "fixed": 0,
              "left": 0, "not_fixed": 0, "still_impossible": 0, "not_own_nearest": 0}
    moved, held, reasons = [], {}, {}
    for n, path in enumerate(descriptions(folders)):
        # Beside the original, so that relative and package paths resolve the same.
        fixed = os.path.join(os.path.dirname(path), f".nearest-{n}-" + os.path.basename(path))
        report, stderr = audit(binary, [path, "--fix", "--fix-mode", "nearest", "-o", fixed])
        totals["robots"] += 1
        if report is None:
            totals["refused"] += 1
            continue
        changed = set(report.get("fixed", {}).get("links", []))
        # The links the fix chose (those flagged) are the changed ones and those it warns of.
        for line in stderr.splitlines():
            if " is left as stated" in line:
                totals["left"] += 1
            elif " is not fixed: " in line:
                totals["not_fixed"] += 1
                why = line.split(" is not fixed: ", 1)[1].split(" (")[0]
                reasons[why] = reasons.get(why, 0) + 1
        for link in report["links"]:
            if link["name"] in changed:
                totals["fixed"] += 1
                nearest = link["nearest"]
                moved.append(nearest["moved_fraction"])
                for h in nearest["held_by"]:
                    held[h["constraint"]] = held.get(h["constraint"], 0) + 1
            if {f["code"] for f in link["findings"]} & IMPOSSIBLE:
                totals["impossible"] += 1
        if changed:
            again, _ = audit(binary, [fixed, "--fix-mode", "nearest"])
            for link in again["links"]:
                if link["name"] not in changed:
                    continue
                if {f["code"] for f in link["findings"]} & IMPOSSIBLE:
                    totals["still_impossible"] += 1
                    print("  still impossible:", path, link["name"])
                if link["nearest"] is None or link["nearest"].get("held_by"):
                    totals["not_own_nearest"] += 1
                    print("  not its own nearest:", path, link["name"])
        if os.path.exists(fixed):
            os.remove(fixed)
        print(f"{path}: {len(report['links'])} links, {len(changed)} fixed")
    print(json.dumps(totals))
    if moved:
        print(f"moved (fraction of the stated tensor): median {statistics.median(moved):.3g}, "
              f"largest {max(moved):.3g}, over {len(moved)} links")
    print("held by:", json.dumps(held))
    print("not fixed:", json.dumps(reasons))


if __name__ == "__main__":
    main()
