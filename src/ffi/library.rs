//! The library itself: its version and the names of its codes.

use std::ffi::{CStr, c_char};

use super::guard;
use crate::error::Code;

const VERSION: &CStr =
    match CStr::from_bytes_with_nul(concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes()) {
        Ok(version) => version,
        Err(_) => panic!("the package version holds a NUL"),
    };

/// The library's version, `"MAJOR.MINOR.PATCH"` (the same as `B2S_VERSION_STRING` of the
/// header it was built with). Static storage.
#[unsafe(no_mangle)]
pub extern "C" fn b2s_version() -> *const c_char {
    VERSION.as_ptr()
}

/// The kebab-case name of a code (`"id-out-of-range"`), or `"unknown-code"` for a number
/// that is no code (so it takes any integer, not only a `b2s_code`). Static storage.
#[unsafe(no_mangle)]
pub extern "C" fn b2s_code_name(code: u32) -> *const c_char {
    guard(
        || c"unknown-code".as_ptr(),
        || Code::from_u32(code).map_or(c"unknown-code", Code::c_name).as_ptr(),
    )
}
