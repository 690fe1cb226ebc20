//! The checks of a Box2D 2.x joint, once every body has its final mass: its fields against
//! the working range, how hard its bodies are to move at its anchors, its spring's
//! stiffness, and how far it starts from satisfied.

use super::body::Body;
use super::math::{cross, distance, dot, length, normalized, rotate, sub};
use super::stiffness::{linear, weld_spring, wheel_spring};
use super::world::Mapper;
use crate::plan::check::Check;
use crate::plan::printf::{G, G9};
use crate::scene::{BodyKind, Joint, JointKind, Vec2};

/// C++'s `std::max`: the first unless the second is greater (NaN stays where it is).
fn max(a: f32, b: f32) -> f32 {
    if a < b { b } else { a }
}

impl Mapper<'_> {
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

    /// What the sweep of docs/working-range.md measured: Box2D 2.4 (whose solver 2.3
    /// shares) holds any one joint that
    /// starts up to 50 m from satisfied alone, but not among other joints (the dialect
    /// fixtures' weld 8.4 m off goes NaN at the first step), so no joint may start further
    /// than `max_violation`; and a body pulled by two joints that start more than
    /// `max_pulled_violation` from satisfied can be torn to NaN by its position solver: the
    /// first such joint on a body is built, the later ones are not.
    pub(super) fn violation_check(&mut self, index: u32, joint: &Joint) -> Check {
        let mut check = self.check();
        let (Some(a), Some(b)) = (self.body(joint.body_a), self.body(joint.body_b)) else {
            return check;
        };
        let violation = self.starting_violation(joint, a, b);
        let engine = self.version.name;
        if violation > self.range.max_violation {
            check.fail(format_args!(
                "it starts {} m from satisfied: a joint further than {} m from satisfied lies \
                 beyond {engine}'s working range (its position solver tears a body to NaN \
                 once other joints act on it)",
                G9(violation),
                G(self.range.max_violation)
            ));
            return check;
        }
        if !(violation > self.range.max_pulled_violation) {
            return check;
        }
        for body in [joint.body_a, joint.body_b] {
            if let Some(other) = self.pulled[body as usize] {
                check.fail(format_args!(
                    "it starts {} m from satisfied, and joint {other} already pulls body {body} \
                     from further than {} m: two such joints on one body lie beyond \
                     {engine}'s working range (its position solver can tear the body to NaN)",
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
    pub(super) fn joint_check(&self, joint: &Joint) -> Check {
        let range = self.range;
        let mut check = self.check();
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
                if !self.version.rope_joint
                    && joint.frequency_hz > 0.0
                    && self.massless(joint.body_a)
                    && self.massless(joint.body_b)
                {
                    // Its upper length, FLT_MAX, gives Box2D's solver an infinite bias that
                    // only a body with mass multiplies into something other than NaN.
                    check.fail(format_args!(
                        "a spring (FrequencyHz > 0) between two bodies without mass, for which \
                         Box2D 2.4's distance joint computes 0 * infinity = NaN"
                    ));
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

    /// Box2D 2.4 divides by h * (damping + h * stiffness): a spring whose stiffness
    /// underflows, from a tiny FrequencyHz or mass, makes that infinite. The stiffness is the
    /// one the def gets. Box2D 2.3 computes its own from the frequency and leaves a zero
    /// divisor out.
    fn check_stiffness(&self, joint: &Joint, check: &mut Check) {
        if self.version.springs_in_hertz || !check.passed() || !(joint.frequency_hz > 0.0) {
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
            check.fail(format_args!(
                "FrequencyHz {} gives a stiffness of {}{} with these bodies, beyond {}'s \
                 working range (0 or at least {})",
                G9(joint.frequency_hz),
                G9(stiffness),
                if weld { " N m/rad" } else { " N/m" },
                self.version.name,
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
        // Only a report needs it.
        let acts = || {
            format!(
                "{field}: the joint acts {} m from the centre of mass of body {body} (mass {} \
                 kg, inertia {} kg m^2), ",
                G9(r),
                G9(mass.mass),
                G9(mass.inertia)
            )
        };
        let gyration = (mass.inertia / mass.mass).sqrt();
        let engine = self.version.name;
        if !(compliance <= self.range.max_compliance) {
            check.fail(format_args!(
                "{}where 1/m + r^2/I = {} 1/kg lies beyond {engine}'s working range (at most \
                 {} 1/kg)",
                acts(),
                G(compliance),
                G(self.range.max_compliance)
            ));
        } else if lever > 0.0 && mass.inertia > 0.0 && !(r <= lever * gyration) {
            check.fail(format_args!(
                "{}{} radii of gyration out, beyond {engine}'s working range for this joint \
                 (at most {})",
                acts(),
                G(r / gyration),
                G(lever)
            ));
        }
    }
}
