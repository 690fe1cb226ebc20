//! A load, stage by stage: the input becomes text, the reader fills an arena with it (its
//! findings placed at their lines and columns as it goes), resolve normalises the dialects
//! and checks every reference, validate applies the rules that need the whole scene, and
//! the arena is frozen into the scene.
#![forbid(unsafe_code)]

use std::fs::File;
use std::io::Read;
use std::path::Path;

use crate::arena::Arena;
use crate::error::{Error, Finding, Parsed, Severity};
use crate::input::Source;
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

/// Loads a scene from an open file (a pipe too), read from its start as from its path;
/// `name` is its name in messages.
pub fn load_file(file: File, name: &Path, options: &LoadOptions) -> Result<Scene, Error> {
    finish(parse::read(Source::file(file, name, options)?, options))
}

/// Loads a scene from a stream read once, a window at a time; `name` is its name in
/// messages.
pub fn load_stream(stream: impl Read, name: &Path, options: &LoadOptions) -> Result<Scene, Error> {
    finish(parse::read(Source::stream(stream, name, options)?, options))
}

/// Resolves, validates and freezes what was read, or reports the problem, everything
/// placed at its line and column.
fn finish((read, placer): (Parsed<Arena>, parse::Placer<'_>)) -> Result<Scene, Error> {
    let checked = read.and_then(|mut arena| {
        resolve::resolve(&mut arena)?;
        validate::dynamic_bodies_without_mass(&mut arena)?;
        validate::joints_start_satisfied(&mut arena)?;
        Ok(arena)
    });
    let mut arena = match checked {
        Ok(arena) => arena,
        Err(problem) => {
            let mut found = [*problem];
            placer.place(&mut found);
            let [Finding { code, position, message, .. }] = found;
            return Err(Error { code, position: position.unwrap_or_default(), message });
        }
    };
    let mut warnings = arena.take_warnings();
    placer.place(&mut warnings);
    for w in warnings {
        let position = w.position.unwrap_or_default();
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
    Ok(arena.scene.freeze())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A load from a path places its warnings in the text it read, which it never reads
    /// again: a file saved over the path while the load runs changes nothing.
    #[cfg(unix)]
    #[test]
    fn positions_are_those_of_the_file_read() {
        let dir = std::env::temp_dir();
        let id = std::process::id();
        let (path, other) = (
            dir.join(format!("box2scene-load-{id}.xml")),
            dir.join(format!("box2scene-load-{id}-new.xml")),
        );
        let scene = |blank_lines: usize| {
            format!(
                "<World Version=\"1\">{}<Shapes/><Fixtures/><Bodies/><Joints/>\n  <Wind/>\n</World>",
                "\n".repeat(blank_lines)
            )
        };
        std::fs::write(&path, scene(1)).unwrap();
        std::fs::write(&other, scene(7)).unwrap();
        let options = LoadOptions::default();
        let source = Source::path(&path, &options).unwrap();
        std::fs::rename(&other, &path).unwrap();
        let scene = finish(parse::read(source, &options)).unwrap();
        std::fs::remove_file(&path).unwrap();
        let warning = &scene.diagnostics()[0];
        assert_eq!((warning.line, warning.column, warning.byte_offset), (3, 3, 61));
    }
}
