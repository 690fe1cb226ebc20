/*
 * Nothing Box2D v3 cannot take: generated levels with every shape and joint kind, their
 * fields drawn from ordinary ranges and, one in 40, from extremes (the largest floats,
 * subnormals, negative zero, the edges of the working range), built through the adapter into
 * real Box2D v3 with its assertions on and stepped 600 times: every body stays finite and
 * nothing aborts. Joints are laid out as an editor lays them out (each body that yields hangs
 * from one earlier body at a shared world point, so that no joint starts far from satisfied
 * or contradicts another: v3's solver, like any, cannot hold those whatever their values).
 * Every other level is built at a placement of its own, turned and moved by up to 100 m.
 * Both versions take the same stream of levels. Compiled once per v3 adapter (V3_SUPPORT
 * names its support header) as box2d3_stress_test and box2d32_stress_test.
 */
#include V3_SUPPORT

#include "stress_levels.h"

#define LEVELS 2000
#define STEPS 600

static int generated_levels_stay_finite(void) {
    int levels = 0, beyond = 0, skipped = 0, bodies = 0, joints = 0;
    int kinds_built[B2S_JOINT_KIND_UNSUPPORTED + 1] = {0};
    for (int attempt = 0; levels < LEVELS && attempt < 4 * LEVELS; ++attempt) {
        b2s_scene* scene = generated_level();
        if (scene == NULL) {
            continue;
        }
        levels += 1;
        float turn = uniform(-3.14159265f, 3.14159265f);
        b2Transform placement = {{uniform(-100.0f, 100.0f), uniform(-100.0f, 100.0f)},
                                 {cosf(turn), sinf(turn)}};
        v3_world world = levels % 2 == 0 ? build_v3_at(scene, placement) : build_v3(scene);
        ENSURE(world.built != NULL);
        beyond += (int)count_reports(&world.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, NULL, 0);
        skipped += (int)count_reports(&world.built->reports, B2S_CODE_SKIPPED_JOINT, NULL, 0);
        for (uint32_t i = 0; i < world.built->body_count; ++i) {
            bodies += !B2_IS_NULL(world.built->bodies[i]);
        }
        const struct b2s_scene_view* view = b2s_scene_get_view(scene);
        for (uint32_t i = 0; i < world.built->joint_count; ++i) {
            bool made = !B2_IS_NULL(world.built->joints[i]);
            joints += made;
            kinds_built[view->joints[i].kind] += made;
        }
        for (int step = 0; step <= STEPS; ++step) {
            if (!bodies_finite(&world)) {
                char* text = NULL;
                b2s_write_memory(scene, NULL, &text, NULL, NULL);
                fprintf(stderr, "level %d is not finite after %d steps:\n%s\n", levels, step,
                        text != NULL ? text : "(not written)");
                b2s_text_free(text);
                return 1;
            }
            if (step < STEPS) {
                b2World_Step(world.id, TIME_STEP, SUB_STEPS);
            }
        }
        free_v3(&world);
        b2s_scene_free(scene);
    }
    printf("%d levels: %d bodies and %d joints built, %d values beyond the working range, "
           "%d joints v3 has no form for\n",
           levels, bodies, joints, beyond, skipped);
    ENSURE_EQ(levels, LEVELS);
    ENSURE(beyond > 0 && skipped > 0);
    /* every kind v3 has a form for was built, and stepped */
    for (uint32_t kind = 0; kind < B2S_JOINT_KIND_UNSUPPORTED; ++kind) {
        bool v3_has_it = kind != B2S_JOINT_KIND_PULLEY && kind != B2S_JOINT_KIND_GEAR;
        if (v3_has_it && kinds_built[kind] < 5) {
            fprintf(stderr, "joint kind %u was built %d times\n", (unsigned)kind,
                    kinds_built[kind]);
            return 1;
        }
    }
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(generated_levels_stay_finite);
    return failed;
}
