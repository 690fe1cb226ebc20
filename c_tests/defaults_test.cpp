// The library's defaults (one source of truth, in Rust) against Box2D 2.4's own def
// constructors, wherever Box2D has the field and the format keeps its meaning.
#include <box2d/box2d.h>
#include <box2scene.h>

#include <initializer_list>

#include "test_macros.h"

// The body kinds are Box2D's b2BodyType values, so the adapter converts them by a cast.
static_assert(static_cast<int>(B2S_BODY_KIND_STATIC) == b2_staticBody, "static");
static_assert(static_cast<int>(B2S_BODY_KIND_KINEMATIC) == b2_kinematicBody, "kinematic");
static_assert(static_cast<int>(B2S_BODY_KIND_DYNAMIC) == b2_dynamicBody, "dynamic");

static int ensure_same(b2s_vec2 v, b2Vec2 w) {
    ENSURE_FLOAT(v.x, w.x);
    ENSURE_FLOAT(v.y, w.y);
    return 0;
}

#define ENSURE_VEC(v, w) ENSURE(ensure_same((v), (w)) == 0)

static int body_defaults_are_box2ds() {
    const b2BodyDef def;
    for (b2s_body_kind kind : {B2S_BODY_KIND_STATIC, B2S_BODY_KIND_KINEMATIC, B2S_BODY_KIND_DYNAMIC}) {
        b2s_body body;
        ENSURE_EQ(b2s_body_default(kind, &body), B2S_CODE_OK);
        ENSURE_EQ(body.kind, kind);
        ENSURE(body.name == nullptr);
        ENSURE_VEC(body.position, def.position);
        ENSURE_FLOAT(body.angle, def.angle);
        ENSURE_VEC(body.linear_velocity, def.linearVelocity);
        ENSURE_FLOAT(body.angular_velocity, def.angularVelocity);
        ENSURE_FLOAT(body.linear_damping, def.linearDamping);
        ENSURE_FLOAT(body.angular_damping, def.angularDamping);
        ENSURE_FLOAT(body.gravity_scale, def.gravityScale);
        ENSURE_EQ(body.active, def.enabled);
        ENSURE_EQ(body.allow_sleep, def.allowSleep);
        ENSURE_EQ(body.awake, def.awake);
        ENSURE_EQ(body.bullet, def.bullet);
        ENSURE_EQ(body.fixed_rotation, def.fixedRotation);
        // Box2D 2.1's field, kept by the format: 1 means "no scaling".
        ENSURE_FLOAT(body.inertia_scale, 1.0f);
        ENSURE(!body.mass_data.mass_given && !body.mass_data.center_given &&
               !body.mass_data.inertia_given);
        ENSURE_EQ(body.fixtures.count, 0);
        ENSURE_EQ(body.user_data, B2S_NONE);
    }
    b2s_body body;
    ENSURE_EQ(b2s_body_default(B2S_BODY_KIND_STATIC, &body), B2S_CODE_OK);
    ENSURE_EQ(body.kind, def.type);
    return 0;
}

static int fixture_defaults_are_box2ds() {
    const b2FixtureDef def;
    b2s_fixture fixture;
    ENSURE_EQ(b2s_fixture_default(&fixture), B2S_CODE_OK);
    ENSURE_FLOAT(fixture.density, def.density);
    ENSURE_FLOAT(fixture.friction, def.friction);
    ENSURE_FLOAT(fixture.restitution, def.restitution);
    ENSURE_EQ(fixture.is_sensor, def.isSensor);
    ENSURE_EQ(fixture.filter.category_bits, def.filter.categoryBits);
    ENSURE_EQ(fixture.filter.mask_bits, def.filter.maskBits);
    ENSURE_EQ(fixture.filter.group_index, def.filter.groupIndex);
    ENSURE(fixture.name == nullptr);
    ENSURE_EQ(fixture.user_data, B2S_NONE);
    return 0;
}

static int joint_of(b2s_joint_kind kind, b2s_joint* joint) {
    ENSURE_EQ(b2s_joint_default(kind, joint), B2S_CODE_OK);
    ENSURE_EQ(joint->kind, kind);
    ENSURE_EQ(joint->joint_a, B2S_NONE);
    ENSURE_EQ(joint->joint_b, B2S_NONE);
    return 0;
}

static int revolute_and_prismatic_defaults_are_box2ds() {
    b2s_joint joint;
    const b2RevoluteJointDef revolute;
    ENSURE(joint_of(B2S_JOINT_KIND_REVOLUTE, &joint) == 0);
    ENSURE_VEC(joint.local_anchor_a, revolute.localAnchorA);
    ENSURE_VEC(joint.local_anchor_b, revolute.localAnchorB);
    ENSURE_FLOAT(joint.reference_angle, revolute.referenceAngle);
    ENSURE_EQ(joint.enable_limit, revolute.enableLimit);
    ENSURE_FLOAT(joint.lower_limit, revolute.lowerAngle);
    ENSURE_FLOAT(joint.upper_limit, revolute.upperAngle);
    ENSURE_EQ(joint.enable_motor, revolute.enableMotor);
    ENSURE_FLOAT(joint.motor_speed, revolute.motorSpeed);
    ENSURE_FLOAT(joint.max_motor_torque, revolute.maxMotorTorque);
    ENSURE_EQ(joint.collide_connected, revolute.collideConnected);

    const b2PrismaticJointDef prismatic;
    ENSURE(joint_of(B2S_JOINT_KIND_PRISMATIC, &joint) == 0);
    ENSURE_VEC(joint.local_anchor_a, prismatic.localAnchorA);
    ENSURE_VEC(joint.local_anchor_b, prismatic.localAnchorB);
    ENSURE_VEC(joint.local_axis_a, prismatic.localAxisA);
    ENSURE_FLOAT(joint.reference_angle, prismatic.referenceAngle);
    ENSURE_EQ(joint.enable_limit, prismatic.enableLimit);
    ENSURE_FLOAT(joint.lower_limit, prismatic.lowerTranslation);
    ENSURE_FLOAT(joint.upper_limit, prismatic.upperTranslation);
    ENSURE_EQ(joint.enable_motor, prismatic.enableMotor);
    ENSURE_FLOAT(joint.max_motor_force, prismatic.maxMotorForce);
    ENSURE_FLOAT(joint.motor_speed, prismatic.motorSpeed);
    return 0;
}

static int distance_and_pulley_defaults_are_box2ds() {
    b2s_joint joint;
    const b2DistanceJointDef distance;
    ENSURE(joint_of(B2S_JOINT_KIND_DISTANCE, &joint) == 0);
    ENSURE_VEC(joint.local_anchor_a, distance.localAnchorA);
    ENSURE_VEC(joint.local_anchor_b, distance.localAnchorB);
    ENSURE_FLOAT(joint.length, distance.length);
    // FrequencyHz 0 is rigid (Box2D 2.1); 2.4 expresses that with min = max = length.
    ENSURE_FLOAT(joint.frequency_hz, 0.0f);
    ENSURE_FLOAT(joint.damping_ratio, 0.0f);

    const b2PulleyJointDef pulley;
    ENSURE(joint_of(B2S_JOINT_KIND_PULLEY, &joint) == 0);
    ENSURE_VEC(joint.ground_anchor_a, pulley.groundAnchorA);
    ENSURE_VEC(joint.ground_anchor_b, pulley.groundAnchorB);
    ENSURE_VEC(joint.local_anchor_a, pulley.localAnchorA);
    ENSURE_VEC(joint.local_anchor_b, pulley.localAnchorB);
    ENSURE_FLOAT(joint.length_a, pulley.lengthA);
    ENSURE_FLOAT(joint.length_b, pulley.lengthB);
    ENSURE_FLOAT(joint.ratio, pulley.ratio);
    // The one deliberate difference: the editor reads an absent CollideConnected as false
    // for every joint, where Box2D's pulley def says true.
    ENSURE(pulley.collideConnected);
    ENSURE(!joint.collide_connected);
    return 0;
}

static int wheel_and_line_defaults_are_box2ds() {
    b2s_joint joint;
    const b2WheelJointDef wheel;
    ENSURE(joint_of(B2S_JOINT_KIND_WHEEL, &joint) == 0);
    ENSURE_VEC(joint.local_anchor_a, wheel.localAnchorA);
    ENSURE_VEC(joint.local_anchor_b, wheel.localAnchorB);
    ENSURE_VEC(joint.local_axis_a, wheel.localAxisA);
    ENSURE_EQ(joint.enable_motor, wheel.enableMotor);
    ENSURE_FLOAT(joint.max_motor_torque, wheel.maxMotorTorque);
    ENSURE_FLOAT(joint.motor_speed, wheel.motorSpeed);
    // Box2D 2.2's spring defaults; 2.4 has stiffness and damping instead.
    ENSURE_FLOAT(joint.frequency_hz, 2.0f);
    ENSURE_FLOAT(joint.damping_ratio, 0.7f);

    ENSURE(joint_of(B2S_JOINT_KIND_LINE, &joint) == 0);
    ENSURE_VEC(joint.local_anchor_a, wheel.localAnchorA);
    ENSURE_VEC(joint.local_anchor_b, wheel.localAnchorB);
    ENSURE_VEC(joint.local_axis_a, wheel.localAxisA);
    ENSURE_EQ(joint.enable_limit, wheel.enableLimit);
    ENSURE_FLOAT(joint.lower_limit, wheel.lowerTranslation);
    ENSURE_FLOAT(joint.upper_limit, wheel.upperTranslation);
    ENSURE_EQ(joint.enable_motor, wheel.enableMotor);
    return 0;
}

static int other_joint_defaults_are_box2ds() {
    b2s_joint joint;
    const b2WeldJointDef weld;
    ENSURE(joint_of(B2S_JOINT_KIND_WELD, &joint) == 0);
    ENSURE_VEC(joint.local_anchor_a, weld.localAnchorA);
    ENSURE_VEC(joint.local_anchor_b, weld.localAnchorB);
    ENSURE_FLOAT(joint.reference_angle, weld.referenceAngle);
    ENSURE_FLOAT(joint.frequency_hz, 0.0f);

    const b2FrictionJointDef friction;
    ENSURE(joint_of(B2S_JOINT_KIND_FRICTION, &joint) == 0);
    ENSURE_VEC(joint.local_anchor_a, friction.localAnchorA);
    ENSURE_VEC(joint.local_anchor_b, friction.localAnchorB);
    ENSURE_FLOAT(joint.max_force, friction.maxForce);
    ENSURE_FLOAT(joint.max_torque, friction.maxTorque);

    const b2MotorJointDef motor;
    ENSURE(joint_of(B2S_JOINT_KIND_MOTOR, &joint) == 0);
    ENSURE_VEC(joint.linear_offset, motor.linearOffset);
    ENSURE_FLOAT(joint.angular_offset, motor.angularOffset);
    ENSURE_FLOAT(joint.max_force, motor.maxForce);
    ENSURE_FLOAT(joint.max_torque, motor.maxTorque);
    ENSURE_FLOAT(joint.correction_factor, motor.correctionFactor);

    const b2GearJointDef gear;
    ENSURE(joint_of(B2S_JOINT_KIND_GEAR, &joint) == 0);
    ENSURE_FLOAT(joint.ratio, gear.ratio);
    return 0;
}

static int shape_defaults_are_box2ds() {
    const b2CircleShape circle;
    b2s_shape shape;
    ENSURE_EQ(b2s_shape_default(B2S_SHAPE_KIND_CIRCLE, &shape), B2S_CODE_OK);
    ENSURE_EQ(shape.kind, B2S_SHAPE_KIND_CIRCLE);
    ENSURE_VEC(shape.position, circle.m_p);
    ENSURE_EQ(b2s_shape_default(B2S_SHAPE_KIND_POLYGON, &shape), B2S_CODE_OK);
    ENSURE(!shape.centroid_given);
    ENSURE_EQ(shape.vertices.count, 0);
    ENSURE_EQ(b2s_shape_default(B2S_SHAPE_KIND_CHAIN, &shape), B2S_CODE_OK);
    ENSURE(!shape.is_loop && !shape.has_prev_vertex && !shape.has_next_vertex);
    return 0;
}

static int unknown_kinds_are_invalid_arguments() {
    b2s_shape shape;
    b2s_body body;
    b2s_joint joint;
    ENSURE_EQ(b2s_shape_default(static_cast<b2s_shape_kind>(4), &shape), B2S_CODE_INVALID_ARGUMENT);
    ENSURE_EQ(b2s_body_default(static_cast<b2s_body_kind>(3), &body), B2S_CODE_INVALID_ARGUMENT);
    ENSURE_EQ(b2s_joint_default(static_cast<b2s_joint_kind>(12), &joint), B2S_CODE_INVALID_ARGUMENT);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(body_defaults_are_box2ds);
    failed += RUN_TEST(fixture_defaults_are_box2ds);
    failed += RUN_TEST(revolute_and_prismatic_defaults_are_box2ds);
    failed += RUN_TEST(distance_and_pulley_defaults_are_box2ds);
    failed += RUN_TEST(wheel_and_line_defaults_are_box2ds);
    failed += RUN_TEST(other_joint_defaults_are_box2ds);
    failed += RUN_TEST(shape_defaults_are_box2ds);
    failed += RUN_TEST(unknown_kinds_are_invalid_arguments);
    return failed;
}
