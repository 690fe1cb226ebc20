//! The command line, parsed by clap: the commands, their options and help, and what to
//! run. A command line that cannot be run is clap's error, which names the argument.

use std::ffi::{OsStr, OsString};
use std::path::PathBuf;

use box2scene::{Dialect, LoadOptions, WriteOptions};
use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::error::ErrorKind;
use clap::{Args, CommandFactory, Parser, Subcommand, ValueEnum};

/// Each command's help starts with its usage, then says what the command does.
const COMMAND_HELP: &str = "{usage-heading} {usage}\n\n{before-help}{all-args}{after-help}";

#[derive(Parser)]
#[command(
    name = "box2scene",
    version,
    about = "box2scene: check, dump, format and draw Box2Scene physics scenes.",
    override_usage = "box2scene COMMAND [OPTIONS] FILE...",
    after_help = "A FILE named '-' is standard input; after '--', every argument is a FILE.\n\
                  Exit status: 0 when no file has an error, 1 when one has, 2 on a usage or \
                  I/O error.",
    subcommand_required = true,
    arg_required_else_help = true
)]
struct Cli {
    #[command(subcommand)]
    verb: VerbArgs,
}

/// What every command that loads a file takes.
#[derive(Args)]
struct Load {
    #[arg(long, help = "Treat every warning as an error")]
    strict: bool,
}

#[derive(Subcommand)]
enum VerbArgs {
    #[command(
        about = "Print every warning and error of each file, with the line it points at",
        override_usage = "box2scene check [--strict] [--format=text|json] FILE...",
        help_template = COMMAND_HELP,
        before_help = "Loads each FILE and prints its errors and warnings in the order of the file,\n\
                       going on past a bad value or an ID that names nothing (a markup error\n\
                       ends the file), then (in text) a line with its counts: FILE: N errors,\n\
                       M warnings. A file that cannot be loaded does not stop the others.",
        after_help = "A FILE named '-' is standard input; after '--', every argument is a FILE.\n\
                      Lines and columns count from 1, columns in characters.\n\
                      Exit status: 0 when no file has an error, 1 when one has, 2 on a usage \
                      or I/O error.\n\
                      Warnings alone exit 0: in a level pipeline, run check --strict, so that\n\
                      a misspelt element or an angle in degrees fails the build."
    )]
    Check {
        #[command(flatten)]
        load: Load,
        #[arg(
            long,
            value_enum,
            default_value_t = Format::Text,
            value_name = "FORMAT",
            hide_default_value = true,
            hide_possible_values = true,
            help = "text: FILE:LINE:COLUMN: SEVERITY[CODE]: MESSAGE, then the line it\n\
                    points at and a caret under the column (the default);\n\
                    json: one JSON object a line with file, line, column, byte_offset,\n\
                    severity, code and message (line and column 0 when unknown)"
        )]
        format: Format,
        #[arg(required = true, value_name = "FILE", help = "The scenes to check")]
        files: Vec<PathBuf>,
    },
    #[command(
        about = "Print the loaded scene as JSON",
        override_usage = "box2scene dump [--strict] FILE",
        help_template = COMMAND_HELP,
        before_help = "Prints the loaded scene as JSON: its version and dialect, every field of every\n\
                       record, floats in their shortest round-trip form, the warnings included.",
        after_help = "A FILE named '-' is standard input; after '--', every argument is a FILE.\n\
                      Exit status: 0 when the file loads, 1 when it has an error, 2 on a usage \
                      or I/O error."
    )]
    Dump {
        #[command(flatten)]
        load: Load,
        #[arg(value_name = "FILE", help = "The scene to dump")]
        file: PathBuf,
    },
    #[command(
        about = "Write a file in canonical form",
        override_usage = "box2scene fmt [--strict] [--all-fields] [--dialect NAME] [-o OUT] FILE",
        help_template = COMMAND_HELP,
        before_help = "Writes FILE in canonical form, keeping its comments and the elements box2scene\n\
                       does not know, to standard output or to OUT (which may be FILE itself: it is\n\
                       replaced atomically). It keeps the dialect FILE was in (an engine's file\n\
                       stays that engine's, or fails naming what its reader cannot take) unless\n\
                       --dialect names another.",
        after_help = "A FILE named '-' is standard input; after '--', every argument is a FILE.\n\
                      Exit status: 0 when the file loads and is written, 1 when it has an error,\n\
                      2 on a usage or I/O error."
    )]
    Fmt {
        #[command(flatten)]
        load: Load,
        #[arg(long, help = "Write every field, also those equal to their defaults")]
        all_fields: bool,
        #[arg(
            long,
            value_name = "NAME",
            value_parser = dialect_named(),
            hide_possible_values = true,
            help = "Write for the reader NAME: box2scene (the editor's form),\n\
                    farseer-3.3, farseer-2013, farseer-3.5 (Velcro too) or aether;\n\
                    what that reader cannot hold is an error naming the object"
        )]
        dialect: Option<Dialect>,
        #[arg(short = 'o', value_name = "OUT", help = "Write to OUT instead of standard output")]
        out: Option<PathBuf>,
        #[arg(value_name = "FILE", help = "The scene to format")]
        file: PathBuf,
    },
    #[command(
        about = "Draw the scene as it starts, as SVG",
        override_usage = "box2scene render [--strict] [-o OUT.svg] FILE",
        help_template = COMMAND_HELP,
        before_help = "Draws the scene as it starts, as SVG, y up: every shape of every fixture where\n\
                       its body puts it, coloured by body type (static grey, kinematic green,\n\
                       dynamic blue), and each joint's anchors and the link between them in red.\n\
                       Names show as tooltips.",
        after_help = "A FILE named '-' is standard input; after '--', every argument is a FILE.\n\
                      Exit status: 0 when the file loads and is drawn, 1 when it has an error,\n\
                      2 on a usage or I/O error."
    )]
    Render {
        #[command(flatten)]
        load: Load,
        #[arg(
            short = 'o',
            value_name = "OUT.svg",
            help = "Write to OUT.svg instead of standard output"
        )]
        out: Option<PathBuf>,
        #[arg(value_name = "FILE", help = "The scene to draw")]
        file: PathBuf,
    },
}

/// `--dialect NAME`: one of the dialects' own names, which clap lists and suggests.
fn dialect_named() -> impl TypedValueParser<Value = Dialect> {
    PossibleValuesParser::new(Dialect::ALL.map(Dialect::name))
        .map(|name| Dialect::named(&name).expect("clap passes only a dialect's own name"))
}

/// The commands that read scene files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verb {
    Check,
    Dump,
    Fmt,
    Render,
}

/// Where a scene is read from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Input {
    Stdin,
    Path(PathBuf),
}

impl Input {
    /// `-` is standard input, as for most tools; `./-` names a file called `-`.
    fn named(path: PathBuf) -> Input {
        if path.as_os_str() == "-" { Input::Stdin } else { Input::Path(path) }
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
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

/// The command line `args` (without the program's name) as a command to run; otherwise
/// clap's error, which is the help or the version to print (its `use_stderr` false) or
/// what is wrong with the command line.
pub fn parse(args: &[OsString]) -> Result<Run, clap::Error> {
    let program = OsStr::new("box2scene");
    let argv = std::iter::once(program).chain(args.iter().map(OsString::as_os_str));
    let cli = Cli::try_parse_from(argv).map_err(|error| match help_asked(args) {
        // clap stops at the first slip; `--help` after a command wins over any other.
        Some(verb) if error.use_stderr() => {
            let asked = [program, verb, OsStr::new("--help")];
            Cli::try_parse_from(asked).err().unwrap_or(error)
        }
        _ => error,
    })?;
    let mut write = WriteOptions::default();
    let (verb, files, format, out, Load { strict }) = match cli.verb {
        VerbArgs::Check { load, format, files } => (Verb::Check, files, format, None, load),
        VerbArgs::Dump { load, file } => (Verb::Dump, vec![file], Format::Text, None, load),
        VerbArgs::Fmt { load, all_fields, dialect, out, file } => {
            write.all_fields = all_fields;
            write.dialect = dialect.map_or(write.dialect, |d| d as u32);
            (Verb::Fmt, vec![file], Format::Text, out, load)
        }
        VerbArgs::Render { load, out, file } => (Verb::Render, vec![file], Format::Text, out, load),
    };
    let load = LoadOptions { strict, ..LoadOptions::default() };
    let inputs: Vec<Input> = files.into_iter().map(Input::named).collect();
    // Standard input can be read only once.
    if inputs.iter().filter(|&input| *input == Input::Stdin).count() > 1 {
        let mut cli = Cli::command();
        cli.build();
        let check = cli.find_subcommand_mut("check").expect("check is a command");
        let problem = "standard input ('-') can be read only once";
        return Err(check.error(ErrorKind::ArgumentConflict, problem));
    }
    Ok(Run { verb, inputs, load, write, format, out })
}

/// The command `-h` or `--help` follows, before any `--`.
fn help_asked(args: &[OsString]) -> Option<&OsStr> {
    let (verb, rest) = args.split_first()?;
    let mut options = rest.iter().take_while(|arg| *arg != "--");
    options.any(|arg| arg == "-h" || arg == "--help").then_some(verb.as_os_str())
}
