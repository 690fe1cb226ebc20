/*
 * What the Box2D v3 adapter's sources (adapter.c and the files it includes) need to know of
 * Box2D v3.1, the one place where the adapter for v3.1 differs from one for another v3
 * (v32.h is v3.2's): its public names, how a body takes its position and fixed rotation,
 * how chains are made (b2ChainDef), how joints take their anchors, axes and reference
 * angles (fields of each def), its motor joint, and how a capture reads them back. What a
 * build gives each def is the library's plan, and what a capture writes of what it reads
 * is the library's too. Names starting with b2s3_ are private to the adapter's one
 * translation unit.
 */
#ifndef BOX2SCENE_BOX2D3_V31_H
#define BOX2SCENE_BOX2D3_V31_H

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The public names: b2s_box2d3_NAME (box2scene/box2d3.h keeps v3.1's names as they were
 * before v3.2 was served). */
#define B2S3_API(name) b2s_box2d3_##name
/* The library's working range the checks read (b2s_working_range). */
#define B2S3_ENGINE_VERSION B2S_ENGINE_BOX2D31
/* The engine, as reports name it. */
#define B2S3_ENGINE "Box2D v3"

typedef b2s_box2d3_report b2s3_report_t;
typedef b2s_box2d3_reports b2s3_reports_t;
typedef b2s_box2d3_built b2s3_built_t;

/* The bytes of a body's name the plan keeps: 0, the working range's name_bytes (v3.1's
 * body.h: name[32], NUL-terminated). */
#define B2S3_NAME_BYTES 0u

/* ---- bodies */

static void b2s3_set_pose(b2BodyDef* def, b2Vec2 position, b2Rot rotation) {
    def->position = position;
    def->rotation = rotation;
}

static b2Vec2 b2s3_body_position(b2BodyId body) {
    return b2Body_GetPosition(body);
}

/* v3.1's fixed rotation gives the body no inertia and keeps the spin it starts with. */
static void b2s3_lock_rotation(b2BodyDef* def, bool fixed) {
    def->fixedRotation = fixed;
}

static bool b2s3_rotation_locked(b2BodyId body) {
    return b2Body_IsFixedRotation(body);
}

/* ---- chains: v3.1's own (b2ChainDef), one b2ChainId per fixture slot */

static bool b2s3_allocate_chains(b2s3_built_t* built, uint32_t slots) {
    built->chains = (b2ChainId*)calloc(slots + 1, sizeof(b2ChainId));
    return built->chains != NULL;
}

static void b2s3_free_chains(b2s3_built_t* built) {
    free(built->chains);
}

/* A chain of `n` points ([ghost, vertices..., ghost], or a loop, of 4 points or more) with
 * the shape def's material, filter and events (no sensor flag: the plan makes a sensor
 * chain solid). Never runs out of memory: v3.1 keeps the chain. */
static bool b2s3_create_chain(b2s3_built_t* built, uint32_t* capacity, uint32_t slot,
                              b2BodyId body, const b2ShapeDef* shape, const b2Vec2* points, int n,
                              bool loop) {
    (void)capacity;
    b2ChainDef def = b2DefaultChainDef();
    def.points = points;
    def.count = n;
    def.isLoop = loop;
    def.materials = &shape->material;
    def.materialCount = 1;
    def.filter = shape->filter;
    def.enableSensorEvents = shape->enableSensorEvents;
    built->chains[slot] = b2CreateChain(body, &def);
    return true;
}

/* ---- joints: anchors, axis and reference angle are fields of each def */

#define B2S3_JOINT_BASE(def) (def)

#define B2S3_ANCHOR_FRAMES(def, j)                                                             \
    do {                                                                                       \
        (def).localAnchorA = b2s3_to_b2((j)->anchor_a);                                        \
        (def).localAnchorB = b2s3_to_b2((j)->anchor_b);                                        \
    } while (0)
#define B2S3_REVOLUTE_FRAMES(def, j)                                                           \
    do {                                                                                       \
        B2S3_ANCHOR_FRAMES(def, j);                                                            \
        (def).referenceAngle = (j)->reference_angle;                                           \
    } while (0)
#define B2S3_WELD_FRAMES(def, j) B2S3_REVOLUTE_FRAMES(def, j)
#define B2S3_PRISMATIC_FRAMES(def, j)                                                          \
    do {                                                                                       \
        B2S3_REVOLUTE_FRAMES(def, j);                                                          \
        (def).localAxisA = b2s3_to_b2((j)->axis);                                              \
    } while (0)
#define B2S3_AXIS_FRAMES(def, j)                                                               \
    do {                                                                                       \
        B2S3_ANCHOR_FRAMES(def, j);                                                            \
        (def).localAxisA = b2s3_to_b2((j)->axis);                                              \
    } while (0)

/* Box2D 2.3's motor joint, whose form v3.1's is (the plan turns the linear offset into the
 * world axes v3.1.1's solver reads it in). */
static void b2s3_motor_def(b2MotorJointDef* def, const b2s_plan_joint* joint) {
    b2Vec2 offset = {joint->linear_offset.x, joint->linear_offset.y};
    def->linearOffset = offset;
    def->angularOffset = joint->angular_offset;
    def->maxForce = joint->max_force;
    def->maxTorque = joint->max_torque;
    def->correctionFactor = joint->correction_factor;
}

/* Friction: a motor joint that holds no offset, at the body origins (the plan's offsets and
 * correction factor are 0). */
static void b2s3_friction_def(b2MotorJointDef* def, const b2s_plan_joint* joint) {
    b2s3_motor_def(def, joint);
}

/* ---- capture: v3.1 holds what the build passed, read as the engine gives it */

/* reports.c's conversion, which the readers below use. */
static b2s_vec2 b2s3_to_b2s(b2Vec2 v);

/* A joint's anchors, and its axis and reference angle where its kind has them. */
static void b2s3_read_frames(b2JointId id, b2s_plan_joint* joint) {
    joint->anchor_a = b2s3_to_b2s(b2Joint_GetLocalAnchorA(id));
    joint->anchor_b = b2s3_to_b2s(b2Joint_GetLocalAnchorB(id));
    uint32_t kind = joint->kind;
    if (kind == B2S_PLAN_JOINT_KIND_PRISMATIC || kind == B2S_PLAN_JOINT_KIND_WHEEL) {
        joint->axis = b2s3_to_b2s(b2Joint_GetLocalAxisA(id));
    }
    if (kind == B2S_PLAN_JOINT_KIND_PRISMATIC || kind == B2S_PLAN_JOINT_KIND_REVOLUTE ||
        kind == B2S_PLAN_JOINT_KIND_WELD) {
        joint->reference_angle = b2Joint_GetReferenceAngle(id);
    }
}

/* A motor joint's fields, Box2D 2.3's. */
static void b2s3_read_motor(b2JointId id, b2s_held_joint* held) {
    held->joint.linear_offset = b2s3_to_b2s(b2MotorJoint_GetLinearOffset(id));
    held->joint.angular_offset = b2MotorJoint_GetAngularOffset(id);
    held->joint.max_force = b2MotorJoint_GetMaxForce(id);
    held->joint.max_torque = b2MotorJoint_GetMaxTorque(id);
    held->joint.correction_factor = b2MotorJoint_GetCorrectionFactor(id);
}

/* What a joint of a kind the format has no form for is. */
static const char* b2s3_joint_without_form(b2JointId id) {
    return b2Joint_GetType(id) == b2_mouseJoint ? "a mouse joint"
                                                : "a joint of a kind this adapter does not know";
}

/* ---- lookups (lookup.c): which shapes a fixture slot holds */

/* The shape of fixture slot `slot`, or its chain's first segment. */
static b2ShapeId b2s3_slot_shape(const b2s3_built_t* built, uint32_t slot) {
    b2ShapeId shape = built->shapes[slot];
    b2ChainId chain = built->chains[slot];
    if (B2_IS_NULL(shape) && B2_IS_NON_NULL(chain) && b2Chain_IsValid(chain)) {
        b2Chain_GetSegments(chain, &shape, 1);
    }
    return shape;
}

/* The shapes of fixture slot `slot` (its shape, or its chain's segments), up to `capacity`
 * of them into `out`: how many it holds. */
static int b2s3_slot_shapes(const b2s3_built_t* built, uint32_t slot, b2ShapeId* out,
                            int capacity) {
    b2ChainId chain = built->chains[slot];
    if (B2_IS_NON_NULL(built->shapes[slot]) || B2_IS_NULL(chain) || !b2Chain_IsValid(chain)) {
        if (capacity > 0) {
            out[0] = built->shapes[slot];
        }
        return B2_IS_NON_NULL(built->shapes[slot]) ? 1 : 0;
    }
    int count = b2Chain_GetSegmentCount(chain);
    return capacity >= count ? b2Chain_GetSegments(chain, out, capacity) : count;
}

/* Whether `shape`, a live shape, is fixture slot `slot`'s or one of its chain's segments. */
static bool b2s3_slot_holds(const b2s3_built_t* built, uint32_t slot, b2ShapeId shape) {
    if (B2_ID_EQUALS(built->shapes[slot], shape)) {
        return true;
    }
    if (B2_IS_NULL(built->chains[slot]) || b2Shape_GetType(shape) != b2_chainSegmentShape) {
        return false;
    }
    b2ChainId parent = b2Shape_GetParentChain(shape);
    return B2_ID_EQUALS(parent, built->chains[slot]);
}

#endif /* BOX2SCENE_BOX2D3_V31_H */
