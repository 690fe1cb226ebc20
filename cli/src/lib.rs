//! The `box2scene` command: check, dump, format and draw Box2Scene files in a level
//! pipeline. Its library target holds [`run`], so that the fuzz targets run what the
//! command runs; it uses only the box2scene library's public API, as any host would.
//!
//! `check` prints each diagnostic as compilers do (`FILE:LINE:COLUMN: warning[CODE]:
//! message`, the line, a caret under the column) so that editors and CI logs can jump to
//! it, or as JSON lines; `dump` prints the scene as JSON; `fmt` rewrites a file in
//! canonical form; `render` draws the scene as SVG. The exit status tells a build script
//! what happened without parsing the output.
//!
//! Every command loads its file from the path as a host does (standard input as a stream),
//! never holding it whole, and a report reads back only the lines it quotes.
#![forbid(unsafe_code)]

mod args;
mod quote;
mod report;

use std::ffi::OsString;
use std::fs::File;
use std::io::{self, Write};
use std::path::Path;

use box2scene::draw::Picture;
use box2scene::escape::terminal_text;
use box2scene::{Checked, Code, Error, LoadOptions, Position, Scene, Severity};

use args::{Format, Input, Run, Verb};
use quote::Quoted;
use report::Report;

/// The exit status, ordered so that a run over many files ends with the worst one.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Status {
    Clean = 0,
    LoadError = 1,
    UsageOrIo = 2,
}

/// Runs the command line `args` (without the program's name), printing to `out` and
/// `err` what the command prints to standard output and standard error, in plain text,
/// and returns its exit status: 0 when no file has an error, 1 when one has, 2 on a usage
/// or I/O error.
pub fn run(args: &[OsString], out: &mut dyn Write, err: &mut dyn Write) -> u8 {
    run_coloured(args, out, err, false)
}

/// [`run`], with what goes to `out` in colour when `colour` says so (standard output is a
/// terminal); standard error is always plain, escaped text.
pub fn run_coloured(
    args: &[OsString],
    out: &mut dyn Write,
    err: &mut dyn Write,
    colour: bool,
) -> u8 {
    let mut io = Io { out, err, colour };
    let status = match args::parse(args) {
        Ok(run) => match run.verb {
            Verb::Check => check(&run, &mut io),
            Verb::Dump => dump(&run, &mut io),
            Verb::Fmt => fmt(&run, &mut io),
            Verb::Render => render(&run, &mut io),
        },
        // The help and the version, asked for.
        Err(error) if !error.use_stderr() => {
            let text = error.render();
            io.emit(&if colour { text.ansi().to_string() } else { text.to_string() })
        }
        Err(error) => {
            let text = error.render().to_string();
            let escaped: Vec<String> = text.lines().map(terminal_text).collect();
            io.report(&(escaped.join("\n") + "\n"));
            Status::UsageOrIo
        }
    };
    status as u8
}

/// Where a command prints, and whether standard output takes colour.
struct Io<'a> {
    out: &'a mut dyn Write,
    err: &'a mut dyn Write,
    colour: bool,
}

impl Io<'_> {
    /// Writes to standard output. A closed or failing output is reported instead of
    /// panicking as `print!` would, so a pipeline gets status 2 and a message.
    fn emit(&mut self, text: &str) -> Status {
        match self.out.write_all(text.as_bytes()).and_then(|()| self.out.flush()) {
            Ok(()) => Status::Clean,
            Err(e) => self.complain(&format!("cannot write to standard output: {e}")),
        }
    }

    /// A report, or another text that is all escaped already, on standard error.
    fn report(&mut self, text: &str) {
        let _ = self.err.write_all(text.as_bytes());
    }

    /// `box2scene: PROBLEM` on standard error, escaped as a report is; status 2.
    fn complain(&mut self, problem: &str) -> Status {
        let _ = writeln!(self.err, "box2scene: {}", terminal_text(problem));
        Status::UsageOrIo
    }
}

/// How a command reads its file: as a host loads it, stopping at the first error, or
/// checked, going on past the errors it can (`check`).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Reading {
    Load,
    Check,
}

/// A file read as a command reads it, and where its lines are read back from.
struct Loaded {
    name: String,
    checked: Checked,
    quoted: Quoted,
}

impl Loaded {
    fn read(input: &Input, options: &LoadOptions, reading: Reading) -> Loaded {
        let name = input.name();
        let (checked, quoted) = match input {
            Input::Path(path) => match File::open(path) {
                Ok(file) => load_file(file, path, options, reading),
                Err(e) => (Checked::from(Err(Error::cannot_read(path, &e))), Quoted::nothing()),
            },
            Input::Stdin => load_stdin(Path::new(&name), options, reading),
        };
        Loaded { name, checked, quoted }
    }

    /// The scene, or None once its error is on standard error.
    fn scene_or_report(&self, io: &mut Io<'_>) -> Result<&Scene, Status> {
        if let Some(scene) = &self.checked.scene {
            return Ok(scene);
        }
        let error = &self.checked.errors[0];
        io.report(&Report::of_error(error).text(&self.name, &self.quoted, false));
        Err(status_of(error))
    }
}

/// Reads an open file: a regular one as a path is read, read back from where a report
/// quotes it; anything else (a pipe, a terminal) as a stream, copied as it is read.
fn load_file(
    file: File,
    name: &Path,
    options: &LoadOptions,
    reading: Reading,
) -> (Checked, Quoted) {
    match file.metadata() {
        Ok(meta) if meta.is_file() => {
            let quoted = Quoted::from(file.try_clone().ok());
            let checked = match reading {
                Reading::Load => Checked::from(box2scene::load_file(file, name, options)),
                Reading::Check => box2scene::check_file(file, name, options),
            };
            (checked, quoted)
        }
        _ => load_stream(file, name, options, reading),
    }
}

/// Reads a stream a window at a time, as a file, while a copy of what is read goes to a
/// file of this run's own (removed when it ends), which is all a report reads back.
fn load_stream(
    stream: impl io::Read,
    name: &Path,
    options: &LoadOptions,
    reading: Reading,
) -> (Checked, Quoted) {
    let quoted = Quoted::spool();
    let stream = quoted.copying(stream);
    let checked = match reading {
        Reading::Load => Checked::from(box2scene::load_reader(stream, name, options)),
        Reading::Check => box2scene::check_reader(stream, name, options),
    };
    (checked, quoted)
}

/// Standard input, through a handle of its own that is a file, so that a redirected file
/// is read as a file is.
#[cfg(unix)]
fn load_stdin(name: &Path, options: &LoadOptions, reading: Reading) -> (Checked, Quoted) {
    use std::os::fd::AsFd;
    match io::stdin().as_fd().try_clone_to_owned() {
        Ok(handle) => load_file(File::from(handle), name, options, reading),
        Err(_) => load_stream(io::stdin().lock(), name, options, reading),
    }
}

#[cfg(not(unix))]
fn load_stdin(name: &Path, options: &LoadOptions, reading: Reading) -> (Checked, Quoted) {
    load_stream(io::stdin().lock(), name, options, reading)
}

/// Checks every file, even after one fails, so that one run reports everything: every
/// error the check could go on past and every warning, in the order of the file.
fn check(run: &Run, io: &mut Io<'_>) -> Status {
    let mut worst = Status::Clean;
    for input in &run.inputs {
        let loaded = Loaded::read(input, &run.load, Reading::Check);
        let Checked { errors, warnings, stopped_at, .. } = &loaded.checked;
        let status = errors.iter().map(status_of).max().unwrap_or(Status::Clean);
        let mut found: Vec<(Severity, &Error)> =
            errors.iter().map(|e| (Severity::Error, e)).collect();
        found.extend(warnings.iter().map(|w| (Severity::Warning, w)));
        found.sort_by_key(|(_, e)| e.position.byte_offset);
        let reports: Vec<Report> = found.into_iter().map(|(s, e)| Report::of(s, e)).collect();
        let mut text: String = reports
            .iter()
            .map(|report| match run.format {
                Format::Text => report.text(&loaded.name, &loaded.quoted, io.colour),
                Format::Json => report.json(&loaded.name),
            })
            .collect();
        match run.format {
            Format::Text => text.push_str(&summary(&loaded.name, &reports, *stopped_at)),
            Format::Json => {
                if let Some(at) = stopped_at {
                    text.push_str(&Report::stopped(*at, STOPPED).json(&loaded.name));
                }
            }
        }
        worst = worst.max(status).max(io.emit(&text));
    }
    worst
}

/// What a check says where it stopped after a hundred errors.
const STOPPED: &str =
    "the check stopped at this error, after a hundred others: what follows it is not checked";

/// `FILE: N errors, M warnings` (or `no errors or warnings`), the last line of a file's
/// text check, as compilers end theirs; before it, when the check stopped short after a
/// hundred errors, a note of where (as GCC notes `-fmax-errors`), since the count is then
/// not the file's.
fn summary(file: &str, reports: &[Report], stopped_at: Option<Position>) -> String {
    let errors = reports.iter().filter(|r| r.is_error()).count();
    let counted = |n: usize, what: &str| format!("{n} {what}{}", if n == 1 { "" } else { "s" });
    let counts = match (errors, reports.len() - errors) {
        (0, 0) => "no errors or warnings".to_owned(),
        (errors, warnings) => {
            format!("{}, {}", counted(errors, "error"), counted(warnings, "warning"))
        }
    };
    let file = terminal_text(file);
    let stopped = stopped_at.map_or(String::new(), |Position { line, column, .. }| {
        format!("{file}:{line}:{column}: note: {STOPPED}\n")
    });
    format!("{stopped}{file}: {counts}\n")
}

fn dump(run: &Run, io: &mut Io<'_>) -> Status {
    let loaded = Loaded::read(&run.inputs[0], &run.load, Reading::Load);
    match loaded.scene_or_report(io) {
        Ok(scene) => io.emit(&scene.to_json()),
        Err(status) => status,
    }
}

/// Writes the file in canonical form, to `-o` or standard output: with its comments,
/// unknown elements and attributes and Farseer-only joints in their places. The file is
/// read whole before anything is written, so the output may be the file itself.
fn fmt(run: &Run, io: &mut Io<'_>) -> Status {
    let loaded = Loaded::read(&run.inputs[0], &run.load, Reading::Load);
    let scene = match loaded.scene_or_report(io) {
        Ok(scene) => scene,
        Err(status) => return status,
    };
    let written = match &run.out {
        None => scene.to_xml(&run.write).map(|text| io.emit(&text)),
        Some(out) => box2scene::write_path(scene, out, &run.write).map(|()| Status::Clean),
    };
    written.unwrap_or_else(|mut error| {
        if error.code == Code::DialectCannotHold && run.write.dialect == 0 {
            // The dialect was the file's own, not asked for: say how to leave it.
            error.message += &format!(
                " ({}'s own dialect; --dialect box2scene writes it in box2scene's form)",
                loaded.name
            );
        }
        let name = run.out.as_ref().map_or(loaded.name.clone(), |out| out.display().to_string());
        io.report(&Report::of_error(&error).text(&name, &Quoted::nothing(), false));
        status_of(&error)
    })
}

/// Draws the scene to `-o` (replaced as `fmt -o` replaces a file) or standard output.
fn render(run: &Run, io: &mut Io<'_>) -> Status {
    let loaded = Loaded::read(&run.inputs[0], &run.load, Reading::Load);
    let scene = match loaded.scene_or_report(io) {
        Ok(scene) => scene,
        Err(status) => return status,
    };
    // The scene where its file puts every body, titled with the file's name.
    let picture = Picture { title: &loaded.name, ..Picture::default() };
    let svg = match box2scene::draw::svg(scene, &picture) {
        Ok(svg) => svg,
        Err(error) => return io.complain(&error.message),
    };
    let Some(out) = &run.out else { return io.emit(&svg) };
    match box2scene::write_file(out, svg.as_bytes()) {
        Ok(()) => Status::Clean,
        Err(e) => io.complain(&format!("cannot write {}: {e}", out.display())),
    }
}

/// A file that cannot be read is the environment's problem, not the file's: status 2.
fn status_of(error: &Error) -> Status {
    if error.code == Code::Io { Status::UsageOrIo } else { Status::LoadError }
}
