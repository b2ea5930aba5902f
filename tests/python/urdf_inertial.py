"""Loads an exported URDF <inertial> element with yourdfpy and prints what it read.

Usage: python3 urdf_inertial.py FILE. FILE holds the output of
`inertia-lab export ... --format urdf`. It is placed in the only link of a minimal robot; the
script prints one JSON object with yourdfpy's version, the mass, the 4x4 origin matrix (its
own reading of xyz/rpy) and the 3x3 inertia matrix it built from ixx..izz.
"""

import io
import json
import sys
from importlib.metadata import version

import yourdfpy


def main() -> None:
    with open(sys.argv[1], encoding="utf-8") as f:
        inertial = f.read()
    xml = '<robot name="exported"><link name="body">' + inertial + "</link></robot>"
    robot = yourdfpy.URDF.load(io.StringIO(xml), build_scene_graph=False, load_meshes=False)
    link = robot.link_map["body"]
    print(
        json.dumps(
            {
                "version": version("yourdfpy"),
                "mass": float(link.inertial.mass),
                "origin": link.inertial.origin.tolist(),
                "inertia": link.inertial.inertia.tolist(),
            }
        )
    )


if __name__ == "__main__":
    main()
