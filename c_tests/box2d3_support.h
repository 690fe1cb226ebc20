/*
 * What the Box2D v3.1 adapter's tests share: v3_support.h for b2s_box2d3_*.
 */
#ifndef BOX2SCENE_BOX2D3_SUPPORT_H
#define BOX2SCENE_BOX2D3_SUPPORT_H

#include <box2scene/box2d3.h>

#define V3_ADAPTER(name) b2s_box2d3_##name
/* The minor version of the Box2D v3 the adapter serves. */
#define V3_MINOR 1
/* The engine whose working range the adapter checks. */
#define V3_ENGINE B2S_ENGINE_BOX2D31

static inline b2Vec2 v3_position(b2BodyId body) {
    return b2Body_GetPosition(body);
}

static inline b2Vec2 v3_pos(b2Vec2 v) {
    return v;
}

/* A revolute joint def between `a` and `b` at the anchors, its reference angle 0. */
static inline b2RevoluteJointDef v3_revolute_def(b2BodyId a, b2BodyId b, b2Vec2 anchor_a,
                                                 b2Vec2 anchor_b) {
    b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
    def.bodyIdA = a;
    def.bodyIdB = b;
    def.localAnchorA = anchor_a;
    def.localAnchorB = anchor_b;
    return def;
}

/* The part of a joint def that names its bodies (v3.1: the def itself). */
#define V3_JOINT_BASE(def) (def)

/* A joint between `a` and `b` of a kind the format has no form for: a mouse joint. */
static inline b2JointId v3_joint_without_form(b2WorldId world, b2BodyId a, b2BodyId b) {
    b2MouseJointDef mouse = b2DefaultMouseJointDef();
    mouse.bodyIdA = a;
    mouse.bodyIdB = b;
    return b2CreateMouseJoint(world, &mouse);
}

static inline void v3_lock_rotation(b2BodyDef* def, bool fixed) {
    def->fixedRotation = fixed;
}

static inline bool v3_rotation_fixed(b2BodyId body) {
    return b2Body_IsFixedRotation(body);
}

static inline b2MassData v3_shape_mass_data(b2ShapeId shape) {
    return b2Shape_GetMassData(shape);
}

static inline b2Vec2 v3_local_center(b2BodyId body) {
    return b2Body_GetLocalCenterOfMass(body);
}

static inline b2Vec2 v3_local_anchor_a(b2JointId joint) {
    return b2Joint_GetLocalAnchorA(joint);
}

static inline b2Vec2 v3_local_anchor_b(b2JointId joint) {
    return b2Joint_GetLocalAnchorB(joint);
}

/* The axis of a prismatic or wheel joint in body A's frame. */
static inline b2Vec2 v3_local_axis_a(b2JointId joint) {
    return b2Joint_GetLocalAxisA(joint);
}

/* How many segments the chain of fixture slot `slot` has (0 when it is not a chain), and
 * up to `capacity` of them in `out` when it is not NULL. */
static inline int v3_chain_segments(const b2s_box2d3_built* built, uint32_t slot, b2ShapeId* out,
                                    int capacity) {
    b2ChainId chain = built->chains[slot];
    if (B2_IS_NULL(chain)) {
        return 0;
    }
    int count = b2Chain_GetSegmentCount(chain);
    if (out != NULL && count <= capacity) {
        b2Chain_GetSegments(chain, out, capacity);
    }
    return count;
}

#include "v3_support.h"

#endif /* BOX2SCENE_BOX2D3_SUPPORT_H */
