// Scenes built into their own Box2D world, and stepping a world while a condition holds:
// the "build a world, step it, check the positions" of the physics tests.
#ifndef BOX2SCENE_TEST_WORLDS_HPP
#define BOX2SCENE_TEST_WORLDS_HPP

#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cmath>
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

/// Whether every created body's position and angle are finite.
inline bool bodies_finite(const World& w) {
    for (const b2Body* body : w.built.bodies) {
        if (body == nullptr) {
            continue;
        }
        b2Vec2 p = body->GetPosition();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(body->GetAngle())) {
            return false;
        }
    }
    return true;
}

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

/// 1/m and 1/I about the centre of mass (b2Body::GetInertia is about the origin) of `body`;
/// 0 where it has none.
inline float inverse_mass_of(const b2Body* body) {
    return body->GetMass() > 0.0f ? 1.0f / body->GetMass() : 0.0f;
}

inline float inverse_central_inertia_of(const b2Body* body) {
    b2Vec2 c = body->GetLocalCenter();
    float inertia = body->GetInertia() - body->GetMass() * b2Dot(c, c);
    return inertia > 0.0f ? 1.0f / inertia : 0.0f;
}

/// Box2D 2.2's springs (docs/format.md, "Onto Box2D 2.4.1"): k = m w^2, c = 2 m zeta w.
inline void spring_22(float hz, float zeta, float mass, float& stiffness, float& damping) {
    float omega = 2.0f * b2_pi * hz;
    stiffness = mass * omega * omega;
    damping = 2.0f * mass * zeta * omega;
}

/// Box2D 2.2's wheel spring: the effective mass along the (unit) axis as the joint starts,
/// 1 / (1/mA + 1/mB + sAx^2/IA + sBx^2/IB), from the bodies as they are.
inline void wheel_spring_22(float hz, float zeta, const b2Body* a, const b2Body* b,
                            b2Vec2 anchor_a, b2Vec2 anchor_b, b2Vec2 unit_axis,
                            float& stiffness, float& damping) {
    b2Rot qA = a->GetTransform().q, qB = b->GetTransform().q;
    b2Vec2 rA = b2Mul(qA, anchor_a - a->GetLocalCenter());
    b2Vec2 rB = b2Mul(qB, anchor_b - b->GetLocalCenter());
    b2Vec2 d = b->GetWorldCenter() + rB - a->GetWorldCenter() - rA;
    b2Vec2 ax = b2Mul(qA, unit_axis);
    float sAx = b2Cross(d + rA, ax), sBx = b2Cross(rB, ax);
    float inverse = inverse_mass_of(a) + inverse_mass_of(b) +
                    inverse_central_inertia_of(a) * sAx * sAx +
                    inverse_central_inertia_of(b) * sBx * sBx;
    spring_22(hz, zeta, inverse > 0.0f ? 1.0f / inverse : 0.0f, stiffness, damping);
}

/// Box2D 2.2's soft weld: the angular mass 1 / (1/IA + 1/IB), inertias about the centres.
inline void weld_spring_22(float hz, float zeta, const b2Body* a, const b2Body* b,
                           float& stiffness, float& damping) {
    float inverse = inverse_central_inertia_of(a) + inverse_central_inertia_of(b);
    spring_22(hz, zeta, inverse > 0.0f ? 1.0f / inverse : 0.0f, stiffness, damping);
}

#endif // BOX2SCENE_TEST_WORLDS_HPP
