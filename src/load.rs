//! A load, stage by stage: the input becomes text, the reader fills an arena with it (its
//! findings placed at their lines and columns as it goes), the check stage normalises the
//! dialects, checks every reference and applies the rules that need the whole scene, and
//! the arena is frozen into the scene.
#![forbid(unsafe_code)]

use std::fs::File;
use std::io::Read;
use std::path::Path;

use crate::error::{Error, Finding, MAX_ERRORS, Position};
use crate::input::Source;
use crate::options::LoadOptions;
use crate::parse;
use crate::place::Placer;
use crate::scene::Scene;

/// Loads a scene from the bytes of a file.
pub fn load(bytes: &[u8], options: &LoadOptions) -> Result<Scene, Error> {
    first_error(finish(parse::read(Source::memory(bytes, options)?, options, false)))
}

/// Loads a scene from a file, reading it a window at a time.
pub fn load_path(path: &Path, options: &LoadOptions) -> Result<Scene, Error> {
    first_error(finish(parse::read(Source::path(path, options)?, options, false)))
}

/// Loads a scene from an open file (a pipe too), read from its start as from its path;
/// `name` is its name in messages.
pub fn load_file(file: File, name: &Path, options: &LoadOptions) -> Result<Scene, Error> {
    first_error(finish(parse::read(Source::file(file, name, options)?, options, false)))
}

/// Loads a scene from a stream read once, a window at a time; `name` is its name in
/// messages.
pub fn load_stream(stream: impl Read, name: &Path, options: &LoadOptions) -> Result<Scene, Error> {
    first_error(finish(parse::read(Source::stream(stream, name, options)?, options, false)))
}

/// What a load that goes on past the errors it can found: the scene when there was no
/// error, else every error (see [`crate::check()`]).
#[derive(Debug)]
pub struct Checked {
    /// The scene, when the file has no error. A check writes nothing, so it keeps none of
    /// the file's text for the writer (comments, unknown elements and attributes): write the
    /// scene a load gives.
    pub scene: Option<Scene>,
    /// Every error, in the order of the file: those the load went on past (a value that
    /// does not convert or is out of range, an ID that names nothing), and the one that
    /// ended it, when one did (a markup error, a limit, a missing element or attribute). At
    /// most one error a place. Empty when `scene` is some.
    pub errors: Vec<Error>,
    /// The warnings, in the order of the file, each as an [`Error`] value holds one: its
    /// code, position and message. A scene's are its diagnostics too.
    pub warnings: Vec<Error>,
    /// Where the check stopped short: the position of the error it stopped at, after the
    /// hundred it went on past; none of what it would have checked after that error was
    /// checked, and more errors may be there. None when the check stopped sooner or not at
    /// all.
    pub stopped_at: Option<Position>,
}

/// Checks a file as [`load_file`] loads it, going on past the errors it can (see
/// [`Checked`]), on one thread.
pub fn check_file(file: File, name: &Path, options: &LoadOptions) -> Checked {
    let options = &one_thread(options);
    checked(Source::file(file, name, options), options)
}

/// Checks a stream as [`load_stream`] loads it, going on past the errors it can.
pub fn check_stream(stream: impl Read, name: &Path, options: &LoadOptions) -> Checked {
    let options = &one_thread(options);
    checked(Source::stream(stream, name, options), options)
}

/// Checks the bytes of a file as [`load`] loads them, going on past the errors it can.
pub fn check(bytes: &[u8], options: &LoadOptions) -> Checked {
    let options = &one_thread(options);
    checked(Source::memory(bytes, options), options)
}

/// A read that goes on past errors reads on one thread: what a second thread reads ahead
/// stops at an error of its piece, and its pieces would have to carry errors as they carry
/// warnings.
fn one_thread(options: &LoadOptions) -> LoadOptions {
    LoadOptions { threads: 1, ..*options }
}

/// The check of `source`, or the error that kept it from being read.
fn checked(source: Result<Source<'_>, Error>, options: &LoadOptions) -> Checked {
    match source {
        Ok(source) => finish(parse::read(source, options, true)),
        Err(error) => Checked::from(Err(error)),
    }
}

/// A load's result as a check gives it: the scene (its warnings are its diagnostics), or
/// the one error.
impl From<Result<Scene, Error>> for Checked {
    fn from(loaded: Result<Scene, Error>) -> Checked {
        match loaded {
            Ok(scene) => Checked {
                scene: Some(scene),
                errors: Vec::new(),
                warnings: Vec::new(),
                stopped_at: None,
            },
            Err(error) => {
                Checked { scene: None, errors: vec![error], warnings: Vec::new(), stopped_at: None }
            }
        }
    }
}

/// A load's result: the scene or its first error.
fn first_error(checked: Checked) -> Result<Scene, Error> {
    match checked.scene {
        Some(scene) => Ok(scene),
        None => {
            Err(checked.errors.into_iter().next().expect("a load without a scene has an error"))
        }
    }
}

/// Resolves, validates and freezes what was read, or reports the errors, everything placed
/// at its line and column.
fn finish((read, placer): parse::Read<'_>) -> Checked {
    let mut arena = match read {
        Ok(arena) => arena,
        Err(stopped) => return failed(stopped.errors, stopped.warnings, &placer),
    };
    let checked = crate::check::run(&mut arena);
    let mut errors = arena.findings.take_errors();
    errors.extend(checked.err().map(|problem| *problem));
    let mut warnings = arena.findings.take_warnings();
    if !errors.is_empty() {
        return failed(errors, warnings, &placer);
    }
    placer.place(&mut warnings);
    let mut kept = Vec::with_capacity(warnings.len());
    for w in warnings {
        arena.scene.push_warning(w.code, w.at.position(), &w.message);
        kept.push(error_of(w));
    }
    Checked {
        scene: Some(arena.scene.freeze()),
        errors: Vec::new(),
        warnings: kept,
        stopped_at: None,
    }
}

/// A load without a scene: its errors and warnings, placed. The errors are in the order
/// found, the one that ended the load, if one did, last: past [`MAX_ERRORS`] gone on past,
/// the check stopped there.
fn failed(mut errors: Vec<Finding>, mut warnings: Vec<Finding>, placer: &Placer<'_>) -> Checked {
    placer.place(&mut warnings);
    placer.place(&mut errors);
    let stopped_at = match errors.len() > MAX_ERRORS {
        true => errors.last().map(|last| last.at.position()),
        false => None,
    };
    let warnings = warnings.into_iter().map(error_of).collect();
    Checked { scene: None, errors: placed(errors, placer), warnings, stopped_at }
}

/// `errors` placed at their lines and columns, in the order of the file, one a place: an ID
/// that did not convert is not reported again as naming nothing.
fn placed(mut errors: Vec<Finding>, placer: &Placer<'_>) -> Vec<Error> {
    errors.sort_by_key(Finding::order);
    errors.dedup_by_key(|e| e.order());
    placer.place(&mut errors);
    errors.into_iter().map(error_of).collect()
}

fn error_of(Finding { code, at, message }: Finding) -> Error {
    Error { code, position: at.position(), message }
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
        let scene = first_error(finish(parse::read(source, &options, false))).unwrap();
        std::fs::remove_file(&path).unwrap();
        let warning = &scene.diagnostics()[0];
        assert_eq!((warning.line, warning.column, warning.byte_offset), (3, 3, 61));
    }
}
