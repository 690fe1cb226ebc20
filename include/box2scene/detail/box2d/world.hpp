// Part of <box2scene/box2d.hpp> (a host includes that header only): one build, which has the
// library plan the scene for Box2D 2.4 (b2s_plan_make: every conversion, check and report)
// and carries the plan out through Box2D's own calls; and scene_gravity. The calls for the
// plan's parts are in shapes.hpp, bodies.hpp and joints.hpp.
#ifndef BOX2SCENE_DETAIL_BOX2D_WORLD_HPP
#define BOX2SCENE_DETAIL_BOX2D_WORLD_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "reports.hpp"

#include <cfloat>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace box2scene {
namespace detail {

inline std::string text_of(b2s_str s) {
    return s != nullptr ? std::string(s) : std::string();
}

/// Frees a plan when it goes out of scope.
struct PlanFree {
    void operator()(b2s_plan* plan) const { b2s_plan_free(plan); }
};
using PlanPtr = std::unique_ptr<b2s_plan, PlanFree>;

/// One build: the plan's view, the world, and what was made so far.
class PlanExecutor {
public:
    /// `shape_count`: the scene's shapes, which the plan's shapes name.
    PlanExecutor(const b2s_plan_view& plan, b2World& world, uint32_t shape_count)
        : plan_(plan), world_(world), shapes_(shape_count) {}
    void run(Built& built);

private:
    // bodies and their fixtures (bodies.hpp, shapes.hpp)
    void make_body(const b2s_plan_body& body, Built& built);
    b2Fixture* make_fixture(const b2s_plan_shape& shape, b2Body* body);
    const b2Shape* shape_of(const b2s_plan_shape& shape);
    std::unique_ptr<b2Shape> make_shape(const b2s_plan_shape& shape) const;
    std::unique_ptr<b2Shape> make_circle(const b2s_plan_shape& shape) const;
    std::unique_ptr<b2Shape> make_polygon(const b2s_plan_shape& shape) const;
    std::unique_ptr<b2Shape> make_segment(const b2s_plan_shape& shape) const;
    std::unique_ptr<b2Shape> make_chain(const b2s_plan_shape& shape) const;
    std::unique_ptr<b2Shape> make_loop(const b2s_plan_shape& shape) const;
    std::vector<b2Vec2> points(const b2s_plan_shape& shape) const;

    // joints (joints.hpp)
    b2Joint* make_joint(const b2s_plan_joint& joint, const Built& built);
    template <class Def>
    b2Joint* create(const b2s_plan_joint& joint, const Built& built, Def& def);

    const b2s_plan_view& plan_;
    b2World& world_;
    std::vector<b2Joint*> joints_; // indexed like the plan's joints
    // indexed like the scene's shapes: each made once, then cloned by Box2D into every
    // fixture that uses it
    std::vector<std::unique_ptr<b2Shape>> shapes_;
};

inline void PlanExecutor::run(Built& built) {
    for (uint32_t i = 0; i < plan_.body_count; ++i) {
        make_body(plan_.bodies[i], built);
    }
    joints_.reserve(plan_.joint_count);
    for (uint32_t i = 0; i < plan_.joint_count; ++i) {
        const b2s_plan_joint& joint = plan_.joints[i];
        joints_.push_back(make_joint(joint, built));
        if (joint.joint != B2S_NONE) {
            built.joints[joint.joint] = joints_.back();
        }
    }
}

/// The library's reports (a plan's, a capture's), as the adapter's own.
inline void append_reports(const b2s_plan_report* from, uint32_t count,
                           std::vector<Report>& reports) {
    reports.reserve(reports.size() + count);
    for (uint32_t i = 0; i < count; ++i) {
        const b2s_plan_report& r = from[i];
        reports.push_back(Report{static_cast<b2s_code>(r.code), r.object, r.index,
                                 text_of(r.name), text_of(r.message)});
    }
}

/// A library failure (never a scene's fault): the build stops, reported on the world.
inline Built failed_build(const b2s_error& error) {
    Built built;
    built.reports.push_back(Report{static_cast<b2s_code>(error.code), "world", 0,
                                   std::string(), error.message});
    return built;
}

} // namespace detail

inline b2Vec2 scene_gravity(const b2s_scene* scene, b2Vec2 fallback) {
    return detail::to_b2(
        b2s_plan_world_gravity(scene, B2S_ENGINE_BOX2D24, detail::to_b2s(fallback)));
}

inline Built build_world_at(const b2s_scene* scene, b2World& world,
                            const b2Transform& placement) {
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (view == nullptr) {
        return Built{};
    }
    b2s_plan_options options{};
    options.engine = B2S_ENGINE_BOX2D24;
    options.placement = b2s_transform{detail::to_b2s(placement.p),
                                      b2s_rot{placement.q.c, placement.q.s}};
    options.gravity = detail::to_b2s(world.GetGravity());
    options.max_linear_speed = FLT_MAX;
    b2s_plan* made = nullptr;
    b2s_error error{};
    if (b2s_plan_make(scene, &options, &made, &error) != B2S_CODE_OK) {
        return detail::failed_build(error);
    }
    detail::PlanPtr plan(made);
    const b2s_plan_view& view_of_plan = *b2s_plan_get_view(plan.get());
    Built built;
    if (view_of_plan.placed) {
        built.bodies.assign(view->body_count, nullptr);
        built.fixtures.assign(view->fixture_id_count, nullptr);
        built.joints.assign(view->joint_count, nullptr);
        detail::PlanExecutor(view_of_plan, world, view->shape_count).run(built);
    }
    detail::append_reports(view_of_plan.reports, view_of_plan.report_count, built.reports);
    return built;
}

inline Built build_world(const b2s_scene* scene, b2World& world) {
    b2Transform identity;
    identity.SetIdentity();
    return build_world_at(scene, world, identity);
}

} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_WORLD_HPP
