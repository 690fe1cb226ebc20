//! The joints of a Box2D 2.4 plan, checked against the working range with every body's
//! final mass, and each kind's def filled as the engine takes it.

use super::body::Body;
use super::check::Check;
use super::math::{cross, distance, dot, length, normalized, rotate, sub};
use super::stiffness::{Spring, linear, spring};
use super::world::Mapper;
use crate::error::Code;
use crate::plan::container::Object;
use crate::plan::printf::{G, G9};
use crate::plan::records::{PlanJoint, PlanJointKind};
use crate::scene::{BodyKind, Joint, JointKind, NONE, Vec2};

/// `b2_linearSlop`.
use crate::rules::LINEAR_SLOP;

/// C++'s `std::max`: the first unless the second is greater (NaN stays where it is).
fn max(a: f32, b: f32) -> f32 {
    if a < b { b } else { a }
}

/// C++'s `std::min`: the first unless the second is less.
fn min(a: f32, b: f32) -> f32 {
    if b < a { b } else { a }
}

impl Mapper<'_> {
    fn body(&self, index: u32) -> Option<Body> {
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
            format_args!("{what} has no Box2D 2.4 equivalent; joint skipped"),
        );
    }

    /// How far the joint starts from satisfied, in metres, along what its kind holds
    /// rigidly, with its bodies as created: what the load warning joint-starts-violated
    /// measures.
    fn starting_violation(&self, joint: &Joint, a: Body, b: Body) -> f32 {
        let pa = a.world_point(joint.local_anchor_a);
        let pb = b.world_point(joint.local_anchor_b);
        let d = sub(pb, pa);
        match JointKind::try_from(joint.kind) {
            Ok(JointKind::Revolute | JointKind::Weld) => length(d),
            Ok(kind @ (JointKind::Prismatic | JointKind::Line | JointKind::Wheel)) => {
                let axis = normalized(rotate(a.frame.q, joint.local_axis_a));
                let across = cross(axis, d).abs();
                let along = dot(axis, d);
                let limited = joint.enable_limit && kind != JointKind::Wheel;
                let beyond = if limited {
                    max(max(joint.lower_limit - along, along - joint.upper_limit), 0.0)
                } else {
                    0.0
                };
                max(across, beyond)
            }
            Ok(JointKind::Distance) => {
                if joint.frequency_hz > 0.0 {
                    0.0
                } else {
                    (length(d) - joint.length).abs()
                }
            }
            Ok(JointKind::Rope) => max(length(d) - joint.max_length, 0.0),
            Ok(JointKind::Pulley) => {
                let now = distance(pa, self.placed(joint.ground_anchor_a))
                    + joint.ratio * distance(pb, self.placed(joint.ground_anchor_b));
                (now - (joint.length_a + joint.ratio * joint.length_b)).abs()
            }
            _ => 0.0, // springs, motors and friction hold nothing in place
        }
    }

    /// What the sweep of docs/working-range.md measured: Box2D 2.4 holds any one joint that
    /// starts up to 50 m from satisfied, but a body pulled by two joints that start more
    /// than `max_pulled_violation` from satisfied can be torn to NaN by its position
    /// solver. The first such joint on a body is built, the later ones are not.
    fn violation_check(&mut self, index: u32, joint: &Joint) -> Check {
        let mut check = Check::default();
        let (Some(a), Some(b)) = (self.body(joint.body_a), self.body(joint.body_b)) else {
            return check;
        };
        let violation = self.starting_violation(joint, a, b);
        if !(violation > self.range.max_pulled_violation) {
            return check;
        }
        for body in [joint.body_a, joint.body_b] {
            if let Some(other) = self.pulled[body as usize] {
                check.fail(format!(
                    "it starts {} m from satisfied, and joint {other} already pulls body {body} \
                     from further than {} m: two such joints on one body lie beyond Box2D \
                     2.4's working range (its position solver can tear the body to NaN)",
                    G9(violation),
                    G(self.range.max_pulled_violation)
                ));
                return check;
            }
        }
        for (body, held) in [(joint.body_a, a), (joint.body_b, b)] {
            if held.kind == BodyKind::Dynamic {
                self.pulled[body as usize] = Some(index);
            }
        }
        check
    }

    /// The fields Box2D gets of the joint's kind, then how hard its bodies are to move at
    /// its anchors.
    fn joint_check(&self, joint: &Joint) -> Check {
        let range = self.range;
        let mut check = Check::default();
        let (mut axis, mut spring, mut forces) = (false, false, false);
        let (mut anchor_a, mut anchor_b) = (joint.local_anchor_a, joint.local_anchor_b);
        let kind = JointKind::try_from(joint.kind);
        match kind {
            Ok(JointKind::Revolute) => {
                check.magnitude("ReferenceAngle", joint.reference_angle, range.max_angle, "rad");
                check.magnitude("LowerAngle", joint.lower_limit, range.max_angle, "rad");
                check.magnitude("UpperAngle", joint.upper_limit, range.max_angle, "rad");
                check.magnitude("MotorSpeed", joint.motor_speed, range.max_speed, "rad/s");
                check.magnitude("MaxMotorTorque", joint.max_motor_torque, range.max_force, "N m");
            }
            Ok(JointKind::Prismatic | JointKind::Line) => {
                if kind == Ok(JointKind::Prismatic) {
                    check.magnitude(
                        "ReferenceAngle",
                        joint.reference_angle,
                        range.max_angle,
                        "rad",
                    );
                    check.magnitude("MotorSpeed", joint.motor_speed, range.max_speed, "m/s");
                    check.magnitude("MaxMotorForce", joint.max_motor_force, range.max_force, "N");
                }
                // a line joint's motor stays off
                axis = true;
                check.magnitude("LowerTranslation", joint.lower_limit, range.max_length, "m");
                check.magnitude("UpperTranslation", joint.upper_limit, range.max_length, "m");
            }
            Ok(JointKind::Distance) => {
                spring = true;
                check.magnitude("Length", joint.length, range.max_length, "m");
                if joint.frequency_hz > 0.0
                    && self.massless(joint.body_a)
                    && self.massless(joint.body_b)
                {
                    // Its upper length, FLT_MAX, gives Box2D's solver an infinite bias that
                    // only a body with mass multiplies into something other than NaN.
                    check.fail(
                        "a spring (FrequencyHz > 0) between two bodies without mass, for which \
                         Box2D 2.4's distance joint computes 0 * infinity = NaN"
                            .to_owned(),
                    );
                }
            }
            Ok(JointKind::Rope) => {
                check.magnitude("MaxLength", joint.max_length, range.max_length, "m");
            }
            Ok(JointKind::Pulley) => {
                check.vector("GroundAnchorA", joint.ground_anchor_a, range.max_length, "m");
                check.vector("GroundAnchorB", joint.ground_anchor_b, range.max_length, "m");
                check.magnitude("LengthA", joint.length_a, range.max_length, "m");
                check.magnitude("LengthB", joint.length_b, range.max_length, "m");
                check.magnitude("Ratio", joint.ratio, range.max_ratio, "");
            }
            Ok(JointKind::Wheel) => {
                axis = true;
                spring = true;
                check.magnitude("MotorSpeed", joint.motor_speed, range.max_speed, "rad/s");
                check.magnitude("MaxMotorTorque", joint.max_motor_torque, range.max_force, "N m");
            }
            Ok(JointKind::Weld) => {
                spring = true;
                check.magnitude("ReferenceAngle", joint.reference_angle, range.max_angle, "rad");
            }
            Ok(JointKind::Friction) => forces = true,
            Ok(JointKind::Motor) => {
                forces = true;
                anchor_a = joint.linear_offset; // body B's origin, held there in A's frame
                anchor_b = Vec2::ZERO;
                check.vector("LinearOffset", joint.linear_offset, range.max_length, "m");
                check.magnitude("AngularOffset", joint.angular_offset, range.max_angle, "rad");
                check.within("CorrectionFactor", joint.correction_factor, 0.0, 1.0, "");
            }
            _ => return check, // not created: reported by make_joint
        }
        if kind != Ok(JointKind::Motor) {
            check.vector("LocalAnchorA", joint.local_anchor_a, range.max_length, "m");
            check.vector("LocalAnchorB", joint.local_anchor_b, range.max_length, "m");
        }
        if axis {
            check.vector("LocalAxisA", joint.local_axis_a, range.max_length, "m");
            check.at_least(
                "The length of LocalAxisA",
                length(joint.local_axis_a),
                range.min_axis,
                "m",
            );
        }
        if spring {
            check.magnitude("FrequencyHz", joint.frequency_hz, range.max_frequency, "Hz");
            check.magnitude("DampingRatio", joint.damping_ratio, range.max_frequency, "");
            self.check_stiffness(joint, &mut check);
        }
        if forces {
            check.magnitude("MaxForce", joint.max_force, range.max_force, "N");
            check.magnitude("MaxTorque", joint.max_torque, range.max_force, "N m");
        }
        if check.passed() {
            self.check_anchors(joint, anchor_a, anchor_b, &mut check);
        }
        check
    }

    fn massless(&self, body: u32) -> bool {
        self.masses[body as usize].mass == 0.0
    }

    /// Box2D divides by h * (damping + h * stiffness): a spring whose stiffness underflows,
    /// from a tiny FrequencyHz or mass, makes that infinite. The stiffness is the one the
    /// def gets.
    fn check_stiffness(&self, joint: &Joint, check: &mut Check) {
        if !check.passed() || !(joint.frequency_hz > 0.0) {
            return;
        }
        let (Some(a), Some(b)) = (self.body(joint.body_a), self.body(joint.body_b)) else {
            return;
        };
        let weld = joint.kind == JointKind::Weld as u32;
        let stiffness = match JointKind::try_from(joint.kind) {
            Ok(JointKind::Weld) => weld_spring(joint, a, b),
            Ok(JointKind::Wheel) => wheel_spring(joint, a, b),
            _ => linear(joint.frequency_hz, joint.damping_ratio, a.mass.mass, b.mass.mass),
        }
        .stiffness;
        if stiffness != 0.0 && !(stiffness >= self.range.min_stiffness) {
            check.fail(format!(
                "FrequencyHz {} gives a stiffness of {}{} with these bodies, beyond Box2D 2.4's \
                 working range (0 or at least {})",
                G9(joint.frequency_hz),
                G9(stiffness),
                if weld { " N m/rad" } else { " N/m" },
                G(self.range.min_stiffness)
            ));
        }
    }

    /// Box2D's joint solvers invert matrices of 1/m + r^2/I at the anchor (r from the
    /// centre of mass): past max_compliance they overflow, and past max_lever_revolute
    /// (revolute, friction, motor) or max_lever (prismatic, weld) radii of gyration their
    /// determinants lose every bit to cancellation (docs/working-range.md). A prismatic
    /// joint's lever on body A reaches body B's anchor.
    fn check_anchors(&self, joint: &Joint, anchor_a: Vec2, anchor_b: Vec2, check: &mut Check) {
        let kind = JointKind::try_from(joint.kind);
        let lever = match kind {
            Ok(JointKind::Revolute | JointKind::Friction | JointKind::Motor) => {
                self.range.max_lever_revolute
            }
            Ok(JointKind::Prismatic | JointKind::Weld) => self.range.max_lever,
            _ => 0.0, // none: Box2D solves the joint's rows one by one
        };
        let center_a = self.masses[joint.body_a as usize].center;
        let mut lever_a = distance(anchor_a, center_a);
        if self.range.prismatic_lever_to_b && kind == Ok(JointKind::Prismatic) {
            if let (Some(a), Some(b)) = (self.body(joint.body_a), self.body(joint.body_b)) {
                let b_on_a = a.local_point(b.world_point(anchor_b));
                lever_a = max(lever_a, distance(b_on_a, center_a));
            }
        }
        let field_a = if kind == Ok(JointKind::Motor) { "LinearOffset" } else { "LocalAnchorA" };
        self.check_anchor(field_a, joint.body_a, lever_a, lever, check);
        let lever_b = distance(anchor_b, self.masses[joint.body_b as usize].center);
        self.check_anchor("LocalAnchorB", joint.body_b, lever_b, lever, check);
    }

    fn check_anchor(&self, field: &str, body: u32, r: f32, lever: f32, check: &mut Check) {
        let mass = self.masses[body as usize];
        if mass.mass == 0.0 {
            return; // it does not move
        }
        let compliance =
            1.0 / mass.mass + if mass.inertia > 0.0 { r * r / mass.inertia } else { 0.0 };
        let where_ = format!(
            "{field}: the joint acts {} m from the centre of mass of body {body} (mass {} kg, \
             inertia {} kg m^2), ",
            G9(r),
            G9(mass.mass),
            G9(mass.inertia)
        );
        let gyration = (mass.inertia / mass.mass).sqrt();
        if !(compliance <= self.range.max_compliance) {
            check.fail(format!(
                "{where_}where 1/m + r^2/I = {} 1/kg lies beyond Box2D 2.4's working range (at \
                 most {} 1/kg)",
                G(compliance),
                G(self.range.max_compliance)
            ));
        } else if lever > 0.0 && mass.inertia > 0.0 && !(r <= lever * gyration) {
            check.fail(format!(
                "{where_}{} radii of gyration out, beyond Box2D 2.4's working range for this \
                 joint (at most {})",
                G(r / gyration),
                G(lever)
            ));
        }
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
            // 2.4's prismatic joint asserts against it all the same.
            std::mem::swap(&mut lower, &mut upper);
            self.report(
                Code::BadLimit,
                Object::Joint,
                index,
                joint.name,
                format_args!(
                    "its disabled limit has LowerTranslation {} above UpperTranslation {}, \
                     which Box2D 2.4 asserts against; they were passed swapped",
                    G9(joint.lower_limit),
                    G9(joint.upper_limit)
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

    /// FrequencyHz 0 is a rigid rod. Box2D 2.4 reads stiffness 0 with the default
    /// min/max lengths as a slack rope, so the rod pins both lengths to its own.
    fn make_distance(&mut self, index: u32, joint: &Joint, a: Body, b: Body) {
        let mut def =
            PlanJoint { length: joint.length, ..Self::def(index, joint, PlanJointKind::Distance) };
        if joint.frequency_hz > 0.0 {
            let s = linear(joint.frequency_hz, joint.damping_ratio, a.mass.mass, b.mass.mass);
            (def.min_length, def.max_length) = (0.0, f32::MAX);
            (def.stiffness, def.damping) = (s.stiffness, s.damping);
        } else {
            (def.min_length, def.max_length) = (joint.length, joint.length);
        }
        self.create(index, def);
    }

    /// Box2D 2.4 has no rope joint: a distance joint that is slack up to MaxLength.
    fn make_rope(&mut self, index: u32, joint: &Joint) {
        let def = PlanJoint {
            length: joint.max_length,
            min_length: 0.0,
            max_length: joint.max_length,
            ..Self::def(index, joint, PlanJointKind::Distance)
        };
        self.create(index, def);
    }

    /// MaxLengthA/B (Box2D 2.1 only) have no 2.4 field: each side's limit becomes a rope
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
                    "{field} {} gives a limit of {} m, which Box2D 2.4 cannot hold {why}; the \
                     side is unlimited",
                    G9(given),
                    G9(limit)
                ),
            );
            return;
        }
        let (holder_index, holder) = holder.expect("checked above");
        self.plan.push_joint(PlanJoint {
            joint: NONE,
            kind: PlanJointKind::Distance as u32,
            body_a: holder_index,
            body_b: body,
            anchor_a: holder.local_point(ground),
            anchor_b: anchor,
            length: limit,
            min_length: 0.0,
            max_length: limit,
            ..PlanJoint::default()
        });
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
    /// translation; the wheel joint's motor drives the rotation, so it stays off.
    fn make_line(&mut self, index: u32, joint: &Joint) {
        let def = PlanJoint {
            enable_limit: joint.enable_limit,
            lower: joint.lower_limit,
            upper: joint.upper_limit,
            ..Self::wheel_def(index, joint)
        };
        if joint.enable_motor {
            self.report(
                Code::LossyLineMotor,
                Object::Joint,
                index,
                joint.name,
                format_args!(
                    "Box2D 2.4 has no linear motor on a line (wheel) joint; the motor is off"
                ),
            );
        }
        self.create(index, def);
    }

    fn make_wheel(&mut self, index: u32, joint: &Joint, a: Body, b: Body) {
        let s = wheel_spring(joint, a, b);
        let def = PlanJoint {
            enable_motor: joint.enable_motor,
            max_motor: joint.max_motor_torque,
            motor_speed: joint.motor_speed,
            stiffness: s.stiffness,
            damping: s.damping,
            ..Self::wheel_def(index, joint)
        };
        self.create(index, def);
    }

    fn make_weld(&mut self, index: u32, joint: &Joint, a: Body, b: Body) {
        let s = if joint.frequency_hz > 0.0 { weld_spring(joint, a, b) } else { Spring::default() };
        let def = PlanJoint {
            reference_angle: joint.reference_angle,
            stiffness: s.stiffness,
            damping: s.damping,
            ..Self::def(index, joint, PlanJointKind::Weld)
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
        let mut check = Check::default();
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
            ..Self::def(index, &joint, PlanJointKind::Gear)
        };
        self.create(index, def);
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
                    "the gear couples joint {input}, whose body B is not dynamic, which Box2D \
                     2.4 asserts against; gear skipped"
                ),
            );
            return None;
        }
        Some(coupled)
    }
}

/// Box2D 2.2's soft weld: the angular mass 1/(1/IA + 1/IB) from the inertias about the
/// centres of mass (`b2AngularStiffness` takes those about the origins).
fn weld_spring(joint: &Joint, a: Body, b: Body) -> Spring {
    let inverse = a.inverse_central_inertia() + b.inverse_central_inertia();
    spring(if inverse > 0.0 { 1.0 / inverse } else { 0.0 }, joint.frequency_hz, joint.damping_ratio)
}

/// Box2D 2.2's wheel spring: the effective mass along the axis as the joint starts,
/// 1/(1/mA + 1/mB + sAx^2/IA + sBx^2/IB), as 2.2's InitVelocityConstraints computes it
/// (`b2LinearStiffness` takes mA mB/(mA + mB)).
fn wheel_spring(joint: &Joint, a: Body, b: Body) -> Spring {
    if !(joint.frequency_hz > 0.0) {
        return Spring::default();
    }
    let axis = normalized(joint.local_axis_a);
    let (qa, qb) = (a.frame.q, b.frame.q);
    let ra = rotate(qa, sub(joint.local_anchor_a, a.mass.center));
    let rb = rotate(qb, sub(joint.local_anchor_b, b.mass.center));
    let d = sub(sub(super::math::add(b.world_center(), rb), a.world_center()), ra);
    let ax = rotate(qa, axis);
    let s_ax = cross(super::math::add(d, ra), ax);
    let s_bx = cross(rb, ax);
    let inverse = a.inverse_mass()
        + b.inverse_mass()
        + a.inverse_central_inertia() * s_ax * s_ax
        + b.inverse_central_inertia() * s_bx * s_bx;
    spring(if inverse > 0.0 { 1.0 / inverse } else { 0.0 }, joint.frequency_hz, joint.damping_ratio)
}
