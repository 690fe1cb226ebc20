//! A scene under construction: its records and pools as a load or the builder fills them,
//! pieces read on two threads appended, and frozen into the immutable [`Scene`]. While it
//! is built a string is a [`PoolStr`], an offset into its pool that the type names; only
//! freezing makes the records' [`Str`] pointers.

use std::ffi::c_char;

use super::kept::{Beyond, Objects, Span};
use super::{
    Body, Diagnostic, Dialect, Fixture, Joint, Kept, KeptText, NONE, Scene, Shape, Str, UserData,
    Vec2,
};
use crate::error::{Code, Position, Severity};

/// A string of the pool a scene is built with: where it starts there. It becomes a
/// [`Str`] when the scene is frozen; until then the records' strings are NULL, and their
/// text is in the builder's string columns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct PoolStr(usize);

impl PoolStr {
    /// The same string once a pool of `before` bytes is put before its own.
    fn shifted(self, before: usize) -> PoolStr {
        PoolStr(self.0 + before)
    }
}

/// The strings of a user data while it is built (see [`UserData`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct UserDataText {
    pub raw: PoolStr,
    pub type_name: Option<PoolStr>,
    pub value: Option<PoolStr>,
}

/// The names of the records, while they are built: beside each array, the records that
/// have one, by index, in order (most records of a large scene have none, and cost
/// nothing here).
#[derive(Debug, Default)]
pub(crate) struct Names {
    pub shapes: Vec<(u32, PoolStr)>,
    pub fixtures: Vec<(u32, PoolStr)>,
    pub bodies: Vec<(u32, PoolStr)>,
    pub joints: Vec<(u32, PoolStr)>,
}

/// Names record `index` `name`, if it has one.
fn name_at(names: &mut Vec<(u32, PoolStr)>, index: usize, name: Option<PoolStr>) {
    if let Some(name) = name {
        names.push((index as u32, name));
    }
}

/// Points each named record at its name.
fn set_names<R>(
    records: &mut [R],
    names: Vec<(u32, PoolStr)>,
    at: impl Fn(PoolStr) -> Str,
    field: fn(&mut R) -> &mut Str,
) {
    for (index, name) in names {
        *field(&mut records[index as usize]) = at(name);
    }
}

/// A scene under construction: the same arrays, their strings (NULL in the records) in
/// columns of pool offsets beside them, and the text kept for the writer in a pool of its
/// own.
#[derive(Debug, Default)]
pub(crate) struct SceneBuilder {
    pub version: u32,
    pub dialect: Option<Dialect>,
    pub world_axes: Vec<(u32, Vec2)>,
    pub gravity: Option<Vec2>,
    pub shapes: Vec<Shape>,
    pub fixtures: Vec<Fixture>,
    pub bodies: Vec<Body>,
    pub joints: Vec<Joint>,
    pub names: Names,
    pub vertices: Vec<Vec2>,
    pub fixture_ids: Vec<u32>,
    pub user_data: Vec<UserDataText>,
    /// Each with its message, the record's own NULL.
    pub diagnostics: Vec<(Diagnostic, PoolStr)>,
    /// In file order.
    pub kept: Vec<Kept<KeptText>>,
    strings: Vec<u8>,
    kept_text: String,
}

impl SceneBuilder {
    /// Stores `text` NUL-terminated in the string pool. Text holding a NUL is cut there
    /// (the loader rejects NUL bytes before this point).
    pub fn add_str(&mut self, text: &str) -> PoolStr {
        let offset = self.strings.len();
        let text = text.as_bytes();
        let text = &text[..memchr::memchr(0, text).unwrap_or(text.len())];
        self.strings.extend_from_slice(text);
        self.strings.push(0);
        PoolStr(offset)
    }

    /// Stores `text` in the pool of kept text and says where.
    pub fn keep_str(&mut self, text: &str) -> KeptText {
        let from = self.kept_text.len();
        self.kept_text.push_str(text);
        KeptText::Pooled(Span { from, to: self.kept_text.len() })
    }

    pub fn push_shape(&mut self, shape: Shape, name: Option<PoolStr>) {
        debug_assert!(shape.name.is_null());
        name_at(&mut self.names.shapes, self.shapes.len(), name);
        self.shapes.push(shape);
    }

    pub fn push_fixture(&mut self, fixture: Fixture, name: Option<PoolStr>) {
        debug_assert!(fixture.name.is_null());
        name_at(&mut self.names.fixtures, self.fixtures.len(), name);
        self.fixtures.push(fixture);
    }

    pub fn push_body(&mut self, body: Body, name: Option<PoolStr>) {
        debug_assert!(body.name.is_null());
        name_at(&mut self.names.bodies, self.bodies.len(), name);
        self.bodies.push(body);
    }

    pub fn push_joint(&mut self, joint: Joint, name: Option<PoolStr>) {
        debug_assert!(joint.name.is_null());
        name_at(&mut self.names.joints, self.joints.len(), name);
        self.joints.push(joint);
    }

    /// Adds a warning with `message` (placed at `position`).
    pub fn push_warning(&mut self, code: Code, position: Position, message: &str) {
        let message = self.add_str(message);
        let diagnostic = Diagnostic {
            message: Str::NULL,
            byte_offset: position.byte_offset,
            code: code as u32,
            severity: Severity::Warning as u32,
            line: position.line,
            column: position.column,
        };
        self.diagnostics.push((diagnostic, message));
    }

    /// Lets go of the room its arrays hold beyond what they hold (a piece read on the second
    /// thread waits with only what it needs until it is appended).
    pub fn shrink_to_fit(&mut self) {
        self.shapes.shrink_to_fit();
        self.fixtures.shrink_to_fit();
        self.bodies.shrink_to_fit();
        self.joints.shrink_to_fit();
        self.vertices.shrink_to_fit();
        self.fixture_ids.shrink_to_fit();
        self.user_data.shrink_to_fit();
        self.diagnostics.shrink_to_fit();
        self.kept.shrink_to_fit();
        self.strings.shrink_to_fit();
    }

    /// Appends what `other` read after this builder's last object: its objects after
    /// these, their pool ranges, user data indices and strings moved along. A gravity
    /// is taken only when this builder has none.
    pub fn append(&mut self, other: SceneBuilder) {
        let SceneBuilder {
            version: _,
            dialect: _,
            world_axes: _,
            gravity,
            shapes,
            fixtures,
            bodies,
            joints,
            names,
            vertices,
            fixture_ids,
            user_data,
            diagnostics,
            kept,
            strings,
            kept_text,
        } = other;
        let strings_before = self.strings.len();
        let string = |s: PoolStr| s.shifted(strings_before);
        let name = |s: Option<PoolStr>| s.map(string);
        let named = |before: u32| move |(i, s): (u32, PoolStr)| (i + before, string(s));
        let before = Objects {
            shapes: self.shapes.len() as u32,
            fixtures: self.fixtures.len() as u32,
            bodies: self.bodies.len() as u32,
            joints: self.joints.len() as u32,
        };
        let user_data_before = self.user_data.len() as u32;
        let user = |index: u32| if index == NONE { NONE } else { index + user_data_before };
        let (vertices_before, ids_before) = (self.vertices.len(), self.fixture_ids.len());
        self.gravity = self.gravity.or(gravity);
        self.shapes.extend(
            shapes
                .into_iter()
                .map(|s| Shape { vertices: s.vertices.shifted(vertices_before), ..s }),
        );
        self.fixtures
            .extend(fixtures.into_iter().map(|f| Fixture { user_data: user(f.user_data), ..f }));
        self.bodies.extend(bodies.into_iter().map(|b| Body {
            fixtures: b.fixtures.shifted(ids_before),
            user_data: user(b.user_data),
            ..b
        }));
        self.joints.extend(joints.into_iter().map(|j| Joint { user_data: user(j.user_data), ..j }));
        self.names.shapes.extend(names.shapes.into_iter().map(named(before.shapes)));
        self.names.fixtures.extend(names.fixtures.into_iter().map(named(before.fixtures)));
        self.names.bodies.extend(names.bodies.into_iter().map(named(before.bodies)));
        self.names.joints.extend(names.joints.into_iter().map(named(before.joints)));
        self.vertices.extend(vertices);
        self.fixture_ids.extend(fixture_ids);
        self.user_data.extend(user_data.into_iter().map(|u| UserDataText {
            raw: string(u.raw),
            type_name: name(u.type_name),
            value: name(u.value),
        }));
        self.diagnostics.extend(diagnostics.into_iter().map(|(d, m)| (d, string(m))));
        let kept_before = self.kept_text.len();
        self.kept.extend(kept.into_iter().map(|k| k.shifted(before, kept_before)));
        self.strings.extend(strings);
        self.kept_text.push_str(&kept_text);
    }

    /// Copies the spans of kept text, read with `slice`, into the pool of kept text.
    pub fn pool_kept_text<'t>(&mut self, slice: impl Fn(usize, usize) -> &'t str) {
        for i in 0..self.kept.len() {
            if let KeptText::File(Span { from, to }) = self.kept[i].text {
                self.kept[i].text = self.keep_str(slice(from, to));
            }
        }
    }

    /// Turns every string into a pointer into the final pool and returns the immutable
    /// scene (whose kept text is all in its pool: see [`SceneBuilder::pool_kept_text`]).
    pub fn freeze(self) -> Scene {
        let mut strings = self.strings;
        strings.shrink_to_fit();
        // The pool is final: it is moved into the scene as a Vec, whose buffer stays put.
        let pool = strings.as_ptr().cast::<c_char>();
        let at = |s: PoolStr| Str(pool.wrapping_add(s.0));
        let named = |name: Option<PoolStr>| name.map_or(Str::NULL, at);
        let (mut shapes, mut fixtures, mut bodies, mut joints) =
            (self.shapes, self.fixtures, self.bodies, self.joints);
        let names = self.names;
        set_names(&mut shapes, names.shapes, at, |s| &mut s.name);
        set_names(&mut fixtures, names.fixtures, at, |f| &mut f.name);
        set_names(&mut bodies, names.bodies, at, |b| &mut b.name);
        set_names(&mut joints, names.joints, at, |j| &mut j.name);
        let user_data = (self.user_data.into_iter())
            .map(|u| UserData {
                raw: at(u.raw),
                type_name: named(u.type_name),
                value: named(u.value),
            })
            .collect();
        let diagnostics =
            self.diagnostics.into_iter().map(|(d, m)| Diagnostic { message: at(m), ..d }).collect();
        let pooled = |k: Kept<KeptText>| match k.text {
            KeptText::Pooled(text) => Some(Kept { object: k.object, place: k.place, text }),
            KeptText::File(..) => None,
        };
        let mut pieces: Vec<Kept> = self.kept.into_iter().filter_map(pooled).collect();
        // Stable: each object's pieces stay in file order.
        pieces.sort_by_key(|k| k.object);
        Scene {
            version: self.version,
            dialect: self.dialect.unwrap_or(Dialect::Box2scene),
            gravity: self.gravity,
            shapes,
            fixtures,
            bodies,
            joints,
            vertices: self.vertices,
            fixture_ids: self.fixture_ids,
            user_data,
            diagnostics,
            strings,
            beyond: Beyond { world_axes: self.world_axes, pieces, text: self.kept_text },
        }
    }
}
