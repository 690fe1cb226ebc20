// Part of <box2scene/box2d.hpp> (a host includes that header only): a plan's shapes made into
// a body's fixtures.
#ifndef BOX2SCENE_DETAIL_BOX2D_SHAPES_HPP
#define BOX2SCENE_DETAIL_BOX2D_SHAPES_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "world.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace box2scene {
namespace detail {

/// A shape's points, as Box2D takes them.
inline std::vector<b2Vec2> PlanExecutor::points(const b2s_plan_shape& shape) const {
    std::vector<b2Vec2> points;
    points.reserve(shape.points.count);
    for (uint32_t i = 0; i < shape.points.count; ++i) {
        points.push_back(to_b2(plan_.points[shape.points.first + i]));
    }
    return points;
}

inline b2Fixture* PlanExecutor::make_fixture(const b2s_plan_shape& shape, b2Body* body) {
    const b2Shape* made = shape_of(shape);
    if (made == nullptr) {
        return nullptr;
    }
    // CreateFixture recomputes the body's mass from all its fixtures whenever it adds one
    // with a density, which makes a body of n fixtures cost n^2: the density is set
    // after, and make_body has the mass computed once.
    bool withheld = shape.density > 0.0f;
    b2FixtureDef def;
    def.shape = made;
    def.density = withheld ? 0.0f : shape.density;
    def.friction = shape.friction;
    def.restitution = shape.restitution;
    def.isSensor = shape.is_sensor;
    def.filter.categoryBits = static_cast<uint16>(shape.filter.category_bits);
    def.filter.maskBits = static_cast<uint16>(shape.filter.mask_bits);
    def.filter.groupIndex = shape.filter.group_index;
    b2Fixture* created = body->CreateFixture(&def);
    if (withheld) {
        created->SetDensity(shape.density);
    }
    return created;
}

/// The plan gives every fixture of a scene shape the same one.
inline const b2Shape* PlanExecutor::shape_of(const b2s_plan_shape& shape) {
    if (shape.shape >= shapes_.size()) {
        return nullptr;
    }
    std::unique_ptr<b2Shape>& made = shapes_[shape.shape];
    if (made == nullptr) {
        made = make_shape(shape);
    }
    return made.get();
}

inline std::unique_ptr<b2Shape> PlanExecutor::make_shape(const b2s_plan_shape& shape) const {
    switch (shape.kind) {
    case B2S_PLAN_SHAPE_KIND_CIRCLE: return make_circle(shape);
    case B2S_PLAN_SHAPE_KIND_POLYGON: return make_polygon(shape);
    case B2S_PLAN_SHAPE_KIND_SEGMENT: return make_segment(shape);
    case B2S_PLAN_SHAPE_KIND_CHAIN: return make_chain(shape);
    case B2S_PLAN_SHAPE_KIND_LOOP: return make_loop(shape);
    default: return nullptr; // the plan makes no other for 2.4
    }
}

inline std::unique_ptr<b2Shape> PlanExecutor::make_circle(const b2s_plan_shape& shape) const {
    auto circle = std::make_unique<b2CircleShape>();
    circle->m_radius = shape.radius;
    circle->m_p = to_b2(shape.center);
    return circle;
}

/// A centroid the file gives is kept (NaN where it gives none).
inline std::unique_ptr<b2Shape> PlanExecutor::make_polygon(const b2s_plan_shape& shape) const {
    auto polygon = std::make_unique<b2PolygonShape>();
    std::vector<b2Vec2> p = points(shape);
    polygon->Set(p.data(), static_cast<int32>(p.size()));
    if (!std::isnan(shape.center.x)) {
        polygon->m_centroid = to_b2(shape.center);
    }
    return polygon;
}

/// Two points: two-sided; four: one-sided, between its ghosts.
inline std::unique_ptr<b2Shape> PlanExecutor::make_segment(const b2s_plan_shape& shape) const {
    auto edge = std::make_unique<b2EdgeShape>();
    std::vector<b2Vec2> p = points(shape);
    if (p.size() == 4) {
        edge->SetOneSided(p[0], p[1], p[2], p[3]);
    } else {
        edge->SetTwoSided(p[0], p[1]);
    }
    return edge;
}

/// Its first and last points are the ghosts.
inline std::unique_ptr<b2Shape> PlanExecutor::make_chain(const b2s_plan_shape& shape) const {
    auto chain = std::make_unique<b2ChainShape>();
    std::vector<b2Vec2> p = points(shape);
    int32 count = static_cast<int32>(p.size());
    chain->CreateChain(p.data() + 1, count - 2, p[0], p[count - 1]);
    return chain;
}

inline std::unique_ptr<b2Shape> PlanExecutor::make_loop(const b2s_plan_shape& shape) const {
    auto chain = std::make_unique<b2ChainShape>();
    std::vector<b2Vec2> p = points(shape);
    chain->CreateLoop(p.data(), static_cast<int32>(p.size()));
    return chain;
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_SHAPES_HPP
