//! The pass over the held records into a scene, the same for every engine: each body with
//! its fixtures in creation order, equal shapes and fixtures written once, the joints in
//! creation order (given the level, in the scene's, with the ones the build skipped back
//! in their places), the labels (the host's, else the level's), and what is not written
//! and why. A family (`box2d2/`, `box2d3/`) turns one held record into the scene's and
//! says what it loses through [`Say`].

use std::collections::HashMap;
use std::fmt;

use super::box2d2;
use super::box2d3;
use super::level::{Level, is_gear};
use super::{Captured, Held, HeldBody, HeldJoint, HeldShape, Label};
use crate::builder::Builder;
use crate::error::{Code, Error};
use crate::plan::box2d2::Version;
use crate::plan::box2d3::V3;
use crate::plan::{Object, Plan};
use crate::scene::{Body, Fixture, Joint, NONE, Shape, Vec2};

/// The engine family a capture is made by, and its version.
#[derive(Clone, Copy, Debug)]
pub(super) enum Family {
    /// Box2D 2.3 or 2.4.
    Box2d2(&'static Version),
    /// Box2D v3.1 or v3.2.
    Box2d3(V3),
}

impl Family {
    /// The scene shape (no name) and its vertices for one held shape, or for a v3 chain's
    /// run of segments; `None`: not written (reported).
    fn shape(
        self,
        run: &[HeldShape],
        points: &[Vec2],
        say: &mut Say,
    ) -> Option<(Shape, Vec<Vec2>)> {
        match self {
            Family::Box2d2(version) => box2d2::shape(version, &run[0], points, say),
            Family::Box2d3(v3) => box2d3::shape(v3, run, points, say),
        }
    }

    /// How many of `rest`, a body's held shapes from a chain's first segment on, make that
    /// chain: the ones that share its `chain`, and of v3.2's loose segments those that
    /// continue one another.
    fn chain_length(self, rest: &[HeldShape], points: &[Vec2]) -> usize {
        match self {
            Family::Box2d2(_) => rest.iter().take_while(|s| s.chain == rest[0].chain).count(),
            Family::Box2d3(v3) => box2d3::chain_length(v3, rest, points),
        }
    }

    /// The scene fixture (no name, shape or UserData) of a held shape's material.
    fn fixture(self, held: &HeldShape, say: &mut Say) -> Fixture {
        match self {
            Family::Box2d2(version) => box2d2::fixture(version, held, say),
            Family::Box2d3(_) => box2d3::fixture(held, say),
        }
    }

    /// The scene body (no name, fixtures or UserData) of a held body, given its held shapes
    /// that are written (in creation order) and the level's body.
    fn body(
        self,
        held: &HeldBody,
        shapes: &[HeldShape],
        points: &[Vec2],
        level: Option<&Body>,
        say: &mut Say,
    ) -> Body {
        match self {
            Family::Box2d2(version) => box2d2::body(version, held, shapes, points, level, say),
            Family::Box2d3(v3) => box2d3::body(v3, held, shapes, points),
        }
    }

    /// What the family says once of all the held bodies, after them (on the world): v3's
    /// solver turns nearly every body it moves to a rotation no angle gives exactly.
    fn bodies_done(self, bodies: &[HeldBody], say: &mut Say) {
        match self {
            Family::Box2d2(_) => {}
            Family::Box2d3(_) => box2d3::turned(bodies, say),
        }
    }

    /// Whether what is not written is said as the Box2D v3 adapter always said it (its
    /// tests hold it): all of it `lossy-capture`, a fixture whose shape has no form not
    /// said again, and a joint's index counting the joints written before it. The 2.x
    /// adapter's says each with its own code and counts the held joints.
    fn v3_reports(self) -> bool {
        matches!(self, Family::Box2d3(_))
    }

    /// Whether equal shapes and equal fixtures are written once. The Box2D v3 adapter
    /// always wrote each engine shape as its own shape and fixture (its tests count them).
    fn writes_equal_once(self) -> bool {
        matches!(self, Family::Box2d2(_))
    }

    /// The scene joint (no bodies, joints, name or UserData) of a held joint between its
    /// two held bodies, given the level's joint; `None`: not written (reported).
    fn joint(
        self,
        held: &HeldJoint,
        a: &HeldBody,
        b: &HeldBody,
        level: Option<&Joint>,
        say: &mut Say,
    ) -> Option<Joint> {
        match self {
            Family::Box2d2(version) => box2d2::joint(version, held, a, b, level, say),
            Family::Box2d3(v3) => box2d3::joint(v3, held, a, level, say),
        }
    }
}

/// One report, before its texts go to the result.
#[derive(Debug)]
struct Said {
    code: Code,
    object: Object,
    index: u32,
    name: Option<String>,
    message: String,
}

/// Where a family says what it loses about one object: the report's object, its index
/// among the held objects of that kind and its name are the pass's.
pub(crate) struct Say<'s> {
    said: &'s mut Vec<Said>,
    object: Object,
    index: u32,
    name: Option<&'s str>,
}

impl Say<'_> {
    /// A value the format cannot hold exactly, written as near as it can.
    pub(crate) fn lossy(&mut self, message: fmt::Arguments<'_>) {
        self.report(Code::LossyCapture, message);
    }

    /// A report of `code`.
    pub(crate) fn report(&mut self, code: Code, message: fmt::Arguments<'_>) {
        self.said.push(Said {
            code,
            object: self.object,
            index: self.index,
            name: self.name.map(str::to_owned),
            message: fmt::format(message),
        });
    }
}

/// The capture of `held` by `family`, labelled from `level` where given.
pub(super) fn capture(
    held: &Held<'_>,
    level: Option<&crate::scene::Scene>,
    family: Family,
) -> Captured {
    let mut pass = Pass::new(held, Level::new(level), family);
    if let Err(e) = pass.builder.set_gravity(Some(held.gravity)) {
        pass.refused(&e, Object::World, 0, None);
    }
    for index in 0..held.bodies.len() {
        pass.body(index);
    }
    pass.family.bodies_done(held.bodies, &mut pass.say(Object::World, 0, None));
    for placed in pass.joints_in_order() {
        match placed {
            Placed::Held(index) => pass.joint(index),
            Placed::Skipped(record) => pass.skipped_joint(record),
        }
    }
    let mut reports = Plan::default();
    for s in &pass.said {
        reports.report(s.code, s.object, s.index, s.name.as_deref(), format_args!("{}", s.message));
    }
    Captured { scene: pass.builder.finish(), reports }
}

/// A joint to write: a held one, or the level's joint the build skipped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Placed {
    Held(usize),
    Skipped(u32),
}

/// What identifies a written shape: its fields' bits, vertices and name.
type ShapeKey = (Vec<u32>, Option<String>);
/// What identifies a written fixture: its shape, material, filter and label.
type FixtureKey = (Vec<u32>, [Option<String>; 4]);

struct Pass<'h> {
    held: &'h Held<'h>,
    level: Level<'h>,
    family: Family,
    builder: Builder,
    said: Vec<Said>,
    shapes: HashMap<ShapeKey, u32>,
    fixtures: HashMap<FixtureKey, u32>,
    /// Per held body, the scene body written, or NONE.
    bodies: Vec<u32>,
    /// Per held joint, the scene joint written, or NONE.
    joints: Vec<u32>,
    /// Per level joint, the scene joint written, or NONE.
    level_written: Vec<u32>,
    /// How many joints are written.
    joints_written: u32,
}

fn some_text(text: Option<&str>) -> Option<&str> {
    text.filter(|t| !t.is_empty())
}

/// Whether a label gives anything (an empty text gives nothing).
fn labelled(label: &Label) -> bool {
    [label.name, label.user_data_raw, label.user_data_type, label.user_data_value]
        .iter()
        .any(|t| some_text(*t).is_some())
}

fn bits(values: &[f32]) -> impl Iterator<Item = u32> + '_ {
    values.iter().map(|v| v.to_bits())
}

impl<'h> Pass<'h> {
    fn new(held: &'h Held<'h>, level: Level<'h>, family: Family) -> Pass<'h> {
        Pass {
            held,
            level,
            family,
            builder: Builder::new(),
            said: Vec::new(),
            shapes: HashMap::new(),
            fixtures: HashMap::new(),
            bodies: vec![NONE; held.bodies.len()],
            joints: vec![NONE; held.joints.len()],
            level_written: vec![NONE; level.joint_count() as usize],
            joints_written: 0,
        }
    }

    fn say(&mut self, object: Object, index: u32, name: Option<&'h str>) -> Say<'_> {
        Say { said: &mut self.said, object, index, name }
    }

    /// A refusal of the builder, reported with its code.
    fn refused(&mut self, e: &Error, object: Object, index: u32, name: Option<&'h str>) {
        self.say(object, index, name).report(e.code, format_args!("{}; not written", e.message));
    }

    /// The scene's UserData of a label, or NONE (none, or refused: reported).
    fn user_data(&mut self, label: &Label<'h>, object: Object, index: u32) -> u32 {
        let raw = some_text(label.user_data_raw);
        let type_name = some_text(label.user_data_type);
        let value = some_text(label.user_data_value);
        if raw.is_none() && type_name.is_none() && value.is_none() {
            return NONE;
        }
        match self.builder.add_user_data(raw, type_name, value) {
            Ok(added) => added,
            Err(e) => {
                self.refused(&e, object, index, some_text(label.name));
                NONE
            }
        }
    }

    // ---- shapes and fixtures, each equal one written once

    /// The scene shape of held shape `index` and the `run` it begins, or NONE (reported).
    fn shape(&mut self, index: u32, run: &[HeldShape]) -> Option<u32> {
        let held = self.held;
        let slot = run[0].shape.slot;
        let name = some_text(held.shape_names.get(index as usize).copied().flatten())
            .or_else(|| some_text(self.level.shape_name(slot)));
        if let Some(other) = held.shape_others.get(index as usize).copied().flatten() {
            let code =
                if self.family.v3_reports() { Code::LossyCapture } else { Code::UnknownType };
            self.say(Object::Shape, index, name)
                .report(code, format_args!("{other} has no Box2Scene form; not written"));
            return None;
        }
        // What the family says is kept until the shape is written: an equal shape written
        // before has said it.
        let mut said = Vec::new();
        let mut say = Say { said: &mut said, object: Object::Shape, index, name };
        let made = self.family.shape(run, held.points, &mut say);
        let Some((shape, vertices)) = made else {
            self.said.append(&mut said);
            return None;
        };
        let key = shape_key(&shape, &vertices, name);
        if let Some(&found) =
            self.family.writes_equal_once().then(|| self.shapes.get(&key)).flatten()
        {
            return Some(found);
        }
        match self.builder.add_shape(&shape, name, &vertices) {
            Ok(added) => {
                self.said.append(&mut said);
                self.shapes.insert(key, added);
                Some(added)
            }
            Err(e) => {
                self.refused(&e, Object::Shape, index, name);
                None
            }
        }
    }

    /// The label of held shape `index`'s fixture: the host's, else the level's.
    fn fixture_label(&self, index: u32) -> Label<'h> {
        let host = self.held.fixture_labels.get(index as usize).copied().unwrap_or_default();
        if labelled(&host) {
            return host;
        }
        let slot = self.held.shapes[index as usize].shape.slot;
        self.level
            .fixture(slot)
            .map_or_else(Label::default, |f| self.level.label(f.name, f.user_data))
    }

    /// The scene fixture of held shape `index` and its `run`, or NONE (reported).
    fn fixture(&mut self, index: u32, run: &[HeldShape]) -> Option<u32> {
        let shape = self.shape(index, run);
        let label = self.fixture_label(index);
        let name = some_text(label.name);
        let Some(shape) = shape else {
            if self.family.v3_reports() {
                return None;
            }
            self.say(Object::Fixture, index, name).report(
                Code::SkippedDependent,
                format_args!("its shape was not written; not written"),
            );
            return None;
        };
        let family = self.family;
        let fixture = family.fixture(&run[0], &mut self.say(Object::Fixture, index, name));
        let key = fixture_key(&fixture, shape, &label);
        if let Some(&found) =
            self.family.writes_equal_once().then(|| self.fixtures.get(&key)).flatten()
        {
            return Some(found);
        }
        let user_data = self.user_data(&label, Object::Fixture, index);
        let record = Fixture { shape, user_data, ..fixture };
        match self.builder.add_fixture(&record, name) {
            Ok(added) => {
                self.fixtures.insert(key, added);
                Some(added)
            }
            Err(e) => {
                self.refused(&e, Object::Fixture, index, name);
                None
            }
        }
    }

    // ---- bodies

    fn body_label(&self, index: usize) -> Label<'h> {
        let host = self.held.body_labels.get(index).copied().unwrap_or_default();
        if labelled(&host) {
            return host;
        }
        let record = self.held.bodies[index].body.body;
        self.level
            .body(record)
            .map_or_else(Label::default, |b| self.level.label(b.name, b.user_data))
    }

    /// The runs of a body's held shapes: a v3 chain's segments together, every other shape
    /// on its own.
    fn runs(&self, body: &HeldBody) -> Vec<std::ops::Range<usize>> {
        let shapes = body.body.shapes.indices();
        let end = shapes.end.min(self.held.shapes.len());
        let mut runs = Vec::new();
        let mut first = shapes.start;
        while first < end {
            let rest = &self.held.shapes[first..end];
            let last = match rest[0].chain {
                NONE => first + 1,
                _ => first + self.family.chain_length(rest, self.held.points),
            };
            runs.push(first..last);
            first = last;
        }
        runs
    }

    fn body(&mut self, index: usize) {
        let held = self.held;
        let body = &held.bodies[index];
        let mut fixture_ids = Vec::new();
        let mut written = Vec::new();
        for run in self.runs(body) {
            if let Some(id) = self.fixture(run.start as u32, &held.shapes[run.clone()]) {
                fixture_ids.push(id);
                written.extend_from_slice(&held.shapes[run]);
            }
        }
        let label = self.body_label(index);
        let name = some_text(label.name);
        let level = self.level.body(body.body.body);
        let family = self.family;
        let made = family.body(
            body,
            &written,
            held.points,
            level,
            &mut self.say(Object::Body, index as u32, name),
        );
        let user_data = self.user_data(&label, Object::Body, index as u32);
        let record = Body { user_data, ..made };
        match self.builder.add_body(&record, name, &fixture_ids) {
            Ok(added) => self.bodies[index] = added,
            Err(e) => self.refused(&e, Object::Body, index as u32, name),
        }
    }

    // ---- joints

    /// The joints in the order they are written: creation order, or given the level the
    /// scene's, with the joints the build skipped in their places and the host's after.
    fn joints_in_order(&self) -> Vec<Placed> {
        let mut placed: Vec<(u64, Placed)> = Vec::new();
        for (i, joint) in self.held.joints.iter().enumerate() {
            placed.push((self.level.place(joint.joint.joint, i as u32), Placed::Held(i)));
        }
        for &record in self.held.skipped_joints {
            if self.level.joint(record).is_some() {
                placed.push((self.level.place(record, 0), Placed::Skipped(record)));
            }
        }
        placed.sort_by_key(|&(place, _)| place);
        placed.into_iter().map(|(_, p)| p).collect()
    }

    fn joint_label(&self, index: usize) -> Label<'h> {
        let host = self.held.joint_labels.get(index).copied().unwrap_or_default();
        if labelled(&host) {
            return host;
        }
        let record = self.held.joints[index].joint.joint;
        self.level
            .joint(record)
            .map_or_else(Label::default, |j| self.level.label(j.name, j.user_data))
    }

    /// The scene index written for held object `index` of `written`, or NONE.
    fn written(written: &[u32], index: u32) -> u32 {
        written.get(index as usize).copied().unwrap_or(NONE)
    }

    fn joint(&mut self, index: usize) {
        let held = self.held;
        let joint = &held.joints[index];
        let label = self.joint_label(index);
        let name = some_text(label.name);
        let v3 = self.family.v3_reports();
        let i = if v3 { self.joints_written } else { index as u32 };
        if let Some(other) = held.joint_others.get(index).copied().flatten() {
            let code = if v3 { Code::LossyCapture } else { Code::SkippedJoint };
            self.say(Object::Joint, i, name)
                .report(code, format_args!("{other} has no Box2Scene form; not written"));
            return;
        }
        let plan = &joint.joint;
        let (joint_a, joint_b) = match is_gear(plan.kind) {
            true => (
                Self::written(&self.joints, plan.joint_a),
                Self::written(&self.joints, plan.joint_b),
            ),
            false => (NONE, NONE),
        };
        if is_gear(plan.kind) && (joint_a == NONE || joint_b == NONE) {
            self.say(Object::Joint, i, name).report(
                Code::SkippedDependent,
                format_args!("a joint the gear couples was not written; not written"),
            );
            return;
        }
        let body_a = Self::written(&self.bodies, plan.body_a);
        let body_b = Self::written(&self.bodies, plan.body_b);
        if body_a == NONE || body_b == NONE {
            let code = if v3 { Code::LossyCapture } else { Code::SkippedDependent };
            self.say(Object::Joint, i, name)
                .report(code, format_args!("one of its bodies was not written; not written"));
            return;
        }
        let (a, b) = (&held.bodies[plan.body_a as usize], &held.bodies[plan.body_b as usize]);
        let level = self.level.joint(plan.joint);
        let family = self.family;
        let Some(made) = family.joint(joint, a, b, level, &mut self.say(Object::Joint, i, name))
        else {
            return;
        };
        let user_data = self.user_data(&label, Object::Joint, i);
        let record = Joint { body_a, body_b, joint_a, joint_b, user_data, ..made };
        match self.builder.add_joint(&record, name) {
            Ok(added) => {
                self.joints_written += 1;
                self.joints[index] = added;
                if let Some(w) = self.level_written.get_mut(plan.joint as usize) {
                    *w = added;
                }
            }
            Err(e) => self.refused(&e, Object::Joint, i, name),
        }
    }

    /// The scene index written for the level's body `record`, or NONE.
    fn written_level_body(&self, record: u32) -> u32 {
        let held = self.held.bodies.iter().position(|b| b.body.body == record);
        held.map_or(NONE, |i| self.bodies[i])
    }

    /// The level's joint `record`, which the build skipped (the engine cannot hold it),
    /// written as the file has it between the written bodies, so that the joints keep
    /// their indices; reported and not written when it names a body or joint not written
    /// before it.
    fn skipped_joint(&mut self, record: u32) {
        let Some(&joint) = self.level.joint(record) else {
            return;
        };
        let label = self.level.label(joint.name, joint.user_data);
        let name = some_text(label.name);
        let mut out = Joint {
            body_a: self.written_level_body(joint.body_a),
            body_b: self.written_level_body(joint.body_b),
            ..joint
        };
        let mut resolved = out.body_a != NONE
            && out.body_b != NONE
            && joint.kind != crate::scene::JointKind::Unsupported as u32;
        for coupled in [&mut out.joint_a, &mut out.joint_b] {
            if *coupled != NONE {
                *coupled = Self::written(&self.level_written, *coupled);
                resolved &= *coupled != NONE;
            }
        }
        let (code, index) = match self.family.v3_reports() {
            true => (Code::LossyCapture, self.joints_written),
            false => (Code::SkippedDependent, record),
        };
        if !resolved {
            self.say(Object::Joint, index, name).report(
                code,
                format_args!(
                    "scene joint {record}, which build_world skipped, names a body or joint not \
                     written (or has no Box2Scene form); not written"
                ),
            );
            return;
        }
        out.user_data = self.user_data(&label, Object::Joint, record);
        match self.builder.add_joint(&out, name) {
            Ok(added) => {
                self.joints_written += 1;
                self.level_written[record as usize] = added;
            }
            Err(e) => self.refused(&e, Object::Joint, record, name),
        }
    }
}

fn shape_key(s: &Shape, vertices: &[Vec2], name: Option<&str>) -> ShapeKey {
    let mut key = vec![s.kind];
    key.extend(bits(&[s.radius, s.position.x, s.position.y, s.centroid.x, s.centroid.y]));
    key.extend(bits(&[s.prev_vertex.x, s.prev_vertex.y, s.next_vertex.x, s.next_vertex.y]));
    key.extend([s.centroid_given, s.has_prev_vertex, s.has_next_vertex, s.is_loop].map(u32::from));
    key.push(vertices.len() as u32);
    for v in vertices {
        key.extend(bits(&[v.x, v.y]));
    }
    (key, name.map(str::to_owned))
}

fn fixture_key(f: &Fixture, shape: u32, label: &Label) -> FixtureKey {
    let mut key = vec![shape];
    key.extend(bits(&[f.density, f.friction, f.restitution]));
    key.extend([u32::from(f.is_sensor), f.filter.category_bits, f.filter.mask_bits]);
    key.push(f.filter.group_index as u32);
    let text = |t: Option<&str>| some_text(t).map(str::to_owned);
    let label = [
        text(label.name),
        text(label.user_data_raw),
        text(label.user_data_type),
        text(label.user_data_value),
    ];
    (key, label)
}

/// What a family says of one object, for its unit tests: each report's code and message.
#[cfg(test)]
pub(crate) fn said<T>(run: impl FnOnce(&mut Say) -> T) -> (T, Vec<(Code, String)>) {
    let mut said = Vec::new();
    let out = run(&mut Say { said: &mut said, object: Object::World, index: 0, name: None });
    (out, said.into_iter().map(|s| (s.code, s.message)).collect())
}
