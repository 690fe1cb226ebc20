//! box2scene's own dialect: the document, each record's elements (defaults left out unless
//! every field is asked for), and the kept text put back in its places.

use std::borrow::Cow;

use super::numbers::{integer_text, push_float};
use crate::containers::Container;
use crate::error::{Code, Error, Position};
use crate::holds::escaped;
use crate::scene::Object;
use crate::scene::joints::{self, Value};
use crate::scene::{Body, BodyKind, Filter, Fixture, Joint, JointKind, Kept, NONE};
use crate::scene::{KeptAt, Scene, Shape, ShapeKind, Str, Vec2};

/// How many items `container` holds.
fn count(scene: &Scene, container: Container) -> usize {
    match container {
        Container::Shapes => scene.shapes().len(),
        Container::Fixtures => scene.fixtures().len(),
        Container::Bodies => scene.bodies().len(),
        Container::Joints => scene.joints().len(),
    }
}

/// The error for the first Farseer-only joint whose user data its file gave in a `<Tag>`
/// written otherwise than `<Tag>...</Tag>`: this dialect reads only `<UserData>`, and
/// [`user_data_spelled`] respells only that form.
pub(super) fn tags_respellable(scene: &Scene) -> Result<(), Error> {
    for kept in &scene.beyond.pieces {
        let (Object::Joint(joint), KeptAt::Whole) = (kept.object, kept.place) else { continue };
        let text = scene.beyond.text(kept);
        let tagged = tagged_user_data(scene, joint, text).is_some_and(|t| !text.contains(&t));
        if tagged {
            return Err(Error {
                code: Code::DialectCannotHold,
                position: Position::default(),
                message: format!(
                    "{} is a Farseer-only joint whose user data is in a <Tag> not written as `<Tag>...</Tag>`, which the box2scene dialect does not read as user data and the writer cannot respell, so the scene cannot be written in it",
                    kept.object
                ),
            });
        }
    }
    Ok(())
}

/// `<Tag>RAW</Tag>` for a joint whose user data, of text RAW, its file gave in a `<Tag>`
/// (a Version 3 file's joint with no `<UserData>`).
fn tagged_user_data(scene: &Scene, joint: u32, text: &str) -> Option<String> {
    let user_data = scene.user_data_at(scene.joints()[joint as usize].user_data)?;
    let raw = scene.text(user_data.raw).unwrap_or_default();
    let lower = text.to_ascii_lowercase();
    (opens(&lower, "<tag") && !opens(&lower, "<userdata")).then(|| format!("<Tag>{raw}</Tag>"))
}

/// Whether `text` holds a start tag `<name` (lower case) of exactly that name.
fn opens(text: &str, start: &str) -> bool {
    let ends_name = |rest: &str| rest.starts_with(['>', '/', ' ', '\t', '\r', '\n']);
    text.match_indices(start).any(|(at, _)| ends_name(&text[at + start.len()..]))
}

/// A Farseer-only joint's whole text, with the user data its file gave in Aether's `<Tag>`
/// written as `<UserData>`, which this dialect reads (`tags_respellable` has checked that
/// the `<Tag>` is spelled so).
fn user_data_spelled<'t>(scene: &Scene, joint: u32, text: &'t str) -> Cow<'t, str> {
    match tagged_user_data(scene, joint, text) {
        Some(tagged) if text.contains(&tagged) => {
            let inner = &tagged["<Tag>".len()..tagged.len() - "</Tag>".len()];
            Cow::Owned(text.replacen(&tagged, &format!("<UserData>{inner}</UserData>"), 1))
        }
        _ => Cow::Borrowed(text),
    }
}

pub(super) struct Writer<'s> {
    pub(super) out: String,
    pub(super) depth: usize,
    pub(super) scene: &'s Scene,
    pub(super) all: bool,
    pub(super) version: u32,
    /// The kept text of the world, and of the item being written.
    pub(super) world: Scope<'s>,
    pub(super) item: Option<Scope<'s>>,
}

/// An object being written (the world or an item) and the text its file held beyond the
/// records, with which of it is written so far.
pub(super) struct Scope<'s> {
    kept: &'s [Kept],
    written: Vec<bool>,
    /// The depth of the object's children.
    depth: usize,
    /// The child open now, whose children are being written ("" for none).
    within: &'static str,
}

impl<'s> Scope<'s> {
    pub(super) fn new(kept: &'s [Kept], depth: usize) -> Scope<'s> {
        Scope { kept, written: vec![false; kept.len()], depth, within: "" }
    }

    /// Whether some of the text goes inside the child `name`, which is then written even
    /// when all its values are defaults.
    fn has_within(&self, name: &str) -> bool {
        self.kept.iter().any(|k| matches!(k.place, KeptAt::Inside { within, .. } if within == name))
    }
}

impl<'s> Writer<'s> {
    fn scope(&mut self) -> &mut Scope<'s> {
        self.item.as_mut().unwrap_or(&mut self.world)
    }

    /// Writes the kept text of the current object at the places `wanted` selects, unless
    /// it was written: attributes as they are, the rest on lines of their own.
    fn put(&mut self, wanted: impl Fn(KeptAt) -> bool) {
        let kept = self.scope().kept;
        for (i, k) in kept.iter().enumerate() {
            if self.scope().written[i] || !wanted(k.place) {
                continue;
            }
            self.scope().written[i] = true;
            let text = self.scene.beyond.text(k);
            let text = match (k.object, k.place) {
                (Object::Joint(joint), KeptAt::Whole) => user_data_spelled(self.scene, joint, text),
                _ => Cow::Borrowed(text),
            };
            if k.place != KeptAt::Attribute {
                self.indent();
            }
            self.out.push_str(&text);
            if k.place != KeptAt::Attribute {
                self.out.push('\n');
            }
        }
    }

    /// Before an element `name` of the current object, or of its child open now: the
    /// kept text that preceded it.
    fn before(&mut self, name: &str) {
        let depth = self.depth;
        let scope = self.scope();
        // Above the object (its own start tag, or the world's) nothing of it goes before.
        let within = match depth.checked_sub(scope.depth) {
            Some(0) => "",
            Some(1) => scope.within,
            _ => return,
        };
        self.put(|at| matches!(at, KeptAt::Inside { within: w, before } if w == within && before == name));
    }

    /// Writes `object` (an item of a container) with `write`, or as its kept whole text,
    /// with the kept text before it.
    fn item(&mut self, object: Object, write: impl FnOnce(&mut Self)) {
        let kept = self.scene.beyond.of(object);
        self.item = Some(Scope::new(kept, self.depth + 1));
        self.put(|at| at == KeptAt::Before);
        if kept.iter().any(|k| k.place == KeptAt::Whole) {
            self.put(|at| at == KeptAt::Whole);
        } else {
            write(self);
        }
        self.item = None;
    }

    /// The whole text: the world's start tag, its gravity, its containers and their
    /// items, and its end tag, each with the kept text around it.
    pub(super) fn document(&mut self) {
        self.put(|at| at == KeptAt::Before);
        self.open_typed("World", "Version", if self.version == 2 { "2" } else { "1" });
        if let Some(gravity) = self.scene.gravity() {
            self.vector("Gravity", gravity);
        }
        let scene = self.scene;
        for container in Container::ALL {
            let (name, count) = (container.name(), count(scene, container));
            if count == 0 && !self.world.has_within(name) {
                self.element(name, "");
                continue;
            }
            self.open(name);
            for i in 0..count {
                let index = i as u32;
                match container {
                    Container::Shapes => {
                        self.item(Object::Shape(index), |w| w.shape(&scene.shapes()[i]))
                    }
                    Container::Fixtures => {
                        self.item(Object::Fixture(index), |w| w.fixture(&scene.fixtures()[i]))
                    }
                    Container::Bodies => {
                        self.item(Object::Body(index), |w| w.body(&scene.bodies()[i]))
                    }
                    Container::Joints => {
                        self.item(Object::Joint(index), |w| w.joint(&scene.joints()[i]))
                    }
                }
            }
            self.close(name);
        }
        self.close("World");
        self.put(|at| at == KeptAt::After);
    }

    fn indent(&mut self) {
        const SPACES: &str = "                ";
        let mut width = 2 * self.depth;
        while width > 0 {
            let piece = &SPACES[..width.min(SPACES.len())];
            self.out.push_str(piece);
            width -= piece.len();
        }
    }

    /// `<name>` on its own line.
    fn open(&mut self, name: &'static str) {
        self.open_with(name, |_| {});
    }

    /// `<name Type="value">` on its own line.
    fn open_typed(&mut self, name: &'static str, attribute: &str, value: &str) {
        self.open_with(name, |out| {
            for piece in [" ", attribute, "=\"", value, "\""] {
                out.push_str(piece);
            }
        });
    }

    /// `<name ...>` on its own line; the object's own start tag gets its kept attributes,
    /// and a child of the object is the one open now.
    fn open_with(&mut self, name: &'static str, attributes: impl FnOnce(&mut String)) {
        self.before(name);
        self.indent();
        self.out.push('<');
        self.out.push_str(name);
        attributes(&mut self.out);
        if self.depth + 1 == self.scope().depth {
            self.put(|at| at == KeptAt::Attribute);
        }
        self.out.push_str(">\n");
        self.depth += 1;
        let depth = self.depth;
        let scope = self.scope();
        if depth == scope.depth + 1 {
            scope.within = name;
        }
    }

    /// `</name>` on its own line, after the kept text that ended the element: for a child
    /// of the object, all of it that goes inside; for an item, whatever of it was not
    /// written yet (what preceded an element that was not written goes at the end).
    fn close(&mut self, name: &'static str) {
        let depth = self.scope().depth;
        if self.depth == depth + 1 {
            self.put(|at| matches!(at, KeptAt::Inside { within, .. } if within == name));
            self.scope().within = "";
        } else if self.depth == depth && self.item.is_some() {
            self.put(|at| matches!(at, KeptAt::Inside { .. }));
        } else if self.depth == depth {
            self.put(|at| at == KeptAt::Inside { within: "", before: "" });
        }
        self.depth -= 1;
        self.indent();
        for piece in ["</", name, ">\n"] {
            self.out.push_str(piece);
        }
    }

    fn element(&mut self, name: &str, text: &str) {
        if text.is_empty() {
            self.before(name);
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
        self.before(name);
        self.indent();
        for piece in ["<", name, ">"] {
            self.out.push_str(piece);
        }
        text(&mut self.out);
        for piece in ["</", name, ">\n"] {
            self.out.push_str(piece);
        }
    }

    fn vector(&mut self, name: &str, v: Vec2) {
        self.element_with(name, |out| {
            push_float(out, v.x);
            out.push(' ');
            push_float(out, v.y);
        });
    }

    fn name(&mut self, name: Str) {
        match self.scene.text(name) {
            Some("") => self.element("Name", ""),
            Some(text) => {
                self.element_with("Name", |out| escaped(text, |piece| out.push_str(piece)))
            }
            None => {}
        }
    }

    fn number(&mut self, name: &str, value: f32) {
        self.element_with(name, |out| push_float(out, value));
    }

    fn integer(&mut self, name: &str, value: impl Into<i64>) {
        let value = value.into();
        self.element_with(name, |out| out.push_str(integer_text(value, &mut [0; 20])));
    }

    /// The optional elements: written when asked for every field or when the value's bits
    /// differ from the default's (so -0.0 and 0.0 stay apart).
    fn float(&mut self, name: &str, value: f32, default: f32) {
        if self.all || value.to_bits() != default.to_bits() {
            self.number(name, value);
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
        self.before("UserData");
        self.indent();
        for piece in ["<UserData>", raw, "</UserData>\n"] {
            self.out.push_str(piece);
        }
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
        self.open_typed("Shape", "Type", ty);
        self.name(shape.name);
        let vertices = self.scene.vertices(shape);
        let zero = Vec2::ZERO;
        match kind {
            ShapeKind::Circle => {
                self.number("Radius", shape.radius);
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
        self.integer("Shape", fixture.shape);
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
        if !self.all && *filter == defaults && !self.scope().has_within("FilterData") {
            return;
        }
        self.open("FilterData");
        for (name, value, default) in [
            ("CategoryBits", filter.category_bits, defaults.category_bits),
            ("MaskBits", filter.mask_bits, defaults.mask_bits),
        ] {
            if self.all || value != default {
                self.integer(name, value);
            }
        }
        if self.all || filter.group_index != defaults.group_index {
            self.integer("GroupIndex", filter.group_index);
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
        self.open_typed("Body", "Type", ty);
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
        if m.mass_given || m.center_given || m.inertia_given || self.scope().has_within("MassData")
        {
            self.open("MassData");
            if m.mass_given {
                self.number("Mass", m.mass);
            }
            if m.center_given {
                self.vector("Center", m.center);
            }
            if m.inertia_given {
                self.number("Inertia", m.inertia);
            }
            self.close("MassData");
        }
        let ids = self.scene.body_fixtures(body);
        if ids.is_empty() {
            self.element("Fixtures", "");
        } else {
            self.open("Fixtures");
            for &id in ids {
                self.integer("ID", id);
            }
            self.close("Fixtures");
        }
        self.user_data(body.user_data);
        self.close("Body");
    }

    fn joint(&mut self, joint: &Joint) {
        let kind = joint.kind().unwrap_or(JointKind::Revolute);
        let d = Joint::new(kind);
        self.open_with("Joint", |out| {
            for piece in [" Type=\"", joints::type_name(kind), "\""] {
                out.push_str(piece);
            }
        });
        self.name(joint.name);
        self.integer("BodyA", joint.body_a);
        self.integer("BodyB", joint.body_b);
        self.flag("CollideConnected", joint.collide_connected, d.collide_connected);
        let (mut given, mut default) = (*joint, d);
        for element in joints::written(kind) {
            let Some(field) = element.field else { continue };
            if element.lowest_version(kind) > self.version {
                continue;
            }
            let name = element.name;
            match field.value {
                Value::Vector(at) => {
                    self.vector_or_default(name, *at(&mut given), *at(&mut default))
                }
                Value::Float(at) | Value::NonNegative(at) => {
                    self.float(name, *at(&mut given), *at(&mut default))
                }
                Value::Flag(at) => self.flag(name, *at(&mut given), *at(&mut default)),
                Value::JointIndex(at) if *at(&mut given) != NONE => {
                    self.integer(name, *at(&mut given))
                }
                Value::JointIndex(_) => {}
            }
        }
        self.user_data(joint.user_data);
        self.close("Joint");
    }
}
