// Part of <box2scene/box2d.hpp> (a host includes that header only): the world, where a build
// places the scene, one build from start to end and its reports, and scene_gravity: a loaded
// scene into a b2World. The builder's parts are in shapes.hpp, bodies.hpp and joints.hpp.
#ifndef BOX2SCENE_DETAIL_BOX2D_WORLD_HPP
#define BOX2SCENE_DETAIL_BOX2D_WORLD_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "reports.hpp"

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

inline std::string text_of(b2s_str s) {
    return s != nullptr ? std::string(s) : std::string();
}

/// One build: the scene's view, the world, and what was made so far.
class WorldBuilder {
public:
    WorldBuilder(const struct b2s_scene_view& view, b2World& world, const b2Transform& placement)
        : view_(view), world_(world), placement_(placement),
          placement_angle_(placement.q.GetAngle()) {}
    Built run();

private:
    // capture_world inverts the springs as the build computes them (capture.hpp)
    friend class WorldCapture;

    // ---- the build and its reports (world.hpp)
    void report(b2s_code code, const char* object, uint32_t index, b2s_str name,
                std::string message);
    bool within_range(const RangeCheck& check, const char* object, uint32_t index,
                      b2s_str name, const std::string& owner = std::string());
    void check_gravity();

    // ---- shapes: made once each, then cloned by Box2D into every fixture that uses them
    // (shapes.hpp, with the fixtures)
    void make_shapes();
    std::unique_ptr<b2Shape> make_shape(uint32_t index);
    bool vertices_of(const b2s_shape& shape, std::vector<b2Vec2>& points) const;
    static RangeCheck shape_check(const b2s_shape& shape, const std::vector<b2Vec2>& points);
    static bool vertex_count_fits(const b2s_shape& shape, size_t count);
    static std::unique_ptr<b2Shape> make_circle(const b2s_shape& shape);
    static std::unique_ptr<b2Shape> make_polygon(const b2s_shape& shape,
                                                 const std::vector<b2Vec2>& points);
    static std::unique_ptr<b2Shape> make_edge(const b2s_shape& shape,
                                              const std::vector<b2Vec2>& points);
    static std::unique_ptr<b2Shape> make_chain(const b2s_shape& shape,
                                               const std::vector<b2Vec2>& points);

    // ---- where the placement puts the scene (world.hpp)
    bool placement_valid() const;
    b2Vec2 placed(b2s_vec2 point) const;

    // ---- bodies and their mass (bodies.hpp)
    void make_body(uint32_t index);
    RangeCheck body_check(const b2s_body& body) const;
    void skip_fixtures_of(uint32_t body_index, const b2s_body& body);
    b2MassData predicted_mass(const b2s_body& body, RangeCheck& check) const;
    static b2MassData with_mass_data(const b2MassData& mass, const b2s_body& body);
    b2BodyDef body_def(uint32_t index, const b2s_body& body);
    float damping(uint32_t index, const b2s_body& body, float value, const char* field);
    // a body's fixtures (shapes.hpp)
    void make_fixtures(uint32_t body_index, const b2s_body& body, b2Body* created);
    bool shape_created(const b2s_fixture& fixture) const;
    static RangeCheck fixture_check(const b2s_fixture& fixture);
    bool fixture_creatable(uint32_t index) const;
    void report_lossy_filters();
    b2Fixture* make_fixture(uint32_t body_index, uint32_t index, b2Body* body);
    // its mass (bodies.hpp)
    void apply_mass_data(uint32_t index, const b2s_body& body, b2Body* created);
    static bool mass_data_given(const b2s_mass_data& given);
    static b2MassData overwritten(b2MassData mass, const b2s_mass_data& given);

    // ---- joints (joints.hpp)
    template <class Def>
    bool connect(uint32_t index, const b2s_joint& joint, Def& def);
    b2Body* created_body(uint32_t index) const;
    template <class Def>
    void create(uint32_t index, const Def& def);
    void make_joint(uint32_t index);
    float starting_violation(const b2s_joint& joint) const;
    RangeCheck violation_check(const b2s_joint& joint);
    RangeCheck joint_check(const b2s_joint& joint) const;
    bool massless(uint32_t body) const;
    void check_stiffness(const b2s_joint& joint, RangeCheck& check) const;
    void check_anchors(const b2s_joint& joint, b2s_vec2 anchor_a, b2s_vec2 anchor_b,
                       RangeCheck& check) const;
    void check_anchor(const char* field, uint32_t body, float r, float lever,
                      RangeCheck& check) const;
    static void spring(const b2s_joint& joint, float mass, float& stiffness, float& damping);
    static float inverse_central_inertia(const b2Body* body);
    static float inverse_mass(const b2Body* body);
    static void weld_spring(const b2s_joint& joint, const b2Body* a, const b2Body* b,
                            float& stiffness, float& damping);
    static void wheel_spring(const b2s_joint& joint, const b2Body* a, const b2Body* b,
                             float& stiffness, float& damping);
    void make_revolute(uint32_t index, const b2s_joint& joint);
    void make_prismatic(uint32_t index, const b2s_joint& joint);
    void make_distance(uint32_t index, const b2s_joint& joint);
    void make_rope(uint32_t index, const b2s_joint& joint);
    void make_pulley(uint32_t index, const b2s_joint& joint);
    void limit_pulley_side(uint32_t index, const b2s_joint& joint, const char* field,
                           float given, float longest, b2Vec2 ground, b2Body* body,
                           b2Vec2 anchor);
    b2Body* static_body() const;
    template <class Def>
    static void set_anchors_and_axis(const b2s_joint& joint, Def& def);
    void make_line(uint32_t index, const b2s_joint& joint);
    void make_wheel(uint32_t index, const b2s_joint& joint);
    void make_weld(uint32_t index, const b2s_joint& joint);
    void make_friction(uint32_t index, const b2s_joint& joint);
    void make_motor(uint32_t index, const b2s_joint& joint);
    void make_gear(uint32_t index);
    b2Joint* gear_input(uint32_t index, const b2s_joint& gear, uint32_t input);

    const struct b2s_scene_view& view_;
    b2World& world_;
    b2Transform placement_;
    float placement_angle_; // rad: what the placement adds to every body's Angle
    std::vector<std::unique_ptr<b2Shape>> shapes_; // indexed like the scene's shapes
    std::vector<b2MassData> masses_; // each dynamic body's, I about its centre of mass
    std::vector<const b2s_joint*> pulled_; // per body: the joint that starts it violated
    Built built_;
};

inline Built WorldBuilder::run() {
    if (!placement_valid()) {
        report(B2S_CODE_INVALID_ARGUMENT, "world", 0, nullptr,
               "the placement (" + decimal(placement_.p.x) + ", " + decimal(placement_.p.y) +
                   ") turned by (" + decimal(placement_.q.c) + ", " +
                   decimal(placement_.q.s) + ") is not finite, not within +-" +
                   decimal(working_range().max_length) +
                   " m or not a normalised rotation; nothing was built");
        return std::move(built_);
    }
    check_gravity();
    report_lossy_filters();
    make_shapes();
    built_.bodies.assign(view_.body_count, nullptr);
    masses_.assign(view_.body_count, b2MassData{0.0f, b2Vec2_zero, 0.0f});
    built_.fixtures.assign(view_.fixture_id_count, nullptr);
    for (uint32_t i = 0; i < view_.body_count; ++i) {
        make_body(i);
    }
    // Joints come after every body has its final mass (spring stiffness depends on it),
    // and gears after the joints they couple, which may come later in the file.
    built_.joints.assign(view_.joint_count, nullptr);
    pulled_.assign(view_.body_count, nullptr);
    for (uint32_t i = 0; i < view_.joint_count; ++i) {
        if (view_.joints[i].kind != B2S_JOINT_KIND_GEAR) {
            make_joint(i);
        }
    }
    for (uint32_t i = 0; i < view_.joint_count; ++i) {
        if (view_.joints[i].kind == B2S_JOINT_KIND_GEAR) {
            make_gear(i);
        }
    }
    return std::move(built_);
}

inline void WorldBuilder::report(b2s_code code, const char* object, uint32_t index, b2s_str name,
            std::string message) {
    built_.reports.push_back(Report{code, object, index, text_of(name), std::move(message)});
}

/// Reports an object found beyond the working range; false when it is.
inline bool WorldBuilder::within_range(const RangeCheck& check, const char* object, uint32_t index,
                  b2s_str name, const std::string& owner) {
    if (check.passed()) {
        return true;
    }
    report(B2S_CODE_BEYOND_BOX2D_RANGE, object, index, name,
           owner + check.problem() + "; " + object + " not created");
    return false;
}

/// scene_gravity gives the host's fallback for a gravity beyond the range.
inline void WorldBuilder::check_gravity() {
    RangeCheck check = gravity_check(view_.gravity);
    if (view_.gravity_given && !check.passed()) {
        report(B2S_CODE_BEYOND_BOX2D_RANGE, "world", 0, nullptr,
               check.problem() + "; scene_gravity gives the host's fallback instead");
    }
}

/// A placement Box2D 2.4 can take: finite, within the working range, its rotation
/// normalised (2.4 keeps a body's angle, and the placement's rotation is added to it).
inline bool WorldBuilder::placement_valid() const {
    const b2Transform& t = placement_;
    float qq = t.q.c * t.q.c + t.q.s * t.q.s;
    return std::isfinite(t.p.x) && std::isfinite(t.p.y) && std::isfinite(t.q.c) &&
           std::isfinite(t.q.s) && std::fabs(qq - 1.0f) < 1e-4f &&
           std::fabs(t.p.x) <= working_range().max_length &&
           std::fabs(t.p.y) <= working_range().max_length;
}

/// A point of the scene's world frame where the placement puts it.
inline b2Vec2 WorldBuilder::placed(b2s_vec2 point) const {
    return b2Mul(placement_, to_b2(point));
}

} // namespace detail

inline b2Vec2 scene_gravity(const b2s_scene* scene, b2Vec2 fallback) {
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (view == nullptr || !view->gravity_given ||
        !detail::gravity_check(view->gravity).passed()) {
        return fallback;
    }
    return detail::to_b2(view->gravity);
}

inline Built build_world_at(const b2s_scene* scene, b2World& world,
                            const b2Transform& placement) {
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (view == nullptr) {
        return Built{};
    }
    return detail::WorldBuilder(*view, world, placement).run();
}

inline Built build_world(const b2s_scene* scene, b2World& world) {
    b2Transform identity;
    identity.SetIdentity();
    return build_world_at(scene, world, identity);
}

} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_WORLD_HPP
