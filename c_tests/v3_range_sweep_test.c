/*
 * The measured working range of Box2D v3 (docs/working-range.md): every case of
 * range_sweep.h, each run in a child process, since v3 is built with its assertions on.
 * Compiled once per v3 adapter (V3_SUPPORT names its support header) as
 * box2d3_range_sweep_test and box2d32_range_sweep_test.
 * Once built satisfied and moved through v3's own API, which measures what the engine holds;
 * once built by the adapter from the file that places body B there, which must hold whatever
 * it builds (finite, within 1e4 m, no assertion, for 600 steps) and report what it leaves out
 * as beyond-box2d-range. v3 has no pulley joint. Prints the table the docs show.
 */
#include V3_SUPPORT
#include "range_sweep.h"

static bool world_holds(const v3_world* w) {
    for (int i = 0; i < SWEEP_STEPS; ++i) {
        step_v3(w, 1);
        for (uint32_t k = 0; k < w->built->body_count; ++k) {
            b2BodyId body = w->built->bodies[k];
            if (B2_IS_NULL(body)) {
                continue;
            }
            b2Vec2 p = v3_position(body);
            b2Rot q = b2Body_GetRotation(body);
            if (!(fabsf(p.x) < SWEEP_BOUND && fabsf(p.y) < SWEEP_BOUND && isfinite(q.c) &&
                  isfinite(q.s))) {
                return false;
            }
        }
    }
    return true;
}

static bool refused(const v3_built* built) {
    for (uint32_t i = 0; i < built->reports.count; ++i) {
        const v3_report* r = &built->reports.items[i];
        if (r->code == B2S_CODE_BEYOND_BOX2D_RANGE && strcmp(r->object, "joint") == 0) {
            return true;
        }
    }
    return false;
}

/* In a child: the case built satisfied, body B moved by b2Body_SetTransform. */
static void run_moved(const sweep_case* c) {
    static char xml[4096];
    sweep_scene_xml(c, 0.0f, 0.0f, xml, sizeof xml);
    b2s_scene* scene = load_text(xml);
    if (scene == NULL) {
        _exit(SWEEP_NOT_LOADED);
    }
    v3_world w = build_v3(scene);
    if (refused(w.built)) {
        _exit(SWEEP_NOT_MEASURED);
    }
    float dx, dy;
    sweep_displacement(c, &dx, &dy);
    b2BodyId b = w.built->bodies[SWEEP_BODY_B];
    b2Vec2 p = v3_position(b);
    b2Body_SetTransform(b, v3_pos((b2Vec2){p.x + dx, p.y + dy}), b2Body_GetRotation(b));
    _exit(world_holds(&w) ? SWEEP_HELD : SWEEP_LOST);
}

/* In a child: the case as the file gives it, through the adapter. */
static void run_built(const sweep_case* c) {
    static char xml[4096];
    float dx, dy;
    sweep_displacement(c, &dx, &dy);
    sweep_scene_xml(c, dx, dy, xml, sizeof xml);
    b2s_scene* scene = load_text(xml);
    if (scene == NULL) {
        _exit(SWEEP_NOT_LOADED);
    }
    v3_world w = build_v3(scene);
    if (refused(w.built)) {
        _exit(SWEEP_REFUSED);
    }
    _exit(world_holds(&w) ? SWEEP_HELD : SWEEP_LOST);
}

/* A line or wheel joint (alone or among four) to a static body A: v3 does not hold body B
 * far out on it even satisfied (measured with the lever bound lifted), so the adapter
 * refuses it past the range's max_lever_fixed_wheel radii of gyration. */
static bool wheel_on_static(const sweep_case* c) {
    bool wheel = c->joint == SWEEP_LINE || c->joint == SWEEP_WHEEL ||
                 c->joint == SWEEP_FOUR_ON_ONE_PAIR;
    return wheel && c->body_a == SWEEP_A_STATIC;
}

static int every_built_world_holds_and_every_satisfied_one_is_built(void) {
    bool has[SWEEP_JOINT_COUNT];
    for (int j = 0; j < SWEEP_JOINT_COUNT; ++j) {
        has[j] = j != SWEEP_PULLEY;
    }
    ENSURE_EQ(sweep_engine(V3_MINOR == 1 ? "Box2D v3.1" : "Box2D v3.2", run_moved, run_built, has, wheel_on_static), 0);
    return 0;
}

int main(void) {
    return RUN_TEST(every_built_world_holds_and_every_satisfied_one_is_built);
}
