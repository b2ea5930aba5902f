"""Loads a robot description and prints every body's mass properties as the loader reads them.

Usage: python3 robot_bodies.py mujoco|yourdfpy FILE.

mujoco: MJCF as it is; a URDF through MuJoCo's URDF importer, from a copy beside it with its
<visual> elements dropped, `package://` paths made relative, and static bodies kept apart
(fusestatic="false"). yourdfpy: a URDF with meshes not loaded. Prints one JSON object:
{"version", "bodies": {name: {"mass", "com" (body frame), "tensor" (3x3 about the centre of mass,
body axes), "iquat" (w x y z, MuJoCo only), "inertia" (principal, MuJoCo only)}}}.
"""

import json
import os
import re
import sys
import tempfile
import xml.etree.ElementTree as ET


def quat_matrix(w, x, y, z):
    n = (w * w + x * x + y * y + z * z) ** 0.5
    w, x, y, z = w / n, x / n, y / n, z / n
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def rotate(r, d):
    """R diag(d) R^T."""
    return [[sum(r[i][k] * d[k] * r[j][k] for k in range(3)) for j in range(3)] for i in range(3)]


def mujoco_bodies(path):
    import mujoco

    if path.endswith(".urdf"):
        tree = ET.parse(path)
        robot = tree.getroot()
        for link in robot.findall("link"):
            for visual in link.findall("visual"):
                link.remove(visual)
        for mesh in robot.iter("mesh"):
            name = mesh.get("filename", "")
            if name.startswith("package://"):
                rest = name[len("package://"):]
                # The package is the folder the URDF sits in or one above it.
                candidates = [rest, rest.split("/", 1)[-1]]
                here = os.path.dirname(os.path.abspath(path))
                mesh.set("filename", next((c for c in candidates if os.path.exists(os.path.join(here, c))), rest))
        extension = ET.SubElement(robot, "mujoco")
        ET.SubElement(extension, "compiler", fusestatic="false", strippath="false", discardvisual="true")
        fd, copy = tempfile.mkstemp(suffix=".urdf", dir=os.path.dirname(os.path.abspath(path)))
        os.close(fd)
        try:
            tree.write(copy)
            model = mujoco.MjModel.from_xml_path(copy)
        finally:
            os.remove(copy)
    else:
        model = mujoco.MjModel.from_xml_path(path)
    bodies = {}
    for b in range(1, model.nbody):
        name = model.body(b).name
        q = [float(v) for v in model.body_iquat[b]]
        d = [float(v) for v in model.body_inertia[b]]
        bodies[name] = {
            "mass": float(model.body_mass[b]),
            "com": [float(v) for v in model.body_ipos[b]],
            "iquat": q,
            "inertia": d,
            "tensor": rotate(quat_matrix(*q), d),
        }
    return {"version": mujoco.__version__, "bodies": bodies}


def yourdfpy_bodies(path):
    import yourdfpy

    robot = yourdfpy.URDF.load(path, load_meshes=False, build_scene_graph=False).robot
    bodies = {}
    for link in robot.links:
        if link.inertial is None:
            continue
        o = link.inertial.origin
        r = [[float(o[i][j]) for j in range(3)] for i in range(3)]
        i = [[float(v) for v in row] for row in link.inertial.inertia]
        tensor = [[sum(r[a][k] * i[k][l] * r[b][l] for k in range(3) for l in range(3)) for b in range(3)] for a in range(3)]
        bodies[link.name] = {
            "mass": float(link.inertial.mass),
            "com": [float(o[k][3]) for k in range(3)],
            "tensor": tensor,
        }
    return {"version": yourdfpy.__version__ if hasattr(yourdfpy, "__version__") else "?", "bodies": bodies}


def main():
    loader, path = sys.argv[1], sys.argv[2]
    result = mujoco_bodies(path) if loader == "mujoco" else yourdfpy_bodies(path)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
