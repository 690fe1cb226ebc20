//! Building a scene from records, as a host does to save its level: the records the loader
//! produces, checked with the loader's rules (same codes and messages, the object's index
//! instead of a line), finished into an ordinary immutable scene.
//!
//! What is added is made canonical, so that the writer writes it and the loader reads it
//! back unchanged: names are trimmed of XML white space (as the loader trims them), fields
//! that the format does not have for an object's kind take that kind's defaults, and
//! UserData gets the raw XML and the type name and value the loader would find in it.
//! What a written file could not hold, or a load with the default options would refuse
//! from it, is refused at the call: a character XML does not allow, a name longer than a
//! load reads in one text, UserData that is not well-formed or nests too deep.
#![forbid(unsafe_code)]

use crate::error::{Code, Error, Finding, Parsed, Position, Problem, problem};
use crate::holds::{escape, needs_version_2, writable_text};
use crate::markup::{USER_DATA_DEPTH, user_data_fragment};
use crate::options::LoadOptions;
use crate::rules;
use crate::scene::joints;
use crate::scene::{
    Body, Fixture, Joint, JointKind, NONE, Object, PoolStr, Range, Scene, SceneBuilder,
};
use crate::scene::{Shape, ShapeKind, Str, UserDataText, Vec2};
use crate::text::trim_xml;

/// A scene under construction. Objects refer to objects added before them.
#[derive(Default)]
pub struct Builder {
    scene: SceneBuilder,
}

/// The error for object `index` of `what` ("shape", "fixture", ...).
fn refused(what: &str, index: usize, why: &Finding) -> Error {
    let message = format!("{what} {index}: {}", why.message);
    Error { code: why.code, position: Position::default(), message }
}

/// An index of a container of `count` objects, or the loader's `id-out-of-range` error.
fn reference(index: u32, count: usize, names: &str, what: &str) -> Parsed<()> {
    match (index as usize) < count {
        true => Ok(()),
        false => Err(problem(
            Code::IdOutOfRange,
            0,
            format!("names {what} {index}, but the scene has {count} {names}"),
        )),
    }
}

/// An index `index` of a container of `count` objects that exists, or the error for
/// object `index` of `what`.
fn existing(index: u32, count: usize, what: &str) -> Result<usize, Error> {
    match (index as usize) < count {
        true => Ok(index as usize),
        false => {
            let why = format!("there is no {what} {index}: the scene has {count}");
            Err(refused(what, index as usize, &Finding::new(Code::IdOutOfRange, 0, why)))
        }
    }
}

/// The error for taking out object `index` of `what` while `by` refers to it.
fn still_referred(what: &str, index: usize, by: String) -> Error {
    let why = format!("{by} refers to it; replace or take that out first");
    refused(what, index, &Finding::new(Code::InvalidArgument, 0, why))
}

impl Builder {
    /// An empty builder.
    pub fn new() -> Builder {
        Builder::default()
    }

    /// A builder holding everything `scene` holds (but its diagnostics), the text its file
    /// held beyond the records too: comments, unknown elements and attributes, Farseer-only
    /// joints. Records added, replaced or taken out change only themselves, so the scene
    /// it finishes writes every such text of the records left unchanged, as `fmt` does.
    pub fn from_scene(scene: &Scene) -> Builder {
        Builder { scene: SceneBuilder::thaw(scene) }
    }

    /// The gravity, or none (the host decides).
    pub fn set_gravity(&mut self, gravity: Option<Vec2>) -> Result<(), Error> {
        if let Some(g) = gravity {
            rules::finite("Gravity", &[g.x, g.y]).map_err(|e| refused("world", 0, &e))?;
        }
        self.scene.gravity = gravity;
        Ok(())
    }

    fn name(&mut self, name: Option<&str>) -> Option<PoolStr> {
        name.map(|n| self.scene.add_str(trim_xml(n)))
    }

    /// Refuses a name that a written file could not hold or read back.
    fn check_name(name: Option<&str>) -> Parsed<()> {
        name.map_or(Ok(()), |n| writable_text("its Name", trim_xml(n)))
    }

    fn user_data_reference(&self, index: u32) -> Parsed<()> {
        match index {
            NONE => Ok(()),
            _ => reference(index, self.scene.user_data.len(), "user data", "user data"),
        }
    }

    fn warn(&mut self, what: &str, index: usize, code: Code, message: &str) {
        let message = format!("{what} {index}: {message}");
        self.scene.push_warning(code, Position::default(), &message);
    }

    /// Adds user data and returns its index. `raw` is XML content, kept verbatim; without
    /// it, a type name and value are written in the editor's form. Either is refused
    /// unless the loader, with its default options, would read it back from a written file.
    pub fn add_user_data(
        &mut self,
        raw: Option<&str>,
        type_name: Option<&str>,
        value: Option<&str>,
    ) -> Result<u32, Error> {
        let index = self.scene.user_data.len();
        let raw = match (raw, type_name) {
            (Some(raw), _) => raw.to_owned(),
            (None, Some(type_name)) => format!(
                "<Type>{}</Type><Value><string>{}</string></Value>",
                escape(trim_xml(type_name)),
                escape(trim_xml(value.unwrap_or_default()))
            ),
            (None, None) if value.is_some() => {
                let why = "a UserData value needs a type name (or raw XML)".to_owned();
                return Err(refused(
                    "user data",
                    index,
                    &Finding::new(Code::InvalidArgument, 0, why),
                ));
            }
            (None, None) => String::new(),
        };
        let (type_name, value) = user_data_fragment(&raw, USER_DATA_DEPTH)
            .map_err(|e| refused("user data", index, &e))?;
        let user_data = UserDataText {
            raw: self.scene.add_str(&raw),
            type_name: type_name.map(|t| self.scene.add_str(&t)),
            value: value.map(|v| self.scene.add_str(&v)),
        };
        self.scene.user_data.push(user_data);
        Ok(index as u32)
    }

    /// Adds a shape with `vertices` (polygons, edges, chains) and returns its index.
    pub fn add_shape(
        &mut self,
        shape: &Shape,
        name: Option<&str>,
        vertices: &[Vec2],
    ) -> Result<u32, Error> {
        self.put_shape(self.scene.shapes.len(), shape, name, vertices)
    }

    /// Replaces shape `index`, checked as [`Builder::add_shape`] checks a new one.
    pub fn replace_shape(
        &mut self,
        index: u32,
        shape: &Shape,
        name: Option<&str>,
        vertices: &[Vec2],
    ) -> Result<(), Error> {
        let index = existing(index, self.scene.shapes.len(), "shape")?;
        self.put_shape(index, shape, name, vertices).map(drop)
    }

    /// Takes out shape `index`, which no fixture may use; the shapes after it move down.
    pub fn remove_shape(&mut self, index: u32) -> Result<(), Error> {
        let at = existing(index, self.scene.shapes.len(), "shape")?;
        if let Some(f) = self.scene.fixtures.iter().position(|f| f.shape == index) {
            return Err(still_referred("shape", at, format!("fixture {f}")));
        }
        self.scene.shapes.remove(at);
        for f in &mut self.scene.fixtures {
            f.shape -= u32::from(f.shape > index && f.shape != NONE);
        }
        self.scene.taken_out(Object::Shape(index));
        Ok(())
    }

    /// Adds (`index` is the count) or replaces shape `index`.
    fn put_shape(
        &mut self,
        index: usize,
        shape: &Shape,
        name: Option<&str>,
        vertices: &[Vec2],
    ) -> Result<u32, Error> {
        let canonical = Self::check_name(name)
            .and_then(|()| self.check_shape(index, shape, vertices))
            .map_err(|e| refused("shape", index, &e))?;
        let first = self.scene.vertices.len();
        self.scene.vertices.extend_from_slice(vertices);
        let vertices = Range::between(first, self.scene.vertices.len());
        let name = self.name(name);
        let shape = Shape { name: Str::NULL, vertices, ..canonical };
        match self.scene.shapes.get_mut(index) {
            Some(old) => {
                *old = shape;
                self.scene.replaced(Object::Shape(index as u32), name);
            }
            None => self.scene.push_shape(shape, name),
        }
        Ok(index as u32)
    }

    fn check_shape(&mut self, index: usize, shape: &Shape, vertices: &[Vec2]) -> Parsed<Shape> {
        let kind = shape.kind().ok_or_else(|| -> Problem {
            problem(Code::InvalidArgument, 0, format!("unknown shape kind {}", shape.kind))
        })?;
        let points: Vec<f32> = vertices.iter().flat_map(|v| [v.x, v.y]).collect();
        rules::finite("Vertex", &points)?;
        let mut canonical = Shape::new(kind);
        let geometry = match kind {
            ShapeKind::Circle => {
                rules::finite("Radius", &[shape.radius])?;
                rules::finite("Position", &[shape.position.x, shape.position.y])?;
                (canonical.radius, canonical.position) = (shape.radius, shape.position);
                if !vertices.is_empty() {
                    return Err(problem(Code::BadVertexCount, 0, "a circle has no vertices"));
                }
                rules::circle(shape.radius, 0)?;
                None
            }
            ShapeKind::Polygon => {
                if shape.centroid_given {
                    rules::finite("Centroid", &[shape.centroid.x, shape.centroid.y])?;
                    (canonical.centroid, canonical.centroid_given) = (shape.centroid, true);
                }
                rules::polygon(vertices, 0)?
            }
            ShapeKind::Edge | ShapeKind::Chain => {
                let ghosts = [
                    shape.prev_vertex.x,
                    shape.prev_vertex.y,
                    shape.next_vertex.x,
                    shape.next_vertex.y,
                ];
                rules::finite("Vertex0", &ghosts)?;
                canonical.prev_vertex = shape.prev_vertex;
                canonical.next_vertex = shape.next_vertex;
                canonical.has_prev_vertex = shape.has_prev_vertex;
                canonical.has_next_vertex = shape.has_next_vertex;
                match kind {
                    ShapeKind::Edge if vertices.len() != 2 => {
                        return Err(problem(
                            Code::BadVertexCount,
                            0,
                            format!("an edge has 2 vertices, not {}", vertices.len()),
                        ));
                    }
                    ShapeKind::Edge => rules::edge(vertices, 0)?,
                    _ => {
                        let most = LoadOptions::default().max_chain_vertices as usize;
                        if vertices.len() > most {
                            return Err(problem(
                                Code::LimitExceeded,
                                0,
                                format!("a chain has at most {most} vertices (max_chain_vertices)"),
                            ));
                        }
                        canonical.is_loop = shape.is_loop;
                        rules::chain(vertices, shape.is_loop, 0)?
                    }
                }
            }
        };
        if let Some(warning) = geometry {
            self.warn("shape", index, warning.code, &warning.message);
        }
        Ok(canonical)
    }

    /// Adds a fixture on an already added shape and returns its index.
    pub fn add_fixture(&mut self, fixture: &Fixture, name: Option<&str>) -> Result<u32, Error> {
        self.put_fixture(self.scene.fixtures.len(), fixture, name)
    }

    /// Replaces fixture `index`, checked as [`Builder::add_fixture`] checks a new one.
    pub fn replace_fixture(
        &mut self,
        index: u32,
        fixture: &Fixture,
        name: Option<&str>,
    ) -> Result<(), Error> {
        let index = existing(index, self.scene.fixtures.len(), "fixture")?;
        self.put_fixture(index, fixture, name).map(drop)
    }

    /// Takes out fixture `index`, which no body may hold; the fixtures after it move down.
    pub fn remove_fixture(&mut self, index: u32) -> Result<(), Error> {
        let at = existing(index, self.scene.fixtures.len(), "fixture")?;
        let ids = &self.scene.fixture_ids;
        if let Some(b) =
            self.scene.bodies.iter().position(|b| ids[b.fixtures.indices()].contains(&index))
        {
            return Err(still_referred("fixture", at, format!("body {b}")));
        }
        self.scene.fixtures.remove(at);
        for id in &mut self.scene.fixture_ids {
            *id -= u32::from(*id > index);
        }
        self.scene.taken_out(Object::Fixture(index));
        Ok(())
    }

    /// Adds (`index` is the count) or replaces fixture `index`.
    fn put_fixture(
        &mut self,
        index: usize,
        fixture: &Fixture,
        name: Option<&str>,
    ) -> Result<u32, Error> {
        Self::check_name(name)
            .and_then(|()| self.check_fixture(fixture))
            .map_err(|e| refused("fixture", index, &e))?;
        let name = self.name(name);
        let fixture = Fixture { name: Str::NULL, ..*fixture };
        match self.scene.fixtures.get_mut(index) {
            Some(old) => {
                *old = fixture;
                self.scene.replaced(Object::Fixture(index as u32), name);
            }
            None => self.scene.push_fixture(fixture, name),
        }
        Ok(index as u32)
    }

    fn check_fixture(&self, f: &Fixture) -> Parsed<()> {
        reference(f.shape, self.scene.shapes.len(), "shapes", "shape")?;
        for (name, value) in
            [("Density", f.density), ("Friction", f.friction), ("Restitution", f.restitution)]
        {
            rules::finite(name, &[value])?;
            rules::not_negative(format_args!("<{name}>"), value, 0)?;
        }
        self.user_data_reference(f.user_data)
    }

    /// Adds a body with already added `fixtures` and returns its index.
    pub fn add_body(
        &mut self,
        body: &Body,
        name: Option<&str>,
        fixtures: &[u32],
    ) -> Result<u32, Error> {
        self.put_body(self.scene.bodies.len(), body, name, fixtures)
    }

    /// Replaces body `index`, checked as [`Builder::add_body`] checks a new one.
    pub fn replace_body(
        &mut self,
        index: u32,
        body: &Body,
        name: Option<&str>,
        fixtures: &[u32],
    ) -> Result<(), Error> {
        let index = existing(index, self.scene.bodies.len(), "body")?;
        self.put_body(index, body, name, fixtures).map(drop)
    }

    /// Takes out body `index`, which no joint may join; the bodies after it move down.
    pub fn remove_body(&mut self, index: u32) -> Result<(), Error> {
        let at = existing(index, self.scene.bodies.len(), "body")?;
        if let Some(j) =
            self.scene.joints.iter().position(|j| j.body_a == index || j.body_b == index)
        {
            return Err(still_referred("body", at, format!("joint {j}")));
        }
        self.scene.bodies.remove(at);
        for j in &mut self.scene.joints {
            j.body_a -= u32::from(j.body_a > index && j.body_a != NONE);
            j.body_b -= u32::from(j.body_b > index && j.body_b != NONE);
        }
        self.scene.taken_out(Object::Body(index));
        Ok(())
    }

    /// Adds (`index` is the count) or replaces body `index`.
    fn put_body(
        &mut self,
        index: usize,
        body: &Body,
        name: Option<&str>,
        fixtures: &[u32],
    ) -> Result<u32, Error> {
        let canonical = Self::check_name(name)
            .and_then(|()| self.check_body(body, fixtures))
            .map_err(|e| refused("body", index, &e))?;
        let first = self.scene.fixture_ids.len();
        self.scene.fixture_ids.extend_from_slice(fixtures);
        let fixtures = Range::between(first, self.scene.fixture_ids.len());
        let name = self.name(name);
        let canonical = Body { name: Str::NULL, fixtures, ..canonical };
        match self.scene.bodies.get_mut(index) {
            Some(old) => {
                *old = canonical;
                self.scene.replaced(Object::Body(index as u32), name);
            }
            None => self.scene.push_body(canonical, name),
        }
        if let Some(message) =
            rules::zero_density(&canonical, &self.scene.fixture_ids, &self.scene.fixtures)
        {
            self.warn("body", index, Code::DynamicBodyZeroDensity, &message);
        }
        Ok(index as u32)
    }

    fn check_body(&self, b: &Body, fixtures: &[u32]) -> Parsed<Body> {
        let kind = b.kind().ok_or_else(|| -> Problem {
            problem(Code::InvalidArgument, 0, format!("unknown body kind {}", b.kind))
        })?;
        let floats = [
            ("Position", b.position.x),
            ("Position", b.position.y),
            ("Angle", b.angle),
            ("LinearVelocity", b.linear_velocity.x),
            ("LinearVelocity", b.linear_velocity.y),
            ("AngularVelocity", b.angular_velocity),
            ("LinearDamping", b.linear_damping),
            ("AngularDamping", b.angular_damping),
            ("GravityScale", b.gravity_scale),
            ("InertiaScale", b.inertia_scale),
        ];
        for (name, value) in floats {
            rules::finite(name, &[value])?;
        }
        let mut mass = Body::new(kind).mass_data;
        let m = b.mass_data;
        if m.mass_given {
            rules::finite("Mass", &[m.mass])?;
            rules::not_negative("<Mass>", m.mass, 0)?;
            (mass.mass, mass.mass_given) = (m.mass, true);
        }
        if m.center_given {
            rules::finite("Center", &[m.center.x, m.center.y])?;
            (mass.center, mass.center_given) = (m.center, true);
        }
        if m.inertia_given {
            rules::finite("Inertia", &[m.inertia])?;
            rules::not_negative("<Inertia>", m.inertia, 0)?;
            (mass.inertia, mass.inertia_given) = (m.inertia, true);
        }
        for &id in fixtures {
            reference(id, self.scene.fixtures.len(), "fixtures", "fixture")?;
        }
        self.user_data_reference(b.user_data)?;
        Ok(Body { mass_data: mass, ..*b })
    }

    /// Adds a joint between already added bodies (a gear: after its two joints) and
    /// returns its index. Farseer-only (unsupported) joints cannot be built.
    pub fn add_joint(&mut self, joint: &Joint, name: Option<&str>) -> Result<u32, Error> {
        self.put_joint(self.scene.joints.len(), joint, name)
    }

    /// Replaces joint `index`, checked as [`Builder::add_joint`] checks a new one; a joint
    /// a gear couples stays a revolute or prismatic joint.
    pub fn replace_joint(
        &mut self,
        index: u32,
        joint: &Joint,
        name: Option<&str>,
    ) -> Result<(), Error> {
        let at = existing(index, self.scene.joints.len(), "joint")?;
        let coupled = !matches!(joint.kind(), Some(JointKind::Revolute | JointKind::Prismatic));
        if let Some(gear) = self.gear_of(index).filter(|_| coupled) {
            return Err(still_referred("joint", at, format!("gear joint {gear}")));
        }
        self.put_joint(at, joint, name).map(drop)
    }

    /// Takes out joint `index`, which no gear may couple; the joints after it move down.
    pub fn remove_joint(&mut self, index: u32) -> Result<(), Error> {
        let at = existing(index, self.scene.joints.len(), "joint")?;
        if let Some(gear) = self.gear_of(index) {
            return Err(still_referred("joint", at, format!("gear joint {gear}")));
        }
        self.scene.joints.remove(at);
        for j in &mut self.scene.joints {
            j.joint_a -= u32::from(j.joint_a > index && j.joint_a != NONE);
            j.joint_b -= u32::from(j.joint_b > index && j.joint_b != NONE);
        }
        self.scene.taken_out(Object::Joint(index));
        Ok(())
    }

    /// The first gear joint that couples joint `index`.
    fn gear_of(&self, index: u32) -> Option<usize> {
        let gear = |j: &Joint| j.kind() == Some(JointKind::Gear);
        self.scene.joints.iter().position(|j| gear(j) && (j.joint_a == index || j.joint_b == index))
    }

    /// Adds (`index` is the count) or replaces joint `index`.
    fn put_joint(&mut self, index: usize, joint: &Joint, name: Option<&str>) -> Result<u32, Error> {
        let canonical = Self::check_name(name)
            .and_then(|()| self.check_joint(joint))
            .map_err(|e| refused("joint", index, &e))?;
        let name = self.name(name);
        let joint = Joint { name: Str::NULL, ..canonical };
        match self.scene.joints.get_mut(index) {
            Some(old) => {
                *old = joint;
                self.scene.replaced(Object::Joint(index as u32), name);
            }
            None => self.scene.push_joint(joint, name),
        }
        Ok(index as u32)
    }

    fn check_joint(&self, joint: &Joint) -> Parsed<Joint> {
        if joint.kind() == Some(JointKind::Unsupported) {
            return Err(problem(
                Code::InvalidArgument,
                0,
                "Farseer-only joints have no Box2Scene form and cannot be built",
            ));
        }
        let kind = joint.kind().ok_or_else(|| -> Problem {
            problem(Code::InvalidArgument, 0, format!("unknown joint kind {}", joint.kind))
        })?;
        // Fails on a non-finite value, or a negative one where the format forbids it,
        // naming the element.
        let canonical = joints::canonical(joint, kind, |name, v, non_negative| {
            rules::finite(name, &[v])?;
            match non_negative {
                true => rules::not_negative(format_args!("<{name}>"), v, 0),
                false => Ok(v),
            }
        })?;
        reference(canonical.body_a, self.scene.bodies.len(), "bodies", "body")?;
        reference(canonical.body_b, self.scene.bodies.len(), "bodies", "body")?;
        rules::joint(&canonical, 0, 0)?;
        if canonical.kind() == Some(JointKind::Gear) {
            for target in [canonical.joint_a, canonical.joint_b] {
                let kind = self.scene.joints.get(target as usize).and_then(Joint::kind);
                if !matches!(kind, Some(JointKind::Revolute | JointKind::Prismatic)) {
                    let count = self.scene.joints.len();
                    return Err(problem(
                        Code::BadGearJoint,
                        0,
                        format!(
                            "the gear names joint {target} (the scene has {count} joints); a gear couples two revolute or prismatic joints added before it"
                        ),
                    ));
                }
            }
        }
        self.user_data_reference(canonical.user_data)?;
        Ok(canonical)
    }

    /// The finished, immutable scene, with the version the writer would give it.
    pub fn finish(self) -> Scene {
        let mut scene = self.scene.freeze();
        // A loaded scene's version stays, unless what was added needs a later one.
        scene.version = scene.version.max(if needs_version_2(&scene) { 2 } else { 1 });
        scene
    }
}
