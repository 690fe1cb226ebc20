// Nothing Box2D 2.4 cannot take, on the very levels the v3 stress tests step (stress_levels.h:
// the same stream, every other level at a placement of its own, turned and moved by up to
// 100 m): each is built through the adapter into Box2D 2.4, whose assertions Debian's build
// keeps, and stepped 600 times; every body stays finite and nothing aborts. With
// box2d3_stress_test and box2d32_stress_test, every level is stepped in all three engines.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cmath>
#include <cstdio>

#include "stress_levels.h"
#include "test_macros.h"

static const int kLevels = 2000;
static const int kSteps = 600;

static bool bodies_finite(const box2scene::Built& built) {
    for (const b2Body* body : built.bodies) {
        if (body == nullptr) {
            continue;
        }
        b2Vec2 p = body->GetPosition(), v = body->GetLinearVelocity();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(body->GetAngle()) ||
            !std::isfinite(v.x) || !std::isfinite(v.y) ||
            !std::isfinite(body->GetAngularVelocity())) {
            return false;
        }
    }
    return true;
}

static int generated_levels_stay_finite_in_box2d_24() {
    int levels = 0, bodies = 0, joints = 0;
    for (int attempt = 0; levels < kLevels && attempt < 4 * kLevels; ++attempt) {
        b2s_scene* scene = generated_level();
        if (scene == nullptr) {
            continue;
        }
        levels += 1;
        // Drawn whatever the level, as the v3 tests draw it, so that the streams agree.
        float turn = uniform(-3.14159265f, 3.14159265f);
        b2Transform placement;
        placement.p.Set(uniform(-100.0f, 100.0f), uniform(-100.0f, 100.0f));
        placement.q.s = std::sin(turn);
        placement.q.c = std::cos(turn);
        b2World world(box2scene::scene_gravity(scene, b2Vec2(0.0f, -10.0f)));
        box2scene::Built built = levels % 2 == 0
                                     ? box2scene::build_world_at(scene, world, placement)
                                     : box2scene::build_world(scene, world);
        for (const b2Body* body : built.bodies) {
            bodies += body != nullptr;
        }
        for (const b2Joint* joint : built.joints) {
            joints += joint != nullptr;
        }
        for (int step = 0; step <= kSteps; ++step) {
            if (!bodies_finite(built)) {
                char* text = nullptr;
                b2s_write_memory(scene, nullptr, &text, nullptr, nullptr);
                std::fprintf(stderr, "level %d is not finite after %d steps:\n%s\n", levels,
                             step, text != nullptr ? text : "(not written)");
                b2s_text_free(text);
                return 1;
            }
            if (step < kSteps) {
                world.Step(1.0f / 60.0f, 8, 3);
            }
        }
        b2s_scene_free(scene);
    }
    std::printf("%d levels: %d bodies and %d joints built in Box2D 2.4\n", levels, bodies, joints);
    ENSURE_EQ(levels, kLevels);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(generated_levels_stay_finite_in_box2d_24);
    return failed;
}
