//! `<Joint Type="...">`: the common fields, then the kind-specific ones, which the model's
//! table of joint elements says each kind has, where they go and what they may hold.

use super::{Element as _, Reader, Seen, Tag, attributes, elements};
use crate::arena::JointOrigin;
use crate::error::{Code, Parsed, problem};
use crate::markup::Name;
use crate::rules;
use crate::scene::joints::{self, Element, Slot, Value};
use crate::scene::{Joint, JointKind, KeptAt, NONE, Object};

elements! {
    enum JointChild {
        Name,
        UserData,
        Tag,
        BodyA,
        BodyB,
        JointA,
        JointB,
        CollideConnected,
        LocalAnchorA,
        LocalAnchorB,
        LocalAxisA,
        ReferenceAngle,
        EnableLimit,
        LowerAngle,
        UpperAngle,
        LowerTranslation,
        UpperTranslation,
        EnableMotor,
        MotorSpeed,
        MaxMotorTorque,
        MaxMotorForce,
        Length,
        FrequencyHz,
        DampingRatio,
        GroundAnchorA,
        GroundAnchorB,
        LengthA,
        LengthB,
        MaxLengthA,
        MaxLengthB,
        Ratio,
        MaxForce,
        MaxTorque,
        MaxLength,
        LinearOffset,
        AngularOffset,
        CorrectionFactor,
        // Farseer's spellings (spec section 8.1).
        Breakpoint,
        LocalXAxis1,
        LocalXAxis,
        Axis,
        WorldAnchorA,
        WorldAnchorB,
        Constant,
        BiasFactor,
        MaxImpulse,
        Softness,
        TargetAngle,
        MinLength,
    }
}

/// The elements that make a Farseer `Line` joint (February 2011 on) a wheel joint.
const WHEEL_ONLY: [JointChild; 4] = [
    JointChild::FrequencyHz,
    JointChild::DampingRatio,
    JointChild::MaxMotorTorque,
    JointChild::LocalXAxis,
];

/// The table's row of each element, by the element's key (none for the common elements):
/// found by name once, when compiling.
static ROWS: [Option<&Element>; JointChild::ALL.len()] = {
    let mut rows = [None; JointChild::ALL.len()];
    let mut i = 0;
    while i < rows.len() {
        rows[i] = joints::named(JointChild::NAMES.names[i]);
        i += 1;
    }
    rows
};

/// Every joint `Type` [`joint_kind`] reads, in the format's spelling, for a "did you mean".
const JOINT_TYPES: [&str; 13] = [
    "Revolute",
    "Prismatic",
    "Distance",
    "Pulley",
    "Line",
    "Weld",
    "Friction",
    "Gear",
    "Wheel",
    "Rope",
    "Motor",
    "Angle",
    "Slider",
];

fn joint_kind(value: &str) -> Option<JointKind> {
    use JointKind::*;
    Some(match super::lowercase(value, &mut [0; 16]) {
        b"angle" | b"slider" => Unsupported,
        b"revolute" => Revolute,
        b"prismatic" => Prismatic,
        b"distance" => Distance,
        b"pulley" => Pulley,
        b"line" => Line,
        b"weld" => Weld,
        b"friction" => Friction,
        b"gear" => Gear,
        b"wheel" => Wheel,
        b"rope" => Rope,
        b"motor" => Motor,
        _ => return None,
    })
}

/// Where a joint's references are written, while it is read.
struct Refs {
    body_a: usize,
    body_b: usize,
    joint_a: usize,
    joint_b: usize,
}

impl<'a> Reader<'a> {
    pub(super) fn joint(&mut self, tag: &Tag) -> Parsed<()> {
        self.begin_object(Object::Joint(self.arena.scene.joints.len() as u32));
        let kind = self.joint_type(tag)?;
        if kind == JointKind::Unsupported {
            // It has no Box2Scene form: the writer writes back its whole text.
            self.tok.kept.pin(tag.at);
        }
        let mut joint = Joint::new(kind);
        let mut name_str = None;
        let mut at = Refs { body_a: tag.at, body_b: tag.at, joint_a: tag.at, joint_b: tag.at };
        let mut seen = Seen::default();
        // Farseer's `Axis` is in world coordinates (spec section 8.1).
        let mut world_axis = None;
        // What a Line joint holds and a Wheel joint does not, with where it is written: a
        // Line joint may yet be read as a Wheel (`line_is_wheel`).
        let mut line_only = Vec::new();
        let mut child = Tag::slot();
        while self.tok.child(tag, &mut child)? {
            let Some((name, repeated)) = self.known(tag, &child, &mut seen)? else {
                continue;
            };
            use JointChild::*;
            let legacy = self.arena.version == 0;
            let common = matches!(name, Name | UserData | BodyA | BodyB | CollideConnected)
                || (name == Tag && self.arena.tag_is_user_data());
            // Legacy files name the bodies JointA and JointB.
            let legacy_body = matches!(name, JointA | JointB) && legacy;
            let row = ROWS[name as usize];
            let slot = row.and_then(|row| row.slot(kind));
            if !common && !legacy_body && slot.is_none() {
                let words =
                    || format!("<{}> does not belong in a {kind:?} joint; ignored", child.name());
                // Kept for the writer, unless the kind the joint may end as reads it: a Line
                // joint may be read as a Wheel (`line_is_wheel`), and written back as one,
                // where the element would be read.
                let wheel = row.and_then(|row| row.slot(JointKind::Wheel));
                match kind == JointKind::Line && wheel.is_some() {
                    true => self.discard(&child, words)?,
                    false => self.ignore(&child, words)?,
                }
                continue;
            }
            if repeated {
                self.duplicate(tag, &child)?;
            }
            if let (Some(row), JointKind::Line) = (row, kind)
                && let (Some(Slot::Fills(value)), None) = (slot, row.slot(JointKind::Wheel))
            {
                line_only.push((value, child.at, row.name));
            }
            // The weld's spring is the one such element.
            if row.is_some_and(|row| row.lowest_version(kind) >= 2) {
                self.newer_construct(child.at, "a soft Weld joint")?;
            }
            match name {
                Name => name_str = Some(self.string(&child)?),
                UserData => joint.user_data = self.user_data(&child)?,
                Tag => joint.user_data = self.tagged_user_data(&child)?,
                CollideConnected => joint.collide_connected = self.boolean(&child)?,
                BodyA => (joint.body_a, at.body_a) = self.id(&child)?,
                BodyB => (joint.body_b, at.body_b) = self.id(&child)?,
                JointA if legacy => (joint.body_a, at.body_a) = self.id(&child)?,
                JointB if legacy => (joint.body_b, at.body_b) = self.id(&child)?,
                JointA => (joint.joint_a, at.joint_a) = self.id(&child)?,
                JointB => (joint.joint_b, at.joint_b) = self.id(&child)?,
                _ => match slot.expect("elements without a slot were skipped above") {
                    Slot::Fills(Value::Vector(field)) => {
                        *field(&mut joint) = self.vector(&child)?
                    }
                    Slot::Fills(Value::Float(field)) if matches!(name, LowerAngle | UpperAngle) => {
                        *field(&mut joint) = self.radians(&child)?
                    }
                    Slot::Fills(Value::Float(field)) => *field(&mut joint) = self.float(&child)?,
                    Slot::Fills(Value::NonNegative(field)) => {
                        *field(&mut joint) = self.non_negative(&child)?
                    }
                    Slot::Fills(Value::Flag(field)) => *field(&mut joint) = self.boolean(&child)?,
                    Slot::Fills(Value::JointIndex(_)) => {
                        unreachable!("JointA and JointB are read above, with where they are")
                    }
                    Slot::Dropped => self.tok.skip(&child)?,
                },
            }
            // Not inside a Farseer-only joint, which every dialect writes back as it was.
            self.arena.origins.signs.farseer_3_3 |= kind != JointKind::Unsupported
                && matches!(name, LocalXAxis1 | LocalXAxis | Breakpoint);
            if matches!(name, LocalAxisA | LocalXAxis1 | LocalXAxis | Axis) {
                world_axis = (name == Axis).then_some(joint.local_axis_a);
            }
        }
        if kind == JointKind::Line && WHEEL_ONLY.into_iter().any(|element| seen.contains(element)) {
            self.line_is_wheel(tag, &mut joint, &seen, &line_only)?;
        }
        self.check_joint(tag, &joint, &at)?;
        if kind == JointKind::Unsupported {
            let text = self.tok.unpin(self.tok.position());
            self.keep_str(KeptAt::Whole, &text);
        }
        self.end_object();
        let origin = JointOrigin {
            body_a: self.spot(at.body_a),
            body_b: self.spot(at.body_b),
            joint_a: self.spot(at.joint_a),
            joint_b: self.spot(at.joint_b),
        };
        self.arena.origins.joints.push(origin);
        if let Some(axis) = world_axis {
            let index = self.arena.scene.joints.len() as u32;
            self.arena.origins.world_axes.push((index, axis));
        }
        self.arena.scene.push_joint(joint, name_str);
        Ok(())
    }

    /// Farseer's `Line` joints from February 2011 on are wheel joints under the old name:
    /// read them as Wheel, with the wheel's defaults for what they leave out. What the file
    /// gave them that a Wheel joint does not hold (`line_only`: a limit, a linear motor's
    /// force, each with the element's offset and name) is ignored with a warning, and the
    /// field is the wheel's default again: the writer, which writes a Wheel joint, would not
    /// write it.
    fn line_is_wheel(
        &mut self,
        tag: &Tag,
        joint: &mut Joint,
        seen: &Seen,
        line_only: &[(Value, usize, &str)],
    ) -> Parsed<()> {
        let mut wheel = Joint::new(JointKind::Wheel);
        joint.kind = JointKind::Wheel as u32;
        self.arena.origins.signs.farseer_3_3 = true;
        if !seen.contains(JointChild::FrequencyHz) {
            joint.frequency_hz = wheel.frequency_hz;
        }
        if !seen.contains(JointChild::DampingRatio) {
            joint.damping_ratio = wheel.damping_ratio;
        }
        self.warn(
            Code::LineJointIsWheel,
            tag.at,
            || "this Line joint has a spring or a motor torque (Farseer's wheel joint under its old name); read as a Wheel joint",
        )?;
        for &(value, at, name) in line_only {
            value.copy(&mut wheel, joint);
            self.warn(Code::UnknownElement, at, || {
                format!(
                    "<{name}> does not belong in a Wheel joint, which this Line joint is read \
                     as; ignored"
                )
            })?;
        }
        Ok(())
    }

    fn joint_type(&mut self, tag: &Tag) -> Parsed<JointKind> {
        let attrs = attributes!(self, tag, &["Type"]);
        let Some(ty) = attrs.iter().find(|a| a.is("type")) else {
            return Err(problem(Code::MissingAttribute, tag.at, "<Joint> has no Type attribute"));
        };
        let value = super::trim_xml(&ty.value);
        let Some(kind) = joint_kind(value) else {
            let why = if value.eq_ignore_ascii_case("mouse") {
                "a mouse joint belongs to a running game, not to a scene".to_string()
            } else {
                let hint = super::did_you_mean(value, &JOINT_TYPES);
                format!("unknown joint Type \"{}\"{hint}", super::shorten(value))
            };
            return Err(problem(
                Code::UnsupportedJointType,
                ty.at,
                format!(
                    "{why}; supported: Revolute, Prismatic, Distance, Pulley, Line, Weld, Friction, Gear, Wheel, Rope, Motor"
                ),
            ));
        };
        // The Type as written, copied in place (a known one is short): the warnings below
        // take the reader, whose text the attributes borrow.
        let (at, value) = (ty.at, Name::new(value));
        if joints::VERSION_2_KINDS.contains(kind) {
            self.newer_construct(at, format_args!("a {value} joint"))?;
        }
        if kind == JointKind::Unsupported {
            self.warn(
                Code::FarseerOnlyJoint,
                at,
                || format!("{value} joints exist only in Farseer and have no Box2D equivalent: kept (so joint indices stay stable) but not simulated"),
            )?;
        }
        Ok(kind)
    }

    /// The rules one joint can break on its own (cross references come later).
    fn check_joint(&mut self, tag: &Tag, joint: &Joint, at: &Refs) -> Parsed<()> {
        let legacy = self.arena.version == 0;
        for (index, name, legacy_name) in
            [(joint.body_a, "BodyA", "JointA"), (joint.body_b, "BodyB", "JointB")]
        {
            if index == NONE {
                let name = if legacy { legacy_name } else { name };
                return Err(self
                    .tok
                    .missing(tag, &format!("<{name}>: a joint names both of its bodies")));
            }
        }
        let kind = joint.kind();
        if kind == Some(JointKind::Gear) {
            for (index, name) in [(joint.joint_a, "JointA"), (joint.joint_b, "JointB")] {
                if index == NONE {
                    return Err(self.tok.missing(
                        tag,
                        &format!("<{name}>: a gear joint names the two joints it couples"),
                    ));
                }
            }
        }
        self.recovered(rules::joint(joint, tag.at, at.body_b), ())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_element_key_finds_its_row_and_each_row_has_a_key() {
        use JointChild::*;
        for &key in JointChild::ALL {
            match ROWS[key as usize] {
                Some(row) => assert_eq!(row.name, key.name()),
                None => assert!(
                    matches!(key, Name | UserData | Tag | BodyA | BodyB | CollideConnected),
                    "{key:?}"
                ),
            }
        }
        for row in &joints::ELEMENTS {
            assert!(JointChild::ALL.iter().any(|&key| key.name() == row.name), "{}", row.name);
        }
    }
}
