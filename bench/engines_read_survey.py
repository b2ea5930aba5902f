#!/usr/bin/env python3
"""Which robot descriptions an engine loads and `inertia-lab audit` refuses.

Usage: bench/engines_read_survey.py INERTIA_LAB_BINARY FOLDER...

Every URDF and MJCF file under the folders (unpacked wheels, say) is audited; each one refused
(exit 3) is then given to MuJoCo (`MjModel.from_xml_path`, URDF and MJCF) and to yourdfpy
(`URDF.load`, URDF), which must be importable. Prints each file an engine loads and we refuse,
with our message and the engine, and the counts: read, refused, refused by every engine too.
"""

import os
import subprocess
import sys


def descriptions(folders):
    for folder in folders:
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                path = os.path.join(root, name)
                if name.endswith(".urdf"):
                    yield path, "urdf"
                elif name.endswith(".xml"):
                    with open(path, "rb") as f:
                        if b"<mujoco" in f.read(4096):
                            yield path, "mjcf"


LOADERS = {
    "mujoco": "import mujoco, sys; mujoco.MjModel.from_xml_path(sys.argv[1])",
    "yourdfpy": "import yourdfpy, sys; yourdfpy.URDF.load(sys.argv[1], load_meshes=False, "
                "build_scene_graph=False, load_collision_meshes=False)",
}


def engine_loads(engine, path):
    try:
        out = subprocess.run([sys.executable, "-c", LOADERS[engine], path], capture_output=True,
                             timeout=120, cwd=os.path.dirname(path))
    except subprocess.TimeoutExpired:
        return False
    return out.returncode == 0


def main():
    binary, folders = sys.argv[1], sys.argv[2:]
    counts = {"read": 0, "refused": 0, "refused_by_engines_too": 0, "loaded_by_an_engine": 0}
    for path, kind in descriptions(folders):
        out = subprocess.run([binary, "audit", path, "--json"], capture_output=True, timeout=600)
        if out.returncode == 0:
            counts["read"] += 1
            continue
        counts["refused"] += 1
        ours = out.stderr.decode(errors="replace").strip().splitlines()
        engines = ["mujoco"] + (["yourdfpy"] if kind == "urdf" else [])
        loaded = [e for e in engines if engine_loads(e, path)]
        if loaded:
            counts["loaded_by_an_engine"] += 1
            print(f"{path}: {', '.join(loaded)} load(s) it; we say: {ours[-1] if ours else '?'}")
        else:
            counts["refused_by_engines_too"] += 1
            print(f"{path}: refused by {', '.join(engines)} too; we say: "
                  f"{ours[-1][:200] if ours else '?'}")
    print(counts)


if __name__ == "__main__":
    main()
