// A C++ host of an installed box2scene and Debian's Box2D 2.4: builds a scene's world
// through the adapter, steps it for one second and prints where the ball is.
#include <box2scene/box2d.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s SCENE.xml\n", argv[0]);
        return 2;
    }
    b2s_scene* scene = nullptr;
    b2s_error error;
    if (b2s_load_file(argv[1], nullptr, &scene, &error) != B2S_CODE_OK) {
        std::fprintf(stderr, "%s:%u:%u: error[%s]: %s\n", argv[1], error.line, error.column,
                     b2s_code_name(error.code), error.message);
        return 1;
    }
    b2World world(box2scene::scene_gravity(scene, b2Vec2(0.0f, -10.0f)));
    box2scene::Built built = box2scene::build_world(scene, world);
    uint32_t ball = b2s_scene_find_body(scene, "Ball");
    b2s_scene_free(scene);  // the world does not refer to the scene
    for (const box2scene::Report& report : built.reports) {
        std::fprintf(stderr, "%s %u: %s\n", report.object, report.index, report.message.c_str());
    }
    if (ball == B2S_NONE || !built.reports.empty()) {
        return 1;
    }

    for (int step = 0; step < 60; ++step) {
        world.Step(1.0f / 60.0f, 8, 3);
    }
    b2Vec2 position = built.bodies[ball]->GetPosition();
    std::printf("%d bodies; after 1 s the ball is at (%.3f, %.3f)\n", world.GetBodyCount(),
                position.x, position.y);
    return 0;
}
