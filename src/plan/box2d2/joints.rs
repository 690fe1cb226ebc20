//! The joints of a Box2D 2.x plan, made once every body has its final mass: checked
//! (`joint_checks.rs`), then each kind's def filled as the engine takes it.

use super::body::Body;
use super::math::normalized;
use super::stiffness::{Spring, linear, weld_spring, wheel_spring};
use super::world::Mapper;
use crate::error::Code;
use crate::plan::container::Object;
use crate::plan::printf::{G, G9};
use crate::plan::records::{PlanJoint, PlanJointKind};
use crate::scene::{BodyKind, Joint, JointKind, NONE, Vec2};

/// `b2_linearSlop`.
use crate::rules::LINEAR_SLOP;

/// C++'s `std::min`: the first unless the second is less.
fn min(a: f32, b: f32) -> f32 {
    if b < a { b } else { a }
}

impl Mapper<'_> {
    pub(super) fn body(&self, index: u32) -> Option<Body> {
        self.bodies.get(index as usize).copied().flatten()
    }

    /// The joint's two bodies, or None (reported) when one is missing or they are one.
    fn connect(&mut self, index: u32, joint: &Joint) -> Option<(Body, Body)> {
        let (Some(a), Some(b)) = (self.body(joint.body_a), self.body(joint.body_b)) else {
            let missing =
                if self.body(joint.body_a).is_none() { joint.body_a } else { joint.body_b };
            self.report(
                Code::SkippedDependent,
                Object::Joint,
                index,
                joint.name,
                format_args!("it names body {missing}, which was not created; joint skipped"),
            );
            return None;
        };
        if joint.body_a == joint.body_b {
            self.report(
                Code::JointSelfReference,
                Object::Joint,
                index,
                joint.name,
                format_args!("it connects a body to itself; joint skipped"),
            );
            return None;
        }
        Some((a, b))
    }

    /// A joint of `kind` between the joint's bodies, with the fields every joint has.
    fn def(index: u32, joint: &Joint, kind: PlanJointKind) -> PlanJoint {
        PlanJoint {
            joint: index,
            kind: kind as u32,
            body_a: joint.body_a,
            body_b: joint.body_b,
            anchor_a: joint.local_anchor_a,
            anchor_b: joint.local_anchor_b,
            collide_connected: joint.collide_connected,
            ..PlanJoint::default()
        }
    }

    fn create(&mut self, index: u32, joint: PlanJoint) {
        self.joints[index as usize] = Some(self.plan.joints().len() as u32);
        self.plan.push_joint(joint);
    }

    pub(super) fn make_joint(&mut self, index: u32) {
        let joint = self.scene.joints()[index as usize];
        // A joint on a body that was not created is reported as its dependent by connect.
        let bodies_created = self.body(joint.body_a).is_some() && self.body(joint.body_b).is_some();
        if bodies_created {
            let check = self.joint_check(&joint);
            if !self.within_range(&check, Object::Joint, index, joint.name, "") {
                return;
            }
            let check = self.violation_check(index, &joint);
            if !self.within_range(&check, Object::Joint, index, joint.name, "") {
                return;
            }
        }
        let kind = match JointKind::try_from(joint.kind) {
            Ok(JointKind::Gear | JointKind::Unsupported) | Err(_) => {
                return self.skip_unknown(index, &joint);
            }
            Ok(kind) => kind,
        };
        let Some((a, b)) = self.connect(index, &joint) else {
            return;
        };
        match kind {
            JointKind::Revolute => self.make_revolute(index, &joint),
            JointKind::Prismatic => self.make_prismatic(index, &joint),
            JointKind::Distance => self.make_distance(index, &joint, a, b),
            JointKind::Pulley => self.make_pulley(index, &joint),
            JointKind::Line => self.make_line(index, &joint),
            JointKind::Weld => self.make_weld(index, &joint, a, b),
            JointKind::Friction => self.make_friction(index, &joint),
            JointKind::Wheel => self.make_wheel(index, &joint, a, b),
            JointKind::Rope => self.make_rope(index, &joint),
            JointKind::Motor => self.make_motor(index, &joint),
            JointKind::Gear | JointKind::Unsupported => unreachable!("skipped above"),
        }
    }

    fn skip_unknown(&mut self, index: u32, joint: &Joint) {
        let what = if joint.kind == JointKind::Unsupported as u32 {
            "a Farseer-only joint".to_owned()
        } else {
            format!("unknown joint kind {}", joint.kind)
        };
        self.report(
            Code::SkippedJoint,
            Object::Joint,
            index,
            joint.name,
            format_args!("{what} has no {} equivalent; joint skipped", self.version.name),
        );
    }

    fn make_revolute(&mut self, index: u32, joint: &Joint) {
        let def = PlanJoint {
            reference_angle: joint.reference_angle,
            enable_limit: joint.enable_limit,
            lower: joint.lower_limit,
            upper: joint.upper_limit,
            enable_motor: joint.enable_motor,
            motor_speed: joint.motor_speed,
            max_motor: joint.max_motor_torque,
            ..Self::def(index, joint, PlanJointKind::Revolute)
        };
        self.create(index, def);
    }

    fn make_prismatic(&mut self, index: u32, joint: &Joint) {
        let (mut lower, mut upper) = (joint.lower_limit, joint.upper_limit);
        if lower > upper {
            // Only a disabled limit gets here (the loader refuses an enabled one), and Box2D
            // asserts against it all the same (`inverted_limit_asserted_by`).
            std::mem::swap(&mut lower, &mut upper);
            self.report(
                Code::BadLimit,
                Object::Joint,
                index,
                joint.name,
                format_args!(
                    "its disabled limit has LowerTranslation {} above UpperTranslation {}, \
                     which {} asserts against; they were passed swapped",
                    G9(joint.lower_limit),
                    G9(joint.upper_limit),
                    self.version.inverted_limit_asserted_by
                ),
            );
        }
        let def = PlanJoint {
            axis: joint.local_axis_a,
            reference_angle: joint.reference_angle,
            enable_limit: joint.enable_limit,
            lower,
            upper,
            enable_motor: joint.enable_motor,
            max_motor: joint.max_motor_force,
            motor_speed: joint.motor_speed,
            ..Self::def(index, joint, PlanJointKind::Prismatic)
        };
        self.create(index, def);
    }

    /// FrequencyHz 0 is a rigid rod. Box2D 2.3 takes the spring as it is; 2.4 reads
    /// stiffness 0 with the default min/max lengths as a slack rope, so the rod pins both
    /// lengths to its own.
    fn make_distance(&mut self, index: u32, joint: &Joint, a: Body, b: Body) {
        let mut def =
            PlanJoint { length: joint.length, ..Self::def(index, joint, PlanJointKind::Distance) };
        if self.version.springs_in_hertz {
            (def.hertz, def.damping_ratio) = (joint.frequency_hz, joint.damping_ratio);
        } else if joint.frequency_hz > 0.0 {
            let s = linear(joint.frequency_hz, joint.damping_ratio, a.mass.mass, b.mass.mass);
            (def.min_length, def.max_length) = (0.0, f32::MAX);
            (def.stiffness, def.damping) = (s.stiffness, s.damping);
        } else {
            (def.min_length, def.max_length) = (joint.length, joint.length);
        }
        self.create(index, def);
    }

    fn make_rope(&mut self, index: u32, joint: &Joint) {
        let def = self.rope(Self::def(index, joint, PlanJointKind::Distance), joint.max_length);
        self.create(index, def);
    }

    /// `def` made a rope of `length`: Box2D 2.3's rope joint, or in 2.4 (which has none) a
    /// distance joint that is slack up to it.
    fn rope(&self, def: PlanJoint, length: f32) -> PlanJoint {
        if self.version.rope_joint {
            return PlanJoint { kind: PlanJointKind::Rope as u32, length, ..def };
        }
        PlanJoint {
            kind: PlanJointKind::Distance as u32,
            length,
            min_length: 0.0,
            max_length: length,
            ..def
        }
    }

    /// MaxLengthA/B (Box2D 2.1 only) have no 2.x field: each side's limit becomes a rope
    /// from its ground anchor, held by a static body, right after the pulley.
    fn make_pulley(&mut self, index: u32, joint: &Joint) {
        // The ground anchors are world points: the placement moves them with the bodies.
        let ground_a = self.placed(joint.ground_anchor_a);
        let ground_b = self.placed(joint.ground_anchor_b);
        let def = PlanJoint {
            ground_anchor_a: ground_a,
            ground_anchor_b: ground_b,
            length_a: joint.length_a,
            length_b: joint.length_b,
            ratio: joint.ratio,
            ..Self::def(index, joint, PlanJointKind::Pulley)
        };
        self.create(index, def);
        // Box2D 2.1.2's limits: the side's maximum, but no longer than leaves the other side
        // its b2_minPulleyLength of 2 m.
        let constant = joint.length_a + joint.ratio * joint.length_b;
        let sides = [
            (
                "MaxLengthA",
                joint.max_length_a,
                constant - joint.ratio * 2.0,
                ground_a,
                joint.body_a,
                joint.local_anchor_a,
            ),
            (
                "MaxLengthB",
                joint.max_length_b,
                (constant - 2.0) / joint.ratio,
                ground_b,
                joint.body_b,
                joint.local_anchor_b,
            ),
        ];
        for (field, given, longest, ground, body, anchor) in sides {
            self.limit_pulley_side(index, joint, field, given, longest, ground, body, anchor);
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn limit_pulley_side(
        &mut self,
        index: u32,
        joint: &Joint,
        field: &str,
        given: f32,
        longest: f32,
        ground: Vec2,
        body: u32,
        anchor: Vec2,
    ) {
        if !(given > 0.0) {
            return; // absent or 0: no limit
        }
        let limit = min(given, longest);
        let holder = self.static_body();
        let why = match holder {
            None => Some("without a static body in the scene".to_owned()),
            // Box2D asserts against a joint of a body to itself.
            Some((held_by, _)) if held_by == body => Some(format!(
                "on body {body}, the static body that would hold its rope (a joint needs two \
                 bodies)"
            )),
            Some(_) if !(limit >= LINEAR_SLOP) => {
                Some("(it is shorter than the linear slop)".to_owned())
            }
            Some(_) => None,
        };
        if let Some(why) = why {
            self.report(
                Code::LossyJoint,
                Object::Joint,
                index,
                joint.name,
                format_args!(
                    "{field} {} gives a limit of {} m, which {} cannot hold {why}; the side is \
                     unlimited",
                    G9(given),
                    G9(limit),
                    self.version.name
                ),
            );
            return;
        }
        let (holder_index, holder) = holder.expect("checked above");
        let side = PlanJoint {
            joint: NONE,
            body_a: holder_index,
            body_b: body,
            anchor_a: holder.local_point(ground),
            anchor_b: anchor,
            ..PlanJoint::default()
        };
        let side = self.rope(side, limit);
        self.plan.push_joint(side);
    }

    /// The first static body of the scene that was created.
    fn static_body(&self) -> Option<(u32, Body)> {
        self.bodies
            .iter()
            .enumerate()
            .find_map(|(i, b)| b.filter(|b| b.kind == BodyKind::Static).map(|b| (i as u32, b)))
    }

    /// Box2D 2.4's wheel joint, unlike its prismatic joint, does not normalise its axis,
    /// and a longer one would scale the translation; an axis is a direction. (The loader
    /// rejects a zero axis.)
    fn wheel_def(index: u32, joint: &Joint) -> PlanJoint {
        PlanJoint {
            axis: normalized(joint.local_axis_a),
            ..Self::def(index, joint, PlanJointKind::Wheel)
        }
    }

    /// Box2D 2.1's line joint is a wheel joint without a spring. Its motor drove the
    /// translation; the wheel joint's motor drives the rotation, so it stays off. Box2D 2.3's
    /// wheel joint has no limit either.
    fn make_line(&mut self, index: u32, joint: &Joint) {
        let engine = self.version.name;
        if joint.enable_motor {
            self.report(
                Code::LossyLineMotor,
                Object::Joint,
                index,
                joint.name,
                format_args!(
                    "{engine} has no linear motor on a line (wheel) joint; the motor is off"
                ),
            );
        }
        let limited = joint.enable_limit && self.version.wheel_limit;
        if joint.enable_limit && !limited {
            self.report(
                Code::LossyJoint,
                Object::Joint,
                index,
                joint.name,
                format_args!(
                    "{engine}'s wheel joint has no translation limit; the line joint's limit is off"
                ),
            );
        }
        let def = PlanJoint {
            enable_limit: limited,
            lower: if limited { joint.lower_limit } else { 0.0 },
            upper: if limited { joint.upper_limit } else { 0.0 },
            ..Self::wheel_def(index, joint)
        };
        let def = self.wheel_spring_in_hertz(index, joint, def, 0.0, 0.0);
        self.create(index, def);
    }

    fn make_wheel(&mut self, index: u32, joint: &Joint, a: Body, b: Body) {
        let def = PlanJoint {
            enable_motor: joint.enable_motor,
            max_motor: joint.max_motor_torque,
            motor_speed: joint.motor_speed,
            ..Self::wheel_def(index, joint)
        };
        let def = if self.version.springs_in_hertz {
            self.wheel_spring_in_hertz(index, joint, def, joint.frequency_hz, joint.damping_ratio)
        } else {
            let s = wheel_spring(joint, a, b);
            PlanJoint { stiffness: s.stiffness, damping: s.damping, ..def }
        };
        self.create(index, def);
    }

    /// A Box2D 2.3 wheel's spring of `hertz` and `ratio`, or the version's stand-in where
    /// it has none (reported); 2.4's `def` as it is.
    fn wheel_spring_in_hertz(
        &mut self,
        index: u32,
        joint: &Joint,
        def: PlanJoint,
        hertz: f32,
        ratio: f32,
    ) -> PlanJoint {
        let stand_in = self.version.springless_wheel_hertz;
        if !self.version.springs_in_hertz {
            return def;
        }
        if hertz > 0.0 || stand_in == 0.0 {
            return PlanJoint { hertz, damping_ratio: ratio, ..def };
        }
        self.report(
            Code::LossyJoint,
            Object::Joint,
            index,
            joint.name,
            format_args!(
                "{}'s wheel joint without a spring reads uninitialised memory; a spring of {} \
                 Hz, undamped, stands in for none (about 1e-6 N s per metre and kg a step)",
                self.version.name,
                G(stand_in)
            ),
        );
        PlanJoint { hertz: stand_in, damping_ratio: 0.0, ..def }
    }

    fn make_weld(&mut self, index: u32, joint: &Joint, a: Body, b: Body) {
        let def = PlanJoint {
            reference_angle: joint.reference_angle,
            ..Self::def(index, joint, PlanJointKind::Weld)
        };
        let def = if self.version.springs_in_hertz {
            PlanJoint { hertz: joint.frequency_hz, damping_ratio: joint.damping_ratio, ..def }
        } else {
            let s =
                if joint.frequency_hz > 0.0 { weld_spring(joint, a, b) } else { Spring::default() };
            PlanJoint { stiffness: s.stiffness, damping: s.damping, ..def }
        };
        self.create(index, def);
    }

    fn make_friction(&mut self, index: u32, joint: &Joint) {
        let def = PlanJoint {
            max_force: joint.max_force,
            max_torque: joint.max_torque,
            ..Self::def(index, joint, PlanJointKind::Friction)
        };
        self.create(index, def);
    }

    fn make_motor(&mut self, index: u32, joint: &Joint) {
        let def = PlanJoint {
            anchor_a: Vec2::ZERO,
            anchor_b: Vec2::ZERO,
            linear_offset: joint.linear_offset,
            angular_offset: joint.angular_offset,
            max_force: joint.max_force,
            max_torque: joint.max_torque,
            correction_factor: joint.correction_factor,
            ..Self::def(index, joint, PlanJointKind::Motor)
        };
        self.create(index, def);
    }

    pub(super) fn make_gear(&mut self, index: u32) {
        let joint = self.scene.joints()[index as usize];
        let first = self.gear_input(index, &joint, joint.joint_a);
        let second = self.gear_input(index, &joint, joint.joint_b);
        let (Some(first), Some(second)) = (first, second) else {
            return;
        };
        if self.connect(index, &joint).is_none() {
            return;
        }
        let bodies = self.gear_bodies(index, &joint, first, second);
        let mut check = self.check();
        check.magnitude("Ratio", joint.ratio, self.range.max_ratio, "");
        if !self.within_range(&check, Object::Joint, index, joint.name, "") {
            return;
        }
        let def = PlanJoint {
            joint_a: first,
            joint_b: second,
            ratio: joint.ratio,
            anchor_a: Vec2::ZERO,
            anchor_b: Vec2::ZERO,
            body_a: bodies[0],
            body_b: bodies[1],
            ..Self::def(index, &joint, PlanJointKind::Gear)
        };
        self.create(index, def);
    }

    /// The bodies of a gear's def. Box2D 2.x's gear moves the coupled joints' bodies B
    /// whatever its def says, and joins only the islands of its def's two bodies: other
    /// bodies would be read from islands the gear never joins. So the def's bodies are those
    /// two, or, where they are one body, it and the first joint's body A (which that joint
    /// keeps in its island); the file's, in its order, where they are the same pair.
    fn gear_bodies(&mut self, index: u32, gear: &Joint, first: u32, second: u32) -> [u32; 2] {
        let (a, b) = (self.plan.joints()[first as usize], self.plan.joints()[second as usize]);
        let wanted = if a.body_b == b.body_b { [a.body_b, a.body_a] } else { [a.body_b, b.body_b] };
        let given = [gear.body_a, gear.body_b];
        if given == wanted || given == [wanted[1], wanted[0]] {
            return given;
        }
        self.report(
            Code::LossyJoint,
            Object::Joint,
            index,
            gear.name,
            format_args!(
                "BodyA {} and BodyB {} are not the bodies the joints it couples move, {} and {}, \
                 on which Box2D 2.x's gear acts: it was made between those",
                gear.body_a, gear.body_b, wanted[0], wanted[1]
            ),
        );
        wanted
    }

    /// The plan joint, revolute or prismatic, a gear couples, or None (reported).
    fn gear_input(&mut self, index: u32, gear: &Joint, input: u32) -> Option<u32> {
        let coupled = self.joints.get(input as usize).copied().flatten();
        let Some(coupled) = coupled else {
            self.report(
                Code::SkippedDependent,
                Object::Joint,
                index,
                gear.name,
                format_args!("the gear couples joint {input}, which was not created; gear skipped"),
            );
            return None;
        };
        let made = self.plan.joints()[coupled as usize];
        let turning = [PlanJointKind::Revolute as u32, PlanJointKind::Prismatic as u32];
        if !turning.contains(&made.kind) {
            self.report(
                Code::BadGearJoint,
                Object::Joint,
                index,
                gear.name,
                format_args!(
                    "the gear couples joint {input}, which is not revolute or prismatic; gear \
                     skipped"
                ),
            );
            return None;
        }
        if self.body(made.body_b).map(|b| b.kind) != Some(BodyKind::Dynamic) {
            self.report(
                Code::BadGearJoint,
                Object::Joint,
                index,
                gear.name,
                format_args!(
                    "the gear couples joint {input}, whose body B is not dynamic, which {} \
                     asserts against; gear skipped",
                    self.version.name
                ),
            );
            return None;
        }
        let bodies = self.scene.bodies();
        if !bodies[made.body_a as usize].active || !bodies[made.body_b as usize].active {
            self.report(
                Code::BadGearJoint,
                Object::Joint,
                index,
                gear.name,
                format_args!(
                    "the gear couples joint {input}, one of whose bodies is not Active: Box2D \
                     2.x's gear reads that body's place in an island it never joins; gear skipped"
                ),
            );
            return None;
        }
        Some(coupled)
    }
}
