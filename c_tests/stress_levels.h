/*
 * The generated levels every engine's stress test steps (v3_stress_test.c for v3.1 and v3.2,
 * stress_test.cpp for 2.4), the same stream in each: every shape and joint kind, their
 * fields drawn from ordinary ranges and, one in 40, from extremes (the largest floats,
 * subnormals, negative zero, the edges of the working range). Joints are laid out as an
 * editor lays them out (each body that yields hangs from one earlier body at a shared world
 * point, so that no joint starts far from satisfied or contradicts another: no solver holds
 * those whatever their values). Plain C over box2scene.h's builder, for C and C++.
 */
#ifndef BOX2SCENE_STRESS_LEVELS_H
#define BOX2SCENE_STRESS_LEVELS_H

#include <box2scene.h>
#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>

/* splitmix64: small, and the same sequence on every platform. */
#ifndef STRESS_SEED
#define STRESS_SEED 0x5EED
#endif
static uint64_t random_state = STRESS_SEED;

static uint64_t next_random(void) {
    uint64_t z = (random_state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

static uint32_t below(uint32_t n) {
    return (uint32_t)(next_random() % n);
}

static bool chance(double p) {
    return (double)(next_random() >> 11) * 0x1p-53 < p;
}

static float uniform(float low, float high) {
    return low + (high - low) * (float)((double)(next_random() >> 40) * 0x1p-24);
}

static const float extremes[] = {FLT_MAX, -FLT_MAX, 1e38f,  -1e30f, 1e20f,    1e10f,  1e6f,
                                 -1e6f,   1.0001e4f, 1e4f,  -1e4f,  1e3f,     -1e3f,  FLT_MIN,
                                 1e-40f,  1.4e-45f, -1.4e-45f, 0.0f, -0.0f,   1e-20f, 1e-7f};

/* A value in [low, high], or one time in 40 an extreme. */
static float value(float low, float high) {
    if (chance(1.0 / 40.0)) {
        return extremes[below(sizeof extremes / sizeof extremes[0])];
    }
    return uniform(low, high);
}

/* Like value, for what the builder refuses below 0. */
static float not_negative(float low, float high) {
    return fabsf(value(low, high));
}

static b2s_vec2 vec(float low, float high) {
    b2s_vec2 v = {value(low, high), value(low, high)};
    return v;
}

/* What gives a body mass: a circle or a polygon of 3 or more vertices, at a positive density. */
static bool shape_massive[4];
static bool fixture_massive[4];

static uint32_t add_shape(b2s_builder* builder) {
    b2s_vec2 points[16];
    uint32_t count = 0;
    b2s_shape shape;
    uint32_t kind = below(5);
    switch (kind) {
    case 0:
        b2s_shape_default(B2S_SHAPE_KIND_CIRCLE, &shape);
        shape.radius = not_negative(0.05f, 2.0f);
        shape.position = vec(-1.0f, 1.0f);
        break;
    case 1: {
        b2s_shape_default(B2S_SHAPE_KIND_POLYGON, &shape);
        count = 3 + below(6);
        float radius = value(0.1f, 2.0f), cx = value(-1.0f, 1.0f), cy = value(-1.0f, 1.0f);
        for (uint32_t i = 0; i < count; ++i) {
            float turn = 6.2831853f * (float)i / (float)count;
            points[i].x = cx + radius * cosf(turn) + uniform(-0.01f, 0.01f);
            points[i].y = cy + radius * sinf(turn) + uniform(-0.01f, 0.01f);
        }
        if (chance(0.3)) {
            shape.centroid_given = true;
            shape.centroid = vec(-1.0f, 1.0f);
        }
        break;
    }
    case 2:
        b2s_shape_default(B2S_SHAPE_KIND_EDGE, &shape);
        points[count++] = vec(-5.0f, 0.0f);
        points[count++] = vec(0.5f, 5.0f);
        shape.has_prev_vertex = chance(0.5);
        shape.prev_vertex = vec(-6.0f, 0.0f);
        shape.has_next_vertex = chance(0.5);
        shape.next_vertex = vec(0.0f, 6.0f);
        break;
    default: {
        b2s_shape_default(B2S_SHAPE_KIND_CHAIN, &shape);
        shape.is_loop = chance(0.4);
        count = (shape.is_loop ? 3 : 2) + below(6);
        float radius = value(1.0f, 8.0f);
        for (uint32_t i = 0; i < count; ++i) {
            float turn = -6.2831853f * (float)i / (float)count; /* clockwise: a loop holds */
            points[i].x = radius * cosf(turn) + uniform(-0.01f, 0.01f);
            points[i].y = radius * sinf(turn) + uniform(-0.01f, 0.01f);
        }
        if (!shape.is_loop) {
            shape.has_prev_vertex = chance(0.5);
            shape.prev_vertex = vec(-9.0f, 9.0f);
            shape.has_next_vertex = chance(0.5);
            shape.next_vertex = vec(-9.0f, 9.0f);
        }
        break;
    }
    }
    uint32_t index = B2S_NONE;
    if (b2s_builder_add_shape(builder, &shape, points, count, &index, NULL) != B2S_CODE_OK) {
        return B2S_NONE; /* refused as a loader would refuse it */
    }
    shape_massive[index] = kind <= 1;
    return index;
}

static void add_fixture(b2s_builder* builder, uint32_t shape, uint32_t index) {
    b2s_fixture fixture;
    b2s_fixture_default(&fixture);
    fixture.shape = shape;
    fixture.density = chance(0.2) ? 0.0f : not_negative(0.1f, 5.0f);
    fixture.friction = not_negative(0.0f, 1.0f);
    fixture.restitution = not_negative(0.0f, 1.0f);
    fixture.is_sensor = chance(0.1);
    fixture.filter.group_index = (int16_t)(chance(0.2) ? -1 : 0);
    b2s_builder_add_fixture(builder, &fixture, NULL, NULL);
    fixture_massive[index] = shape_massive[shape] && fixture.density > 0.0f;
}

typedef struct pose {
    b2s_vec2 p;
    float angle;
} pose;

static b2s_vec2 world_point(pose at, b2s_vec2 local) {
    float c = cosf(at.angle), s = sinf(at.angle);
    b2s_vec2 out = {at.p.x + (c * local.x - s * local.y), at.p.y + (s * local.x + c * local.y)};
    return out;
}

static b2s_vec2 local_point(pose at, b2s_vec2 world) {
    float c = cosf(at.angle), s = sinf(at.angle);
    float dx = world.x - at.p.x, dy = world.y - at.p.y;
    b2s_vec2 out = {c * dx + s * dy, -s * dx + c * dy};
    return out;
}

/* A body joints may hold: static, or dynamic with mass and rotational inertia of its own.
 * A kinematic body, or a dynamic one without (Box2D 2.x gives it 1 kg and no inertia),
 * keeps whatever motion it starts with, and a solver cannot hold a joint that ties another
 * body to that motion far from it: v3's diverges. */
static uint32_t placed;

static pose add_body(b2s_builder* builder, uint32_t fixtures, bool* dynamic, bool* holds,
                     bool* spins) {
    static const uint32_t kinds[] = {B2S_BODY_KIND_STATIC, B2S_BODY_KIND_DYNAMIC,
                                     B2S_BODY_KIND_DYNAMIC, B2S_BODY_KIND_KINEMATIC};
    b2s_body body;
    uint32_t kind = kinds[below(4)];
    b2s_body_default((b2s_body_kind)kind, &body);
    *dynamic = kind == B2S_BODY_KIND_DYNAMIC;
    body.position = vec(-5.0f, 5.0f);
    body.position.x += 12.0f * (float)placed++; /* apart: no body starts inside another */
    body.angle = value(-3.2f, 3.2f);
    body.linear_velocity = vec(-10.0f, 10.0f);
    body.angular_velocity = value(-5.0f, 5.0f);
    body.linear_damping = value(0.0f, 1.0f);
    body.angular_damping = value(0.0f, 1.0f);
    body.gravity_scale = value(-1.0f, 2.0f);
    body.fixed_rotation = chance(0.1);
    body.bullet = chance(0.2);
    body.allow_sleep = chance(0.8);
    body.awake = chance(0.9);
    if (chance(0.2)) {
        body.mass_data.mass_given = chance(0.7);
        body.mass_data.mass = not_negative(0.1f, 10.0f);
        body.mass_data.center_given = chance(0.5);
        body.mass_data.center = vec(-0.5f, 0.5f);
        body.mass_data.inertia_given = chance(0.5);
        body.mass_data.inertia = not_negative(1.0f, 20.0f);
    }
    uint32_t ids[4], count = fixtures > 0 ? below(4) : 0;
    bool massive = false;
    for (uint32_t i = 0; i < count; ++i) {
        ids[i] = below(fixtures);
        massive = massive || fixture_massive[ids[i]];
    }
    *holds = kind == B2S_BODY_KIND_STATIC || massive || body.fixed_rotation;
    /* A body whose rotation is fixed keeps the spin it starts with in every engine, as a
     * kinematic body keeps its motion: Box2D 2.4 and v3.1 both went NaN on a line joint it
     * dragged around 5.5 m out (level 1325). No joint is tied to such a body; its draws are
     * kept, so that the rest of the stream stays what it was. */
    *spins = body.fixed_rotation && body.angular_velocity != 0.0f;
    *dynamic = *dynamic && *holds;
    if (b2s_builder_add_body(builder, &body, ids, count, NULL, NULL) != B2S_CODE_OK) {
        /* a negative mass datum the builder refuses: add the body without it */
        body.mass_data.mass_given = body.mass_data.center_given = false;
        body.mass_data.inertia_given = false;
        b2s_builder_add_body(builder, &body, ids, count, NULL, NULL);
    }
    pose at = {body.position, body.angle};
    return at;
}

/* Each dynamic body that yields may hang from one earlier body by a joint of any kind, anchored at its
 * own position, with the reference angle of the two poses. */
static void add_joints(b2s_builder* builder, const pose* poses, const bool* dynamic,
                       const bool* holds, const bool* spins, uint32_t bodies) {
    uint32_t inputs[8], input_count = 0;
    for (uint32_t b = 1; b < bodies; ++b) {
        if (!dynamic[b] || chance(0.1)) {
            continue;
        }
        uint32_t a = below(b);
        if (!holds[a]) {
            continue;
        }
        uint32_t kind = below(B2S_JOINT_KIND_UNSUPPORTED); /* every kind, gears included */
        if (kind == B2S_JOINT_KIND_GEAR && input_count < 2) {
            kind = B2S_JOINT_KIND_REVOLUTE;
        }
        b2s_joint joint;
        b2s_joint_default((b2s_joint_kind)kind, &joint);
        joint.body_a = a;
        joint.body_b = b;
        /* A length joint spans the two origins; the others meet at body B's. */
        bool spans = kind == B2S_JOINT_KIND_DISTANCE || kind == B2S_JOINT_KIND_ROPE;
        b2s_vec2 origin = {0.0f, 0.0f};
        b2s_vec2 anchor = world_point(spans ? poses[a] : poses[b], origin);
        joint.local_anchor_a = local_point(poses[a], anchor);
        joint.local_anchor_b.x = joint.local_anchor_b.y = 0.0f;
        joint.reference_angle = poses[b].angle - poses[a].angle;
        joint.collide_connected = chance(0.2);
        joint.enable_limit = chance(0.5);
        float range = not_negative(0.1f, 2.0f);
        joint.lower_limit = -range;
        joint.upper_limit = range;
        joint.enable_motor = chance(0.3);
        joint.motor_speed = value(-5.0f, 5.0f);
        joint.max_motor_torque = not_negative(0.0f, 100.0f);
        joint.max_motor_force = not_negative(0.0f, 100.0f);
        joint.local_axis_a = vec(-1.0f, 1.0f);
        joint.frequency_hz = chance(0.5) ? 0.0f : not_negative(0.5f, 10.0f);
        joint.damping_ratio = not_negative(0.0f, 1.0f);
        float dx = poses[b].p.x - poses[a].p.x, dy = poses[b].p.y - poses[a].p.y;
        float distance = sqrtf(dx * dx + dy * dy);
        joint.length = distance;
        joint.max_length = distance + not_negative(0.0f, 1.0f);
        joint.max_force = not_negative(0.0f, 100.0f);
        joint.max_torque = not_negative(0.0f, 100.0f);
        joint.linear_offset = local_point(poses[a], poses[b].p);
        joint.angular_offset = joint.reference_angle;
        joint.correction_factor = not_negative(0.0f, 1.0f);
        joint.ground_anchor_a = vec(-5.0f, 5.0f);
        joint.ground_anchor_b = vec(-5.0f, 5.0f);
        joint.length_a = not_negative(0.5f, 5.0f);
        joint.length_b = not_negative(0.5f, 5.0f);
        joint.ratio = not_negative(0.5f, 2.0f);
        if (kind == B2S_JOINT_KIND_GEAR) {
            joint.joint_a = inputs[below(input_count)];
            joint.joint_b = inputs[below(input_count)];
        }
        uint32_t index = B2S_NONE;
        if (spins[a] || spins[b]) {
            continue;
        }
        if (b2s_builder_add_joint(builder, &joint, &index, NULL) != B2S_CODE_OK) {
            continue; /* refused as a loader would refuse it (a zero axis, ...) */
        }
        bool input = kind == B2S_JOINT_KIND_REVOLUTE || kind == B2S_JOINT_KIND_PRISMATIC;
        if (input && input_count < 8) {
            inputs[input_count++] = index;
        }
    }
}

static b2s_scene* generated_level(void) {
    b2s_builder* builder = b2s_builder_new();
    if (chance(0.7)) {
        b2s_vec2 gravity = vec(-20.0f, 20.0f);
        b2s_builder_set_gravity(builder, &gravity, NULL);
    }
    uint32_t shapes[4], shape_count = 0;
    for (uint32_t i = 1 + below(4); i > 0; --i) {
        uint32_t shape = add_shape(builder);
        if (shape != B2S_NONE) {
            shapes[shape_count++] = shape;
        }
    }
    uint32_t fixtures = shape_count > 0 ? 1 + below(4) : 0;
    for (uint32_t i = 0; i < fixtures; ++i) {
        add_fixture(builder, shapes[below(shape_count)], i);
    }
    pose poses[6];
    bool dynamic[6], holds[6], spins[6];
    uint32_t bodies = 1 + below(6);
    placed = 0;
    for (uint32_t i = 0; i < bodies; ++i) {
        poses[i] = add_body(builder, fixtures, &dynamic[i], &holds[i], &spins[i]);
    }
    add_joints(builder, poses, dynamic, holds, spins, bodies);
    b2s_scene* scene = NULL;
    b2s_builder_finish(builder, &scene, NULL);
    return scene;
}

#endif /* BOX2SCENE_STRESS_LEVELS_H */
