// The mass the library's Box2D 2.4 plan predicts for every dynamic body is the mass Box2D
// gives it, bit for bit: each real editor file (tests/fixtures/corpus/), each scene of
// fidelity_scenes.h and the stress tests' generated levels (every shape kind, fields up to
// the edges of the working range), built by build_world, every b2Body's GetMassData beside
// its plan body.
// Where the plan sets the mass (the file's MassData), Box2D keeps what it was given: the
// mass and centre; the inertia it gives back is its own sum about the origin.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cstdio>
#include <cstring>

#include "fidelity_scenes.h"
#include "stress_levels.h"
#include "test_macros.h"
#include "test_scenes.hpp"

namespace {

bool same_bits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Every dynamic body of `scene` built by build_world against its plan; counts the bodies
/// compared in `compared`.
int ensure_masses_predicted(const b2s_scene* scene, const char* what, int& compared) {
    b2World world(box2scene::scene_gravity(scene, b2Vec2(0.0f, -10.0f)));
    box2scene::Built built = box2scene::build_world(scene, world);
    b2s_plan_options options{};
    options.engine = B2S_ENGINE_BOX2D24;
    options.placement = b2s_transform{{0.0f, 0.0f}, {1.0f, 0.0f}};
    options.gravity = b2s_vec2{world.GetGravity().x, world.GetGravity().y};
    options.max_linear_speed = 3.402823466e38f;
    b2s_plan* plan = nullptr;
    ENSURE_EQ(b2s_plan_make(scene, &options, &plan, nullptr), B2S_CODE_OK);
    const b2s_plan_view& view = *b2s_plan_get_view(plan);
    int failures = 0;
    for (uint32_t i = 0; i < view.body_count; ++i) {
        const b2s_plan_body& body = view.bodies[i];
        if (body.kind != B2S_BODY_KIND_DYNAMIC) {
            continue;
        }
        b2MassData got;
        built.bodies[body.body]->GetMassData(&got);
        const b2s_plan_mass& predicted = body.mass;
        // SetMassData gives a body a mass of 1 kg for one not above 0
        bool mass = same_bits(got.mass, predicted.mass) ||
                    (body.set_mass && !(predicted.mass > 0.0f) && got.mass == 1.0f);
        bool center = same_bits(got.center.x, predicted.center.x) &&
                      same_bits(got.center.y, predicted.center.y);
        bool inertia = body.set_mass || same_bits(got.I, predicted.inertia);
        if (!mass || !center || !inertia) {
            std::printf("  %s body %u: Box2D %.9g kg at (%.9g, %.9g), %.9g kg m^2; the plan "
                        "%.9g kg at (%.9g, %.9g), %.9g kg m^2\n",
                        what, body.body, got.mass, got.center.x, got.center.y, got.I,
                        predicted.mass, predicted.center.x, predicted.center.y,
                        predicted.inertia);
            ++failures;
        }
        ++compared;
    }
    b2s_plan_free(plan);
    return failures;
}

int corpus_masses_are_box2d_s() {
    const char* files[] = {"tests/fixtures/corpus/renderer-scene-v1.xml",
                           "tests/fixtures/corpus/legacy-unversioned.xml",
                           "tests/fixtures/corpus/revolute-all-fields-v1.xml",
                           "tests/fixtures/corpus/revolute-defaults-omitted-v1.xml"};
    int compared = 0;
    for (const char* file : files) {
        ScenePtr scene = load_project_file(file);
        ENSURE(scene != nullptr);
        ENSURE_EQ(ensure_masses_predicted(scene.get(), file, compared), 0);
    }
    ENSURE(compared >= 20); // the renderer scene alone has a dozen dynamic bodies
    return 0;
}

int fidelity_masses_are_box2d_s() {
    int compared = 0;
    for (size_t i = 0; i < FIDELITY_SCENE_COUNT; ++i) {
        ScenePtr scene = load_text(fidelity_scenes[i].xml);
        ENSURE(scene != nullptr);
        ENSURE_EQ(ensure_masses_predicted(scene.get(), fidelity_scenes[i].name, compared), 0);
    }
    ENSURE(compared >= static_cast<int>(FIDELITY_SCENE_COUNT));
    return 0;
}

int generated_masses_are_box2d_s() {
    int compared = 0;
    for (int level = 0; level < 1000; ++level) {
        b2s_scene* scene = generated_level();
        if (scene == nullptr) {
            continue;
        }
        char what[32];
        std::snprintf(what, sizeof what, "level %d", level);
        int failures = ensure_masses_predicted(scene, what, compared);
        b2s_scene_free(scene);
        ENSURE_EQ(failures, 0);
    }
    ENSURE(compared >= 1000);
    return 0;
}

} // namespace

int main() {
    int failed = 0;
    failed += RUN_TEST(corpus_masses_are_box2d_s);
    failed += RUN_TEST(fidelity_masses_are_box2d_s);
    failed += RUN_TEST(generated_masses_are_box2d_s);
    return failed != 0;
}
