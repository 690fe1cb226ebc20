// box2scene/box2d32.h from C++ (pedantic C++17), as a C++ host of Box2D v3.2 uses it: the
// declarations compile, link against the adapter compiled as C (cmake/box2d32.c), build the
// showcase into a world that steps, and capture it back.
#include <box2scene/box2d32.h>

#include <cmath>
#include <cstdio>

#include "test_macros.h"

static int showcase_builds_steps_and_captures_from_cxx() {
    char path[1024];
    std::snprintf(path, sizeof path, "%s/examples/scenes/showcase.xml", BOX2SCENE_SOURCE_DIR);
    b2s_scene* scene = nullptr;
    ENSURE_EQ(b2s_load_file(path, nullptr, &scene, nullptr), B2S_CODE_OK);
    b2WorldDef def = b2s_box2d32_world_def(scene, b2Vec2{0.0f, -10.0f});
    b2WorldId world = b2CreateWorld(&def);
    b2s_box2d32_built* built = b2s_box2d32_build_world(scene, world);
    ENSURE(built != nullptr);
    ENSURE_EQ(built->body_count, b2s_scene_get_view(scene)->body_count);
    for (int step = 0; step < 60; ++step) {
        b2World_Step(world, 1.0f / 60.0f, 4);
    }
    b2Vec2 p = b2ToVec2(b2Body_GetPosition(built->bodies[built->body_count - 1]));
    ENSURE(std::isfinite(p.x) && std::isfinite(p.y));
    b2s_scene* captured = nullptr;
    b2s_box2d32_reports reports;
    ENSURE_EQ(b2s_box2d32_capture_world(world, built->bodies, built->body_count, &captured,
                                        &reports, nullptr),
              B2S_CODE_OK);
    ENSURE_EQ(b2s_scene_get_view(captured)->body_count, built->body_count);
    b2s_box2d32_reports_free(&reports);
    b2s_scene_free(captured);
    b2s_box2d32_built_free(built);
    b2DestroyWorld(world);
    b2s_scene_free(scene);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(showcase_builds_steps_and_captures_from_cxx);
    return failed;
}
