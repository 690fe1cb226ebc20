"""Build a scene into a pyb2d3 world (Box2D v3.1.1), and capture one back into a scene.

The mapping is the library's C v3 adapter's (``include/box2scene/box2d3.h``; the format's
reference, "Mapping onto Box2D v3.1"), with the same reports and the same working range:

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
from types import SimpleNamespace
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np
import pyb2d3 as b2
from pyb2d3 import _pyb2d3 as _b2

from . import _native
from ._error import Error
from ._f32 import F, angle_of, cosf, f32, search_ulps, sinf
from ._records import Body, Fixture, Joint, Shape
from ._report import Check, Report
from ._scene import Builder, Scene

__all__ = ["Built", "Report", "build_world", "capture_world", "create_world", "scene_gravity"]

# The working range: the library's measured table for Box2D v3.1 (pyb2d3 is built on v3.1.1),
# the one the C adapter for v3.1 reads (docs/working-range.md).
RANGE = SimpleNamespace(**_native.working_range("box2d-3.1"))
WORLD_MAX_LINEAR_SPEED = RANGE.world_max_linear_speed
# The engine's own facts, in the same table: its linear slop, the bound of a revolute
# limit, how far a Centroid may lie from v3's own, and the bytes of a body's name it keeps.
LINEAR_SLOP = RANGE.linear_slop
REVOLUTE_LIMIT = RANGE.max_revolute_limit
CENTROID_NOISE = RANGE.centroid_tolerance
NAME_LENGTH = RANGE.name_bytes

ENGINE = "Box2D v3"
# v3's B2_PI (3.14159265359f) is the float nearest pi.
PI = f32(math.pi)
FLT_EPSILON = float(np.finfo(np.float32).eps)
MAX_POLYGON_VERTICES = 8

_KINDS = {"static": b2.BodyType.STATIC, "kinematic": b2.BodyType.KINEMATIC, "dynamic": b2.BodyType.DYNAMIC}


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


def _gravity_fits(g) -> bool:
    return abs(g[0]) <= RANGE.max_acceleration and abs(g[1]) <= RANGE.max_acceleration


def scene_gravity(scene: Scene, fallback: Tuple[float, float] = (0.0, -10.0)) -> Tuple[float, float]:
    """The scene's gravity, or ``fallback`` when it gives none or one beyond the range."""
    if scene.gravity is None or not _gravity_fits(scene.gravity):
        return fallback
    return scene.gravity


def create_world(scene: Scene, fallback_gravity: Tuple[float, float] = (0.0, -10.0), **settings) -> b2.World:
    """A pyb2d3 world for ``scene``: its gravity (or the fallback) and the maximum linear
    speed the working range needs (the C adapter's ``b2s_box2d3_world_def``); ``settings``
    are pyb2d3's other world settings."""
    settings.setdefault("maximum_linear_speed", WORLD_MAX_LINEAR_SPEED)
    return b2.World(gravity=scene_gravity(scene, fallback_gravity), **settings)


# ---- single-precision geometry, operation for operation as v3 computes it


def _sub(a, b):
    return (F(a[0]) - F(b[0]), F(a[1]) - F(b[1]))


def _dot(a, b):
    return F(a[0]) * F(b[0]) + F(a[1]) * F(b[1])


def _cross(a, b):
    return F(a[0]) * F(b[1]) - F(a[1]) * F(b[0])


def _distance_squared(a, b):
    d = _sub(b, a)
    return d[0] * d[0] + d[1] * d[1]


def _length(v):
    return np.sqrt(F(v[0]) * F(v[0]) + F(v[1]) * F(v[1]))


def _normalize(v):
    length = _length(v)
    if length < F(FLT_EPSILON):
        return (0.0, 0.0)
    inverse = F(1.0) / length
    return (float(inverse * F(v[0])), float(inverse * F(v[1])))


def _rotate(c, s, v):
    x, y = F(v[0]), F(v[1])
    return (float(F(c) * x - F(s) * y), float(F(s) * x + F(c) * y))


def _transform_point(p, c, s, v):
    r = _rotate(c, s, v)
    return (float(F(r[0]) + F(p[0])), float(F(r[1]) + F(p[1])))


def _hull_area(points) -> float:
    area = F(0.0)
    for i in range(1, len(points) - 1):
        area += _cross(_sub(points[i], points[0]), _sub(points[i + 1], points[0]))
    return float(F(0.5) * area)


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


def _with_mass_data(computed, body: Body):
    """The final mass data of a dynamic body: from its shapes, then its MassData (whose
    inertia is about the origin; v3's is about the centre of mass)."""
    if body.mass is None and body.center is None and body.inertia is None:
        return computed
    mass, center, inertia = computed
    origin_inertia = inertia + mass * _dot(center, center)
    if body.mass is not None:
        mass = F(body.mass)
    if body.center is not None:
        center = (F(body.center[0]), F(body.center[1]))
    if body.inertia is not None:
        origin_inertia = F(body.inertia)
    if body.fixed_rotation:
        return mass, center, F(0)
    return mass, center, origin_inertia - mass * _dot(center, center)


def _positive_mass(m):
    """Box2D 2.x gives a dynamic body without mass 1 kg; v3 would leave it at 0."""
    return m if m[0] > 0 else (F(1.0), m[1], m[2])


def _extrapolated(end, inner):
    return (float(F(end[0]) + (F(end[0]) - F(inner[0]))), float(F(end[1]) + (F(end[1]) - F(inner[1]))))


class _Geometry:
    def __init__(self, kind: str, value=None, points=None, is_loop: bool = False):
        self.kind = kind  # "circle", "polygon", "segment" or "chain"
        self.value = value
        self.points = points
        self.is_loop = is_loop

    def segments_long_enough(self) -> bool:
        if self.kind == "segment":
            return _segment_long_enough(self.points[0], self.points[1])
        if self.kind != "chain":
            return True
        n = len(self.points)
        count = n if self.is_loop else n - 1
        return all(_segment_long_enough(self.points[i], self.points[(i + 1) % n]) for i in range(count))

    def mass(self, density: float):
        if self.kind == "circle":
            return _circle_mass(self.value.center_tuple, self.value.radius, density)
        if self.kind == "polygon":
            return _polygon_mass(self.points, density)
        return F(0), (F(0), F(0)), F(0)


def _segment_long_enough(a, b) -> bool:
    return bool(_distance_squared(a, b) > F(LINEAR_SLOP) * F(LINEAR_SLOP))


class _Circle:
    def __init__(self, center, radius):
        self.center_tuple = center
        self.radius = radius
        self.shape = b2.circle(center, radius)


class _Build:
    def __init__(self, scene: Scene, world: b2.World, maximum_linear_speed: float):
        self.scene = scene
        self.world = world
        self.speed_limit = maximum_linear_speed
        self.reports: List[Report] = []
        slots = len(scene.fixture_ids)
        self.built = Built([None] * len(scene.bodies), [None] * slots, [None] * slots, [None] * len(scene.joints), self.reports, _scene=scene)
        self.geometries: List[Optional[_Geometry]] = [None] * len(scene.shapes)
        self.masses: Dict[int, tuple] = {}
        # Per body: the joint that already pulls it from further than the range's
        # max_pulled_violation.
        self.pulled: Dict[int, int] = {}
        self.has_sensor = any(f.is_sensor for f in scene.fixtures)
        self.slot_starts = []
        slot = 0
        for body in scene.bodies:
            self.slot_starts.append(slot)
            slot += len(body.fixtures)

    def report(self, code: str, obj: str, index: int, name: Optional[str], message: str) -> None:
        self.reports.append(Report(code, obj, index, name, message))

    def beyond(self, check: Check, obj: str, index: int, name: Optional[str], owner: str = "") -> None:
        self.report("beyond-box2d-range", obj, index, name, f"{owner}{check.problem}; {obj} not created")

    # ---- world and shapes

    def check_gravity(self) -> None:
        g = self.scene.gravity
        if g is not None and not _gravity_fits(g):
            self.report(
                "beyond-box2d-range",
                "world",
                0,
                None,
                f"Gravity ({g[0]:.9g}, {g[1]:.9g}) lies beyond Box2D v3's working range (each "
                f"component within +-{RANGE.max_acceleration:g} m/s^2); scene_gravity gives the host's "
                "fallback instead",
            )

    def shape_check(self, shape: Shape) -> Check:
        check = Check(ENGINE)
        edge = shape.kind == "edge"
        if shape.kind == "circle":
            check.magnitude("Radius", shape.radius, RANGE.max_length, "m")
            check.vector("Position", shape.position, RANGE.max_length, "m")
        for i, v in enumerate(shape.vertices):
            if not check.passed:
                break
            check.vector(f"Vertex{i + 1}" if edge else f"Vertex {i}", v, RANGE.max_length, "m")
        if shape.kind == "polygon" and shape.centroid is not None:
            check.vector("Centroid", shape.centroid, RANGE.max_length, "m")
        ghosts = edge or (shape.kind == "chain" and not shape.is_loop)
        if ghosts and shape.prev_vertex is not None:
            check.vector("Vertex0" if edge else "PrevVertex", shape.prev_vertex, RANGE.max_length, "m")
        if ghosts and shape.next_vertex is not None:
            check.vector("Vertex3" if edge else "NextVertex", shape.next_vertex, RANGE.max_length, "m")
        return check

    def make_polygon(self, index: int, shape: Shape, points) -> Optional[_Geometry]:
        if len(points) == 2:
            if not _segment_long_enough(points[0], points[1]):
                self.report(
                    "degenerate-polygon",
                    "shape",
                    index,
                    shape.name,
                    f"its two vertices are no farther apart than Box2D v3's linear slop ({LINEAR_SLOP:g} m); shape not created",
                )
                return None
            return _Geometry("segment", b2.segment(points[0], points[1]), list(points))
        hull = b2.compute_hull(np.array(points, dtype=np.float32))
        hull_points = [tuple(map(float, p)) for p in hull.points[: hull.count]] if hull.count > 0 else []
        if hull.count < 3 or not _hull_area(hull_points) > 2.0 * FLT_EPSILON:
            self.report(
                "degenerate-polygon",
                "shape",
                index,
                shape.name,
                f"Box2D v3 finds no polygon in its vertices (b2ComputeHull welds points closer than {LINEAR_SLOP:g} m and drops collinear ones); shape not created",
            )
            return None
        polygon = _b2._make_polygon(hull, 0.0)
        vertices = [tuple(map(float, p)) for p in polygon.vertices[: polygon.count]]
        centroid = (float(polygon.centroid.x), float(polygon.centroid.y))
        if shape.centroid is not None:
            dx, dy = shape.centroid[0] - centroid[0], shape.centroid[1] - centroid[1]
            if float(np.sqrt(F(dx) * F(dx) + F(dy) * F(dy))) > CENTROID_NOISE:
                self.report(
                    "lossy-shape",
                    "shape",
                    index,
                    shape.name,
                    f"its Centroid ({shape.centroid[0]:.9g}, {shape.centroid[1]:.9g}) cannot be given to Box2D v3, which uses the polygon's own ({centroid[0]:.9g}, {centroid[1]:.9g})",
                )
        return _Geometry("polygon", polygon, vertices)

    def make_open_chain(self, index: int, shape: Shape, vertices) -> _Geometry:
        edge = shape.kind == "edge"
        first = shape.prev_vertex if shape.prev_vertex is not None else _extrapolated(vertices[0], vertices[1])
        last = shape.next_vertex if shape.next_vertex is not None else _extrapolated(vertices[-1], vertices[-2])
        if shape.prev_vertex is None or shape.next_vertex is None:
            if shape.prev_vertex is None and shape.next_vertex is None:
                which = "both ghost vertices"
            elif shape.prev_vertex is None:
                which = "Vertex0" if edge else "PrevVertex"
            else:
                which = "Vertex3" if edge else "NextVertex"
            self.report(
                "lossy-shape",
                "shape",
                index,
                shape.name,
                f"Box2D v3's chain segments need a ghost vertex at each end: {which} extrapolated along the end segment",
            )
        return _Geometry("chain", None, [tuple(first)] + list(vertices) + [tuple(last)])

    def make_shape(self, index: int) -> None:
        shape = self.scene.shapes[index]
        vertices = list(shape.vertices)
        count = len(vertices)
        fits = {
            "polygon": 2 <= count <= MAX_POLYGON_VERTICES,
            "edge": count == 2,
            "chain": count >= (3 if shape.is_loop else 2),
        }.get(shape.kind, True)
        if not fits:
            self.report("bad-vertex-count", "shape", index, shape.name, f"{count} vertices do not make a Box2D v3 shape; shape not created")
            return
        check = self.shape_check(shape)
        if not check.passed:
            self.beyond(check, "shape", index, shape.name)
            return
        g: Optional[_Geometry]
        if shape.kind == "circle":
            g = _Geometry("circle", _Circle(shape.position, shape.radius))
        elif shape.kind == "polygon":
            g = self.make_polygon(index, shape, vertices)
        elif shape.kind == "edge":
            if shape.prev_vertex is not None or shape.next_vertex is not None:
                g = self.make_open_chain(index, shape, vertices)
            else:
                g = _Geometry("segment", b2.segment(vertices[0], vertices[1]), vertices)
        elif shape.is_loop:
            if count == 3:
                mid = (
                    float(F(vertices[2][0]) + F(0.5) * (F(vertices[0][0]) - F(vertices[2][0]))),
                    float(F(vertices[2][1]) + F(0.5) * (F(vertices[0][1]) - F(vertices[2][1]))),
                )
                vertices = vertices + [mid]
            g = _Geometry("chain", None, vertices, is_loop=True)
        else:
            g = self.make_open_chain(index, shape, vertices)
        if g is not None and not g.segments_long_enough():
            self.report(
                "degenerate-chain" if shape.kind == "chain" else "degenerate-edge",
                "shape",
                index,
                shape.name,
                f"a segment of it is no longer than Box2D v3's linear slop ({LINEAR_SLOP:g} m), which v3 refuses; shape not created",
            )
            g = None
        self.geometries[index] = g

    # ---- bodies and their shapes

    @staticmethod
    def fixture_check(f: Fixture) -> Check:
        check = Check(ENGINE)
        check.magnitude("Density", f.density, RANGE.max_density, "kg/m^2")
        check.magnitude("Friction", f.friction, RANGE.max_friction, "")
        check.magnitude("Restitution", f.restitution, RANGE.max_friction, "")
        if f.density < 0 or f.friction < 0 or f.restitution < 0:
            check.fail("a negative Density, Friction or Restitution, which Box2D v3 asserts against")
        return check

    def fixture_creatable(self, index: int) -> bool:
        f = self.scene.fixtures[index]
        return self.geometries[f.shape] is not None and self.fixture_check(f).passed

    def predicted_mass(self, body: Body, check: Check):
        masses = []
        for index in body.fixtures:
            if self.fixture_creatable(index):
                f = self.scene.fixtures[index]
                masses.append((f.density, self.geometries[f.shape].mass(f.density)))
        computed, kept = _mass_from_shapes(masses, body.fixed_rotation)
        if not kept:
            check.fail("its shapes leave no positive inertia about its centre of mass in Box2D v3's float arithmetic (which asserts)")
        check.vector("its centre of mass", computed[1], RANGE.max_length, "m")
        final = _positive_mass(_with_mass_data(computed, body))
        check.zero_or_within("its mass", float(final[0]), RANGE.min_mass, RANGE.max_mass, "kg")
        check.vector("its centre of mass", final[1], RANGE.max_length, "m")
        if final[2] < 0:
            check.fail("its MassData leaves a negative inertia about the centre of mass (Inertia < Mass * |Center|^2), which Box2D v3 asserts against")
        check.zero_or_within("its inertia about the centre of mass", float(final[2]), RANGE.min_inertia, RANGE.max_inertia, "kg m^2")
        return final

    def body_check(self, body: Body) -> Check:
        check = Check(ENGINE)
        check.vector("Position", body.position, RANGE.max_length, "m")
        check.magnitude("Angle", body.angle, RANGE.max_angle, "rad")
        if body.kind != "static":
            check.vector("LinearVelocity", body.linear_velocity, RANGE.max_speed, "m/s")
            check.magnitude("AngularVelocity", body.angular_velocity, RANGE.max_speed, "rad/s")
            speed = float(_length(body.linear_velocity))
            if check.passed and not speed <= self.speed_limit:
                v = body.linear_velocity
                check.fail(
                    f"LinearVelocity ({v[0]:.9g}, {v[1]:.9g}) is faster than the world's maximum linear speed {self.speed_limit:g} m/s, to which Box2D v3 would clamp it"
                )
        check.magnitude("LinearDamping", body.linear_damping, RANGE.max_damping, "1/s")
        check.magnitude("AngularDamping", body.angular_damping, RANGE.max_damping, "1/s")
        check.magnitude("GravityScale", body.gravity_scale, RANGE.max_gravity_scale, "")
        if body.kind == "dynamic" and check.passed:
            g = self.world.gravity
            scaled = (float(F(body.gravity_scale) * F(g.x)), float(F(body.gravity_scale) * F(g.y)))
            check.vector("GravityScale times the world's gravity", scaled, RANGE.max_acceleration, "m/s^2")
        if body.center is not None:
            check.vector("MassData Center", body.center, RANGE.max_length, "m")
        return check

    def skip_fixtures_of(self, index: int, body: Body) -> None:
        for f in body.fixtures:
            self.report(
                "skipped-dependent",
                "fixture",
                f,
                self.scene.fixtures[f].name,
                f"fixture {f} of body {index}: the body was not created; fixture skipped",
            )

    def damping(self, index: int, body: Body, value: float, field: str) -> float:
        if value >= 0:
            return value
        self.report("negative-value", "body", index, body.name, f"{field} {value:.9g} is negative, which Box2D v3 does not allow; 0 was used")
        return 0.0

    def body_def(self, index: int, body: Body) -> b2.BodyDef:
        d = b2.BodyDef()
        d.type = _KINDS[body.kind]
        d.position = body.position
        rotation = b2.Rot()
        rotation.c, rotation.s = cosf(body.angle), sinf(body.angle)
        d.rotation = rotation
        if body.kind != "static":
            d.linear_velocity = body.linear_velocity
            d.angular_velocity = body.angular_velocity
        d.linear_damping = self.damping(index, body, body.linear_damping, "LinearDamping")
        d.angular_damping = self.damping(index, body, body.angular_damping, "AngularDamping")
        d.gravity_scale = body.gravity_scale
        d.enable_sleep = body.allow_sleep
        d.is_awake = body.awake
        d.fixed_rotation = body.fixed_rotation
        d.is_bullet = body.bullet
        d.is_enabled = body.active
        # v3 keeps NAME_LENGTH bytes of a name; a longer one is not cut (it could split a
        # character), and is reported.
        if body.name is not None and len(body.name.encode()) <= NAME_LENGTH:
            d.name = body.name
        return d

    @staticmethod
    def filter(f: Fixture) -> b2.Filter:
        out = b2.Filter()
        out.category_bits = f.category_bits
        out.mask_bits = f.mask_bits
        out.group_index = f.group_index
        return out

    def make_fixture(self, body_index: int, slot: int, index: int, body: b2.Body) -> None:
        f = self.scene.fixtures[index]
        g = self.geometries[f.shape]
        if g is None:
            self.report(
                "skipped-dependent",
                "fixture",
                index,
                f.name,
                f"fixture {index} of body {body_index} names shape {f.shape}, which was not created; fixture skipped",
            )
            return
        check = self.fixture_check(f)
        if not check.passed:
            self.beyond(check, "fixture", index, f.name, f"fixture {index} of body {body_index}: ")
            return
        shape_def = b2.ShapeDef()
        material = shape_def.material
        material.friction = f.friction
        material.restitution = f.restitution
        if g.kind == "chain":
            chain_def = b2.ChainDef()
            chain_def.points = np.array(g.points, dtype=np.float32)
            chain_def.is_loop = g.is_loop
            chain_def.materials = [material]
            chain_def.filter = self.filter(f)
            if f.is_sensor:
                self.report(
                    "lossy-shape",
                    "fixture",
                    index,
                    f.name,
                    f"fixture {index} of body {body_index} is a sensor, but Box2D v3's chains have no sensor form; it was made a solid chain",
                )
            elif self.has_sensor:
                self.report(
                    "lossy-shape",
                    "fixture",
                    index,
                    f.name,
                    f"fixture {index} of body {body_index}: pyb2d3's chains cannot turn on sensor events, so the scene's sensors do not see this chain",
                )
            chain = body.create_chain(chain_def)
            self.built._chains[int(chain.id)] = (list(g.points), g.is_loop)
            self.built.chains[slot] = chain
            return
        shape_def.material = material
        shape_def.density = f.density
        shape_def.filter = self.filter(f)
        shape_def.is_sensor = f.is_sensor
        # Box2D 2.x's sensors saw every shape; v3's see those with sensor events on.
        shape_def.enable_sensor_events = True
        # One mass update per body, after all its shapes.
        shape_def.update_body_mass = False
        if g.kind == "circle":
            self.built.shapes[slot] = body.create_circle_shape(shape_def, g.value.shape)
        elif g.kind == "polygon":
            self.built.shapes[slot] = body.create_polygon_shape(shape_def, g.value)
        else:
            self.built.shapes[slot] = body.create_segment_shape(shape_def, g.value)

    def make_body(self, index: int) -> None:
        body = self.scene.bodies[index]
        check = self.body_check(body)
        mass = None
        if body.kind == "dynamic" and check.passed:
            mass = self.predicted_mass(body, check)
        if not check.passed:
            self.beyond(check, "body", index, body.name)
            self.skip_fixtures_of(index, body)
            return
        if abs(body.angle) > PI:
            self.report(
                "lossy-capture",
                "body",
                index,
                body.name,
                f"Box2D v3 keeps a rotation, not an angle: the whole turns of Angle {body.angle:.9g} are lost, and a capture writes it within +-pi",
            )
        if body.name is not None and len(body.name.encode()) > NAME_LENGTH:
            self.report(
                "lossy-body",
                "body",
                index,
                body.name,
                f"its Name is longer than the {NAME_LENGTH} bytes Box2D v3 keeps of a name; the body has none, and a capture writes none",
            )
        if not body.awake and not body.allow_sleep and body.kind != "static":
            self.report(
                "lossy-body",
                "body",
                index,
                body.name,
                "Awake false with AllowSleep false: Box2D v3 creates such a body awake (Box2D 2.x keeps it asleep until it is touched)",
            )
        created = self.world.create_body_from_def(self.body_def(index, body))
        self.built.bodies[index] = created
        start = self.slot_starts[index]
        for k, fixture in enumerate(body.fixtures):
            self.make_fixture(index, start + k, fixture, created)
        if body.kind == "dynamic":
            created.apply_mass_from_shapes()
            given = body.mass is not None or body.center is not None or body.inertia is not None
            if given or not created.mass > 0:
                self.set_mass_data(created, body, mass)
            self.masses[index] = mass

    @staticmethod
    def set_mass_data(created: b2.Body, body: Body, mass) -> None:
        """b2Body_SetMassData moves the centre of mass without carrying the velocity: the
        body then gets the velocity that keeps its origin's what the file says, as 2.x's
        SetMassData does."""
        data = b2.MassData()
        data.mass = float(mass[0])
        data.center = (float(mass[1][0]), float(mass[1][1]))
        data.rotational_inertia = float(mass[2])
        created.mass_data = data
        if body.kind == "dynamic":
            created.linear_velocity = _center_velocity(created, body.linear_velocity, body.angular_velocity)

    # ---- joints

    def check_anchor(self, check: Check, field: str, body: int, anchor, lever: float) -> None:
        if self.scene.bodies[body].kind != "dynamic":
            return
        mass, center, inertia = self.masses[body]
        r = float(np.sqrt(_distance_squared(anchor, center)))
        compliance = 1.0 / float(mass) + (r * r / float(inertia) if inertia > 0 else 0.0)
        if not compliance <= RANGE.max_compliance:
            check.fail(
                f"{field}: the joint acts {r:.9g} m from the centre of mass of body {body} (mass {float(mass):.9g} kg, inertia {float(inertia):.9g} kg m^2), where 1/m + r^2/I = {compliance:g} 1/kg lies beyond Box2D v3's working range (at most {RANGE.max_compliance:g} 1/kg)"
            )
        elif inertia > 0 and not r <= lever * math.sqrt(float(inertia) / float(mass)):
            check.fail(
                f"{field}: the joint acts {r / math.sqrt(float(inertia) / float(mass)):g} radii of gyration from the centre of mass of body {body}, beyond Box2D v3's working range (at most {lever:g})"
            )

    def check_drive(self, check: Check, body: int, force: float) -> None:
        if self.scene.bodies[body].kind != "dynamic":
            return
        mass = float(self.masses[body][0])
        acceleration = force / mass
        if not acceleration <= RANGE.max_joint_acceleration:
            check.fail(
                f"its motor or friction force {force:.9g} N accelerates body {body} (mass {mass:.9g} kg) by {acceleration:g} m/s^2, beyond Box2D v3's working range (at most {RANGE.max_joint_acceleration:g} m/s^2)"
            )

    def check_axis_violation(self, check: Check, j: Joint) -> None:
        """A line or wheel joint between two dynamic bodies that starts with body B's anchor
        off body A's axis by more than the range's radii of gyration of the smaller body."""
        a, b = self.scene.bodies[j.body_a], self.scene.bodies[j.body_b]
        if a.kind != "dynamic" or b.kind != "dynamic":
            return
        radii = [math.sqrt(float(m[2]) / float(m[0])) for m in (self.masses[j.body_a], self.masses[j.body_b]) if m[2] > 0]
        if not radii:
            return
        anchor_a = _transform_point(a.position, cosf(a.angle), sinf(a.angle), j.local_anchor_a)
        anchor_b = _transform_point(b.position, cosf(b.angle), sinf(b.angle), j.local_anchor_b)
        axis = _rotate(cosf(a.angle), sinf(a.angle), _normalize(j.local_axis_a))
        off = abs(axis[0] * (anchor_b[1] - anchor_a[1]) - axis[1] * (anchor_b[0] - anchor_a[0]))
        bound = RANGE.max_wheel_violation_gyrations * min(radii)
        if off > float(LINEAR_SLOP) and not off <= bound:
            check.fail(
                f"it starts violated: LocalAnchorB lies {off:.9g} m off the axis through LocalAnchorA, more than {RANGE.max_wheel_violation_gyrations:g} radii of gyration ({bound:.9g} m) of the smaller body, beyond Box2D v3's working range for a {j.kind} joint between two dynamic bodies"
            )

    def starting_violation(self, j: Joint) -> float:
        """How far the joint starts from satisfied, in metres, along what its kind holds
        rigidly, with its bodies as created (the C adapter's measure)."""
        a, b = self.scene.bodies[j.body_a], self.scene.bodies[j.body_b]
        ca, sa = cosf(a.angle), sinf(a.angle)
        pa = _transform_point(a.position, ca, sa, j.local_anchor_a)
        pb = _transform_point(b.position, cosf(b.angle), sinf(b.angle), j.local_anchor_b)
        d = _sub(pb, pa)
        if j.kind in ("revolute", "weld"):
            return float(_length(d))
        if j.kind in ("prismatic", "line", "wheel"):
            axis = _rotate(ca, sa, _normalize(j.local_axis_a))
            across, along = abs(float(_cross(axis, d))), float(_dot(axis, d))
            beyond = 0.0
            if j.enable_limit and j.kind != "wheel":
                beyond = max(j.lower_limit - along, along - j.upper_limit, 0.0)
            return max(across, beyond)
        if j.kind == "distance":
            return 0.0 if j.frequency_hz > 0 else abs(float(_length(d)) - j.length)
        if j.kind == "rope":
            return max(float(_length(d)) - j.max_length, 0.0)
        return 0.0  # springs, motors and friction hold nothing in place

    def check_violation(self, index: int, j: Joint, check: Check) -> None:
        """What the sweep of docs/working-range.md measured: v3.1 flies a line or wheel joint
        that starts more than the range's max_wheel_violation from satisfied apart, and
        asserts on a body that two joints starting more than its max_pulled_violation from
        satisfied pull; the first such joint of another kind on a body is built."""
        violation = self.starting_violation(j)
        if j.kind in ("line", "wheel"):
            if violation > RANGE.max_wheel_violation:
                check.fail(
                    f"it starts {violation:.9g} m from satisfied: a line or wheel joint further than {RANGE.max_wheel_violation:g} m from satisfied lies beyond Box2D v3's working range (its solver flings the bodies apart)"
                )
            return
        if not violation > RANGE.max_pulled_violation:
            return
        for body in (j.body_a, j.body_b):
            if body in self.pulled:
                check.fail(
                    f"it starts {violation:.9g} m from satisfied, and joint {self.pulled[body]} already pulls body {body} from further than {RANGE.max_pulled_violation:g} m: two such joints on one body lie beyond Box2D v3's working range (its solver asserts)"
                )
                return
        for body in (j.body_a, j.body_b):
            if self.scene.bodies[body].kind == "dynamic":
                self.pulled[body] = index

    def lever(self, j: Joint, other: int, lever: float) -> float:
        """A line or wheel joint to a body that does not turn (static, kinematic, or without
        rotational inertia) has the range's shorter lever."""
        turns = self.scene.bodies[other].kind == "dynamic" and self.masses[other][2] > 0
        return RANGE.max_lever_fixed_wheel if j.kind in ("line", "wheel") and not turns else lever

    def b_anchor_on_a(self, j: Joint):
        """Body B's anchor in body A's frame: a prismatic joint's axis reaches it."""
        a, b = self.scene.bodies[j.body_a], self.scene.bodies[j.body_b]
        world = _transform_point(b.position, cosf(b.angle), sinf(b.angle), j.local_anchor_b)
        ca, sa = cosf(a.angle), sinf(a.angle)
        return _rotate(ca, -sa, _sub(world, a.position))

    @staticmethod
    def drive_force(j: Joint) -> float:
        if j.kind == "prismatic":
            return j.max_motor_force if j.enable_motor else 0.0
        if j.kind in ("friction", "motor"):
            return j.max_force
        return 0.0

    def joint_check(self, j: Joint) -> Check:
        check = Check(ENGINE)
        anchored = j.kind != "motor"
        if anchored:
            check.vector("LocalAnchorA", j.local_anchor_a, RANGE.max_length, "m")
            check.vector("LocalAnchorB", j.local_anchor_b, RANGE.max_length, "m")
        if j.kind == "revolute" or j.kind == "wheel":
            check.magnitude("MotorSpeed", j.motor_speed, RANGE.max_speed, "rad/s")
            check.magnitude("MaxMotorTorque", j.max_motor_torque, RANGE.max_force, "N m")
        elif j.kind in ("prismatic", "line"):
            check.magnitude("LowerTranslation", j.lower_limit, RANGE.max_length, "m")
            check.magnitude("UpperTranslation", j.upper_limit, RANGE.max_length, "m")
            check.magnitude("MotorSpeed", j.motor_speed, RANGE.max_speed, "m/s")
            check.magnitude("MaxMotorForce", j.max_motor_force, RANGE.max_force, "N")
            check.magnitude("ReferenceAngle", j.reference_angle, RANGE.max_angle, "rad")
        elif j.kind == "distance":
            check.magnitude("Length", j.length, RANGE.max_length, "m")
        elif j.kind == "rope":
            check.magnitude("MaxLength", j.max_length, RANGE.max_length, "m")
        elif j.kind == "weld":
            check.magnitude("ReferenceAngle", j.reference_angle, RANGE.max_angle, "rad")
        elif j.kind in ("friction", "motor"):
            check.magnitude("MaxForce", j.max_force, RANGE.max_force, "N")
            check.magnitude("MaxTorque", j.max_torque, RANGE.max_force, "N m")
            if j.kind == "motor":
                check.vector("LinearOffset", j.linear_offset, RANGE.max_length, "m")
                check.magnitude("AngularOffset", j.angular_offset, RANGE.max_angle, "rad")
                check.magnitude("CorrectionFactor", j.correction_factor, RANGE.max_frequency, "")
        if j.kind in ("prismatic", "line", "wheel"):
            check.vector("LocalAxisA", j.local_axis_a, RANGE.max_length, "m")
            if check.passed and not float(_length(j.local_axis_a)) >= RANGE.min_axis:
                check.fail(f"LocalAxisA is shorter than {RANGE.min_axis:g} m: Box2D v3 cannot normalise it")
        if j.kind in ("distance", "wheel", "weld"):
            check.magnitude("FrequencyHz", j.frequency_hz, RANGE.max_frequency, "Hz")
            check.magnitude("DampingRatio", j.damping_ratio, RANGE.max_frequency, "")
            if j.frequency_hz < 0 or j.damping_ratio < 0:
                check.fail("a negative FrequencyHz or DampingRatio, which Box2D v3 asserts against")
        levered = anchored and (RANGE.friction_at_anchors or j.kind != "friction")
        if check.passed and levered:
            lever = RANGE.max_lever_revolute if j.kind == "revolute" else RANGE.max_lever
            self.check_anchor(check, "LocalAnchorA", j.body_a, j.local_anchor_a, self.lever(j, j.body_b, lever))
            self.check_anchor(check, "LocalAnchorB", j.body_b, j.local_anchor_b, self.lever(j, j.body_a, lever))
            if RANGE.prismatic_lever_to_b and j.kind == "prismatic":
                self.check_anchor(check, "LocalAnchorB, as body A's lever", j.body_a, self.b_anchor_on_a(j), lever)
        if check.passed and j.kind in ("line", "wheel"):
            self.check_axis_violation(check, j)
        if check.passed:
            self.check_drive(check, j.body_a, self.drive_force(j))
            self.check_drive(check, j.body_b, self.drive_force(j))
        return check

    def ordered_limits(self, index: int, j: Joint, lower_name: str, upper_name: str):
        lower, upper = j.lower_limit, j.upper_limit
        if lower > upper:
            self.report(
                "bad-limit",
                "joint",
                index,
                j.name,
                f"{lower_name} {lower:.9g} lies above {upper_name} {upper:.9g}, which Box2D v3 asserts against; they were passed swapped",
            )
            return upper, lower
        return lower, upper

    def common(self, d, j: Joint, a, b, anchors: bool = True):
        d.body_a = a
        d.body_b = b
        d.collide_connected = j.collide_connected
        if anchors:
            d.local_anchor_a = j.local_anchor_a
            d.local_anchor_b = j.local_anchor_b
        return d

    def joint_length(self, index: int, j: Joint, field: str, length: float) -> float:
        if length >= LINEAR_SLOP:
            return length
        self.report("lossy-joint", "joint", index, j.name, f"{field} {length:.9g} lies under Box2D v3's shortest joint length, {LINEAR_SLOP:g} m, which was used")
        return LINEAR_SLOP

    def make_joint(self, index: int) -> None:
        j = self.scene.joints[index]
        missing = {"pulley": "a pulley joint", "gear": "a gear joint", "unsupported": "a Farseer-only joint"}.get(j.kind)
        if missing is not None:
            self.report("skipped-joint", "joint", index, j.name, f"Box2D v3 has no form for {missing}; joint skipped")
            return
        a, b = self.built.bodies[j.body_a], self.built.bodies[j.body_b]
        if a is None or b is None:
            self.report(
                "skipped-dependent",
                "joint",
                index,
                j.name,
                f"it names body {j.body_a if a is None else j.body_b}, which was not created; joint skipped",
            )
            return
        if j.body_a == j.body_b:
            self.report("joint-self-reference", "joint", index, j.name, "it connects a body to itself; joint skipped")
            return
        check = self.joint_check(j)
        if check.passed:
            self.check_violation(index, j, check)
        if not check.passed:
            self.beyond(check, "joint", index, j.name)
            return
        record = {"collide_connected": j.collide_connected, "name": j.name}
        w = self.world
        if j.kind == "revolute":
            d = self.common(b2.RevoluteJointDef(), j, a, b)
            # v3 clamps a reference angle to +-pi but measures the joint angle unwound.
            d.reference_angle = f32(math.remainder(j.reference_angle, math.tau))
            lower, upper = self.ordered_limits(index, j, "LowerAngle", "UpperAngle")
            lo = min(max(f32(lower), -REVOLUTE_LIMIT), REVOLUTE_LIMIT)
            hi = min(max(f32(upper), -REVOLUTE_LIMIT), REVOLUTE_LIMIT)
            if j.enable_limit and (lo != lower or hi != upper):
                self.report(
                    "lossy-joint",
                    "joint",
                    index,
                    j.name,
                    f"its limit [{lower:.9g}, {upper:.9g}] reaches beyond Box2D v3's +-0.99 pi; it was clamped to [{lo:.9g}, {hi:.9g}]",
                )
            d.lower_angle, d.upper_angle = lo, hi
            d.enable_limit = j.enable_limit
            d.enable_motor = j.enable_motor
            d.motor_speed = j.motor_speed
            d.max_motor_torque = j.max_motor_torque
            record["reference_angle"] = f32(d.reference_angle)
            created = w.create_revolute_joint(d)
        elif j.kind == "prismatic":
            d = self.common(b2.PrismaticJointDef(), j, a, b)
            axis = _normalize(j.local_axis_a)
            d.local_axis_a = axis
            d.reference_angle = j.reference_angle
            d.lower_translation, d.upper_translation = self.ordered_limits(index, j, "LowerTranslation", "UpperTranslation")
            d.enable_limit = j.enable_limit
            d.enable_motor = j.enable_motor
            d.max_motor_force = j.max_motor_force
            d.motor_speed = j.motor_speed
            record.update(local_axis_a=axis, reference_angle=f32(j.reference_angle))
            created = w.create_prismatic_joint(d)
        elif j.kind in ("distance", "rope"):
            d = self.common(b2.DistanceJointDef(), j, a, b)
            if j.kind == "distance":
                d.length = self.joint_length(index, j, "Length", j.length)
                if j.frequency_hz > 0:
                    d.enable_spring = True
                    d.hertz = j.frequency_hz
                    d.damping_ratio = j.damping_ratio
            else:
                d.length = self.joint_length(index, j, "MaxLength", j.max_length)
                d.enable_spring = True
                d.hertz = 0.0
                d.enable_limit = True
                d.min_length = 0.0
                d.max_length = d.length
            created = w.create_distance_joint(d)
        elif j.kind in ("line", "wheel"):
            d = self.common(b2.WheelJointDef(), j, a, b)
            axis = _normalize(j.local_axis_a)
            d.local_axis_a = axis
            if j.kind == "line":
                d.enable_spring = False
                d.lower_translation, d.upper_translation = self.ordered_limits(index, j, "LowerTranslation", "UpperTranslation")
                d.enable_limit = j.enable_limit
                if j.enable_motor:
                    self.report("lossy-line-motor", "joint", index, j.name, "Box2D v3 has no linear motor on a line (wheel) joint; the motor is off")
            else:
                d.enable_spring = True
                d.hertz = j.frequency_hz
                d.damping_ratio = j.damping_ratio
                d.enable_motor = j.enable_motor
                d.max_motor_torque = j.max_motor_torque
                d.motor_speed = j.motor_speed
            record["local_axis_a"] = axis
            created = w.create_wheel_joint(d)
        elif j.kind == "weld":
            d = self.common(b2.WeldJointDef(), j, a, b)
            d.reference_angle = j.reference_angle
            d.linear_hertz = 0.0
            d.angular_hertz = j.frequency_hz
            d.angular_damping_ratio = j.damping_ratio
            record["reference_angle"] = f32(j.reference_angle)
            created = w.create_weld_joint(d)
        elif j.kind == "friction":
            if j.local_anchor_a != (0.0, 0.0) or j.local_anchor_b != (0.0, 0.0):
                self.report(
                    "lossy-joint",
                    "joint",
                    index,
                    j.name,
                    f"Box2D v3's friction (motor) joint acts at the body origins, not at LocalAnchorA ({j.local_anchor_a[0]:.9g}, {j.local_anchor_a[1]:.9g}) and LocalAnchorB ({j.local_anchor_b[0]:.9g}, {j.local_anchor_b[1]:.9g})",
                )
            d = self.common(b2.MotorJointDef(), j, a, b, anchors=False)
            d.linear_offset = (0.0, 0.0)
            d.angular_offset = 0.0
            d.correction_factor = 0.0
            d.max_force = j.max_force
            d.max_torque = j.max_torque
            created = w.create_motor_joint(d)
        else:
            created = self.make_motor(index, j, a, b, record)
        self.built._joints[int(created.id)] = record
        self.built.joints[index] = created

    def make_motor(self, index: int, j: Joint, a, b, record: dict):
        d = self.common(b2.MotorJointDef(), j, a, b, anchors=False)
        # v3.1.1's solver applies the offset in world axes; the file means body A's frame.
        body_a = self.scene.bodies[j.body_a]
        c, s = cosf(body_a.angle), sinf(body_a.angle)
        offset = _rotate(c, s, j.linear_offset)
        turns = not (
            body_a.kind == "static"
            or (body_a.kind == "kinematic" and body_a.angular_velocity == 0.0)
            or (body_a.kind == "dynamic" and body_a.fixed_rotation)
        )
        if turns and j.linear_offset != (0.0, 0.0):
            self.report(
                "lossy-joint",
                "joint",
                index,
                j.name,
                f"Box2D v3.1 holds LinearOffset ({j.linear_offset[0]:.9g}, {j.linear_offset[1]:.9g}) in world axes, not in body A's frame: it was turned by body A's angle as the joint starts, and stays so as body A turns",
            )
        d.linear_offset = offset
        d.angular_offset = j.angular_offset
        d.max_force = j.max_force
        d.max_torque = j.max_torque
        d.correction_factor = j.correction_factor
        if not 0.0 <= j.correction_factor <= 1.0:
            self.report("lossy-joint", "joint", index, j.name, f"CorrectionFactor {j.correction_factor:.9g} lies outside [0, 1], to which Box2D v3 clamps it")
        record["linear_offset_frame"] = (c, s)
        return self.world.create_motor_joint(d)


def _center_velocity(created: b2.Body, origin_velocity, w: float):
    """The velocity of the centre of mass of a body whose origin moves at
    ``origin_velocity``, computed as v3 computes the shift of a moved centre."""
    t = created.transform
    center = _transform_point((t.p.x, t.p.y), t.q.c, t.q.s, _local_center(created))
    shift = (-F(w) * (F(center[1]) - F(t.p.y)), F(w) * (F(center[0]) - F(t.p.x)))
    return (float(F(origin_velocity[0]) + shift[0]), float(F(origin_velocity[1]) + shift[1]))


def _local_center(body: b2.Body):
    c = body.local_center_of_mass()
    return (float(c.x), float(c.y))


def build_world(scene: Scene, world: b2.World, *, maximum_linear_speed: float = WORLD_MAX_LINEAR_SPEED) -> Built:
    """Creates every object of ``scene`` that Box2D v3 can hold in ``world`` and reports the
    rest (never asserting, never producing NaN). ``maximum_linear_speed`` is the world's
    (pyb2d3 cannot read it back): that of :func:`create_world` unless the host made its world
    otherwise."""
    b = _Build(scene, world, maximum_linear_speed)
    b.check_gravity()
    for i in range(len(scene.shapes)):
        b.make_shape(i)
    for i in range(len(scene.bodies)):
        b.make_body(i)
    # Joints come after every body has its final mass: their checks depend on it.
    for i in range(len(scene.joints)):
        b.make_joint(i)
    b.built.fixtures = [s if s is not None else c for s, c in zip(b.built.shapes, b.built.chains)]
    return b.built


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
