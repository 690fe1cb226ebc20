// Part of <box2scene/box2d.hpp> (a host includes that header only): the build's bodies, and their mass.
#ifndef BOX2SCENE_DETAIL_BOX2D_BODIES_HPP
#define BOX2SCENE_DETAIL_BOX2D_BODIES_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "world.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace box2scene {
namespace detail {

inline void WorldBuilder::make_body(uint32_t index) {
    const b2s_body& body = view_.bodies[index];
    if (body.kind > B2S_BODY_KIND_DYNAMIC) {
        report(B2S_CODE_UNKNOWN_TYPE, "body", index, body.name,
               "unknown body kind " + std::to_string(body.kind) + "; body skipped");
        skip_fixtures_of(index, body);
        return;
    }
    RangeCheck check = body_check(body);
    if (body.kind == B2S_BODY_KIND_DYNAMIC && check.passed()) {
        masses_[index] = predicted_mass(body, check);
    }
    if (!within_range(check, "body", index, body.name)) {
        skip_fixtures_of(index, body);
        return;
    }
    b2BodyDef def = body_def(index, body);
    b2Body* created = world_.CreateBody(&def);
    built_.bodies[index] = created;
    make_fixtures(index, body, created);
    apply_mass_data(index, body, created);
}

inline RangeCheck WorldBuilder::body_check(const b2s_body& body) const {
    const b2s_working_range& range = working_range();
    RangeCheck check;
    check.vector("Position", body.position, range.max_length, "m");
    check.magnitude("Angle", body.angle, range.max_angle, "rad");
    check.vector("LinearVelocity", body.linear_velocity, range.max_speed, "m/s");
    check.magnitude("AngularVelocity", body.angular_velocity, range.max_speed, "rad/s");
    check.magnitude("LinearDamping", body.linear_damping, range.max_damping, "1/s");
    check.magnitude("AngularDamping", body.angular_damping, range.max_damping, "1/s");
    check.magnitude("GravityScale", body.gravity_scale, range.max_gravity_scale, "");
    if (body.kind == B2S_BODY_KIND_DYNAMIC) {
        b2Vec2 gravity = body.gravity_scale * world_.GetGravity();
        check.vector("GravityScale times the world's gravity", to_b2s(gravity),
                     range.max_acceleration, "m/s^2");
    }
    if (body.mass_data.center_given) {
        check.vector("MassData Center", body.mass_data.center, range.max_length, "m");
    }
    if (check.passed()) {
        check.vector("its placed Position", to_b2s(placed(body.position)), range.max_length,
                     "m");
    }
    return check;
}

/// The fixtures of a body that was not created: they depend on it.
inline void WorldBuilder::skip_fixtures_of(uint32_t body_index, const b2s_body& body) {
    uint64_t end = uint64_t{body.fixtures.first} + body.fixtures.count;
    for (uint64_t slot = body.fixtures.first; slot < end && slot < view_.fixture_id_count;
         ++slot) {
        uint32_t index = view_.fixture_ids[slot];
        report(B2S_CODE_SKIPPED_DEPENDENT, "fixture", index,
               index < view_.fixture_count ? view_.fixtures[index].name : nullptr,
               "fixture " + std::to_string(index) + " of body " +
                   std::to_string(body_index) + ": the body was not created; fixture skipped");
    }
}

/// The mass Box2D 2.4 will give a dynamic body, as build_world has b2Body compute it:
/// from all of its fixtures at once (ResetMassData, which asserts that an inertia it
/// centres stays positive), then MassData. `check` fails when Box2D would assert or the
/// result lies beyond the working range.
inline b2MassData WorldBuilder::predicted_mass(const b2s_body& body, RangeCheck& check) const {
    std::vector<FixtureMass> created;
    uint64_t end = uint64_t{body.fixtures.first} + body.fixtures.count;
    for (uint64_t slot = body.fixtures.first; slot < end && slot < view_.fixture_id_count;
         ++slot) {
        uint32_t index = view_.fixture_ids[slot];
        if (!fixture_creatable(index)) {
            continue;
        }
        const b2s_fixture& fixture = view_.fixtures[index];
        created.push_back(FixtureMass{fixture.density, {}});
        shapes_[fixture.shape]->ComputeMass(&created.back().mass, fixture.density);
    }
    b2MassData mass = reset_mass(created, body.fixed_rotation);
    if (inertia_centred(created, body.fixed_rotation) && !(mass.I > 0.0f)) {
        check.fail("with fixtures that have a density, it has no positive inertia about its "
                   "centre of mass in Box2D 2.4's float arithmetic (which asserts)");
    }
    // The new centre of mass moves the body's velocity (w x its shift), even where
    // MassData then moves it again: a centre made NaN by a subnormal mass (0 * infinity)
    // would stay in the velocity.
    check.vector("with fixtures that have a density, its centre of mass",
                 to_b2s(mass.center), working_range().max_length, "m");
    mass = with_mass_data(mass, body);
    check.zero_or_within("its mass", mass.mass, working_range().min_mass,
                         working_range().max_mass, "kg");
    check.vector("its centre of mass", to_b2s(mass.center), working_range().max_length, "m");
    check.zero_or_within("its inertia about the centre of mass", mass.I,
                         working_range().min_inertia, working_range().max_inertia, "kg m^2");
    return mass;
}

/// `mass` (from the fixtures, inertia about the centre) as apply_mass_data leaves it.
inline b2MassData WorldBuilder::with_mass_data(const b2MassData& mass, const b2s_body& body) {
    if (!mass_data_given(body.mass_data)) {
        return mass;
    }
    // b2Body::GetMassData gives the inertia about the body origin
    float inertia = mass.I + mass.mass * b2Dot(mass.center, mass.center);
    b2MassData data = overwritten({mass.mass, mass.center, inertia}, body.mass_data);
    return central_inertia_positive(data, body.fixed_rotation)
               ? set_mass(data, body.fixed_rotation)
               : mass;
}

inline b2BodyDef WorldBuilder::body_def(uint32_t index, const b2s_body& body) {
    b2BodyDef def;
    def.type = static_cast<b2BodyType>(body.kind);
    def.position = placed(body.position);
    def.angle = body.angle + placement_angle_;
    // Box2D 2.4 keeps the velocity a static body is created with and moves the body
    // by it whenever a joint puts it in an island; static bodies never move.
    if (body.kind != B2S_BODY_KIND_STATIC) {
        def.linearVelocity = b2Mul(placement_.q, to_b2(body.linear_velocity));
        def.angularVelocity = body.angular_velocity;
    }
    def.linearDamping = damping(index, body, body.linear_damping, "LinearDamping");
    def.angularDamping = damping(index, body, body.angular_damping, "AngularDamping");
    def.allowSleep = body.allow_sleep;
    def.awake = body.awake;
    def.fixedRotation = body.fixed_rotation;
    def.bullet = body.bullet;
    def.enabled = body.active;
    def.gravityScale = body.gravity_scale;
    return def;
}

/// Box2D 2.4 asserts against a negative damping, which the format does not forbid.
inline float WorldBuilder::damping(uint32_t index, const b2s_body& body, float value, const char* field) {
    if (value >= 0.0f) {
        return value;
    }
    report(B2S_CODE_NEGATIVE_VALUE, "body", index, body.name,
           std::string(field) + " " + std::to_string(value) +
               " is negative, which Box2D 2.4 does not allow; 0 was used");
    return 0.0f;
}

/// A datum the file leaves out keeps the value Box2D computed from the fixtures.
inline void WorldBuilder::apply_mass_data(uint32_t index, const b2s_body& body, b2Body* created) {
    if (!mass_data_given(body.mass_data)) {
        return;
    }
    b2MassData mass;
    created->GetMassData(&mass);
    mass = overwritten(mass, body.mass_data);
    if (!central_inertia_positive(mass, body.fixed_rotation)) {
        report(B2S_CODE_INCONSISTENT_MASS_DATA, "body", index, body.name,
               "its MassData leaves no positive inertia about the centre of mass "
               "(Inertia < Mass * |Center|^2); the mass computed from the fixtures was kept");
        return;
    }
    created->SetMassData(&mass);
}

inline bool WorldBuilder::mass_data_given(const b2s_mass_data& given) {
    return given.mass_given || given.center_given || given.inertia_given;
}

/// `mass` (as b2Body::GetMassData gives it: inertia about the body origin) with what
/// the body's MassData gives written over it.
inline b2MassData WorldBuilder::overwritten(b2MassData mass, const b2s_mass_data& given) {
    if (given.mass_given) {
        mass.mass = given.mass;
    }
    if (given.center_given) {
        mass.center = to_b2(given.center);
    }
    if (given.inertia_given) {
        mass.I = given.inertia;
    }
    return mass;
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_BODIES_HPP
