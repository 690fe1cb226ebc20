"""The pyb2d3 world box2scene builds is the world the file means: reference scenes of
c_tests/fidelity_scenes.h (those the C v3 adapter is held to) built by box2scene.pyb2d3 and,
here, by hand through pyb2d3's own calls from what docs/format.md says each file means, in
the same order. Both step 600 times; at steps 60 and 600 every body agrees bit for bit."""

from __future__ import annotations

import numpy as np
import pyb2d3 as b2
import pytest

import box2scene
import box2scene.pyb2d3 as b2s3
from box2scene._native import cosf, sinf

from conftest import ROOT
from helpers import DT, fidelity_scene

F = np.float32
BOX = ((-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5))
BAR = ((-1.0, -0.1), (1.0, -0.1), (1.0, 0.1), (-1.0, 0.1))
BEAM = ((0.0, -0.1), (2.0, -0.1), (2.0, 0.1), (0.0, 0.1))


class Hand:
    """A world built by hand, its bodies in the scene's order."""

    def __init__(self, gravity=(0.0, -10.0)):
        self.world = b2.World(gravity=gravity, maximum_linear_speed=b2s3.WORLD_MAX_LINEAR_SPEED)
        self.bodies = []

    def body(self, kind, x=0.0, y=0.0, angle=0.0, **fields):
        d = b2.BodyDef()
        d.type = kind
        d.position = (x, y)
        q = b2.Rot()
        q.c, q.s = cosf(angle), sinf(angle)  # the file's angle, as its cosine and sine
        d.rotation = q
        for name, value in fields.items():
            setattr(d, name, value)
        self.bodies.append(self.world.create_body_from_def(d))
        return self.bodies[-1]


def shape_def(density=0.0, friction=0.2, restitution=0.0):
    """A shape def as a fixture gives it: the format's friction default is 0.2, and Box2D
    2.x's sensors saw every shape."""
    d = b2.ShapeDef()
    d.density = density
    m = d.material
    m.friction, m.restitution = friction, restitution
    d.material = m
    d.enable_sensor_events = True
    return d


def add_polygon(body, points, density=1.0, friction=0.2, restitution=0.0):
    hull = b2.compute_hull(np.array(points, dtype=np.float32))
    body.create_polygon_shape(shape_def(density, friction, restitution), b2._pyb2d3._make_polygon(hull, 0.0))


def add_ball(body, radius=0.5, density=1.0):
    body.create_circle_shape(shape_def(density), b2.circle((0.0, 0.0), radius))


def add_ground(body, friction):
    body.create_segment_shape(shape_def(0.0, friction), b2.segment((-20.0, 0.0), (20.0, 0.0)))


def mass_data(body, mass=None, center=None, inertia=None):
    """MassData over what the shapes give: the file's inertia is about the origin, v3's
    about the centre, with a mass of 0 counted as 1 kg (as 2.x does); the centre's velocity
    then carries w x (how far it moved), which keeps the origin's velocity."""
    m = body.mass_data
    c = (F(m.center.x), F(m.center.y))
    origin_inertia = F(m.rotational_inertia) + F(m.mass) * (c[0] * c[0] + c[1] * c[1])
    new_mass = F(m.mass) if mass is None else F(mass)
    if not new_mass > 0:
        new_mass = F(1.0)
    if center is not None:
        c = (F(center[0]), F(center[1]))
    if inertia is not None:
        origin_inertia = F(inertia)
    before = body.world_center_of_mass()
    data = b2.MassData()
    data.mass = float(new_mass)
    data.center = (float(c[0]), float(c[1]))
    data.rotational_inertia = float(origin_inertia - new_mass * (c[0] * c[0] + c[1] * c[1]))
    body.mass_data = data
    w = F(body.angular_velocity)
    if w != 0:
        after = body.world_center_of_mass()
        moved = (F(after.x) - F(before.x), F(after.y) - F(before.y))
        v = body.linear_velocity
        body.linear_velocity = (float(F(v.x) + -w * moved[1]), float(F(v.y) + w * moved[0]))


def joined(d, a, b, **fields):
    d.body_a, d.body_b = a, b
    for name, value in fields.items():
        setattr(d, name, value)
    return d


def body_fields(h):
    add_ground(h.body(b2.BodyType.STATIC), 0.6)
    D = b2.BodyType.DYNAMIC
    bodies = [
        h.body(D, -3.0, 4.0, 0.3, linear_velocity=(1.0, 2.0), angular_velocity=-1.5, linear_damping=0.1, angular_damping=0.2, gravity_scale=0.5, is_bullet=True),
        h.body(D, 0.0, 3.0, 0.2, fixed_rotation=True),
        h.body(b2.BodyType.KINEMATIC, 3.0, 2.0, linear_velocity=(0.5, 0.0), angular_velocity=0.8),
        h.body(D, 6.0, 5.0, is_enabled=False),
        h.body(D, -6.0, 0.5, is_awake=False),
        h.body(D, 9.0, 3.0, is_awake=False, enable_sleep=False),  # v3 makes it awake: reported
    ]
    for body in bodies:
        add_polygon(body, BOX, 2.0, 0.4, 0.1)


def mass_data_scene(h):
    add_ground(h.body(b2.BodyType.STATIC), 0.2)
    D = b2.BodyType.DYNAMIC
    full = h.body(D, -4.0, 3.0)
    add_polygon(full, BOX)
    mass_data(full, 3.0, (0.1, 0.0), 2.0)
    spinning = h.body(D, -1.0, 6.0, angular_velocity=3.0)
    add_ball(spinning)
    mass_data(spinning, center=(0.3, 0.0))
    pendulum = h.body(D, 2.0, 6.0)
    add_ball(pendulum)
    mass_data(pendulum, 0.0, (0.4, 0.0), 0.8)
    turned = h.body(D, 5.0, 3.0, 0.4)
    add_polygon(turned, BOX)
    mass_data(turned, inertia=0.5)
    h.world.create_revolute_joint(joined(b2.RevoluteJointDef(), h.bodies[0], pendulum, local_anchor_a=(2.0, 6.0)))


def revolute(h):
    ground = h.body(b2.BodyType.STATIC)
    limited, driven = h.body(b2.BodyType.DYNAMIC, 1.0, 5.0), h.body(b2.BodyType.DYNAMIC, 5.0, 5.0)
    add_polygon(limited, BAR)
    add_polygon(driven, BAR)
    d = joined(b2.RevoluteJointDef(), ground, limited, local_anchor_a=(0.0, 5.0), local_anchor_b=(-1.0, 0.0), reference_angle=0.2)
    d.enable_limit, d.lower_angle, d.upper_angle = True, -0.5, 0.6
    h.world.create_revolute_joint(d)
    d = joined(b2.RevoluteJointDef(), ground, driven, local_anchor_a=(5.0, 5.0))
    d.enable_motor, d.motor_speed, d.max_motor_torque = True, 2.0, 50.0
    h.world.create_revolute_joint(d)


def distance(h):
    ground = h.body(b2.BodyType.STATIC)
    rod_ball, spring_ball = h.body(b2.BodyType.DYNAMIC, 3.0, 5.0), h.body(b2.BodyType.DYNAMIC, 6.0, 3.0)
    add_ball(rod_ball)
    add_ball(spring_ball)
    h.world.create_distance_joint(joined(b2.DistanceJointDef(), ground, rod_ball, local_anchor_a=(0.0, 5.0), length=3.0))
    d = joined(b2.DistanceJointDef(), ground, spring_ball, local_anchor_a=(6.0, 6.0), length=2.0)
    d.enable_spring, d.hertz, d.damping_ratio = True, 2.0, 0.3
    h.world.create_distance_joint(d)


def rope(h):
    ground = h.body(b2.BodyType.STATIC)
    box = h.body(b2.BodyType.DYNAMIC, 2.0, 5.0)
    add_polygon(box, BOX)
    # Slack up to MaxLength: a spring of 0 Hz with its upper limit on.
    d = joined(b2.DistanceJointDef(), ground, box, local_anchor_a=(0.0, 5.0), length=3.0)
    d.enable_spring, d.hertz = True, 0.0
    d.enable_limit, d.min_length, d.max_length = True, 0.0, 3.0
    h.world.create_distance_joint(d)


def line(h):
    ground = h.body(b2.BodyType.STATIC)
    box = h.body(b2.BodyType.DYNAMIC, 0.0, 2.0, linear_velocity=(3.0, 0.0))
    add_polygon(box, BOX)
    # Box2D 2.1's line joint: a wheel joint without its spring.
    d = joined(b2.WheelJointDef(), ground, box, local_anchor_a=(0.0, 2.0), local_axis_a=(1.0, 0.0))
    d.enable_spring = False
    d.enable_limit, d.lower_translation, d.upper_translation = True, -1.0, 2.0
    h.world.create_wheel_joint(d)


def friction(h):
    h.world.gravity = (0.0, 0.0)
    ground = h.body(b2.BodyType.STATIC)
    puck = h.body(b2.BodyType.DYNAMIC, linear_velocity=(4.0, 1.0), angular_velocity=3.0)
    add_polygon(puck, BOX)
    # A motor joint that holds no offset.
    d = joined(b2.MotorJointDef(), ground, puck, linear_offset=(0.0, 0.0), angular_offset=0.0, correction_factor=0.0, max_force=2.0, max_torque=0.5)
    h.world.create_motor_joint(d)


def weld(h):
    ground = h.body(b2.BodyType.STATIC)
    soft, rigid = h.body(b2.BodyType.DYNAMIC, 0.0, 5.0), h.body(b2.BodyType.DYNAMIC, 0.0, 2.0, 0.1)
    add_polygon(soft, BEAM)
    add_polygon(rigid, BEAM)
    d = joined(b2.WeldJointDef(), ground, soft, local_anchor_a=(0.0, 5.0))
    d.linear_hertz, d.angular_hertz, d.angular_damping_ratio = 0.0, 1.0, 0.2
    h.world.create_weld_joint(d)
    d = joined(b2.WeldJointDef(), ground, rigid, local_anchor_a=(0.0, 2.0), reference_angle=0.1)
    d.linear_hertz, d.angular_hertz, d.angular_damping_ratio = 0.0, 0.0, 0.0
    h.world.create_weld_joint(d)


def motor(h):
    ground = h.body(b2.BodyType.STATIC, angle=1.0)
    box = h.body(b2.BodyType.DYNAMIC)
    add_polygon(box, BOX)
    # The offset is in body A's frame; v3.1.1 holds it in world axes.
    c, s = F(cosf(1.0)), F(sinf(1.0))
    offset = (float(c * F(2.0) - s * F(0.0)), float(s * F(2.0) + c * F(0.0)))
    d = joined(b2.MotorJointDef(), ground, box, linear_offset=offset, angular_offset=0.5, max_force=100.0, max_torque=50.0, correction_factor=0.3)
    h.world.create_motor_joint(d)


SCENES = {
    "body_fields": body_fields,
    "mass_data": mass_data_scene,
    "revolute": revolute,
    "distance": distance,
    "rope": rope,
    "line": line,
    "weld": weld,
    "friction": friction,
    "motor": motor,
}


def state(body):
    t, v = body.transform, body.linear_velocity
    return (t.p.x, t.p.y, t.q.c, t.q.s, v.x, v.y, body.angular_velocity)


@pytest.mark.parametrize("name", SCENES)
def test_a_reference_scene_builds_the_world_built_by_hand(name):
    scene = box2scene.loads(fidelity_scene(ROOT, name))
    world = b2s3.create_world(scene)
    built = b2s3.build_world(scene, world)
    hand = Hand()
    SCENES[name](hand)
    assert len(hand.bodies) == len(built.bodies) and all(b is not None for b in built.bodies)
    reported = {r.index for r in built.reports if r.object == "body"}
    assert (world.gravity.x, world.gravity.y) == (hand.world.gravity.x, hand.world.gravity.y)
    for steps in (60, 540):
        for _ in range(steps):
            world.step(DT, 4)
            hand.world.step(DT, 4)
        for i, (mine, theirs) in enumerate(zip(built.bodies, hand.bodies)):
            if i not in reported:
                assert state(mine) == state(theirs), (name, i)
