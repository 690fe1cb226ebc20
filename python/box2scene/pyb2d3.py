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
from ._f32 import F, angle_of, f32, search_ulps
from ._records import Body, Fixture, Joint, Shape
from ._report import Report
from ._scene import Builder, Scene

__all__ = ["Built", "Report", "build_world", "capture_world", "create_world", "scene_gravity"]

# The engine version of the library's plan and working range pyb2d3 is built on.
ENGINE = "box2d-3.1"
# The maximum linear speed of the world a plan for v3.1 needs (the C adapter's world def).
WORLD_MAX_LINEAR_SPEED = _native.working_range(ENGINE)["world_max_linear_speed"]
# v3's B2_PI (3.14159265359f) is the float nearest pi.
PI = f32(math.pi)


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
        self.rotations: Dict[int, Tuple[float, float]] = {}

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
        self.rotations[body.body] = body.rotation
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
            if kind == "motor":
                # The plan turned the offset by body A's rotation: a capture turns it back.
                record["linear_offset_frame"] = self.rotations[j.body_a]
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


# ---- what capture computes as v3 does, operation for operation


def _sub(a, b):
    return (F(a[0]) - F(b[0]), F(a[1]) - F(b[1]))


def _dot(a, b):
    return F(a[0]) * F(b[0]) + F(a[1]) * F(b[1])


def _cross(a, b):
    return F(a[0]) * F(b[1]) - F(a[1]) * F(b[0])


def _rotate(c, s, v):
    x, y = F(v[0]), F(v[1])
    return (float(F(c) * x - F(s) * y), float(F(s) * x + F(c) * y))


def _transform_point(p, c, s, v):
    r = _rotate(c, s, v)
    return (float(F(r[0]) + F(p[0])), float(F(r[1]) + F(p[1])))


def _polygon_mass(vertices, density: float):
    """b2ComputePolygonMass of a polygon of radius 0: (mass, center, inertia about the origin)."""
    r = vertices[0]
    inv3 = F(1.0) / F(3.0)
    cx, cy, area, inertia = F(0), F(0), F(0), F(0)
    for i in range(1, len(vertices) - 1):
        e1 = _sub(vertices[i], r)
        e2 = _sub(vertices[i + 1], r)
        d = _cross(e1, e2)
        triangle = F(0.5) * d
        area += triangle
        w = triangle * inv3
        cx = cx + w * (e1[0] + e2[0])
        cy = cy + w * (e1[1] + e2[1])
        intx2 = e1[0] * e1[0] + e2[0] * e1[0] + e2[0] * e2[0]
        inty2 = e1[1] * e1[1] + e2[1] * e1[1] + e2[1] * e2[1]
        inertia += (F(0.25) * inv3 * d) * (intx2 + inty2)
    mass = F(density) * area
    inverse = F(1.0) / area
    cx *= inverse
    cy *= inverse
    center = (F(r[0]) + cx, F(r[1]) + cy)
    inertia = F(density) * inertia
    inertia += mass * (_dot(center, center) - _dot((cx, cy), (cx, cy)))
    return mass, center, inertia


def _circle_mass(center, radius: float, density: float):
    rr = F(radius) * F(radius)
    mass = F(density) * F(PI) * rr
    return mass, (F(center[0]), F(center[1])), mass * (F(0.5) * rr + _dot(center, center))


def _mass_from_shapes(masses, fixed_rotation: bool):
    """The mass v3 gives a dynamic body with these (density, (mass, center, inertia)) shapes,
    newest first as b2Body_ApplyMassFromShapes walks them; and whether v3 keeps a positive
    centred inertia (it asserts otherwise)."""
    mass, cx, cy, inertia = F(0), F(0), F(0), F(0)
    for density, (m, c, i) in reversed(masses):
        if density == 0.0:
            continue
        mass += m
        cx = cx + m * c[0]
        cy = cy + m * c[1]
        inertia += i
    if mass > 0:
        inverse = F(1.0) / mass
        cx, cy = inverse * cx, inverse * cy
    kept = True
    if inertia > 0 and not fixed_rotation:
        inertia -= mass * _dot((cx, cy), (cx, cy))
        kept = bool(inertia > 0)
    else:
        inertia = F(0)
    return (mass, (cx, cy), inertia), kept




def _positive_mass(m):
    """Box2D 2.x gives a dynamic body without mass 1 kg; v3 would leave it at 0."""
    return m if m[0] > 0 else (F(1.0), m[1], m[2])


def _extrapolated(end, inner):
    return (float(F(end[0]) + (F(end[0]) - F(inner[0]))), float(F(end[1]) + (F(end[1]) - F(inner[1]))))



def _local_center(body: b2.Body):
    c = body.local_center_of_mass()
    return (float(c.x), float(c.y))



# ---- capture


class _Capture:
    def __init__(self, world: b2.World, built: Optional[Built], bodies: Sequence[b2.Body], names: Optional[Sequence[Optional[str]]]):
        self.world = world
        if names is not None and len(names) != len(bodies):
            raise Error("invalid-argument", 0, 0, 0, f"{len(names)} names for {len(bodies)} bodies")
        self.joint_records = built._joints if built is not None else {}
        self.chain_records = built._chains if built is not None else {}
        # The scene name of each fixture the build made, by whether it is a chain and its id
        # (shapes and chains number apart).
        self.fixture_names: Dict[Tuple[bool, int], Optional[str]] = {}
        if built is not None:
            for made, index in zip(built.fixtures, built._scene.fixture_ids):
                if made is not None:
                    self.fixture_names[(isinstance(made, b2.Chain), int(made.id))] = built._scene.fixtures[index].name
        made = [(b, r.name) for b, r in zip(built.bodies, built._scene.bodies) if b is not None and b.is_valid] if built is not None else []
        given = list(zip(bodies, names if names is not None else [b.name or None for b in bodies]))
        self.bodies = [b for b, _ in made + given]
        self.names = [n for _, n in made + given]
        self.index_of: Dict[int, int] = {}
        for i, body in enumerate(self.bodies):
            if int(body.id) in self.index_of:
                raise Error("invalid-argument", 0, 0, 0, f"bodies {self.index_of[int(body.id)]} and {i} are the same body")
            self.index_of[int(body.id)] = i
        self.builder = Builder()
        self.reports: List[Report] = []
        self.shape_count = 0
        self.fixture_count = 0
        self.joint_count = 0
        self.bits, self.group_bits = _native.filter_widths()

    def report(self, code: str, obj: str, index: int, name: Optional[str], message: str) -> None:
        self.reports.append(Report(code, obj, index, name, message))

    def filter_of(self, f) -> Tuple[int, int, int]:
        bits, group_bits = self.bits, self.group_bits
        low = (1 << bits) - 1
        high_mask = f.mask_bits >> bits
        group_low, group_high = -(1 << (group_bits - 1)), (1 << (group_bits - 1)) - 1
        exact = (
            f.category_bits >> bits == 0
            and high_mask in (0, (1 << (64 - bits)) - 1)
            and group_low <= f.group_index <= group_high
        )
        if not exact:
            self.report(
                "lossy-capture",
                "fixture",
                self.fixture_count,
                None,
                f"its filter (category 0x{f.category_bits:x}, mask 0x{f.mask_bits:x}, group {f.group_index}) has bits above the format's {bits} or a group beyond {group_bits} bits; the low {bits} bits were written",
            )
        group = min(max(f.group_index, group_low), group_high)
        return f.category_bits & low, f.mask_bits & low, group

    def add_fixture(self, shape: Shape, source, density: float, is_sensor: bool, name: Optional[str]) -> int:
        shape_index = self.builder.add_shape(shape)
        self.shape_count += 1
        category, mask, group = self.filter_of(source.filter)
        fixture = Fixture.new(
            shape_index,
            density=density,
            friction=float(source.friction),
            restitution=float(source.restitution),
            is_sensor=is_sensor,
            category_bits=category,
            mask_bits=mask,
            group_index=group,
            name=name,
        )
        index = self.builder.add_fixture(fixture)
        self.fixture_count += 1
        return index

    def capture_chain(self, chain: b2.Chain, first) -> int:
        recorded = self.chain_records.get(int(chain.id))
        if recorded is not None:
            points, loop = recorded
        else:
            segments = [s.segment for s in chain.get_segments()]
            points = [(float(s.point1.x), float(s.point1.y)) for s in segments]
            tail = segments[-1]
            end = (float(tail.point2.x), float(tail.point2.y))
            loop = end == points[0]
            if not loop:
                points = [_extrapolated(points[0], points[1])] + points + [end, _extrapolated(end, points[-1])]
            self.report(
                "lossy-capture",
                "shape",
                self.shape_count,
                None,
                "pyb2d3 cannot read a chain's ghost points: those of a chain box2scene did not build were extrapolated",
            )
        if loop:
            shape = Shape.new("chain", vertices=tuple(points), is_loop=True)
        else:
            shape = Shape.new("chain", vertices=tuple(points[1:-1]), prev_vertex=points[0], next_vertex=points[-1])
        return self.add_fixture(shape, first, 0.0, False, self.fixture_names.get((True, int(chain.id))))

    def capture_shape(self, s) -> Optional[int]:
        kind = s.type
        if kind == b2.ShapeType.circle:
            c = s.circle
            shape = Shape.new("circle", radius=float(c.radius), position=(float(c.center.x), float(c.center.y)))
        elif kind == b2.ShapeType.polygon:
            p = s.polygon
            vertices = tuple(tuple(map(float, v)) for v in p.vertices[: p.count])
            if p.radius > 0:
                self.report("lossy-capture", "shape", self.shape_count, None, f"a rounded polygon (radius {p.radius:.9g} m): written without its rounding")
            shape = Shape.new("polygon", vertices=vertices)
        elif kind == b2.ShapeType.segment:
            seg = s.segment
            shape = Shape.new("edge", vertices=((float(seg.point1.x), float(seg.point1.y)), (float(seg.point2.x), float(seg.point2.y))))
        else:
            self.report("lossy-capture", "shape", self.shape_count, None, "a capsule has no Box2Scene form; not written")
            return None
        return self.add_fixture(shape, s, float(s.density), bool(s.is_sensor), self.fixture_names.get((False, int(s.id))))

    def capture_fixtures(self, body: b2.Body):
        """The fixtures of one body in the order its shapes were created (a chain where its
        first segment stands), with the mass its shapes give."""
        shapes = sorted(body.shapes, key=lambda s: int(s.id) & 0xFFFFFFFF)
        fixtures, masses, chains_seen = [], [], set()
        for s in shapes:
            if s.type == b2.ShapeType.chain_segment:
                chain = s.parent_chain
                if int(chain.id) in chains_seen:
                    continue
                chains_seen.add(int(chain.id))
                fixtures.append(self.capture_chain(chain, s))
                continue
            index = self.capture_shape(s)
            if index is None:
                continue
            fixtures.append(index)
            density = float(s.density)
            if s.type == b2.ShapeType.circle:
                c = s.circle
                masses.append((density, _circle_mass((c.center.x, c.center.y), c.radius, density)))
            elif s.type == b2.ShapeType.polygon:
                p = s.polygon
                masses.append((density, _polygon_mass([tuple(v) for v in p.vertices[: p.count]], density)))
            else:
                masses.append((density, (F(0), (F(0), F(0)), F(0))))
        computed, _ = _mass_from_shapes(masses, body.fixed_rotation)
        return fixtures, computed

    def capture_body(self, index: int) -> None:
        body = self.bodies[index]
        fixtures, computed = self.capture_fixtures(body)
        kind = {b2.BodyType.STATIC: "static", b2.BodyType.KINEMATIC: "kinematic", b2.BodyType.DYNAMIC: "dynamic"}[body.type]
        q = body.rotation
        exact, angle = angle_of(float(q.c), float(q.s))
        name = self.names[index]
        if not exact:
            self.report("lossy-capture", "body", index, name, f"no angle has exactly its rotation's cosine and sine; the nearest, {angle:.9g} rad, was written")
        w = float(body.angular_velocity)
        v = (float(body.linear_velocity.x), float(body.linear_velocity.y))
        if kind == "dynamic":
            v = _origin_velocity(body, v, w)
        changes = dict(
            name=name,
            position=(float(body.position.x), float(body.position.y)),
            angle=angle,
            linear_velocity=v,
            angular_velocity=w,
            linear_damping=float(body.linear_damping),
            angular_damping=float(body.angular_damping),
            gravity_scale=float(body.gravity_scale),
            allow_sleep=bool(body.enabled_sleep),
            awake=bool(body.awake),
            bullet=bool(body.bullet),
            fixed_rotation=bool(body.fixed_rotation),
            active=bool(body.enabled),
            fixtures=tuple(fixtures),
        )
        if kind == "dynamic":
            actual = body.mass_data
            center = (float(actual.center.x), float(actual.center.y))
            mine = _positive_mass(computed)
            same = (
                float(mine[0]) == float(actual.mass)
                and (float(mine[1][0]), float(mine[1][1])) == center
                and float(mine[2]) == float(actual.rotational_inertia)
            )
            if not same:
                changes.update(mass=float(actual.mass), center=center, inertia=_origin_inertia(float(actual.rotational_inertia), float(actual.mass), center))
        self.builder.add_body(Body.new(kind, **changes))

    def capture_joint(self, joint) -> None:
        a = self.index_of.get(int(joint.body_a.id))
        b = self.index_of.get(int(joint.body_b.id))
        if a is None or b is None:
            self.report(
                "lossy-capture",
                "joint",
                self.joint_count,
                None,
                f"it connects body {b if a is None else a} to a body the host did not name; not written",
            )
            return
        record = self.joint_records.get(int(joint.id))
        if record is None:
            self.report(
                "lossy-capture",
                "joint",
                self.joint_count,
                None,
                "pyb2d3 cannot read a joint's collide_connected, reference angle or axis: box2scene did not build this joint, so they were written at their defaults",
            )
            record = {}
        fields = self.joint_fields(joint, record)
        if fields is None:
            return
        kind, changes = fields
        changes["collide_connected"] = record.get("collide_connected", False)
        changes["name"] = record.get("name")
        self.builder.add_joint(Joint.new(kind, a, b, **changes))
        self.joint_count += 1

    def lossy(self, what: str) -> None:
        self.report("lossy-capture", "joint", self.joint_count, None, f"{what} has no Box2Scene form; written without it")

    def joint_fields(self, j, record: dict):
        t = j.type
        T = b2.JointType
        anchors = {
            "local_anchor_a": (float(j.local_anchor_a.x), float(j.local_anchor_a.y)),
            "local_anchor_b": (float(j.local_anchor_b.x), float(j.local_anchor_b.y)),
        }
        if t == T.REVOLUTE_JOINT:
            if j.spring_enabled:
                self.lossy("a revolute joint's spring")
            return "revolute", dict(
                anchors,
                reference_angle=record.get("reference_angle", 0.0),
                enable_limit=bool(j.limit_enabled),
                lower_limit=float(j.lower_limit),
                upper_limit=float(j.upper_limit),
                enable_motor=bool(j.motor_enabled),
                motor_speed=float(j.motor_speed),
                max_motor_torque=float(j.max_motor_torque),
            )
        if t == T.PRISMATIC_JOINT:
            if j.spring_enabled:
                self.lossy("a prismatic joint's spring")
            return "prismatic", dict(
                anchors,
                local_axis_a=record.get("local_axis_a", (1.0, 0.0)),
                reference_angle=record.get("reference_angle", 0.0),
                enable_limit=bool(j.limit_enabled),
                lower_limit=float(j.lower_limit),
                upper_limit=float(j.upper_limit),
                enable_motor=bool(j.motor_enabled),
                motor_speed=float(j.motor_speed),
                max_motor_force=float(j.max_motor_force),
            )
        if t == T.DISTANCE_JOINT:
            if j.motor_enabled:
                self.lossy("a distance joint's motor")
            if j.spring_enabled and float(j.spring_hertz) == 0.0:
                if not j.limit_enabled:
                    self.lossy("a slack distance joint without its length limit")
                return "rope", dict(anchors, max_length=float(j.max_length))
            changes = dict(anchors, length=float(j.length))
            if j.spring_enabled:
                changes.update(frequency_hz=float(j.spring_hertz), damping_ratio=float(j.spring_damping_ratio))
            if j.limit_enabled:
                self.lossy("a distance joint's length range")
            return "distance", changes
        if t == T.WHEEL_JOINT:
            axis = record.get("local_axis_a", (1.0, 0.0))
            if j.spring_enabled:
                if j.limit_enabled:
                    self.lossy("a wheel joint's limit beside its spring")
                return "wheel", dict(
                    anchors,
                    local_axis_a=axis,
                    frequency_hz=float(j.spring_hertz),
                    damping_ratio=float(j.spring_damping_ratio),
                    enable_motor=bool(j.motor_enabled),
                    motor_speed=float(j.motor_speed),
                    max_motor_torque=float(j.max_motor_torque),
                )
            if j.motor_enabled:
                self.lossy("a springless wheel joint's rotation motor")
            return "line", dict(
                anchors,
                local_axis_a=axis,
                enable_limit=bool(j.limit_enabled),
                lower_limit=float(j.lower_limit),
                upper_limit=float(j.upper_limit),
            )
        if t == T.WELD_JOINT:
            if float(j.linear_hertz) != 0.0:
                self.lossy("a weld joint's linear spring")
            return "weld", dict(
                anchors,
                reference_angle=record.get("reference_angle", 0.0),
                frequency_hz=float(j.angular_hertz),
                damping_ratio=float(j.angular_damping_ratio),
            )
        if t == T.MOTOR_JOINT:
            offset = (float(j.linear_offset.x), float(j.linear_offset.y))
            angular = float(j.angular_offset)
            factor = float(j.correction_factor)
            if factor == 0.0 and offset == (0.0, 0.0) and angular == 0.0:
                kind = "friction"
            else:
                kind = "motor"
                frame = record.get("linear_offset_frame")
                if frame is not None:
                    offset = _unrotated(frame, offset)
            return kind, dict(
                linear_offset=offset,
                angular_offset=angular,
                max_force=float(j.max_force),
                max_torque=float(j.max_torque),
                correction_factor=factor,
            )
        name = "mouse" if t == T.MOUSE_JOINT else "filter"
        self.report("lossy-capture", "joint", self.joint_count, None, f"a {name} joint has no Box2Scene form; not written")
        return None


def _unrotated(frame, offset):
    """The offset in body A's frame that the build turned into ``offset`` (exact for the
    unturned frame, where the turn is the identity)."""
    c, s = frame
    return _rotate(c, -s, offset)


def _origin_velocity(body: b2.Body, velocity, w: float):
    """The velocity of a body's origin that the build turns back into its centre's."""
    t = body.transform
    center = _transform_point((t.p.x, t.p.y), t.q.c, t.q.s, _local_center(body))
    shift = (float(-F(w) * (F(center[1]) - F(t.p.y))), float(F(w) * (F(center[0]) - F(t.p.x))))
    out = []
    for target, delta in zip(velocity, shift):
        _, before = search_ulps(f32(target - delta), lambda x, t=target, d=delta: float(F(x) + F(d)) == t)
        out.append(before)
    return tuple(out)


def _origin_inertia(central: float, mass: float, center) -> float:
    """The inertia about the origin that the build turns back into ``central``."""
    shift = F(mass) * _dot(center, center)
    _, origin = search_ulps(float(F(central) + shift), lambda x: float(F(x) - shift) == central)
    return origin


def capture_world(
    world: b2.World,
    built: Optional[Built] = None,
    bodies: Sequence[b2.Body] = (),
    joints: Sequence[b2.Joint] = (),
    names: Optional[Sequence[Optional[str]]] = None,
) -> Tuple[Scene, List[Report]]:
    """A scene of what ``built`` made that the world still holds (with the scene's names),
    then of the host's own ``bodies`` (their shapes with them; named by ``names``, or else
    by their Box2D names) and those of its ``joints`` whose two bodies are saved, with the
    world's gravity; and the reports of what has no Box2Scene form. Written and loaded, it
    builds a world that evolves bit for bit like this one. Raises :class:`box2scene.Error`
    when a body is given twice."""
    c = _Capture(world, built, bodies, names)
    g = world.gravity
    c.builder.set_gravity((float(g.x), float(g.y)))
    for i in range(len(c.bodies)):
        c.capture_body(i)
    made = [j for j in built.joints if j is not None and j.is_valid] if built is not None else []
    written = {int(j.id) for j in made}
    host = sorted((j for j in joints if j is not None and int(j.id) not in written), key=lambda j: int(j.id) & 0xFFFFFFFF)
    for joint in made + host:
        c.capture_joint(joint)
    return c.builder.finish(), c.reports
