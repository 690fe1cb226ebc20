// The adapter against Box2D by hand: tests/fixtures/adapter/every-v1-field.xml (every Version 1
// field) goes through b2s_load_file and build_world; the same world is written here with
// plain Box2D calls, following docs/format.md ("Onto Box2D 2.4.1"). Both step 120 times
// and every body must end in exactly the same state, bit for bit. Creation order matters to
// Box2D's solver, so the hand-built world creates bodies, fixtures and joints in the
// adapter's order: bodies and their fixtures in file order, then joints in file order, gears
// last.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cstring>
#include <initializer_list>
#include <vector>

#include "test_macros.h"
#include "test_scenes.hpp"
#include "test_worlds.hpp"

static const b2Vec2 kGravity(0.5f, -9.8f);

// ---- the file's shapes

static b2CircleShape wheel_shape() {
    b2CircleShape shape;
    shape.m_radius = 0.5f;
    shape.m_p.Set(0.1f, -0.2f);
    return shape;
}

static b2PolygonShape box_shape() {
    const b2Vec2 v[] = {{-1.0f, -0.25f}, {1.0f, -0.25f}, {1.0f, 0.25f}, {-1.0f, 0.25f}};
    b2PolygonShape shape;
    shape.Set(v, 4);
    return shape;
}

static b2PolygonShape triangle_shape() {
    const b2Vec2 v[] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.3f, 0.8f}};
    b2PolygonShape shape;
    shape.Set(v, 3);
    shape.m_centroid.Set(0.45f, 0.3f);
    return shape;
}

static b2EdgeShape ground_shape() {
    b2EdgeShape shape;
    shape.SetTwoSided(b2Vec2(-40.0f, 0.0f), b2Vec2(40.0f, 0.0f));
    return shape;
}

static b2PolygonShape hexagon_shape() {
    const b2Vec2 v[] = {{0.6f, 0.0f},   {0.3f, 0.52f},   {-0.3f, 0.52f},
                        {-0.6f, 0.0f},  {-0.3f, -0.52f}, {0.3f, -0.52f}};
    b2PolygonShape shape;
    shape.Set(v, 6);
    shape.m_centroid.Set(0.0f, 0.0f);
    return shape;
}

static b2CircleShape sensor_shape() {
    b2CircleShape shape;
    shape.m_radius = 0.25f;
    shape.m_p.Set(0.0f, 0.0f);
    return shape;
}

// ---- the file's fixtures, by index

static void add_fixture(b2Body* body, int index) {
    const b2CircleShape wheel = wheel_shape();
    const b2PolygonShape box = box_shape();
    const b2PolygonShape triangle = triangle_shape();
    const b2EdgeShape ground = ground_shape();
    const b2PolygonShape hexagon = hexagon_shape();
    const b2CircleShape sensor = sensor_shape();
    b2FixtureDef def;
    switch (index) {
    case 0:
        def.shape = &wheel;
        def.density = 2.0f;
        def.friction = 0.4f;
        def.restitution = 0.1f;
        def.filter.categoryBits = 0x0002;
        def.filter.maskBits = 65533;
        def.filter.groupIndex = -1;
        break;
    case 1:
        def.shape = &box;
        def.density = 1.5f;
        def.friction = 0.6f;
        def.filter.categoryBits = 4;
        break;
    case 2:
        def.shape = &triangle;
        def.density = 3.0f;
        break;
    case 3:
        def.shape = &ground;
        def.friction = 0.8f;
        break;
    case 4:
        def.shape = &hexagon;
        def.density = 0.5f;
        def.restitution = 0.3f;
        break;
    case 5:
        def.shape = &sensor;
        def.isSensor = true;
        break;
    case 6:
        def.shape = &wheel;
        def.density = 1.0f;
        def.filter.groupIndex = 3;
        break;
    }
    body->CreateFixture(&def);
}

static b2Body* add_body(b2World& world, const b2BodyDef& def, std::initializer_list<int> fixtures) {
    b2Body* body = world.CreateBody(&def);
    for (int fixture : fixtures) {
        add_fixture(body, fixture);
    }
    return body;
}

static b2BodyDef body_at(b2BodyType type, float x, float y) {
    b2BodyDef def;
    def.type = type;
    def.position.Set(x, y);
    return def;
}

// ---- the file's bodies, in file order, with their MassData

static std::vector<b2Body*> add_bodies(b2World& world) {
    std::vector<b2Body*> bodies;
    bodies.push_back(add_body(world, body_at(b2_staticBody, 0.0f, 0.0f), {3}));

    b2BodyDef chassis = body_at(b2_dynamicBody, 0.0f, 4.0f);
    chassis.enabled = true;
    chassis.allowSleep = false;
    chassis.angle = 0.1f;
    chassis.angularDamping = 0.05f;
    chassis.angularVelocity = 0.2f;
    chassis.awake = true;
    chassis.bullet = true;
    chassis.fixedRotation = false;
    chassis.linearDamping = 0.01f;
    chassis.linearVelocity.Set(1.0f, 0.5f);
    bodies.push_back(add_body(world, chassis, {1, 5}));
    b2MassData mass;
    bodies.back()->GetMassData(&mass);
    mass.mass = 3.0f;
    mass.center.Set(0.1f, 0.0f);
    mass.I = 2.0f;
    bodies.back()->SetMassData(&mass);

    bodies.push_back(add_body(world, body_at(b2_dynamicBody, -1.0f, 3.5f), {0}));
    bodies.back()->GetMassData(&mass);
    mass.mass = 2.5f;
    bodies.back()->SetMassData(&mass);

    bodies.push_back(add_body(world, body_at(b2_dynamicBody, 1.0f, 3.5f), {0, 6}));
    bodies.back()->GetMassData(&mass);
    mass.center.Set(0.0f, 0.05f);
    bodies.back()->SetMassData(&mass);

    b2BodyDef triangle = body_at(b2_dynamicBody, 3.0f, 6.0f);
    triangle.fixedRotation = true;
    bodies.push_back(add_body(world, triangle, {2}));
    bodies.back()->GetMassData(&mass);
    mass.I = 0.9f;
    bodies.back()->SetMassData(&mass);

    b2BodyDef platform = body_at(b2_kinematicBody, -5.0f, 2.0f);
    platform.linearVelocity.Set(0.5f, 0.0f);
    platform.angularVelocity = 0.3f;
    bodies.push_back(add_body(world, platform, {4}));

    b2BodyDef inactive = body_at(b2_dynamicBody, 10.0f, 10.0f);
    inactive.enabled = false;
    bodies.push_back(add_body(world, inactive, {1}));

    b2BodyDef asleep = body_at(b2_dynamicBody, -8.0f, 5.0f);
    asleep.awake = false;
    bodies.push_back(add_body(world, asleep, {4}));

    bodies.push_back(add_body(world, body_at(b2_dynamicBody, 20.0f, 20.0f), {}));
    bodies.push_back(add_body(world, body_at(b2_dynamicBody, -6.0f, 8.0f), {1}));
    bodies.push_back(add_body(world, body_at(b2_dynamicBody, -3.0f, 8.0f), {4}));
    bodies.push_back(add_body(world, body_at(b2_dynamicBody, 6.0f, 2.0f), {2}));
    bodies.push_back(add_body(world, body_at(b2_dynamicBody, 8.0f, 6.0f), {0}));

    b2BodyDef dragged = body_at(b2_dynamicBody, 4.0f, 1.0f);
    dragged.linearVelocity.Set(3.0f, 0.0f);
    bodies.push_back(add_body(world, dragged, {1}));

    b2BodyDef gear_wheel = body_at(b2_dynamicBody, 12.0f, 5.0f);
    gear_wheel.angularVelocity = 2.0f;
    bodies.push_back(add_body(world, gear_wheel, {0}));
    bodies.push_back(add_body(world, body_at(b2_dynamicBody, 14.0f, 5.0f), {6}));
    bodies.push_back(add_body(world, body_at(b2_dynamicBody, -10.0f, 3.0f), {1}));

    b2BodyDef welded = body_at(b2_dynamicBody, 2.0f, 6.0f);
    welded.angle = 0.1f;
    bodies.push_back(add_body(world, welded, {2}));
    return bodies;
}

// ---- the file's joints: every one but the gear in file order, then the gear

static b2Joint* add_revolute(b2World& world, b2Body* a, b2Body* b, b2Vec2 anchor_a) {
    b2RevoluteJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = anchor_a;
    return world.CreateJoint(&def);
}

static void add_rope(b2World& world, b2Body* ground, b2Body* body, b2Vec2 ground_anchor,
                     b2Vec2 anchor, float max_length) {
    b2DistanceJointDef rope;
    rope.bodyA = ground;
    rope.bodyB = body;
    rope.localAnchorA = ground_anchor;
    rope.localAnchorB = anchor;
    rope.length = rope.maxLength = max_length;
    rope.minLength = 0.0f;
    world.CreateJoint(&rope);
}

static void add_joints(b2World& world, const std::vector<b2Body*>& body) {
    b2RevoluteJointDef left;
    left.bodyA = body[1];
    left.bodyB = body[2];
    left.localAnchorA.Set(-1.0f, -0.5f);
    left.localAnchorB.Set(0.0f, 0.0f);
    left.referenceAngle = -0.1f;
    left.enableMotor = true;
    left.motorSpeed = -2.0f;
    left.maxMotorTorque = 50.0f;
    world.CreateJoint(&left);

    b2RevoluteJointDef right;
    right.bodyA = body[1];
    right.bodyB = body[3];
    right.collideConnected = true;
    right.localAnchorA.Set(1.0f, -0.5f);
    right.enableLimit = true;
    right.lowerAngle = -0.5f;
    right.upperAngle = 0.5f;
    world.CreateJoint(&right);

    b2PrismaticJointDef prismatic;
    prismatic.bodyA = body[0];
    prismatic.bodyB = body[11];
    prismatic.localAnchorA.Set(6.0f, 2.0f);
    prismatic.localAnchorB.Set(0.0f, 0.0f);
    prismatic.localAxisA.Set(1.0f, 0.5f);
    prismatic.referenceAngle = 0.0f;
    prismatic.enableLimit = true;
    prismatic.lowerTranslation = -1.0f;
    prismatic.upperTranslation = 2.0f;
    prismatic.enableMotor = true;
    prismatic.maxMotorForce = 20.0f;
    prismatic.motorSpeed = 1.0f;
    world.CreateJoint(&prismatic);

    b2DistanceJointDef rod;
    rod.bodyA = body[0];
    rod.bodyB = body[12];
    rod.localAnchorA.Set(8.0f, 9.0f);
    rod.localAnchorB.Set(0.0f, 0.0f);
    rod.length = rod.minLength = rod.maxLength = 3.0f;
    world.CreateJoint(&rod);

    b2DistanceJointDef spring;
    spring.bodyA = body[1];
    spring.bodyB = body[4];
    spring.localAnchorA.Set(0.0f, 0.25f);
    spring.localAnchorB.Set(0.3f, 0.3f);
    spring.length = 2.5f;
    spring.minLength = 0.0f;
    spring.maxLength = FLT_MAX;
    b2LinearStiffness(spring.stiffness, spring.damping, 4.0f, 0.5f, body[1], body[4]);
    world.CreateJoint(&spring);

    b2PulleyJointDef pulley;
    pulley.bodyA = body[9];
    pulley.bodyB = body[10];
    pulley.collideConnected = false;
    pulley.groundAnchorA.Set(-6.0f, 12.0f);
    pulley.groundAnchorB.Set(-3.0f, 12.0f);
    pulley.localAnchorA.Set(0.0f, 0.25f);
    pulley.localAnchorB.Set(0.0f, 0.5f);
    pulley.lengthA = 3.75f;
    pulley.lengthB = 3.5f;
    pulley.ratio = 1.5f;
    world.CreateJoint(&pulley);
    // Box2D 2.1.2's MaxLengthA/B: ropes from the ground anchors, on the static body 0. Side
    // A keeps its 6 m; side B is cut to (LengthA + Ratio * LengthB - 2 m) / Ratio.
    add_rope(world, body[0], body[9], pulley.groundAnchorA, pulley.localAnchorA, 6.0f);
    add_rope(world, body[0], body[10], pulley.groundAnchorB, pulley.localAnchorB,
             (9.0f - 2.0f) / 1.5f);

    b2Joint* gear_axle_1 = add_revolute(world, body[0], body[14], b2Vec2(12.0f, 5.0f));
    b2Joint* gear_axle_2 = add_revolute(world, body[0], body[15], b2Vec2(14.0f, 5.0f));

    // Line: a wheel joint without spring; its linear motor has no 2.4 equivalent.
    b2WheelJointDef line;
    line.bodyA = body[0];
    line.bodyB = body[16];
    line.localAnchorA.Set(-10.0f, 3.0f);
    line.localAxisA.Set(0.0f, 1.0f);
    line.enableLimit = true;
    line.lowerTranslation = -0.5f;
    line.upperTranslation = 0.5f;
    line.stiffness = 0.0f;
    line.damping = 0.0f;
    world.CreateJoint(&line);

    b2WeldJointDef weld;
    weld.bodyA = body[1];
    weld.bodyB = body[17];
    weld.localAnchorA.Set(2.0f, 2.0f);
    weld.localAnchorB.Set(0.0f, 0.0f);
    weld.referenceAngle = 0.0f;
    world.CreateJoint(&weld);

    b2FrictionJointDef friction;
    friction.bodyA = body[0];
    friction.bodyB = body[13];
    friction.localAnchorA.Set(4.0f, 1.0f);
    friction.maxForce = 5.0f;
    friction.maxTorque = 2.0f;
    world.CreateJoint(&friction);

    b2GearJointDef gear;
    gear.bodyA = body[14];
    gear.bodyB = body[15];
    gear.joint1 = gear_axle_1;
    gear.joint2 = gear_axle_2;
    gear.ratio = 2.0f;
    world.CreateJoint(&gear);
}

static void step(b2World& world) {
    for (int i = 0; i < 120; ++i) {
        world.Step(1.0f / 60.0f, 8, 3);
    }
}

static int loaded_world_equals_hand_built_world() {
    ScenePtr scene = load_project_file("tests/fixtures/adapter/every-v1-field.xml");
    ENSURE(scene != nullptr);
    b2Vec2 gravity = box2scene::scene_gravity(scene.get(), b2Vec2(0.0f, -10.0f));
    ENSURE(same_bits(gravity, kGravity));
    b2World loaded_world(gravity);
    box2scene::Built built = box2scene::build_world(scene.get(), loaded_world);

    b2World hand_world(kGravity);
    std::vector<b2Body*> by_hand = add_bodies(hand_world);
    add_joints(hand_world, by_hand);

    ENSURE_EQ(built.bodies.size(), by_hand.size());
    ENSURE_EQ(loaded_world.GetBodyCount(), hand_world.GetBodyCount());
    ENSURE_EQ(loaded_world.GetJointCount(), hand_world.GetJointCount());
    ENSURE_EQ(built.reports.size(), 1);
    ENSURE_EQ(built.reports[0].code, B2S_CODE_LOSSY_LINE_MOTOR);
    ENSURE_EQ(built.reports[0].index, 9);
    ENSURE_STR(built.reports[0].object, "joint");
    ENSURE(built.reports[0].name == "line with a motor");

    b2Vec2 chassis_start = built.bodies[1]->GetPosition();
    step(loaded_world);
    step(hand_world);
    int different = 0;
    for (uint32_t i = 0; i < built.bodies.size(); ++i) {
        different += ensure_same_state(i, built.bodies[i], by_hand[i]);
    }
    ENSURE_EQ(different, 0);
    // The comparison means something only if the world moved.
    ENSURE(b2Distance(chassis_start, built.bodies[1]->GetPosition()) > 0.1f);
    return 0;
}

int main() {
    return RUN_TEST(loaded_world_equals_hand_built_world);
}
