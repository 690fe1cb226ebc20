// The harness of a C++ snippet that works on a Box2D 2.4 world: `world`, built from `scene`
// (level.xml, still loaded) as `built`.
#include "snippet_head.h"

#include <box2scene/box2d.hpp>

#include <cstdio>

int main() {
    b2s_scene* scene = nullptr;
    b2s_error error;
    if (b2s_load_file("level.xml", nullptr, &scene, &error) != B2S_CODE_OK) {
        std::fprintf(stderr, "level.xml:%u:%u: %s\n", error.line, error.column, error.message);
        return 1;
    }
    b2World world(box2scene::scene_gravity(scene, b2Vec2(0.0f, -10.0f)));
    box2scene::Built built = box2scene::build_world(scene, world);
    {
#include "snippet_body.h"
    }
    b2s_scene_free(scene);
    return 0;
}
