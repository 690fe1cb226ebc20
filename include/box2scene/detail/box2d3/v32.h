/*
 * What the Box2D v3 adapter's sources (adapter.c and the files it includes) need to know of
 * Box2D v3.2, the one place where the adapter for v3.2 differs from one for another v3:
 * its public names, how a body takes its position and fixed rotation, how a body's mass is
 * summed (for a capture), how chains are made and read back, how joints take their
 * anchors, axes and reference angles (local frames) and give them back, and its motor
 * joint. What a build gives each def is the library's plan.
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

static b2Vec2 b2s3_local_center(b2BodyId body) {
    return b2Body_GetLocalCenter(body);
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

static b2MassData b2s3_shape_mass(b2ShapeId shape) {
    return b2Shape_ComputeMassData(shape);
}

/* The mass v3.2 gives a dynamic body with these shapes (b2Body_ApplyMassFromShapes),
 * operation for operation so that the bits agree: each shape's inertia is about its own
 * centroid; the body walks its shapes newest first, for the mass and the centre and again
 * for the inertia about the centre. `shapes` is in creation order. `inertia_kept` is always
 * true: the sum cannot go negative. */
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
    }
    if (body.mass > 0.0f) {
        float inverse = 1.0f / body.mass;
        center = b2MulSV(inverse, center);
    }
    for (size_t i = count; i-- > 0;) {
        if (densities[i] == 0.0f || shapes[i].mass == 0.0f) {
            continue;
        }
        b2Vec2 offset = b2Sub(center, shapes[i].center);
        float inertia = shapes[i].rotationalInertia + shapes[i].mass * b2Dot(offset, offset);
        body.rotationalInertia += inertia;
    }
    *inertia_kept = true;
    if (fixed_rotation) {
        body.rotationalInertia = 0.0f;
    }
    body.center = center;
    return body;
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

/* The rotation of an angle as the build's frames make it (a capture inverts it). */
static b2Rot b2s3_rotation(float angle) {
    b2Rot q = {cosf(angle), sinf(angle)};
    return q;
}

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

/* The bytes of a loss a capture reports. */
#define B2S3_LOSS_SIZE 320

/* Friction acts at the anchors in v3.2: a motor joint driving no velocity, with the file's
 * force and torque as its limits. */
static void b2s3_friction_def(b2MotorJointDef* def, const b2s_plan_joint* joint) {
    b2s3_place_frames(&def->base, joint);
    def->linearVelocity = b2Vec2_zero;
    def->angularVelocity = 0.0f;
    def->maxVelocityForce = joint->max_force;
    def->maxVelocityTorque = joint->max_torque;
}

/* s^-1: the step rate the motor joint's springs assume when they stand in for Box2D 2.x's
 * CorrectionFactor (a share of the error removed each step); the library's plan holds the
 * same, and a capture inverts it. */
#define B2S3_MOTOR_STEP_RATE 60.0f
#define B2S3_TWO_PI 6.28318530718f

/* The spring frequency that stands in for a CorrectionFactor. */
static float b2s3_motor_hertz(float correction_factor) {
    return correction_factor * B2S3_MOTOR_STEP_RATE / B2S3_TWO_PI;
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

/* ---- capture: v3.2 holds local frames, which capture inverts, and loose chain segments,
 * which it regroups */

/* capture.c's exact inverses and its test of consecutive chain segments, which the hooks
 * below use. */
static float b2s3_ulps_away(float x, int steps);
static bool b2s3_search_ulps(float guess, bool (*gives)(float x, const float* wanted),
                             const float* wanted, float* out);
static bool b2s3_angle_of(b2Rot q, float* angle);
static bool b2s3_continues(b2ChainSegment cur, b2ChainSegment next);

/* Loose segments belong to no chain: consecutive ones that continue one another (the body's
 * shapes sorted by id, as they were created) are one chain. `end`: the shapes before it
 * belong to a chain already met. */
typedef struct b2s3_chains {
    int end;
} b2s3_chains;

static bool b2s3_chains_of(b2s3_chains* chains, const b2ShapeId* shapes, int count) {
    (void)shapes;
    (void)count;
    chains->end = 0;
    return true;
}

static void b2s3_chains_free(b2s3_chains* chains) {
    (void)chains;
}

/* How many chain segments from `first` on continue one another, up to the one that closes
 * a loop (a loop built beside another of the same points must not run into it). */
static int b2s3_segment_run(const b2ShapeId* shapes, int first, int count) {
    int run = 1;
    b2ChainSegment head = b2Shape_GetChainSegment(shapes[first]);
    b2ChainSegment cur = head;
    while (first + run < count && b2Shape_GetType(shapes[first + run]) == b2_chainSegmentShape &&
           !(run >= 3 && b2s3_continues(cur, head))) {
        b2ChainSegment next = b2Shape_GetChainSegment(shapes[first + run]);
        if (!b2s3_continues(cur, next)) {
            break;
        }
        cur = next;
        run += 1;
    }
    return run;
}

/* The segments of the chain that starts at `shapes[i]` (a chain segment), the run of those
 * that continue it; 0 when `shapes[i]` lies inside a chain already met. */
static int b2s3_chain_at(b2s3_chains* chains, const b2ShapeId* shapes, int i, int count,
                         const b2ShapeId** segments) {
    if (i < chains->end) {
        return 0;
    }
    int run = b2s3_segment_run(shapes, i, count);
    chains->end = i + run;
    *segments = shapes + i;
    return run;
}

/* One loose segment was made of an edge with ghost vertices or of a chain of two vertices:
 * written as the edge. */
#define B2S3_LONE_SEGMENT_KIND B2S_SHAPE_KIND_EDGE

/* v3.2 has no mouse joint. */
#define B2S3_HAS_MOUSE_JOINT 0

/* wanted: an axis rotation (c, s), then the rotation of frame B the build makes of it. */
static bool b2s3_prismatic_reference_of(float angle, const float* wanted) {
    b2Rot axis = {wanted[0], wanted[1]};
    b2Rot q = b2InvMulRot(b2s3_rotation(angle), axis);
    return q.c == wanted[2] && q.s == wanted[3];
}

/* The axis whose normalisation in the build gives frame A's x axis `unit` bit for bit: the
 * axis itself, or one a few ulps from it (a unit vector is not always its own
 * normalisation). False, with `unit` written, when none is. */
static bool b2s3_axis_of(b2Vec2 unit, b2s_joint* joint) {
    for (int k = 0; k <= 8; ++k) {
        for (int dx = -k; dx <= k; ++dx) {
            for (int dy = -k; dy <= k; ++dy) {
                if (abs(dx) != k && abs(dy) != k) {
                    continue; /* the ring at distance k only */
                }
                b2Vec2 axis = {b2s3_ulps_away(unit.x, dx), b2s3_ulps_away(unit.y, dy)};
                b2Vec2 normalised = b2Normalize(axis);
                if (normalised.x == unit.x && normalised.y == unit.y) {
                    joint->local_axis_a.x = axis.x;
                    joint->local_axis_a.y = axis.y;
                    return true;
                }
            }
        }
    }
    joint->local_axis_a.x = unit.x;
    joint->local_axis_a.y = unit.y;
    return false;
}

/* A joint's anchors, and its axis and reference angle where its kind has them, from its
 * frames as the build sets them (frame A carries the axis or the reference angle, frame B
 * is unturned but for a prismatic joint's), inverted exactly. What has no exact inverse, or
 * is not of the build's form, is written into `losses` as the nearest; returns their count. */
static int b2s3_frames_of(b2JointId id, b2s_joint* joint, char losses[2][B2S3_LOSS_SIZE]) {
    b2Transform a = b2Joint_GetLocalFrameA(id), b = b2Joint_GetLocalFrameB(id);
    int count = 0;
    if (joint->kind != B2S_JOINT_KIND_PRISMATIC && !(b.q.c == 1.0f && b.q.s == 0.0f)) {
        snprintf(losses[count++], B2S3_LOSS_SIZE, "%s",
                 "a turn of its frame B has no Box2Scene form; written without it");
    }
    joint->local_anchor_a.x = a.p.x;
    joint->local_anchor_a.y = a.p.y;
    joint->local_anchor_b.x = b.p.x;
    joint->local_anchor_b.y = b.p.y;
    b2Vec2 unit = {a.q.c, a.q.s};
    switch (joint->kind) {
    case B2S_JOINT_KIND_REVOLUTE:
    case B2S_JOINT_KIND_WELD:
        if (!b2s3_angle_of(a.q, &joint->reference_angle)) {
            snprintf(losses[count++], B2S3_LOSS_SIZE,
                     "no angle has exactly the rotation of its frame A; the nearest, %.9g rad, "
                     "was written as ReferenceAngle",
                     (double)joint->reference_angle);
        }
        break;
    case B2S_JOINT_KIND_PRISMATIC: {
        if (!b2s3_axis_of(unit, joint)) {
            snprintf(losses[count++], B2S3_LOSS_SIZE,
                     "no axis near (%.9g, %.9g) normalises to it exactly; it was written",
                     (double)unit.x, (double)unit.y);
        }
        float wanted[4] = {a.q.c, a.q.s, b.q.c, b.q.s};
        float guess = atan2f(a.q.s, a.q.c) - atan2f(b.q.s, b.q.c);
        if (!b2s3_search_ulps(guess, b2s3_prismatic_reference_of, wanted,
                              &joint->reference_angle)) {
            snprintf(losses[count++], B2S3_LOSS_SIZE,
                     "no reference angle gives exactly the rotation of its frame B; the "
                     "nearest, %.9g rad, was written",
                     (double)joint->reference_angle);
        }
        break;
    }
    case B2S_JOINT_KIND_WHEEL:
    case B2S_JOINT_KIND_LINE:
        if (!b2s3_axis_of(unit, joint)) {
            snprintf(losses[count++], B2S3_LOSS_SIZE,
                     "no axis near (%.9g, %.9g) normalises to it exactly; it was written",
                     (double)unit.x, (double)unit.y);
        }
        break;
    default: break;
    }
    return count;
}

/* wanted: the spring frequency the build makes of a CorrectionFactor. */
static bool b2s3_motor_hertz_of(float correction_factor, const float* wanted) {
    return b2s3_motor_hertz(correction_factor) == wanted[0];
}

/* A motor joint read back: Friction when it drives no velocity and has no springs, frames
 * unturned (what the build makes of one); else the Motor the build approximates by it, its
 * offsets from frame A and its CorrectionFactor from its spring frequency, inverted
 * exactly. One that has neither form is read as the nearest Motor: returns what the report
 * says of it, else NULL. */
static const char* b2s3_motor_of(b2JointId id, b2s_joint* joint) {
    b2Transform a = b2Joint_GetLocalFrameA(id), b = b2Joint_GetLocalFrameB(id);
    b2Vec2 v = b2MotorJoint_GetLinearVelocity(id);
    bool still = v.x == 0.0f && v.y == 0.0f && b2MotorJoint_GetAngularVelocity(id) == 0.0f;
    bool unturned_b = b.q.c == 1.0f && b.q.s == 0.0f;
    bool friction = still && b2MotorJoint_GetMaxSpringForce(id) == 0.0f &&
                    b2MotorJoint_GetMaxSpringTorque(id) == 0.0f && a.q.c == 1.0f &&
                    a.q.s == 0.0f && unturned_b;
    if (friction) {
        b2s_joint_default(B2S_JOINT_KIND_FRICTION, joint);
        joint->local_anchor_a.x = a.p.x;
        joint->local_anchor_a.y = a.p.y;
        joint->local_anchor_b.x = b.p.x;
        joint->local_anchor_b.y = b.p.y;
        joint->max_force = b2MotorJoint_GetMaxVelocityForce(id);
        joint->max_torque = b2MotorJoint_GetMaxVelocityTorque(id);
        return NULL;
    }
    b2s_joint_default(B2S_JOINT_KIND_MOTOR, joint);
    joint->linear_offset.x = a.p.x;
    joint->linear_offset.y = a.p.y;
    joint->max_force = b2MotorJoint_GetMaxSpringForce(id);
    joint->max_torque = b2MotorJoint_GetMaxSpringTorque(id);
    float hertz = b2MotorJoint_GetLinearHertz(id);
    bool exact = still && unturned_b && b.p.x == 0.0f && b.p.y == 0.0f &&
                 b2MotorJoint_GetMaxVelocityForce(id) == 0.0f &&
                 b2MotorJoint_GetMaxVelocityTorque(id) == 0.0f &&
                 b2MotorJoint_GetAngularHertz(id) == hertz &&
                 b2MotorJoint_GetLinearDampingRatio(id) == 1.0f &&
                 b2MotorJoint_GetAngularDampingRatio(id) == 1.0f;
    float wanted[1] = {hertz};
    exact = b2s3_search_ulps(hertz * B2S3_TWO_PI / B2S3_MOTOR_STEP_RATE, b2s3_motor_hertz_of,
                             wanted, &joint->correction_factor) &&
            exact;
    exact = b2s3_angle_of(a.q, &joint->angular_offset) && exact;
    return exact ? NULL
                 : "a motor joint other than the build makes of a Motor joint: written as the "
                   "nearest, from the offsets of its frame A, its spring limits and a "
                   "CorrectionFactor from its linear spring's frequency";
}

/* ---- lookups (lookup.c): which shapes a fixture slot holds */

/* The shape of fixture slot `slot`: a chain's first segment is there too. */
static b2ShapeId b2s3_slot_shape(const b2s3_built_t* built, uint32_t slot) {
    return built->shapes[slot];
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
