"""Loads an exported MJCF <inertial> element in MuJoCo and prints what MuJoCo compiled.

Usage: python3 mujoco_inertial.py FILE. FILE holds the output of
`inertia-lab export ... --format mjcf`. It is placed in a free-floating body of a minimal model;
the script prints one JSON object with mujoco's version and the body's compiled mass, ipos,
iquat (w x y z) and principal inertia, which the Rust test turns back into a tensor.
"""

import json
import sys

import mujoco


def main() -> None:
    with open(sys.argv[1], encoding="utf-8") as f:
        inertial = f.read()
    xml = (
        "<mujoco><worldbody><body name='b'><freejoint/>"
        + inertial
        + "</body></worldbody></mujoco>"
    )
    model = mujoco.MjModel.from_xml_string(xml)
    body = model.body("b").id
    print(
        json.dumps(
            {
                "version": mujoco.__version__,
                "mass": float(model.body_mass[body]),
                "ipos": [float(v) for v in model.body_ipos[body]],
                "iquat": [float(v) for v in model.body_iquat[body]],
                "inertia": [float(v) for v in model.body_inertia[body]],
            }
        )
    )


if __name__ == "__main__":
    main()
