//! `box2scene`: check, dump, format and draw Box2Scene files in a level pipeline (see this
//! crate's library target, which does the work).

use std::ffi::OsString;
use std::io;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().skip(1).collect();
    ExitCode::from(box2scene_cli::run(&args, &mut io::stdout().lock(), &mut io::stderr().lock()))
}
