#!/usr/bin/env python3
"""Blender's own rigid-body simulation (Bullet) of a body spun about its intermediate axis,
beside the lab's exact tumble of the same body.

Usage: python3 bench/blender_bullet.py INERTIA_LAB_BINARY MESH.obj [--seconds S] [--tilt RAD]
(run with the python of a virtual environment that has bpy 5.0.1, Blender as a Python module).

The mesh (an OBJ in metres, +Y up; Blender's importer turns it +Z up) is given a rigid body in
a Blender scene with gravity and damping off and deactivation disabled, for each collision
shape (convex hull, mesh, box). Blender's rigid bodies have no initial angular velocity, so the
body is spun the way Blender users throw things: animated ("kinematic") for 10 frames at
10 rad/s about an axis `tilt` radians from its intermediate principal axis, then released to
Bullet at frame 11. Blender's scene runs at its defaults otherwise (24 fps, 10 substeps, 10
solver iterations). Over `seconds` the script counts the flips: the times the intermediate axis
turns past perpendicular to where it started.

The lab's side is `simulate --summary --mesh MESH` with the same spin, in the same principal
frame (the body's principal axes must be its mesh axes: the T-handle's are), the default
integrator at 1/240 s. Prints one table.
"""

import argparse
import json
import math
import subprocess
import sys

import bpy
from mathutils import Quaternion, Vector

FPS = 24
RELEASE = 11
OMEGA = 10.0


def blender(mesh: str, shape: str, seconds: float, tilt: float) -> dict:
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = FPS
    bpy.ops.wm.obj_import(filepath=mesh)
    body = [o for o in scene.objects if o.type == "MESH"][0]
    bpy.context.view_layer.objects.active = body
    body.select_set(True)
    bpy.ops.rigidbody.world_add()
    bpy.ops.rigidbody.object_add()
    rb = body.rigid_body
    rb.collision_shape = shape
    rb.mass = 1.0
    rb.linear_damping = 0.0
    rb.angular_damping = 0.0
    rb.use_deactivation = False
    world = scene.rigidbody_world
    world.effector_weights.gravity = 0.0
    frames = int(seconds * FPS)
    world.point_cache.frame_end = frames + RELEASE
    # The mesh's y (its intermediate axis) is Blender's z after the importer's turn; the spin
    # axis leans `tilt` from it towards Blender's x (the mesh's x, the minor axis).
    axis = Vector((math.sin(tilt), 0.0, math.cos(tilt)))
    body.rotation_mode = "QUATERNION"
    for f in range(1, RELEASE):
        body.rotation_quaternion = Quaternion(axis, OMEGA * (f - 1) / FPS)
        body.keyframe_insert("rotation_quaternion", frame=f)
        rb.kinematic = True
        rb.keyframe_insert("kinematic", frame=f)
    rb.kinematic = False
    rb.keyframe_insert("kinematic", frame=RELEASE)
    along = []
    previous = None
    turned = []
    for f in range(1, frames + RELEASE + 1):
        scene.frame_set(f)
        m = body.matrix_world.to_3x3()
        if f >= RELEASE:
            along.append(m.col[2].z)
            if previous is not None:
                turned.append((previous.inverted() @ m).to_quaternion().angle * FPS)
        previous = m.copy()
    flips = sum(1 for a, b in zip(along, along[1:]) if (a > 0) != (b > 0))
    return {
        "flips": flips,
        "least_alignment": min(along),
        "spin_after_release": turned[0] if turned else 0.0,
    }


def lab(binary: str, mesh: str, seconds: float, tilt: float) -> dict:
    omega = f"{OMEGA * math.sin(tilt)},{OMEGA * math.cos(tilt)},0"
    out = subprocess.run(
        [binary, "simulate", "--mesh", mesh, "--omega", omega, "--duration", str(seconds),
         "--summary"],
        check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("mesh")
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--tilt", type=float, default=0.01)
    args = parser.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else None)
    exact = lab(args.binary, args.mesh, args.seconds, args.tilt)
    print(f"{args.mesh}: spun at {OMEGA} rad/s, {args.tilt} rad from the intermediate axis, "
          f"{args.seconds} s")
    print(f"{'simulation':<34} {'flips':>6} {'flip period (s)':>16} {'least cos':>10}")
    period = exact["flip_period_predicted"]
    print(f"{'Inertia Lab (exact moments)':<34} {exact['flips']:>6} "
          f"{period if period else float('nan'):>16.3f} {'':>10}")
    for shape in ("CONVEX_HULL", "MESH", "BOX"):
        b = blender(args.mesh, shape, args.seconds, args.tilt)
        print(f"{'Blender ' + bpy.app.version_string + ' Bullet, ' + shape.lower():<34} "
              f"{b['flips']:>6} {'':>16} {b['least_alignment']:>10.6f}"
              f"   (spin after release {b['spin_after_release']:.3f} rad/s)")


if __name__ == "__main__":
    main()
