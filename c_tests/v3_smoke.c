/*
 * A v3 adapter's build plumbing end to end: the bundled showcase builds into a real Box2D v3
 * world of the adapter's version (checked: v3.1 and v3.2 define the same names, and 2.4 has
 * no b2WorldId), and a dynamic body falls when it is stepped. Compiled once per v3 adapter
 * (V3_SUPPORT names its support header) as box2d3_smoke and box2d32_smoke.
 */
#include V3_SUPPORT

static int showcase_falls_in_box2d_v3(void) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/scenes/showcase.xml", BOX2SCENE_SOURCE_DIR);
    b2s_scene* scene = NULL;
    ENSURE_EQ(b2s_load_file(path, NULL, &scene, NULL), B2S_CODE_OK);
    b2Version version = b2GetVersion();
    ENSURE_EQ(version.major, 3);
    ENSURE_EQ(version.minor, V3_MINOR);

    b2WorldDef def = V3_ADAPTER(world_def)(scene, (b2Vec2){0.0f, -10.0f});
    b2WorldId world = b2CreateWorld(&def);
    v3_built* built = V3_ADAPTER(build_world)(scene, world);
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
    b2Vec2 start = v3_position(body);
    for (int step = 0; step < 60; ++step) {
        b2World_Step(world, 1.0f / 60.0f, 4);
    }
    b2Vec2 end = v3_position(body);
    ENSURE(isfinite(end.x) && isfinite(end.y));
    ENSURE(end.x != start.x || end.y != start.y);

    V3_ADAPTER(built_free)(built);
    b2DestroyWorld(world);
    b2s_scene_free(scene);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(showcase_falls_in_box2d_v3);
    return failed;
}
