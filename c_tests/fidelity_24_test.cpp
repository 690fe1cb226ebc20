// The world the Box2D 2.4 adapter builds is the world the file means: each scene of
// fidelity_scenes.h built by build_world and, here, by hand through Box2D's own API from
// what docs/format.md ("Onto Box2D 2.4.1") says the file means, in the adapter's creation
// order (bodies with their fixtures in file order, joints in file order, a pulley's limits
// right after it, gears last). Both step 600 times; at steps 60 and 600 every body must
// agree bit for bit, but for a body the adapter names in a report. One CTest per scene
// (fidelity_24_<scene>); without an argument, every scene.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <set>
#include <vector>

#include "fidelity_scenes.h"
#include "test_macros.h"
#include "test_scenes.hpp"
#include "test_worlds.hpp"

namespace {

b2PolygonShape polygon(std::initializer_list<b2Vec2> points) {
    std::vector<b2Vec2> v(points);
    b2PolygonShape shape;
    shape.Set(v.data(), static_cast<int32>(v.size()));
    return shape;
}

b2PolygonShape box() {
    return polygon({{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}});
}

b2EdgeShape segment(b2Vec2 a, b2Vec2 b) {
    b2EdgeShape shape;
    shape.SetTwoSided(a, b);
    return shape;
}

b2EdgeShape ground() {
    return segment(b2Vec2(-20.0f, 0.0f), b2Vec2(20.0f, 0.0f));
}

b2CircleShape circle(float radius, b2Vec2 at = b2Vec2(0.0f, 0.0f)) {
    b2CircleShape shape;
    shape.m_radius = radius;
    shape.m_p = at;
    return shape;
}

/// A fixture as the file gives it: the format's defaults are Box2D's.
b2Fixture* fixture(b2Body* body, const b2Shape& shape, float density, float friction = 0.2f,
                   float restitution = 0.0f) {
    b2FixtureDef def;
    def.shape = &shape;
    def.density = density;
    def.friction = friction;
    def.restitution = restitution;
    return body->CreateFixture(&def);
}

b2BodyDef body_def(b2BodyType type, float x = 0.0f, float y = 0.0f, float angle = 0.0f) {
    b2BodyDef def;
    def.type = type;
    def.position.Set(x, y);
    def.angle = angle;
    return def;
}

/// MassData: what the file gives over what the fixtures give (inertia about the origin).
void mass_data(b2Body* body, const float* mass, const b2Vec2* center, const float* inertia) {
    b2MassData m;
    body->GetMassData(&m);
    if (mass != nullptr) {
        m.mass = *mass;
    }
    if (center != nullptr) {
        m.center = *center;
    }
    if (inertia != nullptr) {
        m.I = *inertia;
    }
    body->SetMassData(&m);
}

struct Hand {
    b2World world{b2Vec2(0.0f, -10.0f)};
    std::vector<b2Body*> bodies;

    b2Body* add(const b2BodyDef& def) {
        bodies.push_back(world.CreateBody(&def));
        return bodies.back();
    }
    b2Body* operator[](size_t i) const { return bodies.at(i); }
};

void body_fields(Hand& h) {
    b2PolygonShape b = box();
    b2EdgeShape g = ground();
    fixture(h.add(body_def(b2_staticBody)), g, 0.0f, 0.6f);
    b2BodyDef thrown = body_def(b2_dynamicBody, -3.0f, 4.0f, 0.3f);
    thrown.linearVelocity.Set(1.0f, 2.0f);
    thrown.angularVelocity = -1.5f;
    thrown.linearDamping = 0.1f;
    thrown.angularDamping = 0.2f;
    thrown.gravityScale = 0.5f;
    thrown.bullet = true;
    b2BodyDef fixed = body_def(b2_dynamicBody, 0.0f, 3.0f, 0.2f);
    fixed.fixedRotation = true;
    b2BodyDef platform = body_def(b2_kinematicBody, 3.0f, 2.0f);
    platform.linearVelocity.Set(0.5f, 0.0f);
    platform.angularVelocity = 0.8f;
    b2BodyDef off = body_def(b2_dynamicBody, 6.0f, 5.0f);
    off.enabled = false;
    b2BodyDef asleep = body_def(b2_dynamicBody, -6.0f, 0.5f);
    asleep.awake = false;
    b2BodyDef awake_less = body_def(b2_dynamicBody, 9.0f, 3.0f);
    awake_less.awake = false;
    awake_less.allowSleep = false;
    for (const b2BodyDef& def : {thrown, fixed, platform, off, asleep, awake_less}) {
        fixture(h.add(def), b, 2.0f, 0.4f, 0.1f);
    }
}

void mass_data(Hand& h) {
    b2PolygonShape b = box();
    b2EdgeShape g = ground();
    b2CircleShape ball = circle(0.5f);
    fixture(h.add(body_def(b2_staticBody)), g, 0.0f);
    const float three = 3.0f, two = 2.0f, zero = 0.0f, eight = 0.8f, half = 0.5f;
    const b2Vec2 c1(0.1f, 0.0f), c2(0.3f, 0.0f), c3(0.4f, 0.0f);
    b2Body* full = h.add(body_def(b2_dynamicBody, -4.0f, 3.0f));
    fixture(full, b, 1.0f);
    mass_data(full, &three, &c1, &two);
    b2BodyDef spin = body_def(b2_dynamicBody, -1.0f, 6.0f);
    spin.angularVelocity = 3.0f;
    b2Body* spinning = h.add(spin);
    fixture(spinning, ball, 1.0f);
    mass_data(spinning, nullptr, &c2, nullptr);
    b2Body* pendulum = h.add(body_def(b2_dynamicBody, 2.0f, 6.0f));
    fixture(pendulum, ball, 1.0f);
    mass_data(pendulum, &zero, &c3, &eight);
    b2Body* turned = h.add(body_def(b2_dynamicBody, 5.0f, 3.0f, 0.4f));
    fixture(turned, b, 1.0f);
    mass_data(turned, nullptr, nullptr, &half);
    b2RevoluteJointDef pin;
    pin.bodyA = h[0];
    pin.bodyB = pendulum;
    pin.localAnchorA.Set(2.0f, 6.0f);
    h.world.CreateJoint(&pin);
}

void shapes(Hand& h) {
    b2CircleShape wheel = circle(0.4f, b2Vec2(0.1f, 0.0f));
    b2PolygonShape triangle = polygon({{0.0f, 0.0f}, {1.0f, 0.0f}, {0.3f, 0.8f}});
    b2EdgeShape g = ground();
    b2EdgeShape ramp = segment(b2Vec2(-8.0f, 4.0f), b2Vec2(-2.0f, 2.0f));
    const b2Vec2 dip[] = {{4.0f, 3.0f}, {7.0f, 1.5f}, {10.0f, 3.0f}};
    b2ChainShape chain;
    // Box2D 2.4 needs both ghosts: extended straight from the end segments.
    chain.CreateChain(dip, 3, b2Vec2(1.0f, 4.5f), b2Vec2(13.0f, 4.5f));
    b2PolygonShape hexagon = polygon({{0.6f, 0.0f}, {0.3f, 0.52f}, {-0.3f, 0.52f},
                                      {-0.6f, 0.0f}, {-0.3f, -0.52f}, {0.3f, -0.52f}});
    hexagon.m_centroid.Set(0.05f, 0.0f);
    b2CircleShape sensor = circle(0.3f);
    b2Body* floor = h.add(body_def(b2_staticBody));
    fixture(floor, g, 0.0f, 0.8f);
    fixture(floor, ramp, 0.0f);
    fixture(floor, chain, 0.0f);
    for (float x : {-6.0f, -5.5f}) {
        b2Body* ball = h.add(body_def(b2_dynamicBody, x, x == -6.0f ? 6.0f : 8.0f));
        b2FixtureDef def;
        def.shape = &wheel;
        def.density = 1.0f;
        def.friction = 0.3f;
        def.filter.categoryBits = 2;
        def.filter.maskBits = 65533;
        def.filter.groupIndex = -1;
        ball->CreateFixture(&def);
    }
    fixture(h.add(body_def(b2_dynamicBody, 6.5f, 5.0f)), triangle, 2.0f, 0.2f, 0.2f);
    fixture(h.add(body_def(b2_dynamicBody, 1.0f, 4.0f)), hexagon, 1.0f);
    b2FixtureDef sensing;
    sensing.shape = &sensor;
    sensing.isSensor = true;
    h.add(body_def(b2_staticBody, 1.0f, 1.0f))->CreateFixture(&sensing);
}

b2PolygonShape bar() {
    return polygon({{-1.0f, -0.1f}, {1.0f, -0.1f}, {1.0f, 0.1f}, {-1.0f, 0.1f}});
}

void revolute(Hand& h) {
    b2PolygonShape b = bar();
    h.add(body_def(b2_staticBody));
    fixture(h.add(body_def(b2_dynamicBody, 1.0f, 5.0f)), b, 1.0f);
    fixture(h.add(body_def(b2_dynamicBody, 5.0f, 5.0f)), b, 1.0f);
    b2RevoluteJointDef limited;
    limited.bodyA = h[0];
    limited.bodyB = h[1];
    limited.localAnchorA.Set(0.0f, 5.0f);
    limited.localAnchorB.Set(-1.0f, 0.0f);
    limited.referenceAngle = 0.2f;
    limited.enableLimit = true;
    limited.lowerAngle = -0.5f;
    limited.upperAngle = 0.6f;
    h.world.CreateJoint(&limited);
    b2RevoluteJointDef motor;
    motor.bodyA = h[0];
    motor.bodyB = h[2];
    motor.localAnchorA.Set(5.0f, 5.0f);
    motor.enableMotor = true;
    motor.motorSpeed = 2.0f;
    motor.maxMotorTorque = 50.0f;
    h.world.CreateJoint(&motor);
}

void prismatic(Hand& h) {
    b2PolygonShape b = box();
    h.add(body_def(b2_staticBody));
    fixture(h.add(body_def(b2_dynamicBody, 0.0f, 3.0f)), b, 1.0f);
    h.add(body_def(b2_staticBody, 5.0f, 0.0f, 0.5f));
    fixture(h.add(body_def(b2_dynamicBody, 5.0f, 3.0f, 0.6f)), b, 1.0f);
    b2PrismaticJointDef slider;
    slider.bodyA = h[0];
    slider.bodyB = h[1];
    slider.localAnchorA.Set(0.0f, 3.0f);
    slider.localAxisA.Set(1.0f, 1.0f); // the prismatic joint normalises it
    slider.enableLimit = true;
    slider.lowerTranslation = -1.0f;
    slider.upperTranslation = 1.5f;
    slider.enableMotor = true;
    slider.maxMotorForce = 30.0f;
    slider.motorSpeed = 2.0f;
    h.world.CreateJoint(&slider);
    b2PrismaticJointDef turned;
    turned.bodyA = h[2];
    turned.bodyB = h[3];
    turned.localAnchorA.Set(1.43827662f, 2.63274789f);
    turned.localAxisA.Set(0.0f, 1.0f);
    turned.referenceAngle = 0.1f;
    turned.enableLimit = true;
    turned.lowerTranslation = -2.0f;
    turned.upperTranslation = 1.0f;
    h.world.CreateJoint(&turned);
}

void distance(Hand& h) {
    b2CircleShape ball = circle(0.5f);
    h.add(body_def(b2_staticBody));
    fixture(h.add(body_def(b2_dynamicBody, 3.0f, 5.0f)), ball, 1.0f);
    fixture(h.add(body_def(b2_dynamicBody, 6.0f, 3.0f)), ball, 1.0f);
    b2DistanceJointDef rod; // FrequencyHz 0: rigid, all three lengths the Length
    rod.bodyA = h[0];
    rod.bodyB = h[1];
    rod.localAnchorA.Set(0.0f, 5.0f);
    rod.length = rod.minLength = rod.maxLength = 3.0f;
    h.world.CreateJoint(&rod);
    b2DistanceJointDef spring;
    spring.bodyA = h[0];
    spring.bodyB = h[2];
    spring.localAnchorA.Set(6.0f, 6.0f);
    spring.length = 2.0f;
    spring.minLength = 0.0f;
    spring.maxLength = FLT_MAX;
    b2LinearStiffness(spring.stiffness, spring.damping, 2.0f, 0.3f, h[0], h[2]);
    h.world.CreateJoint(&spring);
}

void rope(Hand& h) {
    b2PolygonShape b = box();
    h.add(body_def(b2_staticBody));
    fixture(h.add(body_def(b2_dynamicBody, 2.0f, 5.0f)), b, 1.0f);
    b2DistanceJointDef def; // slack up to MaxLength
    def.bodyA = h[0];
    def.bodyB = h[1];
    def.localAnchorA.Set(0.0f, 5.0f);
    def.length = def.maxLength = 3.0f;
    def.minLength = 0.0f;
    h.world.CreateJoint(&def);
}

void line(Hand& h) {
    b2PolygonShape b = box();
    h.add(body_def(b2_staticBody));
    b2BodyDef moving = body_def(b2_dynamicBody, 0.0f, 2.0f);
    moving.linearVelocity.Set(3.0f, 0.0f);
    fixture(h.add(moving), b, 1.0f);
    b2WheelJointDef def; // Box2D 2.1's line joint: no spring
    def.bodyA = h[0];
    def.bodyB = h[1];
    def.localAnchorA.Set(0.0f, 2.0f);
    def.localAxisA.Set(1.0f, 0.0f);
    def.enableLimit = true;
    def.lowerTranslation = -1.0f;
    def.upperTranslation = 2.0f;
    def.stiffness = def.damping = 0.0f;
    h.world.CreateJoint(&def);
}

void wheel(Hand& h) {
    b2EdgeShape g = ground();
    b2PolygonShape chassis = polygon({{-2.0f, -0.25f}, {2.0f, -0.25f}, {2.0f, 0.25f}, {-2.0f, 0.25f}});
    b2CircleShape tyre = circle(0.4f);
    fixture(h.add(body_def(b2_staticBody)), g, 0.0f, 0.9f);
    fixture(h.add(body_def(b2_dynamicBody, 0.0f, 1.2f)), chassis, 1.0f);
    fixture(h.add(body_def(b2_dynamicBody, -1.5f, 0.4f)), tyre, 1.0f, 0.9f);
    fixture(h.add(body_def(b2_dynamicBody, 1.5f, 0.4f)), tyre, 1.0f, 0.9f);
    const float hz[] = {2.0f, 3.0f}, zeta[] = {0.7f, 0.5f}, x[] = {-1.5f, 1.5f};
    for (int i = 0; i < 2; ++i) {
        b2WheelJointDef def;
        def.bodyA = h[1];
        def.bodyB = h[2 + i];
        def.localAnchorA.Set(x[i], -0.8f);
        def.localAxisA.Set(0.0f, 1.0f);
        def.enableMotor = i == 0;
        def.maxMotorTorque = i == 0 ? 20.0f : 0.0f;
        def.motorSpeed = i == 0 ? -5.0f : 0.0f;
        // Box2D 2.2's wheel spring: the effective mass along the axis.
        wheel_spring_22(hz[i], zeta[i], def.bodyA, def.bodyB, def.localAnchorA,
                        def.localAnchorB, def.localAxisA, def.stiffness, def.damping);
        h.world.CreateJoint(&def);
    }
}

void weld(Hand& h) {
    b2PolygonShape beam = polygon({{0.0f, -0.1f}, {2.0f, -0.1f}, {2.0f, 0.1f}, {0.0f, 0.1f}});
    h.add(body_def(b2_staticBody));
    fixture(h.add(body_def(b2_dynamicBody, 0.0f, 5.0f)), beam, 1.0f);
    fixture(h.add(body_def(b2_dynamicBody, 0.0f, 2.0f, 0.1f)), beam, 1.0f);
    b2WeldJointDef soft; // Box2D 2.2's soft weld: inertias about the centres of mass
    soft.bodyA = h[0];
    soft.bodyB = h[1];
    soft.localAnchorA.Set(0.0f, 5.0f);
    weld_spring_22(1.0f, 0.2f, h[0], h[1], soft.stiffness, soft.damping);
    h.world.CreateJoint(&soft);
    b2WeldJointDef rigid;
    rigid.bodyA = h[0];
    rigid.bodyB = h[2];
    rigid.localAnchorA.Set(0.0f, 2.0f);
    rigid.referenceAngle = 0.1f;
    h.world.CreateJoint(&rigid);
}

void friction(Hand& h) {
    h.world.SetGravity(b2Vec2(0.0f, 0.0f));
    b2PolygonShape b = box();
    h.add(body_def(b2_staticBody));
    b2BodyDef puck = body_def(b2_dynamicBody);
    puck.linearVelocity.Set(4.0f, 1.0f);
    puck.angularVelocity = 3.0f;
    fixture(h.add(puck), b, 1.0f);
    b2FrictionJointDef def;
    def.bodyA = h[0];
    def.bodyB = h[1];
    def.maxForce = 2.0f;
    def.maxTorque = 0.5f;
    h.world.CreateJoint(&def);
}

void motor(Hand& h) {
    b2PolygonShape b = box();
    h.add(body_def(b2_staticBody, 0.0f, 0.0f, 1.0f));
    fixture(h.add(body_def(b2_dynamicBody)), b, 1.0f);
    b2MotorJointDef def; // the offset in body A's frame, as Box2D 2.4 holds it
    def.bodyA = h[0];
    def.bodyB = h[1];
    def.linearOffset.Set(2.0f, 0.0f);
    def.angularOffset = 0.5f;
    def.maxForce = 100.0f;
    def.maxTorque = 50.0f;
    def.correctionFactor = 0.3f;
    h.world.CreateJoint(&def);
}

void turning_a(Hand& h) {
    b2PolygonShape b = box();
    b2BodyDef turntable = body_def(b2_kinematicBody);
    turntable.angularVelocity = 0.5f;
    fixture(h.add(turntable), b, 1.0f);
    fixture(h.add(body_def(b2_dynamicBody, 2.0f, 0.0f)), b, 1.0f);
    fixture(h.add(body_def(b2_dynamicBody, 0.0f, 3.0f)), b, 1.0f);
    fixture(h.add(body_def(b2_dynamicBody, -3.0f, 0.0f)), b, 1.0f);
    b2RevoluteJointDef hinge;
    hinge.bodyA = h[0];
    hinge.bodyB = h[1];
    hinge.localAnchorA.Set(2.0f, 0.0f);
    h.world.CreateJoint(&hinge);
    b2PrismaticJointDef slider;
    slider.bodyA = h[0];
    slider.bodyB = h[2];
    slider.localAnchorA.Set(0.0f, 3.0f);
    slider.localAxisA.Set(0.0f, 1.0f);
    slider.enableLimit = true;
    slider.lowerTranslation = -1.0f;
    slider.upperTranslation = 1.0f;
    h.world.CreateJoint(&slider);
    b2MotorJointDef motor; // the offset turns with body A, in 2.4 as in the file
    motor.bodyA = h[0];
    motor.bodyB = h[3];
    motor.linearOffset.Set(-3.0f, 0.0f);
    motor.maxForce = 200.0f;
    motor.maxTorque = 50.0f;
    h.world.CreateJoint(&motor);
}

void pulley(Hand& h) {
    b2PolygonShape b = box();
    h.add(body_def(b2_staticBody));
    fixture(h.add(body_def(b2_dynamicBody, -2.0f, 3.0f)), b, 2.0f);
    fixture(h.add(body_def(b2_dynamicBody, 2.0f, 4.0f)), b, 1.0f);
    b2PulleyJointDef def;
    def.bodyA = h[1];
    def.bodyB = h[2];
    def.collideConnected = false;
    def.groundAnchorA.Set(-2.0f, 8.0f);
    def.groundAnchorB.Set(2.0f, 8.0f);
    def.localAnchorA.SetZero();
    def.localAnchorB.SetZero();
    def.lengthA = 5.0f;
    def.lengthB = 4.0f;
    def.ratio = 1.0f;
    h.world.CreateJoint(&def);
    // Box2D 2.1.2's MaxLengthA 5.5: a rope from the ground anchor (MaxLengthB absent).
    b2DistanceJointDef limit;
    limit.bodyA = h[0];
    limit.bodyB = h[1];
    limit.localAnchorA.Set(-2.0f, 8.0f);
    limit.length = limit.maxLength = 5.5f;
    limit.minLength = 0.0f;
    h.world.CreateJoint(&limit);
}

void gear(Hand& h) {
    b2CircleShape ball = circle(0.5f);
    h.add(body_def(b2_staticBody));
    b2BodyDef driven = body_def(b2_dynamicBody, 0.0f, 3.0f);
    driven.angularVelocity = 2.0f;
    fixture(h.add(driven), ball, 1.0f);
    fixture(h.add(body_def(b2_dynamicBody, 3.0f, 3.0f)), ball, 1.0f);
    b2Joint* axles[2];
    for (int i = 0; i < 2; ++i) {
        b2RevoluteJointDef def;
        def.bodyA = h[0];
        def.bodyB = h[1 + i];
        def.localAnchorA.Set(3.0f * i, 3.0f);
        axles[i] = h.world.CreateJoint(&def);
    }
    b2GearJointDef def;
    def.bodyA = h[1];
    def.bodyB = h[2];
    def.joint1 = axles[0];
    def.joint2 = axles[1];
    def.ratio = 2.0f;
    h.world.CreateJoint(&def);
}

struct Row {
    const char* name;
    void (*build)(Hand&);
};

const Row rows[] = {{"body_fields", body_fields}, {"mass_data", mass_data},
                    {"shapes", shapes},           {"revolute", revolute},
                    {"prismatic", prismatic},     {"distance", distance},
                    {"rope", rope},               {"line", line},
                    {"wheel", wheel},             {"weld", weld},
                    {"friction", friction},       {"motor", motor},
                    {"turning_a", turning_a},     {"pulley", pulley},
                    {"gear", gear}};

/// The bodies a report names: its body, or the bodies of its joint.
std::set<size_t> named_bodies(const World& w) {
    std::set<size_t> named;
    const b2s_scene_view& view = view_of(w.scene);
    for (const box2scene::Report& r : w.built.reports) {
        if (std::strcmp(r.object, "body") == 0) {
            named.insert(r.index);
        } else if (std::strcmp(r.object, "joint") == 0 && r.index < view.joint_count) {
            named.insert(view.joints[r.index].body_a);
            named.insert(view.joints[r.index].body_b);
        }
    }
    return named;
}

int differing_bodies(const World& w, const Hand& h, int step) {
    std::set<size_t> named = named_bodies(w);
    int different = 0;
    for (size_t i = 0; i < h.bodies.size(); ++i) {
        if (named.count(i) == 0 && ensure_same_state(i, w.body(i), h[i]) != 0) {
            std::fprintf(stderr, "  after %d steps\n", step);
            different += 1;
        }
    }
    return different;
}

int run_row(const Row& row) {
    const fidelity_scene* scene = fidelity_scene_named(row.name);
    ENSURE(scene != nullptr);
    World w(scene->xml);
    ENSURE(w.scene != nullptr);
    for (const box2scene::Report& r : w.built.reports) {
        std::fprintf(stderr, "  report: %s %s %u: %s\n", b2s_code_name(r.code), r.object,
                     r.index, r.message.c_str());
    }
    Hand h;
    row.build(h);
    ENSURE_EQ(w.built.bodies.size(), h.bodies.size());
    ENSURE_EQ(w.world.GetJointCount(), h.world.GetJointCount());
    ENSURE(same_bits(w.world.GetGravity(), h.world.GetGravity()));
    std::vector<b2Vec2> start;
    for (b2Body* b : h.bodies) {
        start.push_back(b->GetPosition());
    }
    step_for(w.world, 60);
    step_for(h.world, 60);
    ENSURE_EQ(differing_bodies(w, h, 60), 0);
    step_for(w.world, 540);
    step_for(h.world, 540);
    ENSURE_EQ(differing_bodies(w, h, 600), 0);
    // The comparison means something only if the world moved.
    bool moved = false;
    for (size_t i = 0; i < h.bodies.size(); ++i) {
        moved = moved || b2Distance(start[i], h[i]->GetPosition()) > 0.01f ||
                h[i]->GetAngle() != 0.0f;
    }
    ENSURE(moved);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    int failed = 0, ran = 0;
    for (const Row& row : rows) {
        if (argc < 2 || std::strcmp(argv[1], row.name) == 0) {
            int row_failed = run_row(row);
            std::printf("%s %s\n", row_failed != 0 ? "FAIL" : "pass", row.name);
            failed += row_failed;
            ran += 1;
        }
    }
    return ran == 0 ? 1 : failed;
}
