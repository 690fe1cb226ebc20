/*
 * The v3.2 adapter's build plumbing end to end: the bundled showcase builds into a real
 * Box2D v3.2 world (its version checked: the v3.1 engine defines the same names), and a
 * dynamic body falls when it is stepped.
 */
#include <box2scene/box2d32.h>

#include "test_macros.h"

static int showcase_falls_in_box2d_v32(void) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/scenes/showcase.xml", BOX2SCENE_SOURCE_DIR);
    b2s_scene* scene = NULL;
    ENSURE_EQ(b2s_load_file(path, NULL, &scene, NULL), B2S_CODE_OK);
    b2Version version = b2GetVersion();
    ENSURE_EQ(version.major, 3);
    ENSURE_EQ(version.minor, 2);

    b2WorldDef def = b2s_box2d32_world_def(scene, (b2Vec2){0.0f, -10.0f});
    b2WorldId world = b2CreateWorld(&def);
    b2s_box2d32_built* built = b2s_box2d32_build_world(scene, world);
    ENSURE(built != NULL);
    const b2s_scene_view* view = b2s_scene_get_view(scene);
    ENSURE_EQ(built->body_count, view->body_count);

    uint32_t dynamic = view->body_count;
    for (uint32_t i = 0; i < view->body_count && dynamic == view->body_count; ++i) {
        if (view->bodies[i].kind == B2S_BODY_KIND_DYNAMIC && !B2_IS_NULL(built->bodies[i])) {
            dynamic = i;
        }
    }
    ENSURE(dynamic < view->body_count);
    b2BodyId body = built->bodies[dynamic];
    b2Vec2 start = b2ToVec2(b2Body_GetPosition(body));
    for (int step = 0; step < 60; ++step) {
        b2World_Step(world, 1.0f / 60.0f, 4);
    }
    b2Vec2 end = b2ToVec2(b2Body_GetPosition(body));
    ENSURE(isfinite(end.x) && isfinite(end.y));
    ENSURE(end.x != start.x || end.y != start.y);

    b2s_box2d32_built_free(built);
    b2DestroyWorld(world);
    b2s_scene_free(scene);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(showcase_falls_in_box2d_v32);
    return failed;
}
