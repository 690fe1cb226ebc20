/*
 * The library's plan for Box2D v3 (b2s_plan_make) against the world the adapter builds in
 * real Box2D v3.1 and v3.2, row by row: every report as the build gives it (code, object,
 * index, name, message), every body created where the plan places it, the mass the plan
 * predicts for each dynamic body equal bit for bit to b2Body_GetMassData of the built body,
 * the velocity it gives after the mass equal to the body's, and the hull of every polygon
 * equal to b2ComputeHull's of the file's vertices. Over every scene file of the project and
 * the editor's corpus, the fidelity scenes and generated stress levels (every other one
 * placed). Compiled once per v3 adapter (V3_SUPPORT names its support header).
 */
#include V3_SUPPORT

#if V3_MINOR == 2
#include <box2d/constants.h>
#endif

#include "fidelity_scenes.h"
#include "stress_levels.h"

#define LEVELS 400

/* What the comparisons covered, printed at the end. */
static struct {
    uint32_t reports, masses, hulls;
} compared;

static bool same_float(float a, float b) {
    return memcmp(&a, &b, sizeof a) == 0;
}

static bool same_vec(b2Vec2 a, b2s_vec2 b) {
    return same_float(a.x, b.x) && same_float(a.y, b.y);
}

static bool same_text(const char* a, const char* b) {
    return (a == NULL && b == NULL) || (a != NULL && b != NULL && strcmp(a, b) == 0);
}

/* The plan for the scene built into `world` at `placement`, as the adapter asks for it. */
static b2s_plan* plan_for(const b2s_scene* scene, b2WorldId world, b2Transform placement) {
    b2s_plan_options options;
    memset(&options, 0, sizeof options);
    options.engine = V3_ENGINE;
    options.placement.p.x = placement.p.x;
    options.placement.p.y = placement.p.y;
    options.placement.q.c = placement.q.c;
    options.placement.q.s = placement.q.s;
    b2Vec2 gravity = b2World_GetGravity(world);
    options.gravity.x = gravity.x;
    options.gravity.y = gravity.y;
    options.max_linear_speed = b2World_GetMaximumLinearSpeed(world);
#if V3_MINOR == 2
    options.name_bytes = B2_NAME_LENGTH;
#endif
    b2s_plan* plan = NULL;
    b2s_error error;
    if (b2s_plan_make(scene, &options, &plan, &error) != B2S_CODE_OK) {
        fprintf(stderr, "b2s_plan_make: %s\n", error.message);
    }
    return plan;
}

static int reports_agree(const b2s_plan_view* plan, const v3_reports* built, const char* what) {
    if (plan->report_count != built->count) {
        fprintf(stderr, "%s: the plan has %u reports, the build %u\n", what,
                (unsigned)plan->report_count, (unsigned)built->count);
        print_reports(built);
        for (uint32_t i = 0; i < plan->report_count; ++i) {
            fprintf(stderr, "  plan: %s %s %u: %s\n", b2s_code_name(plan->reports[i].code),
                    plan->reports[i].object, plan->reports[i].index, plan->reports[i].message);
        }
        return 1;
    }
    for (uint32_t i = 0; i < built->count; ++i) {
        const b2s_plan_report* p = &plan->reports[i];
        const v3_report* b = &built->items[i];
        if (p->code != (uint32_t)b->code || strcmp(p->object, b->object) != 0 ||
            p->index != b->index || !same_text(p->name, b->name) ||
            strcmp(p->message, b->message) != 0) {
            fprintf(stderr, "%s: report %u differs:\n  plan:  %s %s %u: %s\n  build: %s %s %u: %s\n",
                    what, (unsigned)i, b2s_code_name(p->code), p->object, p->index, p->message,
                    b2s_code_name(b->code), b->object, b->index, b->message);
            return 1;
        }
    }
    compared.reports += built->count;
    return 0;
}

static int bodies_agree(const b2s_plan_view* plan, const v3_built* built, const char* what) {
    uint32_t created = 0;
    for (uint32_t i = 0; i < built->body_count; ++i) {
        created += B2_IS_NON_NULL(built->bodies[i]);
    }
    ENSURE_EQ(plan->body_count, created);
    for (uint32_t i = 0; i < plan->body_count; ++i) {
        const b2s_plan_body* p = &plan->bodies[i];
        ENSURE(p->body < built->body_count);
        b2BodyId id = built->bodies[p->body];
        ENSURE(B2_IS_NON_NULL(id));
        ENSURE_EQ((uint32_t)b2Body_GetType(id), p->kind);
        b2Rot q = b2Body_GetRotation(id);
        ENSURE(same_vec(v3_position(id), p->position));
        ENSURE(same_float(q.c, p->rotation.c) && same_float(q.s, p->rotation.s));
        if (p->kind != B2S_BODY_KIND_DYNAMIC) {
            continue;
        }
        b2MassData m = b2Body_GetMassData(id);
        if (!same_float(m.mass, p->mass.mass) || !same_vec(m.center, p->mass.center) ||
            !same_float(m.rotationalInertia, p->mass.inertia)) {
            fprintf(stderr,
                    "%s: body %u: the plan predicts mass %.9g at (%.9g, %.9g), inertia %.9g; "
                    "Box2D holds %.9g at (%.9g, %.9g), inertia %.9g\n",
                    what, (unsigned)p->body, (double)p->mass.mass, (double)p->mass.center.x,
                    (double)p->mass.center.y, (double)p->mass.inertia, (double)m.mass,
                    (double)m.center.x, (double)m.center.y, (double)m.rotationalInertia);
            return 1;
        }
        compared.masses += 1;
        if (p->set_velocity && !same_vec(b2Body_GetLinearVelocity(id), p->velocity_after_mass)) {
            fprintf(stderr, "%s: body %u: the velocity after its mass differs\n", what,
                    (unsigned)p->body);
            return 1;
        }
    }
    uint32_t joints = 0;
    for (uint32_t i = 0; i < built->joint_count; ++i) {
        joints += B2_IS_NON_NULL(built->joints[i]);
    }
    ENSURE_EQ(plan->joint_count, joints);
    for (uint32_t i = 0; i < plan->joint_count; ++i) {
        ENSURE(B2_IS_NON_NULL(built->joints[plan->joints[i].joint]));
    }
    return 0;
}

/* Every polygon's points in the plan are b2ComputeHull's of the file's vertices. */
static int hulls_agree(const b2s_plan_view* plan, const b2s_scene* scene, const char* what) {
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    for (uint32_t i = 0; i < plan->shape_count; ++i) {
        const b2s_plan_shape* s = &plan->shapes[i];
        if (s->kind != B2S_PLAN_SHAPE_KIND_POLYGON) {
            continue;
        }
        const b2s_shape* shape = &view->shapes[s->shape];
        b2Vec2 points[B2_MAX_POLYGON_VERTICES];
        for (uint32_t k = 0; k < shape->vertices.count; ++k) {
            b2s_vec2 v = view->vertices[shape->vertices.first + k];
            points[k] = (b2Vec2){v.x, v.y};
        }
        b2Hull hull = b2ComputeHull(points, (int)shape->vertices.count);
        bool same = (uint32_t)hull.count == s->points.count;
        for (int k = 0; same && k < hull.count; ++k) {
            same = same_vec(hull.points[k], plan->points[s->points.first + (uint32_t)k]);
        }
        if (!same) {
            fprintf(stderr, "%s: shape %u: the plan's hull is not b2ComputeHull's\n", what,
                    (unsigned)s->shape);
            return 1;
        }
        compared.hulls += 1;
    }
    return 0;
}

/* Builds the scene at `placement` and checks its plan against the built world. */
static int plan_agrees(const b2s_scene* scene, b2Transform placement, const char* what) {
    v3_world world = build_v3_at(scene, placement);
    ENSURE(world.built != NULL);
    b2s_plan* plan = plan_for(scene, world.id, placement);
    ENSURE(plan != NULL);
    const b2s_plan_view* view = b2s_plan_get_view(plan);
    int failed = reports_agree(view, &world.built->reports, what);
    failed = failed != 0 ? failed : bodies_agree(view, world.built, what);
    failed = failed != 0 ? failed : hulls_agree(view, scene, what);
    b2s_plan_free(plan);
    free_v3(&world);
    return failed;
}

static int scene_files_plan_as_built(void) {
    char** paths = scene_files();
    int files = 0;
    for (char** path = paths; *path != NULL; ++path) {
        b2s_scene* scene = load_path(*path);
        if (scene == NULL) {
            continue;
        }
        files += 1;
        int failed = plan_agrees(scene, b2Transform_identity, *path);
        b2s_scene_free(scene);
        if (failed != 0) {
            free_paths(paths);
            return failed;
        }
    }
    free_paths(paths);
    ENSURE(files >= 10);
    return 0;
}

static int fidelity_scenes_plan_as_built(void) {
    for (size_t i = 0; i < FIDELITY_SCENE_COUNT; ++i) {
        b2s_scene* scene = load_text(fidelity_scenes[i].xml);
        ENSURE(scene != NULL);
        int failed = plan_agrees(scene, b2Transform_identity, fidelity_scenes[i].name);
        b2s_scene_free(scene);
        if (failed != 0) {
            return failed;
        }
    }
    return 0;
}

static int stress_levels_plan_as_built(void) {
    int levels = 0;
    for (int attempt = 0; levels < LEVELS && attempt < 4 * LEVELS; ++attempt) {
        b2s_scene* scene = generated_level();
        if (scene == NULL) {
            continue;
        }
        levels += 1;
        float turn = uniform(-3.14159265f, 3.14159265f);
        b2Transform placement = {{uniform(-100.0f, 100.0f), uniform(-100.0f, 100.0f)},
                                 {cosf(turn), sinf(turn)}};
        char what[32];
        snprintf(what, sizeof what, "level %d", levels);
        int failed = plan_agrees(scene, levels % 2 == 0 ? placement : b2Transform_identity, what);
        b2s_scene_free(scene);
        if (failed != 0) {
            return failed;
        }
    }
    ENSURE_EQ(levels, LEVELS);
    return 0;
}

/* A placement v3 cannot take: the plan holds only its report, as the build does. */
static int an_unusable_placement_plans_nothing(void) {
    b2s_scene* scene = load_text(fidelity_scenes[0].xml);
    ENSURE(scene != NULL);
    b2Transform placement = {{0.0f, 0.0f}, {2.0f, 0.0f}};
    v3_world world = build_v3_at(scene, placement);
    b2s_plan* plan = plan_for(scene, world.id, placement);
    ENSURE(plan != NULL);
    const b2s_plan_view* view = b2s_plan_get_view(plan);
    ENSURE(!view->placed);
    ENSURE_EQ(view->body_count, 0);
    ENSURE_EQ(view->report_count, 1);
    ENSURE_EQ(view->reports[0].code, B2S_CODE_INVALID_ARGUMENT);
    ENSURE_STR(view->reports[0].object, "world");
    int failed = reports_agree(view, &world.built->reports, "unusable placement");
    b2s_plan_free(plan);
    free_v3(&world);
    b2s_scene_free(scene);
    return failed;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(scene_files_plan_as_built);
    failed += RUN_TEST(fidelity_scenes_plan_as_built);
    failed += RUN_TEST(stress_levels_plan_as_built);
    failed += RUN_TEST(an_unusable_placement_plans_nothing);
    printf("%u reports, %u dynamic bodies' masses and %u hulls compared\n",
           (unsigned)compared.reports, (unsigned)compared.masses, (unsigned)compared.hulls);
    return failed;
}
