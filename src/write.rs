//! Scene -> Box2Scene XML (spec section 11). What it writes reads back to the identical
//! scene: every float bit for bit, every name, every UserData text.
#![forbid(unsafe_code)]

use std::fmt::Write as _;

use crate::scene::{Body, BodyKind, Filter, Fixture, Joint, JointKind, NONE, Scene, Shape};
use crate::scene::{ShapeKind, Str, Vec2};

/// How to write.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WriteOptions {
    /// Write every field of the file's version, even those equal to their defaults.
    /// Default false: omit them, as the original editor did.
    pub all_fields: bool,
}

/// The joints [`write`] leaves out: Farseer-only joints, which have no Box2Scene form.
pub fn joints_not_written(scene: &Scene) -> Vec<u32> {
    (0..scene.joints().len() as u32)
        .filter(|&i| scene.joints()[i as usize].kind() == Some(JointKind::Unsupported))
        .collect()
}

/// Writes `scene` as a Box2Scene file: `Version="1"` when it uses only Version 1
/// constructs, else `Version="2"`. Farseer-only joints are left out (see
/// [`joints_not_written`]) and gear joints' references renumbered to match.
pub fn write(scene: &Scene, options: &WriteOptions) -> String {
    let version = if needs_version_2(scene) { 2 } else { 1 };
    let mut w = Writer { out: String::new(), depth: 0, scene, all: options.all_fields, version };
    w.out.push_str("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n");
    w.open(&format!("World Version=\"{version}\""));
    if let Some(gravity) = scene.gravity() {
        w.vector("Gravity", gravity);
    }
    w.container("Shapes", scene.shapes(), Writer::shape);
    w.container("Fixtures", scene.fixtures(), Writer::fixture);
    w.container("Bodies", scene.bodies(), Writer::body);
    let renumbered = written_joint_indices(scene);
    let joints: Vec<Joint> = scene
        .joints()
        .iter()
        .filter(|j| j.kind() != Some(JointKind::Unsupported))
        .map(|&j| Joint {
            joint_a: renumber(&renumbered, j.joint_a),
            joint_b: renumber(&renumbered, j.joint_b),
            ..j
        })
        .collect();
    w.container("Joints", &joints, Writer::joint);
    w.close("World");
    w.out
}

/// Per joint, its index among the joints that are written.
fn written_joint_indices(scene: &Scene) -> Vec<u32> {
    let mut next = 0;
    scene
        .joints()
        .iter()
        .map(|j| {
            let index = next;
            next += u32::from(j.kind() != Some(JointKind::Unsupported));
            index
        })
        .collect()
}

fn renumber(renumbered: &[u32], index: u32) -> u32 {
    renumbered.get(index as usize).copied().unwrap_or(index)
}

pub(crate) fn needs_version_2(scene: &Scene) -> bool {
    let shape = |s: &Shape| matches!(s.kind(), Some(ShapeKind::Edge | ShapeKind::Chain));
    let body = |b: &Body| b.gravity_scale.to_bits() != 1f32.to_bits();
    let joint = |j: &Joint| match j.kind() {
        Some(JointKind::Wheel | JointKind::Rope | JointKind::Motor) => true,
        Some(JointKind::Weld) => j.frequency_hz.to_bits() != 0 || j.damping_ratio.to_bits() != 0,
        _ => false,
    };
    scene.shapes().iter().any(shape)
        || scene.bodies().iter().any(body)
        || scene.joints().iter().any(joint)
}

/// The shortest text that reads back to the same f32: plain decimals for ordinary
/// magnitudes, an exponent for tiny and huge ones (as .NET wrote `8.369571E-36`).
pub(crate) fn float_text(value: f32) -> String {
    let mut text = String::new();
    push_float(&mut text, value);
    text
}

/// Appends [`float_text`] of `value` to `out`.
fn push_float(out: &mut String, value: f32) {
    let magnitude = value.abs();
    let _ = if magnitude == 0.0 || (1e-5..1e16).contains(&magnitude) {
        write!(out, "{value}")
    } else {
        write!(out, "{value:e}")
    };
}

/// Text content and attribute values: markup characters as entities, characters XML
/// would change on reading (carriage returns) as character references.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\r' => out.push_str("&#13;"),
            c => out.push(c),
        }
    }
    out
}

struct Writer<'s> {
    out: String,
    depth: usize,
    scene: &'s Scene,
    all: bool,
    version: u32,
}

impl Writer<'_> {
    fn indent(&mut self) {
        for _ in 0..self.depth {
            self.out.push_str("  ");
        }
    }

    /// `<tag>` on its own line; `tag` may carry attributes.
    fn open(&mut self, tag: &str) {
        self.indent();
        let _ = writeln!(self.out, "<{tag}>");
        self.depth += 1;
    }

    fn close(&mut self, name: &str) {
        self.depth -= 1;
        self.indent();
        let _ = writeln!(self.out, "</{name}>");
    }

    fn element(&mut self, name: &str, text: &str) {
        if text.is_empty() {
            self.indent();
            for piece in ["<", name, " />\n"] {
                self.out.push_str(piece);
            }
        } else {
            self.element_with(name, |out| out.push_str(text));
        }
    }

    /// `<name>text</name>` on its own line, `text` written straight into the output.
    fn element_with(&mut self, name: &str, text: impl FnOnce(&mut String)) {
        self.indent();
        for piece in ["<", name, ">"] {
            self.out.push_str(piece);
        }
        text(&mut self.out);
        for piece in ["</", name, ">\n"] {
            self.out.push_str(piece);
        }
    }

    fn container<T>(&mut self, name: &str, items: &[T], write_item: fn(&mut Self, &T)) {
        if items.is_empty() {
            return self.element(name, "");
        }
        self.open(name);
        for item in items {
            write_item(self, item);
        }
        self.close(name);
    }

    fn vector(&mut self, name: &str, v: Vec2) {
        self.element_with(name, |out| {
            push_float(out, v.x);
            out.push(' ');
            push_float(out, v.y);
        });
    }

    fn name(&mut self, name: Str) {
        if let Some(text) = self.scene.text(name) {
            self.element("Name", &escape(text));
        }
    }

    /// The optional elements: written when asked for every field or when the value's bits
    /// differ from the default's (so -0.0 and 0.0 stay apart).
    fn float(&mut self, name: &str, value: f32, default: f32) {
        if self.all || value.to_bits() != default.to_bits() {
            self.element_with(name, |out| push_float(out, value));
        }
    }

    fn vector_or_default(&mut self, name: &str, value: Vec2, default: Vec2) {
        if self.all
            || value.x.to_bits() != default.x.to_bits()
            || value.y.to_bits() != default.y.to_bits()
        {
            self.vector(name, value);
        }
    }

    fn flag(&mut self, name: &str, value: bool, default: bool) {
        if self.all || value != default {
            self.element(name, if value { "true" } else { "false" });
        }
    }

    fn user_data(&mut self, index: u32) {
        let Some(user_data) = self.scene.user_data_at(index) else { return };
        let raw = self.scene.text(user_data.raw).unwrap_or_default();
        self.indent();
        let _ = writeln!(self.out, "<UserData>{raw}</UserData>");
    }

    fn shape(&mut self, shape: &Shape) {
        let kind = shape.kind().unwrap_or(ShapeKind::Circle);
        let ty = match (kind, shape.is_loop) {
            (ShapeKind::Circle, _) => "Circle",
            (ShapeKind::Polygon, _) => "Polygon",
            (ShapeKind::Edge, _) => "Edge",
            (ShapeKind::Chain, false) => "Chain",
            (ShapeKind::Chain, true) => "Loop",
        };
        self.open(&format!("Shape Type=\"{ty}\""));
        self.name(shape.name);
        let vertices = self.scene.vertices(shape);
        let zero = Vec2::ZERO;
        match kind {
            ShapeKind::Circle => {
                self.element("Radius", &float_text(shape.radius));
                self.vector("Position", shape.position);
            }
            ShapeKind::Polygon | ShapeKind::Chain => {
                self.open("Vertices");
                for &v in vertices {
                    self.vector("Vertex", v);
                }
                self.close("Vertices");
            }
            ShapeKind::Edge => {
                self.vector("Vertex1", vertices[0]);
                self.vector("Vertex2", vertices[1]);
            }
        }
        match kind {
            ShapeKind::Polygon if shape.centroid_given => self.vector("Centroid", shape.centroid),
            ShapeKind::Edge => {
                self.vector_or_default("Vertex0", shape.prev_vertex, zero);
                self.vector_or_default("Vertex3", shape.next_vertex, zero);
                self.flag("HasVertex0", shape.has_prev_vertex, false);
                self.flag("HasVertex3", shape.has_next_vertex, false);
            }
            ShapeKind::Chain => {
                self.vector_or_default("PrevVertex", shape.prev_vertex, zero);
                self.vector_or_default("NextVertex", shape.next_vertex, zero);
                self.flag("HasPrevVertex", shape.has_prev_vertex, false);
                self.flag("HasNextVertex", shape.has_next_vertex, false);
            }
            _ => {}
        }
        self.close("Shape");
    }

    fn fixture(&mut self, fixture: &Fixture) {
        let defaults = Fixture::default();
        self.open("Fixture");
        self.element("Shape", &fixture.shape.to_string());
        self.name(fixture.name);
        self.float("Density", fixture.density, defaults.density);
        self.float("Friction", fixture.friction, defaults.friction);
        self.float("Restitution", fixture.restitution, defaults.restitution);
        self.flag("IsSensor", fixture.is_sensor, defaults.is_sensor);
        self.filter(&fixture.filter);
        self.user_data(fixture.user_data);
        self.close("Fixture");
    }

    fn filter(&mut self, filter: &Filter) {
        let defaults = Filter::default();
        if !self.all && *filter == defaults {
            return;
        }
        self.open("FilterData");
        for (name, value, default) in [
            ("CategoryBits", filter.category_bits, defaults.category_bits),
            ("MaskBits", filter.mask_bits, defaults.mask_bits),
        ] {
            if self.all || value != default {
                self.element(name, &value.to_string());
            }
        }
        if self.all || filter.group_index != defaults.group_index {
            self.element("GroupIndex", &filter.group_index.to_string());
        }
        self.close("FilterData");
    }

    fn body(&mut self, body: &Body) {
        let kind = body.kind().unwrap_or(BodyKind::Static);
        let d = Body::new(kind);
        let ty = match kind {
            BodyKind::Static => "Static",
            BodyKind::Kinematic => "Kinematic",
            BodyKind::Dynamic => "Dynamic",
        };
        self.open(&format!("Body Type=\"{ty}\""));
        self.name(body.name);
        self.flag("Active", body.active, d.active);
        self.flag("AllowSleep", body.allow_sleep, d.allow_sleep);
        self.float("Angle", body.angle, d.angle);
        self.float("AngularDamping", body.angular_damping, d.angular_damping);
        self.float("AngularVelocity", body.angular_velocity, d.angular_velocity);
        self.flag("Awake", body.awake, d.awake);
        self.flag("Bullet", body.bullet, d.bullet);
        self.flag("FixedRotation", body.fixed_rotation, d.fixed_rotation);
        if self.version >= 2 {
            self.float("GravityScale", body.gravity_scale, d.gravity_scale);
        }
        self.float("InertiaScale", body.inertia_scale, d.inertia_scale);
        self.float("LinearDamping", body.linear_damping, d.linear_damping);
        self.vector_or_default("LinearVelocity", body.linear_velocity, d.linear_velocity);
        self.vector_or_default("Position", body.position, d.position);
        let m = body.mass_data;
        if m.mass_given || m.center_given || m.inertia_given {
            self.open("MassData");
            if m.mass_given {
                self.element("Mass", &float_text(m.mass));
            }
            if m.center_given {
                self.vector("Center", m.center);
            }
            if m.inertia_given {
                self.element("Inertia", &float_text(m.inertia));
            }
            self.close("MassData");
        }
        let ids: Vec<String> = self.scene.body_fixtures(body).iter().map(u32::to_string).collect();
        if ids.is_empty() {
            self.element("Fixtures", "");
        } else {
            self.open("Fixtures");
            for id in &ids {
                self.element("ID", id);
            }
            self.close("Fixtures");
        }
        self.user_data(body.user_data);
        self.close("Body");
    }

    fn joint(&mut self, joint: &Joint) {
        let kind = joint.kind().unwrap_or(JointKind::Revolute);
        let d = Joint::new(kind);
        self.open(&format!("Joint Type=\"{kind:?}\""));
        self.name(joint.name);
        self.element("BodyA", &joint.body_a.to_string());
        self.element("BodyB", &joint.body_b.to_string());
        self.flag("CollideConnected", joint.collide_connected, d.collide_connected);
        use JointKind::*;
        let is = |kinds: &[JointKind]| kinds.contains(&kind);
        if !is(&[Gear, Motor]) {
            self.vector_or_default("LocalAnchorA", joint.local_anchor_a, d.local_anchor_a);
            self.vector_or_default("LocalAnchorB", joint.local_anchor_b, d.local_anchor_b);
        }
        if is(&[Prismatic, Line, Wheel]) {
            self.vector_or_default("LocalAxisA", joint.local_axis_a, d.local_axis_a);
        }
        if is(&[Revolute, Prismatic, Weld]) {
            self.float("ReferenceAngle", joint.reference_angle, d.reference_angle);
        }
        if is(&[Revolute, Prismatic, Line]) {
            self.flag("EnableLimit", joint.enable_limit, d.enable_limit);
            let (lower, upper) = if kind == Revolute {
                ("LowerAngle", "UpperAngle")
            } else {
                ("LowerTranslation", "UpperTranslation")
            };
            self.float(lower, joint.lower_limit, d.lower_limit);
            self.float(upper, joint.upper_limit, d.upper_limit);
        }
        if is(&[Revolute, Prismatic, Line, Wheel]) {
            self.flag("EnableMotor", joint.enable_motor, d.enable_motor);
            self.float("MotorSpeed", joint.motor_speed, d.motor_speed);
        }
        if is(&[Revolute, Wheel]) {
            self.float("MaxMotorTorque", joint.max_motor_torque, d.max_motor_torque);
        }
        if is(&[Prismatic, Line]) {
            self.float("MaxMotorForce", joint.max_motor_force, d.max_motor_force);
        }
        if kind == Distance {
            self.float("Length", joint.length, d.length);
        }
        if is(&[Distance, Wheel]) || (kind == Weld && self.version >= 2) {
            self.float("FrequencyHz", joint.frequency_hz, d.frequency_hz);
            self.float("DampingRatio", joint.damping_ratio, d.damping_ratio);
        }
        if kind == Pulley {
            self.vector_or_default("GroundAnchorA", joint.ground_anchor_a, d.ground_anchor_a);
            self.vector_or_default("GroundAnchorB", joint.ground_anchor_b, d.ground_anchor_b);
            self.float("LengthA", joint.length_a, d.length_a);
            self.float("LengthB", joint.length_b, d.length_b);
            self.float("MaxLengthA", joint.max_length_a, d.max_length_a);
            self.float("MaxLengthB", joint.max_length_b, d.max_length_b);
        }
        if kind == Gear && joint.joint_a != NONE {
            self.element("JointA", &joint.joint_a.to_string());
            self.element("JointB", &joint.joint_b.to_string());
        }
        if is(&[Pulley, Gear]) {
            self.float("Ratio", joint.ratio, d.ratio);
        }
        if is(&[Friction, Motor]) {
            self.float("MaxForce", joint.max_force, d.max_force);
            self.float("MaxTorque", joint.max_torque, d.max_torque);
        }
        if kind == Rope {
            self.float("MaxLength", joint.max_length, d.max_length);
        }
        if kind == Motor {
            self.vector_or_default("LinearOffset", joint.linear_offset, d.linear_offset);
            self.float("AngularOffset", joint.angular_offset, d.angular_offset);
            self.float("CorrectionFactor", joint.correction_factor, d.correction_factor);
        }
        self.user_data(joint.user_data);
        self.close("Joint");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_are_shortest_and_read_back_to_the_same_bits() {
        for (value, text) in [
            (1.0f32, "1"),
            (0.2, "0.2"),
            (-1.2345679, "-1.2345679"),
            (-0.0, "-0"),
            (8.369571e-36, "8.369571e-36"),
            (f32::MAX, "3.4028235e38"),
            (f32::from_bits(1), "1e-45"),
            (1e-5, "0.00001"),
        ] {
            assert_eq!(float_text(value), text);
            assert_eq!(crate::text::float(text).unwrap().to_bits(), value.to_bits(), "{text}");
        }
    }

    #[test]
    fn text_escapes_markup_and_carriage_returns() {
        assert_eq!(escape("a<b & \"c\">\r\né"), "a&lt;b &amp; &quot;c&quot;&gt;&#13;\né");
    }
}
