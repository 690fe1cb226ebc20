//! The stage after the read: what needs the whole file. Farseer's layout is normalised and
//! every reference checked (`resolve`); then, when no error was found, the rules a whole
//! scene is held to (`scene`).
#![forbid(unsafe_code)]

mod resolve;
mod scene;

use crate::arena::Arena;
use crate::error::Parsed;

/// Resolves what was read and checks the whole scene. A load that goes on past errors
/// records every one it can, and checks the scene only when there is none.
pub(crate) fn run(arena: &mut Arena) -> Parsed<()> {
    resolve::resolve(arena)?;
    if arena.findings.has_errors() {
        return Ok(());
    }
    scene::dynamic_bodies_without_mass(arena)?;
    scene::joints_start_satisfied(arena)
}
