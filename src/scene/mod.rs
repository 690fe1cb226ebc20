//! The model: the flat `#[repr(C)]` records a scene is made of and their defaults
//! (`records`), the one table of the elements each joint kind has (`joints`), the frozen
//! [`Scene`] that owns them, the scene under construction (`builder`), and the text a file
//! held beyond the records, which only the writer reads (`kept`).
//!
//! Every record is part of the C ABI (`include/box2scene.h` is generated from them).
//! Cross references are `u32` indices into sibling arrays, [`NONE`] when absent; variable
//! length data are [`Range`]s into the scene's pools; strings are [`Str`] pointers into the
//! scene's string pool. Enumerations are stored as `u32` so that a value written by C is
//! never an invalid Rust enum; the typed enums below name the values.
//!
//! The doc comments of the exported items are copied into the C header, so they speak C:
//! `NULL`, `uint32_t`, the `b2s_*` names.
#![forbid(unsafe_code)]

mod builder;
mod edit;
pub(crate) mod joints;
mod kept;
mod records;

pub(crate) use builder::{PoolStr, SceneBuilder, UserDataText};
pub(crate) use kept::{Beyond, Kept, KeptAt, KeptText, Object, Span};
pub use records::*;

/// A loaded scene: immutable once built. All arrays are flat; see the field docs of each
/// record for its cross references.
#[derive(Debug)]
pub struct Scene {
    pub(crate) version: u32,
    /// The dialect of the file it was read from; box2scene's own for a built scene.
    pub(crate) dialect: Dialect,
    pub(crate) gravity: Option<Vec2>,
    pub(crate) shapes: Vec<Shape>,
    pub(crate) fixtures: Vec<Fixture>,
    pub(crate) bodies: Vec<Body>,
    pub(crate) joints: Vec<Joint>,
    pub(crate) vertices: Vec<Vec2>,
    pub(crate) fixture_ids: Vec<u32>,
    pub(crate) user_data: Vec<UserData>,
    pub(crate) diagnostics: Vec<Diagnostic>,
    /// The strings the records point into. A Vec, not a Box: moving a Box would invalidate
    /// (for Rust's aliasing rules) the string pointers taken from it when the scene was
    /// frozen.
    pub(crate) strings: Vec<u8>,
    /// What only the writer reads: the file's text beyond the records.
    pub(crate) beyond: Beyond,
}

impl Scene {
    /// The file's `Version` attribute; 0 for an unversioned (legacy) file.
    pub fn version(&self) -> u32 {
        self.version
    }
    /// The dialect of the file it was read from (box2scene's own for a built scene): the
    /// one a write keeps unless another is asked for.
    pub fn dialect(&self) -> Dialect {
        self.dialect
    }
    /// The file's `Gravity`, if it gave one (there is no default gravity).
    pub fn gravity(&self) -> Option<Vec2> {
        self.gravity
    }
    /// The shapes, indexed by the fixtures' `shape`.
    pub fn shapes(&self) -> &[Shape] {
        &self.shapes
    }
    /// The fixtures, indexed by the fixture ID pool.
    pub fn fixtures(&self) -> &[Fixture] {
        &self.fixtures
    }
    /// The bodies, indexed by the joints' `body_a` and `body_b`.
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }
    /// The joints, indexed by the gears' `joint_a` and `joint_b`.
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }
    /// The vertex pool that shapes' `vertices` ranges index.
    pub fn vertex_pool(&self) -> &[Vec2] {
        &self.vertices
    }
    /// The fixture ID pool that bodies' `fixtures` ranges index.
    pub fn fixture_id_pool(&self) -> &[u32] {
        &self.fixture_ids
    }
    /// The user data, indexed by the `user_data` of fixtures, bodies and joints.
    pub fn user_data(&self) -> &[UserData] {
        &self.user_data
    }
    /// The warnings of the load (a failed load returns an error instead of a scene).
    pub fn diagnostics(&self) -> &[Diagnostic] {
        &self.diagnostics
    }
    /// The vertices of `shape`.
    pub fn vertices(&self, shape: &Shape) -> &[Vec2] {
        &self.vertices[shape.vertices.indices()]
    }
    /// The fixture indices of `body`.
    pub fn body_fixtures(&self, body: &Body) -> &[u32] {
        &self.fixture_ids[body.fixtures.indices()]
    }
    /// The user data at `index`, or None for [`NONE`].
    pub fn user_data_at(&self, index: u32) -> Option<&UserData> {
        self.user_data.get(index as usize)
    }

    /// The text of a string of this scene; None for NULL (or a string of another scene).
    pub fn text(&self, s: Str) -> Option<&str> {
        let offset = s.0.addr().checked_sub(self.strings.as_ptr().addr())?;
        let rest = self.strings.get(offset..)?;
        let end = rest.iter().position(|&b| b == 0)?;
        std::str::from_utf8(&rest[..end]).ok()
    }

    /// The index of the first shape named `name`.
    pub fn find_shape(&self, name: &str) -> Option<u32> {
        self.find(self.shapes.iter().map(|s| s.name), name)
    }
    /// The index of the first fixture named `name`.
    pub fn find_fixture(&self, name: &str) -> Option<u32> {
        self.find(self.fixtures.iter().map(|f| f.name), name)
    }
    /// The index of the first body named `name`.
    pub fn find_body(&self, name: &str) -> Option<u32> {
        self.find(self.bodies.iter().map(|b| b.name), name)
    }
    /// The index of the first joint named `name`.
    pub fn find_joint(&self, name: &str) -> Option<u32> {
        self.find(self.joints.iter().map(|j| j.name), name)
    }

    fn find(&self, mut names: impl Iterator<Item = Str>, name: &str) -> Option<u32> {
        let index = names.position(|s| self.text(s) == Some(name))?;
        u32::try_from(index).ok()
    }
}
