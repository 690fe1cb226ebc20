/*
 * box2scene/box2d.hpp: builds a Box2D 2.4 b2World from a loaded box2scene scene, and
 * captures a live b2World back into a scene.
 * Header-only C++17; needs <box2d/box2d.h> (Box2D 2.4.x) and <box2scene.h>.
 *
 *     b2s_scene* scene = nullptr;
 *     if (b2s_load_file("level.xml", nullptr, &scene, nullptr) == B2S_CODE_OK) {
 *         b2World world(box2scene::scene_gravity(scene, b2Vec2(0.0f, -10.0f)));
 *         box2scene::Built built = box2scene::build_world(scene, world);
 *         // built.reports says what Box2D 2.4 could not represent.
 *         b2s_scene_free(scene);  // the world does not need the scene any more
 *     }
 *
 *     std::vector<box2scene::Report> reports;  // what the file cannot hold exactly
 *     b2s_scene* saved = box2scene::capture_world(world, reports);
 *     b2s_write_file(saved, "saved.xml", nullptr, nullptr);
 *     b2s_scene_free(saved);
 *
 * docs/format.md tables the mapping ("Onto Box2D 2.4.1"). The adapter never prints, never
 * aborts and throws nothing for bad data: what it cannot create it skips and reports.
 * Debian's Box2D keeps its assertions on, so the adapter checks what they check before
 * calling Box2D (bodies it follows, joint kinds, a negative damping, a MassData that
 * leaves no positive inertia about the centre of mass, a prismatic limit's order, a gear's
 * bodies), whether or not the loader in use already refuses it: a report is better than an
 * abort. Values past box2scene::working_range, where Box2D would compute inf or NaN, are
 * reported and their objects not created.
 * Call it outside b2World::Step (Box2D refuses to add objects to a locked world).
 */
#ifndef BOX2SCENE_BOX2D_HPP
#define BOX2SCENE_BOX2D_HPP

#include <box2d/box2d.h>
#include <box2scene.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace box2scene {

/// Something of the scene that Box2D 2.4 could not represent, or only approximately.
struct Report {
    b2s_code code;       ///< B2S_CODE_LOSSY_LINE_MOTOR, B2S_CODE_SKIPPED_JOINT, ...
    const char* object;  ///< "shape", "fixture", "body", "joint" or "world" (static storage)
    /// build_world: the object's index in the scene's array of that kind; capture_world: its
    /// place among the world's objects of that kind in creation order (a fixture's and its
    /// shape's: counted over the bodies in creation order).
    uint32_t index;
    std::string name;    ///< the object's Name, empty when it has none
    std::string message; ///< what happened, for a level designer
};

/// What build_world created. Every pointer is owned by the b2World.
struct Built {
    /// Indexed like the scene's bodies; nullptr where not created.
    std::vector<b2Body*> bodies;
    /// Indexed like the scene's fixture ID pool (b2s_scene_view::fixture_ids): one b2Fixture
    /// per (body, fixture) pair, since a scene fixture may serve many bodies; nullptr where
    /// not created. A body's fixtures are the slots its b2s_body::fixtures range names.
    std::vector<b2Fixture*> fixtures;
    /// Indexed like the scene's joints; nullptr where skipped.
    std::vector<b2Joint*> joints;
    /// What could not be represented, in the order it was met.
    std::vector<Report> reports;
};

/// The scene's gravity when the file gives one within working_range::acceleration, else
/// `fallback` (the format has no default gravity: the host decides; build_world reports a
/// gravity beyond the range). A NULL scene gives `fallback`.
inline b2Vec2 scene_gravity(const b2s_scene* scene, b2Vec2 fallback);

/// Adds the scene's bodies, fixtures and joints to `world`. A NULL scene adds nothing.
inline Built build_world(const b2s_scene* scene, b2World& world);

/// The values build_world passes to Box2D 2.4. The format, and the loader, accept any
/// finite float; Box2D does not: near FLT_MAX its solver computes inf and NaN, or trips an
/// assertion (Debian's Box2D keeps them). An object with a value beyond these bounds is not
/// created: build_world reports it (B2S_CODE_BEYOND_BOX2D_RANGE, naming the field and the
/// value) and what depends on it (B2S_CODE_SKIPPED_DEPENDENT). Real levels stay orders of
/// magnitude inside: Box2D is made for objects of 0.1 to 10 m moving at most 2 m a step.
///
/// Why they keep a world finite. Box2D clamps each step's motion to 2 m and pi/2 rad, so a
/// position or an angle stops being finite only through a velocity that did, and a
/// velocity only through a product overflowing FLT_MAX (3.4e38), or 0 times infinity,
/// within one step. With every value at its bound:
/// - speeds entering a step stay under 1e3 (given) + 17 (a step of gravity) + 3e8 (the
///   kick w * r when a fixture moves a spinning body's centre of mass) m/s, and restitution
///   multiplies them by at most 1e5;
/// - a dynamic body has at most 1e10 kg and 1e12 kg m^2, so impulses m * v stay under 1e24
///   and spring stiffnesses m * (2 pi * 1e3 Hz)^2 under 4e17 N/m (I w^2: 4e19 N m/rad);
///   a stiffness under 1e-20 would make Box2D's 1 / (h * (damping + h * stiffness))
///   infinite;
/// - its inverse mass and inertia are at most 1e20, and at a joint's anchor, 1/m + r^2/I at
///   most 1e12: the joint solvers' 2x2 and 3x3 matrices of such terms have cofactors under
///   1e24 (times a velocity: 1e38) and determinants at least (1e-10)^2 * 1e-12 = 1e-32,
///   normal floats; a 2x2 determinant cancels terms (r/g)^2 and a 3x3 one (r/g)^4 times
///   larger than what is left (g = sqrt(I/m)), and lever_2x2 and lever_3x3 keep 4 of
///   float's 24 bits for it;
/// - an axis at least 1e-6 long is one b2Vec2::Normalize turns into a unit vector;
/// - force and torque maxima at most 1e20 keep the friction and motor joints' squared
///   impulse limits (h * F)^2 finite;
/// - damping, friction and restitution only scale velocities; past 1e5 they change nothing
///   (a damping of 1e5/s already stops a body within a step).
/// What Box2D asserts about combinations of values build_world checks exactly, by Box2D's
/// own arithmetic: the inertia left about the centre of mass after each fixture and after
/// MassData, a prismatic limit's order, the bodies of a gear's joints; and it does not make
/// a spring between two bodies without mass, whose upper length, FLT_MAX, Box2D multiplies
/// by 0. Within the range, Box2D's solver can still diverge on an assembly it cannot hold
/// (a light body carrying a heavy one far out, joints that start far from satisfied or
/// fight a kinematic body): that is the level's, whatever its values.
namespace working_range {
/// m, each component: positions, vertices, radii, anchors, lengths, limits, offsets (their
/// squares and products stay far below FLT_MAX).
inline constexpr float length = 1e5f;
/// rad: angles, angle limits and offsets (float still resolves 0.008 rad there).
inline constexpr float angle = 1e5f;
/// m/s and rad/s: velocities and motor speeds (Box2D moves a body at most 120 m/s and
/// 94 rad/s at 60 Hz; a joint takes the rest of a faster start as one impulse).
inline constexpr float speed = 1e3f;
/// m/s^2: each component of the gravity, and of a body's (GravityScale times the world's).
inline constexpr float acceleration = 1e3f;
inline constexpr float gravity_scale = 1e3f; ///< a body's multiple of the gravity
inline constexpr float damping = 1e5f;       ///< 1/s: linear and angular damping
inline constexpr float density = 1e5f;       ///< kg/m^2
inline constexpr float friction = 1e5f;      ///< friction coefficient and restitution
inline constexpr float ratio = 1e5f;         ///< pulley and gear ratios
inline constexpr float frequency = 1e3f;     ///< Hz, and damping ratios, of springs
/// N/m or N m/rad: the softest spring, unless 0 (a rigid joint), as b2LinearStiffness and
/// b2AngularStiffness make it from FrequencyHz and the bodies' masses.
inline constexpr float min_stiffness = 1e-20f;
inline constexpr float force = 1e20f;        ///< N and N m: force and torque maxima
inline constexpr float min_axis = 1e-6f;     ///< m: the shortest joint axis
inline constexpr float mass_min = 1e-20f;    ///< kg: a dynamic body's mass, unless 0
inline constexpr float mass_max = 1e10f;
inline constexpr float inertia_min = 1e-20f; ///< kg m^2, about the centre of mass, unless 0
inline constexpr float inertia_max = 1e12f;
/// 1/kg: 1/m + r^2/I of a body at a joint's anchor.
inline constexpr float compliance = 1e12f;
/// A joint's anchor's distance from its body's centre of mass, in radii of gyration
/// sqrt(I/m), where Box2D inverts a 2x2 matrix for it (revolute, friction and motor joints:
/// a 10 cm ball can hang 70 m out) or a 3x3 one (prismatic and weld joints).
inline constexpr float lever_2x2 = 1e3f;
inline constexpr float lever_3x3 = 30.0f;
} // namespace working_range

namespace detail {

inline b2Vec2 to_b2(b2s_vec2 v) {
    return b2Vec2(v.x, v.y);
}

inline b2s_vec2 to_b2s(b2Vec2 v) {
    return b2s_vec2{v.x, v.y};
}

inline std::string text_of(b2s_str s) {
    return s != nullptr ? std::string(s) : std::string();
}

/// `end` continued by one segment away from `inner`: a ghost vertex for an open chain end
/// the file left without one (Box2D 2.4's CreateChain needs both).
inline b2Vec2 extrapolated(b2Vec2 end, b2Vec2 inner) {
    return end + (end - inner);
}

/// A float for a report: every digit that tells it from its neighbours.
inline std::string decimal(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
    return text;
}

/// A fixture as build_world recreates it: what its body's mass is made of.
struct FixtureMass {
    float density;
    b2MassData mass; ///< of the rebuilt shape at that density
};

/// What b2Body::ResetMassData leaves in a dynamic body holding the first `count` of
/// `created` (its fixture list is newest first), operation for operation as Box2D 2.4.1
/// does it so that the bits agree: mass, centre, and inertia about the centre in `I`.
inline b2MassData reset_mass(const std::vector<FixtureMass>& created, size_t count,
                             bool fixed_rotation) {
    b2MassData body{0.0f, b2Vec2_zero, 0.0f};
    for (size_t i = count; i-- > 0;) {
        if (created[i].density == 0.0f) {
            continue;
        }
        const b2MassData& m = created[i].mass;
        body.mass += m.mass;
        body.center += m.mass * m.center;
        body.I += m.I;
    }
    if (body.mass > 0.0f) {
        float inverse = 1.0f / body.mass;
        body.center *= inverse;
    }
    if (body.I > 0.0f && !fixed_rotation) {
        body.I -= body.mass * b2Dot(body.center, body.center);
    } else {
        body.I = 0.0f;
    }
    return body;
}

/// A bound for a report: as short as it reads.
inline std::string rounded(float v) {
    char text[16];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
    return text;
}

/// The first value of one object found beyond the working range: what its report says.
class RangeCheck {
public:
    bool passed() const { return problem_.empty(); }
    const std::string& problem() const { return problem_; }

    void magnitude(const std::string& field, float value, float bound, const char* unit) {
        if (passed() && !(std::fabs(value) <= bound)) {
            beyond(field + " " + decimal(value), "within +-" + rounded(bound) + " " + unit);
        }
    }
    void vector(const std::string& field, b2s_vec2 v, float bound, const char* unit) {
        if (passed() && !(std::fabs(v.x) <= bound && std::fabs(v.y) <= bound)) {
            beyond(field + " (" + decimal(v.x) + ", " + decimal(v.y) + ")",
                   "each component within +-" + rounded(bound) + " " + unit);
        }
    }
    void within(const std::string& field, float value, float low, float high,
                const char* unit) {
        if (passed() && !(low <= value && value <= high)) {
            beyond(field + " " + decimal(value),
                   "within [" + rounded(low) + ", " + rounded(high) + "] " + unit);
        }
    }
    void at_least(const std::string& field, float value, float bound, const char* unit) {
        if (passed() && !(value >= bound)) {
            beyond(field + " " + decimal(value), "at least " + rounded(bound) + " " + unit);
        }
    }
    /// 0, or within [low, high]: a derived quantity such as a body's mass.
    void zero_or_within(const std::string& field, float value, float low, float high,
                        const char* unit) {
        if (passed() && value != 0.0f && !(low <= value && value <= high)) {
            beyond(field + " " + decimal(value) + " " + unit,
                   "0 or within [" + rounded(low) + ", " + rounded(high) + "] " + unit);
        }
    }
    /// What Box2D 2.4 asserts against, whatever the bounds.
    void fail(const std::string& what) {
        if (passed()) {
            problem_ = what;
        }
    }

private:
    void beyond(const std::string& value, const std::string& range) {
        problem_ = value + " lies beyond Box2D 2.4's working range (" + range + ")";
    }

    std::string problem_;
};

inline RangeCheck gravity_check(b2s_vec2 gravity) {
    RangeCheck check;
    check.vector("Gravity", gravity, working_range::acceleration, "m/s^2");
    return check;
}

/// Whether b2Body::ResetMassData, for the first `count` of `created`, moves an inertia to
/// the centre of mass, and then asserts that some is left: the summed inertia is positive.
inline bool inertia_centred(const std::vector<FixtureMass>& created, size_t count,
                            bool fixed_rotation) {
    float sum = 0.0f;
    for (size_t i = count; i-- > 0;) {
        if (created[i].density != 0.0f) {
            sum += created[i].mass.I;
        }
    }
    return sum > 0.0f && !fixed_rotation;
}

/// What b2Body::SetMassData(&m) leaves in a dynamic body (a zero mass becomes 1), with the
/// inertia about the centre of mass.
inline b2MassData set_mass(const b2MassData& m, bool fixed_rotation) {
    b2MassData body{m.mass > 0.0f ? m.mass : 1.0f, m.center, 0.0f};
    if (m.I > 0.0f && !fixed_rotation) {
        body.I = m.I - body.mass * b2Dot(m.center, m.center);
    }
    return body;
}

/// Whether b2Body::SetMassData(&m) would derive a positive inertia about the centre of mass
/// where it uses one: Box2D asserts that it does.
inline bool central_inertia_positive(const b2MassData& m, bool fixed_rotation) {
    bool inertia_used = m.I > 0.0f && !fixed_rotation;
    return !inertia_used || set_mass(m, fixed_rotation).I > 0.0f;
}

/// One build: the scene's view, the world, and what was made so far.
class WorldBuilder {
public:
    WorldBuilder(const struct b2s_scene_view& view, b2World& world) : view_(view), world_(world) {}

    Built run() {
        check_gravity();
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

private:
    void report(b2s_code code, const char* object, uint32_t index, b2s_str name,
                std::string message) {
        built_.reports.push_back(Report{code, object, index, text_of(name), std::move(message)});
    }

    /// Reports an object found beyond the working range; false when it is.
    bool within_range(const RangeCheck& check, const char* object, uint32_t index,
                      b2s_str name, const std::string& owner = std::string()) {
        if (check.passed()) {
            return true;
        }
        report(B2S_CODE_BEYOND_BOX2D_RANGE, object, index, name,
               owner + check.problem() + "; " + object + " not created");
        return false;
    }

    /// scene_gravity gives the host's fallback for a gravity beyond the range.
    void check_gravity() {
        RangeCheck check = gravity_check(view_.gravity);
        if (view_.gravity_given && !check.passed()) {
            report(B2S_CODE_BEYOND_BOX2D_RANGE, "world", 0, nullptr,
                   check.problem() + "; scene_gravity gives the host's fallback instead");
        }
    }

    // ---- shapes: made once each, then cloned by Box2D into every fixture that uses them

    void make_shapes() {
        shapes_.resize(view_.shape_count);
        for (uint32_t i = 0; i < view_.shape_count; ++i) {
            shapes_[i] = make_shape(i);
        }
    }

    std::unique_ptr<b2Shape> make_shape(uint32_t index) {
        const b2s_shape& shape = view_.shapes[index];
        std::vector<b2Vec2> points;
        if (!vertices_of(shape, points)) {
            report(B2S_CODE_ID_OUT_OF_RANGE, "shape", index, shape.name,
                   "its vertices lie outside the scene's vertex pool");
            return nullptr;
        }
        if (!vertex_count_fits(shape, points.size())) {
            report(B2S_CODE_BAD_VERTEX_COUNT, "shape", index, shape.name,
                   std::to_string(points.size()) + " vertices do not make a Box2D shape");
            return nullptr;
        }
        if (!within_range(shape_check(shape, points), "shape", index, shape.name)) {
            return nullptr;
        }
        switch (shape.kind) {
        case B2S_SHAPE_KIND_CIRCLE: return make_circle(shape);
        case B2S_SHAPE_KIND_POLYGON: return make_polygon(shape, points);
        case B2S_SHAPE_KIND_EDGE: return make_edge(shape, points);
        case B2S_SHAPE_KIND_CHAIN: return make_chain(shape, points);
        }
        report(B2S_CODE_UNKNOWN_TYPE, "shape", index, shape.name,
               "unknown shape kind " + std::to_string(shape.kind));
        return nullptr;
    }

    bool vertices_of(const b2s_shape& shape, std::vector<b2Vec2>& points) const {
        uint64_t end = uint64_t{shape.vertices.first} + shape.vertices.count;
        if (end > view_.vertex_count) {
            return false;
        }
        for (uint32_t i = 0; i < shape.vertices.count; ++i) {
            points.push_back(to_b2(view_.vertices[shape.vertices.first + i]));
        }
        return true;
    }

    /// The points Box2D gets: every vertex, a circle's centre and radius, the centroid and
    /// the ghost vertices where they are used.
    static RangeCheck shape_check(const b2s_shape& shape, const std::vector<b2Vec2>& points) {
        using working_range::length;
        RangeCheck check;
        bool edge = shape.kind == B2S_SHAPE_KIND_EDGE;
        if (shape.kind == B2S_SHAPE_KIND_CIRCLE) {
            check.magnitude("Radius", shape.radius, length, "m");
            check.vector("Position", shape.position, length, "m");
        }
        for (size_t i = 0; i < points.size(); ++i) {
            std::string field = edge ? "Vertex" + std::to_string(i + 1)
                                     : "Vertex " + std::to_string(i);
            check.vector(field, b2s_vec2{points[i].x, points[i].y}, length, "m");
        }
        if (shape.kind == B2S_SHAPE_KIND_POLYGON && shape.centroid_given) {
            check.vector("Centroid", shape.centroid, length, "m");
        }
        bool ghosts = edge || (shape.kind == B2S_SHAPE_KIND_CHAIN && !shape.is_loop);
        if (ghosts && shape.has_prev_vertex) {
            check.vector(edge ? "Vertex0" : "PrevVertex", shape.prev_vertex, length, "m");
        }
        if (ghosts && shape.has_next_vertex) {
            check.vector(edge ? "Vertex3" : "NextVertex", shape.next_vertex, length, "m");
        }
        return check;
    }

    static bool vertex_count_fits(const b2s_shape& shape, size_t count) {
        switch (shape.kind) {
        case B2S_SHAPE_KIND_POLYGON: return count >= 2 && count <= b2_maxPolygonVertices;
        case B2S_SHAPE_KIND_EDGE: return count == 2;
        case B2S_SHAPE_KIND_CHAIN: return count >= (shape.is_loop ? 3u : 2u);
        default: return true;
        }
    }

    static std::unique_ptr<b2Shape> make_circle(const b2s_shape& shape) {
        auto circle = std::make_unique<b2CircleShape>();
        circle->m_radius = shape.radius;
        circle->m_p = to_b2(shape.position);
        return circle;
    }

    /// Two vertices are Box2D 2.1's SetAsEdge output: a line segment.
    static std::unique_ptr<b2Shape> make_polygon(const b2s_shape& shape,
                                                 const std::vector<b2Vec2>& points) {
        if (points.size() == 2) {
            auto edge = std::make_unique<b2EdgeShape>();
            edge->SetTwoSided(points[0], points[1]);
            return edge;
        }
        auto polygon = std::make_unique<b2PolygonShape>();
        polygon->Set(points.data(), static_cast<int32>(points.size()));
        if (shape.centroid_given) {
            polygon->m_centroid = to_b2(shape.centroid);
        }
        return polygon;
    }

    static std::unique_ptr<b2Shape> make_edge(const b2s_shape& shape,
                                              const std::vector<b2Vec2>& points) {
        auto edge = std::make_unique<b2EdgeShape>();
        if (shape.has_prev_vertex && shape.has_next_vertex) {
            edge->SetOneSided(to_b2(shape.prev_vertex), points[0], points[1],
                              to_b2(shape.next_vertex));
        } else {
            edge->SetTwoSided(points[0], points[1]);
        }
        return edge;
    }

    static std::unique_ptr<b2Shape> make_chain(const b2s_shape& shape,
                                               const std::vector<b2Vec2>& points) {
        auto chain = std::make_unique<b2ChainShape>();
        int32 count = static_cast<int32>(points.size());
        if (shape.is_loop) {
            chain->CreateLoop(points.data(), count);
            return chain;
        }
        b2Vec2 prev = shape.has_prev_vertex ? to_b2(shape.prev_vertex)
                                            : extrapolated(points[0], points[1]);
        b2Vec2 next = shape.has_next_vertex
                          ? to_b2(shape.next_vertex)
                          : extrapolated(points[count - 1], points[count - 2]);
        chain->CreateChain(points.data(), count, prev, next);
        return chain;
    }

    // ---- bodies and their fixtures

    void make_body(uint32_t index) {
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

    RangeCheck body_check(const b2s_body& body) const {
        namespace range = working_range;
        RangeCheck check;
        check.vector("Position", body.position, range::length, "m");
        check.magnitude("Angle", body.angle, range::angle, "rad");
        check.vector("LinearVelocity", body.linear_velocity, range::speed, "m/s");
        check.magnitude("AngularVelocity", body.angular_velocity, range::speed, "rad/s");
        check.magnitude("LinearDamping", body.linear_damping, range::damping, "1/s");
        check.magnitude("AngularDamping", body.angular_damping, range::damping, "1/s");
        check.magnitude("GravityScale", body.gravity_scale, range::gravity_scale, "");
        if (body.kind == B2S_BODY_KIND_DYNAMIC) {
            b2Vec2 gravity = body.gravity_scale * world_.GetGravity();
            check.vector("GravityScale times the world's gravity", to_b2s(gravity),
                         range::acceleration, "m/s^2");
        }
        if (body.mass_data.center_given) {
            check.vector("MassData Center", body.mass_data.center, range::length, "m");
        }
        return check;
    }

    /// The fixtures of a body that was not created: they depend on it.
    void skip_fixtures_of(uint32_t body_index, const b2s_body& body) {
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

    /// The mass Box2D 2.4 will give a dynamic body, as b2Body computes it: after each of
    /// its fixtures (ResetMassData, which asserts that an inertia it centres stays
    /// positive), then MassData. `check` fails when Box2D would assert or the result lies
    /// beyond the working range.
    b2MassData predicted_mass(const b2s_body& body, RangeCheck& check) const {
        std::vector<FixtureMass> created;
        b2MassData mass{0.0f, b2Vec2_zero, 0.0f};
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
            if (fixture.density > 0.0f) { // only then does CreateFixture reset the mass
                mass = reset_mass(created, created.size(), body.fixed_rotation);
                std::string with = "with fixture " + std::to_string(index) + " ";
                if (inertia_centred(created, created.size(), body.fixed_rotation) &&
                    !(mass.I > 0.0f)) {
                    check.fail(with + "it has no positive inertia about its centre of mass in "
                                      "Box2D 2.4's float arithmetic (which asserts)");
                }
                // Each new centre of mass moves the body's velocity (w x its shift): a centre
                // made NaN by a subnormal mass (0 * infinity) would stay in it.
                check.vector(with + "its centre of mass", to_b2s(mass.center),
                             working_range::length, "m");
            }
        }
        mass = with_mass_data(mass, body);
        check.zero_or_within("its mass", mass.mass, working_range::mass_min,
                             working_range::mass_max, "kg");
        check.vector("its centre of mass", to_b2s(mass.center), working_range::length, "m");
        check.zero_or_within("its inertia about the centre of mass", mass.I,
                             working_range::inertia_min, working_range::inertia_max, "kg m^2");
        return mass;
    }

    /// `mass` (from the fixtures, inertia about the centre) as apply_mass_data leaves it.
    static b2MassData with_mass_data(const b2MassData& mass, const b2s_body& body) {
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

    b2BodyDef body_def(uint32_t index, const b2s_body& body) {
        b2BodyDef def;
        def.type = static_cast<b2BodyType>(body.kind);
        def.position = to_b2(body.position);
        def.angle = body.angle;
        // Box2D 2.4 keeps the velocity a static body is created with and moves the body
        // by it whenever a joint puts it in an island; static bodies never move.
        if (body.kind != B2S_BODY_KIND_STATIC) {
            def.linearVelocity = to_b2(body.linear_velocity);
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
    float damping(uint32_t index, const b2s_body& body, float value, const char* field) {
        if (value >= 0.0f) {
            return value;
        }
        report(B2S_CODE_NEGATIVE_VALUE, "body", index, body.name,
               std::string(field) + " " + std::to_string(value) +
                   " is negative, which Box2D 2.4 does not allow; 0 was used");
        return 0.0f;
    }

    void make_fixtures(uint32_t body_index, const b2s_body& body, b2Body* created) {
        uint64_t end = uint64_t{body.fixtures.first} + body.fixtures.count;
        if (end > view_.fixture_id_count) {
            report(B2S_CODE_ID_OUT_OF_RANGE, "body", body_index, body.name,
                   "its fixture list lies outside the scene's fixture ID pool");
            return;
        }
        for (uint32_t slot = body.fixtures.first; slot < end; ++slot) {
            built_.fixtures[slot] = make_fixture(body_index, view_.fixture_ids[slot], created);
        }
    }

    bool shape_created(const b2s_fixture& fixture) const {
        return fixture.shape < shapes_.size() && shapes_[fixture.shape] != nullptr;
    }

    static RangeCheck fixture_check(const b2s_fixture& fixture) {
        RangeCheck check;
        check.magnitude("Density", fixture.density, working_range::density, "kg/m^2");
        check.magnitude("Friction", fixture.friction, working_range::friction, "");
        check.magnitude("Restitution", fixture.restitution, working_range::friction, "");
        return check;
    }

    /// Whether make_fixture will create fixture `index`.
    bool fixture_creatable(uint32_t index) const {
        return index < view_.fixture_count && shape_created(view_.fixtures[index]) &&
               fixture_check(view_.fixtures[index]).passed();
    }

    b2Fixture* make_fixture(uint32_t body_index, uint32_t index, b2Body* body) {
        std::string owner = "fixture " + std::to_string(index) + " of body " +
                            std::to_string(body_index);
        if (index >= view_.fixture_count) {
            report(B2S_CODE_ID_OUT_OF_RANGE, "fixture", index, nullptr,
                   owner + " does not exist");
            return nullptr;
        }
        const b2s_fixture& fixture = view_.fixtures[index];
        if (!shape_created(fixture)) {
            report(B2S_CODE_SKIPPED_DEPENDENT, "fixture", index, fixture.name,
                   owner + " names shape " + std::to_string(fixture.shape) +
                       ", which was not created; fixture skipped");
            return nullptr;
        }
        if (!within_range(fixture_check(fixture), "fixture", index, fixture.name,
                          owner + ": ")) {
            return nullptr;
        }
        b2FixtureDef def;
        def.shape = shapes_[fixture.shape].get();
        def.density = fixture.density;
        def.friction = fixture.friction;
        def.restitution = fixture.restitution;
        def.isSensor = fixture.is_sensor;
        def.filter.categoryBits = fixture.filter.category_bits;
        def.filter.maskBits = fixture.filter.mask_bits;
        def.filter.groupIndex = fixture.filter.group_index;
        return body->CreateFixture(&def);
    }

    /// A datum the file leaves out keeps the value Box2D computed from the fixtures.
    void apply_mass_data(uint32_t index, const b2s_body& body, b2Body* created) {
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

    static bool mass_data_given(const b2s_mass_data& given) {
        return given.mass_given || given.center_given || given.inertia_given;
    }

    /// `mass` (as b2Body::GetMassData gives it: inertia about the body origin) with what
    /// the body's MassData gives written over it.
    static b2MassData overwritten(b2MassData mass, const b2s_mass_data& given) {
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

    // ---- joints

    /// Sets the fields every joint has; false (and a report) when a body is missing.
    template <class Def>
    bool connect(uint32_t index, const b2s_joint& joint, Def& def) {
        b2Body* a = created_body(joint.body_a);
        b2Body* b = created_body(joint.body_b);
        if (a == nullptr || b == nullptr) {
            report(B2S_CODE_SKIPPED_DEPENDENT, "joint", index, joint.name,
                   "it names body " + std::to_string(a == nullptr ? joint.body_a : joint.body_b) +
                       ", which was not created; joint skipped");
            return false;
        }
        if (a == b) {
            report(B2S_CODE_JOINT_SELF_REFERENCE, "joint", index, joint.name,
                   "it connects a body to itself; joint skipped");
            return false;
        }
        def.bodyA = a;
        def.bodyB = b;
        def.collideConnected = joint.collide_connected;
        return true;
    }

    b2Body* created_body(uint32_t index) const {
        return index < built_.bodies.size() ? built_.bodies[index] : nullptr;
    }

    template <class Def>
    void create(uint32_t index, const Def& def) {
        built_.joints[index] = world_.CreateJoint(&def);
    }

    void make_joint(uint32_t index) {
        const b2s_joint& joint = view_.joints[index];
        // A joint on a body that was not created is reported as its dependent by connect.
        bool bodies_created = created_body(joint.body_a) != nullptr &&
                              created_body(joint.body_b) != nullptr;
        if (bodies_created && !within_range(joint_check(joint), "joint", index, joint.name)) {
            return;
        }
        switch (joint.kind) {
        case B2S_JOINT_KIND_REVOLUTE: return make_revolute(index, joint);
        case B2S_JOINT_KIND_PRISMATIC: return make_prismatic(index, joint);
        case B2S_JOINT_KIND_DISTANCE: return make_distance(index, joint);
        case B2S_JOINT_KIND_PULLEY: return make_pulley(index, joint);
        case B2S_JOINT_KIND_LINE: return make_line(index, joint);
        case B2S_JOINT_KIND_WELD: return make_weld(index, joint);
        case B2S_JOINT_KIND_FRICTION: return make_friction(index, joint);
        case B2S_JOINT_KIND_WHEEL: return make_wheel(index, joint);
        case B2S_JOINT_KIND_ROPE: return make_rope(index, joint);
        case B2S_JOINT_KIND_MOTOR: return make_motor(index, joint);
        }
        std::string what = joint.kind == B2S_JOINT_KIND_UNSUPPORTED
                               ? std::string("a Farseer-only joint")
                               : "unknown joint kind " + std::to_string(joint.kind);
        report(B2S_CODE_SKIPPED_JOINT, "joint", index, joint.name,
               what + " has no Box2D 2.4 equivalent; joint skipped");
    }

    /// The fields Box2D gets of the joint's kind, then how hard its bodies are to move at
    /// its anchors.
    RangeCheck joint_check(const b2s_joint& joint) const {
        namespace range = working_range;
        RangeCheck check;
        bool axis = false, spring = false, forces = false;
        b2s_vec2 anchor_a = joint.local_anchor_a, anchor_b = joint.local_anchor_b;
        switch (joint.kind) {
        case B2S_JOINT_KIND_REVOLUTE:
            check.magnitude("ReferenceAngle", joint.reference_angle, range::angle, "rad");
            check.magnitude("LowerAngle", joint.lower_limit, range::angle, "rad");
            check.magnitude("UpperAngle", joint.upper_limit, range::angle, "rad");
            check.magnitude("MotorSpeed", joint.motor_speed, range::speed, "rad/s");
            check.magnitude("MaxMotorTorque", joint.max_motor_torque, range::force, "N m");
            break;
        case B2S_JOINT_KIND_PRISMATIC:
            check.magnitude("ReferenceAngle", joint.reference_angle, range::angle, "rad");
            check.magnitude("MotorSpeed", joint.motor_speed, range::speed, "m/s");
            check.magnitude("MaxMotorForce", joint.max_motor_force, range::force, "N");
            [[fallthrough]];
        case B2S_JOINT_KIND_LINE: // its motor stays off
            axis = true;
            check.magnitude("LowerTranslation", joint.lower_limit, range::length, "m");
            check.magnitude("UpperTranslation", joint.upper_limit, range::length, "m");
            break;
        case B2S_JOINT_KIND_DISTANCE:
            spring = true;
            check.magnitude("Length", joint.length, range::length, "m");
            if (joint.frequency_hz > 0.0f && massless(joint.body_a) && massless(joint.body_b)) {
                // Its upper length, FLT_MAX, gives Box2D's solver an infinite bias that
                // only a body with mass multiplies into something other than NaN.
                check.fail("a spring (FrequencyHz > 0) between two bodies without mass, for "
                           "which Box2D 2.4's distance joint computes 0 * infinity = NaN");
            }
            break;
        case B2S_JOINT_KIND_ROPE:
            check.magnitude("MaxLength", joint.max_length, range::length, "m");
            break;
        case B2S_JOINT_KIND_PULLEY:
            check.vector("GroundAnchorA", joint.ground_anchor_a, range::length, "m");
            check.vector("GroundAnchorB", joint.ground_anchor_b, range::length, "m");
            check.magnitude("LengthA", joint.length_a, range::length, "m");
            check.magnitude("LengthB", joint.length_b, range::length, "m");
            check.magnitude("Ratio", joint.ratio, range::ratio, "");
            break;
        case B2S_JOINT_KIND_WHEEL:
            axis = spring = true;
            check.magnitude("MotorSpeed", joint.motor_speed, range::speed, "rad/s");
            check.magnitude("MaxMotorTorque", joint.max_motor_torque, range::force, "N m");
            break;
        case B2S_JOINT_KIND_WELD:
            spring = true;
            check.magnitude("ReferenceAngle", joint.reference_angle, range::angle, "rad");
            break;
        case B2S_JOINT_KIND_FRICTION: forces = true; break;
        case B2S_JOINT_KIND_MOTOR:
            forces = true;
            anchor_a = joint.linear_offset; // body B's origin, held there in A's frame
            anchor_b = b2s_vec2{0.0f, 0.0f};
            check.vector("LinearOffset", joint.linear_offset, range::length, "m");
            check.magnitude("AngularOffset", joint.angular_offset, range::angle, "rad");
            check.within("CorrectionFactor", joint.correction_factor, 0.0f, 1.0f, "");
            break;
        default: return check; // not created: reported by make_joint
        }
        if (joint.kind != B2S_JOINT_KIND_MOTOR) {
            check.vector("LocalAnchorA", joint.local_anchor_a, range::length, "m");
            check.vector("LocalAnchorB", joint.local_anchor_b, range::length, "m");
        }
        if (axis) {
            check.vector("LocalAxisA", joint.local_axis_a, range::length, "m");
            check.at_least("The length of LocalAxisA",
                           b2Vec2(joint.local_axis_a.x, joint.local_axis_a.y).Length(),
                           range::min_axis, "m");
        }
        if (spring) {
            check.magnitude("FrequencyHz", joint.frequency_hz, range::frequency, "Hz");
            check.magnitude("DampingRatio", joint.damping_ratio, range::frequency, "");
            check_stiffness(joint, check);
        }
        if (forces) {
            check.magnitude("MaxForce", joint.max_force, range::force, "N");
            check.magnitude("MaxTorque", joint.max_torque, range::force, "N m");
        }
        if (check.passed()) {
            check_anchors(joint, anchor_a, anchor_b, check);
        }
        return check;
    }

    bool massless(uint32_t body) const { return masses_[body].mass == 0.0f; }

    /// Box2D divides by h * (damping + h * stiffness): a spring whose stiffness underflows,
    /// from a tiny FrequencyHz or mass, makes that infinite. The stiffness is computed as
    /// make_distance, make_wheel and make_weld compute it.
    void check_stiffness(const b2s_joint& joint, RangeCheck& check) const {
        if (!check.passed() || !(joint.frequency_hz > 0.0f)) {
            return;
        }
        const b2Body* a = built_.bodies[joint.body_a];
        const b2Body* b = built_.bodies[joint.body_b];
        float stiffness = 0.0f, damping = 0.0f;
        bool angular = joint.kind == B2S_JOINT_KIND_WELD;
        (angular ? b2AngularStiffness : b2LinearStiffness)(stiffness, damping, joint.frequency_hz,
                                                           joint.damping_ratio, a, b);
        if (stiffness != 0.0f && !(stiffness >= working_range::min_stiffness)) {
            check.fail("FrequencyHz " + decimal(joint.frequency_hz) + " gives a stiffness of " +
                       decimal(stiffness) + (angular ? " N m/rad" : " N/m") +
                       " with these bodies, beyond Box2D 2.4's working range (0 or at least " +
                       rounded(working_range::min_stiffness) + ")");
        }
    }

    /// Box2D's joint solvers work with 1/m + r^2/I of each body at the joint's anchor, r
    /// from the body's centre of mass: past working_range::compliance its products
    /// overflow. Revolute, friction and motor joints invert 2x2 matrices of such terms,
    /// prismatic and weld joints 3x3 ones, whose determinants cancel terms (r/g)^2 and
    /// (r/g)^4 times larger than what is left (g = sqrt(I/m), the radius of gyration): past
    /// working_range::lever_2x2 and lever_3x3, float's 24 bits no longer hold what is left
    /// (at 30, a 3x3 determinant is already 3% off; at 100, its sign is noise) and the
    /// inverse explodes. A prismatic joint's lever on body A reaches body B's anchor.
    void check_anchors(const b2s_joint& joint, b2s_vec2 anchor_a, b2s_vec2 anchor_b,
                       RangeCheck& check) const {
        b2Vec2 a = to_b2(anchor_a), b = to_b2(anchor_b);
        float lever = 0.0f; // none: Box2D solves the joint's rows one by one
        switch (joint.kind) {
        case B2S_JOINT_KIND_REVOLUTE:
        case B2S_JOINT_KIND_FRICTION:
        case B2S_JOINT_KIND_MOTOR: lever = working_range::lever_2x2; break;
        case B2S_JOINT_KIND_PRISMATIC:
        case B2S_JOINT_KIND_WELD: lever = working_range::lever_3x3; break;
        default: break;
        }
        const b2MassData& mass_a = masses_[joint.body_a];
        float lever_a = b2Distance(a, mass_a.center);
        if (joint.kind == B2S_JOINT_KIND_PRISMATIC) {
            const b2Body* body_a = built_.bodies[joint.body_a];
            b2Vec2 b_on_a = body_a->GetLocalPoint(built_.bodies[joint.body_b]->GetWorldPoint(b));
            lever_a = std::max(lever_a, b2Distance(b_on_a, mass_a.center));
        }
        const char* field_a = joint.kind == B2S_JOINT_KIND_MOTOR ? "LinearOffset" : "LocalAnchorA";
        check_anchor(field_a, joint.body_a, lever_a, lever, check);
        check_anchor("LocalAnchorB", joint.body_b,
                     b2Distance(b, masses_[joint.body_b].center), lever, check);
    }

    void check_anchor(const char* field, uint32_t body, float r, float lever,
                      RangeCheck& check) const {
        const b2MassData& mass = masses_[body];
        if (mass.mass == 0.0f) { // it does not move
            return;
        }
        float compliance = 1.0f / mass.mass + (mass.I > 0.0f ? r * r / mass.I : 0.0f);
        std::string where = std::string(field) + ": the joint acts " + decimal(r) +
                            " m from the centre of mass of body " + std::to_string(body) +
                            " (mass " + decimal(mass.mass) + " kg, inertia " +
                            decimal(mass.I) + " kg m^2), ";
        if (!(compliance <= working_range::compliance)) {
            check.fail(where + "where 1/m + r^2/I = " + rounded(compliance) +
                       " 1/kg lies beyond Box2D 2.4's working range (at most " +
                       rounded(working_range::compliance) + " 1/kg)");
        } else if (lever > 0.0f && mass.I > 0.0f &&
                   !(r <= lever * std::sqrt(mass.I / mass.mass))) {
            check.fail(where + rounded(r / std::sqrt(mass.I / mass.mass)) +
                       " radii of gyration out, beyond Box2D 2.4's working range for this "
                       "joint (at most " + rounded(lever) + ")");
        }
    }

    void make_revolute(uint32_t index, const b2s_joint& joint) {
        b2RevoluteJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.referenceAngle = joint.reference_angle;
        def.enableLimit = joint.enable_limit;
        def.lowerAngle = joint.lower_limit;
        def.upperAngle = joint.upper_limit;
        def.enableMotor = joint.enable_motor;
        def.motorSpeed = joint.motor_speed;
        def.maxMotorTorque = joint.max_motor_torque;
        create(index, def);
    }

    void make_prismatic(uint32_t index, const b2s_joint& joint) {
        b2PrismaticJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.localAxisA = to_b2(joint.local_axis_a);
        def.referenceAngle = joint.reference_angle;
        def.enableLimit = joint.enable_limit;
        def.lowerTranslation = joint.lower_limit;
        def.upperTranslation = joint.upper_limit;
        if (def.lowerTranslation > def.upperTranslation) {
            // Only a disabled limit gets here (the loader refuses an enabled one), and Box2D
            // 2.4's prismatic joint asserts against it all the same.
            std::swap(def.lowerTranslation, def.upperTranslation);
            report(B2S_CODE_BAD_LIMIT, "joint", index, joint.name,
                   "its disabled limit has LowerTranslation " + decimal(joint.lower_limit) +
                       " above UpperTranslation " + decimal(joint.upper_limit) +
                       ", which Box2D 2.4 asserts against; they were passed swapped");
        }
        def.enableMotor = joint.enable_motor;
        def.maxMotorForce = joint.max_motor_force;
        def.motorSpeed = joint.motor_speed;
        create(index, def);
    }

    /// FrequencyHz 0 is a rigid rod. Box2D 2.4 reads stiffness 0 with the default
    /// min/max lengths as a slack rope, so the rod pins both lengths to its own.
    void make_distance(uint32_t index, const b2s_joint& joint) {
        b2DistanceJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.length = joint.length;
        if (joint.frequency_hz > 0.0f) {
            def.minLength = 0.0f;
            def.maxLength = FLT_MAX;
            b2LinearStiffness(def.stiffness, def.damping, joint.frequency_hz,
                              joint.damping_ratio, def.bodyA, def.bodyB);
        } else {
            def.minLength = joint.length;
            def.maxLength = joint.length;
        }
        create(index, def);
    }

    /// Box2D 2.4 has no rope joint: a distance joint that is slack up to MaxLength.
    void make_rope(uint32_t index, const b2s_joint& joint) {
        b2DistanceJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.length = joint.max_length;
        def.minLength = 0.0f;
        def.maxLength = joint.max_length;
        create(index, def);
    }

    /// MaxLengthA/B (Box2D 2.1 only) have no 2.4 field and are dropped.
    void make_pulley(uint32_t index, const b2s_joint& joint) {
        b2PulleyJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        def.groundAnchorA = to_b2(joint.ground_anchor_a);
        def.groundAnchorB = to_b2(joint.ground_anchor_b);
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.lengthA = joint.length_a;
        def.lengthB = joint.length_b;
        def.ratio = joint.ratio;
        create(index, def);
    }

    /// Box2D 2.4's wheel joint, unlike its prismatic joint, does not normalise its axis,
    /// and a longer one would scale the translation; an axis is a direction. (The loader
    /// rejects a zero axis.)
    template <class Def>
    static void set_anchors_and_axis(const b2s_joint& joint, Def& def) {
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.localAxisA = to_b2(joint.local_axis_a);
        def.localAxisA.Normalize();
    }

    /// Box2D 2.1's line joint is a wheel joint without a spring. Its motor drove the
    /// translation; the wheel joint's motor drives the rotation, so it stays off.
    void make_line(uint32_t index, const b2s_joint& joint) {
        b2WheelJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        set_anchors_and_axis(joint, def);
        def.enableLimit = joint.enable_limit;
        def.lowerTranslation = joint.lower_limit;
        def.upperTranslation = joint.upper_limit;
        def.stiffness = 0.0f;
        def.damping = 0.0f;
        if (joint.enable_motor) {
            report(B2S_CODE_LOSSY_LINE_MOTOR, "joint", index, joint.name,
                   "Box2D 2.4 has no linear motor on a line (wheel) joint; the motor is off");
        }
        create(index, def);
    }

    void make_wheel(uint32_t index, const b2s_joint& joint) {
        b2WheelJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        set_anchors_and_axis(joint, def);
        def.enableMotor = joint.enable_motor;
        def.maxMotorTorque = joint.max_motor_torque;
        def.motorSpeed = joint.motor_speed;
        b2LinearStiffness(def.stiffness, def.damping, joint.frequency_hz, joint.damping_ratio,
                          def.bodyA, def.bodyB);
        create(index, def);
    }

    void make_weld(uint32_t index, const b2s_joint& joint) {
        b2WeldJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.referenceAngle = joint.reference_angle;
        if (joint.frequency_hz > 0.0f) {
            b2AngularStiffness(def.stiffness, def.damping, joint.frequency_hz,
                               joint.damping_ratio, def.bodyA, def.bodyB);
        }
        create(index, def);
    }

    void make_friction(uint32_t index, const b2s_joint& joint) {
        b2FrictionJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.maxForce = joint.max_force;
        def.maxTorque = joint.max_torque;
        create(index, def);
    }

    void make_motor(uint32_t index, const b2s_joint& joint) {
        b2MotorJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        def.linearOffset = to_b2(joint.linear_offset);
        def.angularOffset = joint.angular_offset;
        def.maxForce = joint.max_force;
        def.maxTorque = joint.max_torque;
        def.correctionFactor = joint.correction_factor;
        create(index, def);
    }

    void make_gear(uint32_t index) {
        const b2s_joint& joint = view_.joints[index];
        b2GearJointDef def;
        def.joint1 = gear_input(index, joint, joint.joint_a);
        def.joint2 = gear_input(index, joint, joint.joint_b);
        if (def.joint1 == nullptr || def.joint2 == nullptr || !connect(index, joint, def)) {
            return;
        }
        RangeCheck check;
        check.magnitude("Ratio", joint.ratio, working_range::ratio, "");
        if (!within_range(check, "joint", index, joint.name)) {
            return;
        }
        def.ratio = joint.ratio;
        create(index, def);
    }

    /// The created revolute or prismatic joint a gear couples, or nullptr (reported).
    b2Joint* gear_input(uint32_t index, const b2s_joint& gear, uint32_t input) {
        b2Joint* coupled = input < built_.joints.size() ? built_.joints[input] : nullptr;
        if (coupled == nullptr) {
            report(B2S_CODE_SKIPPED_DEPENDENT, "joint", index, gear.name,
                   "the gear couples joint " + std::to_string(input) +
                       ", which was not created; gear skipped");
            return nullptr;
        }
        b2JointType type = coupled->GetType();
        if (type != e_revoluteJoint && type != e_prismaticJoint) {
            report(B2S_CODE_BAD_GEAR_JOINT, "joint", index, gear.name,
                   "the gear couples joint " + std::to_string(input) +
                       ", which is not revolute or prismatic; gear skipped");
            return nullptr;
        }
        if (coupled->GetBodyB()->GetType() != b2_dynamicBody) {
            report(B2S_CODE_BAD_GEAR_JOINT, "joint", index, gear.name,
                   "the gear couples joint " + std::to_string(input) +
                       ", whose body B is not dynamic, which Box2D 2.4 asserts against; "
                       "gear skipped");
            return nullptr;
        }
        return coupled;
    }

    const struct b2s_scene_view& view_;
    b2World& world_;
    std::vector<std::unique_ptr<b2Shape>> shapes_; // indexed like the scene's shapes
    std::vector<b2MassData> masses_; // each dynamic body's, I about its centre of mass
    Built built_;
};

} // namespace detail

inline b2Vec2 scene_gravity(const b2s_scene* scene, b2Vec2 fallback) {
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (view == nullptr || !view->gravity_given ||
        !detail::gravity_check(view->gravity).passed()) {
        return fallback;
    }
    return detail::to_b2(view->gravity);
}

inline Built build_world(const b2s_scene* scene, b2World& world) {
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (view == nullptr) {
        return Built{};
    }
    return detail::WorldBuilder(*view, world).run();
}

// ---- capture: a live b2World back into a scene, so that a host can save its level

/// The code of a capture report for a value the format cannot hold exactly, written as near
/// as it can (the message says what changed). The library is to name it
/// B2S_CODE_LOSSY_CAPTURE ("lossy-capture"); until it does, this stand-in lies at the end of
/// the adapter's block of codes, where none is, and b2s_code_name does not know it.
inline constexpr b2s_code lossy_capture_code = B2S_CODE_LOSSY_CAPTURE;

/// A Name and UserData that capture_world gives one object; an empty string gives none.
struct Label {
    std::string name;
    /// UserData as XML content, written verbatim; it wins over type_name and value.
    std::string user_data_raw;
    /// UserData in the editor's form: a type name (`System.String`) and its value.
    std::string user_data_type;
    std::string user_data_value;
};

/// Names and UserData for what capture_world writes, usually found from each object's
/// Box2D user data. Override what you need; the rest stays unnamed. Objects that Box2D
/// holds once per fixture (its shape, its material) are shared in the scene only when
/// their labels agree.
class Namer {
public:
    virtual ~Namer() = default;
    virtual Label body(b2Body&) const { return {}; }
    virtual Label fixture(b2Fixture&) const { return {}; }
    virtual Label joint(b2Joint&) const { return {}; }
    /// Shapes have a Name and no UserData.
    virtual std::string shape(b2Fixture&) const { return {}; }
};

/// A new scene holding `world`: its gravity, bodies in their current state, fixtures and
/// shapes (equal ones shared, as the editor wrote them) and joints, in creation order, so
/// that build_world recreates them in that order and the rebuilt world evolves bit for bit
/// like this one. Derived values are inverted exactly: MassData is written only where it
/// differs from what the fixtures give, spring stiffness and damping become the
/// FrequencyHz and DampingRatio that give back the same bits, a polygon keeps its centroid.
/// Appends to `reports` what the scene does not hold (a mouse joint, a gear on it: not
/// written) or holds only approximately (lossy_capture_code). The caller owns the scene
/// (b2s_scene_free); nullptr only if the library fails to finish it (reported).
///
/// Exactness needs the world to be the scene build_world would make: each body created
/// with its fixtures before the next, gears after every other joint, nothing destroyed
/// (Box2D recycles broad-phase proxies). A world captured in motion keeps each body's
/// state exactly, but not what Box2D carries from step to step (contacts, warm-starting
/// impulses, sleep timers), so it evolves alike, not bit for bit. The world's switches
/// (SetAllowSleeping, SetWarmStarting, ...) are the host's, not the scene's.
/// The world is not changed; it is not const because Box2D 2.4 declares GetUserData,
/// GetBodyA and GetJoint1 non-const. Call it outside b2World::Step.
inline b2s_scene* capture_world(b2World& world, std::vector<Report>& reports,
                                const Namer* namer = nullptr);

namespace detail {

template <class T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// `x` moved by `steps` representable floats (negative: down).
inline float ulps_away(float x, int steps) {
    float toward = steps < 0 ? -FLT_MAX : FLT_MAX;
    for (int i = 0; i < std::abs(steps); ++i) {
        x = std::nextafter(x, toward);
    }
    return x;
}

/// Stores in `x` an argument for which `f`, which never decreases, gives `target`,
/// searching the floats next to `guess` (an inverse computed in floats is off by a few
/// ulps). Zeros of either sign count as equal. When no float gives `target` exactly, `x`
/// is the one that comes nearest and the result is false.
template <class F>
bool solve_nondecreasing(F f, float target, float guess, float& x) {
    x = guess;
    float y = f(x);
    if (y == target) {
        return true;
    }
    const bool upward = y < target;
    for (int i = 0; i < 64; ++i) {
        float next = std::nextafter(x, upward ? FLT_MAX : -FLT_MAX);
        float z = f(next);
        if (z == target) {
            x = next;
            return true;
        }
        if ((z < target) != upward) { // stepped over: no float gives it
            if (std::fabs(z - target) < std::fabs(y - target)) {
                x = next;
            }
            return false;
        }
        x = next;
        y = z;
    }
    return false;
}

/// An axis that b2Vec2::Normalize turns into `unit` bit for bit: Box2D normalises a
/// prismatic axis, and build_world every axis it is given. A vector and twice it normalise
/// alike, so scales in [1, 2) with their neighbouring floats cover the candidates (99.6%
/// of random axes have one); the axis itself comes first.
inline bool axis_normalising_to(b2Vec2 unit, b2Vec2& axis) {
    const int offsets[] = {0, -1, 1};
    for (int i = 0; i < 32; ++i) {
        float scale = 1.0f + static_cast<float>(i) / 32.0f;
        for (int dx : offsets) {
            for (int dy : offsets) {
                b2Vec2 candidate(ulps_away(unit.x * scale, dx), ulps_away(unit.y * scale, dy));
                b2Vec2 normalised = candidate;
                normalised.Normalize();
                if (same_bits(normalised, unit)) {
                    axis = candidate;
                    return true;
                }
            }
        }
    }
    axis = unit;
    return false;
}

/// b2LinearStiffness or b2AngularStiffness.
using StiffnessFunction = void (*)(float&, float&, float, float, const b2Body*, const b2Body*);

/// The FrequencyHz and DampingRatio from which `stiffness_of`, called by build_world on
/// the same two bodies (their masses are final by then), gives back `stiffness` and
/// `damping` bit for bit; false when no floats do (the nearest are stored). A zero
/// stiffness is no spring: Box2D 2.4 then ignores the damping.
inline bool spring_giving(StiffnessFunction stiffness_of, const b2Body* a, const b2Body* b,
                          float stiffness, float damping, float& frequency, float& ratio) {
    frequency = 0.0f;
    ratio = 0.0f;
    if (stiffness == 0.0f) {
        return true;
    }
    auto stiffness_at = [&](float hz) {
        float k = 0.0f, d = 0.0f;
        stiffness_of(k, d, hz, 0.0f, a, b);
        return k;
    };
    float per_hz_squared = stiffness_at(1.0f);
    if (!(per_hz_squared > 0.0f)) { // neither body has mass: no frequency gives a stiffness
        return false;
    }
    bool exact = solve_nondecreasing(stiffness_at, stiffness,
                                     std::sqrt(stiffness / per_hz_squared), frequency);
    auto damping_at = [&](float r) {
        float k = 0.0f, d = 0.0f;
        stiffness_of(k, d, frequency, r, a, b);
        return d;
    };
    float per_ratio = damping_at(1.0f);
    return solve_nondecreasing(damping_at, damping, damping / per_ratio, ratio) && exact;
}

/// The polygon build_world makes from the vertices and centroid capture writes.
inline b2PolygonShape polygon_rebuilt(const b2PolygonShape& polygon) {
    b2PolygonShape rebuilt;
    rebuilt.Set(polygon.m_vertices, polygon.m_count);
    rebuilt.m_centroid = polygon.m_centroid;
    return rebuilt;
}

/// b2PolygonShape::Set starts its hull at the rightmost vertex; SetAsBox, for one, does not.
inline bool same_polygon(const b2PolygonShape& a, const b2PolygonShape& b) {
    size_t bytes = static_cast<size_t>(a.m_count) * sizeof(b2Vec2);
    return a.m_count == b.m_count && std::memcmp(a.m_vertices, b.m_vertices, bytes) == 0 &&
           std::memcmp(a.m_normals, b.m_normals, bytes) == 0;
}

/// CreateLoop's layout: the first vertex repeated at the end, the ghosts next to the seam.
inline bool is_loop(const b2ChainShape& chain) {
    const b2Vec2* v = chain.m_vertices;
    int32 n = chain.m_count;
    return n >= 4 && same_bits(v[n - 1], v[0]) && same_bits(chain.m_prevVertex, v[n - 2]) &&
           same_bits(chain.m_nextVertex, v[1]);
}

/// Appends a value's bytes to a de-duplication key.
template <class T>
void append_key(std::string& key, const T& value) {
    key.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

inline void append_key(std::string& key, const std::string& text) {
    append_key(key, text.size());
    key += text;
}

inline b2s_str name_of(const std::string& name) {
    return name.empty() ? nullptr : name.c_str();
}

/// One capture: the world, the builder filling up, and what each Box2D object became.
class WorldCapture {
public:
    WorldCapture(b2World& world, std::vector<Report>& reports, const Namer* namer)
        : world_(world), reports_(reports), namer_(namer != nullptr ? namer : &unnamed_) {}

    b2s_scene* run() {
        b2s_vec2 gravity = to_b2s(world_.GetGravity());
        b2s_builder_set_gravity(builder_, &gravity, nullptr); // refused only if not finite
        for (b2Body* body : creation_order(world_.GetBodyList())) {
            capture_body(*body);
        }
        for (b2Joint* joint : creation_order(world_.GetJointList())) {
            capture_joint(*joint);
            ++joint_index_;
        }
        b2s_scene* scene = nullptr;
        b2s_error error{};
        b2s_code code = b2s_builder_finish(builder_, &scene, &error);
        if (code != B2S_CODE_OK) {
            report(code, "world", 0, std::string(), error.message);
        }
        return scene;
    }

private:
    /// Box2D prepends what it creates to its lists.
    template <class T>
    static std::vector<T*> creation_order(T* newest) {
        std::vector<T*> objects;
        for (T* object = newest; object != nullptr; object = object->GetNext()) {
            objects.push_back(object);
        }
        return std::vector<T*>(objects.rbegin(), objects.rend());
    }

    void report(b2s_code code, const char* object, uint32_t index, const std::string& name,
                std::string message) {
        reports_.push_back(Report{code, object, index, name, std::move(message)});
    }

    void lossy(const char* object, uint32_t index, const std::string& name, std::string message) {
        report(lossy_capture_code, object, index, name, std::move(message));
    }

    /// Whether the builder took a record; a refusal is reported with the builder's code.
    bool accepted(b2s_code code, const b2s_error& error, const char* object, uint32_t index,
                  const std::string& name) {
        if (code != B2S_CODE_OK) {
            report(code, object, index, name,
                   std::string(error.message) + "; not written");
        }
        return code == B2S_CODE_OK;
    }

    /// The index of the label's UserData in the scene, or B2S_NONE.
    uint32_t user_data(const Label& label, const char* object, uint32_t index) {
        if (label.user_data_raw.empty() && label.user_data_type.empty() &&
            label.user_data_value.empty()) {
            return B2S_NONE;
        }
        b2s_user_data data{name_of(label.user_data_raw), name_of(label.user_data_type),
                           name_of(label.user_data_value)};
        uint32_t added = B2S_NONE;
        b2s_error error{};
        b2s_code code = b2s_builder_add_user_data(builder_, &data, &added, &error);
        return accepted(code, error, object, index, label.name) ? added : B2S_NONE;
    }

    // ---- shapes and fixtures, each equal one written once

    /// The scene shape of the fixture's shape, or B2S_NONE (reported).
    uint32_t scene_shape(b2Fixture& fixture, uint32_t index) {
        std::string name = namer_->shape(fixture);
        b2s_shape shape{};
        std::vector<b2s_vec2> vertices;
        if (!shape_record(*fixture.GetShape(), shape, vertices)) {
            report(B2S_CODE_UNKNOWN_TYPE, "shape", index, name,
                   "Box2D shape type " + std::to_string(fixture.GetType()) +
                       " has no Box2Scene form; not written");
            return B2S_NONE;
        }
        shape.name = name_of(name);
        std::string key = shape_key(shape, vertices, name);
        auto found = shapes_.find(key);
        if (found != shapes_.end()) {
            return found->second;
        }
        uint32_t added = B2S_NONE;
        b2s_error error{};
        b2s_code code = b2s_builder_add_shape(builder_, &shape, vertices.data(),
                                              static_cast<uint32_t>(vertices.size()), &added,
                                              &error);
        if (!accepted(code, error, "shape", index, name)) {
            return B2S_NONE;
        }
        report_inexact_shape(*fixture.GetShape(), index, name);
        shapes_.emplace(key, added);
        return added;
    }

    /// False for a shape type Box2D 2.4 does not have.
    static bool shape_record(const b2Shape& shape, b2s_shape& out,
                             std::vector<b2s_vec2>& vertices) {
        switch (shape.GetType()) {
        case b2Shape::e_circle:
            circle_record(static_cast<const b2CircleShape&>(shape), out);
            return true;
        case b2Shape::e_polygon:
            polygon_record(static_cast<const b2PolygonShape&>(shape), out, vertices);
            return true;
        case b2Shape::e_edge:
            edge_record(static_cast<const b2EdgeShape&>(shape), out, vertices);
            return true;
        case b2Shape::e_chain:
            chain_record(static_cast<const b2ChainShape&>(shape), out, vertices);
            return true;
        default: return false;
        }
    }

    static void circle_record(const b2CircleShape& circle, b2s_shape& out) {
        b2s_shape_default(B2S_SHAPE_KIND_CIRCLE, &out);
        out.radius = circle.m_radius;
        out.position = to_b2s(circle.m_p);
    }

    /// Box2D keeps the hull; its centroid is always written, so that it comes back exactly
    /// even where the host set it.
    static void polygon_record(const b2PolygonShape& polygon, b2s_shape& out,
                               std::vector<b2s_vec2>& vertices) {
        b2s_shape_default(B2S_SHAPE_KIND_POLYGON, &out);
        for (int32 i = 0; i < polygon.m_count; ++i) {
            vertices.push_back(to_b2s(polygon.m_vertices[i]));
        }
        out.centroid = to_b2s(polygon.m_centroid);
        out.centroid_given = true;
    }

    /// A two-sided edge is Version 1's two-vertex polygon; a one-sided one an Edge with
    /// both ghost vertices, as SetOneSided takes them.
    static void edge_record(const b2EdgeShape& edge, b2s_shape& out,
                            std::vector<b2s_vec2>& vertices) {
        vertices = {to_b2s(edge.m_vertex1), to_b2s(edge.m_vertex2)};
        if (!edge.m_oneSided) {
            b2s_shape_default(B2S_SHAPE_KIND_POLYGON, &out);
            return;
        }
        b2s_shape_default(B2S_SHAPE_KIND_EDGE, &out);
        out.prev_vertex = to_b2s(edge.m_vertex0);
        out.next_vertex = to_b2s(edge.m_vertex3);
        out.has_prev_vertex = true;
        out.has_next_vertex = true;
    }

    static void chain_record(const b2ChainShape& chain, b2s_shape& out,
                             std::vector<b2s_vec2>& vertices) {
        b2s_shape_default(B2S_SHAPE_KIND_CHAIN, &out);
        out.is_loop = is_loop(chain);
        int32 count = out.is_loop ? chain.m_count - 1 : chain.m_count;
        for (int32 i = 0; i < count; ++i) {
            vertices.push_back(to_b2s(chain.m_vertices[i]));
        }
        if (!out.is_loop) {
            out.prev_vertex = to_b2s(chain.m_prevVertex);
            out.next_vertex = to_b2s(chain.m_nextVertex);
            out.has_prev_vertex = true;
            out.has_next_vertex = true;
        }
    }

    static std::string shape_key(const b2s_shape& s, const std::vector<b2s_vec2>& vertices,
                                 const std::string& name) {
        std::string key;
        append_key(key, s.kind);
        append_key(key, s.radius);
        append_key(key, s.position);
        append_key(key, s.centroid);
        append_key(key, s.centroid_given);
        append_key(key, s.prev_vertex);
        append_key(key, s.next_vertex);
        append_key(key, s.has_prev_vertex);
        append_key(key, s.has_next_vertex);
        append_key(key, s.is_loop);
        append_key(key, vertices.size());
        key.append(reinterpret_cast<const char*>(vertices.data()),
                   vertices.size() * sizeof(b2s_vec2));
        append_key(key, name);
        return key;
    }

    /// What build_world will not make exactly as Box2D holds it.
    void report_inexact_shape(const b2Shape& shape, uint32_t index, const std::string& name) {
        if (shape.GetType() != b2Shape::e_circle && shape.m_radius != b2_polygonRadius) {
            lossy("shape", index, name,
                  "its skin radius " + decimal(shape.m_radius) +
                      " is not Box2D's b2_polygonRadius, which the format implies");
        }
        if (shape.GetType() == b2Shape::e_polygon) {
            const auto& polygon = static_cast<const b2PolygonShape&>(shape);
            if (!same_polygon(polygon_rebuilt(polygon), polygon)) {
                lossy("shape", index, name,
                      "b2PolygonShape::Set, which build_world uses, orders these vertices "
                      "from another first vertex (as after SetAsBox): the same polygon, but "
                      "its contacts may be solved in another order");
            }
        }
    }

    /// The mass build_world's Box2D will compute for the fixture.
    static b2MassData rebuilt_mass(const b2Fixture& fixture) {
        b2MassData mass;
        if (fixture.GetType() == b2Shape::e_polygon) {
            const auto& polygon = static_cast<const b2PolygonShape&>(*fixture.GetShape());
            polygon_rebuilt(polygon).ComputeMass(&mass, fixture.GetDensity());
        } else {
            fixture.GetMassData(&mass);
        }
        return mass;
    }

    /// The scene fixture for a fixture, or B2S_NONE (reported).
    uint32_t scene_fixture(b2Fixture& fixture, uint32_t index) {
        uint32_t shape = scene_shape(fixture, index);
        Label label = namer_->fixture(fixture);
        if (shape == B2S_NONE) {
            report(B2S_CODE_SKIPPED_DEPENDENT, "fixture", index, label.name,
                   "its shape was not written; not written");
            return B2S_NONE;
        }
        report_fields_not_written(fixture, index, label.name);
        std::string key = fixture_key(fixture, shape, label);
        auto found = fixtures_.find(key);
        if (found != fixtures_.end()) {
            return found->second;
        }
        b2s_fixture record;
        b2s_fixture_default(&record);
        record.name = name_of(label.name);
        record.shape = shape;
        record.density = fixture.GetDensity();
        record.friction = fixture.GetFriction();
        record.restitution = fixture.GetRestitution();
        record.is_sensor = fixture.IsSensor();
        const b2Filter& filter = fixture.GetFilterData();
        record.filter = b2s_filter{filter.categoryBits, filter.maskBits, filter.groupIndex};
        record.user_data = user_data(label, "fixture", index);
        uint32_t added = B2S_NONE;
        b2s_error error{};
        b2s_code code = b2s_builder_add_fixture(builder_, &record, &added, &error);
        if (!accepted(code, error, "fixture", index, label.name)) {
            return B2S_NONE;
        }
        fixtures_.emplace(key, added);
        return added;
    }

    void report_fields_not_written(const b2Fixture& fixture, uint32_t index,
                                   const std::string& name) {
        if (fixture.GetRestitutionThreshold() != b2FixtureDef().restitutionThreshold) {
            lossy("fixture", index, name,
                  "the format has no restitution threshold; " +
                      decimal(fixture.GetRestitutionThreshold()) +
                      " becomes Box2D's default");
        }
    }

    static std::string fixture_key(const b2Fixture& fixture, uint32_t shape, const Label& label) {
        std::string key;
        append_key(key, shape);
        append_key(key, fixture.GetDensity());
        append_key(key, fixture.GetFriction());
        append_key(key, fixture.GetRestitution());
        append_key(key, fixture.IsSensor());
        append_key(key, fixture.GetFilterData().categoryBits);
        append_key(key, fixture.GetFilterData().maskBits);
        append_key(key, fixture.GetFilterData().groupIndex);
        append_key(key, label.name);
        append_key(key, label.user_data_raw);
        append_key(key, label.user_data_type);
        append_key(key, label.user_data_value);
        return key;
    }

    // ---- bodies

    void capture_body(b2Body& body) {
        uint32_t index = body_index_++;
        std::vector<uint32_t> fixture_ids;
        std::vector<FixtureMass> created;
        for (b2Fixture* fixture : creation_order(body.GetFixtureList())) {
            uint32_t id = scene_fixture(*fixture, fixture_index_++);
            if (id != B2S_NONE) {
                fixture_ids.push_back(id);
                created.push_back(FixtureMass{fixture->GetDensity(), rebuilt_mass(*fixture)});
            }
        }
        Label label = namer_->body(body);
        b2s_body record;
        b2s_body_default(static_cast<b2s_body_kind>(body.GetType()), &record);
        record.name = name_of(label.name);
        record.position = to_b2s(body.GetPosition());
        record.angle = body.GetAngle();
        record.angular_velocity = body.GetAngularVelocity();
        record.linear_damping = body.GetLinearDamping();
        record.angular_damping = body.GetAngularDamping();
        record.gravity_scale = body.GetGravityScale();
        record.active = body.IsEnabled();
        record.allow_sleep = body.IsSleepingAllowed();
        // Box2D never marks a static body awake, and ignores the flag when it makes one.
        record.awake = body.GetType() == b2_staticBody || body.IsAwake();
        record.bullet = body.IsBullet();
        record.fixed_rotation = body.IsFixedRotation();
        record.mass_data = mass_data(body, created, index, label.name);
        record.linear_velocity = to_b2s(linear_velocity(body, created, record.mass_data, index,
                                                        label.name));
        record.user_data = user_data(label, "body", index);
        uint32_t added = B2S_NONE;
        b2s_error error{};
        b2s_code code = b2s_builder_add_body(builder_, &record, fixture_ids.data(),
                                             static_cast<uint32_t>(fixture_ids.size()), &added,
                                             &error);
        if (accepted(code, error, "body", index, label.name)) {
            bodies_.emplace(&body, added);
        }
    }

    static bool given(const b2s_mass_data& m) {
        return m.mass_given || m.center_given || m.inertia_given;
    }

    /// None when the fixtures give the body's mass (build_world's Box2D then computes it
    /// the same way); else the data that differ from the fixtures'. Box2D keeps the inertia
    /// about the centre, m_I = I - m|c|^2 from SetMassData, which GetInertia turns back
    /// into I: writing GetInertia gives back m_I (in each of a million random cases tried),
    /// except where m_I is 0 (SetMassData with no inertia), which only Inertia 0 gives.
    b2s_mass_data mass_data(const b2Body& body, const std::vector<FixtureMass>& created,
                            uint32_t index, const std::string& name) {
        b2s_body defaults;
        b2s_body_default(B2S_BODY_KIND_DYNAMIC, &defaults);
        b2s_mass_data out = defaults.mass_data;
        if (body.GetType() != b2_dynamicBody) { // SetMassData ignores other bodies
            return out;
        }
        b2MassData fixtures = reset_mass(created, created.size(), body.IsFixedRotation());
        float fixtures_inertia =
            fixtures.I + fixtures.mass * b2Dot(fixtures.center, fixtures.center);
        float mass = body.GetMass(), inertia = body.GetInertia();
        b2Vec2 center = body.GetLocalCenter();
        out.mass = mass;
        out.mass_given = !same_bits(mass, fixtures.mass);
        out.center = to_b2s(center);
        out.center_given = !same_bits(center, fixtures.center);
        if (!given(out) && same_bits(inertia, fixtures_inertia)) {
            return out;
        }
        if (body.IsFixedRotation()) { // SetMassData ignores its inertia
            return out;
        }
        float moment = mass * b2Dot(center, center);
        auto inertia_after = [moment](float I) { return (I > 0.0f ? I - moment : 0.0f) + moment; };
        auto accepted_by_build = [moment](float I) { return !(I > 0.0f) || I - moment > 0.0f; };
        if (given(out) && same_bits(inertia_after(fixtures_inertia), inertia) &&
            accepted_by_build(fixtures_inertia)) {
            return out; // SetMassData with GetMassData's inertia after the fixtures does
        }
        out.inertia_given = true;
        out.inertia = same_bits(inertia, 0.0f + moment) ? 0.0f : inertia;
        if (!same_bits(inertia_after(out.inertia), inertia) || !accepted_by_build(out.inertia)) {
            lossy("body", index, name,
                  "its MassData Inertia " + decimal(inertia) +
                      " does not come back exactly through Box2D's SetMassData");
        }
        return out;
    }

    /// The LinearVelocity to write: build_world's ResetMassData (one per fixture with a
    /// density) and SetMassData each add w x (how far the centre of mass moved) to it,
    /// and it must end at the body's velocity.
    b2Vec2 linear_velocity(const b2Body& body, const std::vector<FixtureMass>& created,
                           const b2s_mass_data& written, uint32_t index, const std::string& name) {
        std::vector<b2Vec2> kicks = velocity_kicks(body, created, given(written));
        b2Vec2 target = body.GetLinearVelocity();
        b2Vec2 start, miss;
        bool exact = true;
        for (float b2Vec2::*axis : {&b2Vec2::x, &b2Vec2::y}) {
            auto after_build = [&](float v) {
                for (const b2Vec2& kick : kicks) {
                    v += kick.*axis;
                }
                return v;
            };
            float guess = target.*axis;
            for (auto kick = kicks.rbegin(); kick != kicks.rend(); ++kick) {
                guess -= (*kick).*axis;
            }
            exact = solve_nondecreasing(after_build, target.*axis, guess, start.*axis) && exact;
            miss.*axis = after_build(start.*axis) - target.*axis;
        }
        if (!exact) { // the kicks outweigh the velocity: the floats they land on are sparse
            lossy("body", index, name,
                  "no LinearVelocity ends exactly at its velocity once build_world has moved "
                  "its centre of mass; the nearest misses by (" + decimal(miss.x) +
                      ", " + decimal(miss.y) + ") m/s");
        }
        return start;
    }

    /// What build_world's mass updates add to a dynamic body's linear velocity, in order.
    static std::vector<b2Vec2> velocity_kicks(const b2Body& body,
                                              const std::vector<FixtureMass>& created,
                                              bool mass_data_written) {
        std::vector<b2Vec2> kicks;
        if (body.GetType() != b2_dynamicBody) {
            return kicks;
        }
        const b2Transform& xf = body.GetTransform();
        float w = body.GetAngularVelocity();
        b2Vec2 centre = xf.p; // where b2Body's constructor puts it
        auto move_centre = [&](b2Vec2 local) {
            b2Vec2 moved = b2Mul(xf, local);
            kicks.push_back(b2Cross(w, moved - centre));
            centre = moved;
        };
        for (size_t count = 1; count <= created.size(); ++count) {
            if (created[count - 1].density > 0.0f) { // only then does CreateFixture reset the mass
                move_centre(reset_mass(created, count, body.IsFixedRotation()).center);
            }
        }
        if (mass_data_written) {
            move_centre(body.GetLocalCenter());
        }
        return kicks;
    }

    // ---- joints

    void capture_joint(b2Joint& joint) {
        Label label = namer_->joint(joint);
        b2s_joint record;
        if (!joint_record(joint, label.name, record)) {
            return;
        }
        record.name = name_of(label.name);
        record.user_data = user_data(label, "joint", joint_index_);
        uint32_t added = B2S_NONE;
        b2s_error error{};
        b2s_code code = b2s_builder_add_joint(builder_, &record, &added, &error);
        if (accepted(code, error, "joint", joint_index_, label.name)) {
            joints_.emplace(&joint, added);
        }
    }

    /// The record of a joint, or false when it is not written (reported).
    bool joint_record(b2Joint& joint, const std::string& name, b2s_joint& out) {
        switch (joint.GetType()) {
        case e_revoluteJoint:
            return revolute_record(static_cast<b2RevoluteJoint&>(joint), name, out);
        case e_prismaticJoint:
            return prismatic_record(static_cast<b2PrismaticJoint&>(joint), name, out);
        case e_distanceJoint:
            return distance_record(static_cast<b2DistanceJoint&>(joint), name, out);
        case e_pulleyJoint: return pulley_record(static_cast<b2PulleyJoint&>(joint), name, out);
        case e_gearJoint: return gear_record(static_cast<b2GearJoint&>(joint), name, out);
        case e_wheelJoint: return wheel_record(static_cast<b2WheelJoint&>(joint), name, out);
        case e_weldJoint: return weld_record(static_cast<b2WeldJoint&>(joint), name, out);
        case e_frictionJoint:
            return friction_record(static_cast<b2FrictionJoint&>(joint), name, out);
        case e_motorJoint: return motor_record(static_cast<b2MotorJoint&>(joint), name, out);
        case e_mouseJoint:
            report(B2S_CODE_SKIPPED_JOINT, "joint", joint_index_, name,
                   "a mouse joint (a host's drag) has no Box2Scene form; not written");
            return false;
        default:
            report(B2S_CODE_SKIPPED_JOINT, "joint", joint_index_, name,
                   "Box2D joint type " + std::to_string(joint.GetType()) +
                       " has no Box2Scene form; not written");
            return false;
        }
    }

    /// Starts a record of `kind` between the joint's bodies; false (reported) when one of
    /// them was not written.
    bool start(b2Joint& joint, b2s_joint_kind kind, const std::string& name, b2s_joint& out) {
        b2s_joint_default(kind, &out);
        for (b2Body* body : {joint.GetBodyA(), joint.GetBodyB()}) {
            if (bodies_.count(body) == 0) {
                report(B2S_CODE_SKIPPED_DEPENDENT, "joint", joint_index_, name,
                       "one of its bodies was not written; not written");
                return false;
            }
        }
        out.body_a = bodies_.at(joint.GetBodyA());
        out.body_b = bodies_.at(joint.GetBodyB());
        out.collide_connected = joint.GetCollideConnected();
        return true;
    }

    /// An axis build_world normalises back to `unit`, or `unit` itself (reported).
    b2s_vec2 axis_giving(b2Vec2 unit, const std::string& name) {
        b2Vec2 axis;
        if (!axis_normalising_to(unit, axis)) {
            lossy("joint", joint_index_, name,
                  "no axis normalises to its axis (" + decimal(unit.x) + ", " +
                      decimal(unit.y) + ") exactly; it was written as it is");
        }
        return to_b2s(axis);
    }

    void spring(StiffnessFunction stiffness_of, b2Joint& joint, float stiffness, float damping,
                const std::string& name, b2s_joint& out) {
        if (!spring_giving(stiffness_of, joint.GetBodyA(), joint.GetBodyB(), stiffness, damping,
                           out.frequency_hz, out.damping_ratio)) {
            lossy("joint", joint_index_, name,
                  "no FrequencyHz and DampingRatio give back its stiffness " +
                      decimal(stiffness) + " and damping " + decimal(damping) +
                      " exactly; the nearest were written");
        }
    }

    bool revolute_record(b2RevoluteJoint& joint, const std::string& name, b2s_joint& out) {
        if (!start(joint, B2S_JOINT_KIND_REVOLUTE, name, out)) {
            return false;
        }
        out.local_anchor_a = to_b2s(joint.GetLocalAnchorA());
        out.local_anchor_b = to_b2s(joint.GetLocalAnchorB());
        out.reference_angle = joint.GetReferenceAngle();
        out.enable_limit = joint.IsLimitEnabled();
        out.lower_limit = joint.GetLowerLimit();
        out.upper_limit = joint.GetUpperLimit();
        out.enable_motor = joint.IsMotorEnabled();
        out.motor_speed = joint.GetMotorSpeed();
        out.max_motor_torque = joint.GetMaxMotorTorque();
        return true;
    }

    bool prismatic_record(b2PrismaticJoint& joint, const std::string& name, b2s_joint& out) {
        if (!start(joint, B2S_JOINT_KIND_PRISMATIC, name, out)) {
            return false;
        }
        out.local_anchor_a = to_b2s(joint.GetLocalAnchorA());
        out.local_anchor_b = to_b2s(joint.GetLocalAnchorB());
        out.local_axis_a = axis_giving(joint.GetLocalAxisA(), name);
        out.reference_angle = joint.GetReferenceAngle();
        out.enable_limit = joint.IsLimitEnabled();
        out.lower_limit = joint.GetLowerLimit();
        out.upper_limit = joint.GetUpperLimit();
        out.enable_motor = joint.IsMotorEnabled();
        out.motor_speed = joint.GetMotorSpeed();
        out.max_motor_force = joint.GetMaxMotorForce();
        return true;
    }

    /// Box2D 2.4's distance joint is three of the format's joints, told apart by the
    /// lengths build_world gives them (Box2D raises a minimum under b2_linearSlop to it): a
    /// rod (min = max), a spring (min 0, max FLT_MAX, a stiffness) or a rope (min 0, no
    /// stiffness). The rest becomes the nearest of them, reported. What Box2D then ignores
    /// is not kept: a rod's rest length and spring, a rope's rest length and damping.
    bool distance_record(b2DistanceJoint& joint, const std::string& name, b2s_joint& out) {
        float min = joint.GetMinLength(), max = joint.GetMaxLength();
        bool spring_form = joint.GetStiffness() > 0.0f && min != max;
        bool rope_form = !spring_form && min != max;
        if (!start(joint, rope_form ? B2S_JOINT_KIND_ROPE : B2S_JOINT_KIND_DISTANCE, name, out)) {
            return false;
        }
        out.local_anchor_a = to_b2s(joint.GetLocalAnchorA());
        out.local_anchor_b = to_b2s(joint.GetLocalAnchorB());
        if (rope_form) {
            out.max_length = max;
        } else if (spring_form) {
            out.length = joint.GetLength();
            spring(b2LinearStiffness, joint, joint.GetStiffness(), joint.GetDamping(), name, out);
        } else {
            out.length = min;
        }
        bool min_kept = !(spring_form || rope_form) || min == b2_linearSlop;
        bool max_kept = !spring_form || max == FLT_MAX;
        if (!min_kept || !max_kept) {
            lossy("joint", joint_index_, name,
                  "its length limits [" + decimal(min) + ", " + decimal(max) +
                      "] have no Box2Scene form; written as a " +
                      (spring_form ? "spring without them" : "rope without the lower one"));
        }
        return true;
    }

    /// Box2D 2.4.1 has no getters for a pulley's local anchors. A class derived from the
    /// joint may name its protected members, and a pointer to one reads any pulley.
    struct PulleyAnchors : b2PulleyJoint {
        static b2Vec2 a(const b2PulleyJoint& j) { return j.*(&PulleyAnchors::m_localAnchorA); }
        static b2Vec2 b(const b2PulleyJoint& j) { return j.*(&PulleyAnchors::m_localAnchorB); }
    };

    bool pulley_record(b2PulleyJoint& joint, const std::string& name, b2s_joint& out) {
        if (!start(joint, B2S_JOINT_KIND_PULLEY, name, out)) {
            return false;
        }
        out.ground_anchor_a = to_b2s(joint.GetGroundAnchorA());
        out.ground_anchor_b = to_b2s(joint.GetGroundAnchorB());
        out.local_anchor_a = to_b2s(PulleyAnchors::a(joint));
        out.local_anchor_b = to_b2s(PulleyAnchors::b(joint));
        out.length_a = joint.GetLengthA();
        out.length_b = joint.GetLengthB();
        out.ratio = joint.GetRatio();
        return true;
    }

    bool gear_record(b2GearJoint& joint, const std::string& name, b2s_joint& out) {
        auto coupled_a = joints_.find(joint.GetJoint1());
        auto coupled_b = joints_.find(joint.GetJoint2());
        if (coupled_a == joints_.end() || coupled_b == joints_.end()) {
            report(B2S_CODE_SKIPPED_DEPENDENT, "joint", joint_index_, name,
                   "a joint the gear couples was not written; not written");
            return false;
        }
        if (!start(joint, B2S_JOINT_KIND_GEAR, name, out)) {
            return false;
        }
        out.joint_a = coupled_a->second;
        out.joint_b = coupled_b->second;
        out.ratio = joint.GetRatio();
        return true;
    }

    /// A wheel with a limit is the format's Line only without spring and motor, which
    /// Line lacks; with either, it stays a Wheel and loses the limit (reported).
    bool wheel_record(b2WheelJoint& joint, const std::string& name, b2s_joint& out) {
        bool sprung_or_driven = joint.GetStiffness() > 0.0f || joint.IsMotorEnabled();
        bool line = joint.IsLimitEnabled() && !sprung_or_driven;
        if (!start(joint, line ? B2S_JOINT_KIND_LINE : B2S_JOINT_KIND_WHEEL, name, out)) {
            return false;
        }
        out.local_anchor_a = to_b2s(joint.GetLocalAnchorA());
        out.local_anchor_b = to_b2s(joint.GetLocalAnchorB());
        out.local_axis_a = axis_giving(joint.GetLocalAxisA(), name);
        if (line) {
            out.enable_limit = true;
            out.lower_limit = joint.GetLowerLimit();
            out.upper_limit = joint.GetUpperLimit();
            return true;
        }
        out.enable_motor = joint.IsMotorEnabled();
        out.motor_speed = joint.GetMotorSpeed();
        out.max_motor_torque = joint.GetMaxMotorTorque();
        spring(b2LinearStiffness, joint, joint.GetStiffness(), joint.GetDamping(), name, out);
        if (joint.IsLimitEnabled()) {
            lossy("joint", joint_index_, name,
                  "a wheel with a spring or motor has no limit in the format; its limit [" +
                      decimal(joint.GetLowerLimit()) + ", " +
                      decimal(joint.GetUpperLimit()) + "] was dropped");
        }
        return true;
    }

    bool weld_record(b2WeldJoint& joint, const std::string& name, b2s_joint& out) {
        if (!start(joint, B2S_JOINT_KIND_WELD, name, out)) {
            return false;
        }
        out.local_anchor_a = to_b2s(joint.GetLocalAnchorA());
        out.local_anchor_b = to_b2s(joint.GetLocalAnchorB());
        out.reference_angle = joint.GetReferenceAngle();
        spring(b2AngularStiffness, joint, joint.GetStiffness(), joint.GetDamping(), name, out);
        return true;
    }

    bool friction_record(b2FrictionJoint& joint, const std::string& name, b2s_joint& out) {
        if (!start(joint, B2S_JOINT_KIND_FRICTION, name, out)) {
            return false;
        }
        out.local_anchor_a = to_b2s(joint.GetLocalAnchorA());
        out.local_anchor_b = to_b2s(joint.GetLocalAnchorB());
        out.max_force = joint.GetMaxForce();
        out.max_torque = joint.GetMaxTorque();
        return true;
    }

    bool motor_record(b2MotorJoint& joint, const std::string& name, b2s_joint& out) {
        if (!start(joint, B2S_JOINT_KIND_MOTOR, name, out)) {
            return false;
        }
        out.linear_offset = to_b2s(joint.GetLinearOffset());
        out.angular_offset = joint.GetAngularOffset();
        out.max_force = joint.GetMaxForce();
        out.max_torque = joint.GetMaxTorque();
        out.correction_factor = joint.GetCorrectionFactor();
        return true;
    }

    b2World& world_;
    std::vector<Report>& reports_;
    const Namer unnamed_{};
    const Namer* namer_;
    b2s_builder* builder_ = b2s_builder_new();
    std::map<std::string, uint32_t> shapes_;   // by shape_key
    std::map<std::string, uint32_t> fixtures_; // by fixture_key
    std::unordered_map<const b2Body*, uint32_t> bodies_;
    std::unordered_map<const b2Joint*, uint32_t> joints_;
    uint32_t body_index_ = 0;    // in the world, in creation order
    uint32_t fixture_index_ = 0; // likewise, counted over the bodies
    uint32_t joint_index_ = 0;
};

} // namespace detail

inline b2s_scene* capture_world(b2World& world, std::vector<Report>& reports,
                                const Namer* namer) {
    return detail::WorldCapture(world, reports, namer).run();
}

} // namespace box2scene

#endif // BOX2SCENE_BOX2D_HPP
