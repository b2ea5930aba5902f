"""Runs an exported Unreal editor script (export --format unreal-script) in a level of the
stand-in `unreal` module (tests/python/unreal_stub), and prints what it left.

Usage: python3 unreal_editor.py SCRIPT.py LEVEL.json. LEVEL describes the meshes (name, bounds
in cm as [[min], [max]], collision_trace_flag, how many colliding convex shapes) and the actors
(name, mesh, relative scale, selected), and how many times to run the script. Prints one JSON
object: the log, the transactions, each mesh's box and other shapes, and each component's body
instance.
"""

import json
import os
import runpy
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "unreal_stub"))

import unreal  # noqa: E402  (the stand-in, from the path above)


def level(spec):
    meshes = {}
    for m in spec["meshes"]:
        geometry = unreal.KAggregateGeom()
        geometry.set_editor_property(
            "convex_elems", [unreal.KConvexElem(name="hull") for _ in range(m.get("convex", 1))]
        )
        body_setup = unreal.BodySetup(
            m["name"] + "_BodySetup",
            agg_geom=geometry,
            collision_trace_flag=unreal.CollisionTraceFlag[m.get("trace", "CTF_USE_DEFAULT")],
        )
        meshes[m["name"]] = unreal.StaticMesh(m["name"], m["bounds"], body_setup=body_setup)
    actors = unreal.get_editor_subsystem(unreal.EditorActorSubsystem)
    components = {}
    for a in spec["actors"]:
        component = unreal.StaticMeshComponent(
            a["name"] + ".StaticMeshComponent0",
            static_mesh=meshes[a["mesh"]],
            relative_scale3d=unreal.Vector(*a.get("scale", [1.0, 1.0, 1.0])),
        )
        actor = unreal.Actor(a["name"], [component])
        actors.actors.append(actor)
        if a.get("selected"):
            actors.selected.append(actor)
        components[a["name"]] = component
    return meshes, components


def vector(v):
    return [v.x, v.y, v.z]


def shape(s):
    out = {
        "name": str(s.get_editor_property("name")),
        "collision": s.get_editor_property("collision_enabled").name,
        "contribute_to_mass": s.get_editor_property("contribute_to_mass"),
    }
    if isinstance(s, unreal.KBoxElem):
        out["center"] = vector(s.get_editor_property("center"))
        out["xyzw"] = list(s.get_editor_property("rotation").stub_quat)
        out["edges"] = [s.get_editor_property(k) for k in "xyz"]
    return out


def report(meshes, components):
    out = {"log": unreal.LOG, "transactions": unreal.TRANSACTIONS, "meshes": {}, "bodies": {}}
    for name, mesh in meshes.items():
        geometry = mesh.get_editor_property("body_setup").get_editor_property("agg_geom")
        out["meshes"][name] = {
            "boxes": [shape(b) for b in geometry.get_editor_property("box_elems")],
            "convex": [shape(c) for c in geometry.get_editor_property("convex_elems")],
        }
    for name, component in components.items():
        body = component.get_editor_property("body_instance")
        out["bodies"][name] = {
            k: (vector(v) if isinstance(v, unreal.Vector) else v)
            for k, v in ((k, body.get_editor_property(k)) for k in unreal.BodyInstance.PROPERTIES)
        }
    return out


def main():
    script, spec_path = sys.argv[1], sys.argv[2]
    with open(spec_path) as f:
        spec = json.load(f)
    meshes, components = level(spec)
    for _ in range(spec.get("runs", 1)):
        runpy.run_path(script, run_name="__main__")
    print(json.dumps(report(meshes, components)))


if __name__ == "__main__":
    main()
