//! The C API: every export, each inside one panic boundary (`guard`), one submodule a
//! concern (`load`: loading and the scene's view; `write`: writing and drawing, and the
//! texts they hand out; `build`: the builder and the records' defaults; `capture`: a live world's records
//! turned into a scene; `library`: its
//! version and the codes' names; `plan`: what each engine version can be given), which the header lists in that order of their names
//! (cbindgen's). This module holds what they share: the error record, the panic boundary,
//! the checks of arguments. This is the only part of the crate with `unsafe`.
//!
//! Conventions (also in `docs/api.md`): fallible functions return a `b2s_code` (0 = OK) and
//! fill an optional caller-owned `b2s_error`; pointers are checked for NULL; enum values
//! arrive as integers and are converted; a scene is immutable, owned by the library, and
//! freed by `b2s_scene_free`.

use std::ffi::{CStr, c_char};
use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::error::{Code, Error, Position};
use crate::scene::{Scene, Str};

mod build;
mod capture;
mod library;
mod load;
mod plan;
mod write;

pub use build::*;
pub use capture::*;
pub use library::*;
pub use load::*;
pub use plan::*;
pub use write::*;

// SAFETY: a `Str` points into the string pool of the scene that holds it, which is never
// mutated after the scene is frozen; sharing or sending it is sharing immutable bytes.
unsafe impl Send for Str {}
// SAFETY: as above.
unsafe impl Sync for Str {}

// The kind parameters below name their enums in the C prototypes (cbindgen renames these
// aliases to the enums' typedefs, which it emits already, and so does not emit them), yet
// arrive as plain integers: a value from C is converted, never trusted to be a variant.

/// A `b2s_shape_kind` as C passes it: any integer, checked before use.
///
/// cbindgen:no-export
pub type RawShapeKind = u32;
/// A `b2s_body_kind` as C passes it: any integer, checked before use.
///
/// cbindgen:no-export
pub type RawBodyKind = u32;
/// A `b2s_joint_kind` as C passes it: any integer, checked before use.
///
/// cbindgen:no-export
pub type RawJointKind = u32;

/// Bytes in the `message` of a `b2s_error`, the terminating NUL included.
pub const ERROR_MESSAGE_SIZE: usize = 256;

/// Why a call failed. Owned by the caller; filled by the library when a call fails.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ErrorInfo {
    /// A `b2s_code` value; `B2S_CODE_OK` after a successful call.
    pub code: u32,
    /// 1-based line of the offending element or value; 0 when unknown.
    pub line: u32,
    /// 1-based column, in characters; 0 when unknown.
    pub column: u32,
    /// Byte offset in the input; 0 when unknown.
    pub byte_offset: u64,
    /// NUL-terminated UTF-8, cut at a character boundary to fit.
    pub message: [c_char; ERROR_MESSAGE_SIZE],
}

/// Runs `f`, turning a panic into `on_panic()`: no panic crosses the C boundary.
fn guard<R>(on_panic: impl FnOnce() -> R, f: impl FnOnce() -> R) -> R {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|_| on_panic())
}

/// Runs a fallible export: fills `error` (when not NULL) with the outcome, including a
/// caught panic, and returns its code.
fn fallible(error: *mut ErrorInfo, f: impl FnOnce() -> Result<(), Error>) -> Code {
    let outcome = guard(
        || {
            Err(simple_error(
                Code::Internal,
                "internal error (a bug in box2scene): please report it",
            ))
        },
        f,
    );
    let code = outcome.as_ref().err().map_or(Code::Ok, |e| e.code);
    // SAFETY: the caller passes NULL or a pointer to a writable b2s_error.
    if let Some(out) = unsafe { error.as_mut() } {
        *out = error_info(outcome.err().as_ref());
    }
    code
}

fn simple_error(code: Code, message: &str) -> Error {
    Error { code, position: Position::default(), message: message.to_owned() }
}

fn error_info(error: Option<&Error>) -> ErrorInfo {
    let mut info = ErrorInfo {
        code: Code::Ok as u32,
        line: 0,
        column: 0,
        byte_offset: 0,
        message: [0; ERROR_MESSAGE_SIZE],
    };
    if let Some(e) = error {
        info.code = e.code as u32;
        info.line = e.position.line;
        info.column = e.position.column;
        info.byte_offset = e.position.byte_offset;
        let mut end = e.message.len().min(ERROR_MESSAGE_SIZE - 1);
        while !e.message.is_char_boundary(end) {
            end -= 1;
        }
        for (dst, &src) in info.message.iter_mut().zip(&e.message.as_bytes()[..end]) {
            *dst = src as c_char;
        }
    }
    info
}

/// Reads a NUL-terminated argument; NULL and invalid UTF-8 are errors.
///
/// # Safety
/// `s` is NULL or points to a NUL-terminated string.
unsafe fn arg_str<'a>(s: *const c_char, what: &str) -> Result<&'a str, Error> {
    if s.is_null() {
        return Err(simple_error(Code::NullArgument, &format!("{what} is NULL")));
    }
    // SAFETY: not NULL, and NUL-terminated by the caller's contract.
    let s = unsafe { CStr::from_ptr(s) };
    s.to_str()
        .map_err(|_| simple_error(Code::InvalidArgument, &format!("{what} is not valid UTF-8")))
}

/// # Safety
/// `items` is NULL (only with `count` 0) or points to `count` readable items.
unsafe fn arg_slice<'a, T>(items: *const T, count: usize, what: &str) -> Result<&'a [T], Error> {
    match (items.is_null(), count) {
        (true, 0) => Ok(&[]),
        (true, _) => Err(simple_error(Code::NullArgument, &format!("{what} is NULL"))),
        // SAFETY: `count` readable items by the caller's contract.
        (false, _) => Ok(unsafe { std::slice::from_raw_parts(items, count) }),
    }
}

/// # Safety
/// `items` is NULL or points to `count` readable items.
unsafe fn optional_slice<'a, T>(items: *const T, count: usize) -> Option<&'a [T]> {
    // SAFETY: `count` readable items by the caller's contract.
    (!items.is_null()).then(|| unsafe { std::slice::from_raw_parts(items, count) })
}

/// Makes a scene for an export: `*out_scene` is NULL unless `make` succeeds, in which case
/// it owns the new scene; `error` is filled as by [`fallible`].
///
/// # Safety
/// `out_scene` is NULL or points to a writable `b2s_scene *`; `error` is NULL or writable.
unsafe fn scene_into(
    out_scene: *mut *mut SceneHandle,
    error: *mut ErrorInfo,
    make: impl FnOnce() -> Result<Scene, Error>,
) -> Code {
    fallible(error, || {
        // SAFETY: by the caller's contract.
        let out = unsafe { out_scene.as_mut() }
            .ok_or_else(|| simple_error(Code::NullArgument, "out_scene is NULL"))?;
        *out = std::ptr::null_mut();
        *out = Box::into_raw(SceneHandle::new(make()?));
        Ok(())
    })
}
