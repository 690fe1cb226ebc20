"""box2scene.pybox2d against the real pybox2d (``box2d`` 2.3.10) from the package registry."""

from __future__ import annotations

import math
import os

import Box2D as B
import pytest

import box2scene
import box2scene.pybox2d as b2s2

from conftest import ROOT, scene_files, scene_id
from helpers import DT, SceneMaker, codes, f32, finite, growth_over, labels


def build(scene):
    world = B.b2World(gravity=b2s2.scene_gravity(scene, (0.0, -10.0)))
    return world, b2s2.build_world(scene, world)


def step(world, n=600):
    for _ in range(n):
        world.Step(DT, 8, 3)


def state(body):
    p, v = body.position, body.linearVelocity
    return (p[0], p[1], body.angle, v[0], v[1], body.angularVelocity)


@pytest.mark.parametrize("path", scene_files(), ids=scene_id)
def test_every_scene_builds_and_steps_600_times_finite(path):
    scene = box2scene.load(path)
    world, built = build(scene)
    assert len(built.bodies) == len(scene.bodies) and len(built.fixtures) == len(scene.fixture_ids)
    step(world)
    for body in built.bodies:
        if body is not None:
            assert finite(*state(body))
            assert abs(body.position[0]) < 1e5 and abs(body.position[1]) < 1e5


def test_body_fields_are_exact():
    m = SceneMaker()
    m.body(position=(1.0, 2.0), angle=7.5, linear_velocity=(1.0, -2.0), linear_damping=0.1, gravity_scale=0.5, bullet=True, fixed_rotation=True, awake=False, allow_sleep=False)
    m.body("kinematic", angular_velocity=1.0, active=False)
    world, built = build(m.finish())
    body = built.bodies[0]
    assert body.angle == f32(7.5)  # 2.x keeps the angle, whole turns and all
    assert (body.linearDamping, body.gravityScale, body.bullet, body.fixedRotation) == (f32(0.1), 0.5, True, True)
    assert not body.awake and not body.sleepingAllowed
    assert not built.bodies[1].active and built.reports == []


def test_mass_data_is_set_after_the_fixtures():
    m = SceneMaker(gravity=(0.0, 0.0))
    m.body(mass=2.0, inertia=5.0, linear_velocity=(1.0, 0.0))
    m.body(center=(0.25, 0.0))
    m.body(mass=1.0, center=(3.0, 0.0), inertia=1.0)
    world, built = build(m.finish())
    a, b = built.bodies[0].massData, built.bodies[1].massData
    assert (a.mass, a.I) == (2.0, 5.0) and tuple(a.center) == (0.0, 0.0)
    assert b.mass == 1.0 and tuple(b.center) == (0.25, 0.0)
    assert built.bodies[2] is None and codes(built.reports)[0] == ("beyond-box2d-range", "body", 2)


def test_shapes_keep_their_ghosts():
    m = SceneMaker()
    one = m.fixture(m.shape("edge", vertices=((0.0, 0.0), (1.0, 0.0)), prev_vertex=(-1.0, 0.5)))
    chain = m.fixture(m.shape("chain", vertices=((0.0, 0.0), (2.0, 0.0), (4.0, 1.0)), next_vertex=(5.0, 3.0)))
    loop = m.fixture(m.shape("chain", vertices=((0.0, 0.0), (4.0, 0.0), (0.0, 4.0)), is_loop=True))
    off = m.fixture(m.shape("polygon", vertices=((0.0, 0.0), (1.0, 0.0), (0.0, 1.0)), centroid=(0.25, 0.25)))
    m.body("static", fixtures=(one, chain, loop, off))
    world, built = build(m.finish())
    edge = built.fixtures[0].shape
    assert edge.hasVertex0 and not edge.hasVertex3 and tuple(edge.vertex0) == (-1.0, 0.5)
    c = built.fixtures[1].shape
    assert c.m_hasNextVertex and not c.m_hasPrevVertex and tuple(c.m_nextVertex) == (5.0, 3.0)
    assert built.fixtures[2].shape.vertexCount == 4  # the loop closes on its first vertex
    assert tuple(built.fixtures[3].shape.centroid) == (0.25, 0.25)
    assert built.reports == []


def pair(kind_a="static", **joint):
    m = SceneMaker()
    a = m.body(kind_a, position=(0.0, 5.0), fixtures=())
    b = m.body(position=(0.0, 3.0))
    kind = joint.pop("kind")
    m.joint(kind, a, b, **joint)
    return m.finish()


def test_springs_are_box2d_23s_own():
    world, built = build(pair(kind="distance", length=2.0, frequency_hz=3.0, damping_ratio=0.25))
    assert (built.joints[0].frequency, built.joints[0].dampingRatio, built.joints[0].length) == (3.0, 0.25, 2.0)
    world, built = build(pair(kind="wheel", local_axis_a=(0.0, 1.0), frequency_hz=4.0, damping_ratio=0.5))
    assert (built.joints[0].springFrequencyHz, built.joints[0].springDampingRatio) == (4.0, 0.5)
    world, built = build(pair("dynamic", kind="weld", local_anchor_a=(0.0, -1.0), local_anchor_b=(0.0, 1.0), frequency_hz=5.0, damping_ratio=0.7))
    assert (built.joints[0].GetFrequency(), built.joints[0].GetDampingRatio()) == (5.0, f32(0.7))
    step(world)
    assert abs(built.bodies[0].angle - built.bodies[1].angle) < 0.05


def test_a_rod_keeps_its_length_and_a_rope_its_maximum():
    world, built = build(pair(kind="distance", length=2.0))
    step(world)
    assert abs(built.bodies[1].position[1] - 3.0) < 0.01
    world, built = build(pair(kind="rope", local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0), max_length=3.0))
    assert isinstance(built.joints[0], B.b2RopeJoint) and built.joints[0].maxLength == 3.0
    step(world)
    assert 5.0 - built.bodies[1].position[1] < 3.05


def test_line_motor_and_limit_are_reported():
    world, built = build(pair(kind="line", local_axis_a=(0.0, 1.0), enable_motor=True, enable_limit=True, upper_limit=1.0))
    assert codes(built.reports) == [("lossy-line-motor", "joint", 0), ("lossy-joint", "joint", 0), ("lossy-joint", "joint", 0)]
    assert "uninitialised" in built.reports[2].message
    assert built.joints[0].springFrequencyHz == f32(1e-3) and "a spring of 0.001 Hz" in built.reports[2].message
    step(world, 60)
    assert abs(built.bodies[1].position[0]) < 1e-4 and built.bodies[1].position[1] < 3.0


def test_motor_friction_pulley_and_gear():
    m = SceneMaker(gravity=(0.0, 0.0))
    a = m.body("static", angle=math.pi / 2, fixtures=())
    b = m.body()
    m.joint("motor", a, b, linear_offset=(2.0, 0.0), max_force=100.0, max_torque=100.0, correction_factor=0.3)
    c = m.body(position=(10.0, 0.0))
    m.joint("friction", a, c, max_force=3.0, max_torque=2.0)
    d, e = m.body(position=(-5.0, 0.0)), m.body(position=(5.0, 0.0))
    m.joint("pulley", d, e, ground_anchor_a=(-5.0, 5.0), ground_anchor_b=(5.0, 5.0), local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0), length_a=5.0, length_b=5.0, ratio=1.0)
    # body A is turned a quarter: its anchors (0, 5) and (0, -5) lie at d and e, satisfied
    g = m.joint("gear", d, e, joint_a=m.joint("revolute", a, d, local_anchor_a=(0.0, 5.0)), joint_b=m.joint("revolute", a, e, local_anchor_a=(0.0, -5.0)), ratio=2.0)
    world, built = build(m.finish())
    assert built.reports == [] and built.joints[g].ratio == 2.0
    assert (built.joints[1].maxForce, built.joints[1].maxTorque) == (3.0, 2.0)
    step(world)
    moved = built.bodies[b].position
    assert abs(moved[0]) < 0.05 and abs(moved[1] - 2.0) < 0.05  # the offset is in body A's frame


def test_pulley_max_lengths_are_reported():
    satisfied = dict(local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0), ground_anchor_a=(0.0, 8.0), ground_anchor_b=(0.0, 6.0), length_a=3.0, length_b=3.0, ratio=1.0)
    world, built = build(pair(kind="pulley", max_length_a=3.0, **satisfied))
    assert codes(built.reports) == [("lossy-joint", "joint", 0)]


def test_a_captured_world_writes_and_loads_to_the_same_world(showcase):
    scene = box2scene.load(showcase)
    world, built = build(scene)
    captured, reports = b2s2.capture_world(world, built)
    assert reports == []
    again = box2scene.load(captured.to_xml().encode(), strict=True)
    # In the order they were created: a gear after the joints it couples.
    assert sorted(j.kind for j in again.joints) == sorted(j.kind for j in scene.joints)
    assert sorted(j.name for j in again.joints) == sorted(j.name for j in scene.joints)
    assert [b.name for b in again.bodies] == [b.name for b in scene.bodies]
    world2, built2 = build(again)
    for n in (0, 1, 300):
        step(world, n)
        step(world2, n)
        assert [state(b) for b in built.bodies] == [state(b) for b in built2.bodies]


def test_a_capture_refuses_a_body_named_twice():
    world = B.b2World()
    body = world.CreateDynamicBody()
    with pytest.raises(box2scene.Error) as raised:
        b2s2.capture_world(world, bodies=[body, body])
    assert raised.value.code == "invalid-argument"


def _balls(radius, *bodies):
    """A scene maker with a ball fixture of ``radius`` and bodies (kind, position) holding it
    (a static one none)."""
    m = SceneMaker()
    ball = m.fixture(m.shape("circle", radius=radius), density=1.0)
    made = [m.body(kind, position=position, fixtures=() if kind == "static" else (ball,), **changes) for kind, position, changes in bodies]
    return m, made


def test_an_inertia_below_the_tables_bound_is_refused():
    """The builder's own bound was 1e-20 kg m^2; the library's table (2.4's measurements,
    which 2.3's solver shares) has 1e-12."""
    m, (a, b) = _balls(1.0, ("static", (0.0, 0.0), {}), ("dynamic", (0.0, 0.0), dict(angle=0.001, inertia=1e-16)))
    m.joint("prismatic", a, b)
    world, built = build(m.finish())
    assert built.bodies[1] is None
    assert ("beyond-box2d-range", "body", 1) in codes(built.reports)
    step(world)


def test_a_weld_35_radii_out_is_built():
    """The builder's own 3x3 lever bound was 30 radii of gyration; the table's is 75 (the
    sweep's farthest that holds, 71): a weld 5 m out on a 0.2 m ball (35 radii) holds."""
    m, (a, b) = _balls(0.2, ("dynamic", (0.0, 0.0), {}), ("dynamic", (5.0, 0.0), {}))
    m.joint("weld", a, b, local_anchor_a=(0.0, 0.0), local_anchor_b=(-5.0, 0.0))
    world, built = build(m.finish())
    assert built.joints[0] is not None and built.reports == []
    step(world)
    assert all(finite(*state(body)) for body in built.bodies)


def test_a_second_joint_that_starts_violated_on_a_body_is_left_out():
    """The table's max_pulled_violation, which the builder did not check: 2.x's position
    solver can tear a body that two joints starting far from satisfied pull to NaN."""
    m, (a, b, c) = _balls(0.5, ("static", (0.0, 0.0), {}), ("dynamic", (2.0, 0.0), {}), ("static", (0.0, 3.0), {}))
    m.joint("revolute", a, b, local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0))
    m.joint("revolute", c, b, local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0))
    world, built = build(m.finish())
    assert built.joints[0] is not None and built.joints[1] is None
    assert codes(built.reports) == [("beyond-box2d-range", "joint", 1)]
    assert "already pulls body 1" in built.reports[0].message
    step(world)


def test_a_joint_started_beyond_max_violation_is_left_out():
    """The table's max_violation, which the builder did not check: a joint 7 m from
    satisfied is refused (2.x's position solver tears a body to NaN once other joints act
    on it), one 3 m off is built."""
    m, (a, b, c) = _balls(0.5, ("static", (0.0, 0.0), {}), ("dynamic", (7.0, 0.0), {}), ("dynamic", (-3.0, 0.0), {}))
    m.joint("revolute", a, b, local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0))
    m.joint("revolute", a, c, local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0))
    world, built = build(m.finish())
    assert built.joints[0] is None and built.joints[1] is not None
    assert codes(built.reports) == [("beyond-box2d-range", "joint", 0)]
    assert built.reports[0].message.startswith("it starts 7 m from satisfied: a joint further than 4 m from satisfied lies beyond Box2D 2.3's working range")
    step(world)
    assert all(finite(*state(body)) for body in built.bodies)


def test_a_prismatic_lever_to_body_bs_anchor_is_refused():
    """Body B's anchor 25 m along the axis from a 0.2 m ball (177 radii) is body A's lever
    too (the table's prismatic_lever_to_b), as in the 2.4 adapter."""
    m, (a, b) = _balls(0.2, ("dynamic", (0.0, 0.0), {}), ("dynamic", (25.0, 0.0), {}))
    m.joint("prismatic", a, b, local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0), local_axis_a=(1.0, 0.0))
    world, built = build(m.finish())
    assert built.joints[0] is None
    assert codes(built.reports) == [("beyond-box2d-range", "joint", 0)]
    # body A's lever reaches body B's anchor, 25 m from A's centre (its own anchor is at it)
    assert "LocalAnchorA: the joint acts 25 m from the centre of mass of body 0" in built.reports[0].message
    assert "radii of gyration out" in built.reports[0].message


def _brake_scene():
    """Two balls joined by a friction joint named PuckBrake (3 N, 1 N m)."""
    m, (a, b) = _balls(0.5, ("dynamic", (0.0, 0.0), {}), ("dynamic", (3.0, 0.0), {}))
    m.joint("friction", a, b, name="PuckBrake", max_force=3.0, max_torque=1.0, local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0))
    return m.finish()


def test_a_joint_made_at_a_destroyed_built_joints_address_is_captured_as_the_hosts():
    """Box2D 2.3 gives a new joint the address of the one destroyed before it: the host's
    brake of 900 N and 400 N m is saved as its own, never as PuckBrake's 3 and 1."""
    scene = _brake_scene()
    world, built = build(scene)
    old = built.joints[0]
    address = int(old.this)
    world.DestroyJoint(old)
    a, b = built.bodies
    mine = world.CreateJoint(B.b2FrictionJointDef(bodyA=a, bodyB=b, maxForce=900.0, maxTorque=400.0))
    assert int(mine.this) == address  # the case under test: Box2D reused the address
    saved, reports = b2s2.capture_world(world, built, joints=[mine])
    assert [(j.kind, j.name, j.max_force, j.max_torque) for j in saved.joints] == [("friction", None, 900.0, 400.0)]
    assert codes(reports) == [("lossy-capture", "joint", 0)]
    assert reports[0].name == "PuckBrake" and "destroyed" in reports[0].message
    alone, _ = b2s2.capture_world(world, built)
    assert alone.joints == ()


def test_a_joint_the_host_makes_is_captured_with_its_own_maxima():
    """pybox2d reads a friction and a motor joint's maxima as properties; the capture read
    them through getters it lacks and wrote the defaults."""
    world, built = build(_brake_scene())
    a, b = built.bodies
    mine = world.CreateJoint(B.b2MotorJointDef(bodyA=a, bodyB=b, maxForce=900.0, maxTorque=400.0, linearOffset=(1.0, 2.0), angularOffset=0.5))
    saved, _ = b2s2.capture_world(world, built, joints=[mine])
    made, host = saved.joints
    assert (made.name, made.max_force, made.max_torque) == ("PuckBrake", 3.0, 1.0)
    assert (host.kind, host.max_force, host.max_torque, host.linear_offset, host.angular_offset) == ("motor", 900.0, 400.0, (1.0, 2.0), f32(0.5))


def test_2000_worlds_built_captured_and_dropped_grow_memory_by_under_4_mib(showcase):
    """What capture needs lives on the built result: nothing is left behind per world."""
    scene = box2scene.load(showcase)

    def make_and_drop():
        world, built = build(scene)
        b2s2.capture_world(world, built)

    assert growth_over(2000, make_and_drop) < 4 * 1024 * 1024


def test_both_builders_take_the_same_arguments():
    import inspect

    import box2scene.pyb2d3 as b2s3

    def positional(function):
        return [p.name for p in inspect.signature(function).parameters.values() if p.kind in (p.POSITIONAL_OR_KEYWORD, p.VAR_KEYWORD)]

    for name in ("create_world", "build_world", "capture_world", "scene_gravity"):
        assert positional(getattr(b2s2, name)) == positional(getattr(b2s3, name)), name
    assert {"bodies", "fixtures", "joints", "reports"} <= {f for f in b2s2.Built.__dataclass_fields__} & {f for f in b2s3.Built.__dataclass_fields__}


def test_a_capture_keeps_the_scene_names_of_fixtures_and_not_of_a_later_one_at_the_same_address():
    """A built fixture keeps its scene name; one the host makes after destroying it, at the
    address Box2D 2.3 gives back, has none."""
    m = SceneMaker()
    ball = m.fixture(m.shape("circle", radius=0.5), density=1.0, name="Ball")
    rim = m.fixture(m.shape("circle", radius=0.25, position=(1.0, 0.0)), density=1.0, name="Rim")
    m.body(fixtures=(ball, rim), name="Wheel")
    world, built = build(m.finish())
    saved, reports = b2s2.capture_world(world, built)
    assert reports == [] and [f.name for f in saved.fixtures] == ["Ball", "Rim"]
    assert [b.name for b in saved.bodies] == ["Wheel"]
    rim_fixture = built.fixtures[1]
    address = int(rim_fixture.this)
    built.bodies[0].DestroyFixture(rim_fixture)
    mine = built.bodies[0].CreateFixture(B.b2FixtureDef(shape=B.b2CircleShape(radius=0.25), density=1.0))
    assert int(mine.this) == address  # the case under test: Box2D reused the address
    saved, _ = b2s2.capture_world(world, built)
    assert [f.name for f in saved.fixtures] == ["Ball", None]


@pytest.mark.parametrize("path", scene_files(), ids=scene_id)
def test_the_plans_masses_are_pybox2ds_to_the_bit(path):
    """The plan predicts each body's mass in f32 as Box2D 2.3 sums it (its polygons fanned
    from the mean of their vertices, 1 kg for a dynamic body without mass): what pybox2d's
    bodies hold once built. A body given its MassData holds the mass and centre given."""
    scene = box2scene.load(path)
    world, built = build(scene)
    g = world.gravity
    plan = box2scene._native.make_plan(scene._native, "box2d-2.3", (float(g[0]), float(g[1])))
    for planned in plan.bodies:
        held = built.bodies[planned.body].massData
        if planned.set_mass:
            assert (held.mass, tuple(held.center)) == (planned.mass, planned.center), planned.body
        else:
            assert (held.mass, tuple(held.center), held.I) == (planned.mass, planned.center, planned.inertia), planned.body


def test_lookups_reach_the_engine_objects_and_back(showcase):
    scene = box2scene.load(showcase)
    world, built = build(scene)
    i, j = scene.find_body("BridgePostLeft"), scene.find_joint("BridgeLink1")
    assert built.find_body("BridgePostLeft") is built.bodies[i]
    assert built.find_joint("BridgeLink1") is built.joints[j]
    assert built.find_body("Nobody") is None and built.find_fixture("Nothing") is None
    assert built.body_index(world.bodies[i]) == i  # another Python object of the same body
    assert built.joint_index(built.joints[j]) == j
    assert all(built.fixture_slot(f) == k for k, f in enumerate(built.fixtures) if f is not None)


def test_a_body_made_at_a_destroyed_built_bodys_address_is_the_hosts():
    """Box2D 2.3 gives a new body the address of the one destroyed before it: a capture and
    the lookups take it as the host's, never as the built body's."""
    m, (a, b) = _balls(0.5, ("dynamic", (0.0, 0.0), {}), ("dynamic", (3.0, 0.0), {}))
    world, built = build(m.finish())
    old = built.bodies[1]
    address = int(old.this)
    world.DestroyBody(old)
    mine = world.CreateBody(B.b2BodyDef(type=B.b2_dynamicBody, position=(7.0, 0.0)))
    assert int(mine.this) == address  # the case under test: Box2D reused the address
    assert built.body_index(mine) is None
    saved, _ = b2s2.capture_world(world, built)
    assert [b.position for b in saved.bodies] == [(0.0, 0.0)]
    saved, _ = b2s2.capture_world(world, built, bodies=[mine])
    assert [b.position for b in saved.bodies] == [(0.0, 0.0), (7.0, 0.0)]


def test_a_capture_of_a_built_world_writes_a_skipped_joint_back_in_its_place_with_the_levels_names():
    """The build leaves out a joint 7 m from satisfied; the capture writes it back as the
    file has it, so that the named joint after it keeps its index, and every record its
    Name, with no host code."""
    m, (a, b, c) = _balls(0.5, ("static", (0.0, 0.0), {}), ("dynamic", (7.0, 0.0), {}), ("dynamic", (-3.0, 0.0), {}))
    m.joint("revolute", a, b, name="Far", local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0))
    m.joint("revolute", a, c, name="Near", local_anchor_a=(0.0, 0.0), local_anchor_b=(0.0, 0.0))
    scene = m.finish()
    world, built = build(scene)
    assert built.joints[0] is None
    saved, reports = b2s2.capture_world(world, built)
    assert reports == []
    assert [(j.name, j.body_a, j.body_b) for j in saved.joints] == [("Far", 0, 1), ("Near", 0, 2)]
    assert saved.joints[0] == scene.joints[0]


def test_a_capture_keeps_the_levels_names_and_user_data():
    """Every body, fixture and joint the build made is saved with its scene Name and
    UserData, with no host code (the capture had kept names alone)."""
    scene = box2scene.load(os.path.join(ROOT, "tests", "fixtures", "scenes", "every-v1-field.xml"))
    world, built = build(scene)
    saved, _ = b2s2.capture_world(world, built)
    assert any(data is not None for _, data in labels(scene, scene.bodies))
    assert labels(saved, saved.bodies) == labels(scene, scene.bodies)
    assert labels(saved, saved.joints) == labels(scene, scene.joints)
    assert set(labels(saved, saved.fixtures)) == set(labels(scene, scene.fixtures))
