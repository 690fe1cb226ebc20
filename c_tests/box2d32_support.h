/*
 * What the Box2D v3.2 adapter's tests share: v3_support.h for b2s_box2d32_*, whose
 * positions are b2Pos.
 */
#ifndef BOX2SCENE_BOX2D32_SUPPORT_H
#define BOX2SCENE_BOX2D32_SUPPORT_H

#include <box2scene/box2d32.h>

#define V3_ADAPTER(name) b2s_box2d32_##name

static inline b2Vec2 v3_position(b2BodyId body) {
    return b2ToVec2(b2Body_GetPosition(body));
}

#include "v3_support.h"

#endif /* BOX2SCENE_BOX2D32_SUPPORT_H */
