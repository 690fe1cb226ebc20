// Part of <box2scene/box2d.hpp> (a host includes that header only): a plan's bodies, each
// with its fixtures and the mass the plan gives it.
#ifndef BOX2SCENE_DETAIL_BOX2D_BODIES_HPP
#define BOX2SCENE_DETAIL_BOX2D_BODIES_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "world.hpp"

#include <cstdint>

namespace box2scene {
namespace detail {

inline void PlanExecutor::make_body(const b2s_plan_body& body, Built& built) {
    b2BodyDef def;
    def.type = static_cast<b2BodyType>(body.kind);
    def.position = to_b2(body.position);
    def.angle = body.angle;
    def.linearVelocity = to_b2(body.linear_velocity);
    def.angularVelocity = body.angular_velocity;
    def.linearDamping = body.linear_damping;
    def.angularDamping = body.angular_damping;
    def.allowSleep = body.allow_sleep;
    def.awake = body.awake;
    def.fixedRotation = body.fixed_rotation;
    def.bullet = body.bullet;
    def.enabled = body.enabled;
    def.gravityScale = body.gravity_scale;
    b2Body* created = world_.CreateBody(&def);
    built.bodies[body.body] = created;
    for (uint32_t i = 0; i < body.shapes.count; ++i) {
        const b2s_plan_shape& shape = plan_.shapes[body.shapes.first + i];
        built.fixtures[shape.slot] = make_fixture(shape, created);
    }
    // What CreateFixture would have done after each fixture with a density, once.
    if (body.apply_mass_from_shapes) {
        created->ResetMassData();
    }
    if (body.set_mass) {
        b2MassData mass{body.mass.mass, to_b2(body.mass.center), body.mass.inertia};
        created->SetMassData(&mass);
    }
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_BODIES_HPP
