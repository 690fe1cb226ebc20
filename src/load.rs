//! A load, stage by stage: the input becomes text, the reader fills an arena with it,
//! resolve normalises the dialects and checks every reference, validate applies the rules
//! that need the whole scene, and the arena is frozen into the scene, its warnings placed
//! at their lines and columns.
#![forbid(unsafe_code)]

use std::path::Path;

use crate::arena::Arena;
use crate::error::{Error, Parsed, Severity};
use crate::input::{Locator, Source};
use crate::scene::{Diagnostic, Scene};
use crate::{LoadOptions, parse, resolve, validate};

/// Loads a scene from the bytes of a file.
pub fn load(bytes: &[u8], options: &LoadOptions) -> Result<Scene, Error> {
    finish(parse::read(Source::memory(bytes, options)?, options))
}

/// Loads a scene from a file, reading it a window at a time.
pub fn load_path(path: &Path, options: &LoadOptions) -> Result<Scene, Error> {
    finish(parse::read(Source::path(path, options)?, options))
}

/// Resolves, validates and freezes what was read, or places the error.
fn finish((source, read): (Source<'_>, Parsed<Arena>)) -> Result<Scene, Error> {
    let checked = read.and_then(|mut arena| {
        resolve::resolve(&mut arena)?;
        validate::dynamic_bodies_without_mass(&mut arena)?;
        Ok(arena)
    });
    let mut arena = match checked {
        Ok(arena) => arena,
        Err(problem) => {
            return Err(Error {
                code: problem.code,
                position: Locator::new(&source).locate(problem.at),
                message: problem.message,
            });
        }
    };
    if arena.has_warnings() {
        let mut locator = Locator::new(&source);
        for w in arena.take_warnings() {
            let position = locator.locate(w.at);
            let message = arena.scene.add_str(&w.message);
            arena.scene.diagnostics.push(Diagnostic {
                message,
                byte_offset: position.byte_offset,
                code: w.code as u32,
                severity: Severity::Warning as u32,
                line: position.line,
                column: position.column,
            });
        }
    }
    Ok(arena.scene.freeze())
}
