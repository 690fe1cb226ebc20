//! `box2scene`: check, dump, format and draw Box2Scene files in a level pipeline (see this
//! crate's library target, which does the work).

use std::ffi::OsString;
use std::io::{self, IsTerminal};
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().skip(1).collect();
    // Colour on a terminal, unless NO_COLOR says otherwise (no-color.org).
    let colour =
        io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
    let (mut out, mut err) = (io::stdout().lock(), io::stderr().lock());
    ExitCode::from(box2scene_cli::run_coloured(&args, &mut out, &mut err, colour))
}
