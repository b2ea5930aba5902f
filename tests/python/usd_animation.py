"""Opens a baked animation (`inertia-lab simulate ... --animation FILE.usda`) with Pixar's usd-core
and prints where USD puts the body at every time code.

Usage: python3 usd_animation.py FILE.usda. Prints one JSON object: the stage's
timeCodesPerSecond, startTimeCode, endTimeCode and upAxis; whether the default prim is a
kinematic rigid body; and for each time code from start to end the default prim's local-to-world
matrix as USD computes it from its time-sampled xformOps (rows, USD's row-vector convention:
p_world = [p, 1] * M), which the Rust test compares with the lab's own states.
"""

import json
import sys

from pxr import Usd, UsdGeom, UsdPhysics


def main() -> None:
    stage = Usd.Stage.Open(sys.argv[1])
    prim = stage.GetDefaultPrim()
    body = UsdPhysics.RigidBodyAPI(prim)
    xformable = UsdGeom.Xformable(prim)
    start, end = int(stage.GetStartTimeCode()), int(stage.GetEndTimeCode())
    matrices = []
    for k in range(start, end + 1):
        m = xformable.ComputeLocalToWorldTransform(Usd.TimeCode(k))
        matrices.append([[float(m[r][c]) for c in range(4)] for r in range(4)])
    print(json.dumps({
        "time_codes_per_second": stage.GetTimeCodesPerSecond(),
        "start": start,
        "end": end,
        "up_axis": UsdGeom.GetStageUpAxis(stage),
        "kinematic": bool(body.GetKinematicEnabledAttr().Get()),
        "op_order": [op.GetOpName() for op in xformable.GetOrderedXformOps()],
        "matrices": matrices,
    }))


if __name__ == "__main__":
    main()
