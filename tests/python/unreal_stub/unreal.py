"""A stand-in for the Unreal editor's `unreal` module, just wide enough for the exported editor
script (export --format unreal-script), which tests/python/unreal_editor.py runs against it.

It holds to the real module's rules that the script could get wrong: a struct read with
get_editor_property is a copy (a change is lost unless set back), objects are shared, and a
property name that the class does not have raises, as Unreal's does. Names and defaults follow
the Unreal 5.x Python API reference (BodyInstance, BodySetup, KAggregateGeom, KBoxElem,
KShapeElem, StaticMesh, StaticMeshComponent, EditorActorSubsystem). The stand-in's Quat keeps
its four numbers through rotator(), so a test reads back the exact rotation the script set.
"""

import copy
import enum

LOG = []
TRANSACTIONS = []


def log(text):
    LOG.append(("info", text))


def log_warning(text):
    LOG.append(("warning", text))


def log_error(text):
    LOG.append(("error", text))


class _Properties:
    """Editor properties: the class's PROPERTIES (name -> default) and nothing else."""

    PROPERTIES = {}

    def __init__(self, **values):
        self._values = copy.deepcopy(self.PROPERTIES)
        for name, value in values.items():
            self.set_editor_property(name, value)

    def _check(self, name):
        if name not in self._values:
            raise Exception(
                "%s: Failed to find property '%s'" % (type(self).__name__, name)
            )


class StructBase(_Properties):
    """A struct: passed and read by value."""

    def get_editor_property(self, name):
        self._check(name)
        return copy.deepcopy(self._values[name])

    def set_editor_property(self, name, value):
        self._check(name)
        self._values[name] = copy.deepcopy(value)


class Object(_Properties):
    """A UObject: shared; a struct property read from it is a copy."""

    def __init__(self, name="None", **values):
        super().__init__(**values)
        self._name = name
        self.modified = 0

    def get_editor_property(self, name):
        self._check(name)
        value = self._values[name]
        return value if isinstance(value, Object) else copy.deepcopy(value)

    def set_editor_property(self, name, value):
        self._check(name)
        self._values[name] = value if isinstance(value, Object) else copy.deepcopy(value)

    def get_name(self):
        return self._name

    def get_path_name(self):
        return "/Game/%s.%s" % (self._name, self._name)

    def modify(self, always_mark_dirty=True):
        self.modified += 1
        return True


class Vector(StructBase):
    def __init__(self, x=0.0, y=0.0, z=0.0):
        super().__init__()
        self.x, self.y, self.z = float(x), float(y), float(z)


class Rotator(StructBase):
    def __init__(self, roll=0.0, pitch=0.0, yaw=0.0):
        super().__init__()
        self.roll, self.pitch, self.yaw = roll, pitch, yaw
        self.stub_quat = None


class Quat(StructBase):
    def __init__(self, x=0.0, y=0.0, z=0.0, w=1.0):
        super().__init__()
        self.x, self.y, self.z, self.w = float(x), float(y), float(z), float(w)

    def rotator(self):
        r = Rotator()
        r.stub_quat = (self.x, self.y, self.z, self.w)
        return r


class Box(StructBase):
    PROPERTIES = {"min": Vector(), "max": Vector(), "is_valid": True}


class CollisionEnabled(enum.Enum):
    NO_COLLISION = 0
    QUERY_ONLY = 1
    PHYSICS_ONLY = 2
    QUERY_AND_PHYSICS = 3
    PROBE_ONLY = 4
    QUERY_AND_PROBE = 5


class CollisionTraceFlag(enum.Enum):
    CTF_USE_DEFAULT = 0
    CTF_USE_SIMPLE_AND_COMPLEX = 1
    CTF_USE_SIMPLE_AS_COMPLEX = 2
    CTF_USE_COMPLEX_AS_SIMPLE = 3


_SHAPE = {
    "name": "None",
    "collision_enabled": CollisionEnabled.QUERY_AND_PHYSICS,
    "contribute_to_mass": True,
    "rest_offset": 0.0,
}


class KShapeElem(StructBase):
    PROPERTIES = dict(_SHAPE)


class KBoxElem(KShapeElem):
    PROPERTIES = dict(
        _SHAPE, center=Vector(), rotation=Rotator(), x=1.0, y=1.0, z=1.0, is_generated=False
    )


class KSphereElem(KShapeElem):
    PROPERTIES = dict(_SHAPE, center=Vector(), radius=1.0)


class KSphylElem(KShapeElem):
    PROPERTIES = dict(_SHAPE, center=Vector(), rotation=Rotator(), radius=1.0, length=1.0)


class KConvexElem(KShapeElem):
    PROPERTIES = dict(_SHAPE)


class KAggregateGeom(StructBase):
    PROPERTIES = {
        "sphere_elems": [],
        "box_elems": [],
        "sphyl_elems": [],
        "convex_elems": [],
        "tapered_capsule_elems": [],
        "level_set_elems": [],
    }


class BodyInstance(StructBase):
    PROPERTIES = {
        "simulate_physics": False,
        "override_mass": False,
        "mass_in_kg_override": 100.0,
        "mass_scale": 1.0,
        "com_nudge": Vector(),
        "inertia_tensor_scale": Vector(1.0, 1.0, 1.0),
        "inertia_conditioning": True,
        "linear_damping": 0.01,
        "angular_damping": 0.0,
    }


class BodySetup(Object):
    PROPERTIES = {
        "agg_geom": KAggregateGeom(),
        "collision_trace_flag": CollisionTraceFlag.CTF_USE_DEFAULT,
        "default_instance": BodyInstance(),
    }


class StaticMesh(Object):
    PROPERTIES = {"body_setup": None}

    def __init__(self, name, bounds, **values):
        super().__init__(name, **values)
        self._bounds = bounds

    def get_bounding_box(self):
        lo, hi = self._bounds
        return Box(min=Vector(*lo), max=Vector(*hi))


class StaticMeshComponent(Object):
    PROPERTIES = {
        "static_mesh": None,
        "body_instance": BodyInstance(),
        "relative_scale3d": Vector(1.0, 1.0, 1.0),
    }


class Actor(Object):
    def __init__(self, name, components):
        super().__init__(name)
        self._components = components

    def get_components_by_class(self, component_class):
        return [c for c in self._components if isinstance(c, component_class)]


class EditorActorSubsystem:
    def __init__(self):
        self.actors = []
        self.selected = []

    def get_all_level_actors(self):
        return list(self.actors)

    def get_selected_level_actors(self):
        return list(self.selected)


_SUBSYSTEMS = {EditorActorSubsystem: EditorActorSubsystem()}


def get_editor_subsystem(subsystem_class):
    return _SUBSYSTEMS[subsystem_class]


class ScopedEditorTransaction:
    def __init__(self, description):
        self.description = description

    def __enter__(self):
        TRANSACTIONS.append(self.description)
        return self

    def __exit__(self, *exc):
        return False
