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
from ._lookup import Lookups
from ._report import Report
from ._scene import Scene

__all__ = ["Built", "Report", "build_world", "capture_world", "create_world", "scene_gravity"]

ENGINE = "box2d-2.3"


@dataclass
class Built(Lookups):
    """What :func:`build_world` created, index for index with the scene: ``bodies[i]`` for
    body ``i``, ``fixtures[k]`` for the fixture at slot ``k`` of the scene's
    ``fixture_ids``, ``joints[j]`` for joint ``j``; None where nothing was created
    (``reports`` says why)."""

    bodies: List[Optional[B.b2Body]]
    fixtures: List[Optional[B.b2Fixture]]
    joints: List[Optional[B.b2Joint]]
    reports: List[Report] = field(default_factory=list)
    # What capture needs: the scene (what 2.3's bindings cannot read back, and the names),
    # and the userData the build gives its bodies, fixtures and joints, which tells them from
    # ones the host makes later at their freed addresses (Box2D reuses them). One object a build, since
    # pybox2d never releases a joint's userData when its world goes.
    _scene: Optional[Scene] = field(default=None, repr=False, compare=False)
    _mark: object = field(default_factory=object, repr=False, compare=False)
    # The plan's record of each joint built, index for index with ``joints`` (what pybox2d
    # has no getter for), and the scene joints each built gear couples.
    _plans: List[object] = field(default_factory=list, repr=False, compare=False)
    _coupled: Dict[int, Tuple[int, int]] = field(default_factory=dict, repr=False, compare=False)

    def _same(self, made, wanted) -> bool:
        """pybox2d wraps one Box2D object in many Python objects: its address and the
        build's mark tell them apart (Box2D gives a freed address to a later object)."""
        return int(made.this) == int(wanted.this) and wanted.userData is self._mark


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
        self.built = Built([None] * plan.body_count, slots, [None] * plan.joint_count, reports, scene)
        self.built._plans = [None] * plan.joint_count
        # One pybox2d shape per scene shape, which Box2D clones into each of its fixtures.
        self.shapes: Dict[int, object] = {}
        # Index for index with the plan's joints: what a gear couples.
        self.made: List[B.b2Joint] = []
        self.plans: List[object] = []

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
                userData=self.built._mark,
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
            self.built._plans[j.joint] = j
        if j.kind == "gear":
            self.built._coupled[j.joint] = (self.plans[j.joint_a].joint, self.plans[j.joint_b].joint)
        self.plans.append(j)


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


# ---- capture: pybox2d's getters read into the library's held records

_NONE = 0xFFFFFFFF
_NAN = (math.nan, math.nan)


def _vec(v) -> Tuple[float, float]:
    return (float(v[0]), float(v[1]))


def _held_shape(s) -> dict:
    """A shape as Box2D 2.3 holds it: an edge's and a chain's ghost vertices each NaN where
    it has none."""
    t = s.type
    if t == B.b2Shape.e_circle:
        return dict(kind="circle", center=_vec(s.pos), radius=float(s.radius))
    if t == B.b2Shape.e_polygon:
        return dict(kind="polygon", points=[_vec(v) for v in s.vertices], center=_vec(s.centroid), radius=float(s.radius))
    if t == B.b2Shape.e_edge:
        ends = [_vec(s.vertex1), _vec(s.vertex2)]
        if not (s.hasVertex0 or s.hasVertex3):
            return dict(kind="segment", points=ends, radius=float(s.radius))
        ghosts = (_vec(s.vertex0) if s.hasVertex0 else _NAN, _vec(s.vertex3) if s.hasVertex3 else _NAN)
        return dict(kind="segment", points=[ghosts[0]] + ends + [ghosts[1]], radius=float(s.radius))
    prev = _vec(s.m_prevVertex) if s.m_hasPrevVertex else _NAN
    after = _vec(s.m_nextVertex) if s.m_hasNextVertex else _NAN
    return dict(kind="chain", points=[prev] + [_vec(v) for v in s.vertices] + [after], radius=float(s.radius))


def _body(body: B.b2Body, record: int, name: Optional[str], slots: Dict[int, int], mark: object) -> dict:
    shapes = []
    for f in body.fixtures:  # pybox2d lists them in the order they were created
        data = f.filterData
        held = _held_shape(f.shape)
        held.update(
            slot=slots.get(int(f.this), _NONE) if f.userData is mark else _NONE,
            density=float(f.density),
            friction=float(f.friction),
            restitution=float(f.restitution),
            is_sensor=bool(f.sensor),
            category_bits=int(data.categoryBits),
            mask_bits=int(data.maskBits),
            group_index=int(data.groupIndex),
        )
        shapes.append(held)
    xf = body.transform
    m = body.massData
    return dict(
        body=record,
        kind=int(body.type),
        name=name,
        position=_vec(body.position),
        angle=float(body.angle),
        rotation=(float(xf.q.c), float(xf.q.s)),
        linear_velocity=_vec(body.linearVelocity),
        angular_velocity=float(body.angularVelocity),
        linear_damping=float(body.linearDamping),
        angular_damping=float(body.angularDamping),
        gravity_scale=float(body.gravityScale),
        mass=float(m.mass),
        center=_vec(m.center),
        inertia=float(m.I),
        allow_sleep=bool(body.sleepingAllowed),
        awake=bool(body.awake),
        bullet=bool(body.bullet),
        fixed_rotation=bool(body.fixedRotation),
        enabled=bool(body.active),
        shapes=shapes,
    )


def _anchors():
    return [("anchor_a", lambda j: _vec(j.GetLocalAnchorA())), ("anchor_b", lambda j: _vec(j.GetLocalAnchorB()))]


def _limits():
    return [("enable_limit", lambda j: bool(j.limitEnabled)), ("lower", lambda j: float(j.lowerLimit)), ("upper", lambda j: float(j.upperLimit))]


def _motor(maximum):
    return [("enable_motor", lambda j: bool(j.motorEnabled)), ("motor_speed", lambda j: float(j.motorSpeed)), ("max_motor", maximum)]


# Each joint class as the plan's kind, and the fields pybox2d reads of it: a field it has no
# getter for is the build's (the plan's record), or of a joint the host made, reported.
_JOINTS = [
    (B.b2RevoluteJoint, "revolute", _anchors() + [("reference_angle", lambda j: float(j.GetReferenceAngle()))] + _limits() + _motor(lambda j: float(j.GetMaxMotorTorque()))),
    (B.b2PrismaticJoint, "prismatic", _anchors() + [("axis", lambda j: _vec(j.GetLocalAxisA())), ("reference_angle", lambda j: float(j.GetReferenceAngle()))] + _limits() + _motor(lambda j: float(j.maxMotorForce))),
    (B.b2DistanceJoint, "distance", _anchors() + [("length", lambda j: float(j.length)), ("hertz", lambda j: float(j.frequency)), ("damping_ratio", lambda j: float(j.dampingRatio))]),
    (B.b2RopeJoint, "rope", _anchors() + [("length", lambda j: float(j.maxLength))]),
    (B.b2WheelJoint, "wheel", _anchors() + [("axis", lambda j: _vec(j.GetLocalAxisA())), ("hertz", lambda j: float(j.springFrequencyHz)), ("damping_ratio", lambda j: float(j.springDampingRatio))] + _motor(lambda j: float(j.GetMaxMotorTorque()))),
    (B.b2WeldJoint, "weld", _anchors() + [("reference_angle", lambda j: float(j.GetReferenceAngle())), ("hertz", lambda j: float(j.GetFrequency())), ("damping_ratio", lambda j: float(j.GetDampingRatio()))]),
    (B.b2FrictionJoint, "friction", _anchors() + [("max_force", lambda j: float(j.maxForce)), ("max_torque", lambda j: float(j.maxTorque))]),
    (
        B.b2MotorJoint,
        "motor",
        [
            ("linear_offset", lambda j: _vec(j.linearOffset)),
            ("angular_offset", lambda j: float(j.angularOffset)),
            ("max_force", lambda j: float(j.maxForce)),
            ("max_torque", lambda j: float(j.maxTorque)),
            ("correction_factor", lambda j: float(j.GetCorrectionFactor())),
        ],
    ),
    (
        B.b2PulleyJoint,
        "pulley",
        _anchors()
        + [
            ("ground_anchor_a", lambda j: _vec(j.groundAnchorA)),
            ("ground_anchor_b", lambda j: _vec(j.groundAnchorB)),
            ("length_a", lambda j: float(j.lengthA)),
            ("length_b", lambda j: float(j.lengthB)),
            ("ratio", lambda j: float(j.ratio)),
        ],
    ),
    (B.b2GearJoint, "gear", [("ratio", lambda j: float(j.ratio))]),
]


class _Read:
    """A world as pybox2d holds it, in the library's held records (dicts named as their
    fields)."""

    def __init__(self, world: B.b2World, built: Optional[Built]):
        self.reports: List[Report] = []
        self.mark = built._mark if built is not None else None
        self.slots = {int(f.this): k for k, f in enumerate(built.fixtures) if f is not None} if built is not None else {}
        # the joints the build made that the world still holds, by address, with their
        # scene joint: one at a built joint's address without the build's mark is the host's
        self.made: Dict[int, int] = {}
        if built is None:
            return
        live = {_key(j): j for j in world.joints}
        for index, joint in enumerate(built.joints):
            if joint is None or _key(joint) not in live:
                continue
            if live[_key(joint)].userData is built._mark:
                self.made[_key(joint)] = index
            else:
                self.reports.append(
                    Report(
                        "lossy-capture",
                        "joint",
                        index,
                        built._scene.joints[index].name,
                        f"the joint built for scene joint {index} was destroyed, or its userData replaced: the joint at its address is taken as the host's, saved only when given in joints",
                    )
                )

    def joint(self, j, index: int, index_of: Dict[int, int], built: Optional[Built], held_of: Dict[int, int]) -> dict:
        record = self.made.get(_key(j))
        plan = built._plans[record] if record is not None else None
        held = dict(
            joint=record if record is not None else _NONE,
            body_a=index_of.get(int(j.bodyA.this), _NONE),
            body_b=index_of.get(int(j.bodyB.this), _NONE),
            collide_connected=bool(j.collideConnected),
        )
        found = next(((kind, fields) for cls, kind, fields in _JOINTS if isinstance(j, cls)), None)
        if found is None:
            held["other"] = "a mouse joint"
            return held
        kind, fields = found
        held["kind"] = kind
        unread = []
        for name, read in fields:
            try:
                held[name] = read(j)
            except AttributeError:
                if plan is not None:
                    held[name] = getattr(plan, name)
                else:
                    unread.append(name)
        if unread:
            self.reports.append(Report("lossy-capture", "joint", index, None, f"pybox2d cannot read {', '.join(unread)} of a joint box2scene did not build: written at their defaults"))
        if kind == "gear":  # pybox2d cannot read what a gear couples: the build's, if it made it
            a, b = built._coupled[record] if plan is not None else (_NONE, _NONE)
            held.update(joint_a=held_of.get(a, _NONE), joint_b=held_of.get(b, _NONE))
        return held


def capture_world(
    world: B.b2World,
    built: Optional[Built] = None,
    bodies: Sequence[B.b2Body] = (),
    joints: Sequence[B.b2Joint] = (),
    names: Optional[Sequence[Optional[str]]] = None,
) -> Tuple[Scene, List[Report]]:
    """A scene of what ``built`` made that the world still holds (in the scene's order, with
    its names and UserData, the joints Box2D 2.3 could not hold written back where the file
    had them), then of the host's own ``bodies`` (with their fixtures; Box2D 2.3's bodies
    have no names, so ``names`` gives body ``i`` of them its own) and ``joints``, with the
    world's gravity; and the reports of what has no Box2Scene form. The library makes the
    scene of what pybox2d holds, as it does for the C++ adapter. Raises
    :class:`box2scene.Error` when a body is given twice."""
    if names is not None and len(names) != len(bodies):
        raise Error("invalid-argument", 0, 0, 0, f"{len(names)} names for {len(bodies)} bodies")
    read = _Read(world, built)
    mark = built._mark if built is not None else None
    live = {int(b.this) for b in world.bodies if b.userData is mark}
    made = [(b, i) for i, b in enumerate(built.bodies) if b is not None and int(b.this) in live] if built is not None else []
    given = [(b, _NONE) for b in bodies]
    labels = [None] * len(made) + (list(names) if names is not None else [None] * len(bodies))
    index_of: Dict[int, int] = {}
    for i, (body, _) in enumerate(made + given):
        if int(body.this) in index_of:
            raise Error("invalid-argument", 0, 0, 0, f"bodies {index_of[int(body.this)]} and {i} are the same body")
        index_of[int(body.this)] = i
    held_bodies = [_body(b, record, label, read.slots, read.mark) for (b, record), label in zip(made + given, labels)]
    by_key = {_key(j): j for j in world.joints}
    ordered = [by_key[key] for key, _ in sorted(read.made.items(), key=lambda item: item[1])]
    ordered += [j for j in joints if _key(j) not in read.made]
    held_of = {record: k for k, record in enumerate(sorted(read.made.values()))}
    held_joints = [read.joint(j, k, index_of, built, held_of) for k, j in enumerate(ordered)]
    skipped = [i for i, j in enumerate(built.joints) if j is None] if built is not None else []
    level = built._scene._native if built is not None else None
    native, reports = _native.capture(ENGINE, _vec(world.gravity), held_bodies, held_joints, skipped, level)
    return Scene(native), read.reports + [Report(*r) for r in reports]
