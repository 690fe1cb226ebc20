// Part of <box2scene/box2d.hpp> (a host includes that header only): a plan's joints, each
// kind's def filled from the plan, which has checked and converted every value.
#ifndef BOX2SCENE_DETAIL_BOX2D_JOINTS_HPP
#define BOX2SCENE_DETAIL_BOX2D_JOINTS_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include "world.hpp"

namespace box2scene {
namespace detail {

/// The fields every joint has, then the joint.
template <class Def>
inline b2Joint* PlanExecutor::create(const b2s_plan_joint& joint, const Built& built,
                                     Def& def) {
    def.bodyA = built.bodies[joint.body_a];
    def.bodyB = built.bodies[joint.body_b];
    def.collideConnected = joint.collide_connected;
    return world_.CreateJoint(&def);
}

inline b2Joint* PlanExecutor::make_joint(const b2s_plan_joint& joint, const Built& built) {
    b2Vec2 anchor_a = to_b2(joint.anchor_a), anchor_b = to_b2(joint.anchor_b);
    switch (joint.kind) {
    case B2S_PLAN_JOINT_KIND_REVOLUTE: {
        b2RevoluteJointDef def;
        def.localAnchorA = anchor_a;
        def.localAnchorB = anchor_b;
        def.referenceAngle = joint.reference_angle;
        def.enableLimit = joint.enable_limit;
        def.lowerAngle = joint.lower;
        def.upperAngle = joint.upper;
        def.enableMotor = joint.enable_motor;
        def.motorSpeed = joint.motor_speed;
        def.maxMotorTorque = joint.max_motor;
        return create(joint, built, def);
    }
    case B2S_PLAN_JOINT_KIND_PRISMATIC: {
        b2PrismaticJointDef def;
        def.localAnchorA = anchor_a;
        def.localAnchorB = anchor_b;
        def.localAxisA = to_b2(joint.axis);
        def.referenceAngle = joint.reference_angle;
        def.enableLimit = joint.enable_limit;
        def.lowerTranslation = joint.lower;
        def.upperTranslation = joint.upper;
        def.enableMotor = joint.enable_motor;
        def.maxMotorForce = joint.max_motor;
        def.motorSpeed = joint.motor_speed;
        return create(joint, built, def);
    }
    case B2S_PLAN_JOINT_KIND_DISTANCE: {
        b2DistanceJointDef def;
        def.localAnchorA = anchor_a;
        def.localAnchorB = anchor_b;
        def.length = joint.length;
        def.minLength = joint.min_length;
        def.maxLength = joint.max_length;
        def.stiffness = joint.stiffness;
        def.damping = joint.damping;
        return create(joint, built, def);
    }
    case B2S_PLAN_JOINT_KIND_PULLEY: {
        b2PulleyJointDef def;
        def.groundAnchorA = to_b2(joint.ground_anchor_a);
        def.groundAnchorB = to_b2(joint.ground_anchor_b);
        def.localAnchorA = anchor_a;
        def.localAnchorB = anchor_b;
        def.lengthA = joint.length_a;
        def.lengthB = joint.length_b;
        def.ratio = joint.ratio;
        return create(joint, built, def);
    }
    case B2S_PLAN_JOINT_KIND_GEAR: {
        b2GearJointDef def;
        def.joint1 = joints_[joint.joint_a];
        def.joint2 = joints_[joint.joint_b];
        def.ratio = joint.ratio;
        return create(joint, built, def);
    }
    case B2S_PLAN_JOINT_KIND_WHEEL: {
        b2WheelJointDef def;
        def.localAnchorA = anchor_a;
        def.localAnchorB = anchor_b;
        def.localAxisA = to_b2(joint.axis);
        def.enableLimit = joint.enable_limit;
        def.lowerTranslation = joint.lower;
        def.upperTranslation = joint.upper;
        def.enableMotor = joint.enable_motor;
        def.maxMotorTorque = joint.max_motor;
        def.motorSpeed = joint.motor_speed;
        def.stiffness = joint.stiffness;
        def.damping = joint.damping;
        return create(joint, built, def);
    }
    case B2S_PLAN_JOINT_KIND_WELD: {
        b2WeldJointDef def;
        def.localAnchorA = anchor_a;
        def.localAnchorB = anchor_b;
        def.referenceAngle = joint.reference_angle;
        def.stiffness = joint.stiffness;
        def.damping = joint.damping;
        return create(joint, built, def);
    }
    case B2S_PLAN_JOINT_KIND_FRICTION: {
        b2FrictionJointDef def;
        def.localAnchorA = anchor_a;
        def.localAnchorB = anchor_b;
        def.maxForce = joint.max_force;
        def.maxTorque = joint.max_torque;
        return create(joint, built, def);
    }
    case B2S_PLAN_JOINT_KIND_MOTOR: {
        b2MotorJointDef def;
        def.linearOffset = to_b2(joint.linear_offset);
        def.angularOffset = joint.angular_offset;
        def.maxForce = joint.max_force;
        def.maxTorque = joint.max_torque;
        def.correctionFactor = joint.correction_factor;
        return create(joint, built, def);
    }
    default: return nullptr; // the plan makes no other for 2.4
    }
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_JOINTS_HPP
