//! Scene -> the dialects that the engines' own readers read (Farseer 3.3.1, Farseer of July
//! 2013, Farseer 3.5 and Velcro, Aether.Physics2D): spec section 11. Those readers are not XML
//! parsers: they split the text at white space and `/ < > =`, read attributes by position,
//! give an omitted element 0 and split a vector at one space. So every field is written, the
//! read attributes first in the order read, each object on a line of its own in the
//! engines' element order, and nothing they cannot tokenise; what they cannot hold is refused
//! with an error naming the object.

use std::collections::HashMap;

use super::numbers::{integer_text, push_float};
use crate::error::{Code, Error, Position};
use crate::holds::escaped;
use crate::rules::local_axis;
use crate::scene::joints::{self, Element, Value};
use crate::scene::{Body, BodyKind, Dialect, Fixture, Joint, JointKind, KeptAt, Object};
use crate::scene::{Scene, Shape, ShapeKind, Vec2};

/// Writes `scene` in `dialect` (one of the engines' own).
pub(super) fn write(scene: &Scene, dialect: Dialect) -> Result<String, Error> {
    let target = Target::of(dialect);
    if let Some((object, why)) = cannot_hold(scene, dialect) {
        return Err(Error {
            code: Code::DialectCannotHold,
            position: Position::default(),
            message: format!(
                "{object} {why}, which the {} dialect's reader cannot hold, so the scene cannot be written in it",
                dialect.name()
            ),
        });
    }
    let shapes = WrittenShapes::of(scene);
    let mut w = FarseerWriter { out: String::new(), scene, target, shapes };
    w.document();
    Ok(w.out)
}

/// What sets one target apart from the others.
#[derive(Clone, Copy)]
struct Target {
    dialect: Dialect,
    /// Version 3: shapes carry the density, bodies list `Bindings`.
    version_3: bool,
}

impl Target {
    fn of(dialect: Dialect) -> Target {
        Target { dialect, version_3: matches!(dialect, Dialect::Farseer35 | Dialect::Aether) }
    }

    /// Farseer 3.3.1: no chains, no motor joint, sensors lost, `Line` with local axes.
    fn is_3_3(self) -> bool {
        self.dialect == Dialect::Farseer33
    }

    /// Whether the reader keeps a body of no joint asleep, as Farseer 3.3.1's and Aether's
    /// do (and Velcro's, which attaches no fixture); Farseer 2013's and 3.5's wake it.
    fn keeps_asleep(self) -> bool {
        matches!(self.dialect, Dialect::Farseer33 | Dialect::Aether)
    }
}

/// The first object `dialect` (one of the engines') cannot hold, and why.
fn cannot_hold(scene: &Scene, dialect: Dialect) -> Option<(Object, String)> {
    let target = Target::of(dialect);
    let index = |i: usize| i as u32;
    for kept in &scene.beyond.pieces {
        let text = scene.beyond.text(kept);
        if kept.place != KeptAt::Whole {
            return Some((kept.object, "holds comments or unknown content".to_owned()));
        }
        if text.contains("<!") || text.contains("<?") {
            return Some((kept.object, "holds a comment or a CDATA section".to_owned()));
        }
        if !target.is_3_3() && farseer_only_type(text) == "slider" {
            return Some((kept.object, "is a Slider joint".to_owned()));
        }
        let other = if target.dialect == Dialect::Aether { "<userdata" } else { "<tag" };
        if text.to_ascii_lowercase().contains(other) {
            return Some((kept.object, "has user data spelled for another reader".to_owned()));
        }
    }
    // Farseer computes a polygon's mass data only at a density above 0.
    let mut weighed = vec![false; scene.shapes().len()];
    for fixture in scene.fixtures() {
        if let Some(weighed) = weighed.get_mut(fixture.shape as usize) {
            *weighed |= fixture.density > 0.0;
        }
    }
    for (i, shape) in scene.shapes().iter().enumerate() {
        if let Some(why) = shape_cannot(scene, shape, weighed[i], target) {
            return Some((Object::Shape(index(i)), why));
        }
    }
    let mut bound = vec![false; scene.fixtures().len()];
    for &id in scene.bodies().iter().flat_map(|body| scene.body_fixtures(body)) {
        if let Some(bound) = bound.get_mut(id as usize) {
            *bound = true;
        }
    }
    for (i, fixture) in scene.fixtures().iter().enumerate() {
        let object = Object::Fixture(index(i));
        if target.version_3 && !bound[i] {
            // Left out, it would renumber the fixtures after it and say nothing.
            return Some((
                object,
                "is on no body (the reader makes a fixture only where a body's Pair binds one: it would be lost)".to_owned(),
            ));
        }
        if target.is_3_3() && fixture.is_sensor {
            return Some((object, "is a sensor".to_owned()));
        }
        let bits = [fixture.filter.category_bits, fixture.filter.mask_bits];
        if bits.iter().any(|&b| b > i32::MAX as u32) {
            return Some((object, "has filter bits above 31 (the reader reads an Int32)".into()));
        }
        if let Some(why) = user_data_cannot(scene, fixture.user_data) {
            return Some((object, why));
        }
    }
    let mut jointed = vec![false; scene.bodies().len()];
    for joint in scene.joints() {
        for body in [joint.body_a, joint.body_b] {
            if let Some(jointed) = jointed.get_mut(body as usize) {
                *jointed = true;
            }
        }
    }
    for (i, body) in scene.bodies().iter().enumerate() {
        if let Some(why) = body_cannot(body, jointed[i], target) {
            return Some((Object::Body(index(i)), why));
        }
    }
    for (i, joint) in scene.joints().iter().enumerate() {
        let why = joint_cannot(joint, target).or_else(|| user_data_cannot(scene, joint.user_data));
        if let Some(why) = why {
            return Some((Object::Joint(index(i)), why));
        }
    }
    None
}

/// Why `shape` cannot be written for `target`; `weighed` when a fixture of density above 0
/// uses it.
fn shape_cannot(scene: &Scene, shape: &Shape, weighed: bool, target: Target) -> Option<String> {
    let kind = shape.kind()?;
    let vertices = scene.vertices(shape);
    let segment = kind == ShapeKind::Polygon && vertices.len() == 2;
    let why = match kind {
        ShapeKind::Circle | ShapeKind::Edge | ShapeKind::Chain if !shape.name.is_null() => {
            "has a Name (an element this kind of shape may not hold there)"
        }
        ShapeKind::Polygon if segment && !shape.name.is_null() => {
            "is a named two-vertex polygon (written as an edge, which may not hold a Name)"
        }
        // Version 2 readers compute the centroid when the fixture's density is set, unless
        // it is 0: then the file's stays (Farseer's own files say `0 0` there).
        ShapeKind::Polygon
            if shape.centroid_given
                && !segment
                && !target.version_3
                && weighed
                && !is_centroid(vertices, shape.centroid) =>
        {
            "has a Centroid other than its own (the reader computes it)"
        }
        // Written as the edge it is, whose centroid every reader computes as its middle.
        ShapeKind::Polygon
            if segment && shape.centroid_given && !is_middle(vertices, shape.centroid) =>
        {
            "is a two-vertex polygon with a Centroid other than its middle (written as an edge, whose reader computes it)"
        }
        ShapeKind::Edge if shape.has_next_vertex => "has a Vertex3 ghost",
        ShapeKind::Chain if target.is_3_3() => "is a chain",
        ShapeKind::Chain if !shape.is_loop && vertices.first() == vertices.last() => {
            "is an open chain that ends where it starts (read as a loop)"
        }
        ShapeKind::Chain
            if !shape.is_loop
                && ((shape.has_prev_vertex && shape.prev_vertex == Vec2::ZERO)
                    || (shape.has_next_vertex && shape.next_vertex == Vec2::ZERO)) =>
        {
            "has a ghost vertex at exactly (0, 0) (read as no ghost)"
        }
        _ => return None,
    };
    Some(why.to_owned())
}

/// Whether `centroid` is the area centroid of the polygon `vertices`, to float precision.
fn is_centroid(vertices: &[Vec2], centroid: Vec2) -> bool {
    let (mut area, mut cx, mut cy) = (0.0f64, 0.0f64, 0.0f64);
    let origin = vertices[0];
    for (a, b) in vertices.iter().zip(vertices.iter().cycle().skip(1)) {
        let (ax, ay) = (f64::from(a.x - origin.x), f64::from(a.y - origin.y));
        let (bx, by) = (f64::from(b.x - origin.x), f64::from(b.y - origin.y));
        let cross = ax * by - ay * bx;
        area += cross / 2.0;
        (cx, cy) = (cx + cross * (ax + bx) / 6.0, cy + cross * (ay + by) / 6.0);
    }
    let size = vertices.iter().fold(1.0f64, |m, v| m.max(f64::from(v.x.abs().max(v.y.abs()))));
    let near =
        |c: f64, given: f32, o: f32| (c + f64::from(o) - f64::from(given)).abs() <= 1e-5 * size;
    area.abs() > 0.0
        && near(cx / area, centroid.x, origin.x)
        && near(cy / area, centroid.y, origin.y)
}

/// Whether `centroid` is the middle of the segment `vertices`, to float precision.
fn is_middle(vertices: &[Vec2], centroid: Vec2) -> bool {
    let size = vertices.iter().fold(1.0f64, |m, v| m.max(f64::from(v.x.abs().max(v.y.abs()))));
    let near = |a: f32, b: f32, given: f32| {
        ((f64::from(a) + f64::from(b)) / 2.0 - f64::from(given)).abs() <= 1e-5 * size
    };
    near(vertices[0].x, vertices[1].x, centroid.x) && near(vertices[0].y, vertices[1].y, centroid.y)
}

fn user_data_cannot(scene: &Scene, index: u32) -> Option<String> {
    let user_data = scene.user_data_at(index)?;
    let raw = scene.text(user_data.raw).unwrap_or_default();
    // The text runs between its tags, and the tags.
    let runs = || raw.split('<').map(|piece| piece.split_once('>').map_or(piece, |(_, text)| text));
    let tags =
        || raw.split('<').skip(1).map(|piece| piece.split_once('>').map_or(piece, |(tag, _)| tag));
    let why = match scene.text(user_data.type_name) {
        None => "has UserData not in the <Type>/<Value> form",
        Some(ty) if !raw.trim_start().starts_with(&format!("<Type>{ty}</Type>")) => {
            "has UserData whose <Type> is not its first element, exactly as named"
        }
        Some(_) if runs().any(|t| t.contains(['\t', '\r', '\n']) && !t.trim().is_empty()) => {
            "has UserData text with a raw tab or line break (the reader deletes them)"
        }
        Some(_) if raw.contains("<!") || raw.contains("<?") => {
            "has UserData holding a comment or a CDATA section"
        }
        Some(_) if tags().any(|tag| tag.contains('=')) => {
            "has UserData with attributes (the reader's tokenizer takes no such values)"
        }
        Some(_) => return None,
    };
    Some(why.to_owned())
}

/// Why `body` cannot be written for `target`; `jointed` when a joint names it.
fn body_cannot(body: &Body, jointed: bool, target: Target) -> Option<String> {
    let why = if body.gravity_scale.to_bits() != 1f32.to_bits() {
        "has a GravityScale"
    } else if body.inertia_scale.to_bits() != 1f32.to_bits() {
        "has an InertiaScale"
    } else {
        let m = body.mass_data;
        if m.mass_given || m.center_given || m.inertia_given {
            "has MassData"
        } else if !body.awake && !target.keeps_asleep() {
            "is asleep (the reader wakes it)"
        } else if !body.awake && jointed {
            "is asleep and in a joint (the reader wakes a joint's bodies as it sets the joint's fields)"
        } else {
            return None;
        }
    };
    Some(why.to_owned())
}

fn joint_cannot(joint: &Joint, target: Target) -> Option<String> {
    use JointKind::*;
    let why = match joint.kind()? {
        Gear => "is a gear joint",
        Motor if target.is_3_3() => "is a motor joint",
        Line if joint.enable_limit || joint.enable_motor => {
            "is a Box2D 2.1 line joint with a limit or a force motor (the reader's has neither)"
        }
        Weld if [joint.reference_angle, joint.frequency_hz, joint.damping_ratio]
            .iter()
            .any(|v| v.to_bits() != 0) =>
        {
            "is a weld joint with a ReferenceAngle or a spring (the reader reads only its anchors)"
        }
        Pulley
            if !target.is_3_3()
                && (joint.max_length_a.to_bits() != 0 || joint.max_length_b.to_bits() != 0) =>
        {
            "is a pulley with MaxLengthA or MaxLengthB"
        }
        _ => return None,
    };
    Some(why.to_owned())
}

/// The `Type` of a Farseer-only joint's text, lower case ("angle", "slider").
fn farseer_only_type(text: &str) -> String {
    let lower = text.to_ascii_lowercase();
    let after = lower.split_once("type").map_or("", |(_, rest)| rest);
    let value = after.trim_start_matches(|c: char| c == '=' || c.is_whitespace() || c == '"');
    value.chars().take_while(char::is_ascii_alphabetic).collect()
}

/// The shapes as written: the engines keep a density on the shape, so a shape that fixtures
/// of different densities share is written once per density (the first keeps its place, the
/// others follow the scene's shapes).
struct WrittenShapes {
    /// Per written shape: the scene's shape and its density.
    shapes: Vec<(u32, f32)>,
    /// Per fixture: its written shape.
    of_fixture: Vec<u32>,
}

impl WrittenShapes {
    fn of(scene: &Scene) -> WrittenShapes {
        let mut density: Vec<Option<f32>> = vec![None; scene.shapes().len()];
        let mut of_fixture = Vec::with_capacity(scene.fixtures().len());
        let mut extra: Vec<(u32, f32)> = Vec::new();
        // Each extra written shape by its scene shape and density bits: one look-up per
        // fixture, however many densities share a shape.
        let mut extra_at: HashMap<(u32, u32), u32> = HashMap::new();
        for fixture in scene.fixtures() {
            let own = density[fixture.shape as usize].get_or_insert(fixture.density);
            if own.to_bits() == fixture.density.to_bits() {
                of_fixture.push(fixture.shape);
                continue;
            }
            let key = (fixture.shape, fixture.density.to_bits());
            let at = *extra_at.entry(key).or_insert_with(|| {
                extra.push((fixture.shape, fixture.density));
                (extra.len() - 1) as u32
            });
            of_fixture.push(scene.shapes().len() as u32 + at);
        }
        let mut shapes: Vec<(u32, f32)> = Vec::with_capacity(density.len() + extra.len());
        for (s, d) in density.iter().enumerate() {
            shapes.push((s as u32, d.unwrap_or(0.0)));
        }
        shapes.extend(extra);
        WrittenShapes { shapes, of_fixture }
    }
}

struct FarseerWriter<'s> {
    out: String,
    scene: &'s Scene,
    target: Target,
    shapes: WrittenShapes,
}

impl FarseerWriter<'_> {
    fn document(&mut self) {
        let version = if self.target.version_3 { "3" } else { "2" };
        for piece in ["<World Version=\"", version, "\">\n"] {
            self.out.push_str(piece);
        }
        if let Some(gravity) = self.scene.gravity() {
            self.out.push_str("  ");
            self.vector("Gravity", gravity);
            self.out.push('\n');
        }
        let scene = self.scene;
        self.out.push_str("  <Shapes>\n");
        for i in 0..self.shapes.shapes.len() {
            let (shape, density) = self.shapes.shapes[i];
            self.shape(&scene.shapes()[shape as usize], density);
        }
        self.out.push_str("  </Shapes>\n  <Fixtures>\n");
        for (i, fixture) in scene.fixtures().iter().enumerate() {
            self.fixture(i, fixture);
        }
        self.out.push_str("  </Fixtures>\n  <Bodies>\n");
        for body in scene.bodies() {
            self.body(body);
        }
        self.out.push_str("  </Bodies>\n  <Joints>\n");
        for (i, joint) in scene.joints().iter().enumerate() {
            self.joint(i, joint);
        }
        self.out.push_str("  </Joints>\n</World>\n");
    }

    fn element(&mut self, name: &str, text: impl FnOnce(&mut String)) {
        for piece in ["<", name, ">"] {
            self.out.push_str(piece);
        }
        text(&mut self.out);
        for piece in ["</", name, ">"] {
            self.out.push_str(piece);
        }
    }

    fn vector(&mut self, name: &str, v: Vec2) {
        self.element(name, |out| {
            push_float(out, v.x);
            out.push(' ');
            push_float(out, v.y);
        });
    }

    fn number(&mut self, name: &str, value: f32) {
        self.element(name, |out| push_float(out, value));
    }

    fn integer(&mut self, name: &str, value: impl Into<i64>) {
        let value = value.into();
        self.element(name, |out| out.push_str(integer_text(value, &mut [0; 20])));
    }

    fn flag(&mut self, name: &str, value: bool) {
        self.element(name, |out| out.push_str(if value { "true" } else { "false" }));
    }

    fn name(&mut self, name: crate::scene::Str) {
        if let Some(text) = self.scene.text(name) {
            self.element("Name", |out| escaped(text, |piece| out.push_str(piece)));
        }
    }

    /// The user data on a line of its own, as `<UserData>` (`<Tag>` for Aether).
    fn user_data(&mut self, index: u32) {
        let Some(user_data) = self.scene.user_data_at(index) else { return };
        let raw = self.scene.text(user_data.raw).unwrap_or_default();
        let name = if self.target.dialect == Dialect::Aether { "Tag" } else { "UserData" };
        self.out.push_str("\n      ");
        self.element(name, |out| out.push_str(raw));
    }

    fn shape(&mut self, shape: &Shape, density: f32) {
        let vertices = self.scene.vertices(shape);
        let kind = match shape.kind().unwrap_or(ShapeKind::Circle) {
            // Box2D 2.1's SetAsEdge: a line segment, which the engines hold as an edge.
            ShapeKind::Polygon if vertices.len() == 2 => ShapeKind::Edge,
            kind => kind,
        };
        let ty = match kind {
            ShapeKind::Circle => "Circle",
            ShapeKind::Polygon => "Polygon",
            ShapeKind::Edge => "Edge",
            ShapeKind::Chain => "Chain",
        };
        for piece in ["    <Shape Type=\"", ty, "\""] {
            self.out.push_str(piece);
        }
        if self.target.version_3 {
            self.out.push_str(" Density=\"");
            push_float(&mut self.out, density);
            self.out.push('"');
        }
        self.out.push('>');
        match kind {
            ShapeKind::Circle => {
                self.number("Radius", shape.radius);
                self.vector("Position", shape.position);
            }
            ShapeKind::Polygon => {
                self.name(shape.name);
                self.vertices(vertices, None);
                if shape.centroid_given {
                    self.vector("Centroid", shape.centroid);
                }
            }
            ShapeKind::Edge => {
                self.vector("Vertex1", vertices[0]);
                self.vector("Vertex2", vertices[1]);
                if shape.has_prev_vertex {
                    self.flag("HasVertex0", true);
                    self.vector("Vertex0", shape.prev_vertex);
                }
            }
            ShapeKind::Chain if shape.is_loop => {
                // As the engines build a loop: the first vertex again at the end, the
                // neighbours of the seam as ghosts.
                self.vertices(vertices, vertices.first().copied());
                self.vector("NextVertex", vertices[1]);
                self.vector("PrevVertex", vertices[vertices.len() - 1]);
            }
            ShapeKind::Chain => {
                self.vertices(vertices, None);
                if shape.has_next_vertex {
                    self.vector("NextVertex", shape.next_vertex);
                }
                if shape.has_prev_vertex {
                    self.vector("PrevVertex", shape.prev_vertex);
                }
            }
        }
        self.out.push_str("</Shape>\n");
    }

    fn vertices(&mut self, vertices: &[Vec2], then: Option<Vec2>) {
        self.out.push_str("<Vertices>");
        for &v in vertices.iter().chain(then.as_ref()) {
            self.vector("Vertex", v);
        }
        self.out.push_str("</Vertices>");
    }

    fn fixture(&mut self, index: usize, fixture: &Fixture) {
        self.out.push_str("    <Fixture");
        if !self.target.is_3_3() {
            self.out.push_str(" Id=\"");
            self.out.push_str(integer_text(index as i64, &mut [0; 20]));
            self.out.push('"');
        }
        self.out.push('>');
        if !self.target.version_3 {
            self.integer("Shape", self.shapes.of_fixture[index]);
            self.number("Density", fixture.density);
        }
        self.name(fixture.name);
        self.out.push_str("<FilterData>");
        let filter = fixture.filter;
        self.integer("CategoryBits", filter.category_bits);
        self.integer("MaskBits", filter.mask_bits);
        self.integer("GroupIndex", filter.group_index);
        self.out.push_str("</FilterData>");
        self.number("Friction", fixture.friction);
        self.flag("IsSensor", fixture.is_sensor);
        self.number("Restitution", fixture.restitution);
        self.user_data(fixture.user_data);
        self.out.push_str("</Fixture>\n");
    }

    fn body(&mut self, body: &Body) {
        let ty = match body.kind().unwrap_or(BodyKind::Static) {
            BodyKind::Static => "Static",
            BodyKind::Kinematic => "Kinematic",
            BodyKind::Dynamic => "Dynamic",
        };
        // Farseer of 2013 reads its first attribute as an integer.
        let id = if self.target.dialect == Dialect::Farseer2013 { "Id=\"0\" " } else { "" };
        for piece in ["    <Body ", id, "Type=\"", ty, "\">\n      "] {
            self.out.push_str(piece);
        }
        self.name(body.name);
        self.flag("Active", body.active);
        self.flag("AllowSleep", body.allow_sleep);
        self.number("Angle", body.angle);
        self.number("AngularDamping", body.angular_damping);
        self.number("AngularVelocity", body.angular_velocity);
        self.flag("Awake", body.awake);
        self.flag("Bullet", body.bullet);
        self.flag("FixedRotation", body.fixed_rotation);
        self.number("LinearDamping", body.linear_damping);
        self.vector("LinearVelocity", body.linear_velocity);
        self.vector("Position", body.position);
        self.user_data(body.user_data);
        self.out.push_str("\n      ");
        let ids = self.scene.body_fixtures(body);
        match (self.target.version_3, ids.is_empty()) {
            (false, true) => self.out.push_str("<Fixtures />"),
            (true, true) => self.out.push_str("<Bindings />"),
            (false, false) => {
                self.out.push_str("<Fixtures>");
                for &id in ids {
                    self.integer("ID", id);
                }
                self.out.push_str("</Fixtures>");
            }
            (true, false) => {
                self.out.push_str("<Bindings>");
                for &id in ids {
                    let shape = self.shapes.of_fixture[id as usize];
                    let mut buffer = [0; 20];
                    for piece in ["<Pair FixtureId=\"", integer_text(id.into(), &mut buffer)] {
                        self.out.push_str(piece);
                    }
                    for piece in ["\" ShapeId=\"", integer_text(shape.into(), &mut buffer), "\" />"]
                    {
                        self.out.push_str(piece);
                    }
                }
                self.out.push_str("</Bindings>");
            }
        }
        self.out.push_str("\n    </Body>\n");
    }

    /// The axis of a prismatic or wheel joint as the target reads it: Farseer 3.3.1 in body
    /// A's frame, the later ones in world coordinates.
    fn axis(&mut self, index: usize, joint: &Joint, local_name: &str) {
        if self.target.is_3_3() {
            self.vector(local_name, joint.local_axis_a);
            return;
        }
        let kept = self.scene.beyond.world_axes.iter().find(|&&(j, _)| j as usize == index);
        let angle = self.scene.bodies()[joint.body_a as usize].angle;
        let world = match kept {
            Some(&(_, world)) => world,
            None => world_axis(joint.local_axis_a, angle),
        };
        self.vector("Axis", world);
    }

    /// An element of the joint table, from the field it fills in `joint`.
    fn field(&mut self, name: &str, value: Value, joint: &mut Joint) {
        match value {
            Value::Vector(at) => self.vector(name, *at(joint)),
            Value::Float(at) | Value::NonNegative(at) => self.number(name, *at(joint)),
            Value::Flag(at) => self.flag(name, *at(joint)),
            Value::JointIndex(at) => self.integer(name, *at(joint)),
        }
    }

    fn joint(&mut self, index: usize, joint: &Joint) {
        let kept = self.scene.beyond.of(Object::Joint(index as u32));
        if let Some(whole) = kept.iter().find(|k| k.place == KeptAt::Whole) {
            self.out.push_str("    ");
            self.out.push_str(self.scene.beyond.text(whole));
            self.out.push('\n');
            return;
        }
        use JointKind::*;
        let kind = joint.kind().unwrap_or(Revolute);
        let ty = match kind {
            Line if self.target.is_3_3() => "Line",
            Line | Wheel if !self.target.is_3_3() => "Wheel",
            Wheel => "Line",
            _ => joints::type_name(kind),
        };
        for piece in ["    <Joint Type=\"", ty, "\">"] {
            self.out.push_str(piece);
        }
        self.integer("BodyA", joint.body_a);
        self.integer("BodyB", joint.body_b);
        self.flag("CollideConnected", joint.collide_connected);
        if !joint.name.is_null() {
            self.out.push_str("\n      ");
            self.name(joint.name);
        }
        self.user_data(joint.user_data);
        self.out.push_str("\n      ");
        let mut fields = *joint;
        for &part in parts(kind, self.target) {
            match part {
                Part::Element(name, value) => self.field(name, value, &mut fields),
                Part::Axis(local_name) => self.axis(index, joint, local_name),
                Part::Constant => {
                    self.number("Constant", joint.length_a + joint.ratio * joint.length_b)
                }
            }
        }
        self.out.push_str("</Joint>\n");
    }
}

/// An element of a joint as the engines' readers read it.
#[derive(Clone, Copy)]
enum Part {
    /// An element of the joint table, by its name, with the field it fills.
    Element(&'static str, Value),
    /// The axis of a prismatic or wheel joint: in body A's frame under this name for Farseer
    /// 3.3.1, as the table's element of that name; for the later ones in world coordinates.
    Axis(&'static str),
    /// The pulley's `Constant`, `LengthA + Ratio * LengthB`, which box2scene reads and drops.
    Constant,
}

/// The joint table's element `name`, which must fill a field (checked when compiling).
const fn e(name: &str) -> Part {
    match joints::named(name) {
        Some(Element { name, field: Some(field), .. }) => Part::Element(name, field.value),
        _ => panic!("the joint table has no element of that name that fills a field"),
    }
}

const REVOLUTE: &[Part] = &[
    e("EnableLimit"),
    e("EnableMotor"),
    e("LocalAnchorA"),
    e("LocalAnchorB"),
    e("LowerAngle"),
    e("MaxMotorTorque"),
    e("MotorSpeed"),
    e("ReferenceAngle"),
    e("UpperAngle"),
];
const PRISMATIC: &[Part] = &[
    e("EnableLimit"),
    e("EnableMotor"),
    e("LocalAnchorA"),
    e("LocalAnchorB"),
    Part::Axis("LocalXAxis1"),
    e("LowerTranslation"),
    e("UpperTranslation"),
    e("MaxMotorForce"),
    e("MotorSpeed"),
    e("ReferenceAngle"),
];
const DISTANCE: &[Part] =
    &[e("DampingRatio"), e("FrequencyHz"), e("Length"), e("LocalAnchorA"), e("LocalAnchorB")];
const PULLEY_3_3: &[Part] = &[
    e("GroundAnchorA"),
    e("GroundAnchorB"),
    e("LengthA"),
    e("LengthB"),
    e("LocalAnchorA"),
    e("LocalAnchorB"),
    e("MaxLengthA"),
    e("MaxLengthB"),
    e("Ratio"),
];
const PULLEY: &[Part] = &[
    e("WorldAnchorA"),
    e("WorldAnchorB"),
    e("LengthA"),
    e("LengthB"),
    e("LocalAnchorA"),
    e("LocalAnchorB"),
    e("Ratio"),
    Part::Constant,
];
/// A wheel joint, and a line joint, which these readers know only as a wheel joint.
const WHEEL: &[Part] = &[
    e("EnableMotor"),
    e("LocalAnchorA"),
    e("LocalAnchorB"),
    e("MotorSpeed"),
    e("DampingRatio"),
    e("MaxMotorTorque"),
    e("FrequencyHz"),
    Part::Axis("LocalXAxis"),
];
const WELD: &[Part] = &[e("LocalAnchorA"), e("LocalAnchorB")];
const FRICTION: &[Part] = &[e("LocalAnchorA"), e("LocalAnchorB"), e("MaxForce"), e("MaxTorque")];
const ROPE: &[Part] = &[e("LocalAnchorA"), e("LocalAnchorB"), e("MaxLength")];
const MOTOR: &[Part] =
    &[e("AngularOffset"), e("LinearOffset"), e("MaxForce"), e("MaxTorque"), e("CorrectionFactor")];

/// The elements of a joint of `kind` after the common ones, in the order `target` reads
/// them. A gear joint is never written (no target holds one), nor one of the unsupported
/// kind (its kept text is).
fn parts(kind: JointKind, target: Target) -> &'static [Part] {
    use JointKind::*;
    match kind {
        Revolute => REVOLUTE,
        Prismatic => PRISMATIC,
        Distance => DISTANCE,
        Pulley if target.is_3_3() => PULLEY_3_3,
        Pulley => PULLEY,
        Line | Wheel => WHEEL,
        Weld => WELD,
        Friction => FRICTION,
        Rope => ROPE,
        Motor => MOTOR,
        Gear | Unsupported => &[],
    }
}

/// The world axis, in f32, that a reader turning it by minus `angle` (as box2scene's and
/// Farseer's do) reads back as exactly `local`, when one lies within a few steps of the
/// rounded turn; else the rounded turn.
fn world_axis(local: Vec2, angle: f32) -> Vec2 {
    let (sin, cos) = (f64::from(angle).sin(), f64::from(angle).cos());
    let (x, y) = (f64::from(local.x), f64::from(local.y));
    let rounded = Vec2::new((cos * x - sin * y) as f32, (sin * x + cos * y) as f32);
    let step = |v: f32, k: i32| {
        let bits = v.to_bits() as i64 + if v < 0.0 { -i64::from(k) } else { i64::from(k) };
        f32::from_bits(bits.clamp(0, u32::MAX.into()) as u32)
    };
    for dx in [0, -1, 1, -2, 2, -3, 3] {
        for dy in [0, -1, 1, -2, 2, -3, 3] {
            let candidate = Vec2::new(step(rounded.x, dx), step(rounded.y, dy));
            let back = local_axis(candidate, angle);
            if back.x.to_bits() == local.x.to_bits() && back.y.to_bits() == local.y.to_bits() {
                return candidate;
            }
        }
    }
    rounded
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_element_written_for_a_kind_is_one_that_kind_reads() {
        let kinds = (0..).map_while(|n| JointKind::try_from(n).ok());
        for (kind, dialect) in kinds.flat_map(|k| Dialect::ALL.map(|d| (k, d))) {
            for part in parts(kind, Target::of(dialect)) {
                let name = match *part {
                    Part::Element(name, _) | Part::Axis(name) => name,
                    Part::Constant => "Constant",
                };
                let element = joints::named(name).expect("an element of the table");
                assert!(element.read_by.contains(kind), "{name} in {kind:?}");
            }
        }
    }
}
