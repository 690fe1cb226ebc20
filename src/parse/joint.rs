//! `<Joint Type="...">`: the common fields, then one table that says which element each
//! joint kind has, where it goes, and what it may hold.

use super::{JointOrigin, Parsed, Parser, Seen, Tag, problem};
use crate::error::Code;
use crate::scene::{Joint, JointKind, NONE, Vec2};

const JOINT: &[&str] = &[
    "name", "userdata", "bodya", "bodyb", "jointa", "jointb", "collideconnected",
    "localanchora", "localanchorb", "localaxisa", "referenceangle", "enablelimit",
    "lowerangle", "upperangle", "lowertranslation", "uppertranslation", "enablemotor",
    "motorspeed", "maxmotortorque", "maxmotorforce", "length", "frequencyhz", "dampingratio",
    "groundanchora", "groundanchorb", "lengtha", "lengthb", "maxlengtha", "maxlengthb", "ratio",
    "maxforce", "maxtorque", "maxlength", "linearoffset", "angularoffset", "correctionfactor",
    // Farseer's spellings (spec section 8.1).
    "breakpoint", "localxaxis1", "localxaxis", "axis", "worldanchora", "worldanchorb", "constant",
    "biasfactor", "maximpulse", "softness", "targetangle", "minlength",
];

/// The elements that make a Farseer `Line` joint (February 2011 on) a wheel joint.
const WHEEL_ONLY: [&str; 4] = ["frequencyhz", "dampingratio", "maxmotortorque", "localxaxis"];

/// Where a kind-specific element goes.
enum Slot {
    Vector(fn(&mut Joint) -> &mut Vec2),
    Float(fn(&mut Joint) -> &mut f32),
    /// A float that must not be negative.
    NonNegative(fn(&mut Joint) -> &mut f32),
    Flag(fn(&mut Joint) -> &mut bool),
    /// Accepted and dropped: Farseer data with no meaning in the scene.
    Ignored,
}

/// The slot of element `name` (from [`JOINT`]) in a joint of `kind`, if it has one.
fn slot(kind: JointKind, name: &str) -> Option<Slot> {
    use JointKind::*;
    use Slot::*;
    let is = |kinds: &[JointKind]| kinds.contains(&kind);
    let anchored = !is(&[Gear, Motor, Unsupported]);
    let farseer_only = matches!(
        name,
        "localanchora" | "localanchorb" | "biasfactor" | "maximpulse" | "softness" | "targetangle"
            | "minlength" | "maxlength" | "frequencyhz" | "dampingratio"
    );
    Some(match name {
        "breakpoint" => Ignored,
        _ if kind == Unsupported && farseer_only => Ignored,
        "localanchora" if anchored => Vector(|j| &mut j.local_anchor_a),
        "localanchorb" if anchored => Vector(|j| &mut j.local_anchor_b),
        "localaxisa" if is(&[Prismatic, Line, Wheel]) => Vector(|j| &mut j.local_axis_a),
        "localxaxis1" if is(&[Prismatic]) => Vector(|j| &mut j.local_axis_a),
        "localxaxis" if is(&[Line, Wheel]) => Vector(|j| &mut j.local_axis_a),
        "axis" if is(&[Prismatic, Wheel]) => Vector(|j| &mut j.local_axis_a),
        "referenceangle" if is(&[Revolute, Prismatic, Weld]) => Float(|j| &mut j.reference_angle),
        "enablelimit" if is(&[Revolute, Prismatic, Line]) => Flag(|j| &mut j.enable_limit),
        "lowerangle" if is(&[Revolute]) => Float(|j| &mut j.lower_limit),
        "upperangle" if is(&[Revolute]) => Float(|j| &mut j.upper_limit),
        "lowertranslation" if is(&[Prismatic, Line]) => Float(|j| &mut j.lower_limit),
        "uppertranslation" if is(&[Prismatic, Line]) => Float(|j| &mut j.upper_limit),
        "enablemotor" if is(&[Revolute, Prismatic, Line, Wheel]) => Flag(|j| &mut j.enable_motor),
        "motorspeed" if is(&[Revolute, Prismatic, Line, Wheel]) => Float(|j| &mut j.motor_speed),
        "maxmotortorque" if is(&[Revolute, Wheel, Line]) => NonNegative(|j| &mut j.max_motor_torque),
        "maxmotorforce" if is(&[Prismatic, Line]) => NonNegative(|j| &mut j.max_motor_force),
        "length" if is(&[Distance]) => NonNegative(|j| &mut j.length),
        "frequencyhz" if is(&[Distance, Weld, Wheel, Line]) => NonNegative(|j| &mut j.frequency_hz),
        "dampingratio" if is(&[Distance, Weld, Wheel, Line]) => NonNegative(|j| &mut j.damping_ratio),
        "groundanchora" | "worldanchora" if is(&[Pulley]) => Vector(|j| &mut j.ground_anchor_a),
        "groundanchorb" | "worldanchorb" if is(&[Pulley]) => Vector(|j| &mut j.ground_anchor_b),
        "constant" if is(&[Pulley]) => Ignored,
        "lengtha" if is(&[Pulley]) => Float(|j| &mut j.length_a),
        "lengthb" if is(&[Pulley]) => Float(|j| &mut j.length_b),
        "maxlengtha" if is(&[Pulley]) => Float(|j| &mut j.max_length_a),
        "maxlengthb" if is(&[Pulley]) => Float(|j| &mut j.max_length_b),
        "ratio" if is(&[Pulley, Gear]) => Float(|j| &mut j.ratio),
        "maxforce" if is(&[Friction, Motor]) => NonNegative(|j| &mut j.max_force),
        "maxtorque" if is(&[Friction, Motor]) => NonNegative(|j| &mut j.max_torque),
        "maxlength" if is(&[Rope]) => NonNegative(|j| &mut j.max_length),
        "linearoffset" if is(&[Motor]) => Vector(|j| &mut j.linear_offset),
        "angularoffset" if is(&[Motor]) => Float(|j| &mut j.angular_offset),
        "correctionfactor" if is(&[Motor]) => Float(|j| &mut j.correction_factor),
        _ => return None,
    })
}

fn joint_kind(value: &str) -> Option<JointKind> {
    use JointKind::*;
    Some(match value.to_ascii_lowercase().as_str() {
        "angle" | "slider" => Unsupported,
        "revolute" => Revolute,
        "prismatic" => Prismatic,
        "distance" => Distance,
        "pulley" => Pulley,
        "line" => Line,
        "weld" => Weld,
        "friction" => Friction,
        "gear" => Gear,
        "wheel" => Wheel,
        "rope" => Rope,
        "motor" => Motor,
        _ => return None,
    })
}

impl<'a> Parser<'a> {
    pub(super) fn joint(&mut self, tag: Tag<'a>) -> Parsed<()> {
        let kind = self.joint_type(&tag)?;
        let mut joint = Joint::new(kind);
        let mut at = JointOrigin { body_a: tag.at, body_b: tag.at, joint_a: tag.at, joint_b: tag.at };
        let mut seen = Seen::default();
        while let Some(child) = self.child(&tag)? {
            let Some((name, repeated)) = self.known(&tag, &child, JOINT, &mut seen)? else {
                continue;
            };
            let legacy = self.version == 0;
            let common = matches!(name, "name" | "userdata" | "bodya" | "bodyb" | "collideconnected");
            let named_joint = matches!(name, "jointa" | "jointb") && (legacy || kind == JointKind::Gear);
            let slot = slot(kind, name);
            if !common && !named_joint && slot.is_none() {
                let message = format!("<{}> does not belong in a {kind:?} joint; ignored", child.name());
                self.warn(Code::UnknownElement, child.at, message)?;
                self.skip(&child)?;
                continue;
            }
            if repeated {
                self.duplicate(&tag, &child)?;
            }
            if kind == JointKind::Weld && matches!(name, "frequencyhz" | "dampingratio") {
                self.newer_construct(child.at, "a soft Weld joint")?;
            }
            match name {
                "name" => joint.name = self.string(&child)?,
                "userdata" => joint.user_data = self.user_data(&child)?,
                "collideconnected" => joint.collide_connected = self.boolean(&child)?,
                "bodya" => (joint.body_a, at.body_a) = self.id(&child)?,
                "bodyb" => (joint.body_b, at.body_b) = self.id(&child)?,
                // Legacy files name the bodies JointA and JointB.
                "jointa" if legacy => (joint.body_a, at.body_a) = self.id(&child)?,
                "jointb" if legacy => (joint.body_b, at.body_b) = self.id(&child)?,
                "jointa" => (joint.joint_a, at.joint_a) = self.id(&child)?,
                "jointb" => (joint.joint_b, at.joint_b) = self.id(&child)?,
                _ => match slot.expect("elements without a slot were skipped above") {
                    Slot::Vector(field) => *field(&mut joint) = self.vector(&child)?,
                    Slot::Float(field) => *field(&mut joint) = self.float(&child)?,
                    Slot::NonNegative(field) => *field(&mut joint) = self.non_negative(&child)?,
                    Slot::Flag(field) => *field(&mut joint) = self.boolean(&child)?,
                    Slot::Ignored => self.skip(&child)?,
                },
            }
        }
        if kind == JointKind::Line && WHEEL_ONLY.iter().any(|name| seen.contains(JOINT, name)) {
            self.line_is_wheel(&tag, &mut joint, &seen)?;
        }
        self.check_joint(&tag, &joint, &at)?;
        self.origins.joints.push(at);
        self.scene.joints.push(joint);
        Ok(())
    }

    /// Farseer's `Line` joints from February 2011 on are wheel joints under the old name:
    /// read them as Wheel, with the wheel's defaults for what they leave out.
    fn line_is_wheel(&mut self, tag: &Tag<'a>, joint: &mut Joint, seen: &Seen) -> Parsed<()> {
        let wheel = Joint::new(JointKind::Wheel);
        joint.kind = JointKind::Wheel as u32;
        if !seen.contains(JOINT, "frequencyhz") {
            joint.frequency_hz = wheel.frequency_hz;
        }
        if !seen.contains(JOINT, "dampingratio") {
            joint.damping_ratio = wheel.damping_ratio;
        }
        self.warn(
            Code::LineJointIsWheel,
            tag.at,
            "this Line joint has a spring or a motor torque (Farseer's wheel joint under its old name); read as a Wheel joint",
        )
    }

    fn joint_type(&mut self, tag: &Tag<'a>) -> Parsed<JointKind> {
        let attrs = self.attributes(tag)?;
        self.unknown_attributes(tag, &attrs, &["type"])?;
        let Some(ty) = attrs.iter().find(|a| a.is("type")) else {
            return Err(problem(Code::MissingAttribute, tag.at, "<Joint> has no Type attribute"));
        };
        let value = super::trim_xml(&ty.value);
        let Some(kind) = joint_kind(value) else {
            let why = if value.eq_ignore_ascii_case("mouse") {
                "a mouse joint belongs to a running game, not to a scene".to_string()
            } else {
                format!("unknown joint Type \"{}\"", super::shorten(value))
            };
            return Err(problem(
                Code::UnsupportedJointType,
                ty.at,
                format!("{why}; supported: Revolute, Prismatic, Distance, Pulley, Line, Weld, Friction, Gear, Wheel, Rope, Motor"),
            ));
        };
        if matches!(kind, JointKind::Wheel | JointKind::Rope | JointKind::Motor) {
            self.newer_construct(ty.at, &format!("a {value} joint"))?;
        }
        if kind == JointKind::Unsupported {
            self.warn(
                Code::FarseerOnlyJoint,
                ty.at,
                format!("{value} joints exist only in Farseer and have no Box2D equivalent: kept (so joint indices stay stable) but not simulated"),
            )?;
        }
        Ok(kind)
    }

    /// The rules one joint can break on its own (cross references come later).
    fn check_joint(&self, tag: &Tag<'a>, joint: &Joint, at: &JointOrigin) -> Parsed<()> {
        let legacy = self.version == 0;
        for (index, name, legacy_name) in [(joint.body_a, "BodyA", "JointA"), (joint.body_b, "BodyB", "JointB")] {
            if index == NONE {
                let name = if legacy { legacy_name } else { name };
                return Err(self.missing(tag, &format!("<{name}>: a joint names both of its bodies")));
            }
        }
        if joint.body_a == joint.body_b {
            return Err(problem(
                Code::JointSelfReference,
                at.body_b,
                format!("the joint connects body {} to itself", joint.body_a),
            ));
        }
        let kind = joint.kind();
        if kind == Some(JointKind::Gear) {
            for (index, name) in [(joint.joint_a, "JointA"), (joint.joint_b, "JointB")] {
                if index == NONE {
                    return Err(self.missing(tag, &format!("<{name}>: a gear joint names the two joints it couples")));
                }
            }
        }
        if joint.enable_limit && joint.lower_limit > joint.upper_limit {
            let (lower, upper) = match kind {
                Some(JointKind::Revolute) => ("LowerAngle", "UpperAngle"),
                _ => ("LowerTranslation", "UpperTranslation"),
            };
            return Err(problem(
                Code::BadLimit,
                tag.at,
                format!("{lower} {} is above {upper} {} with the limit enabled", joint.lower_limit, joint.upper_limit),
            ));
        }
        let has_axis = matches!(kind, Some(JointKind::Prismatic | JointKind::Line | JointKind::Wheel));
        if has_axis && joint.local_axis_a == Vec2::ZERO {
            return Err(problem(Code::ZeroAxis, tag.at, "<LocalAxisA> is (0, 0): a joint axis needs a direction"));
        }
        if kind == Some(JointKind::Pulley) && joint.ratio <= 0.0 {
            return Err(problem(Code::BadRatio, tag.at, format!("a pulley's <Ratio> must be greater than 0, not {}", joint.ratio)));
        }
        Ok(())
    }
}
