#!/usr/bin/env python3
"""`audit` over the SDFormat and xacro descriptions under some folders, SDFormat checked against
libsdformat itself.

Usage: bench/sdf_xacro_survey.py INERTIA_LAB_BINARY SDF_BODIES FOLDER...

SDF_BODIES is tests/consumers/sdf_bodies.cc compiled (the audit tests build it under
target/.../tmp/sdf_bodies). For every `.sdf` file: our audit (`--json`), and libsdformat's
reading of the same file; every link both read must have the same mass, centre, tensor and pose
(the largest difference is printed, relative to each value's largest entry). Then `--fix` and
libsdformat reading the fixed file: every link fixed must read back as our computed inertial.
For every `.xacro` file: our audit through the xacro tool (which must be on PATH), and the
reason for each one refused. Prints a line per file and the totals.
"""

import json
import os
import subprocess
import sys
import tempfile


def files(folders, ending):
    for folder in folders:
        for root, _, names in os.walk(folder):
            for name in sorted(names):
                if name.endswith(ending) and not name.startswith(".fixed-"):
                    yield os.path.join(root, name)


def run(args, env=None):
    out = subprocess.run(args, capture_output=True, timeout=600, env=env)
    return out.returncode, out.stdout.decode(errors="replace"), out.stderr.decode(errors="replace")


def flat(v):
    if isinstance(v, list):
        return [x for e in v for x in flat(e)]
    return [v]


def relative(a, b):
    a, b = flat(a), flat(b)
    scale = max(max(abs(x) for x in b), 1e-300)
    return max(abs(x - y) for x, y in zip(a, b)) / scale


def sdf(binary, reader, path, totals, out_dir):
    code, out, err = run([binary, "audit", path, "--json"])
    if code != 0:
        totals["sdf_refused"] += 1
        print(f"{path}: refused: {err.strip().splitlines()[-1] if err.strip() else code}")
        return
    report = json.loads(out)
    totals["sdf_read"] += 1
    totals["sdf_links"] += len(report["links"])
    code, theirs, err = run([reader, path])
    if code != 0:
        totals["libsdformat_refused"] += 1
        print(f"{path}: {len(report['links'])} links; libsdformat refuses it: "
              f"{err.strip().splitlines()[0] if err.strip() else code}")
        return
    theirs = json.loads(theirs)["bodies"]
    worst = 0.0
    compared = 0
    for link in report["links"]:
        b = theirs.get(link["name"])
        s = link["stated"]
        if b is None or s is None:
            continue
        compared += 1
        for ours, key in ((s["mass"], "mass"), (s["center_of_mass"], "com"),
                          (s["inertia"], "tensor"), (link["pose"]["position"], "position"),
                          (link["pose"]["rotation"], "rotation")):
            worst = max(worst, relative(ours, b[key]) if any(flat(b[key])) else
                        max(abs(x) for x in flat(ours)))
    totals["links_compared"] += compared
    totals["worst"] = max(totals["worst"], worst)
    flagged = [l["name"] for l in report["links"]
               if any(f["flags_inertial"] for f in l["findings"])]
    impossible = [l["name"] for l in report["links"]
                  if any(f.get("proof") for f in l["findings"])]
    totals["flagged"] += len(flagged)
    totals["impossible"] += len(impossible)
    fixed = os.path.join(os.path.dirname(path), ".fixed-" + os.path.basename(path))
    code, out, err = run([binary, "audit", path, "--json", "--fix", "-o", fixed])
    read_back = ""
    if code == 0 and flagged:
        fixed_report = json.loads(out)
        code, back, err = run([reader, fixed])
        if code != 0:
            totals["fix_refused_by_libsdformat"] += 1
            read_back = f"; libsdformat refuses the fix: {err.strip().splitlines()[0]}"
        else:
            back = json.loads(back)["bodies"]
            worst_fix = 0.0
            for name in fixed_report["fixed"]["links"]:
                c = next(l for l in fixed_report["links"] if l["name"] == name)["computed"]
                b = back[name]
                worst_fix = max(worst_fix, relative(c["mass"], b["mass"]),
                                relative(c["inertia"], b["tensor"]))
                totals["fixed"] += 1
            totals["worst_fix"] = max(totals["worst_fix"], worst_fix)
            read_back = (f"; fixed {len(fixed_report['fixed']['links'])}, read back to "
                         f"{worst_fix:.1e}")
    if os.path.exists(fixed):
        os.remove(fixed)
    print(f"{path}: {len(report['links'])} links, {compared} compared with libsdformat "
          f"(worst {worst:.1e}), {len(flagged)} flagged, {len(impossible)} impossible{read_back}")


def xacro(binary, path, totals):
    code, out, err = run([binary, "audit", path, "--json"])
    if code != 0:
        totals["xacro_refused"] += 1
        reason = err.strip().splitlines()[-1] if err.strip() else str(code)
        totals["xacro_reasons"][reason[:160]] = totals["xacro_reasons"].get(reason[:160], 0) + 1
        return
    report = json.loads(out)
    totals["xacro_read"] += 1
    totals["xacro_links"] += len(report["links"])
    totals["xacro_impossible"] += sum(
        1 for l in report["links"] if any(f.get("proof") for f in l["findings"]))


def main():
    binary, reader, folders = sys.argv[1], sys.argv[2], sys.argv[3:]
    totals = {"sdf_read": 0, "sdf_refused": 0, "sdf_links": 0, "libsdformat_refused": 0,
              "links_compared": 0, "worst": 0.0, "flagged": 0, "impossible": 0, "fixed": 0,
              "worst_fix": 0.0, "fix_refused_by_libsdformat": 0, "xacro_read": 0,
              "xacro_refused": 0, "xacro_links": 0, "xacro_impossible": 0, "xacro_reasons": {}}
    out_dir = tempfile.mkdtemp(prefix="sdf-survey-")
    for path in files(folders, ".sdf"):
        sdf(binary, reader, path, totals, out_dir)
    for path in files(folders, ".xacro"):
        xacro(binary, path, totals)
    print(json.dumps(totals, indent=1))


if __name__ == "__main__":
    main()
