"""Inertia Lab for Blender: the exact mass properties of the selected mesh object, its principal
axes shown, its rigid body's mass set, and its exact tumble baked into keyframes (Blender's own
rigid bodies never flip: see the repository's README).

Built on the ``inertialab`` Python package (``measure.py``, ``bake.py``); this module holds
Blender's side only: the settings on the scene, three operators and the panel in the 3D view's
sidebar (N), tab "Inertia Lab". Installation and use: README.md beside this file.
"""

from __future__ import annotations

import bpy
import numpy as np
from bpy.props import EnumProperty, FloatProperty, PointerProperty, StringProperty
from mathutils import Matrix, Vector

from . import bake, measure

bl_info = {
    "name": "Inertia Lab",
    "description": "Exact mass properties of a mesh, and its exact tumble baked into keyframes",
    "author": "Inertia Lab",
    "version": (0, 1, 0),
    "blender": (4, 2, 0),
    "location": "View3D > Sidebar > Inertia Lab",
    "category": "Physics",
}

# What the Measure operator leaves on the object (custom properties, SI units, metric local
# frame): read back by the panel, the Bake operator and scripts.
MASS = "inertialab_mass"
CENTRE = "inertialab_center_of_mass"
MOMENTS = "inertialab_principal_moments"
AXES = "inertialab_principal_axes"
WARNINGS = "inertialab_warnings"


class InertiaLabSettings(bpy.types.PropertyGroup):
    """The scene's Inertia Lab settings."""

    density: FloatProperty(name="Density", description="Density of the solid, kg/m³",
                           default=1000.0, min=1e-9, soft_max=25000.0)
    spin_axis: EnumProperty(
        name="Spin axis",
        description="The principal axis the body is spun about (moments ascending)",
        items=[("0", "Axis 1 (least moment)", ""),
               ("1", "Axis 2 (intermediate: the flip)", ""),
               ("2", "Axis 3 (greatest moment)", "")],
        default="1",
    )
    spin_rate: FloatProperty(name="Spin rate", description="rad/s about the spin axis",
                             default=10.0, soft_min=-100.0, soft_max=100.0)
    perturbation: FloatProperty(
        name="Perturbation",
        description="Spin about the other two axes, as a fraction of the spin rate",
        default=0.01, min=0.0, soft_max=0.5)
    seconds: FloatProperty(name="Seconds", description="How long to bake", default=10.0,
                           min=0.01, soft_max=600.0)
    message: StringProperty(name="Message", default="")


def _selected_mesh(context):
    obj = context.active_object
    return obj if obj is not None and obj.type == "MESH" else None


def _on_selected(operator, context, work):
    """Runs `work(context, obj, settings)` on the selected mesh object, its words (or its
    error, a ``ValueError`` naming the problem) on the panel's message line."""
    obj = _selected_mesh(context)
    settings = context.scene.inertia_lab
    if obj is None:
        operator.report({"ERROR"}, "Select a mesh object")
        return {"CANCELLED"}
    try:
        settings.message = work(context, obj, settings)
    except ValueError as e:
        settings.message = f"{obj.name}: {e}"
        operator.report({"ERROR"}, settings.message)
        return {"CANCELLED"}
    return {"FINISHED"}


def _principal_empty(obj, centre, axes, unit: float, size: float):
    """An Empty of arrows on the principal axes at the centre of mass, parented to `obj` in its
    metric local frame (the parent's scale undone), so it moves with the body."""
    name = f"{obj.name} principal axes"
    empty = bpy.data.objects.get(name)
    if empty is None:
        empty = bpy.data.objects.new(name, None)
        bpy.context.scene.collection.objects.link(empty)
    empty.empty_display_type = "ARROWS"
    empty.empty_display_size = size
    empty.parent = obj
    empty.matrix_parent_inverse = Matrix.Diagonal(
        [1.0 / s for s in obj.scale] + [1.0])
    rotation = Matrix(np.asarray(axes).T.tolist())
    empty.matrix_basis = Matrix.Translation(Vector((np.asarray(centre) / unit).tolist())) @ \
        rotation.to_4x4()
    return empty


class INERTIALAB_OT_measure(bpy.types.Operator):
    """Compute the exact mass properties of the selected mesh, show its principal axes and set
    its rigid body's mass"""

    bl_idname = "inertialab.measure"
    bl_label = "Measure"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        return _on_selected(self, context, self.measure)

    def measure(self, context, obj, settings):
        result = measure.measure(obj, context.scene, settings.density)
        obj[MASS] = result.mass
        obj[CENTRE] = result.center_of_mass.tolist()
        obj[MOMENTS] = result.principal_moments.tolist()
        obj[AXES] = result.principal_axes.ravel().tolist()
        obj[WARNINGS] = "\n".join(measure.warning_lines(result))
        unit = measure.metres_per_unit(context.scene)
        size = float(np.sqrt(result.principal_moments[-1] / result.mass)) / unit
        _principal_empty(obj, result.center_of_mass, result.principal_axes, unit, size)
        if obj.rigid_body is None:
            if context.scene.rigidbody_world is None:
                bpy.ops.rigidbody.world_add()
            with context.temp_override(active_object=obj, object=obj, selected_objects=[obj]):
                bpy.ops.rigidbody.object_add()
        obj.rigid_body.mass = result.mass
        for line in measure.warning_lines(result):
            self.report({"WARNING"}, line)
        return f"{obj.name}: {result.mass:.6g} kg"


class INERTIALAB_OT_bake_tumble(bpy.types.Operator):
    """Bake the exact tumble of the selected mesh, spun about a principal axis, into keyframes
    from the current frame"""

    bl_idname = "inertialab.bake_tumble"
    bl_label = "Bake exact tumble"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        return _on_selected(self, context, self.bake)

    def bake(self, context, obj, settings):
        result = measure.measure(obj, context.scene, settings.density)
        omega = bake.spin(int(settings.spin_axis), settings.spin_rate, settings.perturbation)
        motion = bake.bake_tumble(obj, context.scene, result, omega, settings.seconds)
        return (f"{obj.name}: {len(motion.time)} frames baked, "
                f"|L| kept to {abs(motion.l_change):.1e}")


class INERTIALAB_PT_panel(bpy.types.Panel):
    """The sidebar panel."""

    bl_label = "Inertia Lab"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Inertia Lab"

    def draw(self, context):
        layout = self.layout
        settings = context.scene.inertia_lab
        obj = _selected_mesh(context)
        layout.prop(settings, "density")
        layout.operator(INERTIALAB_OT_measure.bl_idname)
        if obj is not None and MASS in obj:
            box = layout.box()
            box.label(text=f"mass {obj[MASS]:.6g} kg")
            c = obj[CENTRE]
            box.label(text=f"centre of mass ({c[0]:.4g}, {c[1]:.4g}, {c[2]:.4g}) m")
            m = obj[MOMENTS]
            box.label(text=f"moments {m[0]:.4g}, {m[1]:.4g}, {m[2]:.4g} kg·m²")
            for line in obj[WARNINGS].splitlines():
                box.label(text=line, icon="ERROR")
        layout.separator()
        layout.prop(settings, "spin_axis")
        layout.prop(settings, "spin_rate")
        layout.prop(settings, "perturbation")
        layout.prop(settings, "seconds")
        layout.operator(INERTIALAB_OT_bake_tumble.bl_idname)
        if settings.message:
            layout.label(text=settings.message)


CLASSES = (InertiaLabSettings, INERTIALAB_OT_measure, INERTIALAB_OT_bake_tumble,
           INERTIALAB_PT_panel)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.inertia_lab = PointerProperty(type=InertiaLabSettings)


def unregister():
    del bpy.types.Scene.inertia_lab
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
