"""The records of a scene, as frozen dataclasses: the C view's structs, field for field.

Indices are plain ints into the scene's tuples, None where the C view has ``B2S_NONE``;
an optional datum the file did not give (a polygon's ``centroid``, a ghost vertex, each
part of a body's MassData) is None, never zero. Vectors are ``(x, y)`` tuples. Floats are
the scene's 32-bit values, held exactly by Python's floats. ``Shape.new``, ``Fixture.new``,
``Body.new`` and ``Joint.new`` give a record with every field at the format's default
for its kind (the library's defaults); change fields with ``dataclasses.replace`` or the
keywords of ``new``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, Optional, Tuple, Type, TypeVar

from . import _native

Vec2 = Tuple[float, float]


R = TypeVar("R")


def _new(cls: Type[R], record: str, kind: Optional[str], changes: Dict[str, Any]) -> R:
    return cls(**{**_native.defaults(record, kind), **changes})


@dataclass(frozen=True)
class Shape:
    """A collision shape in body coordinates; fixtures may share it.

    ``kind`` is ``"circle"`` (``radius``, ``position``), ``"polygon"`` (2 to 8
    ``vertices``, 2 being a line segment; optional ``centroid``), ``"edge"`` (two
    ``vertices``, optional ghosts ``prev_vertex`` = Vertex0 and ``next_vertex`` = Vertex3)
    or ``"chain"`` (``vertices``, ``is_loop``, optional ghosts PrevVertex and NextVertex).
    """

    kind: str
    name: Optional[str]
    radius: float
    position: Vec2
    vertices: Tuple[Vec2, ...]
    centroid: Optional[Vec2]
    prev_vertex: Optional[Vec2]
    next_vertex: Optional[Vec2]
    is_loop: bool

    @classmethod
    def new(cls, kind: str, **changes: Any) -> "Shape":
        """A shape of ``kind`` with the format's defaults, then ``changes``."""
        return _new(cls, "shape", kind, changes)


@dataclass(frozen=True)
class Fixture:
    """Material and collision filter for one shape (an index into ``Scene.shapes``).

    Defaults: density 0, friction 0.2, restitution 0, not a sensor, category bits 1,
    mask bits 0xFFFF, group 0 (groups win over the bits), no user data.
    """

    shape: Optional[int]
    name: Optional[str]
    density: float
    friction: float
    restitution: float
    is_sensor: bool
    category_bits: int
    mask_bits: int
    group_index: int
    user_data: Optional[int]

    @classmethod
    def new(cls, shape: int, **changes: Any) -> "Fixture":
        """A fixture on ``shape`` with the format's defaults, then ``changes``."""
        return _new(cls, "fixture", None, {"shape": shape, **changes})


@dataclass(frozen=True)
class Body:
    """A rigid body: ``kind`` is ``"static"``, ``"kinematic"`` or ``"dynamic"``.

    ``fixtures`` are indices into ``Scene.fixtures``. ``mass`` (kg), ``center`` (body
    coordinates, m) and ``inertia`` (about the body origin, kg m²) are the parts of the
    file's MassData, each None when not given (Box2D's value from the fixtures is kept).
    Units: m, rad, m/s, rad/s.
    """

    kind: str
    name: Optional[str]
    position: Vec2
    angle: float
    linear_velocity: Vec2
    angular_velocity: float
    linear_damping: float
    angular_damping: float
    gravity_scale: float
    inertia_scale: float
    active: bool
    allow_sleep: bool
    awake: bool
    bullet: bool
    fixed_rotation: bool
    mass: Optional[float]
    center: Optional[Vec2]
    inertia: Optional[float]
    fixtures: Tuple[int, ...]
    user_data: Optional[int]

    @classmethod
    def new(cls, kind: str, **changes: Any) -> "Body":
        """A body of ``kind`` with the format's defaults, then ``changes``."""
        return _new(cls, "body", kind, changes)


@dataclass(frozen=True)
class Joint:
    """A joint between ``body_a`` and ``body_b`` (indices into ``Scene.bodies``).

    One flat record serves every kind (``"revolute"``, ``"prismatic"``, ``"distance"``,
    ``"pulley"``, ``"line"``, ``"weld"``, ``"friction"``, ``"gear"``, ``"wheel"``,
    ``"rope"``, ``"motor"``, and ``"unsupported"`` for Farseer-only joints kept so that
    indices stay stable); a field a kind does not use holds its default. ``..._a`` and
    ``..._b`` vectors are in the local frame of that body; a gear's ``joint_a`` and
    ``joint_b`` index ``Scene.joints``. ``lower_limit``/``upper_limit`` are the angles of a
    revolute joint and the translations of a prismatic or line joint.
    """

    kind: str
    name: Optional[str]
    body_a: Optional[int]
    body_b: Optional[int]
    joint_a: Optional[int]
    joint_b: Optional[int]
    user_data: Optional[int]
    local_anchor_a: Vec2
    local_anchor_b: Vec2
    local_axis_a: Vec2
    ground_anchor_a: Vec2
    ground_anchor_b: Vec2
    linear_offset: Vec2
    reference_angle: float
    lower_limit: float
    upper_limit: float
    motor_speed: float
    max_motor_torque: float
    max_motor_force: float
    length: float
    frequency_hz: float
    damping_ratio: float
    length_a: float
    length_b: float
    max_length_a: float
    max_length_b: float
    ratio: float
    max_force: float
    max_torque: float
    max_length: float
    angular_offset: float
    correction_factor: float
    collide_connected: bool
    enable_limit: bool
    enable_motor: bool

    @classmethod
    def new(cls, kind: str, body_a: int, body_b: int, **changes: Any) -> "Joint":
        """A joint of ``kind`` with the format's defaults for it, then ``changes``."""
        return _new(cls, "joint", kind, {"body_a": body_a, "body_b": body_b, **changes})


@dataclass(frozen=True)
class UserData:
    """Application data of a fixture, body or joint, never interpreted.

    ``raw`` is the exact XML between the tags; ``type_name`` and ``value`` are set when it
    has the editor's form (``<Type>System.String</Type><Value><string>x</string></Value>``).
    """

    raw: Optional[str]
    type_name: Optional[str]
    value: Optional[str]


@dataclass(frozen=True)
class Diagnostic:
    """A warning of a load: its ``code`` (kebab-case), ``severity``, 1-based ``line`` and
    ``column`` (0 when unknown), ``byte_offset`` and ``message``."""

    code: str
    severity: str
    line: int
    column: int
    byte_offset: int
    message: str
