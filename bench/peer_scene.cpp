#include "peer_scene.hpp"

#include <array>
#include <cstddef>

#include "peer_values.hpp"

namespace bench {

b2s_scene_view PeerScene::view() const {
    b2s_scene_view view{};
    view.shapes = shapes.data();
    view.fixtures = fixtures.data();
    view.bodies = bodies.data();
    view.joints = joints.data();
    view.vertices = vertices.data();
    view.fixture_ids = fixture_ids.data();
    view.shape_count = static_cast<uint32_t>(shapes.size());
    view.fixture_count = static_cast<uint32_t>(fixtures.size());
    view.body_count = static_cast<uint32_t>(bodies.size());
    view.joint_count = static_cast<uint32_t>(joints.size());
    view.vertex_count = static_cast<uint32_t>(vertices.size());
    view.fixture_id_count = static_cast<uint32_t>(fixture_ids.size());
    view.version = version;
    view.gravity = gravity;
    view.gravity_given = gravity_given;
    return view;
}

namespace peer {
namespace {

constexpr uint32_t bit(uint32_t kind) { return 1u << kind; }

constexpr uint32_t kRevolute = bit(B2S_JOINT_KIND_REVOLUTE),
                   kPrismatic = bit(B2S_JOINT_KIND_PRISMATIC),
                   kDistance = bit(B2S_JOINT_KIND_DISTANCE), kPulley = bit(B2S_JOINT_KIND_PULLEY),
                   kLine = bit(B2S_JOINT_KIND_LINE), kWeld = bit(B2S_JOINT_KIND_WELD),
                   kFriction = bit(B2S_JOINT_KIND_FRICTION), kGear = bit(B2S_JOINT_KIND_GEAR),
                   kWheel = bit(B2S_JOINT_KIND_WHEEL), kRope = bit(B2S_JOINT_KIND_ROPE),
                   kMotor = bit(B2S_JOINT_KIND_MOTOR);
constexpr uint32_t kAnchored =
    kRevolute | kPrismatic | kDistance | kPulley | kLine | kWeld | kFriction | kWheel | kRope;

using JointFields = std::array<JointField, static_cast<size_t>(Name::count)>;

/// A Line joint's FrequencyHz, DampingRatio and MaxMotorTorque make it Farseer's wheel
/// joint, which box2scene converts with a warning: not the peers' business.
JointFields make_joint_fields() {
    JointFields fields{};
    auto at = [&](Name name) -> JointField& { return fields[static_cast<size_t>(name)]; };
    auto vector = [&](Name name, uint32_t kinds, b2s_vec2 b2s_joint::*member) {
        at(name).kinds = kinds;
        at(name).vector = member;
    };
    auto real = [&](Name name, uint32_t kinds, float b2s_joint::*member, bool non_negative) {
        at(name).kinds = kinds;
        at(name).real = member;
        at(name).non_negative = non_negative;
    };
    auto flag = [&](Name name, uint32_t kinds, bool b2s_joint::*member) {
        at(name).kinds = kinds;
        at(name).flag = member;
    };
    const uint32_t motorised = kRevolute | kPrismatic | kLine | kWheel;
    vector(Name::local_anchor_a, kAnchored, &b2s_joint::local_anchor_a);
    vector(Name::local_anchor_b, kAnchored, &b2s_joint::local_anchor_b);
    vector(Name::local_axis_a, kPrismatic | kLine | kWheel, &b2s_joint::local_axis_a);
    real(Name::reference_angle, kRevolute | kPrismatic | kWeld, &b2s_joint::reference_angle,
         false);
    flag(Name::enable_limit, kRevolute | kPrismatic | kLine, &b2s_joint::enable_limit);
    real(Name::lower_angle, kRevolute, &b2s_joint::lower_limit, false);
    real(Name::upper_angle, kRevolute, &b2s_joint::upper_limit, false);
    real(Name::lower_translation, kPrismatic | kLine, &b2s_joint::lower_limit, false);
    real(Name::upper_translation, kPrismatic | kLine, &b2s_joint::upper_limit, false);
    flag(Name::enable_motor, motorised, &b2s_joint::enable_motor);
    real(Name::motor_speed, motorised, &b2s_joint::motor_speed, false);
    real(Name::max_motor_torque, kRevolute | kWheel, &b2s_joint::max_motor_torque, true);
    real(Name::max_motor_force, kPrismatic | kLine, &b2s_joint::max_motor_force, true);
    real(Name::length, kDistance, &b2s_joint::length, true);
    real(Name::frequency_hz, kDistance | kWeld | kWheel, &b2s_joint::frequency_hz, true);
    real(Name::damping_ratio, kDistance | kWeld | kWheel, &b2s_joint::damping_ratio, true);
    vector(Name::ground_anchor_a, kPulley, &b2s_joint::ground_anchor_a);
    vector(Name::ground_anchor_b, kPulley, &b2s_joint::ground_anchor_b);
    real(Name::length_a, kPulley, &b2s_joint::length_a, false);
    real(Name::length_b, kPulley, &b2s_joint::length_b, false);
    real(Name::max_length_a, kPulley, &b2s_joint::max_length_a, false);
    real(Name::max_length_b, kPulley, &b2s_joint::max_length_b, false);
    real(Name::ratio, kPulley | kGear, &b2s_joint::ratio, false);
    real(Name::max_force, kFriction | kMotor, &b2s_joint::max_force, true);
    real(Name::max_torque, kFriction | kMotor, &b2s_joint::max_torque, true);
    real(Name::max_length, kRope, &b2s_joint::max_length, true);
    vector(Name::linear_offset, kMotor, &b2s_joint::linear_offset);
    real(Name::angular_offset, kMotor, &b2s_joint::angular_offset, false);
    real(Name::correction_factor, kMotor, &b2s_joint::correction_factor, false);
    return fields;
}

const JointFields kJointFields = make_joint_fields();

/// The joint kinds by their `Type`, lower case, in b2s_joint_kind order.
constexpr const char* kJointTypes[] = {"revolute", "prismatic", "distance", "pulley",
                                       "line",     "weld",      "friction", "gear",
                                       "wheel",    "rope",      "motor"};

/// Whether joint `target` is one the gear `gear` can couple.
bool couplable(const PeerScene& scene, size_t gear, uint32_t target) {
    return target != gear && target < scene.joints.size() &&
           (bit(scene.joints[target].kind) & (kRevolute | kPrismatic)) != 0;
}

} // namespace

b2s_shape shape_default(uint32_t kind) {
    b2s_shape shape{};
    shape.kind = kind;
    return shape;
}

b2s_fixture fixture_default() {
    b2s_fixture fixture{};
    fixture.shape = B2S_NONE;
    fixture.friction = 0.2f;
    fixture.filter = b2s_filter{0x0001, 0xFFFF, 0};
    fixture.user_data = B2S_NONE;
    return fixture;
}

b2s_body body_default(uint32_t kind) {
    b2s_body body{};
    body.kind = kind;
    body.gravity_scale = 1.0f;
    body.inertia_scale = 1.0f;
    body.user_data = B2S_NONE;
    body.active = body.allow_sleep = body.awake = true;
    return body;
}

b2s_joint joint_default(uint32_t kind) {
    b2s_joint joint{};
    joint.kind = kind;
    joint.body_a = joint.body_b = joint.user_data = joint.joint_a = joint.joint_b = B2S_NONE;
    switch (kind) {
    case B2S_JOINT_KIND_PRISMATIC:
    case B2S_JOINT_KIND_LINE:
        joint.local_axis_a = b2s_vec2{1, 0};
        break;
    case B2S_JOINT_KIND_DISTANCE:
        joint.length = 1;
        break;
    case B2S_JOINT_KIND_PULLEY:
        joint.ground_anchor_a = b2s_vec2{-1, 1};
        joint.ground_anchor_b = b2s_vec2{1, 1};
        joint.local_anchor_a = b2s_vec2{-1, 0};
        joint.local_anchor_b = b2s_vec2{1, 0};
        joint.ratio = 1;
        break;
    case B2S_JOINT_KIND_GEAR:
        joint.ratio = 1;
        break;
    case B2S_JOINT_KIND_WHEEL:
        joint.local_axis_a = b2s_vec2{1, 0};
        joint.frequency_hz = 2;
        joint.damping_ratio = 0.7f;
        break;
    case B2S_JOINT_KIND_ROPE:
        joint.local_anchor_a = b2s_vec2{-1, 0};
        joint.local_anchor_b = b2s_vec2{1, 0};
        break;
    case B2S_JOINT_KIND_MOTOR:
        joint.max_force = 1;
        joint.max_torque = 1;
        joint.correction_factor = 0.3f;
        break;
    default:
        break;
    }
    return joint;
}

const JointField& joint_field(Name name) { return kJointFields[static_cast<size_t>(name)]; }

bool joint_kind(std::string_view type, uint32_t& kind) {
    for (uint32_t k = 0; k < sizeof kJointTypes / sizeof kJointTypes[0]; ++k) {
        if (is_word(type, kJointTypes[k])) {
            kind = k;
            return true;
        }
    }
    return false;
}

const char* joint_problem(const b2s_joint& joint) {
    if (joint.body_a == B2S_NONE || joint.body_b == B2S_NONE) {
        return "a joint names both of its bodies (<BodyA>, <BodyB>)";
    }
    if (joint.kind == B2S_JOINT_KIND_GEAR &&
        (joint.joint_a == B2S_NONE || joint.joint_b == B2S_NONE)) {
        return "a gear joint names the two joints it couples (<JointA>, <JointB>)";
    }
    if (joint.body_a == joint.body_b) {
        return "the joint connects a body to itself";
    }
    if (joint.enable_limit && joint.lower_limit > joint.upper_limit) {
        return "a lower limit above the upper one, with the limit enabled";
    }
    bool has_axis = (bit(joint.kind) & (kPrismatic | kLine | kWheel)) != 0;
    if (has_axis && joint.local_axis_a.x == 0 && joint.local_axis_a.y == 0) {
        return "<LocalAxisA> is (0, 0): a joint axis needs a direction";
    }
    if (joint.kind == B2S_JOINT_KIND_PULLEY && !(joint.ratio > 0)) {
        return "a pulley's <Ratio> must be greater than 0";
    }
    return nullptr;
}

std::string reference_problem(const PeerScene& s) {
    for (size_t i = 0; i < s.fixtures.size(); ++i) {
        if (s.fixtures[i].shape >= s.shapes.size()) {
            return "fixture " + std::to_string(i) + " names a shape the file does not have";
        }
    }
    for (uint32_t id : s.fixture_ids) {
        if (id >= s.fixtures.size()) {
            return "a body names fixture " + std::to_string(id) +
                   ", which the file does not have";
        }
    }
    for (size_t i = 0; i < s.joints.size(); ++i) {
        const b2s_joint& joint = s.joints[i];
        if (joint.body_a >= s.bodies.size() || joint.body_b >= s.bodies.size()) {
            return "joint " + std::to_string(i) + " names a body the file does not have";
        }
        if (joint.kind == B2S_JOINT_KIND_GEAR &&
            (!couplable(s, i, joint.joint_a) || !couplable(s, i, joint.joint_b))) {
            return "gear joint " + std::to_string(i) +
                   " does not couple two other revolute or prismatic joints";
        }
    }
    return "";
}

} // namespace peer
} // namespace bench
