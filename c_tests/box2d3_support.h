/*
 * What the Box2D v3.1 adapter's tests share: v3_support.h for b2s_box2d3_*.
 */
#ifndef BOX2SCENE_BOX2D3_SUPPORT_H
#define BOX2SCENE_BOX2D3_SUPPORT_H

#include <box2scene/box2d3.h>

#define V3_ADAPTER(name) b2s_box2d3_##name

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

#include "v3_support.h"

#endif /* BOX2SCENE_BOX2D3_SUPPORT_H */
