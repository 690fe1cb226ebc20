// Box2D 2.4 against Box2D v3 on the same calm scenes (fidelity_scenes.h): each built by its
// adapter and stepped for 1 s; every body must end within kMetres and kRadians of where the
// other engine puts it, but for a body a report of either adapter names and for the scenes
// whose engines differ by design (docs/box2d.md says why): v3 has no pulley and no gear
// joint, and applies a motor joint's correction once per substep where 2.4 applies it once
// per step.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cmath>
#include <cstring>
#include <set>

#include "engines_v3_part.h"
#include "fidelity_scenes.h"
#include "test_macros.h"
#include "test_scenes.hpp"
#include "test_worlds.hpp"

// Joints alone agree to a millimetre; bodies in contact to a few centimetres, since v3's
// soft contacts (docs/box2d.md) settle and roll otherwise than 2.4's.
static const double kMetres = 0.1;
static const double kRadians = 0.15;

static bool differs_by_design(const char* scene) {
    for (const char* name : {"pulley", "gear", "motor"}) {
        if (std::strcmp(scene, name) == 0) {
            return true;
        }
    }
    return false;
}

static bool named_in_24(const World& w, uint32_t body) {
    const b2s_scene_view& view = view_of(w.scene);
    for (const box2scene::Report& r : w.built.reports) {
        if ((std::strcmp(r.object, "body") == 0 && r.index == body) ||
            (std::strcmp(r.object, "joint") == 0 && r.index < view.joint_count &&
             (view.joints[r.index].body_a == body || view.joints[r.index].body_b == body))) {
            return true;
        }
    }
    return false;
}

static int engines_agree_after_one_second(const fidelity_scene& scene, double* worst) {
    World w(scene.xml);
    ENSURE(w.scene != nullptr);
    step_for(w.world, 60);
    float v3[3 * 32];
    unsigned char named[32];
    int count = v3_bodies_after(scene.xml, 60, v3, named, 32);
    ENSURE_EQ(count, static_cast<long long>(w.built.bodies.size()));
    for (int i = 0; i < count; ++i) {
        if (named[i] || named_in_24(w, static_cast<uint32_t>(i))) {
            continue;
        }
        b2Vec2 p = w.body(i)->GetPosition();
        double metres = std::hypot(p.x - v3[3 * i], p.y - v3[3 * i + 1]);
        double radians = std::fabs(std::remainder(w.body(i)->GetAngle() - v3[3 * i + 2],
                                                  2.0 * M_PI));
        *worst = std::max(*worst, metres);
        if (!(metres <= kMetres && radians <= kRadians)) {
            std::fprintf(stderr,
                         "%s body %d: 2.4 at (%.4f, %.4f) %.4f rad, v3 at (%.4f, %.4f) %.4f rad\n",
                         scene.name, i, p.x, p.y, w.body(i)->GetAngle(), v3[3 * i],
                         v3[3 * i + 1], v3[3 * i + 2]);
            return 1;
        }
    }
    return 0;
}

int main() {
    int failed = 0;
    for (const fidelity_scene& scene : fidelity_scenes) {
        if (differs_by_design(scene.name)) {
            continue;
        }
        double worst = 0.0;
        int scene_failed = engines_agree_after_one_second(scene, &worst);
        std::printf("%s %s (farthest apart: %.4f m)\n", scene_failed ? "FAIL" : "pass",
                    scene.name, worst);
        failed += scene_failed;
    }
    return failed;
}
