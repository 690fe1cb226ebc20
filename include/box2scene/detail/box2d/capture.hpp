// Part of <box2scene/box2d.hpp> (a host includes that header only): capture_world, a live
// b2World back into a scene, every derived value inverted so that build_world gives the
// same bits back.
#ifndef BOX2SCENE_DETAIL_BOX2D_CAPTURE_HPP
#define BOX2SCENE_DETAIL_BOX2D_CAPTURE_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "reports.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace box2scene {
namespace detail {

template <class T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// The springs the plan gives a wheel or weld joint (Box2D 2.2's, from the bodies' mass),
/// as the engine's getters give them back: what the capture inverts.
struct BuiltSprings {
    /// Stiffness m w^2 and damping 2 m zeta w, w = 2 pi FrequencyHz, for the mass `m` the
    /// spring moves (b2LinearStiffness's arithmetic).
    static void spring(const b2s_joint& joint, float mass, float& stiffness, float& damping) {
        float omega = 2.0f * b2_pi * joint.frequency_hz;
        stiffness = mass * omega * omega;
        damping = 2.0f * mass * joint.damping_ratio * omega;
    }
    /// 1/I about the centre of mass, 0 for a body that does not turn.
    static float inverse_central_inertia(const b2Body* body) {
        b2Vec2 c = body->GetLocalCenter();
        float inertia = body->GetInertia() - body->GetMass() * b2Dot(c, c);
        return inertia > 0.0f ? 1.0f / inertia : 0.0f;
    }
    static float inverse_mass(const b2Body* body) {
        float mass = body->GetMass();
        return mass > 0.0f ? 1.0f / mass : 0.0f;
    }
    /// The angular mass 1/(1/IA + 1/IB).
    static void weld_spring(const b2s_joint& joint, const b2Body* a, const b2Body* b,
                            float& stiffness, float& damping) {
        float inverse = inverse_central_inertia(a) + inverse_central_inertia(b);
        spring(joint, inverse > 0.0f ? 1.0f / inverse : 0.0f, stiffness, damping);
    }
    /// The effective mass along the axis as the joint starts.
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
};

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

/// The FrequencyHz and DampingRatio from which `spring_of(hz, ratio, stiffness, damping)`,
/// what build_world computes for the joint on the same two bodies (their masses are final
/// by then), gives back `stiffness` and `damping` bit for bit; false when no floats do (the
/// nearest are stored). A zero stiffness is no spring: Box2D 2.4 then ignores the damping.
template <class Spring>
bool spring_giving(Spring spring_of, float stiffness, float damping, float& frequency,
                   float& ratio) {
    frequency = 0.0f;
    ratio = 0.0f;
    if (stiffness == 0.0f) {
        return true;
    }
    auto stiffness_at = [&](float hz) {
        float k = 0.0f, d = 0.0f;
        spring_of(hz, 0.0f, k, d);
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
        spring_of(frequency, r, k, d);
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
    /// `built` and `scene`, both null or both given: what build_world made the world of.
    WorldCapture(b2World& world, std::vector<Report>& reports, const Namer* namer,
                 const Built* built = nullptr, const b2s_scene* scene = nullptr)
        : world_(world), reports_(reports), namer_(namer != nullptr ? namer : &unnamed_),
          built_(built), level_(b2s_scene_get_view(scene)) {
        if (has_level()) {
            index_level(built_->bodies, level_->body_count, level_bodies_);
            index_level(built_->fixtures, level_->fixture_id_count, level_fixtures_);
            index_level(built_->joints, level_->joint_count, level_joints_);
            level_written_.assign(level_->joint_count, B2S_NONE);
        }
    }

    b2s_scene* run() {
        b2s_vec2 gravity = to_b2s(world_.GetGravity());
        b2s_builder_set_gravity(builder_, &gravity, nullptr); // refused only if not finite
        for (b2Body* body : creation_order(world_.GetBodyList())) {
            capture_body(*body);
        }
        for (const PlacedJoint& placed : joints_in_order()) {
            if (placed.joint != nullptr) {
                joint_index_ = placed.created;
                capture_joint(*placed.joint);
            } else {
                write_skipped(placed.record);
            }
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

    // ---- labels: the host's, else (given the scene) the level's

    static bool labelled(const Label& label) {
        return !label.name.empty() || !label.user_data_raw.empty() ||
               !label.user_data_type.empty() || !label.user_data_value.empty();
    }

    /// Whether the capture was given the scene and what build_world made of it.
    bool has_level() const { return built_ != nullptr && level_ != nullptr; }

    /// Indexes `made`, a part of what build_world made, by object, when the result and the
    /// scene agree on how many there are (a result of another scene labels nothing).
    template <class T>
    static void index_level(const std::vector<T*>& made, uint32_t level_count,
                            std::unordered_map<const T*, uint32_t>& index) {
        if (made.size() != level_count) {
            return;
        }
        for (uint32_t i = 0; i < level_count; ++i) {
            if (made[i] != nullptr) {
                index.emplace(made[i], i);
            }
        }
    }

    /// Where `object` stands in what build_world made, or B2S_NONE.
    template <class T>
    static uint32_t level_index(const std::unordered_map<const T*, uint32_t>& index,
                                const T* object) {
        auto found = index.find(object);
        return found != index.end() ? found->second : B2S_NONE;
    }

    /// The Name and UserData of the level's record `record`, or none.
    template <class Record>
    Label level_label(const Record* record) const {
        Label label;
        if (record == nullptr) {
            return label;
        }
        label.name = text_of(record->name);
        if (record->user_data != B2S_NONE && record->user_data < level_->user_data_count) {
            const b2s_user_data& data = level_->user_data[record->user_data];
            label.user_data_raw = text_of(data.raw);
            label.user_data_type = text_of(data.type_name);
            label.user_data_value = text_of(data.value);
        }
        return label;
    }

    /// The level's record a b2Body was built from, or nullptr (none given, or the host's).
    const b2s_body* level_body(const b2Body& body) const {
        uint32_t index = level_index(level_bodies_, &body);
        return index != B2S_NONE ? &level_->bodies[index] : nullptr;
    }

    const b2s_joint* level_joint(const b2Joint& joint) const {
        uint32_t index = level_index(level_joints_, &joint);
        return index != B2S_NONE ? &level_->joints[index] : nullptr;
    }

    const b2s_fixture* level_fixture(const b2Fixture& fixture) const {
        uint32_t slot = level_index(level_fixtures_, &fixture);
        if (slot == B2S_NONE || level_->fixture_ids[slot] >= level_->fixture_count) {
            return nullptr;
        }
        return &level_->fixtures[level_->fixture_ids[slot]];
    }

    Label body_label(b2Body& body) const {
        Label label = namer_->body(body);
        return labelled(label) ? label : level_label(level_body(body));
    }

    Label fixture_label(b2Fixture& fixture) const {
        Label label = namer_->fixture(fixture);
        return labelled(label) ? label : level_label(level_fixture(fixture));
    }

    Label joint_label(b2Joint& joint) const {
        Label label = namer_->joint(joint);
        return labelled(label) ? label : level_label(level_joint(joint));
    }

    std::string shape_name(b2Fixture& fixture) const {
        std::string name = namer_->shape(fixture);
        const b2s_fixture* record = name.empty() ? level_fixture(fixture) : nullptr;
        if (record == nullptr || record->shape >= level_->shape_count) {
            return name;
        }
        return text_of(level_->shapes[record->shape].name);
    }

    // ---- shapes and fixtures, each equal one written once

    /// The scene shape of the fixture's shape, or B2S_NONE (reported).
    uint32_t scene_shape(b2Fixture& fixture, uint32_t index) {
        std::string name = shape_name(fixture);
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
        Label label = fixture_label(fixture);
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
        Label label = body_label(body);
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
        b2MassData fixtures = reset_mass(created, body.IsFixedRotation());
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

    /// The LinearVelocity to write: build_world's ResetMassData (once, after the fixtures,
    /// when one has a density) and SetMassData each add w x (how far the centre of mass
    /// moved) to it, and it must end at the body's velocity.
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
        bool dense = std::any_of(created.begin(), created.end(),
                                 [](const FixtureMass& f) { return f.density > 0.0f; });
        if (dense) { // only then does build_world reset the mass
            move_centre(reset_mass(created, body.IsFixedRotation()).center);
        }
        if (mass_data_written) {
            move_centre(body.GetLocalCenter());
        }
        return kicks;
    }

    // ---- joints

    /// A joint to write: one of the world (`created`, its place among them in creation
    /// order) or, given the level, scene joint `record`, which build_world skipped.
    struct PlacedJoint {
        uint64_t place;
        b2Joint* joint;
        uint32_t created;
        uint32_t record;
    };

    /// Where scene joint `r` is written: at its index, but a gear right after the later of
    /// the joints it couples (the builder takes a gear after them).
    uint64_t record_place(uint32_t r) const {
        const b2s_joint& joint = level_->joints[r];
        uint32_t last = r;
        if (joint.kind == B2S_JOINT_KIND_GEAR) {
            for (uint32_t coupled : {joint.joint_a, joint.joint_b}) {
                last = coupled != B2S_NONE && coupled < level_->joint_count
                           ? std::max(last, coupled)
                           : last;
            }
        }
        return 2u * static_cast<uint64_t>(last) + (last > r ? 1u : 0u);
    }

    /// The joints in the order they are written: creation order, or given the level the
    /// scene's, with the joints build_world skipped in their places and the host's after.
    std::vector<PlacedJoint> joints_in_order() const {
        std::vector<b2Joint*> created = creation_order(world_.GetJointList());
        uint64_t host = has_level() ? 2u * static_cast<uint64_t>(level_->joint_count) : 0u;
        std::vector<PlacedJoint> placed;
        for (uint32_t i = 0; i < created.size(); ++i) {
            uint32_t r = level_index(level_joints_, created[i]);
            placed.push_back({r != B2S_NONE ? record_place(r) : host + i, created[i], i, r});
        }
        if (has_level() && built_->joints.size() == level_->joint_count) {
            for (uint32_t r = 0; r < level_->joint_count; ++r) {
                if (built_->joints[r] == nullptr) {
                    placed.push_back({record_place(r), nullptr, 0, r});
                }
            }
        }
        std::stable_sort(placed.begin(), placed.end(),
                         [](const PlacedJoint& a, const PlacedJoint& b) {
                             return a.place < b.place;
                         });
        return placed;
    }

    /// The index written for scene body `index`, or B2S_NONE.
    uint32_t written_body(uint32_t index) const {
        if (index >= built_->bodies.size()) {
            return B2S_NONE;
        }
        auto found = bodies_.find(built_->bodies[index]);
        return found != bodies_.end() ? found->second : B2S_NONE;
    }

    /// Scene joint `r`, which build_world skipped (Box2D 2.4 cannot hold it), written as the
    /// file has it between the written bodies, so that the joints keep their indices;
    /// reported and not written when it names a body or joint not written before it.
    void write_skipped(uint32_t r) {
        b2s_joint record = level_->joints[r];
        Label label = level_label(&record);
        record.body_a = written_body(record.body_a);
        record.body_b = written_body(record.body_b);
        bool resolved = record.body_a != B2S_NONE && record.body_b != B2S_NONE &&
                        record.kind != B2S_JOINT_KIND_UNSUPPORTED;
        for (uint32_t* coupled : {&record.joint_a, &record.joint_b}) {
            if (*coupled != B2S_NONE) {
                *coupled = *coupled < level_written_.size() ? level_written_[*coupled] : B2S_NONE;
                resolved = resolved && *coupled != B2S_NONE;
            }
        }
        if (!resolved) {
            report(B2S_CODE_SKIPPED_DEPENDENT, "joint", r, label.name,
                   "scene joint " + std::to_string(r) +
                       ", which build_world skipped, names a body or joint not written (or "
                       "has no Box2Scene form); not written");
            return;
        }
        record.name = name_of(label.name);
        record.user_data = user_data(label, "joint", r);
        uint32_t added = B2S_NONE;
        b2s_error error{};
        b2s_code code = b2s_builder_add_joint(builder_, &record, &added, &error);
        if (accepted(code, error, "joint", r, label.name)) {
            level_written_[r] = added;
        }
    }

    void capture_joint(b2Joint& joint) {
        Label label = joint_label(joint);
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
            uint32_t r = level_index(level_joints_, &joint);
            if (r != B2S_NONE) {
                level_written_[r] = added;
            }
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

    /// Writes the FrequencyHz and DampingRatio of the joint's spring: the level's own where
    /// they give back, as build_world computes them (`spring_of`), the stiffness and damping
    /// the engine holds; else the ones inverted from them.
    template <class Spring>
    void spring(Spring spring_of, const b2Joint& joint, float stiffness, float damping,
                const std::string& name, b2s_joint& out) {
        const b2s_joint* level = level_joint(joint);
        if (level != nullptr && level->kind == out.kind) {
            float k = 0.0f, d = 0.0f;
            spring_of(level->frequency_hz, level->damping_ratio, k, d);
            if (same_bits(k, stiffness) && same_bits(d, damping)) {
                out.frequency_hz = level->frequency_hz;
                out.damping_ratio = level->damping_ratio;
                return;
            }
        }
        if (!spring_giving(spring_of, stiffness, damping, out.frequency_hz,
                           out.damping_ratio)) {
            lossy("joint", joint_index_, name,
                  "no FrequencyHz and DampingRatio give back its stiffness " +
                      decimal(stiffness) + " and damping " + decimal(damping) +
                      " exactly; the nearest were written");
        }
    }

    /// build_world's spring for a distance joint: b2LinearStiffness.
    static auto linear_spring(b2Joint& joint) {
        return [&joint](float hz, float ratio, float& stiffness, float& damping) {
            b2LinearStiffness(stiffness, damping, hz, ratio, joint.GetBodyA(), joint.GetBodyB());
        };
    }

    /// build_world's spring for a wheel or weld joint (BuiltSprings::wheel_spring,
    /// weld_spring), from the record written so far and the joint's bodies.
    template <class Builder>
    static auto record_spring(Builder spring_22, b2Joint& joint, const b2s_joint& out) {
        return [spring_22, &joint, &out](float hz, float ratio, float& stiffness,
                                         float& damping) {
            b2s_joint record = out;
            record.frequency_hz = hz;
            record.damping_ratio = ratio;
            spring_22(record, joint.GetBodyA(), joint.GetBodyB(), stiffness, damping);
        };
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
            spring(linear_spring(joint), joint, joint.GetStiffness(), joint.GetDamping(), name,
                   out);
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
        spring(record_spring(BuiltSprings::wheel_spring, joint, out), joint, joint.GetStiffness(),
               joint.GetDamping(), name, out);
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
        spring(record_spring(BuiltSprings::weld_spring, joint, out), joint, joint.GetStiffness(),
               joint.GetDamping(), name, out);
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
    const Built* built_;                // with level_: what build_world made, or nullptr
    const b2s_scene_view* level_;       // the scene it was made from
    // what build_world made, by object: the index of its record (its fixture ID pool entry)
    std::unordered_map<const b2Body*, uint32_t> level_bodies_;
    std::unordered_map<const b2Fixture*, uint32_t> level_fixtures_;
    std::unordered_map<const b2Joint*, uint32_t> level_joints_;
    std::vector<uint32_t> level_written_; // per scene joint, the index written, or B2S_NONE
    b2s_builder* builder_ = b2s_builder_new();
    std::unordered_map<std::string, uint32_t> shapes_;   // by shape_key
    std::unordered_map<std::string, uint32_t> fixtures_; // by fixture_key
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

inline b2s_scene* capture_world(b2World& world, const Built& built, const b2s_scene* scene,
                                std::vector<Report>& reports, const Namer* namer) {
    return detail::WorldCapture(world, reports, namer, &built, scene).run();
}

} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_CAPTURE_HPP
