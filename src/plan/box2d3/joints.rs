//! Joints: skipped where v3 has no form for them or a body is missing, checked, then given
//! as the version's defs take them (v3.1: anchors, axis and reference angle; v3.2: the
//! bodies' local frames).

use super::math::{IDENTITY, ZERO, inv_mul_rot, normalize, rotate, rotation};
use super::{Mapper, V3};
use crate::error::Code;
use crate::plan::container::Object;
use crate::plan::printf::{G, G9};
use crate::plan::records::{PlanJoint, PlanJointKind, Rot, Transform};
use crate::scene::{BodyKind, Joint, JointKind, Str};

/// s^-1: the step rate v3.2's motor joint springs assume when they stand in for Box2D
/// 2.x's CorrectionFactor (a share of the error removed each step).
pub(crate) const MOTOR_STEP_RATE: f32 = 60.0;
pub(crate) const TWO_PI: f32 = 6.28318530718;

/// The spring frequency that stands in for a CorrectionFactor in v3.2.
pub(crate) fn motor_hertz(correction_factor: f32) -> f32 {
    correction_factor * MOTOR_STEP_RATE / TWO_PI
}

/// `remainder(x, y)` of C: `x` less the multiple of `y` nearest to it (the even one on a
/// tie), exact.
fn remainder(x: f64, y: f64) -> f64 {
    let y = y.abs();
    // Exact: |r| < 2y with the sign of x, and x / y has the parity of r / y rounded.
    let r = x % (2.0 * y);
    let a = r.abs();
    // Each difference is exact (Sterbenz); a tie goes to the even multiple.
    let reduced = if a >= 1.5 * y {
        a - 2.0 * y
    } else if a > 0.5 * y {
        a - y
    } else {
        a
    };
    if r.is_sign_negative() { -reduced } else { reduced }
}

/// A scene joint's anchors, unit axis and reference angle, for the version's frames.
struct Frames {
    anchor_a: crate::scene::Vec2,
    anchor_b: crate::scene::Vec2,
    axis: crate::scene::Vec2,
    reference_angle: f32,
}

impl Frames {
    fn of(joint: &Joint) -> Frames {
        Frames {
            anchor_a: joint.local_anchor_a,
            anchor_b: joint.local_anchor_b,
            axis: normalize(joint.local_axis_a),
            reference_angle: joint.reference_angle,
        }
    }
}

/// How a joint kind takes its frames.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Form {
    /// Revolute: v3.1 unwinds the reference angle.
    Revolute,
    /// Weld: frame A turned by the reference angle.
    Weld,
    /// Prismatic: the axis and the reference angle.
    Prismatic,
    /// Line and wheel: the axis.
    Axis,
    /// Distance, rope and friction: the anchors alone.
    Anchors,
}

fn frame(p: crate::scene::Vec2, q: Rot) -> Transform {
    Transform { p, q }
}

impl Form {
    fn of(kind: JointKind) -> Form {
        match kind {
            JointKind::Revolute => Form::Revolute,
            JointKind::Weld => Form::Weld,
            JointKind::Prismatic => Form::Prismatic,
            JointKind::Line | JointKind::Wheel => Form::Axis,
            _ => Form::Anchors,
        }
    }
}

/// The frames (v3.2) or anchor fields (v3.1) the plan gives the def of a scene joint of
/// its kind (a capture searches the joint whose frames are the ones an engine holds).
pub(crate) fn planned_frames(v3: V3, joint: &Joint) -> PlanJoint {
    let mut out = PlanJoint::default();
    let form = joint.kind().map_or(Form::Anchors, Form::of);
    set_frames(v3, &mut out, &Frames::of(joint), form);
    out
}

/// The frames (v3.2) or anchor fields (v3.1) of a def.
fn set_frames(v3: V3, out: &mut PlanJoint, f: &Frames, form: Form) {
    if v3.frames() {
        let axis = Rot { c: f.axis.x, s: f.axis.y };
        let (qa, qb) = match form {
            Form::Revolute | Form::Weld => (rotation(f.reference_angle), IDENTITY),
            Form::Prismatic => (axis, inv_mul_rot(rotation(f.reference_angle), axis)),
            Form::Axis => (axis, IDENTITY),
            Form::Anchors => (IDENTITY, IDENTITY),
        };
        out.frame_a = frame(f.anchor_a, qa);
        out.frame_b = frame(f.anchor_b, qb);
        return;
    }
    out.anchor_a = f.anchor_a;
    out.anchor_b = f.anchor_b;
    match form {
        // v3.1 clamps a revolute reference angle to +-pi but measures the joint angle
        // unwound: the same angle less its whole turns keeps the joint as it was.
        Form::Revolute => {
            out.reference_angle =
                remainder(f64::from(f.reference_angle), std::f64::consts::TAU) as f32;
        }
        Form::Weld => out.reference_angle = f.reference_angle,
        Form::Prismatic => {
            out.axis = f.axis;
            out.reference_angle = f.reference_angle;
        }
        Form::Axis => out.axis = f.axis,
        Form::Anchors => {}
    }
}

impl Mapper<'_> {
    fn joint_report(
        &mut self,
        code: Code,
        index: u32,
        name: Str,
        message: std::fmt::Arguments<'_>,
    ) {
        self.report(code, Object::Joint, index, name, message);
    }

    pub(super) fn make_joint(&mut self, index: u32) {
        let joint = &self.scene.joints()[index as usize];
        let name = self.v3.name();
        let Ok(kind) = JointKind::try_from(joint.kind) else {
            self.joint_report(
                Code::UnknownType,
                index,
                joint.name,
                format_args!("unknown joint kind {}; joint skipped", joint.kind),
            );
            return;
        };
        let missing = match kind {
            JointKind::Pulley => Some("a pulley joint"),
            JointKind::Gear => Some("a gear joint"),
            JointKind::Unsupported => Some("a Farseer-only joint"),
            _ => None,
        };
        if let Some(missing) = missing {
            self.joint_report(
                Code::SkippedJoint,
                index,
                joint.name,
                format_args!("{name} has no form for {missing}; joint skipped"),
            );
            return;
        }
        if !self.connect(index, joint) {
            return;
        }
        let mut check = self.joint_check(joint);
        if check.passed() {
            self.check_violation(index, joint, &mut check);
        }
        if !check.passed() {
            self.beyond(check.problem(), Object::Joint, index, joint.name, "");
            return;
        }
        let mut out = PlanJoint {
            joint: index,
            body_a: joint.body_a,
            body_b: joint.body_b,
            collide_connected: joint.collide_connected,
            ..PlanJoint::default()
        };
        let f = Frames::of(joint);
        match kind {
            JointKind::Revolute => self.revolute(index, joint, &f, &mut out),
            JointKind::Prismatic => self.prismatic(index, joint, &f, &mut out),
            JointKind::Distance => self.distance(index, joint, &f, &mut out),
            JointKind::Rope => self.rope(index, joint, &f, &mut out),
            JointKind::Line => self.line(index, joint, &f, &mut out),
            JointKind::Wheel => self.wheel(joint, &f, &mut out),
            JointKind::Weld => self.weld(joint, &f, &mut out),
            JointKind::Friction => self.friction(index, joint, &f, &mut out),
            JointKind::Motor => self.motor(index, joint, &mut out),
            JointKind::Pulley | JointKind::Gear | JointKind::Unsupported => {
                unreachable!("skipped above")
            }
        }
        self.plan.push_joint(out);
    }

    /// Whether both bodies were created and differ; else the report.
    fn connect(&mut self, index: u32, joint: &Joint) -> bool {
        let created = |b: u32| self.created.get(b as usize).is_some_and(Option::is_some);
        let missing = if !created(joint.body_a) {
            Some(joint.body_a)
        } else if !created(joint.body_b) {
            Some(joint.body_b)
        } else {
            None
        };
        if let Some(body) = missing {
            self.joint_report(
                Code::SkippedDependent,
                index,
                joint.name,
                format_args!("it names body {body}, which was not created; joint skipped"),
            );
            return false;
        }
        if joint.body_a == joint.body_b {
            self.joint_report(
                Code::JointSelfReference,
                index,
                joint.name,
                format_args!("it connects a body to itself; joint skipped"),
            );
            return false;
        }
        true
    }

    /// Limits in the order v3 asserts; a disabled pair in the wrong order has no effect, so
    /// it is passed swapped (an enabled one the loader refuses).
    fn ordered_limits(&mut self, index: u32, joint: &Joint, names: (&str, &str)) -> (f32, f32) {
        let (lower, upper) = (joint.lower_limit, joint.upper_limit);
        if !(lower > upper) {
            return (lower, upper);
        }
        let engine = self.v3.name();
        self.joint_report(
            Code::BadLimit,
            index,
            joint.name,
            format_args!(
                "{} {} lies above {} {}, which {engine} asserts against; they were passed \
                 swapped",
                names.0,
                G9(lower),
                names.1,
                G9(upper)
            ),
        );
        (upper, lower)
    }

    fn revolute(&mut self, index: u32, joint: &Joint, f: &Frames, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Revolute as u32;
        set_frames(self.v3, out, f, Form::Revolute);
        let (lower, upper) = self.ordered_limits(index, joint, ("LowerAngle", "UpperAngle"));
        // v3 asserts that a limit lies within +-0.99 pi (v3.2 even when it is off).
        let bound = self.range.max_revolute_limit;
        out.lower = clamped(lower, -bound, bound);
        out.upper = clamped(upper, -bound, bound);
        if joint.enable_limit && (out.lower != lower || out.upper != upper) {
            let engine = self.v3.name();
            self.joint_report(
                Code::LossyJoint,
                index,
                joint.name,
                format_args!(
                    "its limit [{}, {}] reaches beyond {engine}'s +-0.99 pi; it was clamped to \
                     [{}, {}]",
                    G9(lower),
                    G9(upper),
                    G9(out.lower),
                    G9(out.upper)
                ),
            );
        }
        out.enable_limit = joint.enable_limit;
        out.enable_motor = joint.enable_motor;
        out.motor_speed = joint.motor_speed;
        out.max_motor = joint.max_motor_torque;
    }

    fn prismatic(&mut self, index: u32, joint: &Joint, f: &Frames, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Prismatic as u32;
        set_frames(self.v3, out, f, Form::Prismatic);
        (out.lower, out.upper) =
            self.ordered_limits(index, joint, ("LowerTranslation", "UpperTranslation"));
        out.enable_limit = joint.enable_limit;
        out.enable_motor = joint.enable_motor;
        out.max_motor = joint.max_motor_force;
        out.motor_speed = joint.motor_speed;
    }

    /// v3 asserts a length above 0 and raises it to its linear slop.
    fn joint_length(&mut self, index: u32, joint: &Joint, field: &str, length: f32) -> f32 {
        let slop = self.range.linear_slop;
        if length >= slop {
            return length;
        }
        let engine = self.v3.name();
        self.joint_report(
            Code::LossyJoint,
            index,
            joint.name,
            format_args!(
                "{field} {} lies under {engine}'s shortest joint length, {} m, which was used",
                G9(length),
                G(slop)
            ),
        );
        slop
    }

    /// FrequencyHz 0 is a rigid rod; above it, a spring around Length.
    fn distance(&mut self, index: u32, joint: &Joint, f: &Frames, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Distance as u32;
        set_frames(self.v3, out, f, Form::Anchors);
        out.length = self.joint_length(index, joint, "Length", joint.length);
        if joint.frequency_hz > 0.0 {
            out.enable_spring = true;
            out.hertz = joint.frequency_hz;
            out.damping_ratio = joint.damping_ratio;
        }
    }

    /// A rope is slack up to MaxLength: a spring of 0 Hz with the upper limit on.
    fn rope(&mut self, index: u32, joint: &Joint, f: &Frames, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Distance as u32;
        set_frames(self.v3, out, f, Form::Anchors);
        out.length = self.joint_length(index, joint, "MaxLength", joint.max_length);
        out.enable_spring = true;
        out.hertz = 0.0;
        out.enable_limit = true;
        out.min_length = 0.0;
        out.max_length = out.length;
    }

    /// Box2D 2.1's line joint: a wheel joint without a spring. Its motor drove the
    /// translation; v3's wheel motor drives the rotation, so it stays off.
    fn line(&mut self, index: u32, joint: &Joint, f: &Frames, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Wheel as u32;
        set_frames(self.v3, out, f, Form::Axis);
        out.enable_spring = false;
        (out.lower, out.upper) =
            self.ordered_limits(index, joint, ("LowerTranslation", "UpperTranslation"));
        out.enable_limit = joint.enable_limit;
        if joint.enable_motor {
            let engine = self.v3.name();
            self.joint_report(
                Code::LossyLineMotor,
                index,
                joint.name,
                format_args!(
                    "{engine} has no linear motor on a line (wheel) joint; the motor is off"
                ),
            );
        }
    }

    fn wheel(&mut self, joint: &Joint, f: &Frames, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Wheel as u32;
        set_frames(self.v3, out, f, Form::Axis);
        out.enable_spring = true;
        out.hertz = joint.frequency_hz;
        out.damping_ratio = joint.damping_ratio;
        out.enable_motor = joint.enable_motor;
        out.max_motor = joint.max_motor_torque;
        out.motor_speed = joint.motor_speed;
    }

    fn weld(&mut self, joint: &Joint, f: &Frames, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Weld as u32;
        set_frames(self.v3, out, f, Form::Weld);
        out.hertz = joint.frequency_hz;
        out.damping_ratio = joint.damping_ratio;
    }

    /// v3 has no friction joint: a motor joint that drives no velocity does its work. v3.1's
    /// holds no offset and acts at the body origins (its anchors are lost); v3.2's acts at
    /// the anchors.
    fn friction(&mut self, index: u32, joint: &Joint, f: &Frames, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Friction as u32;
        out.max_force = joint.max_force;
        out.max_torque = joint.max_torque;
        if self.v3.frames() {
            set_frames(self.v3, out, f, Form::Anchors);
            return;
        }
        let (a, b) = (f.anchor_a, f.anchor_b);
        if !(a.x == 0.0 && a.y == 0.0 && b.x == 0.0 && b.y == 0.0) {
            self.joint_report(
                Code::LossyJoint,
                index,
                joint.name,
                format_args!(
                    "Box2D v3's friction (motor) joint acts at the body origins, not at \
                     LocalAnchorA ({}, {}) and LocalAnchorB ({}, {})",
                    G9(a.x),
                    G9(a.y),
                    G9(b.x),
                    G9(b.y)
                ),
            );
        }
    }

    fn motor(&mut self, index: u32, joint: &Joint, out: &mut PlanJoint) {
        out.kind = PlanJointKind::Motor as u32;
        out.max_force = joint.max_force;
        out.max_torque = joint.max_torque;
        if self.v3.frames() {
            self.motor_v32(index, joint, out);
        } else {
            self.motor_v31(index, joint, out);
        }
    }

    /// Box2D 2.3's motor joint, whose form v3.1's is, but for one thing: the file's
    /// LinearOffset is in body A's frame, and v3.1.1's solver subtracts it from the centres'
    /// separation in world axes, so it is passed turned by body A's rotation, which holds
    /// only while A cannot turn (reported otherwise). v3.1 clamps CorrectionFactor to
    /// [0, 1] (reported).
    fn motor_v31(&mut self, index: u32, joint: &Joint, out: &mut PlanJoint) {
        let mut offset = joint.linear_offset;
        if offset.x != 0.0 || offset.y != 0.0 {
            let a = self.created[joint.body_a as usize].expect("connected");
            let fixed = match BodyKind::try_from(a.kind) {
                Ok(BodyKind::Static) => true,
                Ok(BodyKind::Kinematic) => a.angular_velocity == 0.0,
                _ => a.fixed_rotation,
            };
            if !fixed {
                self.joint_report(
                    Code::LossyJoint,
                    index,
                    joint.name,
                    format_args!(
                        "Box2D v3.1 holds LinearOffset ({}, {}) in world axes, not in body A's \
                         frame: it was turned by body A's angle as the joint starts, and stays \
                         so as body A turns",
                        G9(offset.x),
                        G9(offset.y)
                    ),
                );
            }
            offset = rotate(a.transform.q, offset);
        }
        out.linear_offset = offset;
        out.angular_offset = joint.angular_offset;
        out.correction_factor = joint.correction_factor;
        let cf = joint.correction_factor;
        if !(0.0..=1.0).contains(&cf) {
            self.joint_report(
                Code::LossyJoint,
                index,
                joint.name,
                format_args!(
                    "CorrectionFactor {} lies outside [0, 1], to which Box2D v3 clamps it",
                    G9(cf)
                ),
            );
        }
    }

    /// The nearest v3.2 form of Box2D 2.3's motor joint (whose offsets, force limits and
    /// CorrectionFactor v3.2's has no fields for): frame A at the offsets, so that springs
    /// drive body B's origin and angle there, critically damped at CorrectionFactor * 60 /
    /// 2pi Hz (as quick as 2.x's correction at 60 steps a second), limited to MaxForce and
    /// MaxTorque.
    fn motor_v32(&mut self, index: u32, joint: &Joint, out: &mut PlanJoint) {
        out.frame_a = frame(joint.linear_offset, rotation(joint.angular_offset));
        out.frame_b = frame(ZERO, IDENTITY);
        out.hertz = motor_hertz(joint.correction_factor);
        out.damping_ratio = 1.0;
        self.joint_report(
            Code::LossyJoint,
            index,
            joint.name,
            format_args!(
                "Box2D v3.2's motor joint has no offsets, force limits or CorrectionFactor: its \
                 frame A carries LinearOffset and AngularOffset, and critically damped springs \
                 of CorrectionFactor * 60 / 2pi Hz limited to MaxForce and MaxTorque drive body \
                 B there"
            ),
        );
    }
}

fn clamped(value: f32, low: f32, high: f32) -> f32 {
    if value < low {
        low
    } else if value > high {
        high
    } else {
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn remainder_is_cs_remainder() {
        let tau = std::f64::consts::TAU;
        assert_eq!(remainder(1.0, tau), 1.0);
        assert_eq!(remainder(-1.0, tau), -1.0);
        assert_eq!(remainder(4.0, tau), 4.0 - tau);
        assert_eq!(remainder(-4.0, tau), tau - 4.0);
        assert_eq!(remainder(7.0, tau), 7.0 - tau);
        // As glibc's remainder gives them.
        for (x, bits) in [
            (100.0, 0xbfe0_fdaa_2216_8c00_u64),
            (-100.0, 0x3fe0_fdaa_2216_8c00),
            (1e5, 0x4008_d8c0_ab41_39f0),
            (-54321.5, 0x4007_5c7f_ed15_f120),
            (3.14159274101257324, 0xc009_21fb_4888_5a30),
        ] {
            assert_eq!(remainder(x, tau).to_bits(), bits, "{x}");
        }
        assert_eq!(remainder(0.0, tau), 0.0);
        // Ties go to the even multiple.
        assert_eq!(remainder(3.0, 2.0), -1.0);
        assert_eq!(remainder(5.0, 2.0), 1.0);
        assert_eq!(remainder(-3.0, 2.0), 1.0);
    }

    #[test]
    fn motor_hertz_is_a_sixtieth_of_a_turn_per_step() {
        assert_eq!(motor_hertz(0.0), 0.0);
        assert_eq!(motor_hertz(1.0), 60.0 / 6.28318530718);
    }
}

#[cfg(test)]
mod joint_tests {
    use super::super::test_support::{BALL, messages, plan_of};
    use crate::error::Code;
    use crate::plan::{Engine, PlanJointKind};

    const BODIES: &str = "<Body Type=\"Static\"/>\
        <Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body>";

    fn joint(kind: &str, rest: &str) -> String {
        format!("<Joint Type=\"{kind}\"><BodyA>0</BodyA><BodyB>1</BodyB>{rest}</Joint>")
    }

    #[test]
    fn revolute_limits_are_swapped_or_clamped_and_reported() {
        let joints = joint("Revolute", "<LowerAngle>1</LowerAngle><UpperAngle>-1</UpperAngle>")
            + &joint(
                "Revolute",
                "<EnableLimit>true</EnableLimit><LowerAngle>-3.2</LowerAngle>\
                 <UpperAngle>3.2</UpperAngle>",
            );
        let plan = plan_of(Engine::Box2d31, BALL.0, BALL.1, BODIES, &joints);
        let j = plan.joints();
        assert_eq!((j[0].lower, j[0].upper), (-1.0, 1.0));
        let bound = Engine::Box2d31.working_range().max_revolute_limit;
        assert_eq!((j[1].lower, j[1].upper), (-bound, bound));
        let reports = messages(&plan);
        assert_eq!(
            reports[0],
            (
                Code::BadLimit as u32,
                "joint",
                0,
                "LowerAngle 1 lies above UpperAngle -1, which Box2D v3 asserts against; they were \
                 passed swapped"
            )
        );
        assert_eq!(
            reports[1],
            (
                Code::LossyJoint as u32,
                "joint",
                1,
                "its limit [-3.20000005, 3.20000005] reaches beyond Box2D v3's +-0.99 pi; it was \
                 clamped to [-3.1101768, 3.1101768]"
            )
        );
    }

    #[test]
    fn a_reference_angle_is_unwound_in_v31_and_turns_frame_a_in_v32() {
        let joints = joint("Revolute", "<ReferenceAngle>7</ReferenceAngle>");
        let plan = plan_of(Engine::Box2d31, BALL.0, BALL.1, BODIES, &joints);
        assert_eq!(plan.joints()[0].reference_angle, (7.0 - std::f64::consts::TAU) as f32);
        let plan = plan_of(Engine::Box2d32, BALL.0, BALL.1, BODIES, &joints);
        let j = plan.joints()[0];
        assert_eq!(
            (j.reference_angle, j.frame_a.q.c, j.frame_a.q.s),
            (0.0, 7f32.cos(), 7f32.sin())
        );
    }

    #[test]
    fn a_rope_is_a_distance_joint_with_its_limit_on_raised_to_the_slop() {
        let plan = plan_of(
            Engine::Box2d32,
            BALL.0,
            BALL.1,
            BODIES,
            &joint(
                "Rope",
                "<LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>\
                 <MaxLength>0.001</MaxLength>",
            ),
        );
        let j = plan.joints()[0];
        assert_eq!(j.kind, PlanJointKind::Distance as u32);
        assert!(j.enable_limit && j.enable_spring);
        assert_eq!((j.length, j.min_length, j.max_length, j.hertz), (0.005, 0.0, 0.005, 0.0));
        assert_eq!(
            messages(&plan)[0].3,
            "MaxLength 0.00100000005 lies under Box2D v3.2's shortest joint length, 0.005 m, \
             which was used"
        );
    }

    #[test]
    fn a_motor_joint_in_each_version() {
        let motor = joint(
            "Motor",
            "<LinearOffset>1 0</LinearOffset><CorrectionFactor>0.5</CorrectionFactor>",
        );
        // Body 1 as body A, turned a quarter and free to turn: v3.1 holds the offset turned.
        let bodies = "<Body Type=\"Static\"/><Body Type=\"Dynamic\"><Angle>1.57079637</Angle>\
            <Fixtures><ID>0</ID></Fixtures></Body>";
        let turned =
            motor.replace("<BodyA>0</BodyA><BodyB>1</BodyB>", "<BodyA>1</BodyA><BodyB>0</BodyB>");
        let plan = plan_of(Engine::Box2d31, BALL.0, BALL.1, bodies, &turned);
        let j = plan.joints()[0];
        assert_eq!(j.kind, PlanJointKind::Motor as u32);
        assert_eq!(j.linear_offset.x, 1.57079637f32.cos());
        assert_eq!(j.linear_offset.y, 1.57079637f32.sin());
        assert_eq!(j.correction_factor, 0.5);
        assert!(
            messages(&plan)[0].3.starts_with("Box2D v3.1 holds LinearOffset (1, 0) in world axes")
        );
        let plan = plan_of(Engine::Box2d32, BALL.0, BALL.1, bodies, &turned);
        let j = plan.joints()[0];
        assert_eq!((j.frame_a.p.x, j.hertz, j.damping_ratio), (1.0, super::motor_hertz(0.5), 1.0));
        assert_eq!(messages(&plan).len(), 1);
    }
}
