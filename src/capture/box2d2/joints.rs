//! A Box2D 2.x joint read back into the format's forms: a distance joint as a rod, spring
//! or rope, a wheel joint as a Wheel or Line, springs as the FrequencyHz and DampingRatio
//! the build turns into what the engine holds (the level's own where they do), axes that
//! normalise to the engine's.

use super::springs::{axis_normalising_to, spring_giving};
use crate::capture::search::solve_nondecreasing;
use crate::capture::world::Say;
use crate::capture::{HeldBody, HeldJoint};
use crate::error::Code;
use crate::plan::box2d2::Version;
use crate::plan::box2d2::body::Body as BuiltBody;
use crate::plan::box2d2::math::dot;
use crate::plan::box2d2::stiffness::{Spring, linear, weld_spring, wheel_spring};
use crate::plan::printf::G9;
use crate::plan::{PlanJoint, PlanJointKind, PlanMass, Transform};
use crate::rules::LINEAR_SLOP;
use crate::scene::{BodyKind, Joint, JointKind, Vec2};

/// The scene joint of a held 2.x joint between held bodies `a` and `b`; `None` for a kind
/// the plan has not (reported).
pub(crate) fn joint(
    version: &Version,
    held: &HeldJoint,
    a: &HeldBody,
    b: &HeldBody,
    level: Option<&Joint>,
    say: &mut Say,
) -> Option<Joint> {
    let j = &held.joint;
    let Ok(kind) = PlanJointKind::try_from(j.kind) else {
        say.report(
            Code::SkippedJoint,
            format_args!("joint kind {} has no Box2Scene form; not written", j.kind),
        );
        return None;
    };
    let anchored = |kind: JointKind| Joint {
        local_anchor_a: j.anchor_a,
        local_anchor_b: j.anchor_b,
        collide_connected: j.collide_connected,
        ..Joint::new(kind)
    };
    let springs = Springs { version, a: built_body(a), b: built_body(b), level };
    let joint = match kind {
        PlanJointKind::Revolute => Joint {
            reference_angle: j.reference_angle,
            enable_limit: j.enable_limit,
            lower_limit: j.lower,
            upper_limit: j.upper,
            enable_motor: j.enable_motor,
            motor_speed: j.motor_speed,
            max_motor_torque: j.max_motor,
            ..anchored(JointKind::Revolute)
        },
        PlanJointKind::Prismatic => Joint {
            local_axis_a: axis_giving(j.axis, say),
            reference_angle: j.reference_angle,
            enable_limit: j.enable_limit,
            lower_limit: j.lower,
            upper_limit: j.upper,
            enable_motor: j.enable_motor,
            motor_speed: j.motor_speed,
            max_motor_force: j.max_motor,
            ..anchored(JointKind::Prismatic)
        },
        PlanJointKind::Distance => distance(j, &springs, anchored, say),
        PlanJointKind::Rope => Joint { max_length: j.length, ..anchored(JointKind::Rope) },
        PlanJointKind::Pulley => Joint {
            ground_anchor_a: j.ground_anchor_a,
            ground_anchor_b: j.ground_anchor_b,
            length_a: j.length_a,
            length_b: j.length_b,
            ratio: j.ratio,
            ..anchored(JointKind::Pulley)
        },
        PlanJointKind::Gear => Joint {
            ratio: j.ratio,
            collide_connected: j.collide_connected,
            ..Joint::new(JointKind::Gear)
        },
        PlanJointKind::Wheel => wheel(j, &springs, anchored, say),
        PlanJointKind::Weld => {
            let weld = Joint { reference_angle: j.reference_angle, ..anchored(JointKind::Weld) };
            springs.give(weld, j, weld_spring, say)
        }
        PlanJointKind::Friction => Joint {
            max_force: j.max_force,
            max_torque: j.max_torque,
            ..anchored(JointKind::Friction)
        },
        PlanJointKind::Motor => Joint {
            linear_offset: j.linear_offset,
            angular_offset: j.angular_offset,
            max_force: j.max_force,
            max_torque: j.max_torque,
            correction_factor: j.correction_factor,
            collide_connected: j.collide_connected,
            ..Joint::new(JointKind::Motor)
        },
    };
    Some(joint)
}

/// A held body as the build makes it again, for what its joints' springs read of it: its
/// frame, and the inertia about its centre whose `GetInertia` is the one held.
fn built_body(held: &HeldBody) -> BuiltBody {
    let b = &held.body;
    let kind = BodyKind::try_from(b.kind).unwrap_or(BodyKind::Static);
    let frame = Transform { p: b.position, q: b.rotation };
    let PlanMass { mass, center, inertia } = b.mass;
    let about_origin = |central: f32| {
        BuiltBody { frame, mass: PlanMass { mass, center, inertia: central }, kind }.inertia()
    };
    let (central, _) =
        solve_nondecreasing(about_origin, inertia, inertia - mass * dot(center, center));
    BuiltBody { frame, mass: PlanMass { mass, center, inertia: central }, kind }
}

/// An axis the build normalises back to `unit`, or `unit` itself (reported).
fn axis_giving(unit: Vec2, say: &mut Say) -> Vec2 {
    let (axis, exact) = axis_normalising_to(unit);
    if !exact {
        say.lossy(format_args!(
            "no axis normalises to its axis ({}, {}) exactly; it was written as it is",
            G9(unit.x),
            G9(unit.y)
        ));
    }
    axis
}

/// What a joint's spring is computed from as the build makes it.
struct Springs<'a> {
    version: &'a Version,
    a: BuiltBody,
    b: BuiltBody,
    level: Option<&'a Joint>,
}

impl Springs<'_> {
    /// `joint` with the FrequencyHz and DampingRatio of the held spring: 2.3 holds them
    /// as they are; 2.4 a stiffness and damping the build computes with `spring_of` from
    /// the joint and its bodies: the level's own where they give it back, else the ones
    /// searched.
    fn give(
        &self,
        joint: Joint,
        held: &PlanJoint,
        spring_of: impl Fn(&Joint, BuiltBody, BuiltBody) -> Spring,
        say: &mut Say,
    ) -> Joint {
        if self.version.springs_in_hertz {
            return Joint { frequency_hz: held.hertz, damping_ratio: held.damping_ratio, ..joint };
        }
        let target = Spring { stiffness: held.stiffness, damping: held.damping };
        let of = |hz: f32, ratio: f32| {
            spring_of(&Joint { frequency_hz: hz, damping_ratio: ratio, ..joint }, self.a, self.b)
        };
        let same = |s: Spring| {
            s.stiffness.to_bits() == target.stiffness.to_bits()
                && s.damping.to_bits() == target.damping.to_bits()
        };
        if let Some(level) = self.level.filter(|l| l.kind == joint.kind) {
            if same(of(level.frequency_hz, level.damping_ratio)) {
                return Joint {
                    frequency_hz: level.frequency_hz,
                    damping_ratio: level.damping_ratio,
                    ..joint
                };
            }
        }
        let found = spring_giving(of, target);
        if !found.exact {
            say.lossy(format_args!(
                "no FrequencyHz and DampingRatio give back its stiffness {} and damping {} \
                 exactly; the nearest were written",
                G9(target.stiffness),
                G9(target.damping)
            ));
        }
        Joint { frequency_hz: found.hz, damping_ratio: found.ratio, ..joint }
    }
}

/// Box2D 2.4's distance joint is three of the format's joints, told apart by the lengths
/// the build gives them (Box2D raises a minimum under the linear slop to it): a rod (min =
/// max), a spring (min 0, max FLT_MAX, a stiffness) or a rope (min 0, no stiffness). The
/// rest becomes the nearest of them, reported. What Box2D then ignores is not kept: a
/// rod's rest length and spring, a rope's rest length and damping. Box2D 2.3's is a
/// distance joint with its spring in hertz.
fn distance(
    j: &PlanJoint,
    springs: &Springs,
    anchored: impl Fn(JointKind) -> Joint,
    say: &mut Say,
) -> Joint {
    if springs.version.springs_in_hertz {
        return Joint {
            length: j.length,
            frequency_hz: j.hertz,
            damping_ratio: j.damping_ratio,
            ..anchored(JointKind::Distance)
        };
    }
    let (min, max) = (j.min_length, j.max_length);
    let spring_form = j.stiffness > 0.0 && min != max;
    let rope_form = !spring_form && min != max;
    let joint = if rope_form {
        Joint { max_length: max, ..anchored(JointKind::Rope) }
    } else if spring_form {
        let spring = Joint { length: j.length, ..anchored(JointKind::Distance) };
        let (ma, mb) = (springs.a.mass.mass, springs.b.mass.mass);
        springs.give(spring, j, |w, _, _| linear(w.frequency_hz, w.damping_ratio, ma, mb), say)
    } else {
        Joint { length: min, ..anchored(JointKind::Distance) }
    };
    let min_kept = !(spring_form || rope_form) || min == LINEAR_SLOP;
    let max_kept = !spring_form || max == f32::MAX;
    if !min_kept || !max_kept {
        say.lossy(format_args!(
            "its length limits [{}, {}] have no Box2Scene form; written as a {}",
            G9(min),
            G9(max),
            if spring_form { "spring without them" } else { "rope without the lower one" }
        ));
    }
    joint
}

/// A wheel with a limit is the format's Line only without spring and motor, which Line
/// lacks; with either, it stays a Wheel and loses the limit (reported). Without any of
/// them it is the level's Line where the level has one. 2.3's stand-in spring for none
/// (`springless_wheel_hertz`, undamped) is none.
fn wheel(
    j: &PlanJoint,
    springs: &Springs,
    anchored: impl Fn(JointKind) -> Joint,
    say: &mut Say,
) -> Joint {
    let version = springs.version;
    let stand_in = version.springs_in_hertz
        && j.hertz == version.springless_wheel_hertz
        && j.damping_ratio == 0.0;
    let j = &PlanJoint { hertz: if stand_in { 0.0 } else { j.hertz }, ..*j };
    let sprung = if version.springs_in_hertz { j.hertz > 0.0 } else { j.stiffness > 0.0 };
    let level_line = springs.level.is_some_and(|l| l.kind == JointKind::Line as u32);
    let line = !(sprung || j.enable_motor) && (j.enable_limit || level_line);
    let kind = if line { JointKind::Line } else { JointKind::Wheel };
    let axis = axis_giving(j.axis, say);
    let joint = Joint { local_axis_a: axis, ..anchored(kind) };
    if line {
        let (lower_limit, upper_limit) = (j.lower, j.upper);
        return Joint { enable_limit: j.enable_limit, lower_limit, upper_limit, ..joint };
    }
    let joint = Joint {
        enable_motor: j.enable_motor,
        motor_speed: j.motor_speed,
        max_motor_torque: j.max_motor,
        ..joint
    };
    let joint = springs.give(joint, j, wheel_spring, say);
    if j.enable_limit {
        say.lossy(format_args!(
            "a wheel with a spring or motor has no limit in the format; its limit [{}, {}] was \
             dropped",
            G9(j.lower),
            G9(j.upper)
        ));
    }
    joint
}
