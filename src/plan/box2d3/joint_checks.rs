//! The checks of a joint, once every body has its final mass: the working range of its
//! values, the levers and compliance at its anchors, what its drive does to its bodies, and
//! how far from satisfied it starts.

use super::geometry::Mass;
use super::math::transform_point;
use super::math::{cross, distance, dot, inv_transform_point, length, normalize, rotate, sub};
use super::{Created, Mapper};
use crate::plan::check::Check;
use crate::plan::printf::{G, G9};
use crate::scene::{BodyKind, Joint, JointKind, Vec2};

/// `b2MaxFloat`: `a` unless `b` is greater.
fn max_float(a: f32, b: f32) -> f32 {
    if a > b { a } else { b }
}

fn kind_of(joint: &Joint) -> Option<JointKind> {
    JointKind::try_from(joint.kind).ok()
}

fn is_wheel(joint: &Joint) -> bool {
    matches!(kind_of(joint), Some(JointKind::Line | JointKind::Wheel))
}

/// sqrt(I/m) about the centre of mass; a body that cannot turn has no bound of its own.
fn gyration(mass: &Mass) -> f32 {
    if mass.inertia > 0.0 { (mass.inertia / mass.mass).sqrt() } else { f32::MAX }
}

impl Mapper<'_> {
    fn body(&self, index: u32) -> &Created {
        self.created[index as usize].as_ref().expect("a joint's bodies are created")
    }

    /// The final mass of a created dynamic body, else none.
    fn dynamic_mass(&self, index: u32) -> Option<Mass> {
        let body = self.body(index);
        (body.kind == BodyKind::Dynamic as u32).then_some(body.mass)
    }

    /// Box2D's joint solvers work with 1/m + r^2/I of each body at the anchor (r from its
    /// centre of mass) and invert 2x2 matrices of such terms: past this, their products
    /// overflow or the determinant loses every bit.
    fn check_anchor(&self, check: &mut Check, field: &str, body: u32, anchor: Vec2, lever: f32) {
        let Some(mass) = self.dynamic_mass(body) else { return };
        let (v3, r_) = (self.v3, self.range);
        let r = distance(anchor, mass.center);
        let inertia = mass.inertia;
        let compliance = 1.0 / mass.mass + if inertia > 0.0 { r * r / inertia } else { 0.0 };
        if !(compliance <= r_.max_compliance) {
            check.fail(format_args!(
                "{field}: the joint acts {} m from the centre of mass of body {body} (mass {} kg, \
                 inertia {} kg m^2), where 1/m + r^2/I = {} 1/kg lies beyond {}'s working range \
                 (at most {} 1/kg)",
                G9(r),
                G9(mass.mass),
                G9(inertia),
                G(compliance),
                v3.name(),
                G(r_.max_compliance)
            ));
        } else if inertia > 0.0 && !(r <= lever * (inertia / mass.mass).sqrt()) {
            check.fail(format_args!(
                "{field}: the joint acts {} radii of gyration from the centre of mass of body \
                 {body}, beyond {}'s working range (at most {})",
                G(r / (inertia / mass.mass).sqrt()),
                v3.name(),
                G(lever)
            ));
        }
    }

    /// What a motor's or friction's force (N) does to `body`.
    fn check_drive(&self, check: &mut Check, body: u32, force: f32) {
        let Some(mass) = self.dynamic_mass(body) else { return };
        let acceleration = force / mass.mass;
        let bound = self.range.max_joint_acceleration;
        if !(acceleration <= bound) {
            check.fail(format_args!(
                "its motor or friction force {} N accelerates body {body} (mass {} kg) by {} \
                 m/s^2, beyond {}'s working range (at most {} m/s^2)",
                G9(force),
                G9(mass.mass),
                G(acceleration),
                self.v3.name(),
                G(bound)
            ));
        }
    }

    /// The farthest lever of one body of a joint whose other body is `other`: a line or
    /// wheel joint to a body that does not turn (one that does not move, or a dynamic one
    /// without rotational inertia: fixed rotation) leaves the body free to turn about an
    /// anchor that the engine may not hold as far out as other joints.
    fn lever(&self, joint: &Joint, other: u32, lever: f32) -> f32 {
        let turns = self.dynamic_mass(other).is_some_and(|m| m.inertia > 0.0);
        if is_wheel(joint) && !turns { self.range.max_lever_fixed_wheel } else { lever }
    }

    /// Marks every created dynamic body that a revolute or weld joint of the scene holds to
    /// a created body that does not move (static or kinematic), whether or not that joint
    /// is planned: the file means it pinned, and a distance joint's check must know it
    /// before the pin's own turn comes.
    pub(super) fn find_pinned(&mut self) {
        let created = |b: u32| self.created.get(b as usize).is_some_and(Option::is_some);
        let moves = |b: u32| self.body(b).kind == BodyKind::Dynamic as u32;
        let pins = self.scene.joints().iter().filter(|joint| {
            matches!(kind_of(joint), Some(JointKind::Revolute | JointKind::Weld))
                && joint.body_a != joint.body_b
                && created(joint.body_a)
                && created(joint.body_b)
        });
        let pinned: Vec<u32> = pins
            .flat_map(|joint| [(joint.body_a, joint.body_b), (joint.body_b, joint.body_a)])
            .filter(|&(body, other)| moves(body) && !moves(other))
            .map(|(body, _)| body)
            .collect();
        for body in pinned {
            self.pinned[body as usize] = true;
        }
    }

    /// A distance joint (a rod or a rope) by which a pinned body carries another dynamic
    /// body: its lever on the pinned one, in radii of gyration of the smaller of the two,
    /// within `max_lever_pinned_distance`. Built by hand, v3 throws such a pair off or
    /// asserts far nearer than the levers of the same joint on a free body; to a body that
    /// does not move, the same joint holds on a pinned body as far out as it was measured
    /// (`docs/working-range.md`).
    fn check_pinned_distance(&self, check: &mut Check, joint: &Joint) {
        let bound = self.range.max_lever_pinned_distance;
        let (a, b) = (joint.body_a, joint.body_b);
        let (Some(mass_a), Some(mass_b)) = (self.dynamic_mass(a), self.dynamic_mass(b)) else {
            return;
        };
        let smallest = gyration(&mass_a).min(gyration(&mass_b));
        let anchors =
            [("LocalAnchorA", a, joint.local_anchor_a), ("LocalAnchorB", b, joint.local_anchor_b)];
        for ((field, body, anchor), mass) in anchors.into_iter().zip([mass_a, mass_b]) {
            if !self.pinned[body as usize] {
                continue;
            }
            let lever = distance(anchor, mass.center) / smallest;
            if !(lever <= bound) {
                check.fail(format_args!(
                    "{field}: the joint acts {} radii of gyration (of its smaller dynamic body) \
                     from the centre of mass of body {body}, which a revolute or weld joint holds \
                     to a body that does not move: a distance joint that far out on such a body \
                     lies beyond {}'s working range (at most {})",
                    G(lever),
                    self.v3.name(),
                    G(bound)
                ));
                return;
            }
        }
    }

    pub(super) fn joint_check(&self, joint: &Joint) -> Check {
        let (v3, r) = (self.v3, self.range);
        let length = r.max_length;
        let mut check = Check::new(v3.name());
        let c = &mut check;
        let kind = kind_of(joint);
        let anchored = kind != Some(JointKind::Motor);
        if anchored {
            c.vector("LocalAnchorA", joint.local_anchor_a, length, "m");
            c.vector("LocalAnchorB", joint.local_anchor_b, length, "m");
        }
        match kind {
            Some(JointKind::Revolute) => {
                c.magnitude("MotorSpeed", joint.motor_speed, r.max_speed, "rad/s");
                c.magnitude("MaxMotorTorque", joint.max_motor_torque, r.max_force, "N m");
                c.magnitude("ReferenceAngle", joint.reference_angle, r.max_angle, "rad");
            }
            Some(JointKind::Prismatic | JointKind::Line) => {
                c.magnitude("LowerTranslation", joint.lower_limit, length, "m");
                c.magnitude("UpperTranslation", joint.upper_limit, length, "m");
                c.magnitude("MotorSpeed", joint.motor_speed, r.max_speed, "m/s");
                c.magnitude("MaxMotorForce", joint.max_motor_force, r.max_force, "N");
                c.magnitude("ReferenceAngle", joint.reference_angle, r.max_angle, "rad");
            }
            Some(JointKind::Wheel) => {
                c.magnitude("MotorSpeed", joint.motor_speed, r.max_speed, "rad/s");
                c.magnitude("MaxMotorTorque", joint.max_motor_torque, r.max_force, "N m");
            }
            Some(JointKind::Distance) => c.magnitude("Length", joint.length, length, "m"),
            Some(JointKind::Rope) => c.magnitude("MaxLength", joint.max_length, length, "m"),
            Some(JointKind::Weld) => {
                c.magnitude("ReferenceAngle", joint.reference_angle, r.max_angle, "rad");
            }
            Some(JointKind::Friction | JointKind::Motor) => {
                c.magnitude("MaxForce", joint.max_force, r.max_force, "N");
                c.magnitude("MaxTorque", joint.max_torque, r.max_force, "N m");
                if joint.max_force < 0.0 || joint.max_torque < 0.0 {
                    c.fail(format_args!(
                        "a negative MaxForce or MaxTorque, which {} asserts against",
                        v3.name()
                    ));
                }
                if kind == Some(JointKind::Motor) {
                    c.vector("LinearOffset", joint.linear_offset, length, "m");
                    c.magnitude("AngularOffset", joint.angular_offset, r.max_angle, "rad");
                    c.magnitude("CorrectionFactor", joint.correction_factor, r.max_frequency, "");
                }
            }
            _ => {}
        }
        if matches!(kind, Some(JointKind::Prismatic | JointKind::Line | JointKind::Wheel)) {
            c.vector("LocalAxisA", joint.local_axis_a, length, "m");
            if c.passed() && !(super::math::length(joint.local_axis_a) >= r.min_axis) {
                c.fail(format_args!(
                    "LocalAxisA is shorter than {} m: {} cannot normalise it",
                    G(r.min_axis),
                    v3.name()
                ));
            }
        }
        if matches!(kind, Some(JointKind::Distance | JointKind::Wheel | JointKind::Weld)) {
            c.magnitude("FrequencyHz", joint.frequency_hz, r.max_frequency, "Hz");
            c.magnitude("DampingRatio", joint.damping_ratio, r.max_frequency, "");
            if joint.frequency_hz < 0.0 || joint.damping_ratio < 0.0 {
                c.fail(format_args!(
                    "a negative FrequencyHz or DampingRatio, which {} asserts against",
                    v3.name()
                ));
            }
        }
        let levered = anchored && (r.friction_at_anchors || kind != Some(JointKind::Friction));
        if c.passed() && levered {
            let lever =
                if kind == Some(JointKind::Revolute) { r.max_lever_revolute } else { r.max_lever };
            let (a, b) = (joint.body_a, joint.body_b);
            let lever_a = self.lever(joint, b, lever);
            self.check_anchor(c, "LocalAnchorA", a, joint.local_anchor_a, lever_a);
            let lever_b = self.lever(joint, a, lever);
            self.check_anchor(c, "LocalAnchorB", b, joint.local_anchor_b, lever_b);
            // Its axis reaches body B's anchor: that is body A's lever too. v3's line and
            // wheel joints turn body A about it as well (`wheel_joint.c`: the cross product
            // of d + rA with the axis): a wheel 50 m along its axis from a pinned 0.3 m ball
            // made v3.1 assert.
            let axis_reaches_b = match kind {
                Some(JointKind::Prismatic) => r.prismatic_lever_to_b,
                Some(JointKind::Line | JointKind::Wheel) => true,
                _ => false,
            };
            if axis_reaches_b {
                let b_anchor = transform_point(self.body(b).transform, joint.local_anchor_b);
                let local = inv_transform_point(self.body(a).transform, b_anchor);
                self.check_anchor(c, "LocalAnchorB, as body A's lever", a, local, lever);
            }
            if c.passed() && matches!(kind, Some(JointKind::Distance | JointKind::Rope)) {
                self.check_pinned_distance(c, joint);
            }
        }
        if c.passed() {
            let force = drive_force(joint);
            self.check_drive(c, joint.body_a, force);
            self.check_drive(c, joint.body_b, force);
        }
        check
    }

    /// How far the joint starts from satisfied, in metres, along what its kind holds
    /// rigidly (what the load warning joint-starts-violated measures), and how far its
    /// anchors start apart across its axis (0 without one).
    fn starting_violation(&self, joint: &Joint) -> (f32, f32) {
        let (ta, tb) = (self.body(joint.body_a).transform, self.body(joint.body_b).transform);
        let pa = transform_point(ta, joint.local_anchor_a);
        let pb = transform_point(tb, joint.local_anchor_b);
        let d = sub(pb, pa);
        match kind_of(joint) {
            Some(JointKind::Revolute | JointKind::Weld) => (length(d), 0.0),
            Some(kind @ (JointKind::Prismatic | JointKind::Line | JointKind::Wheel)) => {
                let axis = normalize(rotate(ta.q, joint.local_axis_a));
                let along = dot(axis, d);
                let across = cross(axis, d).abs();
                let mut beyond = 0.0;
                if joint.enable_limit && kind != JointKind::Wheel {
                    let outside = max_float(joint.lower_limit - along, along - joint.upper_limit);
                    beyond = max_float(outside, 0.0);
                }
                (max_float(across, beyond), across)
            }
            Some(JointKind::Distance) if joint.frequency_hz > 0.0 => (0.0, 0.0),
            Some(JointKind::Distance) => ((length(d) - joint.length).abs(), 0.0),
            Some(JointKind::Rope) => (max_float(length(d) - joint.max_length, 0.0), 0.0),
            // Springs, motors and friction hold nothing in place.
            _ => (0.0, 0.0),
        }
    }

    /// Whether a line or wheel joint turns a body as it pulls body B onto its axis: the axis
    /// turns with a dynamic body A; on a body A that does not move, body B turns about an
    /// anchor further than `max_lever_violated_wheel` radii of gyration from its centre of
    /// mass. Built by hand, v3.1 pulls body B back from 50 m when neither turns.
    fn wheel_turns_a_body(&self, joint: &Joint) -> bool {
        if self.dynamic_mass(joint.body_a).is_some() {
            return true;
        }
        let Some(mass) = self.dynamic_mass(joint.body_b) else { return false };
        let bound = self.range.max_lever_violated_wheel * gyration(&mass);
        !(distance(joint.local_anchor_b, mass.center) <= bound)
    }

    /// What the working-range sweeps, the levels that asserted and the joints built by hand
    /// measured of joints that start violated: a line or wheel joint that turns a body too
    /// far from satisfied, or whose anchors start too many radii of gyration apart across an
    /// axis that turns with its dynamic body A (to another dynamic body or to one that does
    /// not move), flings its bodies off; a joint of another kind too
    /// far from satisfied makes the solver assert once anything else acts on its bodies;
    /// where the version has a bound only for a body pulled by two such joints, the first is
    /// planned and the later ones are not.
    pub(super) fn check_violation(&mut self, index: u32, joint: &Joint, check: &mut Check) {
        let (v3, r) = (self.v3, self.range);
        let (violation, across) = self.starting_violation(joint);
        let wheel = is_wheel(joint);
        let turns = wheel && self.wheel_turns_a_body(joint);
        // Where body A is dynamic, its axis turns with it: the bound in radii of gyration of
        // its smaller dynamic body (body A's own where body B does not move), where the joint
        // starts beyond it.
        let mass_b = self.dynamic_mass(joint.body_b);
        let thrown = match self.dynamic_mass(joint.body_a) {
            Some(a) if wheel => {
                let smaller = mass_b.map_or(gyration(&a), |b| gyration(&a).min(gyration(&b)));
                let bound = r.max_wheel_violation_gyrations * smaller;
                (across > r.linear_slop && !(across <= bound)).then_some(bound)
            }
            _ => None,
        };
        let between = if mass_b.is_some() {
            "between two dynamic bodies"
        } else {
            "from a dynamic body A to a body that does not move"
        };
        if turns && violation > r.max_wheel_violation {
            // Where the pair's bound is passed too, the report names it as well.
            let also = thrown.map_or(String::new(), |bound| {
                format!(
                    ", and it starts violated by {} m across its axis {between}, beyond {} \
                     radii of gyration ({} m)",
                    G9(across),
                    G(r.max_wheel_violation_gyrations),
                    G9(bound)
                )
            });
            check.fail(format_args!(
                "it starts {} m from satisfied: a line or wheel joint that turns a body (a \
                 dynamic body A, or body B about an anchor beyond {} radii of gyration) further \
                 than {} m from satisfied lies beyond {}'s working range (its solver flings \
                 the bodies apart){also}",
                G9(violation),
                G(r.max_lever_violated_wheel),
                G(r.max_wheel_violation),
                v3.name()
            ));
            return;
        }
        if let Some(bound) = thrown {
            check.fail(format_args!(
                "it starts violated by {} m across its axis {between}, beyond {}'s working \
                 range (at most {} radii of gyration, {} m), where its solver throws them off",
                G9(across),
                v3.name(),
                G(r.max_wheel_violation_gyrations),
                G9(bound)
            ));
            return;
        }
        if !wheel && violation > r.max_violation {
            check.fail(format_args!(
                "it starts {} m from satisfied: a joint further than {} m from satisfied lies \
                 beyond {}'s working range (its solver asserts once other joints or contacts \
                 act on its bodies)",
                G9(violation),
                G(r.max_violation),
                v3.name()
            ));
            return;
        }
        if wheel {
            self.check_second_rail(index, joint, across, check);
            return;
        }
        if !(violation > r.max_pulled_violation) {
            return;
        }
        let bodies = [joint.body_a, joint.body_b];
        for body in bodies {
            let pulled = self.pulled[body as usize];
            if pulled != 0 {
                check.fail(format_args!(
                    "it starts {} m from satisfied, and joint {} already pulls body {body} from \
                     further than {} m: two such joints on one body lie beyond {}'s working \
                     range (its solver asserts)",
                    G9(violation),
                    pulled - 1,
                    G(r.max_pulled_violation),
                    v3.name()
                ));
                return;
            }
        }
        for body in bodies {
            if self.dynamic_mass(body).is_some() {
                self.pulled[body as usize] = index + 1;
            }
        }
    }

    /// A dynamic body A on two line or wheel joints to bodies that do not turn (rails) holds
    /// while both start on their axes; once either starts violated across its axis, v3.1
    /// and v3.2 assert (0.1 m balls from 0.3 m, 0.2 m balls from 0.5 m; a single such joint
    /// holds 20 m off). The first is planned, a later one is not.
    fn check_second_rail(&mut self, index: u32, joint: &Joint, across: f32, check: &mut Check) {
        let (a, b) = (joint.body_a, joint.body_b);
        let b_turns = self.dynamic_mass(b).is_some_and(|m| m.inertia > 0.0);
        if self.dynamic_mass(a).is_none() || b_turns {
            return;
        }
        let Some((first, first_across)) = self.railed[a as usize] else {
            self.railed[a as usize] = Some((index, across));
            return;
        };
        let slop = self.range.linear_slop;
        if across > slop || first_across > slop {
            check.fail(format_args!(
                "body {a} already runs on joint {first}, a line or wheel joint to a body that \
                 does not turn: a second such joint lies beyond {}'s working range unless both \
                 start on their axes (this one starts {} m off it, joint {first} {} m; its \
                 solver asserts)",
                self.v3.name(),
                G9(across),
                G9(first_across)
            ));
        }
    }
}

/// The force a joint's motor or friction may apply, as v3 gets it.
fn drive_force(joint: &Joint) -> f32 {
    match kind_of(joint) {
        Some(JointKind::Prismatic) if joint.enable_motor => joint.max_motor_force,
        Some(JointKind::Friction | JointKind::Motor) => joint.max_force,
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_support::{BALL, messages, plan_of};
    use crate::error::Code;
    use crate::plan::Engine;

    /// Body 0 static at the origin, bodies 1 and 2 dynamic balls at (1, 0) and (0, 1).
    const BODIES: &str = "<Body Type=\"Static\"/>\
        <Body Type=\"Dynamic\"><Position>1 0</Position><Fixtures><ID>0</ID></Fixtures></Body>\
        <Body Type=\"Dynamic\"><Position>0 1</Position><Fixtures><ID>0</ID></Fixtures></Body>";

    fn joint(kind: &str, a: u32, b: u32, rest: &str) -> String {
        format!("<Joint Type=\"{kind}\"><BodyA>{a}</BodyA><BodyB>{b}</BodyB>{rest}</Joint>")
    }

    #[test]
    fn a_joint_far_from_satisfied_is_refused_in_v3() {
        // Joint 0 pins ball 1 at the origin, 1 m from where it is; joint 1 pins it to ball
        // 2's origin, sqrt(2) m away; joint 2, a weld 0.5 m off, is held.
        let joints = joint("Revolute", 0, 1, "")
            + &joint("Revolute", 2, 1, "")
            + &joint("Weld", 0, 1, "<LocalAnchorA>0.5 0</LocalAnchorA>");
        let plan = plan_of(Engine::Box2d31, BALL.0, BALL.1, BODIES, &joints);
        assert_eq!(plan.joints().len(), 1);
        assert_eq!(plan.joints()[0].joint, 2);
        let refused = |violation: &str| {
            format!(
                "it starts {violation} m from satisfied: a joint further than 0.5 m from \
                 satisfied lies beyond Box2D v3's working range (its solver asserts once other \
                 joints or contacts act on its bodies); joint not created"
            )
        };
        assert_eq!(
            messages(&plan),
            [
                (Code::BeyondBox2dRange as u32, "joint", 0, refused("1").as_str()),
                (Code::BeyondBox2dRange as u32, "joint", 1, refused("1.41421354").as_str()),
            ]
        );
        // v3.2 holds joints up to 4 m off.
        let plan = plan_of(Engine::Box2d32, BALL.0, BALL.1, BODIES, &joints);
        assert_eq!(plan.joints().len(), 3);
        let far = joint("Revolute", 0, 1, "<LocalAnchorA>-4 0</LocalAnchorA>");
        let plan = plan_of(Engine::Box2d32, BALL.0, BALL.1, BODIES, &far);
        assert!(plan.joints().is_empty());
    }

    #[test]
    fn a_wheel_far_from_satisfied_across_its_axis_is_refused_in_v31() {
        // The ground's anchor lies 0.75 m from ball 1, body A, across its vertical axis (2.12
        // radii of gyration, within the 2.4 of a dynamic body A).
        let across =
            joint("Wheel", 1, 0, "<LocalAnchorB>0.25 0</LocalAnchorB><LocalAxisA>0 1</LocalAxisA>");
        let plan = plan_of(Engine::Box2d31, BALL.0, BALL.1, BODIES, &across);
        assert!(plan.joints().is_empty());
        assert_eq!(
            messages(&plan)[0].3,
            "it starts 0.75 m from satisfied: a line or wheel joint that turns a body (a dynamic \
             body A, or body B about an anchor beyond 2 radii of gyration) further than 0.5 m \
             from satisfied lies beyond Box2D v3's working range (its solver flings the bodies \
             apart); joint not created"
        );
        // Along its axis, a wheel is satisfied wherever it starts.
        let along = joint("Wheel", 1, 0, "<LocalAxisA>1 0</LocalAxisA>");
        let plan = plan_of(Engine::Box2d31, BALL.0, BALL.1, BODIES, &along);
        assert_eq!(plan.joints().len(), 1);
        // v3.2 has no such 0.5 m, only its bound in radii of gyration (4).
        let plan = plan_of(Engine::Box2d32, BALL.0, BALL.1, BODIES, &across);
        assert_eq!(plan.joints().len(), 1);
    }

    #[test]
    fn a_line_or_wheel_joint_far_off_the_axis_of_a_body_that_does_not_move_is_built() {
        // Ball 1 starts `off` m across the vertical axis through the origin of body 0, body A,
        // static or kinematic, the joint anchored `lever` m from the ball's centre (its radius
        // of gyration is 0.354 m): measured by hand, v3.1 pulls it back onto the axis from
        // 50 m while the anchor lies within 2.4 radii of gyration, and from 2.5 radii throws
        // some balls off (carrying another ball on a revolute joint).
        let scene = |kind: &str, joint_kind: &str, off: f32, lever: &str| {
            let bodies = format!(
                "<Body Type=\"{kind}\"/><Body Type=\"Dynamic\"><Position>{} 0</Position>\
                 <Fixtures><ID>0</ID></Fixtures></Body>",
                off - lever.parse::<f32>().unwrap()
            );
            let fields =
                format!("<LocalAnchorB>{lever} 0</LocalAnchorB><LocalAxisA>0 1</LocalAxisA>");
            (bodies, joint(joint_kind, 0, 1, &fields))
        };
        for engine in [Engine::Box2d31, Engine::Box2d32] {
            for kind in ["Static", "Kinematic"] {
                for joint_kind in ["Line", "Wheel"] {
                    for (off, lever) in [(1.5, "0"), (20.0, "0"), (1.5, "0.7")] {
                        let (bodies, joints) = scene(kind, joint_kind, off, lever);
                        let plan = plan_of(engine, BALL.0, BALL.1, &bodies, &joints);
                        assert_eq!(plan.joints().len(), 1, "{engine:?} {kind} {joint_kind} {off}");
                        assert!(plan.reports().is_empty(), "{:?}", messages(&plan));
                    }
                }
            }
        }
        let refused = |plan: &crate::plan::Plan| {
            assert!(plan.joints().is_empty());
            let (code, _, index, message) = messages(plan)[0];
            assert_eq!((code, index), (Code::BeyondBox2dRange as u32, 0));
            let words = "it starts 1.5 m from satisfied: a line or wheel joint that turns a body";
            assert!(message.starts_with(words), "{message}");
        };
        // Anchored 0.75 m from the ball's centre (2.12 radii), the ball turns about it: the
        // 0.5 m of a line or wheel joint that turns a body holds in v3.1, not in v3.2.
        let (bodies, far) = scene("Static", "Wheel", 1.5, "0.75");
        refused(&plan_of(Engine::Box2d31, BALL.0, BALL.1, &bodies, &far));
        assert_eq!(plan_of(Engine::Box2d32, BALL.0, BALL.1, &bodies, &far).joints().len(), 1);
        // With the ball as body A, its axis turns with it: v3.1 throws it off from 3 radii of
        // gyration across the axis.
        let (bodies, _) = scene("Static", "Line", 1.5, "0");
        let ball_first = joint("Line", 1, 0, "<LocalAxisA>0 1</LocalAxisA>");
        refused(&plan_of(Engine::Box2d31, BALL.0, BALL.1, &bodies, &ball_first));
    }

    /// A 0.1 m ball (radius of gyration 0.0707 m) as shape 0, fixture 0 of density 1.
    const SMALL_BALL: (&str, &str) = (
        "<Shape Type=\"Circle\"><Radius>0.1</Radius><Position>0 0</Position></Shape>",
        "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
    );

    #[test]
    fn a_line_or_wheel_joint_on_a_dynamic_body_a_is_bounded_in_its_radii_of_gyration() {
        // Body 0 is `other` at the origin, body 1 a 0.1 m ball `off` m below it; a line joint
        // along x between their origins, the ball body A: `off` m across an axis that turns
        // with the ball, within the 0.5 m of a line joint that turns a body. Built by hand,
        // v3.1 throws such a ball off from 2.8 radii of gyration (2.45 for a 3 cm body), v3.2
        // from 6.
        let scene = |other: &str, off: f32| {
            let bodies = format!(
                "<Body Type=\"{other}\"><Fixtures>{}</Fixtures></Body><Body Type=\"Dynamic\">\
                 <Position>0 {}</Position><Fixtures><ID>0</ID></Fixtures></Body>",
                if other == "Dynamic" { "<ID>0</ID>" } else { "" },
                -off
            );
            (bodies, joint("Line", 1, 0, "<LocalAxisA>1 0</LocalAxisA>"))
        };
        let planned = |engine, (bodies, joints): (String, String)| {
            plan_of(engine, SMALL_BALL.0, SMALL_BALL.1, &bodies, &joints)
        };
        for other in ["Static", "Kinematic"] {
            // 3.54 radii: beyond v3.1's 2.4, within v3.2's 4.
            let plan = planned(Engine::Box2d31, scene(other, 0.25));
            assert!(plan.joints().is_empty());
            assert_eq!(
                messages(&plan),
                [(
                    Code::BeyondBox2dRange as u32,
                    "joint",
                    0,
                    "it starts violated by 0.25 m across its axis from a dynamic body A to a body \
                     that does not move, beyond Box2D v3's working range (at most 2.4 radii of \
                     gyration, 0.169705644 m), where its solver throws them off; joint not created"
                )]
            );
            assert_eq!(planned(Engine::Box2d32, scene(other, 0.25)).joints().len(), 1);
            // 4.95 radii: beyond v3.2's 4 too.
            assert!(planned(Engine::Box2d32, scene(other, 0.35)).joints().is_empty());
            // 2.26 radii: built in both.
            for engine in [Engine::Box2d31, Engine::Box2d32] {
                let plan = planned(engine, scene(other, 0.16));
                assert_eq!(plan.joints().len(), 1);
                assert!(plan.reports().is_empty(), "{:?}", messages(&plan));
            }
        }
        // Two such balls, 3 radii apart across the axis: v3.1 threw some pairs off from 2.9.
        let plan = planned(Engine::Box2d31, scene("Dynamic", 0.212132));
        assert!(plan.joints().is_empty());
        let (code, _, index, message) = messages(&plan)[0];
        assert_eq!((code, index), (Code::BeyondBox2dRange as u32, 0));
        assert!(
            message.starts_with(
                "it starts violated by 0.212132007 m across its axis between two dynamic bodies"
            ),
            "{message}"
        );
        assert_eq!(planned(Engine::Box2d32, scene("Dynamic", 0.212132)).joints().len(), 1);
        // The ground as body A: its axis does not turn, and v3.1 pulls the ball back from 50 m.
        let (bodies, _) = scene("Static", 0.25);
        let ground_first = joint("Line", 0, 1, "<LocalAxisA>1 0</LocalAxisA>");
        let plan = plan_of(Engine::Box2d31, SMALL_BALL.0, SMALL_BALL.1, &bodies, &ground_first);
        assert_eq!(plan.joints().len(), 1);
    }

    #[test]
    fn a_line_or_wheel_joint_far_out_on_its_ball_to_the_ground_is_refused_from_3_radii_in_v31() {
        // The ground's anchor at the origin, on a vertical axis; ball 1's anchor `lever` m out
        // along x from its centre (radius of gyration 0.354 m), `off` m across the axis. Built
        // by hand, v3.1 threw balls and boxes anchored 3.5 radii out off from 0.25 m across,
        // and held every one anchored up to 3 radii out within 0.5 m.
        let scene = |off: f32, lever: f32| {
            let bodies = format!(
                "<Body Type=\"Static\"/><Body Type=\"Dynamic\"><Position>{} 0</Position>\
                 <Fixtures><ID>0</ID></Fixtures></Body>",
                off - lever
            );
            let fields =
                format!("<LocalAnchorB>{lever} 0</LocalAnchorB><LocalAxisA>0 1</LocalAxisA>");
            (bodies, joint("Wheel", 0, 1, &fields))
        };
        let planned = |engine, (bodies, joints): (String, String)| {
            plan_of(engine, BALL.0, BALL.1, &bodies, &joints)
        };
        // Satisfied, 4 radii out: beyond v3.1's 3, within v3.2's 5.
        let plan = planned(Engine::Box2d31, scene(0.0, 1.41421354));
        assert!(plan.joints().is_empty());
        assert_eq!(
            messages(&plan)[0].3,
            "LocalAnchorB: the joint acts 4 radii of gyration from the centre of mass of body 1, \
             beyond Box2D v3's working range (at most 3); joint not created"
        );
        assert_eq!(planned(Engine::Box2d32, scene(0.0, 1.41421354)).joints().len(), 1);
        // 2.83 radii out: built satisfied and 0.5 m off; 1 m off, the 0.5 m of a joint that
        // turns a body refuses it.
        for off in [0.0, 0.5] {
            let plan = planned(Engine::Box2d31, scene(off, 1.0));
            assert_eq!(plan.joints().len(), 1);
            assert!(plan.reports().is_empty(), "{:?}", messages(&plan));
        }
        let plan = planned(Engine::Box2d31, scene(1.0, 1.0));
        assert!(plan.joints().is_empty());
        assert!(messages(&plan)[0].3.starts_with("it starts 1 m from satisfied: a line or wheel"));
    }

    #[test]
    fn a_wheel_far_from_satisfied_between_two_dynamic_bodies_names_both_bounds() {
        // Ball 2's anchor lies 3 m off a vertical axis through ball 1: beyond the 0.5 m of
        // any wheel and the pair's 2.4 radii of gyration.
        let anchors = "<LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>-2 0</LocalAnchorB>";
        let across = joint("Wheel", 1, 2, &format!("{anchors}<LocalAxisA>0 1</LocalAxisA>"));
        let plan = plan_of(Engine::Box2d31, BALL.0, BALL.1, BODIES, &across);
        assert!(plan.joints().is_empty());
        assert_eq!(
            messages(&plan)[0].3,
            "it starts 3 m from satisfied: a line or wheel joint that turns a body (a dynamic \
             body A, or body B about an anchor beyond 2 radii of gyration) further than 0.5 m \
             from satisfied lies beyond Box2D v3's working range (its solver flings the bodies \
             apart), and it starts violated by 3 m across its axis between two dynamic bodies, \
             beyond 2.4 radii of gyration (0.848528147 m); joint not created"
        );
    }

    #[test]
    fn a_wheel_far_along_its_axis_is_body_as_lever() {
        // The ground's anchor lies on the axis through ball 1's centre, 30 m along it: 84.9
        // radii of gyration of the 0.5 m ball (beyond 75); 20 m: 56.6 (within).
        let along = |x: &str| {
            let fields = format!(
                "<LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>{x} 0</LocalAnchorB>\
                 <LocalAxisA>1 0</LocalAxisA>"
            );
            joint("Wheel", 1, 0, &fields)
        };
        for engine in [Engine::Box2d31, Engine::Box2d32] {
            let plan = plan_of(engine, BALL.0, BALL.1, BODIES, &along("31"));
            assert!(plan.joints().is_empty());
            let (code, _, index, message) = messages(&plan)[0];
            assert_eq!((code, index), (Code::BeyondBox2dRange as u32, 0));
            assert!(message.starts_with("LocalAnchorB, as body A's lever: "), "{message}");
            let plan = plan_of(engine, BALL.0, BALL.1, BODIES, &along("21"));
            assert_eq!(plan.joints().len(), 1);
        }
    }

    #[test]
    fn a_second_rail_is_refused_once_either_starts_off_its_axis() {
        // Ball 1 runs on two wheel joints to the ground: along x through its centre, and
        // along y through the ground's anchor, which lies `off` m from the ball across y.
        let rails = |off: &str| {
            joint("Wheel", 1, 0, "<LocalAnchorB>1 0</LocalAnchorB><LocalAxisA>1 0</LocalAxisA>")
                + &joint(
                    "Wheel",
                    1,
                    0,
                    &format!("<LocalAnchorB>{off} 0</LocalAnchorB><LocalAxisA>0 1</LocalAxisA>"),
                )
        };
        for engine in [Engine::Box2d31, Engine::Box2d32] {
            let plan = plan_of(engine, BALL.0, BALL.1, BODIES, &rails("1.3"));
            assert_eq!(plan.joints().len(), 1);
            assert_eq!(plan.joints()[0].joint, 0);
            let (code, _, index, message) = messages(&plan)[0];
            assert_eq!((code, index), (Code::BeyondBox2dRange as u32, 1));
            assert!(
                message.starts_with(
                    "body 1 already runs on joint 0, a line or wheel joint to a body that does \
                     not turn: a second such joint lies beyond"
                ),
                "{message}"
            );
            assert!(
                message.contains("(this one starts 0.299999952 m off it, joint 0 0 m;"),
                "{message}"
            );
            // Both on their axes: both are built.
            let plan = plan_of(engine, BALL.0, BALL.1, BODIES, &rails("1"));
            assert_eq!(plan.joints().len(), 2);
        }
    }

    #[test]
    fn a_rope_far_out_on_a_pinned_ball_is_refused() {
        // Rope 0 hangs ball 2 from ball 1, anchored `x` m from ball 1's centre (radius of
        // gyration 0.354 m); joint 1, after it, pins ball 1 to the ground.
        let rope = |x: &str| {
            joint(
                "Rope",
                1,
                2,
                &format!(
                    "<LocalAnchorA>{x} 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB><MaxLength>3</MaxLength>"
                ),
            )
        };
        let pin = |kind: &str| {
            joint(kind, 0, 1, "<LocalAnchorA>1 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>")
        };
        for kind in ["Revolute", "Weld"] {
            // 2.83 radii: beyond v3.1's 2.5, within v3.2's 7.
            let plan = plan_of(Engine::Box2d31, BALL.0, BALL.1, BODIES, &(rope("1") + &pin(kind)));
            assert_eq!(plan.joints().len(), 1);
            assert_eq!(plan.joints()[0].joint, 1);
            let (code, _, index, message) = messages(&plan)[0];
            assert_eq!((code, index), (Code::BeyondBox2dRange as u32, 0));
            assert_eq!(
                message,
                "LocalAnchorA: the joint acts 2.82843 radii of gyration (of its smaller dynamic \
                 body) from the centre of mass of body 1, which a revolute or weld joint holds to \
                 a body that does not move: a distance joint that far out on such a body lies \
                 beyond Box2D v3's working range (at most 2.5); joint not created"
            );
            let plan = plan_of(Engine::Box2d32, BALL.0, BALL.1, BODIES, &(rope("1") + &pin(kind)));
            assert_eq!(plan.joints().len(), 2);
            let plan =
                plan_of(Engine::Box2d31, BALL.0, BALL.1, BODIES, &(rope("0.8") + &pin(kind)));
            assert_eq!(plan.joints().len(), 2);
        }
        // The same rope on the free ball is built, up to the lever every joint has (75); so
        // is a rope from the ground to the pinned ball, which carries no other body on it.
        let to_ground = joint(
            "Rope",
            0,
            1,
            "<LocalAnchorA>2 0</LocalAnchorA><LocalAnchorB>1 0</LocalAnchorB><MaxLength>3</MaxLength>",
        );
        for engine in [Engine::Box2d31, Engine::Box2d32] {
            let plan = plan_of(engine, BALL.0, BALL.1, BODIES, &rope("1"));
            assert_eq!(plan.joints().len(), 1);
            assert!(plan.reports().is_empty());
            let plan = plan_of(engine, BALL.0, BALL.1, BODIES, &(to_ground.clone() + &pin("Weld")));
            assert_eq!(plan.joints().len(), 2);
            assert!(plan.reports().is_empty());
        }
    }

    #[test]
    fn a_drive_that_flings_a_light_body_is_refused() {
        let friction = joint("Friction", 0, 1, "<MaxForce>1e9</MaxForce>");
        let plan = plan_of(Engine::Box2d32, BALL.0, BALL.1, BODIES, &friction);
        assert!(plan.joints().is_empty());
        let (code, _, _, message) = messages(&plan)[0];
        assert_eq!(code, Code::BeyondBox2dRange as u32);
        assert!(
            message.starts_with("its motor or friction force 1e+09 N accelerates body 1 (mass"),
            "{message}"
        );
    }
}
