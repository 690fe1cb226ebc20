// Part of <box2scene/box2d.hpp> (a host includes that header only): the build's shapes, made once each, and the fixtures that use them.
#ifndef BOX2SCENE_DETAIL_BOX2D_SHAPES_HPP
#define BOX2SCENE_DETAIL_BOX2D_SHAPES_HPP

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

/// `end` continued by one segment away from `inner`: a ghost vertex for an open chain end
/// the file left without one (Box2D 2.4's CreateChain needs both).
inline b2Vec2 extrapolated(b2Vec2 end, b2Vec2 inner) {
    return end + (end - inner);
}

inline void WorldBuilder::make_shapes() {
    shapes_.resize(view_.shape_count);
    for (uint32_t i = 0; i < view_.shape_count; ++i) {
        shapes_[i] = make_shape(i);
    }
}

inline std::unique_ptr<b2Shape> WorldBuilder::make_shape(uint32_t index) {
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

inline bool WorldBuilder::vertices_of(const b2s_shape& shape, std::vector<b2Vec2>& points) const {
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
inline RangeCheck WorldBuilder::shape_check(const b2s_shape& shape, const std::vector<b2Vec2>& points) {
    const float length = working_range().max_length;
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

inline bool WorldBuilder::vertex_count_fits(const b2s_shape& shape, size_t count) {
    switch (shape.kind) {
    case B2S_SHAPE_KIND_POLYGON: return count >= 2 && count <= b2_maxPolygonVertices;
    case B2S_SHAPE_KIND_EDGE: return count == 2;
    case B2S_SHAPE_KIND_CHAIN: return count >= (shape.is_loop ? 3u : 2u);
    default: return true;
    }
}

inline std::unique_ptr<b2Shape> WorldBuilder::make_circle(const b2s_shape& shape) {
    auto circle = std::make_unique<b2CircleShape>();
    circle->m_radius = shape.radius;
    circle->m_p = to_b2(shape.position);
    return circle;
}

/// Two vertices are Box2D 2.1's SetAsEdge output: a line segment.
inline std::unique_ptr<b2Shape> WorldBuilder::make_polygon(const b2s_shape& shape,
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

inline std::unique_ptr<b2Shape> WorldBuilder::make_edge(const b2s_shape& shape,
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

inline std::unique_ptr<b2Shape> WorldBuilder::make_chain(const b2s_shape& shape,
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

inline void WorldBuilder::make_fixtures(uint32_t body_index, const b2s_body& body, b2Body* created) {
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

inline bool WorldBuilder::shape_created(const b2s_fixture& fixture) const {
    return fixture.shape < shapes_.size() && shapes_[fixture.shape] != nullptr;
}

inline RangeCheck WorldBuilder::fixture_check(const b2s_fixture& fixture) {
    RangeCheck check;
    check.magnitude("Density", fixture.density, working_range().max_density, "kg/m^2");
    check.magnitude("Friction", fixture.friction, working_range().max_friction, "");
    check.magnitude("Restitution", fixture.restitution, working_range().max_friction, "");
    return check;
}

/// Box2D 2.4 holds 16 of the scene's 32 filter bits: reports each fixture that the cut
/// makes collide otherwise (a category bit above 16, or a mask meeting one in use).
inline void WorldBuilder::report_lossy_filters() {
    const uint32_t high = 0xFFFF0000u;
    uint32_t high_in_use = 0;
    for (uint32_t i = 0; i < view_.fixture_count; ++i) {
        high_in_use |= view_.fixtures[i].filter.category_bits & high;
    }
    for (uint32_t i = 0; high_in_use != 0 && i < view_.fixture_count; ++i) {
        const b2s_filter& filter = view_.fixtures[i].filter;
        if ((filter.category_bits & high) != 0 || (filter.mask_bits & high_in_use) != 0) {
            report(B2S_CODE_LOSSY_FILTER, "fixture", i, view_.fixtures[i].name,
                   "category bits " + std::to_string(filter.category_bits) + " and mask bits " +
                       std::to_string(filter.mask_bits) +
                       " reach above Box2D 2.4's 16 filter bits where categories in use "
                       "are; the low 16 were used, so it collides otherwise");
        }
    }
}

/// Whether make_fixture will create fixture `index`.
inline bool WorldBuilder::fixture_creatable(uint32_t index) const {
    return index < view_.fixture_count && shape_created(view_.fixtures[index]) &&
           fixture_check(view_.fixtures[index]).passed();
}

inline b2Fixture* WorldBuilder::make_fixture(uint32_t body_index, uint32_t index, b2Body* body) {
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
    def.filter.categoryBits = static_cast<uint16>(fixture.filter.category_bits);
    def.filter.maskBits = static_cast<uint16>(fixture.filter.mask_bits);
    def.filter.groupIndex = fixture.filter.group_index;
    b2Fixture* created = body->CreateFixture(&def);
    if (withheld) {
        created->SetDensity(fixture.density);
    }
    return created;
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_SHAPES_HPP
