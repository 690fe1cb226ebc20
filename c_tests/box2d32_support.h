/*
 * What the Box2D v3.2 adapter's tests share: v3_support.h for b2s_box2d32_*, whose
 * positions are b2Pos and whose joints take local frames.
 */
#ifndef BOX2SCENE_BOX2D32_SUPPORT_H
#define BOX2SCENE_BOX2D32_SUPPORT_H

#include <box2scene/box2d32.h>

#define V3_ADAPTER(name) b2s_box2d32_##name
/* The minor version of the Box2D v3 the adapter serves. */
#define V3_MINOR 2
/* The engine whose working range the adapter checks. */
#define V3_ENGINE B2S_ENGINE_BOX2D32

static inline b2Vec2 v3_position(b2BodyId body) {
    return b2ToVec2(b2Body_GetPosition(body));
}

static inline b2Pos v3_pos(b2Vec2 v) {
    return b2ToPos(v);
}

/* A revolute joint def between `a` and `b` at the anchors, its reference angle 0. */
static inline b2RevoluteJointDef v3_revolute_def(b2BodyId a, b2BodyId b, b2Vec2 anchor_a,
                                                 b2Vec2 anchor_b) {
    b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
    def.base.bodyIdA = a;
    def.base.bodyIdB = b;
    def.base.localFrameA.p = anchor_a;
    def.base.localFrameA.q = b2Rot_identity;
    def.base.localFrameB.p = anchor_b;
    return def;
}

/* The part of a joint def that names its bodies (v3.2: its base). */
#define V3_JOINT_BASE(def) ((def).base)

/* A joint between `a` and `b` of a kind the format has no form for: a filter joint (v3.2
 * has no mouse joint). */
static inline b2JointId v3_joint_without_form(b2WorldId world, b2BodyId a, b2BodyId b) {
    b2FilterJointDef filter = b2DefaultFilterJointDef();
    filter.base.bodyIdA = a;
    filter.base.bodyIdB = b;
    return b2CreateFilterJoint(world, &filter);
}

static inline void v3_lock_rotation(b2BodyDef* def, bool fixed) {
    def->motionLocks.angularZ = fixed;
}

static inline bool v3_rotation_fixed(b2BodyId body) {
    return b2Body_GetMotionLocks(body).angularZ;
}

static inline b2MassData v3_shape_mass_data(b2ShapeId shape) {
    return b2Shape_ComputeMassData(shape);
}

static inline b2Vec2 v3_local_center(b2BodyId body) {
    return b2Body_GetLocalCenter(body);
}

static inline b2Vec2 v3_local_anchor_a(b2JointId joint) {
    return b2Joint_GetLocalFrameA(joint).p;
}

static inline b2Vec2 v3_local_anchor_b(b2JointId joint) {
    return b2Joint_GetLocalFrameB(joint).p;
}

/* The axis of a prismatic or wheel joint in body A's frame: frame A's x axis. */
static inline b2Vec2 v3_local_axis_a(b2JointId joint) {
    return b2Rot_GetXAxis(b2Joint_GetLocalFrameA(joint).q);
}

/* How many segments the chain of fixture slot `slot` has (0 when it is not a chain), and
 * up to `capacity` of them in `out` when it is not NULL. */
static inline int v3_chain_segments(const b2s_box2d32_built* built, uint32_t slot,
                                    b2ShapeId* out, int capacity) {
    if (B2_IS_NULL(built->shapes[slot])) {
        return 0;
    }
    int count = (int)built->segments[slot].count;
    for (int i = 0; out != NULL && count <= capacity && i < count; ++i) {
        out[i] = built->segment_pool[built->segments[slot].first + (uint32_t)i];
    }
    return count;
}

#include "v3_support.h"

#endif /* BOX2SCENE_BOX2D32_SUPPORT_H */
