// build_world takes time linear in fixtures, bodies and joints: each scene of
// growth_scenes.h is built at 2 000 and 32 000 objects, the fastest of several runs of each
// counts, and the larger must take less than 64 times as long (a linear build takes 16,
// a quadratic one 256).
// Box2D 2.4's CreateFixture alone would recompute a body's mass from all its fixtures each
// time, so the one-body scene also checks that the mass the adapter has Box2D compute once
// is, bit for bit, what Box2D's ResetMassData gives over those fixtures. capture_world of
// that body must grow linearly too, and so must capture_world of a built level.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <algorithm>
#include <cfloat>
#include <functional>
#include <memory>

#include "growth_scenes.h"
#include "test_macros.h"
#include "test_worlds.hpp"

/// The fastest of GROWTH_RUNS builds of `scene`, each into a new world; `check` sees the
/// last one.
static double fastest_build(const b2s_scene* scene,
                            const std::function<bool(const box2scene::Built&)>& check,
                            bool& checked) {
    double fastest = DBL_MAX;
    checked = true;
    for (int run = 0; run < GROWTH_RUNS; ++run) {
        auto world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
        double start = growth_clock();
        box2scene::Built built = box2scene::build_world(scene, *world);
        fastest = std::min(fastest, growth_clock() - start);
        checked = checked && built.reports.empty() && check(built);
    }
    return fastest;
}

/// Builds `make`'s scene at both sizes; false unless every build passes `check` and the
/// larger takes less than GROWTH_MAX_RATIO times as long.
static bool grows_linearly(const char* what, b2s_scene* (*make)(uint32_t),
                           const std::function<bool(const box2scene::Built&, uint32_t)>& check) {
    double times[2] = {0.0, 0.0};
    const uint32_t sizes[2] = {GROWTH_SMALL, GROWTH_LARGE};
    for (int i = 0; i < 2; ++i) {
        ScenePtr scene(make(sizes[i]));
        if (scene == nullptr) {
            return false;
        }
        bool checked = false;
        times[i] = fastest_build(
            scene.get(), [&](const box2scene::Built& built) { return check(built, sizes[i]); },
            checked);
        if (!checked) {
            std::fprintf(stderr, "%s: the build of %u is not as expected\n", what, sizes[i]);
            return false;
        }
    }
    return growth_linear(what, times[0], times[1]);
}

/// What b2Body::ResetMassData makes of the one-body scene's fixtures, summed as it sums
/// them (its fixture list is newest first): mass, and centre in body coordinates.
static b2MassData by_hand(uint32_t count) {
    b2MassData sum{0.0f, b2Vec2_zero, 0.0f};
    for (uint32_t i = count; i-- > 0;) {
        b2CircleShape circle;
        circle.m_radius = 0.25f;
        circle.m_p.Set(growth_circle_x(i % GROWTH_CIRCLES), growth_circle_y(i % GROWTH_CIRCLES));
        b2MassData mass;
        circle.ComputeMass(&mass, growth_density(i));
        sum.mass += mass.mass;
        sum.center += mass.mass * mass.center;
    }
    sum.center *= 1.0f / sum.mass;
    return sum;
}

static int fixtures_on_one_body() {
    ENSURE(grows_linearly("fixtures on one body", growth_one_body,
                          [](const box2scene::Built& built, uint32_t count) {
        const b2Body* body = built.bodies.at(0);
        b2MassData expected = by_hand(count);
        // One mass update moved the centre of mass once: the velocity of the origin,
        // (1, 0), plus w x (the centre's shift), in one rounding.
        b2Vec2 shift = b2Mul(body->GetTransform(), expected.center) - body->GetPosition();
        b2Vec2 velocity = b2Vec2(1.0f, 0.0f) + b2Cross(2.0f, shift);
        return body->GetFixtureList() != nullptr &&
               std::all_of(built.fixtures.begin(), built.fixtures.end(),
                           [](const b2Fixture* f) { return f != nullptr; }) &&
               same_bits(body->GetMass(), expected.mass) &&
               same_bits(body->GetLocalCenter(), expected.center) &&
               same_bits(body->GetLinearVelocity(), velocity);
    }));
    return 0;
}

/// capture_world of the one-body world likewise: its equal fixtures become one scene fixture
/// each, found by hashing, and the velocity it writes is inverted through one mass update.
static int capture_of_one_body() {
    double times[2] = {0.0, 0.0};
    const uint32_t sizes[2] = {GROWTH_SMALL, GROWTH_LARGE};
    for (int i = 0; i < 2; ++i) {
        ScenePtr scene(growth_one_body(sizes[i]));
        ENSURE(scene != nullptr);
        b2World world(b2Vec2(0.0f, -10.0f));
        ENSURE(box2scene::build_world(scene.get(), world).reports.empty());
        times[i] = DBL_MAX;
        for (int run = 0; run < GROWTH_RUNS; ++run) {
            std::vector<box2scene::Report> reports;
            double start = growth_clock();
            ScenePtr captured(box2scene::capture_world(world, reports));
            times[i] = std::min(times[i], growth_clock() - start);
            ENSURE(captured != nullptr && reports.empty());
            const b2s_scene_view& view = view_of(captured);
            ENSURE_EQ(view.body_count, 1);
            ENSURE_EQ(view.fixture_id_count, sizes[i]);
            ENSURE_EQ(view.fixture_count, GROWTH_CIRCLES * 3);
            ENSURE_FLOAT(view.bodies[0].linear_velocity.x, 1.0f);
            ENSURE_FLOAT(view.bodies[0].linear_velocity.y, 0.0f);
        }
    }
    ENSURE(growth_linear("capture of fixtures on one body", times[0], times[1]));
    return 0;
}

/// capture_world of a built level (given the scene and what the build made, so that every
/// record keeps its place and names): each engine object's scene record is found by hashing,
/// not by a walk over what the build made.
static int capture_of_a_built_level() {
    for (b2s_scene* (*make)(uint32_t) : {growth_many_bodies, growth_many_joints}) {
        double times[2] = {0.0, 0.0};
        const uint32_t sizes[2] = {GROWTH_SMALL, GROWTH_LARGE};
        for (int i = 0; i < 2; ++i) {
            ScenePtr scene(make(sizes[i]));
            ENSURE(scene != nullptr);
            b2World world(b2Vec2(0.0f, -10.0f));
            box2scene::Built built = box2scene::build_world(scene.get(), world);
            ENSURE(built.reports.empty());
            times[i] = DBL_MAX;
            for (int run = 0; run < GROWTH_RUNS; ++run) {
                std::vector<box2scene::Report> reports;
                double start = growth_clock();
                ScenePtr captured(box2scene::capture_world(world, built, scene.get(), reports));
                times[i] = std::min(times[i], growth_clock() - start);
                ENSURE(captured != nullptr && reports.empty());
                const b2s_scene_view& view = view_of(captured);
                const b2s_scene_view& level = view_of(scene);
                ENSURE_EQ(view.body_count, level.body_count);
                ENSURE_EQ(view.joint_count, level.joint_count);
            }
        }
        ENSURE(growth_linear("capture of a built level", times[0], times[1]));
    }
    return 0;
}

static int many_bodies() {
    ENSURE(grows_linearly("bodies", growth_many_bodies,
                          [](const box2scene::Built& built, uint32_t count) {
        return built.bodies.size() == count &&
               std::all_of(built.bodies.begin(), built.bodies.end(), [](const b2Body* b) {
                   return b != nullptr && b->GetMass() > 0.0f;
               });
    }));
    return 0;
}

static int many_joints() {
    ENSURE(grows_linearly("joints", growth_many_joints,
                          [](const box2scene::Built& built, uint32_t count) {
        return built.joints.size() == count &&
               std::all_of(built.joints.begin(), built.joints.end(),
                           [](const b2Joint* j) { return j != nullptr; }) &&
               built.joints[1]->GetType() == e_distanceJoint &&
               static_cast<const b2DistanceJoint*>(built.joints[1])->GetStiffness() > 0.0f;
    }));
    return 0;
}

int main() {
    growth_keep_memory_in_the_heap();
    int failed = 0;
    failed += RUN_TEST(fixtures_on_one_body);
    failed += RUN_TEST(capture_of_one_body);
    failed += RUN_TEST(capture_of_a_built_level);
    failed += RUN_TEST(many_bodies);
    failed += RUN_TEST(many_joints);
    return failed;
}
