//! What a loaded file held that no record has, kept for the writer: by object, by place
//! in it, in a pool of its own apart from the strings of the C view, and while the file is
//! read as spans of its text.

use super::Vec2;

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
pub(crate) enum KeptAt {
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
/// a Farseer-only joint. Only the writer reads it (`docs/format.md`, "Writing"); the C view
/// has none of it. While a file is read, `T` says where the text is (see [`KeptText`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Kept<T = Span> {
    pub object: Object,
    pub place: KeptAt,
    pub text: T,
}

/// Bytes `from..to` of a text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Span {
    pub from: usize,
    pub to: usize,
}

/// Kept text while a file is read: a span of the file's text, which stays at hand until
/// the load ends and is copied only once it succeeds (so a file of many unknown elements
/// costs a few spans, not a copy), or a span of the pool of kept text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum KeptText {
    File(Span),
    Pooled(Span),
}

impl Kept<KeptText> {
    /// The same piece after `before` more objects of each kind, and a pool of kept text of
    /// `pool_before` bytes, were put before it.
    pub(super) fn shifted(self, before: Objects, pool_before: usize) -> Self {
        let text = match self.text {
            KeptText::Pooled(Span { from, to }) => {
                KeptText::Pooled(Span { from: from + pool_before, to: to + pool_before })
            }
            file => file,
        };
        Kept { object: self.object.shifted(before), text, ..self }
    }
}

/// What only the writer reads of a frozen scene: what its file held beyond the records.
#[derive(Debug, Default)]
pub(crate) struct Beyond {
    /// The joints whose file gave Farseer's world `Axis`, with it, for a writer that
    /// writes it back as it was.
    pub world_axes: Vec<(u32, Vec2)>,
    /// By object, each object's in file order.
    pub pieces: Vec<Kept>,
    /// The text of the pieces.
    pub text: String,
}

impl Beyond {
    /// The pieces of `object`, in file order.
    pub(crate) fn of(&self, object: Object) -> &[Kept] {
        let first = self.pieces.partition_point(|k| k.object < object);
        let end = first + self.pieces[first..].partition_point(|k| k.object == object);
        &self.pieces[first..end]
    }

    /// The text of `piece`.
    pub(crate) fn text(&self, piece: &Kept) -> &str {
        &self.text[piece.text.from..piece.text.to]
    }
}
