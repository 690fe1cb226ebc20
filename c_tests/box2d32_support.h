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

/* build_v3 at a placement. */
static inline v3_world build_v3_at(const b2s_scene* scene, b2Transform placement) {
    v3_world world;
    b2WorldDef def = b2s_box2d32_world_def(scene, (b2Vec2){0.0f, -10.0f});
    world.id = b2CreateWorld(&def);
    world.built = b2s_box2d32_build_world_at(scene, world.id, placement);
    return world;
}

#endif /* BOX2SCENE_BOX2D32_SUPPORT_H */
