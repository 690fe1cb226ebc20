// The harness of a C++ snippet that works on a Box2D 2.4 world: `world`, built from `scene`
// (level.xml, still loaded) as `built`.
#include "snippet_head.h"

#include <box2scene/box2d.hpp>

#include "level.h"

int main() {
    b2s_scene* scene = load_level();
    if (scene == nullptr) {
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
