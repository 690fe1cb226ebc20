/*
 * b2s_box2d3_build_world takes time linear in shapes, bodies and joints: each scene of
 * growth_scenes.h is built at 4 000 and 16 000 objects, the fastest of several runs of each
 * counts, and the larger must take less than 8 times as long (a quadratic build takes 16).
 * The adapter creates a body's shapes without updating its mass and has v3 compute it once;
 * the one-body scene checks that mass, bit for bit, against v3's sum over those shapes.
 */
#include "box2d3_support.h"
#include "growth_scenes.h"

#include <float.h>

/* What a build of one size must have made. */
typedef bool built_check(const b2s_box2d3_built* built, uint32_t count);

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

static bool one_body_built(const b2s_box2d3_built* built, uint32_t count) {
    if (built->body_count != 1 || built->fixture_count != count) {
        return false;
    }
    for (uint32_t i = 0; i < count; ++i) {
        if (B2_IS_NULL(built->shapes[i])) {
            return false;
        }
    }
    b2MassData expected = by_hand(count);
    b2Vec2 center = b2Body_GetLocalCenterOfMass(built->bodies[0]);
    return b2Body_GetShapeCount(built->bodies[0]) == (int)count &&
           same_float(b2Body_GetMass(built->bodies[0]), expected.mass) &&
           same_float(center.x, expected.center.x) && same_float(center.y, expected.center.y);
}

static bool bodies_built(const b2s_box2d3_built* built, uint32_t count) {
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

static bool joints_built(const b2s_box2d3_built* built, uint32_t count) {
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
        b2WorldDef def = b2s_box2d3_world_def(scene, (b2Vec2){0.0f, -10.0f});
        b2WorldId world = b2CreateWorld(&def);
        double start = growth_clock();
        b2s_box2d3_built* built = b2s_box2d3_build_world(scene, world);
        double time = growth_clock() - start;
        bool expected = built != NULL && built->reports.count == 0 && check(built, count);
        if (built != NULL) {
            print_reports(&built->reports);
        }
        b2s_box2d3_built_free(built);
        b2DestroyWorld(world);
        if (!expected) {
            fprintf(stderr, "the build of %u is not as expected\n", (unsigned)count);
            return -1.0;
        }
        fastest = time < fastest ? time : fastest;
    }
    return fastest;
}

/* Builds `make`'s scene at both sizes: whether every build is as `check` expects and the
 * larger takes less than GROWTH_MAX_RATIO times as long. */
static bool grows_linearly(const char* what, b2s_scene* (*make)(uint32_t), built_check* check) {
    double times[2] = {0.0, 0.0};
    const uint32_t sizes[2] = {GROWTH_SMALL, GROWTH_LARGE};
    for (int i = 0; i < 2; ++i) {
        b2s_scene* scene = make(sizes[i]);
        if (scene == NULL) {
            return false;
        }
        times[i] = fastest_build(scene, sizes[i], check);
        b2s_scene_free(scene);
        if (times[i] < 0.0) {
            return false;
        }
    }
    return growth_linear(what, times[0], times[1]);
}

static int shapes_on_one_body(void) {
    ENSURE(grows_linearly("shapes on one body", growth_one_body, one_body_built));
    return 0;
}

static int many_bodies(void) {
    ENSURE(grows_linearly("bodies", growth_many_bodies, bodies_built));
    return 0;
}

static int many_joints(void) {
    ENSURE(grows_linearly("joints", growth_many_joints, joints_built));
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(shapes_on_one_body);
    failed += RUN_TEST(many_bodies);
    failed += RUN_TEST(many_joints);
    return failed;
}
