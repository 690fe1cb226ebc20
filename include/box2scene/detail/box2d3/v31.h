/*
 * What the Box2D v3 adapter's sources (adapter.c and the files it includes) need to know of
 * Box2D v3.1, the one place where the adapter for v3.1 differs from one for another v3
 * (v32.h is v3.2's): its public names, how a body takes its position and fixed rotation,
 * how a body's mass is summed (for a capture), how chains are made (b2ChainDef) and read
 * back, how joints take their anchors, axes and reference angles (fields of each def) and
 * give them back, and its motor joint. What a build gives each def is the library's plan. Names starting with b2s3_ are private to the
 * adapter's one translation unit.
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

static b2Vec2 b2s3_local_center(b2BodyId body) {
    return b2Body_GetLocalCenterOfMass(body);
}

/* v3.1's fixed rotation gives the body no inertia and keeps the spin it starts with. */
static void b2s3_lock_rotation(b2BodyDef* def, bool fixed) {
    def->fixedRotation = fixed;
}

static bool b2s3_rotation_locked(b2BodyId body) {
    return b2Body_IsFixedRotation(body);
}

static b2MassData b2s3_shape_mass(b2ShapeId shape) {
    return b2Shape_GetMassData(shape);
}

/* The mass v3.1 gives a dynamic body with these shapes (b2Body_ApplyMassFromShapes, which
 * walks a body's shapes newest first, their inertias about the body origin), operation for
 * operation so that the bits agree; `shapes` is in creation order.
 * `inertia_kept` is false when v3 would assert that the centred inertia is positive. */
static b2MassData b2s3_mass_from_shapes(const b2MassData* shapes, const float* densities,
                                        size_t count, bool fixed_rotation, bool* inertia_kept) {
    b2MassData body = {0.0f, {0.0f, 0.0f}, 0.0f};
    b2Vec2 center = b2Vec2_zero;
    for (size_t i = count; i-- > 0;) {
        if (densities[i] == 0.0f) {
            continue;
        }
        body.mass += shapes[i].mass;
        center = b2MulAdd(center, shapes[i].mass, shapes[i].center);
        body.rotationalInertia += shapes[i].rotationalInertia;
    }
    if (body.mass > 0.0f) {
        float inverse = 1.0f / body.mass;
        center = b2MulSV(inverse, center);
    }
    *inertia_kept = true;
    if (body.rotationalInertia > 0.0f && !fixed_rotation) {
        body.rotationalInertia -= body.mass * b2Dot(center, center);
        *inertia_kept = body.rotationalInertia > 0.0f;
    } else {
        body.rotationalInertia = 0.0f;
    }
    body.center = center;
    return body;
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

/* The bytes of a loss a capture reports. */
#define B2S3_LOSS_SIZE 320

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

/* ---- capture: v3.1 holds what the build passed, and its chains are objects */

/* A chain is a b2ChainId that lists its segments in order: capture finds each chain where
 * its first segment stands among the body's shapes and makes one fixture of all of them. */
typedef struct b2s3_chain_seen {
    b2ChainId id;
    bool captured;
} b2s3_chain_seen;

typedef struct b2s3_chains {
    b2s3_chain_seen* seen; /* the body's chains, each once and sorted */
    size_t count;
    b2ShapeId* segments; /* one chain's, room for all the body's shapes */
    int capacity;
} b2s3_chains;

static int b2s3_chain_order(const void* a, const void* b) {
    b2ChainId x = ((const b2s3_chain_seen*)a)->id, y = ((const b2s3_chain_seen*)b)->id;
    if (x.index1 != y.index1) {
        return x.index1 < y.index1 ? -1 : 1;
    }
    return (x.generation > y.generation) - (x.generation < y.generation);
}

/* The chains among a body's `count` shapes, each once and sorted, so that a segment finds
 * its chain's entry by a binary search however many chains the body holds. False when
 * memory runs out (b2s3_chains_free frees what was made). */
static bool b2s3_chains_of(b2s3_chains* chains, const b2ShapeId* shapes, int count) {
    size_t room = (size_t)(count > 0 ? count : 1);
    chains->seen = (b2s3_chain_seen*)malloc(room * sizeof(b2s3_chain_seen));
    chains->segments = (b2ShapeId*)malloc(room * sizeof(b2ShapeId));
    chains->count = 0;
    chains->capacity = count;
    if (chains->seen == NULL || chains->segments == NULL) {
        return false;
    }
    size_t found = 0;
    for (int i = 0; i < count; ++i) {
        if (b2Shape_GetType(shapes[i]) == b2_chainSegmentShape) {
            chains->seen[found].id = b2Shape_GetParentChain(shapes[i]);
            chains->seen[found].captured = false;
            found += 1;
        }
    }
    qsort(chains->seen, found, sizeof(b2s3_chain_seen), b2s3_chain_order);
    for (size_t k = 0; k < found; ++k) {
        if (chains->count == 0 ||
            b2s3_chain_order(&chains->seen[chains->count - 1], &chains->seen[k]) != 0) {
            chains->seen[chains->count++] = chains->seen[k];
        }
    }
    return true;
}

static void b2s3_chains_free(b2s3_chains* chains) {
    free(chains->seen);
    free(chains->segments);
}

/* The segments, in their chain's order, of the chain that `shapes[i]` (a chain segment)
 * belongs to, the first time one of them is met; 0 once its chain has been met. */
static int b2s3_chain_at(b2s3_chains* chains, const b2ShapeId* shapes, int i, int count,
                         const b2ShapeId** segments) {
    (void)count;
    b2s3_chain_seen key = {b2Shape_GetParentChain(shapes[i]), false};
    b2s3_chain_seen* chain = (b2s3_chain_seen*)bsearch(&key, chains->seen, chains->count,
                                                       sizeof(b2s3_chain_seen),
                                                       b2s3_chain_order);
    if (chain->captured) {
        return 0;
    }
    chain->captured = true;
    *segments = chains->segments;
    return b2Chain_GetSegments(chain->id, chains->segments, chains->capacity);
}

/* A chain of one segment was made of an edge with ghost vertices or of a chain of two
 * vertices: v3.1's capture writes it as the chain. */
#define B2S3_LONE_SEGMENT_KIND B2S_SHAPE_KIND_CHAIN

/* v3.1 has a mouse joint, which the format has no form for. */
#define B2S3_HAS_MOUSE_JOINT 1

/* A joint's anchors, and its axis and reference angle where its kind has them, read back
 * as the joint holds them: as the build passed them, nothing to invert and nothing lost
 * (returns 0, the count of losses written into `losses`). */
static int b2s3_frames_of(b2JointId id, b2s_joint* joint, char losses[2][B2S3_LOSS_SIZE]) {
    (void)losses;
    b2Vec2 anchor_a = b2Joint_GetLocalAnchorA(id), anchor_b = b2Joint_GetLocalAnchorB(id);
    joint->local_anchor_a.x = anchor_a.x;
    joint->local_anchor_a.y = anchor_a.y;
    joint->local_anchor_b.x = anchor_b.x;
    joint->local_anchor_b.y = anchor_b.y;
    switch (joint->kind) {
    case B2S_JOINT_KIND_PRISMATIC:
    case B2S_JOINT_KIND_WHEEL:
    case B2S_JOINT_KIND_LINE: {
        b2Vec2 axis = b2Joint_GetLocalAxisA(id);
        joint->local_axis_a.x = axis.x;
        joint->local_axis_a.y = axis.y;
        break;
    }
    default: break;
    }
    switch (joint->kind) {
    case B2S_JOINT_KIND_PRISMATIC:
    case B2S_JOINT_KIND_REVOLUTE:
    case B2S_JOINT_KIND_WELD: joint->reference_angle = b2Joint_GetReferenceAngle(id); break;
    default: break;
    }
    return 0;
}

/* A motor joint read back as it holds its fields: Friction when it holds no offset and no
 * CorrectionFactor (what the build makes of one), else Motor. Loses nothing (returns NULL,
 * where a loss would be said). */
static const char* b2s3_motor_of(b2JointId id, b2s_joint* joint) {
    b2Vec2 offset = b2MotorJoint_GetLinearOffset(id);
    float angular = b2MotorJoint_GetAngularOffset(id);
    float correction = b2MotorJoint_GetCorrectionFactor(id);
    bool friction = correction == 0.0f && offset.x == 0.0f && offset.y == 0.0f && angular == 0.0f;
    b2s_joint_default(friction ? B2S_JOINT_KIND_FRICTION : B2S_JOINT_KIND_MOTOR, joint);
    joint->linear_offset.x = offset.x;
    joint->linear_offset.y = offset.y;
    joint->angular_offset = angular;
    joint->max_force = b2MotorJoint_GetMaxForce(id);
    joint->max_torque = b2MotorJoint_GetMaxTorque(id);
    joint->correction_factor = correction;
    return NULL;
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
