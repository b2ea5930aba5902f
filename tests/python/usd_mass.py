"""Opens an exported USD stage with Pixar's usd-core and prints what UsdPhysics reads.

Usage: python3 usd_mass.py FILE.usda. FILE holds the output of `inertia-lab export ...
--format usd`. The script prints one JSON object: usd-core's version; the stage's metersPerUnit,
kilogramsPerUnit and upAxis; the default prim's RigidBodyAPI and MassAPI (mass, centerOfMass,
diagonalInertia, principalAxes as w x y z, each as the schema's single-precision attribute and
as the double-precision inertialab: attribute beside it); and its Mesh child's volume and centre
of volume (the divergence theorem over its triangles, in stage units), which the Rust test
compares with the mesh's own.
"""

import json
import sys

from pxr import Usd, UsdGeom, UsdPhysics


def vec(v):
    return [float(c) for c in v]


def quat(q):
    return [float(q.GetReal())] + vec(q.GetImaginary())


def main() -> None:
    stage = Usd.Stage.Open(sys.argv[1])
    prim = stage.GetDefaultPrim()
    if not prim.HasAPI(UsdPhysics.RigidBodyAPI) or not prim.HasAPI(UsdPhysics.MassAPI):
        raise SystemExit("the default prim has no RigidBodyAPI or MassAPI")
    mass = UsdPhysics.MassAPI(prim)
    meshes = [c for c in prim.GetChildren() if c.IsA(UsdGeom.Mesh)]
    if len(meshes) != 1 or not meshes[0].HasAPI(UsdPhysics.CollisionAPI):
        raise SystemExit("expected one Mesh child with CollisionAPI")
    mesh = UsdGeom.Mesh(meshes[0])
    points = mesh.GetPointsAttr().Get()
    counts = mesh.GetFaceVertexCountsAttr().Get()
    indices = mesh.GetFaceVertexIndicesAttr().Get()
    volume = 0.0
    moment = [0.0, 0.0, 0.0]
    k = 0
    for n in counts:
        a = points[indices[k]]
        for j in range(1, n - 1):
            b = points[indices[k + j]]
            c = points[indices[k + j + 1]]
            v = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                 + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
            volume += v
            for i in range(3):
                moment[i] += v * (a[i] + b[i] + c[i]) / 4.0
        k += n
    attr = lambda name: prim.GetAttribute(name).Get()
    print(json.dumps({
        "version": ".".join(str(v) for v in Usd.GetVersion()),
        "meters_per_unit": UsdGeom.GetStageMetersPerUnit(stage),
        "kilograms_per_unit": UsdPhysics.GetStageKilogramsPerUnit(stage),
        "up_axis": UsdGeom.GetStageUpAxis(stage),
        "mass": float(mass.GetMassAttr().Get()),
        "center_of_mass": vec(mass.GetCenterOfMassAttr().Get()),
        "diagonal_inertia": vec(mass.GetDiagonalInertiaAttr().Get()),
        "principal_axes": quat(mass.GetPrincipalAxesAttr().Get()),
        "double": {
            "mass": float(attr("inertialab:mass")),
            "center_of_mass": vec(attr("inertialab:centerOfMass")),
            "diagonal_inertia": vec(attr("inertialab:diagonalInertia")),
            "principal_axes": quat(attr("inertialab:principalAxes")),
        },
        "volume": volume,
        "centre_of_volume": [m / volume for m in moment],
    }))


if __name__ == "__main__":
    main()
