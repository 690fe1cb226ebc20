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
(2.3's wheel joint has none), pulley ``MaxLengthA``/``MaxLengthB`` (2.1 only), a
polygon's ``Centroid`` is applied as in the 2.4 adapter. Filter bits are 16 wide.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Dict, List, Optional, Sequence, Tuple

import Box2D as B

from . import _native
from ._error import Error
from ._f32 import F, f32, search_ulps
from ._records import Body, Fixture, Joint, Shape
from ._report import Check, Report
from ._scene import Builder, Scene

__all__ = ["Built", "Report", "build_world", "capture_world", "create_world", "scene_gravity"]

ENGINE = "Box2D 2.3"
# The working range: the library's measured table for Box2D 2.3 as pybox2d holds it, 2.4's
# solver, whose measurements it shares (docs/working-range.md).
RANGE = SimpleNamespace(**_native.working_range("box2d-2.3"))
FILTER_BITS = 16
# Hz: the spring that stands in for none on a Box2D 2.3 wheel joint (see wheel_hertz).
SPRINGLESS_WHEEL_HZ = 1e-3

_KINDS = {"static": B.b2_staticBody, "kinematic": B.b2_kinematicBody, "dynamic": B.b2_dynamicBody}


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
    g = scene.gravity
    if g is None or not (abs(g[0]) <= RANGE.max_acceleration and abs(g[1]) <= RANGE.max_acceleration):
        return fallback
    return g


def create_world(scene: Scene, fallback_gravity: Tuple[float, float] = (0.0, -10.0), **settings) -> B.b2World:
    """A pybox2d world for ``scene``: its gravity (or the fallback); ``settings`` are
    pybox2d's other world settings."""
    return B.b2World(gravity=scene_gravity(scene, fallback_gravity), **settings)


def _key(joint) -> int:
    return int(joint.this)


class _Build:
    def __init__(self, scene: Scene, world: B.b2World):
        self.scene = scene
        self.world = world
        self.reports: List[Report] = []
        slots = len(scene.fixture_ids)
        self.built = Built([None] * len(scene.bodies), [None] * slots, [None] * len(scene.joints), self.reports, scene)
        self.shapes: List[Optional[object]] = [None] * len(scene.shapes)
        # Per body: the joint that already pulls it from further than the range's
        # max_pulled_violation.
        self.pulled: Dict[int, int] = {}
        self.slot_starts = []
        slot = 0
        for body in scene.bodies:
            self.slot_starts.append(slot)
            slot += len(body.fixtures)

    def report(self, code: str, obj: str, index: int, name: Optional[str], message: str) -> None:
        self.reports.append(Report(code, obj, index, name, message))

    def beyond(self, check: Check, obj: str, index: int, name: Optional[str], owner: str = "") -> None:
        self.report("beyond-box2d-range", obj, index, name, f"{owner}{check.problem}; {obj} not created")

    def check_gravity(self) -> None:
        g = self.scene.gravity
        if g is not None:
            check = Check(ENGINE)
            check.vector("Gravity", g, RANGE.max_acceleration, "m/s^2")
            if not check.passed:
                self.report("beyond-box2d-range", "world", 0, None, f"{check.problem}; scene_gravity gives the host's fallback instead")

    def check_filters(self) -> None:
        """Box2D 2.3 holds 16 filter bits: reported only where that changes what collides, a
        category bit above 16 in use (high mask bits matter only against those)."""
        high = 0
        for f in self.scene.fixtures:
            high |= f.category_bits >> FILTER_BITS
        if not high:
            return
        for i, f in enumerate(self.scene.fixtures):
            if f.category_bits >> FILTER_BITS or (f.mask_bits >> FILTER_BITS) & high not in (0, high):
                self.report(
                    "lossy-filter",
                    "fixture",
                    i,
                    f.name,
                    f"its filter (category 0x{f.category_bits:x}, mask 0x{f.mask_bits:x}) uses bits above Box2D 2.3's 16, which change what collides; the low 16 bits were used",
                )

    # ---- shapes

    def make_shape(self, index: int) -> None:
        shape = self.scene.shapes[index]
        check = Check(ENGINE)
        if shape.kind == "circle":
            check.magnitude("Radius", shape.radius, RANGE.max_length, "m")
            check.vector("Position", shape.position, RANGE.max_length, "m")
        for i, v in enumerate(shape.vertices):
            check.vector(f"Vertex {i}", v, RANGE.max_length, "m")
        for field_name, v in (("Centroid", shape.centroid), ("PrevVertex", shape.prev_vertex), ("NextVertex", shape.next_vertex)):
            if v is not None:
                check.vector(field_name, v, RANGE.max_length, "m")
        if not check.passed:
            self.beyond(check, "shape", index, shape.name)
            return
        vertices = [tuple(v) for v in shape.vertices]
        if shape.kind == "circle":
            made = B.b2CircleShape(radius=shape.radius, pos=shape.position)
        elif shape.kind == "polygon" and len(vertices) == 2:
            made = B.b2EdgeShape(vertices=vertices)
        elif shape.kind == "polygon":
            made = B.b2PolygonShape(vertices=vertices)
            if shape.centroid is not None:
                made.centroid = shape.centroid
        elif shape.kind == "edge":
            made = B.b2EdgeShape(vertices=vertices)
            if shape.prev_vertex is not None:
                made.vertex0, made.hasVertex0 = shape.prev_vertex, True
            if shape.next_vertex is not None:
                made.vertex3, made.hasVertex3 = shape.next_vertex, True
        elif shape.is_loop:
            made = B.b2ChainShape(vertices_loop=vertices)
        else:
            made = B.b2ChainShape(vertices_chain=vertices)
            if shape.prev_vertex is not None:
                made.SetPrevVertex(shape.prev_vertex)
            if shape.next_vertex is not None:
                made.SetNextVertex(shape.next_vertex)
        self.shapes[index] = made

    # ---- bodies

    @staticmethod
    def fixture_check(f: Fixture) -> Check:
        check = Check(ENGINE)
        check.magnitude("Density", f.density, RANGE.max_density, "kg/m^2")
        check.magnitude("Friction", f.friction, RANGE.max_friction, "")
        check.magnitude("Restitution", f.restitution, RANGE.max_friction, "")
        return check

    def body_check(self, body: Body) -> Check:
        check = Check(ENGINE)
        check.vector("Position", body.position, RANGE.max_length, "m")
        check.magnitude("Angle", body.angle, RANGE.max_angle, "rad")
        if body.kind != "static":
            check.vector("LinearVelocity", body.linear_velocity, RANGE.max_speed, "m/s")
            check.magnitude("AngularVelocity", body.angular_velocity, RANGE.max_speed, "rad/s")
        check.magnitude("LinearDamping", body.linear_damping, RANGE.max_damping, "1/s")
        check.magnitude("AngularDamping", body.angular_damping, RANGE.max_damping, "1/s")
        check.magnitude("GravityScale", body.gravity_scale, RANGE.max_gravity_scale, "")
        if body.kind == "dynamic" and check.passed:
            g = self.world.gravity
            check.vector("GravityScale times the world's gravity", (body.gravity_scale * g[0], body.gravity_scale * g[1]), RANGE.max_acceleration, "m/s^2")
        if body.center is not None:
            check.vector("MassData Center", body.center, RANGE.max_length, "m")
        return check

    def skip_fixtures_of(self, index: int, body: Body) -> None:
        for f in body.fixtures:
            self.report("skipped-dependent", "fixture", f, self.scene.fixtures[f].name, f"fixture {f} of body {index}: the body was not created; fixture skipped")

    def make_fixture(self, body_index: int, slot: int, index: int, body: B.b2Body) -> None:
        f = self.scene.fixtures[index]
        shape = self.shapes[f.shape]
        if shape is None:
            self.report("skipped-dependent", "fixture", index, f.name, f"fixture {index} of body {body_index} names shape {f.shape}, which was not created; fixture skipped")
            return
        check = self.fixture_check(f)
        if not check.passed:
            self.beyond(check, "fixture", index, f.name, f"fixture {index} of body {body_index}: ")
            return
        low = (1 << FILTER_BITS) - 1
        self.built.fixtures[slot] = body.CreateFixture(
            B.b2FixtureDef(
                shape=shape,
                density=f.density,
                friction=f.friction,
                restitution=f.restitution,
                isSensor=f.is_sensor,
                categoryBits=f.category_bits & low,
                maskBits=f.mask_bits & low,
                groupIndex=f.group_index,
                userData=self.built._mark,
            )
        )

    def mass_check(self, created: B.b2Body, body: Body) -> Tuple[Check, Optional[B.b2MassData]]:
        """The mass data to set (None to keep 2.3's), checked: 2.3 asserts that the inertia
        about the centre of mass stays positive."""
        check = Check(ENGINE)
        given = body.mass is not None or body.center is not None or body.inertia is not None
        data = created.massData
        if given:
            if body.mass is not None:
                data.mass = body.mass
            if body.center is not None:
                data.center = body.center
            if body.inertia is not None:
                data.I = body.inertia
            mass = data.mass if data.mass > 0 else 1.0
            central = data.I - mass * (data.center[0] ** 2 + data.center[1] ** 2)
            if data.I > 0 and not body.fixed_rotation and not central > 0:
                check.fail("its MassData leaves no positive inertia about the centre of mass (Inertia <= Mass * |Center|^2), which Box2D 2.3 asserts against")
        mass = data.mass if data.mass > 0 else 1.0
        central = data.I - mass * (data.center[0] ** 2 + data.center[1] ** 2)
        check.zero_or_within("its mass", data.mass, RANGE.min_mass, RANGE.max_mass, "kg")
        check.vector("its centre of mass", tuple(data.center), RANGE.max_length, "m")
        if not body.fixed_rotation and data.I > 0:
            check.zero_or_within("its inertia about the centre of mass", central, RANGE.min_inertia, RANGE.max_inertia, "kg m^2")
        return check, (data if given else None)

    def make_body(self, index: int) -> None:
        body = self.scene.bodies[index]
        check = self.body_check(body)
        if not check.passed:
            self.beyond(check, "body", index, body.name)
            self.skip_fixtures_of(index, body)
            return
        created = self.world.CreateBody(
            B.b2BodyDef(
                type=_KINDS[body.kind],
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
                active=body.active,
            )
        )
        kept = len(self.reports)
        start = self.slot_starts[index]
        for k, fixture in enumerate(body.fixtures):
            self.make_fixture(index, start + k, fixture, created)
        if body.kind == "dynamic":
            check, data = self.mass_check(created, body)
            if not check.passed:
                self.world.DestroyBody(created)
                del self.reports[kept:]
                for k in range(len(body.fixtures)):
                    self.built.fixtures[start + k] = None
                self.beyond(check, "body", index, body.name)
                self.skip_fixtures_of(index, body)
                return
            if data is not None:
                created.massData = data
            # Box2D shifts the centre's velocity each time a fixture moves the centre of
            # mass; the file's velocity is its origin's, given once the mass is final.
            velocity = _center_velocity(created, body.linear_velocity, body.angular_velocity)
            if velocity != _vec(created.linearVelocity) and body.awake:
                created.linearVelocity = velocity
        self.built.bodies[index] = created

    # ---- joints

    def anchor_check(self, check: Check, field_name: str, body: int, anchor, lever: float) -> None:
        created = self.built.bodies[body]
        if created.mass == 0:
            return
        center = created.localCenter
        r = math.hypot(anchor[0] - center[0], anchor[1] - center[1])
        mass = created.mass
        inertia = created.inertia - mass * (center[0] ** 2 + center[1] ** 2)
        compliance = 1.0 / mass + (r * r / inertia if inertia > 0 else 0.0)
        if not compliance <= RANGE.max_compliance:
            check.fail(f"{field_name}: the joint acts {r:.9g} m from the centre of mass of body {body}, where 1/m + r^2/I = {compliance:g} 1/kg lies beyond Box2D 2.3's working range (at most {RANGE.max_compliance:g} 1/kg)")
        elif lever > 0 and inertia > 0 and not r <= lever * math.sqrt(inertia / mass):
            check.fail(f"{field_name}: the joint acts {r / math.sqrt(inertia / mass):g} radii of gyration from the centre of mass of body {body}, beyond Box2D 2.3's working range for this joint (at most {lever:g})")

    def joint_check(self, j: Joint) -> Check:
        check = Check(ENGINE)
        for name, v in (("LocalAnchorA", j.local_anchor_a), ("LocalAnchorB", j.local_anchor_b), ("LocalAxisA", j.local_axis_a), ("LinearOffset", j.linear_offset), ("GroundAnchorA", j.ground_anchor_a), ("GroundAnchorB", j.ground_anchor_b)):
            check.vector(name, v, RANGE.max_length, "m")
        for name, v, bound, unit in (
            ("ReferenceAngle", j.reference_angle, RANGE.max_angle, "rad"),
            ("AngularOffset", j.angular_offset, RANGE.max_angle, "rad"),
            ("MotorSpeed", j.motor_speed, RANGE.max_speed, "per s"),
            ("MaxMotorTorque", j.max_motor_torque, RANGE.max_force, "N m"),
            ("MaxMotorForce", j.max_motor_force, RANGE.max_force, "N"),
            ("MaxForce", j.max_force, RANGE.max_force, "N"),
            ("MaxTorque", j.max_torque, RANGE.max_force, "N m"),
            ("Length", j.length, RANGE.max_length, "m"),
            ("MaxLength", j.max_length, RANGE.max_length, "m"),
            ("LengthA", j.length_a, RANGE.max_length, "m"),
            ("LengthB", j.length_b, RANGE.max_length, "m"),
            ("FrequencyHz", j.frequency_hz, RANGE.max_frequency, "Hz"),
            ("DampingRatio", j.damping_ratio, RANGE.max_frequency, ""),
            ("Ratio", j.ratio, RANGE.max_ratio, ""),
            ("CorrectionFactor", j.correction_factor, RANGE.max_frequency, ""),
        ):
            check.magnitude(name, v, bound, unit)
        if j.kind in ("prismatic", "line", "wheel") and check.passed and not math.hypot(*j.local_axis_a) >= RANGE.min_axis:
            check.fail(f"LocalAxisA is shorter than {RANGE.min_axis:g} m: Box2D 2.3 cannot normalise it")
        if j.kind in ("revolute", "friction", "motor"):
            lever = RANGE.max_lever_revolute
        elif j.kind in ("prismatic", "weld"):
            lever = RANGE.max_lever
        else:
            lever = 0.0
        if check.passed and j.kind != "gear":
            self.anchor_check(check, "LocalAnchorA", j.body_a, j.local_anchor_a, lever)
            self.anchor_check(check, "LocalAnchorB", j.body_b, j.local_anchor_b, lever)
        if check.passed and RANGE.prismatic_lever_to_b and j.kind == "prismatic":
            a, b = self.built.bodies[j.body_a], self.built.bodies[j.body_b]
            b_on_a = _vec(a.GetLocalPoint(b.GetWorldPoint(j.local_anchor_b)))
            self.anchor_check(check, "LocalAnchorB, as body A's lever", j.body_a, b_on_a, lever)
        return check

    def starting_violation(self, j: Joint) -> float:
        """How far the joint starts from satisfied, in metres, along what its kind holds
        rigidly, with its bodies as created (what the load warning joint-starts-violated
        measures)."""
        a, b = self.built.bodies[j.body_a], self.built.bodies[j.body_b]
        pa, pb = a.GetWorldPoint(j.local_anchor_a), b.GetWorldPoint(j.local_anchor_b)
        d = (pb[0] - pa[0], pb[1] - pa[1])
        if j.kind in ("revolute", "weld"):
            return math.hypot(*d)
        if j.kind in ("prismatic", "line", "wheel"):
            axis = a.GetWorldVector(j.local_axis_a)
            length = math.hypot(axis[0], axis[1])
            ux, uy = axis[0] / length, axis[1] / length
            across, along = abs(ux * d[1] - uy * d[0]), ux * d[0] + uy * d[1]
            beyond = max(j.lower_limit - along, along - j.upper_limit, 0.0) if j.enable_limit and j.kind != "wheel" else 0.0
            return max(across, beyond)
        if j.kind == "distance":
            return 0.0 if j.frequency_hz > 0 else abs(math.hypot(*d) - j.length)
        if j.kind == "rope":
            return max(math.hypot(*d) - j.max_length, 0.0)
        if j.kind == "pulley":
            ga, gb = j.ground_anchor_a, j.ground_anchor_b
            now = math.hypot(pa[0] - ga[0], pa[1] - ga[1]) + j.ratio * math.hypot(pb[0] - gb[0], pb[1] - gb[1])
            return abs(now - (j.length_a + j.ratio * j.length_b))
        return 0.0  # springs, motors and friction hold nothing in place

    def violation_check(self, index: int, j: Joint, check: Check) -> None:
        """What the sweep of docs/working-range.md measured: 2.x holds any one joint that
        starts far from satisfied, but its position solver can tear a body that two such
        joints pull to NaN. The first such joint on a body is built, the later ones are not."""
        violation = self.starting_violation(j)
        if not violation > RANGE.max_pulled_violation:
            return
        for body in (j.body_a, j.body_b):
            if body in self.pulled:
                check.fail(f"it starts {violation:.9g} m from satisfied, and joint {self.pulled[body]} already pulls body {body} from further than {RANGE.max_pulled_violation:g} m: two such joints on one body lie beyond Box2D 2.3's working range (its position solver can tear the body to NaN)")
                return
        for body in (j.body_a, j.body_b):
            if self.built.bodies[body].type == B.b2_dynamicBody:
                self.pulled[body] = index

    def wheel_hertz(self, index: int, j: Joint, hertz: float) -> float:
        """Box2D 2.3's wheel joint without a spring (0 Hz) reads its lever arms before it
        ever computes them (b2WheelJoint::InitVelocityConstraints computes m_sAx, m_sBx only
        for a spring, and warm starting multiplies them by 0): whatever the memory held,
        NaN included, goes into the bodies. A spring too soft to matter stands in for none."""
        if hertz > 0.0:
            return hertz
        self.report(
            "lossy-joint",
            "joint",
            index,
            j.name,
            f"Box2D 2.3's wheel joint without a spring reads uninitialised memory; a spring of {SPRINGLESS_WHEEL_HZ:g} Hz, undamped, stands in for none (about 1e-6 N s per metre and kg a step)",
        )
        return SPRINGLESS_WHEEL_HZ

    def limits(self, index: int, j: Joint, lower_name: str, upper_name: str) -> Tuple[float, float]:
        if j.lower_limit > j.upper_limit:
            self.report("bad-limit", "joint", index, j.name, f"{lower_name} {j.lower_limit:.9g} lies above {upper_name} {j.upper_limit:.9g}; they were passed swapped")
            return j.upper_limit, j.lower_limit
        return j.lower_limit, j.upper_limit

    def make_joint(self, index: int) -> None:
        j = self.scene.joints[index]
        if j.kind == "unsupported":
            self.report("skipped-joint", "joint", index, j.name, "Box2D 2.3 has no form for a Farseer-only joint; joint skipped")
            return
        a, b = self.built.bodies[j.body_a], self.built.bodies[j.body_b]
        if a is None or b is None:
            self.report("skipped-dependent", "joint", index, j.name, f"it names body {j.body_a if a is None else j.body_b}, which was not created; joint skipped")
            return
        if j.body_a == j.body_b:
            self.report("joint-self-reference", "joint", index, j.name, "it connects a body to itself; joint skipped")
            return
        check = self.joint_check(j)
        if check.passed and j.kind != "gear":
            self.violation_check(index, j, check)
        if not check.passed:
            self.beyond(check, "joint", index, j.name)
            return
        common = dict(bodyA=a, bodyB=b, collideConnected=j.collide_connected)
        anchors = dict(localAnchorA=j.local_anchor_a, localAnchorB=j.local_anchor_b)
        w = self.world
        kind = j.kind
        if kind == "revolute":
            lower, upper = self.limits(index, j, "LowerAngle", "UpperAngle")
            d = B.b2RevoluteJointDef(referenceAngle=j.reference_angle, enableLimit=j.enable_limit, lowerAngle=lower, upperAngle=upper, enableMotor=j.enable_motor, motorSpeed=j.motor_speed, maxMotorTorque=j.max_motor_torque, **common, **anchors)
        elif kind == "prismatic":
            lower, upper = self.limits(index, j, "LowerTranslation", "UpperTranslation")
            d = B.b2PrismaticJointDef(localAxisA=j.local_axis_a, referenceAngle=j.reference_angle, enableLimit=j.enable_limit, lowerTranslation=lower, upperTranslation=upper, enableMotor=j.enable_motor, maxMotorForce=j.max_motor_force, motorSpeed=j.motor_speed, **common, **anchors)
        elif kind == "distance":
            d = B.b2DistanceJointDef(length=j.length, frequencyHz=j.frequency_hz, dampingRatio=j.damping_ratio, **common, **anchors)
        elif kind == "rope":
            d = B.b2RopeJointDef(maxLength=j.max_length, **common, **anchors)
        elif kind in ("line", "wheel"):
            if kind == "line":
                if j.enable_motor:
                    self.report("lossy-line-motor", "joint", index, j.name, "Box2D 2.3 has no linear motor on a line (wheel) joint; the motor is off")
                if j.enable_limit:
                    self.report("lossy-joint", "joint", index, j.name, "Box2D 2.3's wheel joint has no translation limit; the line joint's limit is off")
                d = B.b2WheelJointDef(localAxisA=j.local_axis_a, frequencyHz=self.wheel_hertz(index, j, 0.0), dampingRatio=0.0, **common, **anchors)
            else:
                d = B.b2WheelJointDef(localAxisA=j.local_axis_a, frequencyHz=self.wheel_hertz(index, j, j.frequency_hz), dampingRatio=j.damping_ratio, enableMotor=j.enable_motor, maxMotorTorque=j.max_motor_torque, motorSpeed=j.motor_speed, **common, **anchors)
        elif kind == "weld":
            d = B.b2WeldJointDef(referenceAngle=j.reference_angle, frequencyHz=j.frequency_hz, dampingRatio=j.damping_ratio, **common, **anchors)
        elif kind == "friction":
            d = B.b2FrictionJointDef(maxForce=j.max_force, maxTorque=j.max_torque, **common, **anchors)
        elif kind == "motor":
            d = B.b2MotorJointDef(linearOffset=j.linear_offset, angularOffset=j.angular_offset, maxForce=j.max_force, maxTorque=j.max_torque, correctionFactor=j.correction_factor, **common)
        elif kind == "pulley":
            if j.max_length_a > 0 or j.max_length_b > 0:
                self.report("lossy-joint", "joint", index, j.name, f"MaxLengthA {j.max_length_a:.9g} and MaxLengthB {j.max_length_b:.9g} are Box2D 2.1's, which 2.3 has not: the sides are not limited")
            d = B.b2PulleyJointDef(groundAnchorA=j.ground_anchor_a, groundAnchorB=j.ground_anchor_b, lengthA=j.length_a, lengthB=j.length_b, ratio=j.ratio, **common, **anchors)
        else:  # gear
            joint_a, joint_b = self.built.joints[j.joint_a], self.built.joints[j.joint_b]
            if joint_a is None or joint_b is None:
                self.report("skipped-dependent", "joint", index, j.name, f"it couples joint {j.joint_a if joint_a is None else j.joint_b}, which was not created; joint skipped")
                return
            for target, coupled in ((j.joint_a, joint_a), (j.joint_b, joint_b)):
                if coupled.bodyB.type != B.b2_dynamicBody or not (coupled.bodyA.active and coupled.bodyB.active):
                    self.report("bad-gear-joint", "joint", index, j.name, f"the gear couples joint {target}, whose body B is not dynamic or whose bodies are not all active, which Box2D 2.3's gear cannot solve; gear skipped")
                    return
            d = B.b2GearJointDef(joint1=joint_a, joint2=joint_b, ratio=j.ratio, **common)
        d.userData = self.built._mark
        self.built.joints[index] = w.CreateJoint(d)


def build_world(scene: Scene, world: B.b2World) -> Built:
    """Creates every object of ``scene`` that Box2D 2.3 can hold in ``world`` and reports
    the rest (never asserting, never producing NaN)."""
    b = _Build(scene, world)
    b.check_gravity()
    b.check_filters()
    for i in range(len(scene.shapes)):
        b.make_shape(i)
    for i in range(len(scene.bodies)):
        b.make_body(i)
    # A gear is created after the joints it couples, wherever it stands in the scene.
    joints = range(len(scene.joints))
    for i in [i for i in joints if scene.joints[i].kind != "gear"] + [i for i in joints if scene.joints[i].kind == "gear"]:
        b.make_joint(i)
    # pybox2d's fixture def takes a shape from Python and never frees it; Box2D cloned each
    # into its fixtures, so the build's own shapes go with the build.
    for shape in b.shapes:
        if shape is not None:
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


def _center_velocity(body: B.b2Body, origin_velocity, w: float):
    shift = _shift(body, w)
    return (float(F(origin_velocity[0]) + shift[0]), float(F(origin_velocity[1]) + shift[1]))


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
            changes["frequency_hz"] = 0.0  # the stand-in spring of wheel_hertz
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
