//! box2scene: load Box2Scene XML files (whole Box2D worlds) into flat arrays of plain
//! records, from Rust or, through `include/box2scene.h`, from C and C++.
//!
//! ```no_run
//! let scene = box2scene::load_path("level.xml", &box2scene::LoadOptions::default())?;
//! for body in scene.bodies() {
//!     println!("{:?} at {:?}", scene.text(body.name), body.position);
//! }
//! # Ok::<(), box2scene::Error>(())
//! ```
//!
//! The format (every element and its default, every error and warning code, the mapping
//! onto Box2D) is described in the repository's `docs/format.md`; the C API's conventions
//! in `docs/api.md`. The records of [`scene`] are the C API's structs, and [`ffi`] holds
//! every function of the C header.

#![warn(missing_docs)]

mod arena;
mod builder;
mod bytes;
pub mod capture;
mod check;
#[doc(hidden)]
mod containers;
pub mod draw;
mod dump;
pub mod error;
pub mod escape;
pub mod ffi;
mod holds;
mod input;
mod load;
mod markup;
mod options;
mod output;
mod parse;
mod place;
pub mod plan;
mod rules;
mod scan;
pub mod scene;
mod text;
mod write;

use std::fs::File;
use std::io::Read;
use std::path::Path;

pub use builder::Builder;
pub use error::{Code, Error, Position, Severity};
pub use load::Checked;
pub use options::{LoadOptions, WriteOptions};
pub use plan::{Engine, WorkingRange};
pub use scene::{
    Body, BodyKind, Diagnostic, Dialect, Filter, Fixture, Joint, JointKind, MassData, NONE, Range,
    Scene, Shape, ShapeKind, Str, UserData, Vec2,
};
pub use write::write;

/// Loads a scene from the bytes of a file. The result keeps no reference to `bytes`.
pub fn load(bytes: &[u8], options: &LoadOptions) -> Result<Scene, Error> {
    load::load(bytes, options)
}

/// Loads a scene from a file.
pub fn load_path(path: impl AsRef<Path>, options: &LoadOptions) -> Result<Scene, Error> {
    load::load_path(path.as_ref(), options)
}

/// Loads a scene from a file already open (a regular file, a pipe, a terminal), read from
/// its start a window at a time, as [`load_path`] reads one; `name` is the file's name
/// in messages.
pub fn load_file(
    file: File,
    name: impl AsRef<Path>,
    options: &LoadOptions,
) -> Result<Scene, Error> {
    load::load_file(file, name.as_ref(), options)
}

/// Loads a scene from a stream read once, a window at a time, never held whole; `name` is
/// its name in messages.
pub fn load_reader(
    reader: impl Read,
    name: impl AsRef<Path>,
    options: &LoadOptions,
) -> Result<Scene, Error> {
    load::load_stream(reader, name.as_ref(), options)
}

/// Checks the bytes of a file as [`load()`] loads them, but goes on past the errors it can,
/// as a compiler does, to report every one: a value that does not convert or is out of
/// range is read as its type's zero, an ID that names nothing is reported with every other,
/// and the load stops only at what leaves nothing to read on from (a markup error, a limit,
/// a missing element or attribute) or after a hundred errors. The scene, when there is no
/// error, is the one [`load()`] gives. Reads on one thread.
pub fn check(bytes: &[u8], options: &LoadOptions) -> Checked {
    load::check(bytes, options)
}

/// [`check()`] for a file already open, read as [`load_file`] reads it.
pub fn check_file(file: File, name: impl AsRef<Path>, options: &LoadOptions) -> Checked {
    load::check_file(file, name.as_ref(), options)
}

/// [`check()`] for a stream, read as [`load_reader`] reads it.
pub fn check_reader(reader: impl Read, name: impl AsRef<Path>, options: &LoadOptions) -> Checked {
    load::check_stream(reader, name.as_ref(), options)
}

/// Replaces the file at `path` by `bytes` as [`write_path`] replaces one: atomically, with
/// the old file's permissions, through a link to its target.
pub fn write_file(path: impl AsRef<Path>, bytes: &[u8]) -> std::io::Result<()> {
    output::replace(path.as_ref(), bytes)
}

/// Writes `scene` to a file (see [`write()`]), replacing it atomically: the text goes to a
/// new file beside it, flushed to disk, then renamed over it, so a failed write (a full
/// disk, a scene that cannot be written) leaves the old file as it was. The new file has
/// the old one's permissions, owner and group (those the writer may set) before its first
/// byte; through a link, the link's target is written, created if it does not exist.
pub fn write_path(
    scene: &Scene,
    path: impl AsRef<Path>,
    options: &WriteOptions,
) -> Result<(), Error> {
    let path = path.as_ref();
    output::replace(path, &write::write_utf8(scene, options)?).map_err(|e| Error {
        code: Code::Io,
        position: Position::default(),
        message: format!("cannot write {}: {e}", path.display()),
    })
}

impl Scene {
    /// The scene as Box2Scene XML (see [`write()`]).
    pub fn to_xml(&self, options: &WriteOptions) -> Result<String, Error> {
        write(self, options)
    }

    /// The scene as JSON: its version and dialect, every field of every record, floats in
    /// shortest round-trip form, diagnostics included.
    pub fn to_json(&self) -> String {
        dump::to_json(self)
    }
}

/// The random numbers of the unit tests: xorshift64, the same on every run from the same
/// seed.
#[cfg(test)]
struct Xorshift(u64);

#[cfg(test)]
impl Xorshift {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// A number below `n`.
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// The project's scene files and the editor's (tests/fixtures/scenes, tests/fixtures/corpus): names
/// and bytes, for the unit tests.
#[cfg(test)]
fn scene_files() -> Vec<(String, Vec<u8>)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["tests/fixtures/scenes", "tests/fixtures/corpus"] {
        for entry in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "xml") {
                files.push((path.display().to_string(), std::fs::read(&path).unwrap()));
            }
        }
    }
    assert!(files.len() >= 9, "the scene files are missing");
    files
}
