/*
 * V3_ADAPTER(build_world) takes time linear in shapes, bodies and joints: each scene of
 * growth_scenes.h is built at 2 000 and 32 000 objects, the fastest of several runs of each
 * counts, and the larger must take less than 64 times as long (a linear build takes 16,
 * a quadratic one 256).
 * The adapter creates a body's shapes without updating its mass and has v3 compute it once;
 * the one-body scene checks that mass, bit for bit, against v3's sum over those shapes.
 *
 * V3_ADAPTER(capture_world) is held to the same bound: each scene is built once at each size
 * and its capture timed, so that a host saving a large level does not wait on it. Bodies and
 * joints grow together in one of the scenes, since a capture looks up both bodies of every
 * joint; chains are captured once each however many segments a body holds. Each capture is
 * checked against the world it came from: its counts, and the values of a few objects.
 */
#include V3_SUPPORT
#include "growth_scenes.h"

#include <float.h>

/* What a build of one size must have made. */
typedef bool built_check(const v3_built* built, uint32_t count);

/* What b2Body_ApplyMassFromShapes makes of the one-body scene's shapes, summed as it sums
 * them (its shape list is newest first): mass, and centre in body coordinates. */
static b2MassData by_hand(uint32_t count) {
    b2MassData sum = {0.0f, {0.0f, 0.0f}, 0.0f};
    for (uint32_t i = count; i-- > 0;) {
        uint32_t k = i % GROWTH_CIRCLES;
        b2Circle circle = {{growth_circle_x(k), growth_circle_y(k)}, 0.25f};
        b2MassData mass = b2ComputeCircleMass(&circle, growth_density(i));
        sum.mass += mass.mass;
        sum.center = b2MulAdd(sum.center, mass.mass, mass.center);
    }
    sum.center = b2MulSV(1.0f / sum.mass, sum.center);
    return sum;
}

static bool same_float(float a, float b) {
    return memcmp(&a, &b, sizeof a) == 0;
}

static bool one_body_built(const v3_built* built, uint32_t count) {
    if (built->body_count != 1 || built->fixture_count != count) {
        return false;
    }
    for (uint32_t i = 0; i < count; ++i) {
        if (B2_IS_NULL(built->shapes[i])) {
            return false;
        }
    }
    b2MassData expected = by_hand(count);
    b2Vec2 center = v3_local_center(built->bodies[0]);
    return b2Body_GetShapeCount(built->bodies[0]) == (int)count &&
           same_float(b2Body_GetMass(built->bodies[0]), expected.mass) &&
           same_float(center.x, expected.center.x) && same_float(center.y, expected.center.y);
}

static bool bodies_built(const v3_built* built, uint32_t count) {
    if (built->body_count != count) {
        return false;
    }
    for (uint32_t i = 0; i < count; ++i) {
        if (B2_IS_NULL(built->bodies[i]) || !(b2Body_GetMass(built->bodies[i]) > 0.0f)) {
            return false;
        }
    }
    return true;
}

static bool joints_built(const v3_built* built, uint32_t count) {
    if (built->joint_count != count) {
        return false;
    }
    for (uint32_t i = 0; i < count; ++i) {
        if (B2_IS_NULL(built->joints[i])) {
            return false;
        }
    }
    return b2Joint_GetType(built->joints[1]) == b2_distanceJoint &&
           b2DistanceJoint_IsSpringEnabled(built->joints[1]);
}

/* The fastest of GROWTH_RUNS builds of `scene`, each into a new world, or a negative time
 * when one of them is not as `check` expects. */
static double fastest_build(const b2s_scene* scene, uint32_t count, built_check* check) {
    double fastest = DBL_MAX;
    for (int run = 0; run < GROWTH_RUNS; ++run) {
        b2WorldDef def = V3_ADAPTER(world_def)(scene, (b2Vec2){0.0f, -10.0f});
        b2WorldId world = b2CreateWorld(&def);
        double start = growth_clock();
        v3_built* built = V3_ADAPTER(build_world)(scene, world);
        double time = growth_clock() - start;
        bool expected = built != NULL && built->reports.count == 0 && check(built, count);
        if (built != NULL) {
            print_reports(&built->reports);
        }
        V3_ADAPTER(built_free)(built);
        b2DestroyWorld(world);
        if (!expected) {
            fprintf(stderr, "the build of %u is not as expected\n", (unsigned)count);
            return -1.0;
        }
        fastest = time < fastest ? time : fastest;
    }
    return fastest;
}

/* ---- capture */

/* What the capture of a world built from a scene of one size must hold. */
typedef bool captured_check(const b2s_scene_view* view, const v3_built* built,
                            uint32_t count);

static bool same_vec(b2s_vec2 a, b2Vec2 b) {
    return same_float(a.x, b.x) && same_float(a.y, b.y);
}

/* The objects whose values a check compares: both ends and two in between. */
#define SAMPLES 4

static uint32_t sample(uint32_t k, uint32_t count) {
    const uint32_t at[SAMPLES] = {0, 1, count / 2, count - 1};
    return at[k];
}

/* The captured body's `k`-th fixture. */
static const b2s_fixture* fixture_of(const b2s_scene_view* view, const b2s_body* body,
                                     uint32_t k) {
    return &view->fixtures[view->fixture_ids[body->fixtures.first + k]];
}

static bool one_body_captured(const b2s_scene_view* view, const v3_built* built,
                              uint32_t count) {
    if (view->body_count != 1 || view->fixture_count != count || view->shape_count != count ||
        view->joint_count != 0 || view->bodies[0].fixtures.count != count) {
        return false;
    }
    const b2s_body* body = &view->bodies[0];
    b2BodyId id = built->bodies[0];
    /* the mass v3 computes from the shapes is no MassData of the file's */
    if (!same_vec(body->position, v3_position(id)) ||
        !same_float(body->angular_velocity, b2Body_GetAngularVelocity(id)) ||
        body->mass_data.mass_given) {
        return false;
    }
    for (uint32_t k = 0; k < SAMPLES; ++k) {
        uint32_t i = sample(k, count);
        const b2s_fixture* fixture = fixture_of(view, body, i);
        const b2s_shape* shape = &view->shapes[fixture->shape];
        b2Circle circle = b2Shape_GetCircle(built->shapes[i]);
        if (shape->kind != B2S_SHAPE_KIND_CIRCLE || !same_float(shape->radius, circle.radius) ||
            !same_vec(shape->position, circle.center) ||
            !same_float(fixture->density, b2Shape_GetDensity(built->shapes[i]))) {
            return false;
        }
    }
    return true;
}

static bool bodies_captured(const b2s_scene_view* view, const v3_built* built,
                            uint32_t count) {
    if (view->body_count != count || view->fixture_count != count ||
        view->shape_count != count || view->joint_count != 0) {
        return false;
    }
    for (uint32_t k = 0; k < SAMPLES; ++k) {
        uint32_t i = sample(k, count);
        const b2s_body* body = &view->bodies[i];
        if (body->kind != B2S_BODY_KIND_DYNAMIC || body->fixtures.count != 1 ||
            !same_vec(body->position, v3_position(built->bodies[i]))) {
            return false;
        }
        const b2s_fixture* fixture = fixture_of(view, body, 0);
        const b2s_shape* shape = &view->shapes[fixture->shape];
        b2Polygon polygon = b2Shape_GetPolygon(built->shapes[i]);
        if (shape->kind != B2S_SHAPE_KIND_POLYGON || shape->vertices.count != 4 ||
            !same_vec(view->vertices[shape->vertices.first + 2], polygon.vertices[2]) ||
            !same_float(fixture->density, b2Shape_GetDensity(built->shapes[i]))) {
            return false;
        }
    }
    return true;
}

/* The index of v3 body `id` among the built bodies, or B2S_NONE. */
static uint32_t built_index(const v3_built* built, b2BodyId id) {
    for (uint32_t i = 0; i < built->body_count; ++i) {
        if (B2_ID_EQUALS(built->bodies[i], id)) {
            return i;
        }
    }
    return B2S_NONE;
}

static uint32_t kind_of(b2JointId id) {
    switch (b2Joint_GetType(id)) {
    case b2_revoluteJoint: return B2S_JOINT_KIND_REVOLUTE;
    case b2_distanceJoint: return B2S_JOINT_KIND_DISTANCE;
    case b2_weldJoint: return B2S_JOINT_KIND_WELD;
    default: return B2S_NONE;
    }
}

static bool joints_captured(const b2s_scene_view* view, const v3_built* built,
                            uint32_t count) {
    if (view->joint_count != count || view->body_count != built->body_count) {
        return false;
    }
    for (uint32_t k = 0; k < SAMPLES; ++k) {
        uint32_t i = sample(k, count);
        const b2s_joint* joint = &view->joints[i];
        b2JointId id = built->joints[i];
        if (joint->kind != kind_of(id) ||
            joint->body_a != built_index(built, b2Joint_GetBodyA(id)) ||
            joint->body_b != built_index(built, b2Joint_GetBodyB(id)) ||
            !same_vec(joint->local_anchor_a, v3_local_anchor_a(id)) ||
            !same_vec(joint->local_anchor_b, v3_local_anchor_b(id))) {
            return false;
        }
    }
    return true;
}

static bool chains_built(const v3_built* built, uint32_t count) {
    if (built->body_count != 1 || built->fixture_count != count) {
        return false;
    }
    for (uint32_t i = 0; i < count; ++i) {
        if (v3_chain_segments(built, i, NULL, 4) != 4) {
            return false;
        }
    }
    return true;
}

static bool chains_captured(const b2s_scene_view* view, const v3_built* built,
                            uint32_t count) {
    if (view->body_count != 1 || view->shape_count != count || view->fixture_count != count ||
        view->bodies[0].fixtures.count != count) {
        return false;
    }
    for (uint32_t k = 0; k < SAMPLES; ++k) {
        uint32_t i = sample(k, count);
        const b2s_shape* shape = &view->shapes[fixture_of(view, &view->bodies[0], i)->shape];
        b2ShapeId segments[4];
        if (v3_chain_segments(built, i, segments, 4) != 4 || shape->kind != B2S_SHAPE_KIND_CHAIN ||
            !shape->is_loop || shape->vertices.count != 4) {
            return false;
        }
        for (uint32_t v = 0; v < 4; ++v) {
            b2Vec2 point = b2Shape_GetChainSegment(segments[v]).segment.point1;
            if (!same_vec(view->vertices[shape->vertices.first + v], point)) {
                return false;
            }
        }
    }
    return true;
}

/* The fastest of GROWTH_RUNS captures of every body of `scene` built (once, as `built`
 * expects) into a new world, given the level when `of_the_level` (each record's scene
 * record found from what the build made), or a negative time when the build or a capture
 * is not as expected. */
static double fastest_capture(const b2s_scene* scene, uint32_t count, built_check* built,
                              captured_check* captured, bool of_the_level) {
    v3_world world = build_v3(scene);
    if (world.built == NULL || world.built->reports.count != 0 ||
        !built(world.built, count)) {
        fprintf(stderr, "the build of %u is not as expected\n", (unsigned)count);
        if (world.built != NULL) {
            print_reports(&world.built->reports);
        }
        free_v3(&world);
        return -1.0;
    }
    double fastest = DBL_MAX;
    for (int run = 0; run < GROWTH_RUNS && fastest >= 0.0; ++run) {
        b2s_scene* capture = NULL;
        v3_reports reports;
        b2s_error error;
        double start = growth_clock();
        b2s_code code =
            of_the_level
                ? V3_ADAPTER(capture_built)(world.id, world.built, scene, &capture, &reports,
                                            &error)
                : V3_ADAPTER(capture_world)(world.id, world.built->bodies,
                                            world.built->body_count, &capture, &reports, &error);
        double time = growth_clock() - start;
        if (code != B2S_CODE_OK) {
            fprintf(stderr, "the capture of %u failed: %s\n", (unsigned)count, error.message);
            fastest = -1.0;
            continue;
        }
        print_reports(&reports);
        if (reports.count != 0 || !captured(b2s_scene_get_view(capture), world.built, count)) {
            fprintf(stderr, "the capture of %u is not as expected\n", (unsigned)count);
            fastest = -1.0;
        } else {
            fastest = time < fastest ? time : fastest;
        }
        V3_ADAPTER(reports_free)(&reports);
        b2s_scene_free(capture);
    }
    free_v3(&world);
    return fastest;
}

/* ---- both */

/* One scene at both sizes: what is timed and what each size must give. */
typedef struct growth_case {
    const char* what;
    b2s_scene* (*make)(uint32_t count);
    built_check* built;
    captured_check* captured; /* NULL: the build is timed; else the capture */
    bool of_the_level;        /* the capture is given the scene and what the build made */
} growth_case;

/* Times `test`'s scene at both sizes: whether every run is as expected and the larger
 * takes less than GROWTH_MAX_RATIO times as long. */
static bool grows_linearly(const growth_case* test) {
    double times[2] = {0.0, 0.0};
    const uint32_t sizes[2] = {GROWTH_SMALL, GROWTH_LARGE};
    for (int i = 0; i < 2; ++i) {
        b2s_scene* scene = test->make(sizes[i]);
        if (scene == NULL) {
            return false;
        }
        times[i] = test->captured == NULL
                       ? fastest_build(scene, sizes[i], test->built)
                       : fastest_capture(scene, sizes[i], test->built, test->captured,
                                         test->of_the_level);
        b2s_scene_free(scene);
        if (times[i] < 0.0) {
            return false;
        }
    }
    return growth_linear(test->what, times[0], times[1]);
}

static int shapes_on_one_body(void) {
    const growth_case test = {"shapes on one body", growth_one_body, one_body_built, NULL, false};
    ENSURE(grows_linearly(&test));
    return 0;
}

static int many_bodies(void) {
    const growth_case test = {"bodies", growth_many_bodies, bodies_built, NULL, false};
    ENSURE(grows_linearly(&test));
    return 0;
}

static int many_joints(void) {
    const growth_case test = {"joints", growth_many_joints, joints_built, NULL, false};
    ENSURE(grows_linearly(&test));
    return 0;
}

static int capture_of_shapes_on_one_body(void) {
    const growth_case test = {"capture: shapes on one body", growth_one_body, one_body_built,
                              one_body_captured, false};
    ENSURE(grows_linearly(&test));
    return 0;
}

static int capture_of_bodies(void) {
    const growth_case test = {"capture: bodies", growth_many_bodies, bodies_built,
                              bodies_captured, false};
    ENSURE(grows_linearly(&test));
    return 0;
}

static int capture_of_joints(void) {
    const growth_case test = {"capture: joints", growth_many_joints, joints_built,
                              joints_captured, false};
    ENSURE(grows_linearly(&test));
    return 0;
}

static int capture_of_joints_among_as_many_bodies(void) {
    const growth_case test = {"capture: joints among as many bodies", growth_joined_bodies,
                              joints_built, joints_captured, false};
    ENSURE(grows_linearly(&test));
    return 0;
}

static int capture_of_chains_on_one_body(void) {
    const growth_case test = {"capture: chains on one body", growth_chains, chains_built,
                              chains_captured, false};
    ENSURE(grows_linearly(&test));
    return 0;
}

/* A capture of a built level finds the fixture slot of each shape once: a body of many
 * shapes, and one of many chains, take no walk over the body's slots a shape. */
static int capture_of_a_built_level(void) {
    const growth_case shapes = {"capture of the level: shapes on one body", growth_one_body,
                                one_body_built, one_body_captured, true};
    ENSURE(grows_linearly(&shapes));
    const growth_case chains = {"capture of the level: chains on one body", growth_chains,
                                chains_built, chains_captured, true};
    ENSURE(grows_linearly(&chains));
    return 0;
}

int main(void) {
    growth_keep_memory_in_the_heap();
    int failed = 0;
    failed += RUN_TEST(shapes_on_one_body);
    failed += RUN_TEST(many_bodies);
    failed += RUN_TEST(many_joints);
    failed += RUN_TEST(capture_of_shapes_on_one_body);
    failed += RUN_TEST(capture_of_bodies);
    failed += RUN_TEST(capture_of_joints);
    failed += RUN_TEST(capture_of_joints_among_as_many_bodies);
    failed += RUN_TEST(capture_of_chains_on_one_body);
    failed += RUN_TEST(capture_of_a_built_level);
    return failed;
}
