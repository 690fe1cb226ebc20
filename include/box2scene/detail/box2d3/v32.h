/*
 * What the Box2D v3 adapter's sources (adapter.c and the files it includes) need to know of
 * Box2D v3.2, the one place where the adapter for v3.2 differs from one for another v3:
 * its public names, how a body takes its position and fixed rotation, how chains are made,
 * how joints take their anchors, axes and reference angles (local frames), its motor
 * joint, and how a capture reads them back. What a build gives each def is the library's
 * plan, and what a capture writes of what it reads is the library's too.
 *
 * Built and tested against upstream commit 56edae79 (June 2026, the sources of boxdd-sys
 * 0.6.0); only the part of the API it shares with main 617d32ab (August 2026) is used. The
 * 3.2.0 release (October 2026) reworked b2ChainDef and is not available here to build. So:
 * no b2ChainDef, no b2DestroyJoint, no pre-solve callback, no state hash, joint kinds
 * compared by name.
 * Names starting with b2s3_ are private to the adapter's one translation unit.
 */
#ifndef BOX2SCENE_BOX2D3_V32_H
#define BOX2SCENE_BOX2D3_V32_H

#include <box2d/constants.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef BOX2D_DOUBLE_PRECISION
#error "box2scene's Box2D v3.2 adapter serves Box2D's single-precision build only"
#endif

/* The public names: b2s_box2d32_NAME. */
#define B2S3_API(name) b2s_box2d32_##name
/* The library's working range the checks read (b2s_working_range). */
#define B2S3_ENGINE_VERSION B2S_ENGINE_BOX2D32
/* The engine, as reports name it. */
#define B2S3_ENGINE "Box2D v3.2"

typedef b2s_box2d32_report b2s3_report_t;
typedef b2s_box2d32_reports b2s3_reports_t;
typedef b2s_box2d32_built b2s3_built_t;

/* The bytes of a body's name the plan keeps: B2_NAME_LENGTH itself, which a host's build
 * may redefine (the working range's name_bytes is its default). */
#define B2S3_NAME_BYTES ((uint32_t)B2_NAME_LENGTH)

/* ---- bodies */

static void b2s3_set_pose(b2BodyDef* def, b2Vec2 position, b2Rot rotation) {
    def->position = b2ToPos(position);
    def->rotation = rotation;
}

static b2Vec2 b2s3_body_position(b2BodyId body) {
    return b2ToVec2(b2Body_GetPosition(body));
}

/* A fixed rotation is a motion lock; the snapshot keeps the inertia under it and later
 * sources zero it, so the plan also gives such a body an inertia of 0. The lock zeroes the
 * spin at every step (spec section 13: the plan reports it lossy-body). */
static void b2s3_lock_rotation(b2BodyDef* def, bool fixed) {
    def->motionLocks.angularZ = fixed;
}

static bool b2s3_rotation_locked(b2BodyId body) {
    return b2Body_GetMotionLocks(body).angularZ;
}

/* ---- chains: loose chain segments, one shape per edge, each with its neighbours as ghosts.
 * They collide exactly as v3.2's chains of the same points, and, unlike b2ChainDef (reworked
 * by the 3.2.0 release), are the same in both trees the adapter serves; they also take the
 * sensor flag. */

/* Edge i of a chain's points (open: [ghost, vertices..., ghost], a loop: the vertices). */
static b2ChainSegment b2s3_chain_segment(const b2Vec2* p, int n, bool loop, int i) {
    b2ChainSegment s;
    memset(&s, 0, sizeof s);
    if (loop) {
        s.ghost1 = p[(i + n - 1) % n];
        s.segment.point1 = p[i];
        s.segment.point2 = p[(i + 1) % n];
        s.ghost2 = p[(i + 2) % n];
    } else {
        s.ghost1 = p[i];
        s.segment.point1 = p[i + 1];
        s.segment.point2 = p[i + 2];
        s.ghost2 = p[i + 3];
    }
    return s;
}

/* How many shapes a chain of `n` points makes. */
static int b2s3_chain_segment_count(int n, bool loop) {
    return loop ? n : n - 3;
}

/* The built result's store of chain segments: per fixture slot, the range of its segments
 * in one pool that grows by doubling. */
static bool b2s3_allocate_chains(b2s3_built_t* built, uint32_t slots) {
    built->segments = (b2s_range*)calloc(slots + 1, sizeof(b2s_range));
    return built->segments != NULL;
}

static void b2s3_free_chains(b2s3_built_t* built) {
    free(built->segments);
    free(built->segment_pool);
}

/* Room for `more` ids at the end of the built segment pool of `*capacity` ids. */
static bool b2s3_reserve_segments(b2s3_built_t* built, uint32_t* capacity, uint32_t more) {
    if (built->segment_pool_count + more <= *capacity) {
        return true;
    }
    uint32_t grown = *capacity < 16u ? 16u : 2u * *capacity;
    while (grown < built->segment_pool_count + more) {
        grown *= 2u;
    }
    b2ShapeId* pool = (b2ShapeId*)realloc(built->segment_pool, grown * sizeof(b2ShapeId));
    if (pool == NULL) {
        return false;
    }
    built->segment_pool = pool;
    *capacity = grown;
    return true;
}

/* A chain of `n` points as one loose chain segment per edge, in order, into the segment
 * pool; false when memory runs out. */
static bool b2s3_create_chain(b2s3_built_t* built, uint32_t* capacity, uint32_t slot,
                              b2BodyId body, const b2ShapeDef* def, const b2Vec2* points, int n,
                              bool loop) {
    int count = b2s3_chain_segment_count(n, loop);
    if (!b2s3_reserve_segments(built, capacity, (uint32_t)count)) {
        return false;
    }
    built->segments[slot].first = built->segment_pool_count;
    built->segments[slot].count = (uint32_t)count;
    for (int i = 0; i < count; ++i) {
        b2ChainSegment segment = b2s3_chain_segment(points, n, loop, i);
        built->segment_pool[built->segment_pool_count++] =
            b2CreateChainSegmentShape(body, def, &segment);
    }
    built->shapes[slot] = built->segment_pool[built->segments[slot].first];
    return true;
}

/* ---- joints: anchors, axes and reference angles are the bodies' local frames */

#define B2S3_JOINT_BASE(def) ((def).base)

/* The frames the plan gives every kind. */
static void b2s3_place_frames(b2JointDef* base, const b2s_plan_joint* joint) {
    const b2s_transform* frames[2] = {&joint->frame_a, &joint->frame_b};
    b2Transform* out[2] = {&base->localFrameA, &base->localFrameB};
    for (int i = 0; i < 2; ++i) {
        out[i]->p.x = frames[i]->p.x;
        out[i]->p.y = frames[i]->p.y;
        out[i]->q.c = frames[i]->q.c;
        out[i]->q.s = frames[i]->q.s;
    }
}

#define B2S3_REVOLUTE_FRAMES(def, j) b2s3_place_frames(&(def).base, (j))
#define B2S3_WELD_FRAMES(def, j) b2s3_place_frames(&(def).base, (j))
#define B2S3_PRISMATIC_FRAMES(def, j) b2s3_place_frames(&(def).base, (j))
#define B2S3_AXIS_FRAMES(def, j) b2s3_place_frames(&(def).base, (j))
#define B2S3_ANCHOR_FRAMES(def, j) b2s3_place_frames(&(def).base, (j))

/* Friction acts at the anchors in v3.2: a motor joint driving no velocity, with the file's
 * force and torque as its limits. */
static void b2s3_friction_def(b2MotorJointDef* def, const b2s_plan_joint* joint) {
    b2s3_place_frames(&def->base, joint);
    def->linearVelocity = b2Vec2_zero;
    def->angularVelocity = 0.0f;
    def->maxVelocityForce = joint->max_force;
    def->maxVelocityTorque = joint->max_torque;
}

/* The nearest v3.2 form of Box2D 2.3's motor joint (the plan's): frame A at the offsets,
 * critically damped springs of the plan's frequency limited to MaxForce and MaxTorque. */
static void b2s3_motor_def(b2MotorJointDef* def, const b2s_plan_joint* joint) {
    b2s3_place_frames(&def->base, joint);
    def->linearHertz = joint->hertz;
    def->angularHertz = joint->hertz;
    def->linearDampingRatio = joint->damping_ratio;
    def->angularDampingRatio = joint->damping_ratio;
    def->maxSpringForce = joint->max_force;
    def->maxSpringTorque = joint->max_torque;
}

/* ---- capture: what a joint holds in v3.2's own fields, read as the engine gives them */

/* reports.c's conversion, which the readers below use. */
static b2s_vec2 b2s3_to_b2s(b2Vec2 v);

/* A joint's local frames (the library inverts them). */
static void b2s3_read_frames(b2JointId id, b2s_plan_joint* joint) {
    b2Transform frames[2] = {b2Joint_GetLocalFrameA(id), b2Joint_GetLocalFrameB(id)};
    b2s_transform* out[2] = {&joint->frame_a, &joint->frame_b};
    for (int i = 0; i < 2; ++i) {
        out[i]->p = b2s3_to_b2s(frames[i].p);
        out[i]->q.c = frames[i].q.c;
        out[i]->q.s = frames[i].q.s;
    }
}

/* A motor joint's velocity drive and springs (its frames are read as every kind's). */
static void b2s3_read_motor(b2JointId id, b2s_held_joint* held) {
    held->linear_velocity = b2s3_to_b2s(b2MotorJoint_GetLinearVelocity(id));
    held->angular_velocity = b2MotorJoint_GetAngularVelocity(id);
    held->max_velocity_force = b2MotorJoint_GetMaxVelocityForce(id);
    held->max_velocity_torque = b2MotorJoint_GetMaxVelocityTorque(id);
    held->joint.max_force = b2MotorJoint_GetMaxSpringForce(id);
    held->joint.max_torque = b2MotorJoint_GetMaxSpringTorque(id);
    held->joint.hertz = b2MotorJoint_GetAngularHertz(id);
    held->joint.damping_ratio = b2MotorJoint_GetAngularDampingRatio(id);
    held->linear_hertz = b2MotorJoint_GetLinearHertz(id);
    held->linear_damping_ratio = b2MotorJoint_GetLinearDampingRatio(id);
}

/* What a joint of a kind the format has no form for is (v3.2 has no mouse joint). */
static const char* b2s3_joint_without_form(b2JointId id) {
    (void)id;
    return "a joint of a kind this adapter does not know";
}

/* ---- lookups (lookup.c): which shapes a fixture slot holds */

/* The shape of fixture slot `slot`: a chain's first segment is there too. */
static b2ShapeId b2s3_slot_shape(const b2s3_built_t* built, uint32_t slot) {
    return built->shapes[slot];
}

/* The shapes of fixture slot `slot` (its shape, or its chain's segments), up to `capacity`
 * of them into `out`: how many it holds. */
static int b2s3_slot_shapes(const b2s3_built_t* built, uint32_t slot, b2ShapeId* out,
                            int capacity) {
    b2s_range segments = built->segments[slot];
    if (segments.count == 0) {
        if (capacity > 0) {
            out[0] = built->shapes[slot];
        }
        return B2_IS_NON_NULL(built->shapes[slot]) ? 1 : 0;
    }
    for (uint32_t i = 0; i < segments.count && (int)i < capacity; ++i) {
        out[i] = built->segment_pool[segments.first + i];
    }
    return (int)segments.count;
}

/* Whether `shape` is fixture slot `slot`'s or one of its chain's segments. */
static bool b2s3_slot_holds(const b2s3_built_t* built, uint32_t slot, b2ShapeId shape) {
    if (B2_ID_EQUALS(built->shapes[slot], shape)) {
        return true;
    }
    b2s_range segments = built->segments[slot];
    for (uint32_t i = 0; i < segments.count; ++i) {
        if (B2_ID_EQUALS(built->segment_pool[segments.first + i], shape)) {
            return true;
        }
    }
    return false;
}

#endif /* BOX2SCENE_BOX2D3_V32_H */
