//! `box2scene`: check, dump, format and draw Box2Scene files in a level pipeline.
//!
//! `check` prints each diagnostic as compilers do (`FILE:LINE:COLUMN: warning[CODE]:
//! message`, the line, a caret under the column) so that editors and CI logs can jump to
//! it, or as JSON lines; `dump` prints the scene as JSON; `fmt` rewrites a file in
//! canonical form; `render` draws the scene as SVG. The exit status tells a build script
//! what happened without parsing the output.

mod args;
mod render;
mod report;

use std::ffi::OsString;
use std::fs::File;
use std::io::{self, Read, Write};
use std::process::ExitCode;

use box2scene::{Code, Error, LoadOptions, Position, Scene};

use args::{Command, Format, Input, Run, Verb};
use report::{Report, Source};

/// The exit status, ordered so that a run over many files ends with the worst one.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Status {
    Clean = 0,
    LoadError = 1,
    UsageOrIo = 2,
}

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().skip(1).collect();
    let status = match args::parse(&args) {
        Ok(Command::Print(text)) => emit(&text),
        Ok(Command::Run(run)) => match run.verb {
            Verb::Check => check(&run),
            Verb::Dump => dump(&run),
            Verb::Fmt => fmt(&run),
            Verb::Render => render(&run),
        },
        Err(slip) => {
            eprintln!("box2scene: {slip}");
            Status::UsageOrIo
        }
    };
    ExitCode::from(status as u8)
}

/// A file read whole, and what loading those very bytes gave, so that a report shows the
/// line that was loaded.
struct Loaded {
    name: String,
    bytes: Vec<u8>,
    scene: Result<Scene, Error>,
}

impl Loaded {
    fn read(input: &Input, options: &LoadOptions) -> Loaded {
        let name = input.name();
        match read(input, options.max_input_bytes) {
            Ok(bytes) => {
                let scene = box2scene::load(&bytes, options);
                Loaded { name, bytes, scene }
            }
            Err(e) => {
                let error = Error {
                    code: Code::Io,
                    position: Position::default(),
                    message: format!("cannot read {name}: {e}"),
                };
                Loaded { name, bytes: Vec::new(), scene: Err(error) }
            }
        }
    }

    /// The scene, or None once its error is on standard error.
    fn scene_or_report(&self) -> Result<&Scene, Status> {
        self.scene.as_ref().map_err(|error| {
            eprint!("{}", Report::of_error(error).text(&self.name, &Source::new(&self.bytes)));
            status_of(error)
        })
    }
}

/// The input's bytes; one more than `max` at most, enough for the loader to refuse a file
/// that is too large without holding all of it.
fn read(input: &Input, max: u64) -> io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    let limit = max.saturating_add(1);
    match input {
        Input::Stdin => io::stdin().lock().take(limit).read_to_end(&mut bytes)?,
        Input::Path(path) => File::open(path)?.take(limit).read_to_end(&mut bytes)?,
    };
    Ok(bytes)
}

/// Checks every file, even after one fails, so that one run reports everything.
fn check(run: &Run) -> Status {
    let mut worst = Status::Clean;
    for input in &run.inputs {
        let loaded = Loaded::read(input, &run.load);
        let (status, reports) = match &loaded.scene {
            Ok(scene) => {
                let reports = scene.diagnostics().iter().map(|d| Report::of_diagnostic(scene, d));
                (Status::Clean, reports.collect())
            }
            Err(error) => (status_of(error), vec![Report::of_error(error)]),
        };
        let source = Source::new(&loaded.bytes);
        let text: String = reports
            .iter()
            .map(|report| match run.format {
                Format::Text => report.text(&loaded.name, &source),
                Format::Json => report.json(&loaded.name),
            })
            .collect();
        worst = worst.max(status).max(emit(&text));
    }
    worst
}

fn dump(run: &Run) -> Status {
    let loaded = Loaded::read(&run.inputs[0], &run.load);
    match loaded.scene_or_report() {
        Ok(scene) => emit(&scene.to_json()),
        Err(status) => status,
    }
}

/// Writes the file in canonical form, to `-o` or standard output: with its comments,
/// unknown elements and attributes and Farseer-only joints in their places. The file is
/// read whole before anything is written, so the output may be the file itself.
fn fmt(run: &Run) -> Status {
    let loaded = Loaded::read(&run.inputs[0], &run.load);
    let scene = match loaded.scene_or_report() {
        Ok(scene) => scene,
        Err(status) => return status,
    };
    let written = match &run.out {
        None => scene.to_xml(&run.write).map(|text| emit(&text)),
        Some(out) => box2scene::write_path(scene, out, &run.write).map(|()| Status::Clean),
    };
    written.unwrap_or_else(|error| {
        let name = run.out.as_ref().map_or(loaded.name.clone(), |out| out.display().to_string());
        eprint!("{}", Report::of_error(&error).text(&name, &Source::new(&[])));
        status_of(&error)
    })
}

/// Draws the scene to `-o` or standard output.
fn render(run: &Run) -> Status {
    let loaded = Loaded::read(&run.inputs[0], &run.load);
    let svg = match loaded.scene_or_report() {
        Ok(scene) => render::svg(scene),
        Err(status) => return status,
    };
    let Some(out) = &run.out else { return emit(&svg) };
    match std::fs::write(out, svg) {
        Ok(()) => Status::Clean,
        Err(e) => {
            eprintln!("box2scene: cannot write {}: {e}", out.display());
            Status::UsageOrIo
        }
    }
}

/// A file that cannot be read is the environment's problem, not the file's: status 2.
fn status_of(error: &Error) -> Status {
    if error.code == Code::Io { Status::UsageOrIo } else { Status::LoadError }
}

/// Writes to standard output. A closed or failing output is reported instead of panicking
/// as `print!` would, so a pipeline gets status 2 and a message.
fn emit(text: &str) -> Status {
    let mut stdout = io::stdout().lock();
    match stdout.write_all(text.as_bytes()).and_then(|()| stdout.flush()) {
        Ok(()) => Status::Clean,
        Err(e) => {
            eprintln!("box2scene: cannot write to standard output: {e}");
            Status::UsageOrIo
        }
    }
}
