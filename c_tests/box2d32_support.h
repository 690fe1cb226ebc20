/*
 * What the Box2D v3.2 adapter's tests share: v3_support.h for b2s_box2d32_*, whose
 * positions are b2Pos and whose joints take local frames.
 */
#ifndef BOX2SCENE_BOX2D32_SUPPORT_H
#define BOX2SCENE_BOX2D32_SUPPORT_H

#include <box2scene/box2d32.h>

#define V3_ADAPTER(name) b2s_box2d32_##name

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

#include "v3_support.h"

#endif /* BOX2SCENE_BOX2D32_SUPPORT_H */
