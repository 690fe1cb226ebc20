//! The command line: what to run, each command's help, and the one-line message for a
//! command line that cannot be run.

use std::ffi::{OsStr, OsString};
use std::fmt;
use std::path::PathBuf;

use box2scene::{Dialect, LoadOptions, WriteOptions};

const HELP: &str = "\
box2scene: check, dump, format and draw Box2Scene physics scenes.

Usage: box2scene COMMAND [OPTIONS] FILE...

Commands:
  check    print every warning and error of each file, with the line it points at
  dump     print the loaded scene as JSON
  fmt      write a file in canonical form
  render   draw the scene as it starts, as SVG
  help     print this help, or a command's (box2scene help COMMAND)

Options:
  -h, --help   print this help; after a command, that command's help
  --version    print the version

A FILE named '-' is standard input; after '--', every argument is a FILE.
Exit status: 0 when no file has an error, 1 when one has, 2 on a usage or I/O error.
";

const CHECK_HELP: &str = "\
Usage: box2scene check [--strict] [--format=text|json] FILE...

Loads each FILE and prints its warnings, or the error that stopped its load, then (in text)
a line with its counts: FILE: N errors, M warnings. A file that cannot be loaded does not
stop the others.

Options:
  --strict          treat every warning as an error
  --format=text     FILE:LINE:COLUMN: SEVERITY[CODE]: MESSAGE, then the line it points at
                    and a caret under the column (the default)
  --format=json     one JSON object a line with file, line, column, byte_offset, severity,
                    code and message (line and column 0 when unknown)
  -h, --help        print this help

A FILE named '-' is standard input; after '--', every argument is a FILE.
Lines and columns count from 1, columns in characters.
Exit status: 0 when no file has an error, 1 when one has, 2 on a usage or I/O error.
";

const DUMP_HELP: &str = "\
Usage: box2scene dump [--strict] FILE

Prints the loaded scene as JSON: its version and dialect, every field of every record,
floats in their shortest round-trip form, the warnings included.

Options:
  --strict     treat every warning as an error
  -h, --help   print this help

A FILE named '-' is standard input; after '--', every argument is a FILE.
Exit status: 0 when the file loads, 1 when it has an error, 2 on a usage or I/O error.
";

const FMT_HELP: &str = "\
Usage: box2scene fmt [--strict] [--all-fields] [--dialect NAME] [-o OUT] FILE

Writes FILE in canonical form, keeping its comments and the elements box2scene does not
know, to standard output or to OUT (which may be FILE itself: it is replaced atomically).
It keeps the dialect FILE was in (an engine's file stays that engine's) unless --dialect
names another.

Options:
  --strict          treat every warning as an error
  --all-fields      write every field, also those equal to their defaults
  --dialect NAME    write for the reader NAME: box2scene (the editor's form),
                    farseer-3.3, farseer-2013, farseer-3.5 (Velcro too) or aether; what
                    that reader cannot hold is an error naming the object
  -o OUT            write to OUT instead of standard output
  -h, --help     print this help

A FILE named '-' is standard input; after '--', every argument is a FILE.
Exit status: 0 when the file loads and is written, 1 when it has an error, 2 on a usage or
I/O error.
";

const RENDER_HELP: &str = "\
Usage: box2scene render [--strict] [-o OUT.svg] FILE

Draws the scene as it starts, as SVG, y up: every shape of every fixture where its body
puts it, coloured by body type (static grey, kinematic green, dynamic blue), and each
joint's anchors and the link between them in red. Names show as tooltips.

Options:
  --strict       treat every warning as an error
  -o OUT.svg     write to OUT.svg instead of standard output
  -h, --help     print this help

A FILE named '-' is standard input; after '--', every argument is a FILE.
Exit status: 0 when the file loads and is drawn, 1 when it has an error, 2 on a usage or
I/O error.
";

/// The commands that read scene files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verb {
    Check,
    Dump,
    Fmt,
    Render,
}

impl Verb {
    fn named(name: &OsStr) -> Option<Verb> {
        match name.to_str()? {
            "check" => Some(Verb::Check),
            "dump" => Some(Verb::Dump),
            "fmt" => Some(Verb::Fmt),
            "render" => Some(Verb::Render),
            _ => None,
        }
    }

    fn name(self) -> &'static str {
        match self {
            Verb::Check => "check",
            Verb::Dump => "dump",
            Verb::Fmt => "fmt",
            Verb::Render => "render",
        }
    }

    fn help(self) -> &'static str {
        match self {
            Verb::Check => CHECK_HELP,
            Verb::Dump => DUMP_HELP,
            Verb::Fmt => FMT_HELP,
            Verb::Render => RENDER_HELP,
        }
    }
}

/// Where a scene is read from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Input {
    Stdin,
    Path(PathBuf),
}

impl Input {
    /// `-` is standard input, as for most tools; `./-` names a file called `-`.
    fn named(arg: &OsStr) -> Input {
        if arg == "-" { Input::Stdin } else { Input::Path(PathBuf::from(arg)) }
    }

    /// The name reports give it.
    pub fn name(&self) -> String {
        match self {
            Input::Stdin => "<stdin>".to_owned(),
            Input::Path(path) => path.display().to_string(),
        }
    }
}

/// How `check` prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Text,
    Json,
}

/// A command to run on scene files, with every option it was given.
#[derive(Debug)]
pub struct Run {
    pub verb: Verb,
    pub inputs: Vec<Input>,
    pub load: LoadOptions,
    pub write: WriteOptions,
    pub format: Format,
    pub out: Option<PathBuf>,
}

pub enum Command {
    /// Prints this text and exits 0.
    Print(String),
    Run(Run),
}

/// What is wrong with a command line, and the help to read about it.
#[derive(Debug)]
pub struct Slip {
    problem: String,
    help: String,
}

impl Slip {
    fn general(problem: String) -> Slip {
        Slip { problem, help: "box2scene help".to_owned() }
    }

    fn of(verb: Verb, problem: String) -> Slip {
        Slip { problem, help: format!("box2scene {} --help", verb.name()) }
    }
}

impl fmt::Display for Slip {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}; see '{}'", self.problem, self.help)
    }
}

pub fn parse(args: &[OsString]) -> Result<Command, Slip> {
    let Some((first, rest)) = args.split_first() else {
        return Err(Slip::general("no command given".to_owned()));
    };
    let print = |text: &str| match rest.first() {
        None => Ok(Command::Print(text.to_owned())),
        Some(extra) => Err(Slip::general(format!("unexpected '{}'", extra.to_string_lossy()))),
    };
    match first.to_str() {
        Some("--help" | "-h") => print(HELP),
        Some("--version") => print(&format!("box2scene {}\n", env!("CARGO_PKG_VERSION"))),
        Some("help") => help(rest),
        _ => match Verb::named(first) {
            Some(verb) => parse_run(verb, rest),
            None => Err(Slip::general(format!("unknown command '{}'", first.to_string_lossy()))),
        },
    }
}

/// `help` alone, or `help COMMAND`.
fn help(args: &[OsString]) -> Result<Command, Slip> {
    match args {
        [] => Ok(Command::Print(HELP.to_owned())),
        [name] => match Verb::named(name) {
            Some(verb) => Ok(Command::Print(verb.help().to_owned())),
            None if name == "help" => Ok(Command::Print(HELP.to_owned())),
            None => Err(Slip::general(format!("unknown command '{}'", name.to_string_lossy()))),
        },
        [_, extra, ..] => Err(Slip::general(format!("unexpected '{}'", extra.to_string_lossy()))),
    }
}

/// A command's options and files; options may come anywhere before a `--`, after which
/// every argument is a file. `--help` anywhere before it wins over any other slip.
fn parse_run(verb: Verb, all: &[OsString]) -> Result<Command, Slip> {
    let options_end = all.iter().position(|a| a == "--").unwrap_or(all.len());
    let (options, files) = all.split_at(options_end);
    if options.iter().any(|a| a == "--help" || a == "-h") {
        return Ok(Command::Print(verb.help().to_owned()));
    }
    let slip = |problem: String| Slip::of(verb, problem);
    let mut run = Run {
        verb,
        inputs: Vec::new(),
        load: LoadOptions::default(),
        write: WriteOptions::default(),
        format: Format::Text,
        out: None,
    };
    let mut args = options.iter();
    while let Some(arg) = args.next() {
        let text = arg.to_str().unwrap_or_default();
        match text {
            "--strict" => run.load.strict = true,
            "--all-fields" if verb == Verb::Fmt => run.write.all_fields = true,
            "--dialect" if verb == Verb::Fmt => {
                let name = args.next().ok_or_else(|| slip("--dialect needs a NAME".to_owned()))?;
                run.write.dialect = dialect_named(&name.to_string_lossy()).map_err(slip)?;
            }
            _ if verb == Verb::Fmt && text.starts_with("--dialect=") => {
                run.write.dialect = dialect_named(&text["--dialect=".len()..]).map_err(slip)?;
            }
            "-o" if matches!(verb, Verb::Fmt | Verb::Render) => {
                let out = args.next().ok_or_else(|| slip("-o needs a file name".to_owned()))?;
                run.out = Some(PathBuf::from(out));
            }
            "--format" if verb == Verb::Check => {
                let name =
                    args.next().ok_or_else(|| slip("--format needs text or json".to_owned()))?;
                run.format = format_named(&name.to_string_lossy()).map_err(slip)?;
            }
            _ if verb == Verb::Check && text.starts_with("--format=") => {
                run.format = format_named(&text["--format=".len()..]).map_err(slip)?;
            }
            _ if arg != "-" && arg.as_encoded_bytes().starts_with(b"-") => {
                return Err(slip(format!(
                    "unknown option '{}' for {}",
                    arg.to_string_lossy(),
                    verb.name()
                )));
            }
            _ => run.inputs.push(Input::named(arg)),
        }
    }
    // `files` starts with the `--`, if there is one.
    run.inputs.extend(files.iter().skip(1).map(|file| Input::named(file)));
    check_inputs(&run).map_err(slip)?;
    Ok(Command::Run(run))
}

fn dialect_named(name: &str) -> Result<u32, String> {
    Dialect::named(name).map(|d| d as u32).ok_or_else(|| {
        let names: Vec<&str> = Dialect::ALL.iter().map(|d| d.name()).collect();
        format!("unknown dialect '{name}' ({})", names.join(", "))
    })
}

fn format_named(name: &str) -> Result<Format, String> {
    match name {
        "text" => Ok(Format::Text),
        "json" => Ok(Format::Json),
        _ => Err(format!("unknown format '{name}' (text or json)")),
    }
}

/// One FILE for every command but `check`, which takes any number but none; standard
/// input at most once, as it can be read only once.
fn check_inputs(run: &Run) -> Result<(), String> {
    let name = run.verb.name();
    match (run.verb, run.inputs.len()) {
        (Verb::Check, 0) => return Err("check needs at least one FILE".to_owned()),
        (Verb::Check, _) | (_, 1) => {}
        (_, 0) => return Err(format!("{name} needs a FILE")),
        (_, _) => return Err(format!("{name} takes one FILE")),
    }
    if run.inputs.iter().filter(|&input| *input == Input::Stdin).count() > 1 {
        return Err("standard input ('-') can be read only once".to_owned());
    }
    Ok(())
}
