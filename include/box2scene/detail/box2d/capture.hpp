// Part of <box2scene/box2d.hpp> (a host includes that header only): capture_world, a live
// b2World read through Box2D's getters into the library's held records (b2s_held_world:
// the plan's own records, read back), which the library turns into a scene and the reports
// of what it cannot hold exactly (b2s_capture_make). Nothing is converted or checked here.
#ifndef BOX2SCENE_DETAIL_BOX2D_CAPTURE_HPP
#define BOX2SCENE_DETAIL_BOX2D_CAPTURE_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "world.hpp"

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace box2scene {
namespace detail {

/// Frees a capture when it goes out of scope.
struct CaptureFree {
    void operator()(b2s_capture* capture) const { b2s_capture_free(capture); }
};
using CapturePtr = std::unique_ptr<b2s_capture, CaptureFree>;

/// Box2D 2.4.1 has no getters for a pulley's local anchors. A class derived from the joint
/// may name its protected members, and a pointer to one reads any pulley.
struct PulleyAnchors : b2PulleyJoint {
    static b2Vec2 a(const b2PulleyJoint& j) { return j.*(&PulleyAnchors::m_localAnchorA); }
    static b2Vec2 b(const b2PulleyJoint& j) { return j.*(&PulleyAnchors::m_localAnchorB); }
};

/// Box2D prepends what it creates to its lists.
template <class T>
std::vector<T*> creation_order(T* newest) {
    std::vector<T*> objects;
    for (T* object = newest; object != nullptr; object = object->GetNext()) {
        objects.push_back(object);
    }
    return std::vector<T*>(objects.rbegin(), objects.rend());
}

/// What a world holds, read into the held records, and the texts their labels point at.
class WorldReader {
public:
    /// `built`: what build_world made of the level the capture is given, or nullptr.
    WorldReader(b2World& world, const Namer& namer, const Built* built)
        : world_(world), namer_(namer), built_(built) {
        if (built_ != nullptr) {
            index_made(built_->bodies, made_bodies_);
            index_made(built_->fixtures, made_fixtures_);
            index_made(built_->joints, made_joints_);
        }
    }

    b2s_held_world read() {
        for (b2Body* body : creation_order(world_.GetBodyList())) {
            body_index_.emplace(body, static_cast<uint32_t>(bodies_.size()));
            read_body(*body);
        }
        std::vector<b2Joint*> joints = creation_order(world_.GetJointList());
        for (b2Joint* joint : joints) {
            joint_index_.emplace(joint, static_cast<uint32_t>(joint_index_.size()));
        }
        for (b2Joint* joint : joints) {
            read_joint(*joint);
        }
        if (built_ != nullptr) {
            for (uint32_t r = 0; r < built_->joints.size(); ++r) {
                if (built_->joints[r] == nullptr) {
                    skipped_.push_back(r);
                }
            }
        }
        b2s_held_world world{};
        world.engine = B2S_ENGINE_BOX2D24;
        world.gravity = to_b2s(world_.GetGravity());
        world.bodies = bodies_.data();
        world.shapes = shapes_.data();
        world.points = points_.data();
        world.joints = joints_.data();
        world.skipped_joints = skipped_.data();
        world.body_count = static_cast<uint32_t>(bodies_.size());
        world.shape_count = static_cast<uint32_t>(shapes_.size());
        world.point_count = static_cast<uint32_t>(points_.size());
        world.joint_count = static_cast<uint32_t>(joints_.size());
        world.skipped_count = static_cast<uint32_t>(skipped_.size());
        return world;
    }

private:
    /// Where each object build_world made stands in what it made (its scene record, or its
    /// fixture slot), found by hashing: one walk over what it made, not one an object.
    template <class T>
    static void index_made(const std::vector<T*>& made,
                           std::unordered_map<const T*, uint32_t>& at) {
        at.reserve(made.size());
        for (uint32_t i = 0; i < made.size(); ++i) {
            if (made[i] != nullptr) {
                at.emplace(made[i], i);
            }
        }
    }

    /// The scene record `object` was made from, or B2S_NONE (the host's).
    template <class T>
    static uint32_t made_at(const std::unordered_map<const T*, uint32_t>& at, const T* object) {
        auto found = at.find(object);
        return found != at.end() ? found->second : B2S_NONE;
    }

    /// A text the records point at, kept until the capture is made; NULL for none.
    b2s_str keep(const std::string& text) {
        if (text.empty()) {
            return nullptr;
        }
        texts_.push_back(text);
        return texts_.back().c_str();
    }

    b2s_held_label label(const Label& label) {
        return b2s_held_label{keep(label.name),
                              b2s_user_data{keep(label.user_data_raw), keep(label.user_data_type),
                                            keep(label.user_data_value)}};
    }

    void read_body(b2Body& body) {
        b2s_held_body held{};
        b2s_plan_body& b = held.body;
        b.body = made_at(made_bodies_, &body);
        b.kind = static_cast<uint32_t>(body.GetType());
        b.position = to_b2s(body.GetPosition());
        b.angle = body.GetAngle();
        b.rotation = b2s_rot{body.GetTransform().q.c, body.GetTransform().q.s};
        b.linear_velocity = to_b2s(body.GetLinearVelocity());
        b.angular_velocity = body.GetAngularVelocity();
        b.linear_damping = body.GetLinearDamping();
        b.angular_damping = body.GetAngularDamping();
        b.gravity_scale = body.GetGravityScale();
        b.mass = b2s_plan_mass{body.GetMass(), to_b2s(body.GetLocalCenter()), body.GetInertia()};
        b.allow_sleep = body.IsSleepingAllowed();
        b.awake = body.IsAwake();
        b.fixed_rotation = body.IsFixedRotation();
        b.bullet = body.IsBullet();
        b.enabled = body.IsEnabled();
        uint32_t first = static_cast<uint32_t>(shapes_.size());
        for (b2Fixture* fixture : creation_order(body.GetFixtureList())) {
            read_fixture(*fixture);
        }
        b.shapes = b2s_range{first, static_cast<uint32_t>(shapes_.size()) - first};
        held.label = label(namer_.body(body));
        bodies_.push_back(held);
    }

    /// The shape's points, as the plan gives them (see b2s_plan_shape_kind).
    b2s_range push_points(std::initializer_list<b2Vec2> points) {
        return push_points(points.begin(), points.size());
    }
    b2s_range push_points(const b2Vec2* points, size_t count) {
        uint32_t first = static_cast<uint32_t>(points_.size());
        for (size_t i = 0; i < count; ++i) {
            points_.push_back(to_b2s(points[i]));
        }
        return b2s_range{first, static_cast<uint32_t>(count)};
    }

    void read_shape(const b2Shape& shape, b2s_held_shape& held) {
        b2s_plan_shape& s = held.shape;
        s.radius = shape.m_radius;
        switch (shape.GetType()) {
        case b2Shape::e_circle: {
            s.kind = B2S_PLAN_SHAPE_KIND_CIRCLE;
            s.center = to_b2s(static_cast<const b2CircleShape&>(shape).m_p);
            return;
        }
        case b2Shape::e_polygon: {
            const auto& polygon = static_cast<const b2PolygonShape&>(shape);
            s.kind = B2S_PLAN_SHAPE_KIND_POLYGON;
            s.points = push_points(polygon.m_vertices, static_cast<size_t>(polygon.m_count));
            s.center = to_b2s(polygon.m_centroid);
            return;
        }
        case b2Shape::e_edge: {
            const auto& edge = static_cast<const b2EdgeShape&>(shape);
            s.kind = B2S_PLAN_SHAPE_KIND_SEGMENT;
            s.points = edge.m_oneSided ? push_points({edge.m_vertex0, edge.m_vertex1,
                                                      edge.m_vertex2, edge.m_vertex3})
                                       : push_points({edge.m_vertex1, edge.m_vertex2});
            return;
        }
        case b2Shape::e_chain: {
            const auto& chain = static_cast<const b2ChainShape&>(shape);
            s.kind = B2S_PLAN_SHAPE_KIND_CHAIN;
            s.points = push_points({chain.m_prevVertex});
            push_points(chain.m_vertices, static_cast<size_t>(chain.m_count));
            push_points({chain.m_nextVertex});
            s.points.count = static_cast<uint32_t>(points_.size()) - s.points.first;
            return;
        }
        default:
            held.other = keep("Box2D shape type " + std::to_string(shape.GetType()));
        }
    }

    void read_fixture(b2Fixture& fixture) {
        b2s_held_shape held{};
        b2s_plan_shape& s = held.shape;
        s.slot = made_at(made_fixtures_, &fixture);
        s.fixture = B2S_NONE;
        s.shape = B2S_NONE;
        read_shape(*fixture.GetShape(), held);
        s.density = fixture.GetDensity();
        s.friction = fixture.GetFriction();
        s.restitution = fixture.GetRestitution();
        s.is_sensor = fixture.IsSensor();
        const b2Filter& filter = fixture.GetFilterData();
        held.category_bits = filter.categoryBits;
        held.mask_bits = filter.maskBits;
        held.group_index = filter.groupIndex;
        held.restitution_threshold = fixture.GetRestitutionThreshold();
        held.chain = B2S_NONE;
        held.label = label(namer_.fixture(fixture));
        held.shape_name = keep(namer_.shape(fixture));
        shapes_.push_back(held);
    }

    uint32_t held_body(b2Body* body) const {
        auto found = body_index_.find(body);
        return found != body_index_.end() ? found->second : B2S_NONE;
    }

    uint32_t held_joint(b2Joint* joint) const {
        auto found = joint_index_.find(joint);
        return found != joint_index_.end() ? found->second : B2S_NONE;
    }

    void read_joint(b2Joint& joint) {
        b2s_held_joint held{};
        b2s_plan_joint& j = held.joint;
        j.joint = made_at(made_joints_, &joint);
        j.body_a = held_body(joint.GetBodyA());
        j.body_b = held_body(joint.GetBodyB());
        j.joint_a = j.joint_b = B2S_NONE;
        j.collide_connected = joint.GetCollideConnected();
        read_kind(joint, held);
        held.label = label(namer_.joint(joint));
        joints_.push_back(held);
    }

    /// The anchors every kind but the gear and motor joint has.
    template <class Joint>
    static void anchors(const Joint& joint, b2s_plan_joint& j) {
        j.anchor_a = to_b2s(joint.GetLocalAnchorA());
        j.anchor_b = to_b2s(joint.GetLocalAnchorB());
    }

    /// The limit and motor of a revolute or prismatic joint.
    template <class Joint>
    static void limit_and_motor(const Joint& joint, b2s_plan_joint& j) {
        j.reference_angle = joint.GetReferenceAngle();
        j.enable_limit = joint.IsLimitEnabled();
        j.lower = joint.GetLowerLimit();
        j.upper = joint.GetUpperLimit();
        j.enable_motor = joint.IsMotorEnabled();
        j.motor_speed = joint.GetMotorSpeed();
    }

    void read_kind(b2Joint& joint, b2s_held_joint& held) {
        b2s_plan_joint& j = held.joint;
        switch (joint.GetType()) {
        case e_revoluteJoint: {
            const auto& r = static_cast<const b2RevoluteJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_REVOLUTE;
            anchors(r, j);
            limit_and_motor(r, j);
            j.max_motor = r.GetMaxMotorTorque();
            return;
        }
        case e_prismaticJoint: {
            const auto& p = static_cast<const b2PrismaticJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_PRISMATIC;
            anchors(p, j);
            limit_and_motor(p, j);
            j.axis = to_b2s(p.GetLocalAxisA());
            j.max_motor = p.GetMaxMotorForce();
            return;
        }
        case e_distanceJoint: {
            const auto& d = static_cast<const b2DistanceJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_DISTANCE;
            anchors(d, j);
            j.length = d.GetLength();
            j.min_length = d.GetMinLength();
            j.max_length = d.GetMaxLength();
            j.stiffness = d.GetStiffness();
            j.damping = d.GetDamping();
            return;
        }
        case e_pulleyJoint: {
            const auto& p = static_cast<const b2PulleyJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_PULLEY;
            j.anchor_a = to_b2s(PulleyAnchors::a(p));
            j.anchor_b = to_b2s(PulleyAnchors::b(p));
            j.ground_anchor_a = to_b2s(p.GetGroundAnchorA());
            j.ground_anchor_b = to_b2s(p.GetGroundAnchorB());
            j.length_a = p.GetLengthA();
            j.length_b = p.GetLengthB();
            j.ratio = p.GetRatio();
            return;
        }
        case e_gearJoint: {
            auto& g = static_cast<b2GearJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_GEAR;
            j.joint_a = held_joint(g.GetJoint1());
            j.joint_b = held_joint(g.GetJoint2());
            j.ratio = g.GetRatio();
            return;
        }
        case e_wheelJoint: {
            const auto& w = static_cast<const b2WheelJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_WHEEL;
            anchors(w, j);
            j.axis = to_b2s(w.GetLocalAxisA());
            j.enable_limit = w.IsLimitEnabled();
            j.lower = w.GetLowerLimit();
            j.upper = w.GetUpperLimit();
            j.enable_motor = w.IsMotorEnabled();
            j.motor_speed = w.GetMotorSpeed();
            j.max_motor = w.GetMaxMotorTorque();
            j.stiffness = w.GetStiffness();
            j.damping = w.GetDamping();
            return;
        }
        case e_weldJoint: {
            const auto& w = static_cast<const b2WeldJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_WELD;
            anchors(w, j);
            j.reference_angle = w.GetReferenceAngle();
            j.stiffness = w.GetStiffness();
            j.damping = w.GetDamping();
            return;
        }
        case e_frictionJoint: {
            const auto& f = static_cast<const b2FrictionJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_FRICTION;
            anchors(f, j);
            j.max_force = f.GetMaxForce();
            j.max_torque = f.GetMaxTorque();
            return;
        }
        case e_motorJoint: {
            const auto& m = static_cast<const b2MotorJoint&>(joint);
            j.kind = B2S_PLAN_JOINT_KIND_MOTOR;
            j.linear_offset = to_b2s(m.GetLinearOffset());
            j.angular_offset = m.GetAngularOffset();
            j.max_force = m.GetMaxForce();
            j.max_torque = m.GetMaxTorque();
            j.correction_factor = m.GetCorrectionFactor();
            return;
        }
        case e_mouseJoint: held.other = keep("a mouse joint (a host's drag)"); return;
        default: held.other = keep("Box2D joint type " + std::to_string(joint.GetType()));
        }
    }

    b2World& world_;
    const Namer& namer_;
    const Built* built_;
    std::vector<b2s_held_body> bodies_;
    std::vector<b2s_held_shape> shapes_;
    std::vector<b2s_vec2> points_;
    std::vector<b2s_held_joint> joints_;
    std::vector<uint32_t> skipped_;
    std::deque<std::string> texts_; // a deque keeps each text where it is as it grows
    std::unordered_map<const b2Body*, uint32_t> body_index_;
    std::unordered_map<const b2Joint*, uint32_t> joint_index_;
    std::unordered_map<const b2Body*, uint32_t> made_bodies_;
    std::unordered_map<const b2Fixture*, uint32_t> made_fixtures_;
    std::unordered_map<const b2Joint*, uint32_t> made_joints_;
};

/// The scene of what `world` holds, labelled from `scene` (what build_world made `built`
/// of) where given; the library's reports are appended to `reports`.
inline b2s_scene* capture(b2World& world, std::vector<Report>& reports, const Namer* namer,
                          const Built* built, const b2s_scene* scene) {
    const Namer unnamed;
    const b2s_scene_view* level = b2s_scene_get_view(scene);
    // A result of another scene, with other counts, labels nothing.
    bool same_level = built != nullptr && level != nullptr &&
                      built->bodies.size() == level->body_count &&
                      built->fixtures.size() == level->fixture_id_count &&
                      built->joints.size() == level->joint_count;
    WorldReader reader(world, namer != nullptr ? *namer : unnamed, same_level ? built : nullptr);
    b2s_held_world held = reader.read();
    b2s_capture* made = nullptr;
    b2s_error error{};
    if (b2s_capture_make(&held, same_level ? scene : nullptr, &made, &error) != B2S_CODE_OK) {
        reports.push_back(Report{static_cast<b2s_code>(error.code), "world", 0, std::string(),
                                 error.message});
        return nullptr;
    }
    CapturePtr captured(made);
    const b2s_capture_view& view = *b2s_capture_get_view(captured.get());
    append_reports(view.reports, view.report_count, reports);
    return b2s_capture_take_scene(captured.get());
}

} // namespace detail

inline b2s_scene* capture_world(b2World& world, std::vector<Report>& reports,
                                const Namer* namer) {
    return detail::capture(world, reports, namer, nullptr, nullptr);
}

inline b2s_scene* capture_world(b2World& world, const Built& built, const b2s_scene* scene,
                                std::vector<Report>& reports, const Namer* namer) {
    return detail::capture(world, reports, namer, &built, scene);
}

} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_CAPTURE_HPP
