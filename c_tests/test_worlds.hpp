// Scenes built into their own Box2D world, and stepping a world while a condition holds:
// the "build a world, step it, check the positions" of the physics tests.
#ifndef BOX2SCENE_TEST_WORLDS_HPP
#define BOX2SCENE_TEST_WORLDS_HPP

#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cstdio>
#include <cstring>
#include <functional>
#include <utility>

#include "test_scenes.hpp"

/// A scene loaded and built into its own world (gravity (0, -10) unless the file says).
struct World {
    ScenePtr scene;
    b2World world{b2Vec2(0.0f, -10.0f)};
    box2scene::Built built;

    explicit World(const char* xml) : World(load_text(xml)) {}
    explicit World(ScenePtr loaded) : scene(std::move(loaded)) {
        world.SetGravity(box2scene::scene_gravity(scene.get(), world.GetGravity()));
        built = box2scene::build_world(scene.get(), world);
    }
    bool ok() const { return scene != nullptr && built.reports.empty(); }
    b2Body* body(size_t i) const { return built.bodies.at(i); }
    b2Joint* joint(size_t i) const { return built.joints.at(i); }
};

/// One step of 1/60 s, with Box2D's customary 8 velocity and 3 position iterations.
inline void step_once(b2World& world) {
    world.Step(1.0f / 60.0f, 8, 3);
}

inline void step_for(b2World& world, int steps) {
    for (int i = 0; i < steps; ++i) {
        step_once(world);
    }
}

/// Steps `steps` times; false as soon as `holds` is false after a step.
inline bool holds_for_steps(b2World& world, int steps, const std::function<bool()>& holds) {
    for (int i = 0; i < steps; ++i) {
        step_once(world);
        if (!holds()) {
            std::fprintf(stderr, "broken after step %d\n", i + 1);
            return false;
        }
    }
    return true;
}

template <class T>
inline bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// Whether two bodies are in the same state bit for bit (and say how they differ if not).
inline int ensure_same_state(size_t index, const b2Body* rebuilt, const b2Body* original) {
    b2Vec2 p = rebuilt->GetPosition(), q = original->GetPosition();
    b2Vec2 v = rebuilt->GetLinearVelocity(), w = original->GetLinearVelocity();
    float a = rebuilt->GetAngle(), b = original->GetAngle();
    float s = rebuilt->GetAngularVelocity(), t = original->GetAngularVelocity();
    if (!same_bits(p, q) || !same_bits(a, b) || !same_bits(v, w) || !same_bits(s, t) ||
        rebuilt->IsAwake() != original->IsAwake()) {
        std::fprintf(stderr,
                     "body %zu: rebuilt at (%.9g, %.9g) %.9g rad moving (%.9g, %.9g) %.9g rad/s,\n"
                     "  original at (%.9g, %.9g) %.9g rad moving (%.9g, %.9g) %.9g rad/s\n",
                     index, p.x, p.y, a, v.x, v.y, s, q.x, q.y, b, w.x, w.y, t);
        return 1;
    }
    return 0;
}


#endif // BOX2SCENE_TEST_WORLDS_HPP
