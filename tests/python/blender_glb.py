"""Imports a GLB into Blender (`bpy`, Blender as a Python module) and prints where Blender puts
the body at every frame.

Usage: python3 blender_glb.py FILE.glb FPS. The scene's frame rate is set to FPS before the
import (Blender's glTF importer turns keyframe times into frames at the scene's rate). Prints one
JSON object: Blender's version; the mesh objects' names; the imported action's frame range; for
each frame from the first to the last the mesh object's world matrix (rows, column-vector
convention: p_world = M [p, 1], in Blender's +Z-up metres); and at the first frame the world
bounding box of its vertices, which the Rust test compares with the body's own.
"""

import json
import sys

import bpy


def main() -> None:
    path, fps = sys.argv[1], int(sys.argv[2])
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = fps
    scene.render.fps_base = 1.0
    bpy.ops.import_scene.gltf(filepath=path)
    meshes = [o for o in scene.objects if o.type == "MESH"]
    body = meshes[0]
    action = body.animation_data.action if body.animation_data else None
    first, last = (int(round(f)) for f in action.frame_range) if action else (0, 0)
    matrices = []
    for k in range(first, last + 1):
        scene.frame_set(k)
        matrices.append([[float(c) for c in row] for row in body.matrix_world])
    scene.frame_set(first)
    world = [body.matrix_world @ v.co for v in body.data.vertices]
    print(json.dumps({
        "version": bpy.app.version_string,
        "meshes": [o.name for o in meshes],
        "rotation_mode": body.rotation_mode,
        "frames": [first, last],
        "matrices": matrices,
        "box_min": [min(p[i] for p in world) for i in range(3)],
        "box_max": [max(p[i] for p in world) for i in range(3)],
    }))


if __name__ == "__main__":
    main()
