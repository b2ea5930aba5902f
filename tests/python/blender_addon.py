"""The Blender add-on (crates/py/blender/inertia_lab) under bpy: measures, shows, sets and bakes.

Usage: python3 blender_addon.py BODY.obj OPEN.obj (bpy and inertialab importable, the add-on's
folder on sys.path). BODY is imported (Blender's OBJ importer turns it +Z up), measured at
1000 kg/m³, and its tumble about its intermediate axis baked for 12 s at 24 fps; OPEN (a mesh
with a hole) is measured. Prints one JSON object on its last line: what the add-on left on each
object (mass, moments, warnings, the rigid body's mass, the principal-axes empty's world
matrix), and for each baked frame the object's world rotation (w x y z) and location, with
inertialab.simulate's own motion beside them, which the Rust test compares.
"""

import json
import sys

import bpy

import inertia_lab


def imported(path):
    bpy.ops.wm.obj_import(filepath=path)
    obj = bpy.context.selected_objects[0]
    bpy.context.view_layer.objects.active = obj
    return obj


def measured(obj):
    bpy.context.view_layer.objects.active = obj
    assert bpy.ops.inertialab.measure() == {"FINISHED"}
    empty = bpy.data.objects[f"{obj.name} principal axes"]
    bpy.context.view_layer.update()
    return {
        "mass": obj[inertia_lab.MASS],
        "centre": list(obj[inertia_lab.CENTRE]),
        "moments": list(obj[inertia_lab.MOMENTS]),
        "axes": list(obj[inertia_lab.AXES]),
        "warnings": obj[inertia_lab.WARNINGS].splitlines(),
        "rigid_body_mass": obj.rigid_body.mass,
        "empty": [list(r) for r in empty.matrix_world],
        "matrix_world": [list(r) for r in obj.matrix_world],
    }


def main() -> None:
    body_path, open_path = sys.argv[1], sys.argv[2]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    inertia_lab.register()
    scene = bpy.context.scene
    scene.render.fps = 24
    settings = scene.inertia_lab
    settings.density = 1000.0
    body = imported(body_path)
    out = {"version": bpy.app.version_string, "body": measured(body)}
    settings.spin_axis = "1"
    settings.spin_rate = 10.0
    settings.perturbation = 0.1
    settings.seconds = 12.0
    scene.frame_set(1)
    bpy.context.view_layer.objects.active = body
    assert bpy.ops.inertialab.bake_tumble() == {"FINISHED"}
    frames = []
    for k in range(1, 1 + 12 * 24 + 1):
        scene.frame_set(k)
        q = body.matrix_world.to_quaternion()
        frames.append({"rotation": list(q), "location": list(body.matrix_world.translation)})
    out["frames"] = frames
    out["kinematic"] = body.rigid_body.kinematic
    out["message"] = settings.message
    import inertialab as il
    from inertia_lab import bake, measure
    result = measure.measure(body, scene, 1000.0)
    motion = il.simulate(result, omega=tuple(bake.spin(1, 10.0, 0.1)), duration=12.0, fps=24,
                         integrator="exact")
    out["motion"] = {"orientation": motion.orientation.tolist(),
                     "translation": motion.translation.tolist()}
    for o in list(scene.objects):
        bpy.data.objects.remove(o)
    out["open"] = measured(imported(open_path))
    print(json.dumps(out))


if __name__ == "__main__":
    main()
