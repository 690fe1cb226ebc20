//! What a loaded file held that no record has, kept for the writer: by object, by place
//! in it, and while the file is read as spans of its text.

use super::Str;

/// The object a piece of [`Kept`] text belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Object {
    World,
    Shape(u32),
    Fixture(u32),
    Body(u32),
    Joint(u32),
}

/// As messages name objects: "the world", "body 3".
impl std::fmt::Display for Object {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Object::World => f.write_str("the world"),
            Object::Shape(i) => write!(f, "shape {i}"),
            Object::Fixture(i) => write!(f, "fixture {i}"),
            Object::Body(i) => write!(f, "body {i}"),
            Object::Joint(i) => write!(f, "joint {i}"),
        }
    }
}

impl Object {
    /// The same object after `before` more of each kind were put before it.
    fn shifted(self, before: Objects) -> Object {
        match self {
            Object::World => Object::World,
            Object::Shape(i) => Object::Shape(i + before.shapes),
            Object::Fixture(i) => Object::Fixture(i + before.fixtures),
            Object::Body(i) => Object::Body(i + before.bodies),
            Object::Joint(i) => Object::Joint(i + before.joints),
        }
    }
}

/// How many objects of each kind.
#[derive(Clone, Copy)]
pub(super) struct Objects {
    pub(super) shapes: u32,
    pub(super) fixtures: u32,
    pub(super) bodies: u32,
    pub(super) joints: u32,
}

/// Where in its object a piece of [`Kept`] text goes. Element names are the writer's
/// spelling (the canonical one of the loader's tables).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Place {
    /// Before the object's start tag: a comment that preceded it (for the world, before
    /// `<World>`).
    Before,
    /// In the object's start tag: an unknown attribute, as ` name="value"`.
    Attribute,
    /// Instead of the object: its whole text (a Farseer-only joint, which has no
    /// Box2Scene form).
    Whole,
    /// Inside the object, within its child element `within` ("" for the object itself):
    /// before the element `before`, or at the end when that is "" or not written.
    Inside { within: &'static str, before: &'static str },
    /// After the object's end tag (for the world, after `</World>`).
    After,
}

/// Text a loaded file held that no record has: a comment, an unknown element or attribute,
/// a Farseer-only joint. Only the writer reads it (`docs/format.md`, "Writing"); the C view has none of it. While a file is read, `T` says where the text
/// is (see [`KeptText`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Kept<T = Str> {
    pub object: Object,
    pub place: Place,
    pub text: T,
}

/// Kept text while a file is read: a span of a text that stays at hand until the load
/// ends, copied only once it succeeds (so a file of many unknown elements costs a few
/// spans, not a copy), or a string of the pool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum KeptText {
    Span(usize, usize),
    Pooled(Str),
}

impl Kept<KeptText> {
    /// The same piece after `before` more objects of each kind, and a string pool of
    /// `strings_before` bytes, were put before it.
    pub(super) fn shifted(self, before: Objects, strings_before: usize) -> Self {
        let text = match self.text {
            KeptText::Pooled(s) => KeptText::Pooled(s.shifted(strings_before)),
            span => span,
        };
        Kept { object: self.object.shifted(before), text, ..self }
    }
}
