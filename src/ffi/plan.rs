//! The plan for each engine version: today its working range.

use std::ptr;

use super::guard;
use crate::plan::{Engine, WorkingRange};

/// The working range of an engine version (a `b2s_engine` number): the bounds its executor
/// checks, each measured (docs/working-range.md). Static storage, never freed; NULL for a
/// number that is no engine version.
#[unsafe(no_mangle)]
pub extern "C" fn b2s_engine_working_range(engine: u32) -> *const WorkingRange {
    guard(ptr::null, || {
        Engine::try_from(engine).map_or(ptr::null(), |e| ptr::from_ref(e.working_range()))
    })
}
