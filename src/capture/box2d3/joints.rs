//! Joints: the format's kind a v3 joint was built from, its anchors, axis and reference
//! angle (v3.1 holds them as passed; v3.2's frames are inverted through the plan's own
//! frames), the motor joint read back as Friction or Motor, and what has no form.

use super::bodies::angle_of;
use crate::capture::search::{nearest, nearest_pair};
use crate::capture::world::Say;
use crate::capture::{HeldBody, HeldJoint};
use crate::plan::box2d3::V3;
use crate::plan::box2d3::joints::{MOTOR_STEP_RATE, TWO_PI, motor_hertz, planned_frames};
use crate::plan::math::rotate;
use crate::plan::printf::G9;
use crate::plan::{PlanJointKind, Rot};
use crate::scene::{Joint, JointKind, Vec2};

const UNTURNED: Rot = Rot { c: 1.0, s: 0.0 };

/// Says that `what` has no Box2Scene form and the joint was written without it.
fn without(say: &mut Say, what: &str) {
    say.lossy(format_args!("{what} has no Box2Scene form; written without it"));
}

/// The scene joint (bodies, joints, name and user data left for the caller) for a held
/// joint, given the level's joint it was built from, or `None` where it has no form
/// (reported).
pub(crate) fn joint(
    v3: V3,
    held: &HeldJoint,
    a: &HeldBody,
    level: Option<&Joint>,
    say: &mut Say,
) -> Option<Joint> {
    let j = &held.joint;
    let kind = match PlanJointKind::try_from(j.kind) {
        Ok(PlanJointKind::Revolute) => JointKind::Revolute,
        Ok(PlanJointKind::Prismatic) => JointKind::Prismatic,
        Ok(PlanJointKind::Weld) => JointKind::Weld,
        Ok(PlanJointKind::Distance) if j.enable_spring && j.hertz == 0.0 => JointKind::Rope,
        Ok(PlanJointKind::Distance) => JointKind::Distance,
        Ok(PlanJointKind::Wheel) if j.enable_spring => JointKind::Wheel,
        Ok(PlanJointKind::Wheel) => JointKind::Line,
        Ok(PlanJointKind::Motor | PlanJointKind::Friction) => {
            let mut joint = match v3.frames() {
                true => motor_v32(held, say),
                false => motor_v31(held, a.body.rotation, level, say),
            };
            joint.collide_connected = j.collide_connected;
            return Some(joint);
        }
        _ => {
            say.lossy(format_args!(
                "a joint of a kind this adapter does not know has no Box2Scene form; not \
                 written"
            ));
            return None;
        }
    };
    let mut joint = Joint::new(kind);
    joint.collide_connected = j.collide_connected;
    if v3.frames() {
        frames_v32(held, &mut joint, say);
    } else {
        frames_v31(held, &mut joint);
    }
    fields(held, &mut joint, say);
    Some(joint)
}

/// What each kind holds beyond its frames, and what it holds that the format has no form
/// for.
fn fields(held: &HeldJoint, joint: &mut Joint, say: &mut Say) {
    let j = &held.joint;
    match joint.kind() {
        Some(JointKind::Revolute | JointKind::Prismatic) => {
            joint.enable_limit = j.enable_limit;
            joint.lower_limit = j.lower;
            joint.upper_limit = j.upper;
            joint.enable_motor = j.enable_motor;
            joint.motor_speed = j.motor_speed;
            let revolute = joint.kind() == Some(JointKind::Revolute);
            if revolute {
                joint.max_motor_torque = j.max_motor;
            } else {
                joint.max_motor_force = j.max_motor;
            }
            if j.enable_spring {
                let what = if revolute { "revolute" } else { "prismatic" };
                without(say, &format!("a {what} joint's spring"));
            }
        }
        Some(JointKind::Distance) => {
            joint.length = j.length;
            if j.enable_spring {
                joint.frequency_hz = j.hertz;
                joint.damping_ratio = j.damping_ratio;
            }
            if j.enable_limit {
                without(say, "a distance joint's length range");
            }
            if j.enable_motor {
                without(say, "a distance joint's motor");
            }
        }
        Some(JointKind::Rope) => {
            joint.max_length = j.max_length;
            if !j.enable_limit {
                without(say, "a slack distance joint without its length limit");
            }
            if j.enable_motor {
                without(say, "a distance joint's motor");
            }
        }
        Some(JointKind::Wheel) => {
            joint.frequency_hz = j.hertz;
            joint.damping_ratio = j.damping_ratio;
            joint.enable_motor = j.enable_motor;
            joint.motor_speed = j.motor_speed;
            joint.max_motor_torque = j.max_motor;
            if j.enable_limit {
                without(say, "a wheel joint's limit beside its spring");
            }
        }
        Some(JointKind::Line) => {
            joint.enable_limit = j.enable_limit;
            joint.lower_limit = j.lower;
            joint.upper_limit = j.upper;
            if j.enable_motor {
                without(say, "a springless wheel joint's rotation motor");
            }
        }
        Some(JointKind::Weld) => {
            joint.frequency_hz = j.hertz;
            joint.damping_ratio = j.damping_ratio;
            if held.linear_hertz != 0.0 {
                without(say, "a weld joint's linear spring");
            }
        }
        _ => {}
    }
}

/// v3.1 holds the anchors, axis and reference angle as the build passed them.
fn frames_v31(held: &HeldJoint, joint: &mut Joint) {
    let j = &held.joint;
    joint.local_anchor_a = j.anchor_a;
    joint.local_anchor_b = j.anchor_b;
    let kind = joint.kind();
    if matches!(kind, Some(JointKind::Prismatic | JointKind::Wheel | JointKind::Line)) {
        joint.local_axis_a = j.axis;
    }
    if matches!(kind, Some(JointKind::Prismatic | JointKind::Revolute | JointKind::Weld)) {
        joint.reference_angle = j.reference_angle;
    }
}

/// v3.2's frames as the plan sets them (frame A carries the axis or the reference angle,
/// frame B is unturned but for a prismatic joint's), inverted exactly; what has no exact
/// inverse or is not of the plan's form is written as the nearest and reported.
fn frames_v32(held: &HeldJoint, joint: &mut Joint, say: &mut Say) {
    let (a, b) = (held.joint.frame_a, held.joint.frame_b);
    let kind = joint.kind();
    let prismatic = kind == Some(JointKind::Prismatic);
    if !prismatic && b.q != UNTURNED {
        without(say, "a turn of its frame B");
    }
    joint.local_anchor_a = a.p;
    joint.local_anchor_b = b.p;
    let planned = |joint: &Joint| planned_frames(V3::V32, joint);
    match kind {
        Some(JointKind::Revolute | JointKind::Weld) => {
            let found = nearest(a.q.s.atan2(a.q.c), |angle| {
                planned(&Joint { reference_angle: angle, ..*joint }).frame_a.q == a.q
            });
            joint.reference_angle = found.unwrap_or_else(|x| x);
            if found.is_err() {
                say.lossy(format_args!(
                    "no angle has exactly the rotation of its frame A; the nearest, {} rad, \
                         was written as ReferenceAngle",
                    G9(joint.reference_angle)
                ));
            }
        }
        Some(JointKind::Prismatic | JointKind::Wheel | JointKind::Line) => {
            let unit = Vec2::new(a.q.c, a.q.s);
            let found = nearest_pair(unit, |axis| {
                planned(&Joint { local_axis_a: axis, ..*joint }).frame_a.q == a.q
            });
            joint.local_axis_a = found.unwrap_or_else(|x| x);
            if found.is_err() {
                say.lossy(format_args!(
                    "no axis near ({}, {}) normalises to it exactly; it was written",
                    G9(unit.x),
                    G9(unit.y)
                ));
            }
            if !prismatic {
                return;
            }
            let guess = a.q.s.atan2(a.q.c) - b.q.s.atan2(b.q.c);
            let found = nearest(guess, |angle| {
                planned(&Joint { reference_angle: angle, ..*joint }).frame_b.q == b.q
            });
            joint.reference_angle = found.unwrap_or_else(|x| x);
            if found.is_err() {
                say.lossy(format_args!(
                    "no reference angle gives exactly the rotation of its frame B; the \
                         nearest, {} rad, was written",
                    G9(joint.reference_angle)
                ));
            }
        }
        _ => {}
    }
}

/// v3.1's motor joint holds Box2D 2.3's fields: Friction where it holds no offset and no
/// CorrectionFactor (what the build makes of one), else Motor. It holds no anchors: a
/// Friction built from the level's keeps the level's, which the build reported it cannot
/// act at. It holds a Motor's LinearOffset in world axes, where the build turned the
/// file's by body A's rotation `q_a`: turned back, the level's own where it still gives
/// what is held.
fn motor_v31(held: &HeldJoint, q_a: Rot, level: Option<&Joint>, say: &mut Say) -> Joint {
    let j = &held.joint;
    let offset = j.linear_offset;
    let friction =
        j.correction_factor == 0.0 && offset.x == 0.0 && offset.y == 0.0 && j.angular_offset == 0.0;
    let mut joint = Joint::new(if friction { JointKind::Friction } else { JointKind::Motor });
    joint.linear_offset = if friction { offset } else { offset_in_a(offset, q_a, level, say) };
    joint.angular_offset = j.angular_offset;
    joint.max_force = j.max_force;
    joint.max_torque = j.max_torque;
    joint.correction_factor = j.correction_factor;
    if let Some(level) = level.filter(|l| friction && l.kind() == Some(JointKind::Friction)) {
        joint.local_anchor_a = level.local_anchor_a;
        joint.local_anchor_b = level.local_anchor_b;
    }
    joint
}

/// The LinearOffset in body A's frame that, turned by `q_a` as the build turns it, gives
/// `held`: the level's where it does, else the one searched (reported where none does).
fn offset_in_a(held: Vec2, q_a: Rot, level: Option<&Joint>, say: &mut Say) -> Vec2 {
    let gives = |offset: Vec2| {
        let turned = rotate(q_a, offset);
        turned.x.to_bits() == held.x.to_bits() && turned.y.to_bits() == held.y.to_bits()
    };
    let level = level.filter(|l| l.kind() == Some(JointKind::Motor)).map(|l| l.linear_offset);
    if let Some(offset) = level.filter(|&o| gives(o)) {
        return offset;
    }
    let back = rotate(Rot { c: q_a.c, s: -q_a.s }, held);
    nearest_pair(back, gives).unwrap_or_else(|nearest| {
        say.lossy(format_args!(
            "no LinearOffset turned by body A's rotation gives its offset ({}, {}) exactly; the \
             nearest was written",
            G9(held.x),
            G9(held.y)
        ));
        nearest
    })
}

/// v3.2's motor joint: Friction where it drives no velocity and has no springs, its frames
/// unturned (what the build makes of one); else the Motor the build approximates by it,
/// its offsets from frame A and its CorrectionFactor from its spring frequency, inverted
/// exactly. One of neither form is written as the nearest Motor and reported.
fn motor_v32(held: &HeldJoint, say: &mut Say) -> Joint {
    let j = &held.joint;
    let (a, b) = (j.frame_a, j.frame_b);
    let v = held.linear_velocity;
    let still = v.x == 0.0 && v.y == 0.0 && held.angular_velocity == 0.0;
    let unturned_b = b.q == UNTURNED;
    let springless = j.max_force == 0.0 && j.max_torque == 0.0;
    if still && springless && a.q == UNTURNED && unturned_b {
        let mut joint = Joint::new(JointKind::Friction);
        joint.local_anchor_a = a.p;
        joint.local_anchor_b = b.p;
        joint.max_force = held.max_velocity_force;
        joint.max_torque = held.max_velocity_torque;
        return joint;
    }
    let mut joint = Joint::new(JointKind::Motor);
    joint.linear_offset = a.p;
    joint.max_force = j.max_force;
    joint.max_torque = j.max_torque;
    let hertz = held.linear_hertz;
    let exact = still
        && unturned_b
        && b.p.x == 0.0
        && b.p.y == 0.0
        && held.max_velocity_force == 0.0
        && held.max_velocity_torque == 0.0
        && j.hertz == hertz
        && held.linear_damping_ratio == 1.0
        && j.damping_ratio == 1.0;
    let factor = nearest(hertz * TWO_PI / MOTOR_STEP_RATE, |cf| motor_hertz(cf) == hertz);
    joint.correction_factor = factor.unwrap_or_else(|x| x);
    let offset = angle_of(a.q);
    joint.angular_offset = offset.unwrap_or_else(|x| x);
    if !(exact && factor.is_ok() && offset.is_ok()) {
        say.lossy(format_args!(
            "a motor joint other than the build makes of a Motor joint: written as the \
                 nearest, from the offsets of its frame A, its spring limits and a \
                 CorrectionFactor from its linear spring's frequency"
        ));
    }
    joint
}
