// The measured working range of Box2D 2.4 (docs/working-range.md): every case of
// range_sweep.h, each run in a child process, since Debian's Box2D asserts. Once built
// satisfied and moved through Box2D's own API, which measures what the engine holds; once
// built by the adapter from the file that places body B there, which must hold whatever it
// builds (finite, within 1e4 m, no assertion, for 600 steps) and report what it leaves out
// as beyond-box2d-range. Prints the table the docs show.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "range_sweep.h"
#include "test_macros.h"
#include "test_scenes.hpp"
#include "test_worlds.hpp"

static bool world_holds(b2World& world) {
    for (int i = 0; i < SWEEP_STEPS; ++i) {
        step_once(world);
        for (b2Body* b = world.GetBodyList(); b != nullptr; b = b->GetNext()) {
            b2Vec2 p = b->GetPosition();
            if (!(std::fabs(p.x) < SWEEP_BOUND && std::fabs(p.y) < SWEEP_BOUND &&
                  std::isfinite(b->GetAngle()))) {
                return false;
            }
        }
    }
    return true;
}

/// Whether the adapter left out one of the case's joints as beyond its range.
static bool refused(const box2scene::Built& built) {
    for (const box2scene::Report& r : built.reports) {
        if (r.code == B2S_CODE_BEYOND_BOX2D_RANGE && std::string(r.object) == "joint") {
            return true;
        }
    }
    return false;
}

/// In a child: the case built satisfied, body B moved by Box2D's SetTransform.
static void run_moved(const sweep_case* c) {
    static char xml[4096];
    sweep_scene_xml(c, 0.0f, 0.0f, xml, sizeof xml);
    World w(xml);
    if (w.scene == nullptr || refused(w.built)) {
        _exit(SWEEP_NOT_MEASURED);
    }
    float dx, dy;
    sweep_displacement(c, &dx, &dy);
    b2Body* b = w.body(SWEEP_BODY_B);
    b->SetTransform(b->GetPosition() + b2Vec2(dx, dy), b->GetAngle());
    _exit(world_holds(w.world) ? SWEEP_HELD : SWEEP_LOST);
}

/// In a child: the case as the file gives it, through the adapter.
static void run_built(const sweep_case* c) {
    static char xml[4096];
    float dx, dy;
    sweep_displacement(c, &dx, &dy);
    sweep_scene_xml(c, dx, dy, xml, sizeof xml);
    World w(xml);
    if (w.scene == nullptr) {
        _exit(SWEEP_NOT_LOADED);
    }
    if (refused(w.built)) {
        _exit(SWEEP_REFUSED);
    }
    _exit(world_holds(w.world) ? SWEEP_HELD : SWEEP_LOST);
}

/// Box2D 2.4 holds every satisfied case the adapter builds; none may be refused.
static bool none(const sweep_case*) {
    return false;
}

static int every_built_world_holds_and_every_satisfied_one_is_built() {
    bool has[SWEEP_JOINT_COUNT];
    for (bool& h : has) {
        h = true;
    }
    ENSURE_EQ(sweep_engine("Box2D 2.4", run_moved, run_built, has, none), 0);
    return 0;
}

int main() {
    return RUN_TEST(every_built_world_holds_and_every_satisfied_one_is_built);
}
