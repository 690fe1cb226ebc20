//! The one table of a joint's kind-specific elements (spec section 8): for each element a
//! file may give a joint, in the order box2scene's own writer writes them, the kinds that
//! read it, the kinds that writer writes it for, the field of the record it fills (with its
//! value class), and the kinds in which only a Version 2 file may hold it. The reader, the
//! canonical joint (see [`canonical`]), both writers, the dump and the check of what needs
//! Version 2 take it from here.
//!
//! The elements every kind has (`Name`, `BodyA`, `BodyB` and `CollideConnected` before the
//! table's, `UserData` after them) are not in the table, nor are the defaults, which
//! [`Joint::new`] gives.

use super::records::{Joint, JointKind, Vec2};
use JointKind::*;

/// A set of joint kinds.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) struct Kinds(u16);

impl Kinds {
    pub(crate) const EMPTY: Kinds = Kinds(0);

    pub(crate) const fn of(kinds: &[JointKind]) -> Kinds {
        let mut bits = 0;
        let mut i = 0;
        while i < kinds.len() {
            bits |= 1 << kinds[i] as u32;
            i += 1;
        }
        Kinds(bits)
    }

    pub(crate) const fn contains(self, kind: JointKind) -> bool {
        self.0 & (1 << kind as u32) != 0
    }

    const fn and(self, other: Kinds) -> Kinds {
        Kinds(self.0 | other.0)
    }
}

const fn of(kinds: &[JointKind]) -> Kinds {
    Kinds::of(kinds)
}

/// How many kinds there are (the values 0 to 11).
const KIND_COUNT: usize = Unsupported as usize + 1;

/// Every kind.
const EVERY_KIND: Kinds = of(&[
    Revolute,
    Prismatic,
    Distance,
    Pulley,
    Line,
    Weld,
    Friction,
    Gear,
    Wheel,
    Rope,
    Motor,
    Unsupported,
]);

/// The kinds with anchors in the bodies' frames: all but the gear and the motor, which
/// join two bodies without a point in common, and Farseer's own kinds (which have anchors
/// that box2scene drops).
const ANCHORED: Kinds =
    of(&[Revolute, Prismatic, Distance, Pulley, Line, Weld, Friction, Wheel, Rope]);

/// The kinds with an axis in body A's frame.
pub(crate) const AXIAL: Kinds = of(&[Prismatic, Line, Wheel]);

/// The kinds with a spring: frequency and damping ratio.
const SPRUNG: Kinds = of(&[Distance, Weld, Wheel]);

/// Farseer's own kinds (Angle, Slider): read to be kept whole, never written from fields.
const FARSEER_ONLY: Kinds = of(&[Unsupported]);

/// The kinds that only a Version 2 file may hold (spec section 1).
pub(crate) const VERSION_2_KINDS: Kinds = of(&[Wheel, Rope, Motor]);

/// The `Type` attribute of a joint of `kind`, as the writers spell it (a reader takes any
/// letter case).
pub(crate) const fn type_name(kind: JointKind) -> &'static str {
    match kind {
        Revolute => "Revolute",
        Prismatic => "Prismatic",
        Distance => "Distance",
        Pulley => "Pulley",
        Line => "Line",
        Weld => "Weld",
        Friction => "Friction",
        Gear => "Gear",
        Wheel => "Wheel",
        Rope => "Rope",
        Motor => "Motor",
        Unsupported => "Unsupported",
    }
}

/// What a field holds (its value class), and where it is in the record.
#[derive(Clone, Copy)]
pub(crate) enum Value {
    Vector(fn(&mut Joint) -> &mut Vec2),
    Float(fn(&mut Joint) -> &mut f32),
    /// A float that must not be negative.
    NonNegative(fn(&mut Joint) -> &mut f32),
    Flag(fn(&mut Joint) -> &mut bool),
    /// An index into the scene's joints; `NONE` while unset, and then not written.
    JointIndex(fn(&mut Joint) -> &mut u32),
}

impl Value {
    /// Sets the field of `to` to that of `from`.
    pub(crate) fn copy(self, from: &mut Joint, to: &mut Joint) {
        match self {
            Value::Vector(at) => *at(to) = *at(from),
            Value::Float(at) | Value::NonNegative(at) => *at(to) = *at(from),
            Value::Flag(at) => *at(to) = *at(from),
            Value::JointIndex(at) => *at(to) = *at(from),
        }
    }

    /// Whether the field's bits differ in `a` and `b` (so -0.0 and 0.0 differ).
    pub(crate) fn differs(self, a: &mut Joint, b: &mut Joint) -> bool {
        match self {
            Value::Vector(at) => {
                let (a, b) = (*at(a), *at(b));
                a.x.to_bits() != b.x.to_bits() || a.y.to_bits() != b.y.to_bits()
            }
            Value::Float(at) | Value::NonNegative(at) => at(a).to_bits() != at(b).to_bits(),
            Value::Flag(at) => at(a) != at(b),
            Value::JointIndex(at) => at(a) != at(b),
        }
    }
}

/// A kind-specific field of the joint record: its name, as the dump spells it, and its value.
#[derive(Clone, Copy)]
pub(crate) struct Field {
    pub(crate) name: &'static str,
    pub(crate) value: Value,
}

const fn field(name: &'static str, value: Value) -> Field {
    Field { name, value }
}

const JOINT_A: Field = field("joint_a", Value::JointIndex(|j| &mut j.joint_a));
const JOINT_B: Field = field("joint_b", Value::JointIndex(|j| &mut j.joint_b));
const LOCAL_ANCHOR_A: Field = field("local_anchor_a", Value::Vector(|j| &mut j.local_anchor_a));
const LOCAL_ANCHOR_B: Field = field("local_anchor_b", Value::Vector(|j| &mut j.local_anchor_b));
const LOCAL_AXIS_A: Field = field("local_axis_a", Value::Vector(|j| &mut j.local_axis_a));
const GROUND_ANCHOR_A: Field = field("ground_anchor_a", Value::Vector(|j| &mut j.ground_anchor_a));
const GROUND_ANCHOR_B: Field = field("ground_anchor_b", Value::Vector(|j| &mut j.ground_anchor_b));
const LINEAR_OFFSET: Field = field("linear_offset", Value::Vector(|j| &mut j.linear_offset));
const REFERENCE_ANGLE: Field = field("reference_angle", Value::Float(|j| &mut j.reference_angle));
const ENABLE_LIMIT: Field = field("enable_limit", Value::Flag(|j| &mut j.enable_limit));
const LOWER_LIMIT: Field = field("lower_limit", Value::Float(|j| &mut j.lower_limit));
const UPPER_LIMIT: Field = field("upper_limit", Value::Float(|j| &mut j.upper_limit));
const ENABLE_MOTOR: Field = field("enable_motor", Value::Flag(|j| &mut j.enable_motor));
const MOTOR_SPEED: Field = field("motor_speed", Value::Float(|j| &mut j.motor_speed));
const MAX_MOTOR_TORQUE: Field =
    field("max_motor_torque", Value::NonNegative(|j| &mut j.max_motor_torque));
const MAX_MOTOR_FORCE: Field =
    field("max_motor_force", Value::NonNegative(|j| &mut j.max_motor_force));
const LENGTH: Field = field("length", Value::NonNegative(|j| &mut j.length));
const FREQUENCY_HZ: Field = field("frequency_hz", Value::NonNegative(|j| &mut j.frequency_hz));
const DAMPING_RATIO: Field = field("damping_ratio", Value::NonNegative(|j| &mut j.damping_ratio));
const LENGTH_A: Field = field("length_a", Value::Float(|j| &mut j.length_a));
const LENGTH_B: Field = field("length_b", Value::Float(|j| &mut j.length_b));
const MAX_LENGTH_A: Field = field("max_length_a", Value::Float(|j| &mut j.max_length_a));
const MAX_LENGTH_B: Field = field("max_length_b", Value::Float(|j| &mut j.max_length_b));
const RATIO: Field = field("ratio", Value::Float(|j| &mut j.ratio));
const MAX_FORCE: Field = field("max_force", Value::NonNegative(|j| &mut j.max_force));
const MAX_TORQUE: Field = field("max_torque", Value::NonNegative(|j| &mut j.max_torque));
const MAX_LENGTH: Field = field("max_length", Value::NonNegative(|j| &mut j.max_length));
const ANGULAR_OFFSET: Field = field("angular_offset", Value::Float(|j| &mut j.angular_offset));
const CORRECTION_FACTOR: Field =
    field("correction_factor", Value::Float(|j| &mut j.correction_factor));

/// Every kind-specific field of the record, in groups of related ones (a flag beside the
/// values it governs), in the record's order otherwise: the dump shows a group to a line.
pub(crate) const FIELD_GROUPS: [&[Field]; 8] = [
    &[JOINT_A, JOINT_B],
    &[LOCAL_ANCHOR_A, LOCAL_ANCHOR_B, LOCAL_AXIS_A],
    &[GROUND_ANCHOR_A, GROUND_ANCHOR_B, LINEAR_OFFSET],
    &[REFERENCE_ANGLE, ENABLE_LIMIT, LOWER_LIMIT, UPPER_LIMIT],
    &[ENABLE_MOTOR, MOTOR_SPEED, MAX_MOTOR_TORQUE, MAX_MOTOR_FORCE],
    &[LENGTH, FREQUENCY_HZ, DAMPING_RATIO],
    &[LENGTH_A, LENGTH_B, MAX_LENGTH_A, MAX_LENGTH_B, RATIO],
    &[MAX_FORCE, MAX_TORQUE, MAX_LENGTH, ANGULAR_OFFSET, CORRECTION_FACTOR],
];

/// An element a joint's file may hold: a row of [`ELEMENTS`].
pub(crate) struct Element {
    /// The element's name, as written (a reader takes any letter case).
    pub(crate) name: &'static str,
    /// The kinds whose joints read it.
    pub(crate) read_by: Kinds,
    /// The kinds box2scene's own writer writes it for.
    pub(crate) written_for: Kinds,
    /// The field it fills; None for an element that is read and dropped.
    pub(crate) field: Option<&'static Field>,
    /// The kinds in which only a Version 2 file may hold it (beyond the kinds that only
    /// Version 2 has, [`VERSION_2_KINDS`]).
    pub(crate) version_2_in: Kinds,
}

/// What an element is in a joint of one kind.
#[derive(Clone, Copy)]
pub(crate) enum Slot {
    /// Its text fills this field.
    Fills(Value),
    /// Accepted and dropped: Farseer data with no meaning in the scene.
    Dropped,
}

impl Element {
    /// What the element is in a joint of `kind`; None when that kind has no such element.
    pub(crate) fn slot(&self, kind: JointKind) -> Option<Slot> {
        if !self.read_by.contains(kind) {
            return None;
        }
        match self.field {
            // A Farseer-only joint keeps its whole text instead of values.
            Some(field) if kind != Unsupported => Some(Slot::Fills(field.value)),
            _ => Some(Slot::Dropped),
        }
    }

    /// The lowest `Version` of a file that may hold the element in a joint of `kind`.
    pub(crate) fn lowest_version(&self, kind: JointKind) -> u32 {
        if self.version_2_in.contains(kind) { 2 } else { 1 }
    }

    const fn version_2_in(self, kinds: Kinds) -> Element {
        Element { version_2_in: kinds, ..self }
    }
}

/// An element that the joints of `kinds` read, which box2scene's own writer writes for them.
const fn row(name: &'static str, kinds: Kinds, field: &'static Field) -> Element {
    read_by_more(name, kinds, kinds, field)
}

/// An element that more kinds read than box2scene's own writer writes it for.
const fn read_by_more(
    name: &'static str,
    read_by: Kinds,
    written_for: Kinds,
    field: &'static Field,
) -> Element {
    Element { name, read_by, written_for, field: Some(field), version_2_in: Kinds::EMPTY }
}

/// An element that is read, and that box2scene's own writer never writes.
const fn read_only(name: &'static str, read_by: Kinds, field: &'static Field) -> Element {
    read_by_more(name, read_by, Kinds::EMPTY, field)
}

/// An element that is read and dropped, and never written.
const fn dropped(name: &'static str, read_by: Kinds) -> Element {
    Element { name, read_by, written_for: Kinds::EMPTY, field: None, version_2_in: Kinds::EMPTY }
}

/// The table, in the order box2scene's own writer writes the elements: in each row the
/// element's name, the kinds that read it (for `read_by_more`, then the fewer kinds the
/// writer writes it for, with a comment that says why), and the field it fills; what only
/// a Version 2 file may hold says so with `version_2_in`.
pub(crate) static ELEMENTS: [Element; 43] = [
    // Farseer's Angle and Slider joints have anchors too.
    read_by_more("LocalAnchorA", ANCHORED.and(FARSEER_ONLY), ANCHORED, &LOCAL_ANCHOR_A),
    read_by_more("LocalAnchorB", ANCHORED.and(FARSEER_ONLY), ANCHORED, &LOCAL_ANCHOR_B),
    row("LocalAxisA", AXIAL, &LOCAL_AXIS_A),
    row("ReferenceAngle", of(&[Revolute, Prismatic, Weld]), &REFERENCE_ANGLE),
    row("EnableLimit", of(&[Revolute, Prismatic, Line]), &ENABLE_LIMIT),
    row("LowerAngle", of(&[Revolute]), &LOWER_LIMIT),
    row("UpperAngle", of(&[Revolute]), &UPPER_LIMIT),
    row("LowerTranslation", of(&[Prismatic, Line]), &LOWER_LIMIT),
    row("UpperTranslation", of(&[Prismatic, Line]), &UPPER_LIMIT),
    row("EnableMotor", of(&[Revolute, Prismatic, Line, Wheel]), &ENABLE_MOTOR),
    row("MotorSpeed", of(&[Revolute, Prismatic, Line, Wheel]), &MOTOR_SPEED),
    // Farseer's Line joints (a wheel joint under its old name) have a motor torque and a
    // spring: a Line joint that gives one is read as a Wheel joint, so none holds them.
    read_by_more(
        "MaxMotorTorque",
        of(&[Revolute, Line, Wheel]),
        of(&[Revolute, Wheel]),
        &MAX_MOTOR_TORQUE,
    ),
    row("MaxMotorForce", of(&[Prismatic, Line]), &MAX_MOTOR_FORCE),
    row("Length", of(&[Distance]), &LENGTH),
    // The weld's spring is Box2D 2.2's (Version 2). Farseer's Slider has a spring too.
    read_by_more("FrequencyHz", SPRUNG.and(of(&[Line, Unsupported])), SPRUNG, &FREQUENCY_HZ)
        .version_2_in(of(&[Weld])),
    read_by_more("DampingRatio", SPRUNG.and(of(&[Line, Unsupported])), SPRUNG, &DAMPING_RATIO)
        .version_2_in(of(&[Weld])),
    row("GroundAnchorA", of(&[Pulley]), &GROUND_ANCHOR_A),
    row("GroundAnchorB", of(&[Pulley]), &GROUND_ANCHOR_B),
    row("LengthA", of(&[Pulley]), &LENGTH_A),
    row("LengthB", of(&[Pulley]), &LENGTH_B),
    row("MaxLengthA", of(&[Pulley]), &MAX_LENGTH_A),
    row("MaxLengthB", of(&[Pulley]), &MAX_LENGTH_B),
    // Joint indices, written only when set. The reader reads them itself, with where they
    // are, and as the bodies of any joint in a legacy file.
    row("JointA", of(&[Gear]), &JOINT_A),
    row("JointB", of(&[Gear]), &JOINT_B),
    row("Ratio", of(&[Pulley, Gear]), &RATIO),
    row("MaxForce", of(&[Friction, Motor]), &MAX_FORCE),
    row("MaxTorque", of(&[Friction, Motor]), &MAX_TORQUE),
    // Farseer's Slider has a maximum length too.
    read_by_more("MaxLength", of(&[Rope, Unsupported]), of(&[Rope]), &MAX_LENGTH),
    row("LinearOffset", of(&[Motor]), &LINEAR_OFFSET),
    row("AngularOffset", of(&[Motor]), &ANGULAR_OFFSET),
    row("CorrectionFactor", of(&[Motor]), &CORRECTION_FACTOR),
    // Farseer's spellings (spec section 8.1), written only for an engine's reader.
    dropped("Breakpoint", EVERY_KIND),
    read_only("LocalXAxis1", of(&[Prismatic]), &LOCAL_AXIS_A),
    read_only("LocalXAxis", of(&[Line, Wheel]), &LOCAL_AXIS_A),
    // In world coordinates: turned into body A's frame once the bodies are read.
    read_only("Axis", of(&[Prismatic, Wheel]), &LOCAL_AXIS_A),
    read_only("WorldAnchorA", of(&[Pulley]), &GROUND_ANCHOR_A),
    read_only("WorldAnchorB", of(&[Pulley]), &GROUND_ANCHOR_B),
    // LengthA + Ratio * LengthB.
    dropped("Constant", of(&[Pulley])),
    // Farseer's Angle and Slider joints.
    dropped("BiasFactor", FARSEER_ONLY),
    dropped("MaxImpulse", FARSEER_ONLY),
    dropped("Softness", FARSEER_ONLY),
    dropped("TargetAngle", FARSEER_ONLY),
    dropped("MinLength", FARSEER_ONLY),
];

/// The rows box2scene's own writer writes for a joint of `kind`, in the table's order.
pub(crate) fn written(kind: JointKind) -> &'static [&'static Element] {
    let (count, rows) = &WRITTEN[kind as usize];
    &rows[..*count]
}

/// For each kind, by its value, how many rows the own writer writes for it and which: the
/// writer then looks at those alone.
static WRITTEN: [(usize, [&Element; ELEMENTS.len()]); KIND_COUNT] = {
    let mut written = [(0, [&ELEMENTS[0]; ELEMENTS.len()]); KIND_COUNT];
    let mut e = 0;
    while e < ELEMENTS.len() {
        let mut k = 0;
        while k < KIND_COUNT {
            if ELEMENTS[e].written_for.0 & (1 << k) != 0 {
                let (count, rows) = &mut written[k];
                rows[*count] = &ELEMENTS[e];
                *count += 1;
            }
            k += 1;
        }
        e += 1;
    }
    written
};

/// The row named `name` (exactly), when the table has one: for tables made when compiling.
pub(crate) const fn named(name: &str) -> Option<&'static Element> {
    let mut i = 0;
    while i < ELEMENTS.len() {
        if same(ELEMENTS[i].name.as_bytes(), name.as_bytes()) {
            return Some(&ELEMENTS[i]);
        }
        i += 1;
    }
    None
}

const fn same(a: &[u8], b: &[u8]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// `given` as the format can hold a joint of its `kind`: the defaults of the kind, then
/// every field the format has for it taken from `given` (the common fields too). Each
/// float goes through `float` with its element's name and whether the format forbids it
/// negative, which may refuse it.
pub(crate) fn canonical<E>(
    given: &Joint,
    kind: JointKind,
    mut float: impl FnMut(&str, f32, bool) -> Result<f32, E>,
) -> Result<Joint, E> {
    let mut joint = Joint {
        name: given.name,
        user_data: given.user_data,
        body_a: given.body_a,
        body_b: given.body_b,
        collide_connected: given.collide_connected,
        ..Joint::new(kind)
    };
    let mut source = *given;
    for element in &ELEMENTS {
        let name = element.name;
        let Some(Slot::Fills(value)) = element.slot(kind) else { continue };
        match value {
            Value::Vector(field) => {
                let v = *field(&mut source);
                *field(&mut joint) = Vec2::new(float(name, v.x, false)?, float(name, v.y, false)?);
            }
            Value::Float(field) => *field(&mut joint) = float(name, *field(&mut source), false)?,
            Value::NonNegative(field) => {
                *field(&mut joint) = float(name, *field(&mut source), true)?;
            }
            Value::Flag(field) => *field(&mut joint) = *field(&mut source),
            Value::JointIndex(field) => *field(&mut joint) = *field(&mut source),
        }
    }
    Ok(joint)
}

/// Whether `joint`, of `kind`, holds a value other than its kind's default in an element
/// that only a Version 2 file may hold in that kind (a weld's spring).
pub(crate) fn has_version_2_value(joint: &Joint, kind: JointKind) -> bool {
    let (mut given, mut default) = (*joint, Joint::new(kind));
    ELEMENTS
        .iter()
        .filter(|e| e.lowest_version(kind) >= 2)
        .filter_map(|e| e.field)
        .any(|f| f.value.differs(&mut given, &mut default))
}

#[cfg(test)]
mod tests;
