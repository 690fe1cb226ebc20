// Part of <box2scene/box2d.hpp> (a host includes that header only): build_world and
// scene_gravity, a loaded scene into a b2World.
#ifndef BOX2SCENE_DETAIL_BOX2D_BUILD_HPP
#define BOX2SCENE_DETAIL_BOX2D_BUILD_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "box2d_common.hpp"
#include "box2d_working_range.hpp"

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

/// `end` continued by one segment away from `inner`: a ghost vertex for an open chain end
/// the file left without one (Box2D 2.4's CreateChain needs both).
inline b2Vec2 extrapolated(b2Vec2 end, b2Vec2 inner) {
    return end + (end - inner);
}

/// One build: the scene's view, the world, and what was made so far.
class WorldBuilder {
public:
    WorldBuilder(const struct b2s_scene_view& view, b2World& world, const b2Transform& placement)
        : view_(view), world_(world), placement_(placement),
          placement_angle_(placement.q.GetAngle()) {}

    Built run() {
        if (!placement_valid()) {
            report(B2S_CODE_INVALID_ARGUMENT, "world", 0, nullptr,
                   "the placement (" + decimal(placement_.p.x) + ", " + decimal(placement_.p.y) +
                       ") turned by (" + decimal(placement_.q.c) + ", " +
                       decimal(placement_.q.s) + ") is not finite, not within +-" +
                       decimal(working_range::length) +
                       " m or not a normalised rotation; nothing was built");
            return std::move(built_);
        }
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

    /// A placement Box2D 2.4 can take: finite, within the working range, its rotation
    /// normalised (2.4 keeps a body's angle, and the placement's rotation is added to it).
    bool placement_valid() const {
        const b2Transform& t = placement_;
        float qq = t.q.c * t.q.c + t.q.s * t.q.s;
        return std::isfinite(t.p.x) && std::isfinite(t.p.y) && std::isfinite(t.q.c) &&
               std::isfinite(t.q.s) && std::fabs(qq - 1.0f) < 1e-4f &&
               std::fabs(t.p.x) <= working_range::length &&
               std::fabs(t.p.y) <= working_range::length;
    }

    /// A point of the scene's world frame where the placement puts it.
    b2Vec2 placed(b2s_vec2 point) const {
        return b2Mul(placement_, to_b2(point));
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
        if (check.passed()) {
            check.vector("its placed Position", to_b2s(placed(body.position)), range::length,
                         "m");
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

    /// The mass Box2D 2.4 will give a dynamic body, as build_world has b2Body compute it:
    /// from all of its fixtures at once (ResetMassData, which asserts that an inertia it
    /// centres stays positive), then MassData. `check` fails when Box2D would assert or the
    /// result lies beyond the working range.
    b2MassData predicted_mass(const b2s_body& body, RangeCheck& check) const {
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
                     to_b2s(mass.center), working_range::length, "m");
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
        bool dense = false;
        for (uint32_t slot = body.fixtures.first; slot < end; ++slot) {
            b2Fixture* fixture = make_fixture(body_index, view_.fixture_ids[slot], created);
            built_.fixtures[slot] = fixture;
            dense = dense || (fixture != nullptr && fixture->GetDensity() > 0.0f);
        }
        // What CreateFixture would have done after each fixture with a density, once.
        if (dense) {
            created->ResetMassData();
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
        auto owner = [&] { // only a report needs it
            return "fixture " + std::to_string(index) + " of body " + std::to_string(body_index);
        };
        if (index >= view_.fixture_count) {
            report(B2S_CODE_ID_OUT_OF_RANGE, "fixture", index, nullptr,
                   owner() + " does not exist");
            return nullptr;
        }
        const b2s_fixture& fixture = view_.fixtures[index];
        if (!shape_created(fixture)) {
            report(B2S_CODE_SKIPPED_DEPENDENT, "fixture", index, fixture.name,
                   owner() + " names shape " + std::to_string(fixture.shape) +
                       ", which was not created; fixture skipped");
            return nullptr;
        }
        RangeCheck check = fixture_check(fixture);
        if (!check.passed()) {
            within_range(check, "fixture", index, fixture.name, owner() + ": ");
            return nullptr;
        }
        // CreateFixture recomputes the body's mass from all its fixtures whenever it adds one
        // with a density, which makes a body of n fixtures cost n^2: the density is set
        // after, and make_fixtures has the mass computed once.
        bool withheld = fixture.density > 0.0f;
        b2FixtureDef def;
        def.shape = shapes_[fixture.shape].get();
        def.density = withheld ? 0.0f : fixture.density;
        def.friction = fixture.friction;
        def.restitution = fixture.restitution;
        def.isSensor = fixture.is_sensor;
        def.filter.categoryBits = fixture.filter.category_bits;
        def.filter.maskBits = fixture.filter.mask_bits;
        def.filter.groupIndex = fixture.filter.group_index;
        b2Fixture* created = body->CreateFixture(&def);
        if (withheld) {
            created->SetDensity(fixture.density);
        }
        return created;
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
        if (bodies_created && (!within_range(joint_check(joint), "joint", index, joint.name) ||
                               !within_range(violation_check(joint), "joint", index,
                                             joint.name))) {
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

    /// How far the joint starts from satisfied, in metres, along what its kind holds
    /// rigidly, with its bodies as created: what the load warning joint-starts-violated
    /// measures.
    float starting_violation(const b2s_joint& joint) const {
        const b2Body* a = built_.bodies[joint.body_a];
        const b2Body* b = built_.bodies[joint.body_b];
        b2Vec2 pa = a->GetWorldPoint(to_b2(joint.local_anchor_a));
        b2Vec2 pb = b->GetWorldPoint(to_b2(joint.local_anchor_b));
        b2Vec2 d = pb - pa;
        switch (joint.kind) {
        case B2S_JOINT_KIND_REVOLUTE:
        case B2S_JOINT_KIND_WELD: return d.Length();
        case B2S_JOINT_KIND_PRISMATIC:
        case B2S_JOINT_KIND_LINE:
        case B2S_JOINT_KIND_WHEEL: {
            b2Vec2 axis = a->GetWorldVector(to_b2(joint.local_axis_a));
            axis.Normalize();
            float across = std::fabs(b2Cross(axis, d));
            float along = b2Dot(axis, d);
            bool limited = joint.enable_limit && joint.kind != B2S_JOINT_KIND_WHEEL;
            float beyond = limited ? std::max({joint.lower_limit - along,
                                               along - joint.upper_limit, 0.0f})
                                   : 0.0f;
            return std::max(across, beyond);
        }
        case B2S_JOINT_KIND_DISTANCE:
            return joint.frequency_hz > 0.0f ? 0.0f : std::fabs(d.Length() - joint.length);
        case B2S_JOINT_KIND_ROPE: return std::max(d.Length() - joint.max_length, 0.0f);
        case B2S_JOINT_KIND_PULLEY: {
            float now = b2Distance(pa, placed(joint.ground_anchor_a)) +
                        joint.ratio * b2Distance(pb, placed(joint.ground_anchor_b));
            return std::fabs(now - (joint.length_a + joint.ratio * joint.length_b));
        }
        default: return 0.0f; // springs, motors and friction hold nothing in place
        }
    }

    /// What the sweep of docs/working-range.md measured: Box2D 2.4 holds any one joint that
    /// starts up to 50 m from satisfied, but a body pulled by two joints that start more
    /// than working_range::violation from satisfied can be torn to NaN by its position
    /// solver. The first such joint on a body is built, the later ones are not.
    RangeCheck violation_check(const b2s_joint& joint) {
        RangeCheck check;
        float violation = starting_violation(joint);
        if (!(violation > working_range::violation)) {
            return check;
        }
        for (uint32_t body : {joint.body_a, joint.body_b}) {
            if (pulled_[body] != nullptr) {
                check.fail("it starts " + decimal(violation) + " m from satisfied, and joint " +
                           std::to_string(pulled_[body] - view_.joints) + " already pulls body " +
                           std::to_string(body) + " from further than " +
                           rounded(working_range::violation) +
                           " m: two such joints on one body lie beyond Box2D 2.4's working "
                           "range (its position solver can tear the body to NaN)");
                return check;
            }
        }
        for (uint32_t body : {joint.body_a, joint.body_b}) {
            if (built_.bodies[body]->GetType() == b2_dynamicBody) {
                pulled_[body] = &joint;
            }
        }
        return check;
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
        switch (joint.kind) {
        case B2S_JOINT_KIND_WELD: weld_spring(joint, a, b, stiffness, damping); break;
        case B2S_JOINT_KIND_WHEEL: wheel_spring(joint, a, b, stiffness, damping); break;
        default:
            b2LinearStiffness(stiffness, damping, joint.frequency_hz, joint.damping_ratio, a, b);
        }
        if (stiffness != 0.0f && !(stiffness >= working_range::min_stiffness)) {
            check.fail("FrequencyHz " + decimal(joint.frequency_hz) + " gives a stiffness of " +
                       decimal(stiffness) + (angular ? " N m/rad" : " N/m") +
                       " with these bodies, beyond Box2D 2.4's working range (0 or at least " +
                       rounded(working_range::min_stiffness) + ")");
        }
    }

    /// Box2D's joint solvers invert matrices of 1/m + r^2/I at the anchor (r from the
    /// centre of mass): past working_range::compliance they overflow, and past lever_2x2
    /// (revolute, friction, motor) or lever_3x3 (prismatic, weld) radii of gyration their
    /// determinants lose every bit to cancellation (docs/working-range.md). A prismatic
    /// joint's lever on body A reaches body B's anchor.
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

    /// Box2D 2.2's springs: stiffness m w^2 and damping 2 m zeta w, w = 2 pi FrequencyHz,
    /// for the mass `m` the spring moves (b2LinearStiffness's arithmetic).
    static void spring(const b2s_joint& joint, float mass, float& stiffness, float& damping) {
        float omega = 2.0f * b2_pi * joint.frequency_hz;
        stiffness = mass * omega * omega;
        damping = 2.0f * mass * joint.damping_ratio * omega;
    }

    /// 1/I about the centre of mass (b2Body::GetInertia is about the origin), 0 for a body
    /// that does not turn.
    static float inverse_central_inertia(const b2Body* body) {
        b2Vec2 c = body->GetLocalCenter();
        float inertia = body->GetInertia() - body->GetMass() * b2Dot(c, c);
        return inertia > 0.0f ? 1.0f / inertia : 0.0f;
    }

    static float inverse_mass(const b2Body* body) {
        float mass = body->GetMass();
        return mass > 0.0f ? 1.0f / mass : 0.0f;
    }

    /// Box2D 2.2's soft weld: the angular mass 1/(1/IA + 1/IB) from the inertias about the
    /// centres of mass (b2AngularStiffness takes those about the origins).
    static void weld_spring(const b2s_joint& joint, const b2Body* a, const b2Body* b,
                            float& stiffness, float& damping) {
        float inverse = inverse_central_inertia(a) + inverse_central_inertia(b);
        spring(joint, inverse > 0.0f ? 1.0f / inverse : 0.0f, stiffness, damping);
    }

    /// Box2D 2.2's wheel spring: the effective mass along the axis as the joint starts,
    /// 1/(1/mA + 1/mB + sAx^2/IA + sBx^2/IB), as 2.2's InitVelocityConstraints computes it
    /// (b2LinearStiffness takes mA mB/(mA + mB)).
    static void wheel_spring(const b2s_joint& joint, const b2Body* a, const b2Body* b,
                             float& stiffness, float& damping) {
        if (!(joint.frequency_hz > 0.0f)) {
            stiffness = damping = 0.0f;
            return;
        }
        b2Vec2 axis = to_b2(joint.local_axis_a);
        axis.Normalize();
        b2Rot qA = a->GetTransform().q, qB = b->GetTransform().q;
        b2Vec2 rA = b2Mul(qA, to_b2(joint.local_anchor_a) - a->GetLocalCenter());
        b2Vec2 rB = b2Mul(qB, to_b2(joint.local_anchor_b) - b->GetLocalCenter());
        b2Vec2 d = b->GetWorldCenter() + rB - a->GetWorldCenter() - rA;
        b2Vec2 ax = b2Mul(qA, axis);
        float sAx = b2Cross(d + rA, ax), sBx = b2Cross(rB, ax);
        float inverse = inverse_mass(a) + inverse_mass(b) +
                        inverse_central_inertia(a) * sAx * sAx +
                        inverse_central_inertia(b) * sBx * sBx;
        spring(joint, inverse > 0.0f ? 1.0f / inverse : 0.0f, stiffness, damping);
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

    /// MaxLengthA/B (Box2D 2.1 only) have no 2.4 field: each side's limit becomes a rope
    /// from its ground anchor, held by a static body, right after the pulley.
    void make_pulley(uint32_t index, const b2s_joint& joint) {
        b2PulleyJointDef def;
        if (!connect(index, joint, def)) {
            return;
        }
        // The ground anchors are world points: the placement moves them with the bodies.
        def.groundAnchorA = placed(joint.ground_anchor_a);
        def.groundAnchorB = placed(joint.ground_anchor_b);
        def.localAnchorA = to_b2(joint.local_anchor_a);
        def.localAnchorB = to_b2(joint.local_anchor_b);
        def.lengthA = joint.length_a;
        def.lengthB = joint.length_b;
        def.ratio = joint.ratio;
        create(index, def);
        // Box2D 2.1.2's limits: the side's maximum, but no longer than leaves the other side
        // its b2_minPulleyLength of 2 m.
        float constant = joint.length_a + joint.ratio * joint.length_b;
        limit_pulley_side(index, joint, "MaxLengthA", joint.max_length_a,
                          constant - joint.ratio * 2.0f, def.groundAnchorA, def.bodyA,
                          def.localAnchorA);
        limit_pulley_side(index, joint, "MaxLengthB", joint.max_length_b,
                          (constant - 2.0f) / joint.ratio, def.groundAnchorB, def.bodyB,
                          def.localAnchorB);
    }

    void limit_pulley_side(uint32_t index, const b2s_joint& joint, const char* field,
                           float given, float longest, b2Vec2 ground, b2Body* body,
                           b2Vec2 anchor) {
        if (!(given > 0.0f)) { // absent or 0: no limit
            return;
        }
        float limit = std::min(given, longest);
        b2Body* holder = static_body();
        if (holder == nullptr || !(limit >= b2_linearSlop)) {
            report(B2S_CODE_LOSSY_JOINT, "joint", index, joint.name,
                   std::string(field) + " " + decimal(given) + " gives a limit of " +
                       decimal(limit) + " m, which Box2D 2.4 cannot hold " +
                       (holder == nullptr ? "without a static body in the scene"
                                          : "(it is shorter than the linear slop)") +
                       "; the side is unlimited");
            return;
        }
        b2DistanceJointDef rope;
        rope.bodyA = holder;
        rope.bodyB = body;
        rope.localAnchorA = holder->GetLocalPoint(ground);
        rope.localAnchorB = anchor;
        rope.length = limit;
        rope.minLength = 0.0f;
        rope.maxLength = limit;
        world_.CreateJoint(&rope);
    }

    /// The first static body of the scene that was created, or nullptr.
    b2Body* static_body() const {
        for (b2Body* body : built_.bodies) {
            if (body != nullptr && body->GetType() == b2_staticBody) {
                return body;
            }
        }
        return nullptr;
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
        wheel_spring(joint, def.bodyA, def.bodyB, def.stiffness, def.damping);
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
            weld_spring(joint, def.bodyA, def.bodyB, def.stiffness, def.damping);
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
    b2Transform placement_;
    float placement_angle_; // rad: what the placement adds to every body's Angle
    std::vector<std::unique_ptr<b2Shape>> shapes_; // indexed like the scene's shapes
    std::vector<b2MassData> masses_; // each dynamic body's, I about its centre of mass
    std::vector<const b2s_joint*> pulled_; // per body: the joint that starts it violated
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

#endif // BOX2SCENE_DETAIL_BOX2D_BUILD_HPP
