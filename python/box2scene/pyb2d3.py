"""Build a scene into a pyb2d3 world (Box2D v3.1.1), and capture one back into a scene.

A build carries out the library's plan of the scene for Box2D v3.1, the one the C v3
adapter (``include/box2scene/box2d3.h``) carries out: the library converts, checks the
working range, predicts every mass and writes every report; this module only creates what
the plan says through pyb2d3's calls, in the plan's order:

    import pyb2d3, box2scene, box2scene.pyb2d3 as b2s3
    scene = box2scene.load("level.xml")
    world = b2s3.create_world(scene, fallback_gravity=(0, -10))
    built = b2s3.build_world(scene, world)
    for report in built.reports: print(report.code, report.object, report.index, report.message)
    for _ in range(600): world.step(1 / 60, 4)
    saved, reports = b2s3.capture_world(world, built)

pyb2d3 cannot read everything it was given: a world's maximum linear speed, a joint's
``collide_connected``, reference angle and axis (and its name), a chain's ghost points. The builder
keeps what it gives each joint and chain on the :class:`Built` it returns, so that a capture
of the world it built is exact; for joints and chains a host made itself, the capture
writes those fields at their defaults and reports ``lossy-capture``. pyb2d3 cannot list a
body's joints either, so :func:`capture_world` takes the host's own joints beside its
bodies. Its chains cannot
turn on sensor events (v3's ``enableSensorEvents``, which the C adapter sets): a sensor of
the scene does not see them, which a build with a sensor and a chain reports.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np
import pyb2d3 as b2

from . import _native
from ._error import Error
from ._lookup import Lookups
from ._report import Report
from ._scene import Scene

__all__ = ["Built", "Report", "build_world", "capture_world", "create_world", "scene_gravity"]

# The engine version of the library's plan and working range pyb2d3 is built on.
ENGINE = "box2d-3.1"
# The maximum linear speed of the world a plan for v3.1 needs (the C adapter's world def).
WORLD_MAX_LINEAR_SPEED = _native.working_range(ENGINE)["world_max_linear_speed"]


@dataclass
class Built(Lookups):
    """What :func:`build_world` created, index for index with the scene: ``bodies[i]`` for
    body ``i``; ``shapes[k]`` and ``chains[k]`` for the fixture at slot ``k`` of the
    scene's ``fixture_ids`` (a chain fixture in ``chains``, any other in ``shapes``);
    ``joints[j]`` for joint ``j``; ``fixtures[k]`` for either kind. None where nothing was
    created (then ``reports`` says why)."""

    bodies: List[Optional[b2.Body]]
    shapes: List[Optional[b2.Shape]]
    chains: List[Optional[b2.Chain]]
    joints: List[Optional[b2.Joint]]
    reports: List[Report] = field(default_factory=list)
    fixtures: List[Optional[object]] = field(default_factory=list)
    # What capture needs that pyb2d3 cannot read back: the scene (the level a capture keeps),
    # and the plan's record of each joint and chain the build made, by id (a v3 id names one
    # object, never a later one).
    _scene: Optional[Scene] = field(default=None, repr=False, compare=False)
    _joints: Dict[int, object] = field(default_factory=dict, repr=False, compare=False)
    _chains: Dict[int, object] = field(default_factory=dict, repr=False, compare=False)

    @staticmethod
    def _same(made, wanted) -> bool:
        """A v3 id names one object, never a later one."""
        return int(made.id) == int(wanted.id)


def scene_gravity(scene: Scene, fallback: Tuple[float, float] = (0.0, -10.0)) -> Tuple[float, float]:
    """The scene's gravity, or ``fallback`` when it gives none or one beyond the range."""
    gravity = _native.world_gravity(scene._native, ENGINE)
    return fallback if gravity is None else gravity


def create_world(scene: Scene, fallback_gravity: Tuple[float, float] = (0.0, -10.0), **settings) -> b2.World:
    """A pyb2d3 world for ``scene``: its gravity (or the fallback) and the maximum linear
    speed the working range needs (the C adapter's ``b2s_box2d3_world_def``); ``settings``
    are pyb2d3's other world settings."""
    settings.setdefault("maximum_linear_speed", WORLD_MAX_LINEAR_SPEED)
    return b2.World(gravity=scene_gravity(scene, fallback_gravity), **settings)


# ---- one build: the plan carried out


def _filter(shape) -> b2.Filter:
    out = b2.Filter()
    out.category_bits = shape.category_bits
    out.mask_bits = shape.mask_bits
    out.group_index = shape.group_index
    return out


def _body_def(body) -> b2.BodyDef:
    d = b2.BodyDef()
    d.type = b2.BodyType(body.kind)
    d.position = body.position
    rotation = b2.Rot()
    rotation.c, rotation.s = body.rotation
    d.rotation = rotation
    d.linear_velocity = body.linear_velocity
    d.angular_velocity = body.angular_velocity
    d.linear_damping = body.linear_damping
    d.angular_damping = body.angular_damping
    d.gravity_scale = body.gravity_scale
    d.enable_sleep = body.allow_sleep
    d.is_awake = body.awake
    d.fixed_rotation = body.fixed_rotation
    d.is_bullet = body.bullet
    d.is_enabled = body.enabled
    if body.name is not None:
        d.name = body.name
    return d


class _Build:
    def __init__(self, scene: Scene, world: b2.World, plan):
        self.world = world
        self.has_sensor = plan.has_sensor
        reports = [Report(*r) for r in plan.reports]
        slots = [None] * plan.slot_count
        self.built = Built([None] * plan.body_count, slots, list(slots), [None] * plan.joint_count, reports, _scene=scene)

    def report_chain_sensor(self, shape, body: int) -> None:
        """pyb2d3's chain def has no ``enableSensorEvents``: the scene's sensors do not see
        its chains (a sensor chain itself the plan reports)."""
        if self.has_sensor and not shape.fixture_is_sensor:
            self.built.reports.append(
                Report(
                    "lossy-shape",
                    "fixture",
                    shape.fixture,
                    shape.name,
                    f"fixture {shape.fixture} of body {body}: pyb2d3's chains cannot turn on sensor events, so the scene's sensors do not see this chain",
                )
            )

    def make_shape(self, shape, body_index: int, body: b2.Body) -> None:
        d = b2.ShapeDef()
        material = d.material
        material.friction = shape.friction
        material.restitution = shape.restitution
        kind = shape.kind
        if kind in ("chain", "loop"):
            chain_def = b2.ChainDef()
            chain_def.points = np.array(shape.points, dtype=np.float32)
            chain_def.is_loop = kind == "loop"
            chain_def.materials = [material]
            chain_def.filter = _filter(shape)
            self.report_chain_sensor(shape, body_index)
            chain = body.create_chain(chain_def)
            self.built._chains[int(chain.id)] = shape
            self.built.chains[shape.slot] = chain
            return
        d.material = material
        d.density = shape.density
        d.filter = _filter(shape)
        d.is_sensor = shape.is_sensor
        # Box2D 2.x's sensors saw every shape; v3's see those with sensor events on.
        d.enable_sensor_events = True
        # One mass update per body, after all its shapes.
        d.update_body_mass = False
        if kind == "circle":
            made = body.create_circle_shape(d, b2.circle(shape.center, shape.radius))
        elif kind == "polygon":
            # The plan's points are b2ComputeHull's own, which it gives back unchanged.
            hull = b2.compute_hull(np.array(shape.points, dtype=np.float32))
            made = body.create_polygon_shape(d, b2._pyb2d3._make_polygon(hull, 0.0))
        else:
            made = body.create_segment_shape(d, b2.segment(*shape.points))
        self.built.shapes[shape.slot] = made

    def make_body(self, body) -> None:
        created = self.world.create_body_from_def(_body_def(body))
        self.built.bodies[body.body] = created
        for shape in body.shapes:
            self.make_shape(shape, body.body, created)
        if body.apply_mass_from_shapes:
            created.apply_mass_from_shapes()
        if body.set_mass:
            data = b2.MassData()
            data.mass = body.mass
            data.center = body.center
            data.rotational_inertia = body.inertia
            created.mass_data = data
        if body.set_velocity:
            created.linear_velocity = body.velocity_after_mass

    def make_joint(self, j) -> None:
        a, b = self.built.bodies[j.body_a], self.built.bodies[j.body_b]
        kind = j.kind
        if kind == "revolute":
            d = b2.RevoluteJointDef()
            d.local_anchor_a, d.local_anchor_b, d.reference_angle = j.anchor_a, j.anchor_b, j.reference_angle
            d.lower_angle, d.upper_angle = j.lower, j.upper
            d.enable_limit, d.enable_motor = j.enable_limit, j.enable_motor
            d.motor_speed, d.max_motor_torque = j.motor_speed, j.max_motor
            create = self.world.create_revolute_joint
        elif kind == "prismatic":
            d = b2.PrismaticJointDef()
            d.local_anchor_a, d.local_anchor_b, d.reference_angle = j.anchor_a, j.anchor_b, j.reference_angle
            d.local_axis_a = j.axis
            d.lower_translation, d.upper_translation = j.lower, j.upper
            d.enable_limit, d.enable_motor = j.enable_limit, j.enable_motor
            d.max_motor_force, d.motor_speed = j.max_motor, j.motor_speed
            create = self.world.create_prismatic_joint
        elif kind == "distance":
            d = b2.DistanceJointDef()
            d.local_anchor_a, d.local_anchor_b = j.anchor_a, j.anchor_b
            d.length = j.length
            d.enable_spring, d.hertz, d.damping_ratio = j.enable_spring, j.hertz, j.damping_ratio
            if j.enable_limit:
                d.enable_limit, d.min_length, d.max_length = True, j.min_length, j.max_length
            create = self.world.create_distance_joint
        elif kind == "wheel":
            d = b2.WheelJointDef()
            d.local_anchor_a, d.local_anchor_b = j.anchor_a, j.anchor_b
            d.local_axis_a = j.axis
            d.enable_spring = j.enable_spring
            if j.enable_spring:
                d.hertz, d.damping_ratio = j.hertz, j.damping_ratio
            d.lower_translation, d.upper_translation = j.lower, j.upper
            d.enable_limit, d.enable_motor = j.enable_limit, j.enable_motor
            d.max_motor_torque, d.motor_speed = j.max_motor, j.motor_speed
            create = self.world.create_wheel_joint
        elif kind == "weld":
            d = b2.WeldJointDef()
            d.local_anchor_a, d.local_anchor_b, d.reference_angle = j.anchor_a, j.anchor_b, j.reference_angle
            d.linear_hertz, d.angular_hertz, d.angular_damping_ratio = 0.0, j.hertz, j.damping_ratio
            create = self.world.create_weld_joint
        else:
            # v3 has no friction joint: a motor joint that drives no velocity does its work
            # (the plan's offsets and correction factor are then 0).
            d = b2.MotorJointDef()
            d.linear_offset, d.angular_offset = j.linear_offset, j.angular_offset
            d.max_force, d.max_torque, d.correction_factor = j.max_force, j.max_torque, j.correction_factor
            create = self.world.create_motor_joint
        d.body_a, d.body_b, d.collide_connected = a, b, j.collide_connected
        created = create(d)
        self.built._joints[int(created.id)] = j
        self.built.joints[j.joint] = created


def build_world(scene: Scene, world: b2.World, *, maximum_linear_speed: float = WORLD_MAX_LINEAR_SPEED) -> Built:
    """Creates every object of ``scene`` that Box2D v3 can hold in ``world`` and reports the
    rest (never asserting, never producing NaN). ``maximum_linear_speed`` is the world's
    (pyb2d3 cannot read it back): that of :func:`create_world` unless the host made its world
    otherwise."""
    g = world.gravity
    plan = _native.make_plan(scene._native, ENGINE, (float(g.x), float(g.y)), maximum_linear_speed)
    b = _Build(scene, world, plan)
    for body in plan.bodies:
        b.make_body(body)
    for joint in plan.joints:
        b.make_joint(joint)
    b.built.fixtures = [s if s is not None else c for s, c in zip(b.built.shapes, b.built.chains)]
    return b.built


# ---- capture: pyb2d3's getters read into the library's held records


def _pair(v) -> Tuple[float, float]:
    return (float(v[0]), float(v[1]))


_NONE = 0xFFFFFFFF
_KINDS = {b2.ShapeType.circle: "circle", b2.ShapeType.polygon: "polygon", b2.ShapeType.segment: "segment"}


class _Read:
    """A world as pyb2d3 holds it, in the library's held records (dicts named as their
    fields): what pyb2d3 cannot read of what the build made comes from the plan's records
    the build kept; of the host's own, it is reported and left at its default."""

    def __init__(self, built: Optional[Built]):
        self.joints = built._joints if built is not None else {}
        self.chains = built._chains if built is not None else {}
        self.slots: Dict[Tuple[bool, int], int] = {}
        if built is not None:
            for slot, made in enumerate(built.fixtures):
                if made is not None:
                    self.slots[(isinstance(made, b2.Chain), int(made.id))] = slot
        self.reports: List[Report] = []

    def material(self, s, held: dict) -> dict:
        f = s.filter
        held.update(
            friction=float(s.friction),
            restitution=float(s.restitution),
            category_bits=int(f.category_bits),
            mask_bits=int(f.mask_bits),
            group_index=int(f.group_index),
        )
        return held

    def chain(self, chain: b2.Chain, first) -> dict:
        """A chain held whole: pyb2d3 gives its segments without their ghosts, so one the build
        made is the plan's, and one of the host's has its ghosts unread (NaN)."""
        plan = self.chains.get(int(chain.id))
        if plan is not None:
            held = dict(kind=plan.kind, points=list(plan.points))
        else:
            segments = [s.segment for s in chain.get_segments()]
            points = [_pair(s.point1) for s in segments] + [_pair(segments[-1].point2)]
            held = dict(kind="chain", points=[(math.nan, math.nan)] + points + [(math.nan, math.nan)])
        held["slot"] = self.slots.get((True, int(chain.id)), _NONE)
        return self.material(first, held)

    def shape(self, s) -> dict:
        kind = _KINDS.get(s.type)
        held = dict(slot=self.slots.get((False, int(s.id)), _NONE), density=float(s.density), is_sensor=bool(s.is_sensor))
        if kind == "circle":
            held.update(kind=kind, center=_pair(s.circle.center), radius=float(s.circle.radius))
        elif kind == "polygon":
            p = s.polygon
            held.update(kind=kind, points=[_pair(v) for v in p.vertices[: p.count]], radius=float(p.radius))
        elif kind == "segment":
            held.update(kind=kind, points=[_pair(s.segment.point1), _pair(s.segment.point2)])
        else:
            held["other"] = "a capsule"
        return self.material(s, held)

    def shapes(self, body: b2.Body) -> List[dict]:
        """A body's shapes in the order they were created, a chain where its first segment
        stands."""
        out, seen = [], set()
        for s in sorted(body.shapes, key=lambda s: int(s.id) & 0xFFFFFFFF):
            if s.type != b2.ShapeType.chain_segment:
                out.append(self.shape(s))
            elif int(s.parent_chain.id) not in seen:
                seen.add(int(s.parent_chain.id))
                out.append(self.chain(s.parent_chain, s))
        return out

    def body(self, body: b2.Body, record: int, name: Optional[str]) -> dict:
        m = body.mass_data
        return dict(
            body=record,
            kind=body.type.value,
            name=name,
            position=_pair(body.position),
            rotation=(float(body.rotation.c), float(body.rotation.s)),
            linear_velocity=_pair(body.linear_velocity),
            angular_velocity=float(body.angular_velocity),
            linear_damping=float(body.linear_damping),
            angular_damping=float(body.angular_damping),
            gravity_scale=float(body.gravity_scale),
            mass=float(m.mass),
            center=_pair(m.center),
            inertia=float(m.rotational_inertia),
            allow_sleep=bool(body.enabled_sleep),
            awake=bool(body.awake),
            bullet=bool(body.bullet),
            fixed_rotation=bool(body.fixed_rotation),
            enabled=bool(body.enabled),
            shapes=self.shapes(body),
        )

    def joint(self, j, index_of: Dict[int, int], held_index: int) -> dict:
        plan = self.joints.get(int(j.id))
        T = b2.JointType
        held = dict(
            joint=plan.joint if plan is not None else _NONE,
            body_a=index_of.get(int(j.body_a.id), _NONE),
            body_b=index_of.get(int(j.body_b.id), _NONE),
        )
        if plan is not None:  # what pyb2d3 cannot read: as the build gave it
            held.update(collide_connected=plan.collide_connected, reference_angle=plan.reference_angle, axis=plan.axis)
        elif _NONE not in (held["body_a"], held["body_b"]) and j.type in (T.REVOLUTE_JOINT, T.PRISMATIC_JOINT, T.WHEEL_JOINT, T.WELD_JOINT):
            held["axis"] = (1.0, 0.0)
            self.reports.append(
                Report(
                    "lossy-capture",
                    "joint",
                    held_index,
                    None,
                    "pyb2d3 cannot read a joint's collide_connected, reference angle or axis: box2scene did not build this joint, so they were written at their defaults",
                )
            )
        if j.type not in (T.MOTOR_JOINT, T.MOUSE_JOINT) and j.type in _JOINT_KINDS:
            held.update(anchor_a=_pair(j.local_anchor_a), anchor_b=_pair(j.local_anchor_b))
        read = _JOINT_KINDS.get(j.type)
        if read is None:
            held["other"] = "a mouse joint" if j.type == T.MOUSE_JOINT else "a filter joint"
            return held
        kind, fields = read
        held["kind"] = kind
        held.update(fields(j))
        return held


def _limits(j) -> dict:
    return dict(enable_limit=bool(j.limit_enabled), lower=float(j.lower_limit), upper=float(j.upper_limit))


def _motor(j, maximum: str) -> dict:
    return dict(enable_motor=bool(j.motor_enabled), motor_speed=float(j.motor_speed), max_motor=float(getattr(j, maximum)))


def _spring(j, hertz: str = "spring_hertz", ratio: str = "spring_damping_ratio") -> dict:
    return dict(hertz=float(getattr(j, hertz)), damping_ratio=float(getattr(j, ratio)))


_JOINT_KINDS = {
    b2.JointType.REVOLUTE_JOINT: ("revolute", lambda j: dict(_limits(j), **_motor(j, "max_motor_torque"), enable_spring=bool(j.spring_enabled))),
    b2.JointType.PRISMATIC_JOINT: ("prismatic", lambda j: dict(_limits(j), **_motor(j, "max_motor_force"), enable_spring=bool(j.spring_enabled))),
    b2.JointType.DISTANCE_JOINT: (
        "distance",
        lambda j: dict(
            _spring(j),
            length=float(j.length),
            min_length=float(j.min_length),
            max_length=float(j.max_length),
            enable_spring=bool(j.spring_enabled),
            enable_limit=bool(j.limit_enabled),
            enable_motor=bool(j.motor_enabled),
        ),
    ),
    b2.JointType.WHEEL_JOINT: ("wheel", lambda j: dict(_limits(j), **_motor(j, "max_motor_torque"), **_spring(j), enable_spring=bool(j.spring_enabled))),
    b2.JointType.WELD_JOINT: (
        "weld",
        lambda j: dict(_spring(j, "angular_hertz", "angular_damping_ratio"), linear_hertz=float(j.linear_hertz)),
    ),
    b2.JointType.MOTOR_JOINT: (
        "motor",
        lambda j: dict(
            linear_offset=_pair(j.linear_offset),
            angular_offset=float(j.angular_offset),
            max_force=float(j.max_force),
            max_torque=float(j.max_torque),
            correction_factor=float(j.correction_factor),
        ),
    ),
}


def capture_world(
    world: b2.World,
    built: Optional[Built] = None,
    bodies: Sequence[b2.Body] = (),
    joints: Sequence[b2.Joint] = (),
    names: Optional[Sequence[Optional[str]]] = None,
) -> Tuple[Scene, List[Report]]:
    """A scene of what ``built`` made that the world still holds (in the scene's order, with
    its names and UserData, the joints pyb2d3 could not hold written back where the file had
    them), then of the host's own ``bodies`` (their shapes with them; named by ``names``, or
    else by their Box2D names) and those of its ``joints`` whose two bodies are saved, with
    the world's gravity; and the reports of what has no Box2Scene form. The library makes
    the scene of what pyb2d3 holds, as it does for the C adapter. Raises
    :class:`box2scene.Error` when a body is given twice."""
    if names is not None and len(names) != len(bodies):
        raise Error("invalid-argument", 0, 0, 0, f"{len(names)} names for {len(bodies)} bodies")
    read = _Read(built)
    made = [(b, i) for i, b in enumerate(built.bodies) if b is not None and b.is_valid] if built is not None else []
    given = [(b, _NONE) for b in bodies]
    labels = [None] * len(made) + (list(names) if names is not None else [b.name or None for b in bodies])
    index_of: Dict[int, int] = {}
    for i, (body, _) in enumerate(made + given):
        if int(body.id) in index_of:
            raise Error("invalid-argument", 0, 0, 0, f"bodies {index_of[int(body.id)]} and {i} are the same body")
        index_of[int(body.id)] = i
    held_bodies = [read.body(b, record, label) for (b, record), label in zip(made + given, labels)]
    built_joints = [j for j in built.joints if j is not None and j.is_valid] if built is not None else []
    written = {int(j.id) for j in built_joints}
    host = sorted((j for j in joints if j is not None and int(j.id) not in written), key=lambda j: int(j.id) & 0xFFFFFFFF)
    held_joints = [read.joint(j, index_of, k) for k, j in enumerate(built_joints + host)]
    skipped = [i for i, j in enumerate(built.joints) if j is None] if built is not None else []
    g = world.gravity
    level = built._scene._native if built is not None else None
    native, reports = _native.capture(ENGINE, (float(g.x), float(g.y)), held_bodies, held_joints, skipped, level)
    return Scene(native), read.reports + [Report(*r) for r in reports]
