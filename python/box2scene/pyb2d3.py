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
from ._f32 import f32
from ._report import Report
from ._scene import Scene

__all__ = ["Built", "Report", "build_world", "capture_world", "create_world", "scene_gravity"]

# The engine version of the library's plan and working range pyb2d3 is built on.
ENGINE = "box2d-3.1"
# The maximum linear speed of the world a plan for v3.1 needs (the C adapter's world def).
WORLD_MAX_LINEAR_SPEED = _native.working_range(ENGINE)["world_max_linear_speed"]


@dataclass
class Built:
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
    # What capture needs that pyb2d3 cannot read back: the scene (its names), and what the
    # build gave each joint and chain, by id (a v3 id names one object, never a later one).
    _scene: Optional[Scene] = field(default=None, repr=False, compare=False)
    _joints: Dict[int, dict] = field(default_factory=dict, repr=False, compare=False)
    _chains: Dict[int, Tuple[List[Tuple[float, float]], bool]] = field(default_factory=dict, repr=False, compare=False)


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
            self.built._chains[int(chain.id)] = (list(shape.points), kind == "loop")
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
        # What capture reads back that pyb2d3 cannot give: as the build passed it.
        record = {"collide_connected": j.collide_connected, "name": j.name}
        if kind == "revolute":
            d = b2.RevoluteJointDef()
            d.local_anchor_a, d.local_anchor_b, d.reference_angle = j.anchor_a, j.anchor_b, j.reference_angle
            d.lower_angle, d.upper_angle = j.lower, j.upper
            d.enable_limit, d.enable_motor = j.enable_limit, j.enable_motor
            d.motor_speed, d.max_motor_torque = j.motor_speed, j.max_motor
            record["reference_angle"] = j.reference_angle
            create = self.world.create_revolute_joint
        elif kind == "prismatic":
            d = b2.PrismaticJointDef()
            d.local_anchor_a, d.local_anchor_b, d.reference_angle = j.anchor_a, j.anchor_b, j.reference_angle
            d.local_axis_a = j.axis
            d.lower_translation, d.upper_translation = j.lower, j.upper
            d.enable_limit, d.enable_motor = j.enable_limit, j.enable_motor
            d.max_motor_force, d.motor_speed = j.max_motor, j.motor_speed
            record.update(local_axis_a=j.axis, reference_angle=j.reference_angle)
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
            record["local_axis_a"] = j.axis
            create = self.world.create_wheel_joint
        elif kind == "weld":
            d = b2.WeldJointDef()
            d.local_anchor_a, d.local_anchor_b, d.reference_angle = j.anchor_a, j.anchor_b, j.reference_angle
            d.linear_hertz, d.angular_hertz, d.angular_damping_ratio = 0.0, j.hertz, j.damping_ratio
            record["reference_angle"] = j.reference_angle
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
        self.built._joints[int(created.id)] = record
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


# ---- capture: the world read through pyb2d3's getters into the held records (the plan's
# own, read back), which the library turns into a scene and the reports

_NONE = 0xFFFFFFFF
_KINDS = {b2.BodyType.STATIC: 0, b2.BodyType.KINEMATIC: 1, b2.BodyType.DYNAMIC: 2}
_PAIRS = ("anchor_a", "anchor_b", "axis", "ground_anchor_a", "ground_anchor_b", "linear_offset")
_FLAGS = ("collide_connected", "enable_limit", "enable_motor", "enable_spring")


def _vec(v) -> Tuple[float, float]:
    return (float(v.x), float(v.y))


def _extrapolated(end, inner):
    """A ghost point pyb2d3 cannot read: the end segment continued one length."""
    return (float(f32(end[0] + (end[0] - inner[0]))), float(f32(end[1] + (end[1] - inner[1]))))


def _joint_defaults() -> Dict[str, object]:
    held: Dict[str, object] = {f: (0.0, 0.0) for f in _PAIRS}
    held.update({f: False for f in _FLAGS})
    for f in ("reference_angle", "length_a", "length_b", "ratio", "lower", "upper", "length", "min_length", "max_length", "motor_speed", "max_motor", "stiffness", "damping", "hertz", "damping_ratio", "angular_offset", "max_force", "max_torque", "correction_factor", "linear_hertz", "linear_damping_ratio"):
        held[f] = 0.0
    held.update(joint=_NONE, joint_a=_NONE, joint_b=_NONE, name=None, other=None)
    return held


def _limit_and_motor(j, max_motor: float) -> Dict[str, object]:
    return dict(
        enable_spring=bool(j.spring_enabled),
        enable_limit=bool(j.limit_enabled),
        lower=float(j.lower_limit),
        upper=float(j.upper_limit),
        enable_motor=bool(j.motor_enabled),
        motor_speed=float(j.motor_speed),
        max_motor=max_motor,
    )


def _held_joint_fields(j) -> Optional[Tuple[str, Dict[str, object]]]:
    """The plan's kind and the fields a joint holds that pyb2d3 reads back; None for a kind
    the format has no form for."""
    T = b2.JointType
    t = j.type
    anchors = dict(anchor_a=_vec(j.local_anchor_a), anchor_b=_vec(j.local_anchor_b))
    if t == T.REVOLUTE_JOINT:
        return "revolute", dict(anchors, **_limit_and_motor(j, float(j.max_motor_torque)))
    if t == T.PRISMATIC_JOINT:
        return "prismatic", dict(anchors, **_limit_and_motor(j, float(j.max_motor_force)))
    if t == T.DISTANCE_JOINT:
        return "distance", dict(
            anchors,
            length=float(j.length),
            enable_spring=bool(j.spring_enabled),
            hertz=float(j.spring_hertz),
            damping_ratio=float(j.spring_damping_ratio),
            enable_limit=bool(j.limit_enabled),
            min_length=float(j.min_length),
            max_length=float(j.max_length),
            enable_motor=bool(j.motor_enabled),
        )
    if t == T.WHEEL_JOINT:
        fields = _limit_and_motor(j, float(j.max_motor_torque))
        return "wheel", dict(anchors, hertz=float(j.spring_hertz), damping_ratio=float(j.spring_damping_ratio), **fields)
    if t == T.WELD_JOINT:
        return "weld", dict(
            anchors,
            hertz=float(j.angular_hertz),
            damping_ratio=float(j.angular_damping_ratio),
            linear_hertz=float(j.linear_hertz),
            linear_damping_ratio=float(j.linear_damping_ratio),
        )
    if t == T.MOTOR_JOINT:
        return "motor", dict(
            linear_offset=_vec(j.linear_offset),
            angular_offset=float(j.angular_offset),
            max_force=float(j.max_force),
            max_torque=float(j.max_torque),
            correction_factor=float(j.correction_factor),
        )
    return None


class _Reader:
    """What ``capture_world`` saves, read into the held records: the bodies the build made
    that the world still holds, then the host's ``bodies``; the build's joints the world
    still holds, then the host's ``joints``. What pyb2d3 cannot read back is what the build
    gave (kept on the :class:`Built`), or for the host's own objects the defaults, reported."""

    def __init__(self, world: b2.World, built: Optional[Built], bodies: Sequence[b2.Body], names: Optional[Sequence[Optional[str]]]):
        if names is not None and len(names) != len(bodies):
            raise Error("invalid-argument", 0, 0, 0, f"{len(names)} names for {len(bodies)} bodies")
        self.reports: List[Report] = []
        self.records = built._joints if built is not None else {}
        self.chains = built._chains if built is not None else {}
        # The fixture slot of each shape and chain the build made (their ids number apart).
        self.slots: Dict[Tuple[bool, int], int] = {}
        saved: List[Tuple[b2.Body, int, Optional[str]]] = []
        if built is not None:
            for slot, made in enumerate(built.fixtures):
                if made is not None:
                    self.slots[(isinstance(made, b2.Chain), int(made.id))] = slot
            saved += [(b, i, None) for i, b in enumerate(built.bodies) if b is not None and b.is_valid]
        given = names if names is not None else [b.name or None for b in bodies]
        saved += [(b, _NONE, name) for b, name in zip(bodies, given)]
        self.index_of: Dict[int, int] = {}
        for i, (body, _, _) in enumerate(saved):
            if int(body.id) in self.index_of:
                raise Error("invalid-argument", 0, 0, 0, f"bodies {self.index_of[int(body.id)]} and {i} are the same body")
            self.index_of[int(body.id)] = i
        self.shape_count = 0
        self.bodies = [self.held_body(*entry) for entry in saved]
        self.joints: List[Dict[str, object]] = []

    def held_material(self, s, slot: int) -> Dict[str, object]:
        f = s.filter
        self.shape_count += 1
        return dict(
            slot=slot,
            center=(0.0, 0.0),
            radius=0.0,
            density=float(s.density),
            friction=float(s.friction),
            restitution=float(s.restitution),
            is_sensor=bool(s.is_sensor),
            category_bits=int(f.category_bits),
            mask_bits=int(f.mask_bits),
            group_index=int(f.group_index),
            restitution_threshold=math.nan,  # v3.1 has none
            name=None,
            shape_name=None,
            other=None,
        )

    def held_chain(self, chain: b2.Chain, first) -> Dict[str, object]:
        """A chain whole, as the plan gave it: pyb2d3 reads no ghost points, so a chain the
        build did not make has its ghosts extrapolated (reported)."""
        held = self.held_material(first, self.slots.get((True, int(chain.id)), _NONE))
        held.update(density=0.0, is_sensor=False)
        recorded = self.chains.get(int(chain.id))
        if recorded is not None:
            points, loop = recorded
        else:
            segments = [s.segment for s in chain.get_segments()]
            points = [_vec(s.point1) for s in segments]
            end = _vec(segments[-1].point2)
            loop = end == points[0]
            if not loop:
                points = [_extrapolated(points[0], points[1])] + points + [end, _extrapolated(end, points[-1])]
            self.reports.append(Report("lossy-capture", "shape", self.shape_count - 1, None, "pyb2d3 cannot read a chain's ghost points: those of a chain box2scene did not build were extrapolated"))
        held.update(kind="loop" if loop else "chain", points=[tuple(p) for p in points])
        return held

    def held_shape(self, s) -> Dict[str, object]:
        held = self.held_material(s, self.slots.get((False, int(s.id)), _NONE))
        kind = s.type
        if kind == b2.ShapeType.circle:
            c = s.circle
            held.update(kind="circle", points=[], center=_vec(c.center), radius=float(c.radius))
        elif kind == b2.ShapeType.polygon:
            p = s.polygon
            held.update(kind="polygon", points=[tuple(map(float, v)) for v in p.vertices[: p.count]], radius=float(p.radius))
        elif kind == b2.ShapeType.segment:
            held.update(kind="segment", points=[_vec(s.segment.point1), _vec(s.segment.point2)])
        else:
            held.update(kind="other", points=[], other="a capsule")
        return held

    def held_shapes(self, body: b2.Body) -> List[Dict[str, object]]:
        """A body's shapes in the order they were created, a chain where its first segment
        stands."""
        shapes, chains_seen = [], set()
        for s in sorted(body.shapes, key=lambda s: int(s.id) & 0xFFFFFFFF):
            if s.type != b2.ShapeType.chain_segment:
                shapes.append(self.held_shape(s))
            elif int(s.parent_chain.id) not in chains_seen:
                chains_seen.add(int(s.parent_chain.id))
                shapes.append(self.held_chain(s.parent_chain, s))
        return shapes

    def held_body(self, body: b2.Body, index: int, name: Optional[str]) -> Dict[str, object]:
        mass = body.mass_data
        q = body.rotation
        return dict(
            body=index,
            kind=_KINDS[body.type],
            position=_vec(body.position),
            angle=0.0,  # v3 holds a rotation
            rotation=(float(q.c), float(q.s)),
            linear_velocity=_vec(body.linear_velocity),
            angular_velocity=float(body.angular_velocity),
            linear_damping=float(body.linear_damping),
            angular_damping=float(body.angular_damping),
            gravity_scale=float(body.gravity_scale),
            mass=float(mass.mass),
            center=_vec(mass.center),
            inertia=float(mass.rotational_inertia),
            allow_sleep=bool(body.enabled_sleep),
            awake=bool(body.awake),
            fixed_rotation=bool(body.fixed_rotation),
            bullet=bool(body.bullet),
            enabled=bool(body.enabled),
            name=name,
            shapes=self.held_shapes(body),
        )

    def read_joints(self, built: Optional[Built], joints: Sequence[b2.Joint]) -> None:
        """The build's joints the world still holds, then the host's."""
        read = set()
        for index, joint in enumerate(built.joints if built is not None else ()):
            if joint is not None and joint.is_valid:
                self.read_joint(joint, index)
                read.add(int(joint.id))
        for joint in sorted((j for j in joints if j is not None and int(j.id) not in read), key=lambda j: int(j.id) & 0xFFFFFFFF):
            self.read_joint(joint, _NONE)

    def read_joint(self, j, index: int) -> None:
        held = _joint_defaults()
        held.update(joint=index, body_a=self.index_of.get(int(j.body_a.id), _NONE), body_b=self.index_of.get(int(j.body_b.id), _NONE))
        self.joints.append(held)
        fields = _held_joint_fields(j)
        if fields is None:
            held.update(kind="other", other="a mouse joint" if j.type == b2.JointType.MOUSE_JOINT else "a filter joint")
            return
        held["kind"], read = fields
        held.update(read)
        record = self.records.get(int(j.id))
        written = held["body_a"] != _NONE and held["body_b"] != _NONE
        if record is None and written:
            self.reports.append(Report("lossy-capture", "joint", len(self.joints) - 1, None, "pyb2d3 cannot read a joint's collide_connected, reference angle or axis: box2scene did not build this joint, so they were written at their defaults"))
        record = record or {}
        held.update(collide_connected=record.get("collide_connected", False), reference_angle=record.get("reference_angle", 0.0), axis=record.get("local_axis_a", (1.0, 0.0)))


def capture_world(
    world: b2.World,
    built: Optional[Built] = None,
    bodies: Sequence[b2.Body] = (),
    joints: Sequence[b2.Joint] = (),
    names: Optional[Sequence[Optional[str]]] = None,
) -> Tuple[Scene, List[Report]]:
    """A scene of what ``built`` made that the world still holds (with the scene's names and
    UserData, its joints in the scene's order), then of the host's own ``bodies`` (their shapes with them; named by
    ``names``, or else by their Box2D names) and those of its ``joints`` whose two bodies
    are saved, with the world's gravity; and the reports of what the format cannot hold
    exactly or has no form for. Written and loaded, it builds a world that evolves bit for
    bit like this one. Raises :class:`box2scene.Error` when a body is given twice."""
    reader = _Reader(world, built, bodies, names)
    reader.read_joints(built, joints)
    level = built._scene._native if built is not None else None
    native, said = _native.capture(ENGINE, _vec(world.gravity), reader.bodies, reader.joints, [], level)
    return Scene(native), reader.reports + [Report(*r) for r in said]
