"""The exact tumble of a Blender object baked into its keyframes, from ``inertialab.simulate``.

The motion is simulated in the object's metric local frame (``measure.py``) from rest where the
object is at the current frame, and keyed on the object at every frame of the scene's rate: at
frame k the object's rotation is R0·q(k) and its location l0 + R0·t(k) (t(k) in Blender units),
where R0 and l0 are its own at the start and q, t the motion's node transform. Its scale is
kept. The keys are linear: between frames Blender interpolates, at frames it shows the
simulation's states. An object with a rigid body is made "Animated" (kinematic), so that
Bullet follows the baked motion instead of simulating the object again.
"""

from __future__ import annotations

import bpy
import numpy as np
from mathutils import Quaternion, Vector

import inertialab as il

from .measure import metres_per_unit


def spin(axis: int, rate: float, perturbation: float) -> np.ndarray:
    """ω (rad/s, principal frame): `rate` about principal axis `axis` (0, 1, 2, moments
    ascending) and `perturbation` × `rate` about the other two."""
    omega = np.full(3, perturbation * rate)
    omega[axis] = rate
    return omega


def bake_tumble(obj, scene, result: il.MassResult, omega, seconds: float,
                integrator: str = "exact") -> il.Motion:
    """Keys `obj`'s motion for `seconds` from the scene's current frame; returns the motion."""
    render = scene.render
    fps = render.fps / render.fps_base
    motion = il.simulate(result, omega=tuple(float(w) for w in omega), duration=seconds,
                         fps=fps, integrator=integrator)
    unit = metres_per_unit(scene)
    start = scene.frame_current
    location, rotation, _ = obj.matrix_basis.decompose()
    obj.rotation_mode = "QUATERNION"
    if obj.rigid_body is not None:
        obj.rigid_body.kinematic = True
    edit = bpy.context.preferences.edit
    before = edit.keyframe_new_interpolation_type
    edit.keyframe_new_interpolation_type = "LINEAR"
    try:
        for k, (q, t) in enumerate(zip(motion.orientation, motion.translation)):
            obj.rotation_quaternion = rotation @ Quaternion(q.tolist())
            obj.location = location + rotation @ Vector((t / unit).tolist())
            obj.keyframe_insert("rotation_quaternion", frame=start + k)
            obj.keyframe_insert("location", frame=start + k)
    finally:
        edit.keyframe_new_interpolation_type = before
    return motion
