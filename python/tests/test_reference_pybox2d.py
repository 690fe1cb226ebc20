"""The pybox2d world box2scene builds is the world the file means: reference scenes of
c_tests/fidelity_scenes.h (those the C++ 2.4 adapter is held to) built by
box2scene.pybox2d and, here, by hand through pybox2d's own calls (Box2D 2.3, the engine the
format's files were written for) from what docs/format.md says each file means, in the same
order. Both step 600 times; at steps 60 and 600 every body agrees bit for bit."""

from __future__ import annotations

import Box2D as B
import pytest

import box2scene
import box2scene.pybox2d as b2s2

from conftest import ROOT
from helpers import DT, fidelity_scene

BOX = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
BAR = [(-1.0, -0.1), (1.0, -0.1), (1.0, 0.1), (-1.0, 0.1)]
BEAM = [(0.0, -0.1), (2.0, -0.1), (2.0, 0.1), (0.0, 0.1)]
DYNAMIC, STATIC, KINEMATIC = B.b2_dynamicBody, B.b2_staticBody, B.b2_kinematicBody


class Hand:
    """A world built by hand, its bodies in the scene's order."""

    def __init__(self):
        self.world = B.b2World(gravity=(0.0, -10.0))
        self.bodies = []

    def body(self, kind, x=0.0, y=0.0, angle=0.0, **fields):
        self.bodies.append(self.world.CreateBody(B.b2BodyDef(type=kind, position=(x, y), angle=angle, **fields)))
        return self.bodies[-1]


def fixture(body, shape, density, friction=0.2, restitution=0.0):
    """A fixture as the file gives it: the format's defaults are Box2D's."""
    body.CreateFixture(B.b2FixtureDef(shape=shape, density=density, friction=friction, restitution=restitution))


def ground():
    return B.b2EdgeShape(vertices=[(-20.0, 0.0), (20.0, 0.0)])


def mass_data(body, mass=None, center=None, inertia=None):
    """MassData: what the file gives over what the fixtures give (inertia about the origin)."""
    m = body.massData
    if mass is not None:
        m.mass = mass
    if center is not None:
        m.center = center
    if inertia is not None:
        m.I = inertia
    body.massData = m


def body_fields(h):
    fixture(h.body(STATIC), ground(), 0.0, 0.6)
    bodies = [
        h.body(DYNAMIC, -3.0, 4.0, 0.3, linearVelocity=(1.0, 2.0), angularVelocity=-1.5, linearDamping=0.1, angularDamping=0.2, gravityScale=0.5, bullet=True),
        h.body(DYNAMIC, 0.0, 3.0, 0.2, fixedRotation=True),
        h.body(KINEMATIC, 3.0, 2.0, linearVelocity=(0.5, 0.0), angularVelocity=0.8),
        h.body(DYNAMIC, 6.0, 5.0, active=False),
        h.body(DYNAMIC, -6.0, 0.5, awake=False),
        h.body(DYNAMIC, 9.0, 3.0, awake=False, allowSleep=False),
    ]
    for body in bodies:
        fixture(body, B.b2PolygonShape(vertices=BOX), 2.0, 0.4, 0.1)


def mass_data_scene(h):
    fixture(h.body(STATIC), ground(), 0.0)
    full = h.body(DYNAMIC, -4.0, 3.0)
    fixture(full, B.b2PolygonShape(vertices=BOX), 1.0)
    mass_data(full, 3.0, (0.1, 0.0), 2.0)
    spinning = h.body(DYNAMIC, -1.0, 6.0, angularVelocity=3.0)
    fixture(spinning, B.b2CircleShape(radius=0.5), 1.0)
    mass_data(spinning, center=(0.3, 0.0))
    pendulum = h.body(DYNAMIC, 2.0, 6.0)
    fixture(pendulum, B.b2CircleShape(radius=0.5), 1.0)
    mass_data(pendulum, 0.0, (0.4, 0.0), 0.8)
    turned = h.body(DYNAMIC, 5.0, 3.0, 0.4)
    fixture(turned, B.b2PolygonShape(vertices=BOX), 1.0)
    mass_data(turned, inertia=0.5)
    h.world.CreateJoint(B.b2RevoluteJointDef(bodyA=h.bodies[0], bodyB=pendulum, localAnchorA=(2.0, 6.0)))


def revolute(h):
    ground_body = h.body(STATIC)
    limited, driven = h.body(DYNAMIC, 1.0, 5.0), h.body(DYNAMIC, 5.0, 5.0)
    fixture(limited, B.b2PolygonShape(vertices=BAR), 1.0)
    fixture(driven, B.b2PolygonShape(vertices=BAR), 1.0)
    h.world.CreateJoint(
        B.b2RevoluteJointDef(bodyA=ground_body, bodyB=limited, localAnchorA=(0.0, 5.0), localAnchorB=(-1.0, 0.0), referenceAngle=0.2, enableLimit=True, lowerAngle=-0.5, upperAngle=0.6)
    )
    h.world.CreateJoint(B.b2RevoluteJointDef(bodyA=ground_body, bodyB=driven, localAnchorA=(5.0, 5.0), enableMotor=True, motorSpeed=2.0, maxMotorTorque=50.0))


def distance(h):
    ground_body = h.body(STATIC)
    rod_ball, spring_ball = h.body(DYNAMIC, 3.0, 5.0), h.body(DYNAMIC, 6.0, 3.0)
    fixture(rod_ball, B.b2CircleShape(radius=0.5), 1.0)
    fixture(spring_ball, B.b2CircleShape(radius=0.5), 1.0)
    h.world.CreateJoint(B.b2DistanceJointDef(bodyA=ground_body, bodyB=rod_ball, localAnchorA=(0.0, 5.0), length=3.0))
    # Box2D 2.3 holds the file's spring as it is.
    h.world.CreateJoint(B.b2DistanceJointDef(bodyA=ground_body, bodyB=spring_ball, localAnchorA=(6.0, 6.0), length=2.0, frequencyHz=2.0, dampingRatio=0.3))


def rope(h):
    ground_body = h.body(STATIC)
    box = h.body(DYNAMIC, 2.0, 5.0)
    fixture(box, B.b2PolygonShape(vertices=BOX), 1.0)
    # Box2D 2.3's own rope joint.
    h.world.CreateJoint(B.b2RopeJointDef(bodyA=ground_body, bodyB=box, localAnchorA=(0.0, 5.0), localAnchorB=(0.0, 0.0), maxLength=3.0))


def friction(h):
    h.world.gravity = (0.0, 0.0)
    ground_body = h.body(STATIC)
    puck = h.body(DYNAMIC, linearVelocity=(4.0, 1.0), angularVelocity=3.0)
    fixture(puck, B.b2PolygonShape(vertices=BOX), 1.0)
    h.world.CreateJoint(B.b2FrictionJointDef(bodyA=ground_body, bodyB=puck, maxForce=2.0, maxTorque=0.5))


def weld(h):
    ground_body = h.body(STATIC)
    soft, rigid = h.body(DYNAMIC, 0.0, 5.0), h.body(DYNAMIC, 0.0, 2.0, 0.1)
    fixture(soft, B.b2PolygonShape(vertices=BEAM), 1.0)
    fixture(rigid, B.b2PolygonShape(vertices=BEAM), 1.0)
    # Box2D 2.3's soft weld is the file's own.
    h.world.CreateJoint(B.b2WeldJointDef(bodyA=ground_body, bodyB=soft, localAnchorA=(0.0, 5.0), frequencyHz=1.0, dampingRatio=0.2))
    h.world.CreateJoint(B.b2WeldJointDef(bodyA=ground_body, bodyB=rigid, localAnchorA=(0.0, 2.0), referenceAngle=0.1))


def motor(h):
    ground_body = h.body(STATIC, angle=1.0)
    box = h.body(DYNAMIC)
    fixture(box, B.b2PolygonShape(vertices=BOX), 1.0)
    # The offset in body A's frame, as Box2D 2.3 holds it.
    h.world.CreateJoint(B.b2MotorJointDef(bodyA=ground_body, bodyB=box, linearOffset=(2.0, 0.0), angularOffset=0.5, maxForce=100.0, maxTorque=50.0, correctionFactor=0.3))


SCENES = {
    "body_fields": body_fields,
    "mass_data": mass_data_scene,
    "revolute": revolute,
    "distance": distance,
    "rope": rope,
    "weld": weld,
    "friction": friction,
    "motor": motor,
}


def state(body):
    p, v = body.position, body.linearVelocity
    return (p[0], p[1], body.angle, v[0], v[1], body.angularVelocity)


@pytest.mark.parametrize("name", SCENES)
def test_a_reference_scene_builds_the_world_built_by_hand(name):
    scene = box2scene.loads(fidelity_scene(ROOT, name))
    world = b2s2.create_world(scene)
    built = b2s2.build_world(scene, world)
    hand = Hand()
    SCENES[name](hand)
    assert len(hand.bodies) == len(built.bodies) and all(b is not None for b in built.bodies)
    assert tuple(world.gravity) == tuple(hand.world.gravity)
    for steps in (60, 540):
        for _ in range(steps):
            world.Step(DT, 8, 3)
            hand.world.Step(DT, 8, 3)
        for i, (mine, theirs) in enumerate(zip(built.bodies, hand.bodies)):
            assert state(mine) == state(theirs), (name, i)
