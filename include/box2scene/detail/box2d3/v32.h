/*
 * What the Box2D v3 adapter's sources (adapter.c and the files it includes) need to know of
 * Box2D v3.2, the one place where the adapter for v3.2 differs from one for another v3:
 * its public names, its constants, how a body takes its position and fixed rotation, how a
 * body's mass is summed, how chains are made and read back, how joints take their anchors,
 * axes and reference angles (local frames), and its motor joint.
 *
 * Only the part of the API that Box2D's 3.2 development snapshot (boxdd-sys 0.6.0), its
 * upstream of August 2026 and the 3.2.0 release share is used: no b2ChainDef, no
 * b2DestroyJoint, no pre-solve callback, no state hash, joint kinds compared by name.
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

/* The public names: b2s_box2d32_NAME, B2S_BOX2D32_LIMIT. */
#define B2S3_API(name) b2s_box2d32_##name
#define B2S3_LIMIT(name) B2S_BOX2D32_##name
/* The engine, as reports name it. */
#define B2S3_ENGINE "Box2D v3.2"

typedef b2s_box2d32_report b2s3_report_t;
typedef b2s_box2d32_reports b2s3_reports_t;
typedef b2s_box2d32_built b2s3_built_t;

/* v3.2's linear slop (B2_LINEAR_SLOP) at one length unit per metre: it refuses a segment no
 * longer than that and raises a distance joint's length to it. */
#define B2S3_LINEAR_SLOP 0.005f
/* The bytes of a body's name v3.2 keeps (B2_NAME_LENGTH, which a build may redefine). */
#define B2S3_NAME_LENGTH ((size_t)B2_NAME_LENGTH)

/* ---- bodies */

static void b2s3_set_pose(b2BodyDef* def, b2Vec2 position, b2Rot rotation) {
    def->position = b2ToPos(position);
    def->rotation = rotation;
}

static b2Vec2 b2s3_body_position(b2BodyId body) {
    return b2ToVec2(b2Body_GetPosition(body));
}

/* A fixed rotation is a motion lock; the snapshot keeps the inertia under it and later
 * sources zero it, so the adapter also gives such a body an inertia of 0 (bodies.c). */
static void b2s3_lock_rotation(b2BodyDef* def, bool fixed) {
    def->motionLocks.angularZ = fixed;
}

static bool b2s3_rotation_locked(b2BodyId body) {
    return b2Body_GetMotionLocks(body).angularZ;
}

/* Every kinematic and dynamic body whose shapes did not update its mass must have it
 * computed once, or v3.2 asserts at the step. */
static bool b2s3_needs_mass_update(b2BodyType type) {
    return type != b2_staticBody;
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
 * They collide exactly as v3.2's chains of the same points, and, unlike b2ChainDef (revised
 * in 3.2.0), are the same in every 3.2 source; they also take the sensor flag. */

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

/* v3.2's loose segments make a loop of any 3 points on. */
#define B2S3_MIN_LOOP_POINTS 3

/* What a chain loses of its fixture's shape def: nothing. */
static const char* b2s3_chain_loss(const b2ShapeDef* def) {
    (void)def;
    return NULL;
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

/* ---- the working range where v3.2's measurements differ from v3.1's (docs/working-range.md) */

/* Friction acts at the anchors, so their levers count. */
#define B2S3_FRICTION_AT_ANCHORS true
/* A line or wheel joint to a body that does not move has the lever of any other kind. */
#define B2S3_MAX_LEVER_FIXED_WHEEL B2S_BOX2D32_MAX_LEVER
/* A line or wheel joint is bounded by how far across its axis it starts between two
 * dynamic bodies, in radii of gyration, not in metres. */
#define B2S3_MAX_WHEEL_VIOLATION FLT_MAX
#define B2S3_WHEEL_VIOLATION_GYRATIONS B2S_BOX2D32_MAX_INITIAL_VIOLATION
/* v3.2 holds a prismatic joint whose axis runs far from body A's centre to body B's anchor,
 * and several joints that start violated on one pair of bodies (the line or wheel joint
 * among them left out). */
#define B2S3_PRISMATIC_LEVER_TO_B false
#define B2S3_MAX_PULLED_VIOLATION FLT_MAX

/* ---- joints: anchors, axes and reference angles are the bodies' local frames */

#define B2S3_JOINT_BASE(def) ((def).base)

typedef struct b2s3_frames {
    b2Vec2 anchor_a, anchor_b;
    b2Vec2 axis; /* unit, where the joint kind has one */
    float reference_angle;
} b2s3_frames;

static b2Rot b2s3_rotation(float angle) {
    b2Rot q = {cosf(angle), sinf(angle)};
    return q;
}

static b2Rot b2s3_axis_rotation(b2Vec2 unit) {
    b2Rot q = {unit.x, unit.y};
    return q;
}

static void b2s3_place_frames(b2JointDef* base, b2Vec2 anchor_a, b2Rot qa, b2Vec2 anchor_b,
                              b2Rot qb) {
    base->localFrameA.p = anchor_a;
    base->localFrameA.q = qa;
    base->localFrameB.p = anchor_b;
    base->localFrameB.q = qb;
}

/* Revolute and weld: frame A turned by the reference angle. */
#define B2S3_REVOLUTE_FRAMES(def, f) B2S3_ANGLE_FRAMES(def, f)
#define B2S3_WELD_FRAMES(def, f) B2S3_ANGLE_FRAMES(def, f)
#define B2S3_ANGLE_FRAMES(def, f)                                                              \
    b2s3_place_frames(&(def).base, (f).anchor_a, b2s3_rotation((f).reference_angle),           \
                      (f).anchor_b, b2Rot_identity)
/* Prismatic: the axis is frame A's x, and frame B keeps the bodies at the reference angle. */
#define B2S3_PRISMATIC_FRAMES(def, f)                                                          \
    b2s3_place_frames(&(def).base, (f).anchor_a, b2s3_axis_rotation((f).axis), (f).anchor_b,   \
                      b2InvMulRot(b2s3_rotation((f).reference_angle),                          \
                                  b2s3_axis_rotation((f).axis)))
/* Line and wheel: the axis is frame A's x. */
#define B2S3_AXIS_FRAMES(def, f)                                                               \
    b2s3_place_frames(&(def).base, (f).anchor_a, b2s3_axis_rotation((f).axis), (f).anchor_b,   \
                      b2Rot_identity)
/* Distance, rope and friction: the anchors alone. */
#define B2S3_ANCHOR_FRAMES(def, f)                                                             \
    b2s3_place_frames(&(def).base, (f).anchor_a, b2Rot_identity, (f).anchor_b, b2Rot_identity)

/* The bytes of a loss a joint def reports. */
#define B2S3_LOSS_SIZE 320

/* Friction acts at the anchors in v3.2: a motor joint driving no velocity, with the file's
 * force and torque as its limits. Loses nothing (returns false). */
static bool b2s3_friction_def(b2MotorJointDef* def, const b2s_joint* joint, b2s3_frames f,
                              char* loss) {
    (void)loss;
    B2S3_ANCHOR_FRAMES(*def, f);
    def->linearVelocity = b2Vec2_zero;
    def->angularVelocity = 0.0f;
    def->maxVelocityForce = joint->max_force;
    def->maxVelocityTorque = joint->max_torque;
    return false;
}

/* s^-1: the step rate the motor joint's springs assume when they stand in for Box2D 2.x's
 * CorrectionFactor (a share of the error removed each step). */
#define B2S3_MOTOR_STEP_RATE 60.0f
#define B2S3_TWO_PI 6.28318530718f

/* The spring frequency that stands in for a CorrectionFactor. */
static float b2s3_motor_hertz(float correction_factor) {
    return correction_factor * B2S3_MOTOR_STEP_RATE / B2S3_TWO_PI;
}

/* The nearest v3.2 form of Box2D 2.3's motor joint (whose offsets, force limits and
 * CorrectionFactor v3.2's has no fields for): frame A at the offsets, so that springs drive
 * body B's origin and angle there, a critically damped spring of CorrectionFactor * 60 / 2pi
 * Hz (as quick as 2.x's correction at 60 steps a second), limited to MaxForce and MaxTorque.
 * Writes what the report says of it into `losses` and returns their count. */
static int b2s3_motor_def(b2MotorJointDef* def, const b2s_joint* joint,
                          char losses[2][B2S3_LOSS_SIZE]) {
    float hertz = b2s3_motor_hertz(joint->correction_factor);
    b2s3_place_frames(&def->base, b2Vec2_zero, b2Rot_identity, b2Vec2_zero, b2Rot_identity);
    def->base.localFrameA.p.x = joint->linear_offset.x;
    def->base.localFrameA.p.y = joint->linear_offset.y;
    def->base.localFrameA.q = b2s3_rotation(joint->angular_offset);
    def->linearHertz = hertz;
    def->angularHertz = hertz;
    def->linearDampingRatio = 1.0f;
    def->angularDampingRatio = 1.0f;
    def->maxSpringForce = joint->max_force;
    def->maxSpringTorque = joint->max_torque;
    snprintf(losses[0], B2S3_LOSS_SIZE, "%s",
             "Box2D v3.2's motor joint has no offsets, force limits or CorrectionFactor: its "
             "frame A carries LinearOffset and AngularOffset, and critically damped springs of "
             "CorrectionFactor * 60 / 2pi Hz limited to MaxForce and MaxTorque drive body B "
             "there");
    return 1;
}

/* ---- capture */

/* The frames of a joint, as the build set them: false when they do not have the build's
 * form (frame B turned for a kind whose frame B the build leaves unturned). */
static bool b2s3_frames_of(b2JointId id, b2s3_frames* f, bool prismatic) {
    b2Transform a = b2Joint_GetLocalFrameA(id), b = b2Joint_GetLocalFrameB(id);
    f->anchor_a = a.p;
    f->anchor_b = b.p;
    f->axis.x = a.q.c;
    f->axis.y = a.q.s;
    f->reference_angle = 0.0f;
    return prismatic || (b.q.c == 1.0f && b.q.s == 0.0f);
}

/* A motor joint read back: Friction when it drives no velocity and has no springs, frames
 * unturned (what the build makes of one); else the Motor the build approximates by it, its
 * offsets in frame A and its spring frequency in `*hertz`, for the caller to invert. False
 * when the joint does not have the form the build gives either. */
static bool b2s3_motor_of(b2JointId id, b2s_joint* joint, bool* friction, float* hertz) {
    b2Transform a = b2Joint_GetLocalFrameA(id), b = b2Joint_GetLocalFrameB(id);
    b2Vec2 v = b2MotorJoint_GetLinearVelocity(id);
    bool still = v.x == 0.0f && v.y == 0.0f && b2MotorJoint_GetAngularVelocity(id) == 0.0f;
    bool unturned_b = b.q.c == 1.0f && b.q.s == 0.0f;
    *friction = still && b2MotorJoint_GetMaxSpringForce(id) == 0.0f &&
                b2MotorJoint_GetMaxSpringTorque(id) == 0.0f && a.q.c == 1.0f && a.q.s == 0.0f &&
                unturned_b;
    if (*friction) {
        b2s_joint_default(B2S_JOINT_KIND_FRICTION, joint);
        joint->local_anchor_a.x = a.p.x;
        joint->local_anchor_a.y = a.p.y;
        joint->local_anchor_b.x = b.p.x;
        joint->local_anchor_b.y = b.p.y;
        joint->max_force = b2MotorJoint_GetMaxVelocityForce(id);
        joint->max_torque = b2MotorJoint_GetMaxVelocityTorque(id);
        return true;
    }
    b2s_joint_default(B2S_JOINT_KIND_MOTOR, joint);
    joint->linear_offset.x = a.p.x;
    joint->linear_offset.y = a.p.y;
    joint->max_force = b2MotorJoint_GetMaxSpringForce(id);
    joint->max_torque = b2MotorJoint_GetMaxSpringTorque(id);
    *hertz = b2MotorJoint_GetLinearHertz(id);
    return still && unturned_b && b.p.x == 0.0f && b.p.y == 0.0f &&
           b2MotorJoint_GetMaxVelocityForce(id) == 0.0f &&
           b2MotorJoint_GetMaxVelocityTorque(id) == 0.0f &&
           b2MotorJoint_GetAngularHertz(id) == *hertz &&
           b2MotorJoint_GetLinearDampingRatio(id) == 1.0f &&
           b2MotorJoint_GetAngularDampingRatio(id) == 1.0f;
}

/* What the scene calls a v3.2 joint kind without a Box2Scene form (NULL for the kinds the
 * capture writes). Kinds are compared by name: their numbers moved between 3.2 sources. */
static const char* b2s3_unwritten_joint(b2JointType type) {
    switch (type) {
    case b2_distanceJoint:
    case b2_motorJoint:
    case b2_prismaticJoint:
    case b2_revoluteJoint:
    case b2_weldJoint:
    case b2_wheelJoint: return NULL;
    case b2_filterJoint: return "a filter joint";
    default: return "a joint of a kind this adapter does not know";
    }
}

#endif /* BOX2SCENE_BOX2D3_V32_H */
