//! A scene under construction: its records and pools as a load or the builder fills them,
//! pieces read on two threads appended, and frozen into the immutable [`Scene`].

use std::ffi::c_char;

use super::kept::Objects;
use super::{
    Body, Diagnostic, Dialect, Fixture, Joint, Kept, KeptText, NONE, Scene, Shape, Str, UserData,
    Vec2,
};

/// A scene under construction: the same arrays, with strings still as pool offsets.
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
    pub vertices: Vec<Vec2>,
    pub fixture_ids: Vec<u32>,
    pub user_data: Vec<UserData>,
    pub diagnostics: Vec<Diagnostic>,
    /// In file order.
    pub kept: Vec<Kept<KeptText>>,
    strings: Vec<u8>,
}

impl SceneBuilder {
    /// Stores `text` NUL-terminated in the string pool. Text holding a NUL is cut there
    /// (the loader rejects NUL bytes before this point).
    pub fn add_str(&mut self, text: &str) -> Str {
        let offset = self.strings.len();
        let text = text.split('\0').next().unwrap_or_default();
        self.strings.extend_from_slice(text.as_bytes());
        self.strings.push(0);
        Str::pending(offset)
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
            vertices,
            fixture_ids,
            user_data,
            diagnostics,
            kept,
            strings,
        } = other;
        let strings_before = self.strings.len();
        let name = |s: Str| s.shifted(strings_before);
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
        self.shapes.extend(shapes.into_iter().map(|s| Shape {
            name: name(s.name),
            vertices: s.vertices.shifted(vertices_before),
            ..s
        }));
        self.fixtures.extend(fixtures.into_iter().map(|f| Fixture {
            name: name(f.name),
            user_data: user(f.user_data),
            ..f
        }));
        self.bodies.extend(bodies.into_iter().map(|b| Body {
            name: name(b.name),
            fixtures: b.fixtures.shifted(ids_before),
            user_data: user(b.user_data),
            ..b
        }));
        self.joints.extend(joints.into_iter().map(|j| Joint {
            name: name(j.name),
            user_data: user(j.user_data),
            ..j
        }));
        self.vertices.extend(vertices);
        self.fixture_ids.extend(fixture_ids);
        self.user_data.extend(user_data.into_iter().map(|u| UserData {
            raw: name(u.raw),
            type_name: name(u.type_name),
            value: name(u.value),
        }));
        self.diagnostics
            .extend(diagnostics.into_iter().map(|d| Diagnostic { message: name(d.message), ..d }));
        self.kept.extend(kept.into_iter().map(|k| k.shifted(before, strings_before)));
        self.strings.extend(strings);
    }

    /// Copies the spans of kept text, read with `slice`, into the string pool.
    pub fn pool_kept_text<'t>(&mut self, slice: impl Fn(usize, usize) -> &'t str) {
        for i in 0..self.kept.len() {
            if let KeptText::Span(from, to) = self.kept[i].text {
                self.kept[i].text = KeptText::Pooled(self.add_str(slice(from, to)));
            }
        }
    }

    /// Rebases every string into the final pool and returns the immutable scene (whose
    /// kept text is all in the pool: see [`SceneBuilder::pool_kept_text`]).
    pub fn freeze(self) -> Scene {
        let mut scene = Scene {
            version: self.version,
            dialect: self.dialect.unwrap_or(Dialect::Box2scene),
            world_axes: self.world_axes,
            gravity: self.gravity,
            shapes: self.shapes,
            fixtures: self.fixtures,
            bodies: self.bodies,
            joints: self.joints,
            vertices: self.vertices,
            fixture_ids: self.fixture_ids,
            user_data: self.user_data,
            diagnostics: self.diagnostics,
            kept: {
                let pooled = |k: Kept<KeptText>| match k.text {
                    KeptText::Pooled(text) => Some(Kept { object: k.object, place: k.place, text }),
                    KeptText::Span(..) => None,
                };
                let mut kept: Vec<Kept> = self.kept.into_iter().filter_map(pooled).collect();
                // Stable: each object's pieces stay in file order.
                kept.sort_by_key(|k| k.object);
                kept
            },
            strings: {
                let mut strings = self.strings;
                strings.shrink_to_fit();
                strings
            },
        };
        let pool = scene.strings.as_ptr().cast::<c_char>();
        let names = (scene.shapes.iter_mut().map(|s| &mut s.name))
            .chain(scene.fixtures.iter_mut().map(|f| &mut f.name))
            .chain(scene.bodies.iter_mut().map(|b| &mut b.name))
            .chain(scene.joints.iter_mut().map(|j| &mut j.name))
            .chain(scene.diagnostics.iter_mut().map(|d| &mut d.message))
            .chain(scene.kept.iter_mut().map(|k| &mut k.text));
        let user_data =
            scene.user_data.iter_mut().flat_map(|u| [&mut u.raw, &mut u.type_name, &mut u.value]);
        for s in names.chain(user_data) {
            s.rebase(pool);
        }
        scene
    }
}
