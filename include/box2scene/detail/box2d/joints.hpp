// Part of <box2scene/box2d.hpp> (a host includes that header only): the build's joints,
// checked against the working range once every body has its final mass.
#ifndef BOX2SCENE_DETAIL_BOX2D_JOINTS_HPP
#define BOX2SCENE_DETAIL_BOX2D_JOINTS_HPP

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

/// Sets the fields every joint has; false (and a report) when a body is missing.
template <class Def>
inline bool WorldBuilder::connect(uint32_t index, const b2s_joint& joint, Def& def) {
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

inline b2Body* WorldBuilder::created_body(uint32_t index) const {
    return index < built_.bodies.size() ? built_.bodies[index] : nullptr;
}

template <class Def>
inline void WorldBuilder::create(uint32_t index, const Def& def) {
    built_.joints[index] = world_.CreateJoint(&def);
}

inline void WorldBuilder::make_joint(uint32_t index) {
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
inline float WorldBuilder::starting_violation(const b2s_joint& joint) const {
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
/// than working_range().max_pulled_violation from satisfied can be torn to NaN by its position
/// solver. The first such joint on a body is built, the later ones are not.
inline RangeCheck WorldBuilder::violation_check(const b2s_joint& joint) {
    RangeCheck check;
    float violation = starting_violation(joint);
    if (!(violation > working_range().max_pulled_violation)) {
        return check;
    }
    for (uint32_t body : {joint.body_a, joint.body_b}) {
        if (pulled_[body] != nullptr) {
            check.fail("it starts " + decimal(violation) + " m from satisfied, and joint " +
                       std::to_string(pulled_[body] - view_.joints) + " already pulls body " +
                       std::to_string(body) + " from further than " +
                       rounded(working_range().max_pulled_violation) +
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
inline RangeCheck WorldBuilder::joint_check(const b2s_joint& joint) const {
    const b2s_working_range& range = working_range();
    RangeCheck check;
    bool axis = false, spring = false, forces = false;
    b2s_vec2 anchor_a = joint.local_anchor_a, anchor_b = joint.local_anchor_b;
    switch (joint.kind) {
    case B2S_JOINT_KIND_REVOLUTE:
        check.magnitude("ReferenceAngle", joint.reference_angle, range.max_angle, "rad");
        check.magnitude("LowerAngle", joint.lower_limit, range.max_angle, "rad");
        check.magnitude("UpperAngle", joint.upper_limit, range.max_angle, "rad");
        check.magnitude("MotorSpeed", joint.motor_speed, range.max_speed, "rad/s");
        check.magnitude("MaxMotorTorque", joint.max_motor_torque, range.max_force, "N m");
        break;
    case B2S_JOINT_KIND_PRISMATIC:
        check.magnitude("ReferenceAngle", joint.reference_angle, range.max_angle, "rad");
        check.magnitude("MotorSpeed", joint.motor_speed, range.max_speed, "m/s");
        check.magnitude("MaxMotorForce", joint.max_motor_force, range.max_force, "N");
        [[fallthrough]];
    case B2S_JOINT_KIND_LINE: // its motor stays off
        axis = true;
        check.magnitude("LowerTranslation", joint.lower_limit, range.max_length, "m");
        check.magnitude("UpperTranslation", joint.upper_limit, range.max_length, "m");
        break;
    case B2S_JOINT_KIND_DISTANCE:
        spring = true;
        check.magnitude("Length", joint.length, range.max_length, "m");
        if (joint.frequency_hz > 0.0f && massless(joint.body_a) && massless(joint.body_b)) {
            // Its upper length, FLT_MAX, gives Box2D's solver an infinite bias that
            // only a body with mass multiplies into something other than NaN.
            check.fail("a spring (FrequencyHz > 0) between two bodies without mass, for "
                       "which Box2D 2.4's distance joint computes 0 * infinity = NaN");
        }
        break;
    case B2S_JOINT_KIND_ROPE:
        check.magnitude("MaxLength", joint.max_length, range.max_length, "m");
        break;
    case B2S_JOINT_KIND_PULLEY:
        check.vector("GroundAnchorA", joint.ground_anchor_a, range.max_length, "m");
        check.vector("GroundAnchorB", joint.ground_anchor_b, range.max_length, "m");
        check.magnitude("LengthA", joint.length_a, range.max_length, "m");
        check.magnitude("LengthB", joint.length_b, range.max_length, "m");
        check.magnitude("Ratio", joint.ratio, range.max_ratio, "");
        break;
    case B2S_JOINT_KIND_WHEEL:
        axis = spring = true;
        check.magnitude("MotorSpeed", joint.motor_speed, range.max_speed, "rad/s");
        check.magnitude("MaxMotorTorque", joint.max_motor_torque, range.max_force, "N m");
        break;
    case B2S_JOINT_KIND_WELD:
        spring = true;
        check.magnitude("ReferenceAngle", joint.reference_angle, range.max_angle, "rad");
        break;
    case B2S_JOINT_KIND_FRICTION: forces = true; break;
    case B2S_JOINT_KIND_MOTOR:
        forces = true;
        anchor_a = joint.linear_offset; // body B's origin, held there in A's frame
        anchor_b = b2s_vec2{0.0f, 0.0f};
        check.vector("LinearOffset", joint.linear_offset, range.max_length, "m");
        check.magnitude("AngularOffset", joint.angular_offset, range.max_angle, "rad");
        check.within("CorrectionFactor", joint.correction_factor, 0.0f, 1.0f, "");
        break;
    default: return check; // not created: reported by make_joint
    }
    if (joint.kind != B2S_JOINT_KIND_MOTOR) {
        check.vector("LocalAnchorA", joint.local_anchor_a, range.max_length, "m");
        check.vector("LocalAnchorB", joint.local_anchor_b, range.max_length, "m");
    }
    if (axis) {
        check.vector("LocalAxisA", joint.local_axis_a, range.max_length, "m");
        check.at_least("The length of LocalAxisA",
                       b2Vec2(joint.local_axis_a.x, joint.local_axis_a.y).Length(),
                       range.min_axis, "m");
    }
    if (spring) {
        check.magnitude("FrequencyHz", joint.frequency_hz, range.max_frequency, "Hz");
        check.magnitude("DampingRatio", joint.damping_ratio, range.max_frequency, "");
        check_stiffness(joint, check);
    }
    if (forces) {
        check.magnitude("MaxForce", joint.max_force, range.max_force, "N");
        check.magnitude("MaxTorque", joint.max_torque, range.max_force, "N m");
    }
    if (check.passed()) {
        check_anchors(joint, anchor_a, anchor_b, check);
    }
    return check;
}

inline bool WorldBuilder::massless(uint32_t body) const { return masses_[body].mass == 0.0f; }

/// Box2D divides by h * (damping + h * stiffness): a spring whose stiffness underflows,
/// from a tiny FrequencyHz or mass, makes that infinite. The stiffness is computed as
/// make_distance, make_wheel and make_weld compute it.
inline void WorldBuilder::check_stiffness(const b2s_joint& joint, RangeCheck& check) const {
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
    if (stiffness != 0.0f && !(stiffness >= working_range().min_stiffness)) {
        check.fail("FrequencyHz " + decimal(joint.frequency_hz) + " gives a stiffness of " +
                   decimal(stiffness) + (angular ? " N m/rad" : " N/m") +
                   " with these bodies, beyond Box2D 2.4's working range (0 or at least " +
                   rounded(working_range().min_stiffness) + ")");
    }
}

/// Box2D's joint solvers invert matrices of 1/m + r^2/I at the anchor (r from the
/// centre of mass): past max_compliance they overflow, and past max_lever_revolute
/// (revolute, friction, motor) or max_lever (prismatic, weld) radii of gyration their
/// determinants lose every bit to cancellation (docs/working-range.md). A prismatic
/// joint's lever on body A reaches body B's anchor.
inline void WorldBuilder::check_anchors(const b2s_joint& joint, b2s_vec2 anchor_a, b2s_vec2 anchor_b,
                   RangeCheck& check) const {
    b2Vec2 a = to_b2(anchor_a), b = to_b2(anchor_b);
    float lever = 0.0f; // none: Box2D solves the joint's rows one by one
    switch (joint.kind) {
    case B2S_JOINT_KIND_REVOLUTE:
    case B2S_JOINT_KIND_FRICTION:
    case B2S_JOINT_KIND_MOTOR: lever = working_range().max_lever_revolute; break;
    case B2S_JOINT_KIND_PRISMATIC:
    case B2S_JOINT_KIND_WELD: lever = working_range().max_lever; break;
    default: break;
    }
    const b2MassData& mass_a = masses_[joint.body_a];
    float lever_a = b2Distance(a, mass_a.center);
    if (working_range().prismatic_lever_to_b && joint.kind == B2S_JOINT_KIND_PRISMATIC) {
        const b2Body* body_a = built_.bodies[joint.body_a];
        b2Vec2 b_on_a = body_a->GetLocalPoint(built_.bodies[joint.body_b]->GetWorldPoint(b));
        lever_a = std::max(lever_a, b2Distance(b_on_a, mass_a.center));
    }
    const char* field_a = joint.kind == B2S_JOINT_KIND_MOTOR ? "LinearOffset" : "LocalAnchorA";
    check_anchor(field_a, joint.body_a, lever_a, lever, check);
    check_anchor("LocalAnchorB", joint.body_b,
                 b2Distance(b, masses_[joint.body_b].center), lever, check);
}

inline void WorldBuilder::check_anchor(const char* field, uint32_t body, float r, float lever,
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
    if (!(compliance <= working_range().max_compliance)) {
        check.fail(where + "where 1/m + r^2/I = " + rounded(compliance) +
                   " 1/kg lies beyond Box2D 2.4's working range (at most " +
                   rounded(working_range().max_compliance) + " 1/kg)");
    } else if (lever > 0.0f && mass.I > 0.0f &&
               !(r <= lever * std::sqrt(mass.I / mass.mass))) {
        check.fail(where + rounded(r / std::sqrt(mass.I / mass.mass)) +
                   " radii of gyration out, beyond Box2D 2.4's working range for this "
                   "joint (at most " + rounded(lever) + ")");
    }
}

/// Box2D 2.2's springs: stiffness m w^2 and damping 2 m zeta w, w = 2 pi FrequencyHz,
/// for the mass `m` the spring moves (b2LinearStiffness's arithmetic).
inline void WorldBuilder::spring(const b2s_joint& joint, float mass, float& stiffness, float& damping) {
    float omega = 2.0f * b2_pi * joint.frequency_hz;
    stiffness = mass * omega * omega;
    damping = 2.0f * mass * joint.damping_ratio * omega;
}

/// 1/I about the centre of mass (b2Body::GetInertia is about the origin), 0 for a body
/// that does not turn.
inline float WorldBuilder::inverse_central_inertia(const b2Body* body) {
    b2Vec2 c = body->GetLocalCenter();
    float inertia = body->GetInertia() - body->GetMass() * b2Dot(c, c);
    return inertia > 0.0f ? 1.0f / inertia : 0.0f;
}

inline float WorldBuilder::inverse_mass(const b2Body* body) {
    float mass = body->GetMass();
    return mass > 0.0f ? 1.0f / mass : 0.0f;
}

/// Box2D 2.2's soft weld: the angular mass 1/(1/IA + 1/IB) from the inertias about the
/// centres of mass (b2AngularStiffness takes those about the origins).
inline void WorldBuilder::weld_spring(const b2s_joint& joint, const b2Body* a, const b2Body* b,
                        float& stiffness, float& damping) {
    float inverse = inverse_central_inertia(a) + inverse_central_inertia(b);
    spring(joint, inverse > 0.0f ? 1.0f / inverse : 0.0f, stiffness, damping);
}

/// Box2D 2.2's wheel spring: the effective mass along the axis as the joint starts,
/// 1/(1/mA + 1/mB + sAx^2/IA + sBx^2/IB), as 2.2's InitVelocityConstraints computes it
/// (b2LinearStiffness takes mA mB/(mA + mB)).
inline void WorldBuilder::wheel_spring(const b2s_joint& joint, const b2Body* a, const b2Body* b,
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

inline void WorldBuilder::make_revolute(uint32_t index, const b2s_joint& joint) {
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

inline void WorldBuilder::make_prismatic(uint32_t index, const b2s_joint& joint) {
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
inline void WorldBuilder::make_distance(uint32_t index, const b2s_joint& joint) {
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
inline void WorldBuilder::make_rope(uint32_t index, const b2s_joint& joint) {
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
inline void WorldBuilder::make_pulley(uint32_t index, const b2s_joint& joint) {
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

inline void WorldBuilder::limit_pulley_side(uint32_t index, const b2s_joint& joint, const char* field,
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
inline b2Body* WorldBuilder::static_body() const {
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
inline void WorldBuilder::set_anchors_and_axis(const b2s_joint& joint, Def& def) {
    def.localAnchorA = to_b2(joint.local_anchor_a);
    def.localAnchorB = to_b2(joint.local_anchor_b);
    def.localAxisA = to_b2(joint.local_axis_a);
    def.localAxisA.Normalize();
}

/// Box2D 2.1's line joint is a wheel joint without a spring. Its motor drove the
/// translation; the wheel joint's motor drives the rotation, so it stays off.
inline void WorldBuilder::make_line(uint32_t index, const b2s_joint& joint) {
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

inline void WorldBuilder::make_wheel(uint32_t index, const b2s_joint& joint) {
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

inline void WorldBuilder::make_weld(uint32_t index, const b2s_joint& joint) {
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

inline void WorldBuilder::make_friction(uint32_t index, const b2s_joint& joint) {
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

inline void WorldBuilder::make_motor(uint32_t index, const b2s_joint& joint) {
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

inline void WorldBuilder::make_gear(uint32_t index) {
    const b2s_joint& joint = view_.joints[index];
    b2GearJointDef def;
    def.joint1 = gear_input(index, joint, joint.joint_a);
    def.joint2 = gear_input(index, joint, joint.joint_b);
    if (def.joint1 == nullptr || def.joint2 == nullptr || !connect(index, joint, def)) {
        return;
    }
    RangeCheck check;
    check.magnitude("Ratio", joint.ratio, working_range().max_ratio, "");
    if (!within_range(check, "joint", index, joint.name)) {
        return;
    }
    def.ratio = joint.ratio;
    create(index, def);
}

/// The created revolute or prismatic joint a gear couples, or nullptr (reported).
inline b2Joint* WorldBuilder::gear_input(uint32_t index, const b2s_joint& gear, uint32_t input) {
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

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_JOINTS_HPP
