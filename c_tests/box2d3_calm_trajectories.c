/*
 * Where the bodies of the calm scenes (calm_scenes.h) go in Box2D v3.1, built by the v3.1
 * adapter: written to the file BOX2SCENE_CALM_TRAJECTORIES names, one line per sample
 * ("scene body sample x y angle", floats as %a), for box2d32_agrees_with_box2d3_test. Run
 * alone (tools/check-memory), without BOX2SCENE_CALM_TRAJECTORIES, it records them and
 * writes nothing.
 */
#include <box2scene/box2d3.h>

#define V3_ADAPTER(name) b2s_box2d3_##name

static inline b2Vec2 v3_position(b2BodyId body) {
    return b2Body_GetPosition(body);
}

#include "v3_support.h"

#include "calm_scenes.h"

static int calm_scenes_are_recorded_in_v31(void) {
    const char* path = getenv("BOX2SCENE_CALM_TRAJECTORIES");
    FILE* file = path != NULL ? fopen(path, "w") : tmpfile();
    ENSURE(file != NULL);
    for (size_t i = 0; i < CALM_SCENE_COUNT; ++i) {
        uint32_t bodies = calm_body_count(i);
        calm_sample* samples = (calm_sample*)calloc((size_t)bodies * CALM_SAMPLES + 1,
                                                    sizeof(calm_sample));
        ENSURE(samples != NULL);
        ENSURE(calm_trajectories(i, samples));
        for (uint32_t b = 0; b < bodies; ++b) {
            for (int k = 0; k < CALM_SAMPLES; ++k) {
                const calm_sample* s = &samples[(size_t)b * CALM_SAMPLES + (size_t)k];
                fprintf(file, "%u %u %d %a %a %a\n", (unsigned)i, (unsigned)b, k, (double)s->x,
                        (double)s->y, (double)s->angle);
            }
        }
        free(samples);
    }
    ENSURE_EQ(fclose(file), 0);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(calm_scenes_are_recorded_in_v31);
    return failed;
}
