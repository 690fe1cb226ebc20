/* A C host of an installed box2scene and its own Box2D v3.2: builds a scene's world through
 * the v3.2 adapter, steps it for one second and prints where the ball is. */
#include <box2scene/box2d32.h>

#include <stdio.h>

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s SCENE.xml\n", argv[0]);
        return 2;
    }
    b2s_scene* scene = NULL;
    b2s_error error;
    if (b2s_load_file(argv[1], NULL, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "%s:%u:%u: error[%s]: %s\n", argv[1], error.line, error.column,
                b2s_code_name(error.code), error.message);
        return 1;
    }
    b2WorldDef def = b2s_box2d32_world_def(scene, (b2Vec2){0.0f, -10.0f});
    b2WorldId world = b2CreateWorld(&def);
    b2s_box2d32_built* built = b2s_box2d32_build_world(scene, world);
    uint32_t ball = b2s_scene_find_body(scene, "Ball");
    b2s_scene_free(scene); /* the world does not refer to the scene */
    if (built == NULL) {
        return 1;
    }
    for (uint32_t i = 0; i < built->reports.count; ++i) {
        const b2s_box2d32_report* report = &built->reports.items[i];
        fprintf(stderr, "%s %u: %s\n", report->object, report->index, report->message);
    }
    int status = 1;
    if (ball != B2S_NONE && built->reports.count == 0) {
        for (int step = 0; step < 60; ++step) {
            b2World_Step(world, 1.0f / 60.0f, 4);
        }
        b2Vec2 position = b2ToVec2(b2Body_GetPosition(built->bodies[ball]));
        printf("%d bodies; after 1 s the ball is at (%.3f, %.3f)\n",
               b2World_GetCounters(world).bodyCount, position.x, position.y);
        status = 0;
    }
    b2s_box2d32_built_free(built);
    b2DestroyWorld(world);
    return status;
}
