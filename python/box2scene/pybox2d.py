"""Build a scene into a pybox2d world (the ``box2d`` package 2.3.10: Box2D 2.3), and capture
one back into a scene.

    import Box2D, box2scene, box2scene.pybox2d as b2s2
    scene = box2scene.load("level.xml")
    world = b2s2.create_world(scene, fallback_gravity=(0, -10))
    built = b2s2.build_world(scene, world)
    for _ in range(600): world.Step(1 / 60, 8, 3)
    saved, reports = b2s2.capture_world(world, built)

Box2D 2.3 is the engine the format's Version 2 files were written for, so more of a scene
is exact here than in Box2D 2.4 or v3: distance joints keep ``FrequencyHz`` and
``DampingRatio`` as they are (2.4 needs a stiffness computed from the masses), a rope is
Box2D's rope joint, a wheel joint's spring is 2.2's, a weld joint's spring is 2.2's soft
weld, the motor and friction joints are Box2D's own, an edge keeps each ghost vertex on
its own (2.4 needs both), and a chain takes the ghosts the file gives (none extrapolated).
What 2.3 lacks is reported: a line joint's linear motor (``lossy-line-motor``) and limit
(2.3's wheel joint has none), and a wheel joint without a spring, which gets a stand-in.
Pulley ``MaxLengthA``/``MaxLengthB`` (2.1 only) become rope joints from a static body, a
polygon's ``Centroid`` is applied as in the 2.4 adapter. Filter bits are 16 wide.

The library plans the world (``make_plan``: every conversion, check, predicted mass and
report); this module creates what the plan says through pybox2d, in its order.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import Box2D as B

from . import _native
from ._error import Error
from ._report import Report
from ._scene import Scene

__all__ = ["Built", "Report", "build_world", "capture_world", "create_world", "scene_gravity"]

ENGINE = "box2d-2.3"


@dataclass
class Built:
    """What :func:`build_world` created, index for index with the scene: ``bodies[i]`` for
    body ``i``, ``fixtures[k]`` for the fixture at slot ``k`` of the scene's
    ``fixture_ids``, ``joints[j]`` for joint ``j``; None where nothing was created
    (``reports`` says why)."""

    bodies: List[Optional[B.b2Body]]
    fixtures: List[Optional[B.b2Fixture]]
    joints: List[Optional[B.b2Joint]]
    reports: List[Report] = field(default_factory=list)
    # What capture needs: the scene (the level's names, order and skipped joints), the plan
    # (what the build gave a joint that 2.3's bindings cannot read back), and the userData
    # the build gives its fixtures and joints, which tells them from ones the host makes
    # later at their freed addresses (Box2D reuses them). One object a build, since pybox2d
    # never releases a joint's userData when its world goes.
    _scene: Optional[Scene] = field(default=None, repr=False, compare=False)
    _mark: object = field(default_factory=object, repr=False, compare=False)
    _plan: object = field(default=None, repr=False, compare=False)


def scene_gravity(scene: Scene, fallback: Tuple[float, float] = (0.0, -10.0)) -> Tuple[float, float]:
    """The scene's gravity, or ``fallback`` when it gives none or one beyond the range."""
    gravity = _native.world_gravity(scene._native, ENGINE)
    return fallback if gravity is None else gravity


def create_world(scene: Scene, fallback_gravity: Tuple[float, float] = (0.0, -10.0), **settings) -> B.b2World:
    """A pybox2d world for ``scene``: its gravity (or the fallback); ``settings`` are
    pybox2d's other world settings."""
    return B.b2World(gravity=scene_gravity(scene, fallback_gravity), **settings)


def _key(joint) -> int:
    return int(joint.this)


def _vertices(points) -> List[Tuple[float, float]]:
    return [tuple(p) for p in points]


def _given(point) -> bool:
    """A ghost vertex the plan gives (NaN where the file gives none)."""
    return not math.isnan(point[0])


def _shape(shape):
    """A pybox2d shape of the plan's: Box2D 2.3 keeps each ghost vertex of an edge or chain
    on its own."""
    kind, points = shape.kind, shape.points
    if kind == "circle":
        return B.b2CircleShape(radius=shape.radius, pos=shape.center)
    if kind == "polygon":
        made = B.b2PolygonShape(vertices=_vertices(points))
        if not math.isnan(shape.center[0]):
            made.centroid = shape.center
        return made
    if kind == "segment":
        if len(points) == 2:
            return B.b2EdgeShape(vertices=_vertices(points))
        made = B.b2EdgeShape(vertices=_vertices(points[1:3]))
        if _given(points[0]):
            made.vertex0, made.hasVertex0 = points[0], True
        if _given(points[3]):
            made.vertex3, made.hasVertex3 = points[3], True
        return made
    if kind == "loop":
        return B.b2ChainShape(vertices_loop=_vertices(points))
    made = B.b2ChainShape(vertices_chain=_vertices(points[1:-1]))
    if _given(points[0]):
        made.SetPrevVertex(points[0])
    if _given(points[-1]):
        made.SetNextVertex(points[-1])
    return made


def _joint_def(j, made: List[B.b2Joint]):
    """pybox2d's def of the plan joint ``j``; ``made`` holds the plan joints created so far."""
    kind = j.kind
    anchors = dict(localAnchorA=j.anchor_a, localAnchorB=j.anchor_b)
    if kind == "revolute":
        return B.b2RevoluteJointDef(referenceAngle=j.reference_angle, enableLimit=j.enable_limit, lowerAngle=j.lower, upperAngle=j.upper, enableMotor=j.enable_motor, motorSpeed=j.motor_speed, maxMotorTorque=j.max_motor, **anchors)
    if kind == "prismatic":
        return B.b2PrismaticJointDef(localAxisA=j.axis, referenceAngle=j.reference_angle, enableLimit=j.enable_limit, lowerTranslation=j.lower, upperTranslation=j.upper, enableMotor=j.enable_motor, maxMotorForce=j.max_motor, motorSpeed=j.motor_speed, **anchors)
    if kind == "distance":
        return B.b2DistanceJointDef(length=j.length, frequencyHz=j.hertz, dampingRatio=j.damping_ratio, **anchors)
    if kind == "rope":
        return B.b2RopeJointDef(maxLength=j.length, **anchors)
    if kind == "wheel":
        return B.b2WheelJointDef(localAxisA=j.axis, frequencyHz=j.hertz, dampingRatio=j.damping_ratio, enableMotor=j.enable_motor, maxMotorTorque=j.max_motor, motorSpeed=j.motor_speed, **anchors)
    if kind == "weld":
        return B.b2WeldJointDef(referenceAngle=j.reference_angle, frequencyHz=j.hertz, dampingRatio=j.damping_ratio, **anchors)
    if kind == "friction":
        return B.b2FrictionJointDef(maxForce=j.max_force, maxTorque=j.max_torque, **anchors)
    if kind == "motor":
        return B.b2MotorJointDef(linearOffset=j.linear_offset, angularOffset=j.angular_offset, maxForce=j.max_force, maxTorque=j.max_torque, correctionFactor=j.correction_factor)
    if kind == "pulley":
        return B.b2PulleyJointDef(groundAnchorA=j.ground_anchor_a, groundAnchorB=j.ground_anchor_b, lengthA=j.length_a, lengthB=j.length_b, ratio=j.ratio, **anchors)
    return B.b2GearJointDef(joint1=made[j.joint_a], joint2=made[j.joint_b], ratio=j.ratio)


class _Build:
    def __init__(self, scene: Scene, world: B.b2World, plan):
        self.world = world
        reports = [Report(*r) for r in plan.reports]
        slots = [None] * plan.slot_count
        self.built = Built([None] * plan.body_count, slots, [None] * plan.joint_count, reports, scene, _plan=plan)
        # One pybox2d shape per scene shape, which Box2D clones into each of its fixtures.
        self.shapes: Dict[int, object] = {}
        # Index for index with the plan's joints: what a gear couples.
        self.made: List[B.b2Joint] = []

    def make_fixture(self, shape, body: B.b2Body) -> None:
        made = self.shapes.get(shape.shape)
        if made is None:
            made = self.shapes[shape.shape] = _shape(shape)
        self.built.fixtures[shape.slot] = body.CreateFixture(
            B.b2FixtureDef(
                shape=made,
                density=shape.density,
                friction=shape.friction,
                restitution=shape.restitution,
                isSensor=shape.is_sensor,
                categoryBits=shape.category_bits,
                maskBits=shape.mask_bits,
                groupIndex=shape.group_index,
                userData=self.built._mark,
            )
        )

    def make_body(self, body) -> None:
        created = self.world.CreateBody(
            B.b2BodyDef(
                type=body.kind,
                position=body.position,
                angle=body.angle,
                linearVelocity=body.linear_velocity,
                angularVelocity=body.angular_velocity,
                linearDamping=body.linear_damping,
                angularDamping=body.angular_damping,
                gravityScale=body.gravity_scale,
                allowSleep=body.allow_sleep,
                awake=body.awake,
                bullet=body.bullet,
                fixedRotation=body.fixed_rotation,
                active=body.enabled,
            )
        )
        for shape in body.shapes:
            self.make_fixture(shape, created)
        if body.set_mass:
            data = created.massData
            data.mass, data.center, data.I = body.mass, body.center, body.inertia
            created.massData = data
        if body.set_velocity:
            created.linearVelocity = body.velocity_after_mass
        self.built.bodies[body.body] = created

    def make_joint(self, j) -> None:
        d = _joint_def(j, self.made)
        d.bodyA, d.bodyB, d.collideConnected = self.built.bodies[j.body_a], self.built.bodies[j.body_b], j.collide_connected
        d.userData = self.built._mark
        created = self.world.CreateJoint(d)
        self.made.append(created)
        if j.joint < len(self.built.joints):  # not a rope the plan adds to a pulley's side
            self.built.joints[j.joint] = created


def build_world(scene: Scene, world: B.b2World) -> Built:
    """Creates every object of ``scene`` that Box2D 2.3 can hold in ``world`` and reports
    the rest (never asserting, never producing NaN)."""
    g = world.gravity
    plan = _native.make_plan(scene._native, ENGINE, (float(g[0]), float(g[1])))
    b = _Build(scene, world, plan)
    for body in plan.bodies:
        b.make_body(body)
    for joint in plan.joints:
        b.make_joint(joint)
    # pybox2d's fixture def takes a shape from Python and never frees it; Box2D cloned each
    # into its fixtures, so the build's own shapes go with the build.
    for shape in b.shapes.values():
        shape.thisown = True
    return b.built


# ---- capture: the world read through pybox2d's getters into the held records (the plan's
# own, read back), which the library turns into a scene and the reports

_NONE = 0xFFFFFFFF
_NAN = (math.nan, math.nan)

_JOINT_CLASSES = [
    ("revolute", B.b2RevoluteJoint),
    ("prismatic", B.b2PrismaticJoint),
    ("distance", B.b2DistanceJoint),
    ("rope", B.b2RopeJoint),
    ("wheel", B.b2WheelJoint),
    ("weld", B.b2WeldJoint),
    ("friction", B.b2FrictionJoint),
    ("motor", B.b2MotorJoint),
    ("pulley", B.b2PulleyJoint),
    ("gear", B.b2GearJoint),
]


def _vec(v) -> Tuple[float, float]:
    return (float(v[0]), float(v[1]))


def _anchors():
    return [("anchor_a", lambda j: j.GetLocalAnchorA()), ("anchor_b", lambda j: j.GetLocalAnchorB())]


def _limit_and_motor(max_motor):
    return [
        ("reference_angle", lambda j: j.GetReferenceAngle()),
        ("enable_limit", lambda j: j.limitEnabled),
        ("lower", lambda j: j.lowerLimit),
        ("upper", lambda j: j.upperLimit),
        ("enable_motor", lambda j: j.motorEnabled),
        ("motor_speed", lambda j: j.motorSpeed),
        ("max_motor", max_motor),
    ]


# What each kind holds, read through pybox2d's getters into the plan's joint fields (a
# rope's maximum is the plan's length, as its def takes it).
_HELD = {
    "revolute": _anchors() + _limit_and_motor(lambda j: j.GetMaxMotorTorque()),
    "prismatic": _anchors() + [("axis", lambda j: j.GetLocalAxisA())] + _limit_and_motor(lambda j: j.maxMotorForce),
    "distance": _anchors() + [("length", lambda j: j.length), ("hertz", lambda j: j.frequency), ("damping_ratio", lambda j: j.dampingRatio)],
    "rope": _anchors() + [("length", lambda j: j.maxLength)],
    "wheel": _anchors()
    + [
        ("axis", lambda j: j.GetLocalAxisA()),
        ("hertz", lambda j: j.springFrequencyHz),
        ("damping_ratio", lambda j: j.springDampingRatio),
        ("enable_motor", lambda j: j.motorEnabled),
        ("motor_speed", lambda j: j.motorSpeed),
        ("max_motor", lambda j: j.GetMaxMotorTorque()),
    ],
    "weld": _anchors() + [("reference_angle", lambda j: j.GetReferenceAngle()), ("hertz", lambda j: j.GetFrequency()), ("damping_ratio", lambda j: j.GetDampingRatio())],
    "friction": _anchors() + [("max_force", lambda j: j.maxForce), ("max_torque", lambda j: j.maxTorque)],
    "motor": [
        ("linear_offset", lambda j: j.linearOffset),
        ("angular_offset", lambda j: j.angularOffset),
        ("max_force", lambda j: j.maxForce),
        ("max_torque", lambda j: j.maxTorque),
        ("correction_factor", lambda j: j.GetCorrectionFactor()),
    ],
    "pulley": _anchors()
    + [
        ("ground_anchor_a", lambda j: j.groundAnchorA),
        ("ground_anchor_b", lambda j: j.groundAnchorB),
        ("length_a", lambda j: j.lengthA),
        ("length_b", lambda j: j.lengthB),
        ("ratio", lambda j: j.ratio),
    ],
    "gear": [("ratio", lambda j: j.ratio)],
}

_PAIRS = ("anchor_a", "anchor_b", "axis", "ground_anchor_a", "ground_anchor_b", "linear_offset")
_FLAGS = ("collide_connected", "enable_limit", "enable_motor")


def _joint_defaults() -> Dict[str, object]:
    held: Dict[str, object] = {f: (0.0, 0.0) for f in _PAIRS}
    held.update({f: False for f in _FLAGS})
    for f in ("reference_angle", "length_a", "length_b", "ratio", "lower", "upper", "length", "min_length", "max_length", "motor_speed", "max_motor", "stiffness", "damping", "hertz", "damping_ratio", "angular_offset", "max_force", "max_torque", "correction_factor"):
        held[f] = 0.0
    held.update(joint=_NONE, joint_a=_NONE, joint_b=_NONE, name=None, other=None)
    return held


def _ghost(given: bool, vertex) -> Tuple[float, float]:
    """A ghost vertex as the plan gives it to Box2D 2.3: NaN where the shape has none."""
    return _vec(vertex) if given else _NAN


def _held_shape(s) -> Dict[str, object]:
    """The shape's kind, points, centre and skin in the plan's terms."""
    t = s.type
    if t == B.b2Shape.e_circle:
        return dict(kind="circle", points=[], center=_vec(s.pos), radius=float(s.radius))
    held = dict(center=(0.0, 0.0), radius=float(s.radius))
    if t == B.b2Shape.e_polygon:
        return dict(held, kind="polygon", points=[_vec(v) for v in s.vertices], center=_vec(s.centroid))
    if t == B.b2Shape.e_edge:
        ends = [_vec(s.vertex1), _vec(s.vertex2)]
        if s.hasVertex0 or s.hasVertex3:
            ends = [_ghost(s.hasVertex0, s.vertex0)] + ends + [_ghost(s.hasVertex3, s.vertex3)]
        return dict(held, kind="segment", points=ends)
    if t == B.b2Shape.e_chain:
        vertices = [_vec(v) for v in s.vertices]
        ghosts = _ghost(s.m_hasPrevVertex, s.m_prevVertex), _ghost(s.m_hasNextVertex, s.m_nextVertex)
        return dict(held, kind="chain", points=[ghosts[0]] + vertices + [ghosts[1]])
    return dict(held, kind="other", points=[], other=f"Box2D shape type {t}")


class _Reader:
    """What ``capture_world`` saves, read into the held records: the bodies the build made
    that the world still holds, then the host's ``bodies``; the build's joints the world
    still holds (a joint at a built joint's address without the build's userData is the
    host's), then the host's ``joints``."""

    def __init__(self, world: B.b2World, built: Optional[Built], bodies: Sequence[B.b2Body], names: Optional[Sequence[Optional[str]]]):
        names = list(names) if names is not None else [None] * len(bodies)
        if len(names) != len(bodies):
            raise Error("invalid-argument", 0, 0, 0, f"{len(names)} names for {len(bodies)} bodies")
        self.built = built
        self.mark = built._mark if built is not None else None
        self.reports: List[Report] = []
        # (body, its scene index or _NONE, the host's name)
        saved: List[Tuple[B.b2Body, int, Optional[str]]] = []
        self.slots: Dict[int, int] = {}
        self.plan_joints: Dict[int, object] = {}
        if built is not None:
            live = {int(b.this) for b in world.bodies}
            saved += [(b, i, None) for i, b in enumerate(built.bodies) if b is not None and int(b.this) in live]
            self.slots = {int(f.this): slot for slot, f in enumerate(built.fixtures) if f is not None}
            self.plan_joints = {j.joint: j for j in built._plan.joints if j.joint < len(built.joints)}
        saved += [(b, _NONE, name) for b, name in zip(bodies, names)]
        self.index_of: Dict[int, int] = {}
        for i, (body, _, _) in enumerate(saved):
            key = int(body.this)
            if key in self.index_of:
                raise Error("invalid-argument", 0, 0, 0, f"bodies {self.index_of[key]} and {i} are the same body")
            self.index_of[key] = i
        self.bodies = [self.held_body(*entry) for entry in saved]
        self.joints: List[Dict[str, object]] = []
        self.joint_of: Dict[int, int] = {}

    def held_fixture(self, f) -> Dict[str, object]:
        data = f.filterData
        built = f.userData is self.mark and self.mark is not None
        held = dict(
            slot=self.slots.get(int(f.this), _NONE) if built else _NONE,
            density=float(f.density),
            friction=float(f.friction),
            restitution=float(f.restitution),
            is_sensor=bool(f.sensor),
            category_bits=int(data.categoryBits),
            mask_bits=int(data.maskBits),
            group_index=int(data.groupIndex),
            restitution_threshold=math.nan,  # Box2D 2.3 has none
            name=None,
            shape_name=None,
            other=None,
        )
        held.update(_held_shape(f.shape))
        return held

    def held_body(self, body: B.b2Body, index: int, name: Optional[str]) -> Dict[str, object]:
        mass = body.massData
        q = body.transform.q
        return dict(
            body=index,
            kind=int(body.type),
            position=_vec(body.position),
            angle=float(body.angle),
            rotation=(float(q.c), float(q.s)),
            linear_velocity=_vec(body.linearVelocity),
            angular_velocity=float(body.angularVelocity),
            linear_damping=float(body.linearDamping),
            angular_damping=float(body.angularDamping),
            gravity_scale=float(body.gravityScale),
            mass=float(mass.mass),
            center=_vec(mass.center),
            inertia=float(mass.I),
            allow_sleep=bool(body.sleepingAllowed),
            awake=bool(body.awake),
            fixed_rotation=bool(body.fixedRotation),
            bullet=bool(body.bullet),
            enabled=bool(body.active),
            name=name,
            # pybox2d lists a body's fixtures in the order they were created
            shapes=[self.held_fixture(f) for f in body.fixtures],
        )

    def read_joints(self, world: B.b2World, joints: Sequence[B.b2Joint]) -> List[int]:
        """The joints to save, read; returns the scene joints the build skipped."""
        built = self.built
        skipped: List[int] = []
        if built is not None:
            live = {_key(j): j for j in world.joints}
            made = []
            for index, joint in enumerate(built.joints):
                if joint is None:
                    skipped.append(index)
                elif _key(joint) in live and live[_key(joint)].userData is built._mark:
                    made.append((index, live[_key(joint)]))
                elif _key(joint) in live:
                    self.reports.append(Report("lossy-capture", "joint", index, built._scene.joints[index].name, f"the joint built for scene joint {index} was destroyed, or its userData replaced: the joint at its address is taken as the host's, saved only when given in joints"))
            # in the order the build made them: a gear after every other joint
            for index, joint in sorted(made, key=lambda m: isinstance(m[1], B.b2GearJoint)):
                self.read_joint(joint, index)
        for joint in joints:
            if _key(joint) not in self.joint_of:
                self.read_joint(joint, _NONE)
        return skipped

    def read_joint(self, j, index: int) -> None:
        held = _joint_defaults()
        held.update(joint=index, body_a=self.index_of.get(int(j.bodyA.this), _NONE), body_b=self.index_of.get(int(j.bodyB.this), _NONE))
        held["collide_connected"] = bool(j.collideConnected)
        kind = next((k for k, cls in _JOINT_CLASSES if isinstance(j, cls)), None)
        self.joint_of[_key(j)] = len(self.joints)
        self.joints.append(held)
        if kind is None:
            held.update(kind="other", other="a mouse joint (a host's drag)" if isinstance(j, B.b2MouseJoint) else f"Box2D joint type {j.type}")
            return
        held["kind"] = kind
        planned = self.plan_joints.get(index)
        unread = []
        for field_name, read in _HELD[kind]:
            try:
                value = read(j)
            except AttributeError:
                # what the build gave a joint it made; a host's keeps the def's default
                if planned is not None:
                    held[field_name] = getattr(planned, field_name)
                else:
                    unread.append(field_name)
                continue
            held[field_name] = _vec(value) if field_name in _PAIRS else bool(value) if field_name in _FLAGS else float(value)
        if unread:
            self.reports.append(Report("lossy-capture", "joint", len(self.joints) - 1, None, f"pybox2d cannot read {', '.join(unread)} of a joint box2scene did not build: written at their defaults"))
        if kind == "gear" and planned is not None:
            # the joints the level's gear couples, as the build made them
            record = self.built._scene.joints[index]
            held["joint_a"] = self.held_joint(record.joint_a)
            held["joint_b"] = self.held_joint(record.joint_b)

    def held_joint(self, scene_index: Optional[int]) -> int:
        """The held index of the joint the build made for scene joint ``scene_index``."""
        if scene_index is None or scene_index >= len(self.built.joints) or self.built.joints[scene_index] is None:
            return _NONE
        return self.joint_of.get(_key(self.built.joints[scene_index]), _NONE)


def capture_world(
    world: B.b2World,
    built: Optional[Built] = None,
    bodies: Sequence[B.b2Body] = (),
    joints: Sequence[B.b2Joint] = (),
    names: Optional[Sequence[Optional[str]]] = None,
) -> Tuple[Scene, List[Report]]:
    """A scene of what ``built`` made that the world still holds (with the scene's names and
    UserData, its joints in the scene's order, the ones the build skipped written back as
    the file has them), then of the host's own ``bodies`` (with their fixtures; Box2D 2.3's
    bodies have no names, so ``names`` gives body ``i`` of them its own) and ``joints``,
    with the world's gravity; and the reports of what the format cannot hold exactly or has
    no form for. Written and loaded, it builds a world that moves like this one. Raises
    :class:`box2scene.Error` when a body is given twice."""
    reader = _Reader(world, built, bodies, names)
    skipped = reader.read_joints(world, joints)
    level = built._scene._native if built is not None else None
    native, said = _native.capture(ENGINE, _vec(world.gravity), reader.bodies, reader.joints, skipped, level)
    return Scene(native), reader.reports + [Report(*r) for r in said]
