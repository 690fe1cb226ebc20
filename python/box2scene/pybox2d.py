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
from ._f32 import F, f32, search_ulps
from ._records import Body, Fixture, Joint, Shape
from ._report import Report
from ._scene import Builder, Scene

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
    # What capture needs: the scene (what 2.3's bindings cannot read back, and the names),
    # and the userData the build gives its fixtures and joints, which tells them from ones
    # the host makes later at their freed addresses (Box2D reuses them). One object a build, since
    # pybox2d never releases a joint's userData when its world goes.
    _scene: Optional[Scene] = field(default=None, repr=False, compare=False)
    _mark: object = field(default_factory=object, repr=False, compare=False)


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


def _shift(body: B.b2Body, w: float):
    """w x (centre of mass - origin), as Box2D computes it in floats."""
    xf = body.transform
    c, s = F(xf.q.c), F(xf.q.s)
    lx, ly = F(body.localCenter[0]), F(body.localCenter[1])
    px, py = F(xf.position[0]), F(xf.position[1])
    cx = (c * lx - s * ly) + px
    cy = (s * lx + c * ly) + py
    return (-F(w) * (cy - py), F(w) * (cx - px))


def _origin_velocity(body: B.b2Body, velocity, w: float):
    """The origin velocity whose centre velocity, as the build gives it, is ``velocity``."""
    shift = _shift(body, w)
    out = []
    for target, delta in zip(velocity, shift):
        _, before = search_ulps(f32(target - float(delta)), lambda x, t=target, d=delta: float(F(x) + d) == t)
        out.append(before)
    return tuple(out)


def _computed_mass(body: B.b2Body):
    """The mass data Box2D 2.3's ResetMassData gives ``body`` from its fixtures, as
    GetMassData reports it (inertia about the origin), operation for operation."""
    mass, cx, cy, inertia = F(0), F(0), F(0), F(0)
    for f in body.fixtures:
        if f.density == 0:
            continue
        m = f.massData
        mass += F(m.mass)
        cx = cx + F(m.mass) * F(m.center[0])
        cy = cy + F(m.mass) * F(m.center[1])
        inertia += F(m.I)
    if mass > 0:
        inverse = F(1) / mass
        cx, cy = inverse * cx, inverse * cy
    else:
        mass = F(1)
    dot = cx * cx + cy * cy
    if inertia > 0 and not body.fixedRotation:
        inertia -= mass * dot
    else:
        inertia = F(0)
    return float(mass), (float(cx), float(cy)), float(inertia + mass * dot)


# ---- capture

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
_JOINT_FIELDS = [f for f in Joint.__dataclass_fields__ if f not in ("kind", "name", "body_a", "body_b", "joint_a", "joint_b", "user_data")]


def _anchors():
    return [("local_anchor_a", lambda j: j.GetLocalAnchorA()), ("local_anchor_b", lambda j: j.GetLocalAnchorB())]


# What can change in a live joint, read back where pybox2d has a getter; the rest is what
# the builder gave the joint (and its defaults for a joint it did not build).
_LIVE = {
    "revolute": _anchors() + [
        ("reference_angle", lambda j: float(j.GetReferenceAngle())),
        ("enable_limit", lambda j: bool(j.limitEnabled)),
        ("lower_limit", lambda j: float(j.lowerLimit)),
        ("upper_limit", lambda j: float(j.upperLimit)),
        ("enable_motor", lambda j: bool(j.motorEnabled)),
        ("motor_speed", lambda j: float(j.motorSpeed)),
        ("max_motor_torque", lambda j: float(j.GetMaxMotorTorque())),
    ],
    "prismatic": _anchors() + [
        ("local_axis_a", lambda j: j.GetLocalAxisA()),
        ("reference_angle", lambda j: float(j.GetReferenceAngle())),
        ("enable_limit", lambda j: bool(j.limitEnabled)),
        ("lower_limit", lambda j: float(j.lowerLimit)),
        ("upper_limit", lambda j: float(j.upperLimit)),
        ("enable_motor", lambda j: bool(j.motorEnabled)),
        ("motor_speed", lambda j: float(j.motorSpeed)),
        ("max_motor_force", lambda j: float(j.maxMotorForce)),
    ],
    "distance": _anchors() + [
        ("length", lambda j: float(j.length)),
        ("frequency_hz", lambda j: float(j.frequency)),
        ("damping_ratio", lambda j: float(j.dampingRatio)),
    ],
    "rope": _anchors() + [("max_length", lambda j: float(j.maxLength))],
    "wheel": _anchors() + [
        ("local_axis_a", lambda j: j.GetLocalAxisA()),
        ("frequency_hz", lambda j: float(j.springFrequencyHz)),
        ("damping_ratio", lambda j: float(j.springDampingRatio)),
        ("enable_motor", lambda j: bool(j.motorEnabled)),
        ("motor_speed", lambda j: float(j.motorSpeed)),
        ("max_motor_torque", lambda j: float(j.GetMaxMotorTorque())),
    ],
    "line": _anchors() + [("local_axis_a", lambda j: j.GetLocalAxisA())],
    "weld": _anchors() + [
        ("reference_angle", lambda j: float(j.GetReferenceAngle())),
        ("frequency_hz", lambda j: float(j.GetFrequency())),
        ("damping_ratio", lambda j: float(j.GetDampingRatio())),
    ],
    "friction": _anchors() + [
        ("max_force", lambda j: float(j.maxForce)),
        ("max_torque", lambda j: float(j.maxTorque)),
    ],
    "motor": [
        ("linear_offset", lambda j: j.linearOffset),
        ("angular_offset", lambda j: float(j.angularOffset)),
        ("max_force", lambda j: float(j.maxForce)),
        ("max_torque", lambda j: float(j.maxTorque)),
        ("correction_factor", lambda j: float(j.GetCorrectionFactor())),
    ],
    "pulley": _anchors() + [
        ("ground_anchor_a", lambda j: j.groundAnchorA),
        ("ground_anchor_b", lambda j: j.groundAnchorB),
        ("length_a", lambda j: float(j.lengthA)),
        ("length_b", lambda j: float(j.lengthB)),
        ("ratio", lambda j: float(j.ratio)),
    ],
    "gear": [("ratio", lambda j: float(j.ratio))],
}


def _vec(v) -> Tuple[float, float]:
    return (float(v[0]), float(v[1]))


class _Capture:
    def __init__(self, world: B.b2World, built: Optional[Built], bodies: Sequence[B.b2Body], names: Optional[Sequence[Optional[str]]]):
        self.world = world
        self.scene = built._scene if built is not None else None
        names = list(names) if names is not None else [None] * len(bodies)
        if len(names) != len(bodies):
            raise Error("invalid-argument", 0, 0, 0, f"{len(names)} names for {len(bodies)} bodies")
        self.bodies: List[B.b2Body] = []
        self.names: List[Optional[str]] = []
        # The scene's joint for each joint the build made that still lives, by its key.
        self.built_joints: Dict[int, Joint] = {}
        self.scene_joints: Dict[int, int] = {}
        self.fixture_names: Dict[int, Optional[str]] = {}
        self.mark = built._mark if built is not None else None
        self.builder = Builder()
        self.reports: List[Report] = []
        if built is not None:
            self.take_built(built)
        self.bodies += list(bodies)
        self.names += names
        self.index_of: Dict[int, int] = {}
        for i, body in enumerate(self.bodies):
            key = int(body.this)
            if key in self.index_of:
                raise Error("invalid-argument", 0, 0, 0, f"bodies {self.index_of[key]} and {i} are the same body")
            self.index_of[key] = i
        self.joint_indices: Dict[int, int] = {}

    def take_built(self, built: Built) -> None:
        """The bodies the build made that the world still holds, with their scene names; and
        the joints it made that the world holds: a joint at a built joint's address without
        the userData the build gave it is the host's, made after the build's was destroyed."""
        live = {int(b.this) for b in self.world.bodies}
        for body, record in zip(built.bodies, self.scene.bodies):
            if body is not None and int(body.this) in live:
                self.bodies.append(body)
                self.names.append(record.name)
        for fixture, index in zip(built.fixtures, self.scene.fixture_ids):
            if fixture is not None:
                self.fixture_names[int(fixture.this)] = self.scene.fixtures[index].name
        live_joints = {_key(j): j for j in self.world.joints}
        for index, joint in enumerate(built.joints):
            if joint is None or _key(joint) not in live_joints:
                continue
            record = self.scene.joints[index]
            if live_joints[_key(joint)].userData is built._mark:
                self.built_joints[_key(joint)] = record
                self.scene_joints[index] = _key(joint)
            else:
                self.report(
                    "lossy-capture",
                    "joint",
                    index,
                    record.name,
                    f"the joint built for scene joint {index} was destroyed, or its userData replaced: the joint at its address is taken as the host's, saved only when given in joints",
                )

    def report(self, code: str, obj: str, index: int, name: Optional[str], message: str) -> None:
        self.reports.append(Report(code, obj, index, name, message))

    def capture_shape(self, s) -> Shape:
        t = s.type
        if t == B.b2Shape.e_circle:
            return Shape.new("circle", radius=float(s.radius), position=_vec(s.pos))
        if t == B.b2Shape.e_polygon:
            return Shape.new("polygon", vertices=tuple(_vec(v) for v in s.vertices), centroid=_vec(s.centroid))
        if t == B.b2Shape.e_edge:
            return Shape.new(
                "edge",
                vertices=(_vec(s.vertex1), _vec(s.vertex2)),
                prev_vertex=_vec(s.vertex0) if s.hasVertex0 else None,
                next_vertex=_vec(s.vertex3) if s.hasVertex3 else None,
            )
        vertices = [_vec(v) for v in s.vertices]
        loop = len(vertices) > 3 and vertices[0] == vertices[-1] and not s.m_hasPrevVertex and not s.m_hasNextVertex
        if loop:
            return Shape.new("chain", vertices=tuple(vertices[:-1]), is_loop=True)
        return Shape.new(
            "chain",
            vertices=tuple(vertices),
            prev_vertex=_vec(s.m_prevVertex) if s.m_hasPrevVertex else None,
            next_vertex=_vec(s.m_nextVertex) if s.m_hasNextVertex else None,
        )

    def capture_body(self, index: int) -> None:
        body = self.bodies[index]
        fixtures = []
        for f in body.fixtures:  # pybox2d lists them in the order they were created
            shape = self.builder.add_shape(self.capture_shape(f.shape))
            data = f.filterData
            fixtures.append(
                self.builder.add_fixture(
                    Fixture.new(
                        shape,
                        density=float(f.density),
                        friction=float(f.friction),
                        restitution=float(f.restitution),
                        is_sensor=bool(f.sensor),
                        category_bits=int(data.categoryBits),
                        mask_bits=int(data.maskBits),
                        group_index=int(data.groupIndex),
                        name=self.fixture_names.get(int(f.this)) if f.userData is self.mark else None,
                    )
                )
            )
        kind = {B.b2_staticBody: "static", B.b2_kinematicBody: "kinematic", B.b2_dynamicBody: "dynamic"}[body.type]
        changes = dict(
            position=_vec(body.position),
            angle=float(body.angle),
            linear_velocity=_vec(body.linearVelocity),
            angular_velocity=float(body.angularVelocity),
            linear_damping=float(body.linearDamping),
            angular_damping=float(body.angularDamping),
            gravity_scale=float(body.gravityScale),
            allow_sleep=bool(body.sleepingAllowed),
            awake=bool(body.awake),
            bullet=bool(body.bullet),
            fixed_rotation=bool(body.fixedRotation),
            active=bool(body.active),
            fixtures=tuple(fixtures),
        )
        if kind == "dynamic":
            changes["linear_velocity"] = _origin_velocity(body, changes["linear_velocity"], changes["angular_velocity"])
            actual = body.massData
            if (float(actual.mass), _vec(actual.center), float(actual.I)) != _computed_mass(body):
                changes.update(mass=float(actual.mass), center=_vec(actual.center), inertia=float(actual.I))
        self.builder.add_body(Body.new(kind, name=self.names[index], **changes))

    def capture_joints(self, joints: Sequence[B.b2Joint]) -> None:
        """The build's joints in the order it made them (a gear after the joints it couples),
        then the host's."""
        by_key = {_key(j): j for j in self.world.joints}
        made = sorted(self.scene_joints.items(), key=lambda item: self.scene.joints[item[0]].kind == "gear")
        for _, key in made:
            self.capture_joint(by_key[key])
        for joint in joints:
            if _key(joint) not in self.joint_indices:
                self.capture_joint(joint)

    def capture_joint(self, j) -> None:
        index = len(self.joint_indices)
        a = self.index_of.get(int(j.bodyA.this))
        b = self.index_of.get(int(j.bodyB.this))
        if a is None or b is None:
            self.report("lossy-capture", "joint", index, None, f"it connects body {b if a is None else a} to a body not saved; not written")
            return
        kind = next((k for k, cls in _JOINT_CLASSES if isinstance(j, cls)), None)
        if kind is None:
            self.report("lossy-capture", "joint", index, None, "a mouse joint has no Box2Scene form; not written")
            return
        built = self.built_joints.get(_key(j))
        if built is not None:
            kind = built.kind
            changes = {f: getattr(built, f) for f in _JOINT_FIELDS}
        else:
            changes = {f: getattr(Joint.new(kind, 0, 1), f) for f in _JOINT_FIELDS}
        unread = []
        for field_name, read in _LIVE[kind]:
            try:
                value = read(j)
            except AttributeError:
                unread.append(field_name)
                continue
            changes[field_name] = tuple(map(float, value)) if isinstance(value, B.b2Vec2) else value
        if built is not None and kind in ("line", "wheel") and built.frequency_hz == 0.0:
            # the plan's stand-in spring for none
            changes.update(frequency_hz=0.0, damping_ratio=built.damping_ratio)
        if built is None and unread:
            self.report("lossy-capture", "joint", index, None, f"pybox2d cannot read {', '.join(unread)} of a joint box2scene did not build: written at their defaults")
        if kind == "gear":
            coupled = (built.joint_a, built.joint_b) if built is not None else ()
            targets = [self.joint_indices.get(self.scene_joints.get(k, -1)) for k in coupled]
            if len(targets) != 2 or None in targets:
                self.report("lossy-capture", "joint", index, None, "the joints this gear couples were not written (or box2scene did not build it); not written")
                return
            changes.update(joint_a=targets[0], joint_b=targets[1])
        changes["collide_connected"] = bool(j.collideConnected)
        changes["name"] = built.name if built is not None else None
        self.builder.add_joint(Joint.new(kind, a, b, **changes))
        self.joint_indices[_key(j)] = index


def capture_world(
    world: B.b2World,
    built: Optional[Built] = None,
    bodies: Sequence[B.b2Body] = (),
    joints: Sequence[B.b2Joint] = (),
    names: Optional[Sequence[Optional[str]]] = None,
) -> Tuple[Scene, List[Report]]:
    """A scene of what ``built`` made that the world still holds (with the scene's names),
    then of the host's own ``bodies`` (with their fixtures; Box2D 2.3's bodies have no
    names, so ``names`` gives body ``i`` of them its own) and ``joints``, with the world's
    gravity; and the reports of what has no Box2Scene form. Written and loaded, it builds
    a world that moves like this one. Raises :class:`box2scene.Error` when a body is given
    twice."""
    c = _Capture(world, built, bodies, names)
    c.builder.set_gravity(_vec(world.gravity))
    for i in range(len(c.bodies)):
        c.capture_body(i)
    c.capture_joints(joints)
    return c.builder.finish(), c.reports
