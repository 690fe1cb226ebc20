//! Writing a scene and drawing it: the texts the library hands out and frees.

use std::ffi::{CString, c_char};
use std::path::Path;

use super::{
    ErrorInfo, SceneHandle, arg_slice, arg_str, fallible, guard, optional_slice, simple_error,
};
use crate::draw::{Picture, Pose};
use crate::error::{Code, Error};
use crate::options::WriteOptions;
use crate::scene::{Scene, Vec2};
use crate::write::write_utf8;
use crate::write_path;

/// The write options with every field at its default (defaults omitted, as the editor
/// wrote; in the dialect the scene remembers).
#[unsafe(no_mangle)]
pub extern "C" fn b2s_write_options_default() -> WriteOptions {
    WriteOptions::default()
}

/// The scene a write or a drawing reads; NULL is an error.
///
/// # Safety
/// `scene` is NULL or a live scene.
unsafe fn arg_scene<'a>(scene: *const SceneHandle) -> Result<&'a Scene, Error> {
    // SAFETY: by the caller's contract.
    let handle = unsafe { scene.as_ref() }
        .ok_or_else(|| simple_error(Code::NullArgument, "scene is NULL"))?;
    Ok(&handle.scene)
}

/// # Safety
/// `scene` is NULL or a live scene; `options` NULL or valid.
unsafe fn scene_and_options<'a>(
    scene: *const SceneHandle,
    options: *const WriteOptions,
) -> Result<(&'a Scene, WriteOptions), Error> {
    // SAFETY: by the caller's contract.
    Ok(unsafe { (arg_scene(scene)?, options.as_ref().copied().unwrap_or_default()) })
}

/// Writes `scene` as Box2Scene XML into a new NUL-terminated UTF-8 text owned by the
/// library: stores it in `*out_text` (free it with `b2s_text_free`) and, when `out_size`
/// is not NULL, its length in bytes without the NUL. `options` may be NULL (defaults).
/// A loaded scene is written with everything its file held beyond the records
/// (comments, unknown elements and attributes, Farseer-only joints, in their places).
/// A joint of the unsupported kind that was built, not loaded, has no form to write:
/// `B2S_CODE_UNSUPPORTED_JOINT_TYPE`, naming it, and `*out_text` stays NULL. So has an
/// object given two unknown attributes of one name from different places of its file (a
/// Version 3 body, those of its Pairs): `B2S_CODE_DUPLICATE_ATTRIBUTE`, naming it.
///
/// # Safety
/// `scene` is NULL or a live scene; `options` NULL or valid; `out_text` NULL or writable;
/// `out_size` NULL or writable; `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_write_memory(
    scene: *const SceneHandle,
    options: *const WriteOptions,
    out_text: *mut *mut c_char,
    out_size: *mut usize,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    fallible(error, || unsafe {
        hand_out(out_text, out_size, || {
            let (scene, options) = scene_and_options(scene, options)?;
            write_utf8(scene, &options)
        })
    })
}

/// Frees a text from `b2s_write_memory` or `b2s_draw_svg`. NULL is ignored.
///
/// # Safety
/// `text` is NULL or a text from `b2s_write_memory` or `b2s_draw_svg` that was not freed
/// yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_text_free(text: *mut c_char) {
    guard(
        || (),
        || {
            if !text.is_null() {
                // SAFETY: made by CString::into_raw in b2s_write_memory, freed once.
                drop(unsafe { CString::from_raw(text) });
            }
        },
    )
}

/// Writes `scene` as Box2Scene XML to the file at `path` (UTF-8), replacing it
/// atomically: a new file beside it, flushed to disk, renamed over it. A failed write
/// leaves the old file as it was. The new file has the old one's permissions, owner and
/// group (those the caller may set) before its first byte; through a link, the link's
/// target is written, created if it does not exist. Otherwise as `b2s_write_memory`.
///
/// # Safety
/// `scene` is NULL or a live scene; `path` NULL or NUL-terminated; `options` NULL or
/// valid; `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_write_file(
    scene: *const SceneHandle,
    path: *const c_char,
    options: *const WriteOptions,
    error: *mut ErrorInfo,
) -> Code {
    fallible(error, || {
        // SAFETY: by the caller's contract.
        let (scene, options) = unsafe { scene_and_options(scene, options)? };
        // SAFETY: by the caller's contract.
        let path = unsafe { arg_str(path, "path")? };
        write_path(scene, Path::new(path), &options)
    })
}

/// What `b2s_draw_svg` draws beside the scene's shapes and joints; `b2s_picture_default`
/// gives a picture of the scene where its file puts every body, with no title.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct PictureInfo {
    /// The line on top, NUL-terminated UTF-8; NULL or empty for none.
    pub title: *const c_char,
    /// NULL (where the scene puts each body) or one pose per body of the scene, in its
    /// order. A pose that is not finite is not drawn (a body the host did not create).
    pub start: *const Pose,
    /// NULL (the start alone, solid) or one pose per body: where each ended; the start is
    /// then drawn faint.
    pub end: *const Pose,
    /// NULL (every joint of the scene) or one flag per joint: whether the host created it.
    /// A joint not created is not drawn.
    pub joints_created: *const bool,
    /// NULL (only with `trajectory_samples` 0) or `trajectory_samples` samples, each one
    /// point per body in the scene's order: the path each body's origin took. A point
    /// that is not finite breaks its body's path.
    pub trajectories: *const Vec2,
    /// How many samples `trajectories` holds.
    pub trajectory_samples: usize,
}

/// A picture of the scene where its file puts every body, with no title.
#[unsafe(no_mangle)]
pub extern "C" fn b2s_picture_default() -> PictureInfo {
    PictureInfo {
        title: std::ptr::null(),
        start: std::ptr::null(),
        end: std::ptr::null(),
        joints_created: std::ptr::null(),
        trajectories: std::ptr::null(),
        trajectory_samples: 0,
    }
}

/// Draws `scene` as an SVG document (`docs/api.md` shows one): every body's shapes
/// coloured by its type, its joints as Box2D's debug draw draws them, the names of named
/// bodies, a title and a key; where a host's simulation started and ended, and the path
/// between, when `picture` gives them (NULL: the defaults). Stores the document in
/// `*out_text` as `b2s_write_memory` does (free it with `b2s_text_free`).
/// `B2S_CODE_NULL_ARGUMENT` when `trajectories` is NULL with samples;
/// `B2S_CODE_INVALID_ARGUMENT` when `trajectory_samples` times the body count overflows or
/// the title is not UTF-8; `*out_text` then stays NULL.
///
/// # Safety
/// `scene` is NULL or a live scene; `picture` NULL or valid: its `start` and `end` NULL or
/// one pose per body of the scene, its `joints_created` NULL or one flag per joint, its
/// `trajectories` NULL or `trajectory_samples` times as many points as bodies; `out_text`
/// NULL or writable; `out_size` NULL or writable; `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_draw_svg(
    scene: *const SceneHandle,
    picture: *const PictureInfo,
    out_text: *mut *mut c_char,
    out_size: *mut usize,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    fallible(error, || unsafe {
        hand_out(out_text, out_size, || {
            let scene = arg_scene(scene)?;
            let info = picture.as_ref().copied().unwrap_or_else(|| b2s_picture_default());
            let bodies = scene.bodies().len();
            let points = info.trajectory_samples.checked_mul(bodies).ok_or_else(|| {
                simple_error(Code::InvalidArgument, "trajectory_samples is too large")
            })?;
            let title = match info.title.is_null() {
                true => "",
                false => arg_str(info.title, "the title")?,
            };
            let picture = Picture {
                title,
                start: optional_slice(info.start, bodies),
                end: optional_slice(info.end, bodies),
                joints: optional_slice(info.joints_created, scene.joints().len()),
                trajectories: arg_slice(info.trajectories, points, "trajectories")?,
            };
            crate::draw::svg(scene, &picture)
        })
    })
}

/// A call that hands out a text: `*out_text` is NULL until `make` made it, then the text,
/// NUL-terminated, for `b2s_text_free`; its length goes to `*out_size` when that is not NULL.
///
/// # Safety
/// `out_text` is NULL or writable; `out_size` NULL or writable.
unsafe fn hand_out<T: Into<Vec<u8>>>(
    out_text: *mut *mut c_char,
    out_size: *mut usize,
    make: impl FnOnce() -> Result<T, Error>,
) -> Result<(), Error> {
    // SAFETY: by the caller's contract.
    let out = unsafe { out_text.as_mut() }
        .ok_or_else(|| simple_error(Code::NullArgument, "out_text is NULL"))?;
    *out = std::ptr::null_mut();
    let text = CString::new(make()?)
        .map_err(|_| simple_error(Code::Internal, "the text made holds a NUL byte"))?;
    // SAFETY: by the caller's contract.
    if let Some(size) = unsafe { out_size.as_mut() } {
        *size = text.as_bytes().len();
    }
    *out = text.into_raw();
    Ok(())
}
