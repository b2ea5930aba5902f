"""Gives the static mesh MESH_NAME the body's exact mass properties, in the Unreal editor (5.1+).

Run it with the level open: Tools > Execute Python Script, or `py <this file>` in the Output
Log. It changes every placed StaticMeshComponent whose static mesh is MESH_NAME (of the
selected actors only, when actors are selected), in one transaction that Edit > Undo takes back.

Why a box: Unreal computes a body's mass, centre of mass and inertia from its simple collision
shapes at uniform density; BodyInstance has a mass override, a centre-of-mass nudge and a scale
of that computed inertia, but no field for a tensor. A solid box of mass m and edges a, b, c
has the principal moments m(b^2 + c^2)/12, m(a^2 + c^2)/12 and m(a^2 + b^2)/12, so every
physical body has an equivalent box: the one with its mass, centre, principal axes and
principal moments. This script adds that box to the mesh's simple collision with its collision
off and Contribute To Mass on, turns Contribute To Mass off on the mesh's other shapes (which
go on colliding as before), overrides each component's mass, and turns off what would change
the result (a centre-of-mass nudge, an inertia scale, inertia conditioning). Chaos then
computes the body's own centre, axes and moments, in its single precision.

Run it again after adding collision shapes or placing the mesh again: it replaces its box.
"""

import math

import unreal

BOX_NAME = "InertiaLab equivalent box"

# The mesh as Unreal imported it may differ from the body measured by this much of its size.
BOUNDS_TOLERANCE = 0.01

# The body, in Unreal's axes (left-handed, +Z up) and units (cm, kg, kg*cm^2), local to the mesh:
# its mass, centre of mass, principal moments about it, the rotation from the principal axes to
# the mesh's (a quaternion x, y, z, w), and the mesh's bounds.
#@BODY@


def equivalent_box_edges(mass, moments):
    """The edges (cm) of the solid box of `mass` whose principal moments are `moments`."""
    i1, i2, i3 = moments
    pairs = ((i2, i3, i1), (i1, i3, i2), (i1, i2, i3))
    # A flat body's box is flat (an edge 0); Chaos gives it a tiny thickness.
    return tuple(math.sqrt(max(6.0 * (a + b - c) / mass, 0.0)) for a, b, c in pairs)


def _size(lo, hi):
    return [hi[k] - lo[k] for k in range(3)]


def bounds_problem(mesh):
    """Why the mesh's bounds are not the body's (a sentence), or None when they agree."""
    box = mesh.get_bounding_box()
    lo = box.get_editor_property("min")
    hi = box.get_editor_property("max")
    got_lo, got_hi = (lo.x, lo.y, lo.z), (hi.x, hi.y, hi.z)
    want_lo, want_hi = BOUNDS_CM
    got, want = _size(got_lo, got_hi), _size(want_lo, want_hi)
    scale = max(want)
    off = max(
        max(abs(got_lo[k] - want_lo[k]), abs(got_hi[k] - want_hi[k])) for k in range(3)
    )
    if off <= BOUNDS_TOLERANCE * scale:
        return None
    ratios = [g / w for g, w in zip(got, want) if w > BOUNDS_TOLERANCE * scale]
    ratio = sum(ratios) / len(ratios)
    if ratio > 0 and all(abs(r / ratio - 1.0) <= BOUNDS_TOLERANCE for r in ratios):
        if abs(ratio - 1.0) > BOUNDS_TOLERANCE:
            return (
                "it was imported at %.6g times the body's size: reimport it with Uniform Scale "
                "%.6g (Unreal measures in cm)" % (ratio, 1.0 / ratio)
            )
    return (
        "its bounds (%s to %s cm) are not the body's (%s to %s cm): reimport it at the units "
        "and up axis the body was exported for, with no offset or rotation"
        % (_fmt(got_lo), _fmt(got_hi), _fmt(want_lo), _fmt(want_hi))
    )


def _fmt(v):
    return "(%s)" % ", ".join("%.6g" % c for c in v)


def mesh_problem(mesh):
    """Why the script cannot give `mesh` the body's mass properties (a sentence), or None."""
    body_setup = mesh.get_editor_property("body_setup")
    if body_setup is None:
        return "it has no collision (Body Setup): open it and add simple collision"
    flag = body_setup.get_editor_property("collision_trace_flag")
    if flag == unreal.CollisionTraceFlag.CTF_USE_COMPLEX_AS_SIMPLE:
        return (
            "its Collision Complexity is Use Complex Collision As Simple, which Unreal cannot "
            "simulate: set it to Project Default and give it simple collision"
        )
    return bounds_problem(mesh)


def _collides(shape):
    return shape.get_editor_property("collision_enabled") != unreal.CollisionEnabled.NO_COLLISION


def set_mass_shapes(mesh):
    """Adds (or replaces) the equivalent box on `mesh` and takes its other shapes out of the
    mass; returns how many shapes still collide."""
    body_setup = mesh.get_editor_property("body_setup")
    body_setup.modify()
    geometry = body_setup.get_editor_property("agg_geom")
    colliding = 0
    for kind in ("sphere_elems", "sphyl_elems", "convex_elems", "tapered_capsule_elems"):
        shapes = geometry.get_editor_property(kind)
        for shape in shapes:
            shape.set_editor_property("contribute_to_mass", False)
            colliding += _collides(shape)
        geometry.set_editor_property(kind, shapes)
    boxes = [
        b
        for b in geometry.get_editor_property("box_elems")
        if str(b.get_editor_property("name")) != BOX_NAME
    ]
    for shape in boxes:
        shape.set_editor_property("contribute_to_mass", False)
        colliding += _collides(shape)
    edges = equivalent_box_edges(MASS_KG, PRINCIPAL_MOMENTS_KG_CM2)
    x, y, z, w = PRINCIPAL_AXES_XYZW
    box = unreal.KBoxElem()
    box.set_editor_property("name", BOX_NAME)
    box.set_editor_property("center", unreal.Vector(*CENTER_OF_MASS_CM))
    box.set_editor_property("rotation", unreal.Quat(x, y, z, w).rotator())
    box.set_editor_property("x", edges[0])
    box.set_editor_property("y", edges[1])
    box.set_editor_property("z", edges[2])
    box.set_editor_property("collision_enabled", unreal.CollisionEnabled.NO_COLLISION)
    box.set_editor_property("contribute_to_mass", True)
    boxes.append(box)
    geometry.set_editor_property("box_elems", boxes)
    body_setup.set_editor_property("agg_geom", geometry)
    return colliding


def set_body(component):
    """Overrides the component's mass and clears what would change the computed inertia."""
    component.modify()
    body = component.get_editor_property("body_instance")
    body.set_editor_property("override_mass", True)
    body.set_editor_property("mass_in_kg_override", MASS_KG)
    body.set_editor_property("mass_scale", 1.0)
    body.set_editor_property("com_nudge", unreal.Vector(0.0, 0.0, 0.0))
    body.set_editor_property("inertia_tensor_scale", unreal.Vector(1.0, 1.0, 1.0))
    body.set_editor_property("inertia_conditioning", False)
    component.set_editor_property("body_instance", body)


def components():
    """The placed components showing MESH_NAME (the selected actors' when any are selected)."""
    actors = unreal.get_editor_subsystem(unreal.EditorActorSubsystem)
    chosen = actors.get_selected_level_actors() or actors.get_all_level_actors()
    found = []
    for actor in chosen:
        for component in actor.get_components_by_class(unreal.StaticMeshComponent):
            mesh = component.get_editor_property("static_mesh")
            if mesh is not None and mesh.get_name() == MESH_NAME:
                found.append(component)
    return found


def main():
    found = components()
    if not found:
        unreal.log_error(
            "Inertia Lab: no placed static mesh is %r (of the selected actors, if any are "
            "selected): import the mesh, place it, and run this script again" % MESH_NAME
        )
        return False
    meshes = {}
    for component in found:
        mesh = component.get_editor_property("static_mesh")
        meshes.setdefault(mesh.get_path_name(), mesh)
    # Every mesh is checked before anything changes.
    problems = [(path, mesh_problem(mesh)) for path, mesh in meshes.items()]
    problems = [(path, why) for path, why in problems if why is not None]
    for path, why in problems:
        unreal.log_error("Inertia Lab: %s not changed: %s" % (path, why))
    if problems:
        return False
    with unreal.ScopedEditorTransaction("Inertia Lab mass properties of %s" % MESH_NAME):
        for path, mesh in meshes.items():
            if set_mass_shapes(mesh) == 0:
                unreal.log_warning(
                    "Inertia Lab: %s has no colliding simple shape, so it falls through "
                    "everything: add one (Collision > Add Convex Collision); its mass "
                    "properties stay the body's" % path
                )
        for component in found:
            set_body(component)
            s = component.get_editor_property("relative_scale3d")
            if not s.x == s.y == s.z:
                unreal.log_warning(
                    "Inertia Lab: %s is scaled unevenly %s, and an unevenly scaled body has "
                    "other mass properties: scale it evenly"
                    % (component.get_path_name(), _fmt((s.x, s.y, s.z)))
                )
    unreal.log(
        "Inertia Lab: %s set to %.6g kg on %d component(s) of %d mesh(es)"
        % (MESH_NAME, MASS_KG, len(found), len(meshes))
    )
    return True


main()
