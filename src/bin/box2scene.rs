//! `box2scene`: check, dump and format Box2Scene files in a level pipeline.
//!
//! `check` prints one compiler-style line per diagnostic (`FILE:LINE:COLUMN: warning[CODE]:
//! message`) so that editors and CI logs can jump to it; `dump` prints the scene as JSON;
//! `fmt` rewrites a file in canonical form.
//! The exit status tells a build script what happened without parsing the output.

use std::ffi::OsString;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use box2scene::{Code, Diagnostic, Error, LoadOptions, Position, Scene, Severity, WriteOptions};

const USAGE: &str = "\
Usage:
  box2scene check [--strict] FILE...   print every warning and error of each file
  box2scene dump [--strict] FILE       print the scene as JSON
  box2scene fmt [--strict] [--all-fields] [-o OUT] FILE
                                       write FILE in canonical form to standard output,
                                       or to OUT (which may be FILE itself)
  box2scene --help | -h                print this help
  box2scene --version                  print the version

Options:
  --strict       treat every warning as an error
  --all-fields   fmt: write every field, also those equal to their defaults
  -o OUT         fmt: write to OUT instead of standard output

Exit status: 0 when no file has an error, 1 when one has, 2 on a usage or I/O error.
";

/// The exit status, ordered so that a run over many files ends with the worst one.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Status {
    Clean = 0,
    LoadError = 1,
    UsageOrIo = 2,
}

enum Command {
    Help,
    Version,
    Check { files: Vec<PathBuf>, options: LoadOptions },
    Dump { file: PathBuf, options: LoadOptions },
    Fmt { file: PathBuf, out: Option<PathBuf>, options: LoadOptions, write: WriteOptions },
}

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().skip(1).collect();
    let status = match parse_command(&args) {
        Ok(command) => run(command),
        Err(problem) => {
            eprint!("box2scene: {problem}\n\n{USAGE}");
            Status::UsageOrIo
        }
    };
    ExitCode::from(status as u8)
}

fn run(command: Command) -> Status {
    match command {
        Command::Help => emit(USAGE),
        Command::Version => emit(&format!("box2scene {}\n", env!("CARGO_PKG_VERSION"))),
        Command::Check { files, options } => check(&files, &options),
        Command::Dump { file, options } => dump(&file, &options),
        Command::Fmt { file, out, options, write } => fmt(&file, out.as_deref(), &options, &write),
    }
}

/// Reads the command line; the error is what was wrong with it, for the usage message.
fn parse_command(args: &[OsString]) -> Result<Command, String> {
    let Some((command, rest)) = args.split_first() else {
        return Err("no command given".to_owned());
    };
    match command.to_str() {
        Some("--help" | "-h") => Ok(Command::Help),
        Some("--version") => Ok(Command::Version),
        Some("check") => {
            let (files, options) = parse_load_args(rest)?;
            if files.is_empty() {
                return Err("check needs at least one FILE".to_owned());
            }
            Ok(Command::Check { files, options })
        }
        Some("dump") => {
            let (files, options) = parse_load_args(rest)?;
            match <[PathBuf; 1]>::try_from(files) {
                Ok([file]) => Ok(Command::Dump { file, options }),
                Err(_) => Err("dump needs exactly one FILE".to_owned()),
            }
        }
        Some("fmt") => parse_fmt_args(rest),
        _ => Err(format!("unknown command '{}'", command.to_string_lossy())),
    }
}

/// The files and load options of `check` and `dump`; options may come anywhere.
fn parse_load_args(args: &[OsString]) -> Result<(Vec<PathBuf>, LoadOptions), String> {
    let mut options = LoadOptions::default();
    let mut files = Vec::new();
    for arg in args {
        if arg == "--strict" {
            options.strict = true;
        } else if arg.as_encoded_bytes().starts_with(b"-") {
            return Err(format!("unknown option '{}'", arg.to_string_lossy()));
        } else {
            files.push(PathBuf::from(arg));
        }
    }
    Ok((files, options))
}

/// `fmt`'s arguments: its own options, then those of every loading command.
fn parse_fmt_args(args: &[OsString]) -> Result<Command, String> {
    let mut write = WriteOptions::default();
    let mut out = None;
    let mut rest = Vec::new();
    let mut args = args.iter();
    while let Some(arg) = args.next() {
        if arg == "--all-fields" {
            write.all_fields = true;
        } else if arg == "-o" {
            let path = args.next().ok_or("-o needs a file name")?;
            out = Some(PathBuf::from(path));
        } else {
            rest.push(arg.clone());
        }
    }
    let (files, options) = parse_load_args(&rest)?;
    match <[PathBuf; 1]>::try_from(files) {
        Ok([file]) => Ok(Command::Fmt { file, out, options, write }),
        Err(_) => Err("fmt needs exactly one FILE".to_owned()),
    }
}

/// Checks every file, even after one fails, so that one run reports everything.
fn check(files: &[PathBuf], options: &LoadOptions) -> Status {
    let mut worst = Status::Clean;
    for file in files {
        let (status, lines) = check_file(file, options);
        worst = worst.max(status).max(emit(&lines));
    }
    worst
}

/// The file's status and its report, one line per diagnostic or the load error.
fn check_file(file: &Path, options: &LoadOptions) -> (Status, String) {
    match box2scene::load_path(file, options) {
        Ok(scene) => {
            let lines: String = scene
                .diagnostics()
                .iter()
                .map(|d| diagnostic_line(file, &scene, d) + "\n")
                .collect();
            (Status::Clean, lines)
        }
        Err(error) => (status_of(&error), error_line(file, &error) + "\n"),
    }
}

fn dump(file: &Path, options: &LoadOptions) -> Status {
    match box2scene::load_path(file, options) {
        Ok(scene) => emit(&scene.to_json()),
        Err(error) => {
            eprintln!("{}", error_line(file, &error));
            status_of(&error)
        }
    }
}

/// Loads `file` and writes it in canonical form, to `out` or standard output: with its
/// comments, unknown elements and attributes and Farseer-only joints in their places. The
/// file is read whole before anything is written, so `out` may be `file` itself.
fn fmt(file: &Path, out: Option<&Path>, options: &LoadOptions, write: &WriteOptions) -> Status {
    let scene = match box2scene::load_path(file, options) {
        Ok(scene) => scene,
        Err(error) => {
            eprintln!("{}", error_line(file, &error));
            return status_of(&error);
        }
    };
    let written = match out {
        None => scene.to_xml(write).map(|text| emit(&text)),
        Some(out) => box2scene::write_path(&scene, out, write).map(|()| Status::Clean),
    };
    written.unwrap_or_else(|error| {
        eprintln!("{}", error_line(out.unwrap_or(file), &error));
        status_of(&error)
    })
}

/// A file that cannot be read is the environment's problem, not the file's: status 2.
fn status_of(error: &Error) -> Status {
    if error.code == Code::Io { Status::UsageOrIo } else { Status::LoadError }
}

fn error_line(file: &Path, error: &Error) -> String {
    report_line(file, error.position, Severity::Error.name(), error.code.name(), &error.message)
}

fn diagnostic_line(file: &Path, scene: &Scene, d: &Diagnostic) -> String {
    // A loaded scene's diagnostics carry known codes and severities; a value without a
    // name is shown as its number rather than guessed.
    let code = d.code().map_or_else(|| d.code.to_string(), |c| c.name().to_owned());
    let severity = d.severity().map_or_else(|| d.severity.to_string(), |s| s.name().to_owned());
    let message = scene.text(d.message).unwrap_or_default();
    report_line(file, d.position(), &severity, &code, message)
}

/// `FILE:LINE:COLUMN: SEVERITY[CODE]: MESSAGE`, leaving out the parts of the position that
/// are unknown (0), as compilers do.
fn report_line(file: &Path, at: Position, severity: &str, code: &str, message: &str) -> String {
    let file = file.display();
    let place = match (at.line, at.column) {
        (0, _) => format!("{file}"),
        (line, 0) => format!("{file}:{line}"),
        (line, column) => format!("{file}:{line}:{column}"),
    };
    format!("{place}: {severity}[{code}]: {message}")
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
