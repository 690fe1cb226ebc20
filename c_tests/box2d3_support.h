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

#include "v3_support.h"

#endif /* BOX2SCENE_BOX2D3_SUPPORT_H */
