/*
 * box2scene/box2d.hpp: builds a Box2D 2.4 b2World from a loaded box2scene scene.
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
 * The mapping is section 10 of the format specification. The adapter never prints, never
 * aborts and throws nothing for bad data: what it cannot create it skips and reports.
 * Debian's Box2D keeps its assertions on, so the adapter checks what they check before
 * calling Box2D (bodies it follows, joint kinds, a negative damping, a MassData that
 * leaves no positive inertia about the centre of mass), whether or not the loader in use
 * already refuses it: a report is better than an abort.
 * Call it outside b2World::Step (Box2D refuses to add objects to a locked world).
 */
#ifndef BOX2SCENE_BOX2D_HPP
#define BOX2SCENE_BOX2D_HPP

#include <box2d/box2d.h>
#include <box2scene.h>

#include <cfloat>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace box2scene {

/// Something of the scene that Box2D 2.4 could not represent, or only approximately.
struct Report {
    b2s_code code;       ///< B2S_CODE_LOSSY_LINE_MOTOR, B2S_CODE_SKIPPED_JOINT, ...
    const char* object;  ///< "shape", "fixture", "body" or "joint" (static storage)
    uint32_t index;      ///< index of the object in the scene's array of that kind
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

/// The scene's gravity when the file gives one, else `fallback` (the format has no default
/// gravity: the host decides). A NULL scene gives `fallback`.
inline b2Vec2 scene_gravity(const b2s_scene* scene, b2Vec2 fallback);

/// Adds the scene's bodies, fixtures and joints to `world`. A NULL scene adds nothing.
inline Built build_world(const b2s_scene* scene, b2World& world);

namespace detail {

inline b2Vec2 to_b2(b2s_vec2 v) {
    return b2Vec2(v.x, v.y);
}

inline std::string text_of(b2s_str s) {
    return s != nullptr ? std::string(s) : std::string();
}

/// `end` continued by one segment away from `inner`: a ghost vertex for an open chain end
/// the file left without one (Box2D 2.4's CreateChain needs both).
inline b2Vec2 extrapolated(b2Vec2 end, b2Vec2 inner) {
    return end + (end - inner);
}

/// Whether b2Body::SetMassData(&m) would derive a positive inertia about the centre of mass
/// where it uses one: Box2D asserts that it does.
inline bool central_inertia_positive(const b2MassData& m, bool fixed_rotation) {
    float mass = m.mass > 0.0f ? m.mass : 1.0f; // SetMassData replaces a zero mass by 1
    bool inertia_used = m.I > 0.0f && !fixed_rotation;
    return !inertia_used || m.I - mass * b2Dot(m.center, m.center) > 0.0f;
}

/// One build: the scene's view, the world, and what was made so far.
class WorldBuilder {
public:
    WorldBuilder(const struct b2s_scene_view& view, b2World& world) : view_(view), world_(world) {}

    Built run() {
        make_shapes();
        built_.bodies.assign(view_.body_count, nullptr);
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
            return;
        }
        b2BodyDef def = body_def(index, body);
        b2Body* created = world_.CreateBody(&def);
        built_.bodies[index] = created;
        make_fixtures(index, body, created);
        apply_mass_data(index, body, created);
    }

    b2BodyDef body_def(uint32_t index, const b2s_body& body) {
        b2BodyDef def;
        def.type = static_cast<b2BodyType>(body.kind);
        def.position = to_b2(body.position);
        def.angle = body.angle;
        def.linearVelocity = to_b2(body.linear_velocity);
        def.angularVelocity = body.angular_velocity;
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

    b2Fixture* make_fixture(uint32_t body_index, uint32_t index, b2Body* body) {
        std::string owner = "fixture " + std::to_string(index) + " of body " +
                            std::to_string(body_index);
        if (index >= view_.fixture_count) {
            report(B2S_CODE_ID_OUT_OF_RANGE, "fixture", index, nullptr,
                   owner + " does not exist");
            return nullptr;
        }
        const b2s_fixture& fixture = view_.fixtures[index];
        if (fixture.shape >= shapes_.size() || shapes_[fixture.shape] == nullptr) {
            report(B2S_CODE_SKIPPED_DEPENDENT, "fixture", index, fixture.name,
                   owner + " names shape " + std::to_string(fixture.shape) +
                       ", which was not created; fixture skipped");
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
        const b2s_mass_data& given = body.mass_data;
        if (!given.mass_given && !given.center_given && !given.inertia_given) {
            return;
        }
        b2MassData mass;
        created->GetMassData(&mass);
        if (given.mass_given) {
            mass.mass = given.mass;
        }
        if (given.center_given) {
            mass.center = to_b2(given.center);
        }
        if (given.inertia_given) {
            mass.I = given.inertia;
        }
        if (!central_inertia_positive(mass, body.fixed_rotation)) {
            report(B2S_CODE_INCONSISTENT_MASS_DATA, "body", index, body.name,
                   "its MassData leaves no positive inertia about the centre of mass "
                   "(Inertia < Mass * |Center|^2); the mass computed from the fixtures was kept");
            return;
        }
        created->SetMassData(&mass);
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
        return coupled;
    }

    const struct b2s_scene_view& view_;
    b2World& world_;
    std::vector<std::unique_ptr<b2Shape>> shapes_; // indexed like the scene's shapes
    Built built_;
};

} // namespace detail

inline b2Vec2 scene_gravity(const b2s_scene* scene, b2Vec2 fallback) {
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (view == nullptr || !view->gravity_given) {
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

} // namespace box2scene

#endif // BOX2SCENE_BOX2D_HPP
