//! The C API. Every export is here, in header order, each inside one panic boundary
//! (`guard`); this is the only module with `unsafe`.
//!
//! Conventions (also in `docs/api.md`): fallible functions return a `b2s_code` (0 = OK) and
//! fill an optional caller-owned `b2s_error`; pointers are checked for NULL; enum values
//! arrive as integers and are converted; a scene is immutable, owned by the library, and
//! freed by `b2s_scene_free`.

use std::ffi::{CStr, CString, c_char};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

use crate::draw::{Picture, Pose};
use crate::error::{Code, Error, Position};
use crate::options::{LoadOptions, WriteOptions};
use crate::scene::{Body, BodyKind, Fixture, Joint, JointKind, Scene, Shape, ShapeKind, Str};
use crate::scene::{Diagnostic, NONE, UserData, Vec2};
use crate::write::write_utf8;
use crate::{Builder, load, load_path, write_path};

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

/// A read-only view of a loaded scene: a pointer and a count per array. Valid until the
/// scene is freed.
#[repr(C)]
pub struct SceneView {
    /// The `shape_count` shapes.
    pub shapes: *const Shape,
    /// The `fixture_count` fixtures.
    pub fixtures: *const Fixture,
    /// The `body_count` bodies.
    pub bodies: *const Body,
    /// The `joint_count` joints.
    pub joints: *const Joint,
    /// The vertex pool that the `vertices` ranges of shapes index.
    pub vertices: *const Vec2,
    /// The fixture ID pool that the `fixtures` ranges of bodies index.
    pub fixture_ids: *const u32,
    /// The user data that `user_data` indices name.
    pub user_data: *const UserData,
    /// The load's warnings (`B2S_SEVERITY_WARNING`).
    pub diagnostics: *const Diagnostic,
    /// Number of items in `shapes`.
    pub shape_count: u32,
    /// Number of items in `fixtures`.
    pub fixture_count: u32,
    /// Number of items in `bodies`.
    pub body_count: u32,
    /// Number of items in `joints`.
    pub joint_count: u32,
    /// Number of items in `vertices`.
    pub vertex_count: u32,
    /// Number of items in `fixture_ids`.
    pub fixture_id_count: u32,
    /// Number of items in `user_data`.
    pub user_data_count: u32,
    /// Number of items in `diagnostics`.
    pub diagnostic_count: u32,
    /// The file's `Version`; 0 for an unversioned (legacy) file.
    pub version: u32,
    /// The file's `Gravity` (m/s²), meaningful only when `gravity_given`: there is no
    /// default gravity, the host decides.
    pub gravity: Vec2,
    /// The file gave a `Gravity`.
    pub gravity_given: bool,
}

/// A loaded scene (opaque). Immutable; free it with `b2s_scene_free`.
pub struct SceneHandle {
    scene: Scene,
    view: SceneView,
}

impl SceneHandle {
    fn new(scene: Scene) -> Box<SceneHandle> {
        let count = |n: usize| u32::try_from(n).expect("the loader caps counts below 2^32");
        let view = SceneView {
            shapes: scene.shapes().as_ptr(),
            fixtures: scene.fixtures().as_ptr(),
            bodies: scene.bodies().as_ptr(),
            joints: scene.joints().as_ptr(),
            vertices: scene.vertex_pool().as_ptr(),
            fixture_ids: scene.fixture_id_pool().as_ptr(),
            user_data: scene.user_data().as_ptr(),
            diagnostics: scene.diagnostics().as_ptr(),
            shape_count: count(scene.shapes().len()),
            fixture_count: count(scene.fixtures().len()),
            body_count: count(scene.bodies().len()),
            joint_count: count(scene.joints().len()),
            vertex_count: count(scene.vertex_pool().len()),
            fixture_id_count: count(scene.fixture_id_pool().len()),
            user_data_count: count(scene.user_data().len()),
            diagnostic_count: count(scene.diagnostics().len()),
            version: scene.version(),
            gravity: scene.gravity().unwrap_or_default(),
            gravity_given: scene.gravity().is_some(),
        };
        Box::new(SceneHandle { scene, view })
    }
}

// SAFETY: the view's pointers point into the handle's own immutable scene.
unsafe impl Send for SceneHandle {}
// SAFETY: as above; nothing in a handle is ever mutated after it is made.
unsafe impl Sync for SceneHandle {}

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
/// `options` is NULL or points to a `b2s_load_options`.
unsafe fn arg_options(options: *const LoadOptions) -> LoadOptions {
    // SAFETY: by the caller's contract.
    unsafe { options.as_ref() }.copied().unwrap_or_default()
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

/// The load options with every field at its default (the limits of `docs/format.md`,
/// strict off, threads chosen by box2scene). Start from this and change what you need.
#[unsafe(no_mangle)]
pub extern "C" fn b2s_load_options_default() -> LoadOptions {
    LoadOptions::default()
}

/// Loads the scene file at `path` (UTF-8). `options` may be NULL (defaults). On success
/// returns `B2S_CODE_OK` and stores a new scene in `*out_scene`; free it with
/// `b2s_scene_free`. On failure stores NULL there, returns the error's code and, when
/// `error` is not NULL, fills it. Thread-safe.
///
/// # Safety
/// `path` is NULL or NUL-terminated; `options` NULL or valid; `out_scene` NULL or
/// writable; `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_load_file(
    path: *const c_char,
    options: *const LoadOptions,
    out_scene: *mut *mut SceneHandle,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        scene_into(out_scene, error, || {
            let (path, options) = (arg_str(path, "path")?, arg_options(options));
            load_path(Path::new(path), &options)
        })
    }
}

/// Loads a scene from `size` bytes at `data` (a whole file's content). The scene keeps
/// no reference to `data`. Otherwise as `b2s_load_file`.
///
/// # Safety
/// `data` is NULL (only with `size` 0) or points to `size` readable bytes; the other
/// pointers as for `b2s_load_file`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_load_memory(
    data: *const u8,
    size: usize,
    options: *const LoadOptions,
    out_scene: *mut *mut SceneHandle,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        scene_into(out_scene, error, || {
            let bytes: &[u8] = match (data.is_null(), size) {
                (true, 0) => &[],
                (true, _) => return Err(simple_error(Code::NullArgument, "data is NULL")),
                // SAFETY: `size` readable bytes by the caller's contract.
                (false, _) => std::slice::from_raw_parts(data, size),
            };
            load(bytes, &arg_options(options))
        })
    }
}

/// Frees a scene and everything it owns. NULL is ignored.
///
/// # Safety
/// `scene` is NULL or a scene from this library that was not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_scene_free(scene: *mut SceneHandle) {
    guard(
        || (),
        || {
            if !scene.is_null() {
                // SAFETY: made by Box::into_raw in scene_into, freed once by contract.
                drop(unsafe { Box::from_raw(scene) });
            }
        },
    )
}

/// The scene's arrays. NULL for a NULL scene. Valid until the scene is freed.
///
/// # Safety
/// `scene` is NULL or a live scene.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_scene_get_view(scene: *const SceneHandle) -> *const SceneView {
    guard(std::ptr::null, || {
        // SAFETY: by the caller's contract.
        unsafe { scene.as_ref() }.map_or(std::ptr::null(), |h| &h.view)
    })
}

/// # Safety
/// As for the `b2s_scene_find_*` functions.
unsafe fn find(
    scene: *const SceneHandle,
    name: *const c_char,
    by_name: fn(&Scene, &str) -> Option<u32>,
) -> u32 {
    guard(
        || NONE,
        || {
            // SAFETY: by the caller's contract.
            let (Some(h), Ok(name)) = (unsafe { scene.as_ref() }, unsafe { arg_str(name, "") })
            else {
                return NONE;
            };
            by_name(&h.scene, name).unwrap_or(NONE)
        },
    )
}

/// The index of the first shape whose `Name` is `name`, or `B2S_NONE` (also for NULL
/// arguments).
///
/// # Safety
/// `scene` is NULL or a live scene; `name` NULL or NUL-terminated.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_scene_find_shape(
    scene: *const SceneHandle,
    name: *const c_char,
) -> u32 {
    // SAFETY: same contract.
    unsafe { find(scene, name, Scene::find_shape) }
}

/// The index of the first fixture whose `Name` is `name`, or `B2S_NONE`.
///
/// # Safety
/// As for `b2s_scene_find_shape`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_scene_find_fixture(
    scene: *const SceneHandle,
    name: *const c_char,
) -> u32 {
    // SAFETY: same contract.
    unsafe { find(scene, name, Scene::find_fixture) }
}

/// The index of the first body whose `Name` is `name`, or `B2S_NONE`.
///
/// # Safety
/// As for `b2s_scene_find_shape`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_scene_find_body(
    scene: *const SceneHandle,
    name: *const c_char,
) -> u32 {
    // SAFETY: same contract.
    unsafe { find(scene, name, Scene::find_body) }
}

/// The index of the first joint whose `Name` is `name`, or `B2S_NONE`.
///
/// # Safety
/// As for `b2s_scene_find_shape`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_scene_find_joint(
    scene: *const SceneHandle,
    name: *const c_char,
) -> u32 {
    // SAFETY: same contract.
    unsafe { find(scene, name, Scene::find_joint) }
}

/// The dialect `scene` was loaded in, a `b2s_dialect` value (`B2S_DIALECT_BOX2SCENE` for a
/// built scene): the one a write keeps when its options' `dialect` is 0. 0 when `scene` is
/// NULL.
///
/// # Safety
/// `scene` is NULL or a live scene.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_scene_dialect(scene: *const SceneHandle) -> u32 {
    guard(
        || 0,
        || {
            // SAFETY: by the caller's contract.
            unsafe { scene.as_ref() }.map_or(0, |handle| handle.scene.dialect() as u32)
        },
    )
}

/// The write options with every field at its default (defaults omitted, as the editor
/// wrote; in the dialect the scene remembers).
#[unsafe(no_mangle)]
pub extern "C" fn b2s_write_options_default() -> WriteOptions {
    WriteOptions::default()
}

/// # Safety
/// `scene` is NULL or a live scene; `options` NULL or valid.
unsafe fn scene_and_options<'a>(
    scene: *const SceneHandle,
    options: *const WriteOptions,
) -> Result<(&'a Scene, WriteOptions), Error> {
    // SAFETY: by the caller's contract.
    let handle = unsafe { scene.as_ref() }
        .ok_or_else(|| simple_error(Code::NullArgument, "scene is NULL"))?;
    // SAFETY: by the caller's contract.
    Ok((&handle.scene, unsafe { options.as_ref() }.copied().unwrap_or_default()))
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
            let (scene, _) = scene_and_options(scene, std::ptr::null())?;
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

/// A scene under construction (opaque): `b2s_builder_new`, then `b2s_builder_add_*`, then
/// `b2s_builder_finish` (or `b2s_builder_free` to abandon it). Not for use from two
/// threads at once.
pub struct BuilderHandle {
    builder: Builder,
}

/// A new, empty scene builder. Never NULL.
#[unsafe(no_mangle)]
pub extern "C" fn b2s_builder_new() -> *mut BuilderHandle {
    Box::into_raw(Box::new(BuilderHandle { builder: Builder::new() }))
}

/// Abandons a builder and everything added to it. NULL is ignored.
///
/// # Safety
/// `builder` is NULL or a builder that was not finished or freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_free(builder: *mut BuilderHandle) {
    guard(
        || (),
        || {
            if !builder.is_null() {
                // SAFETY: made by Box::into_raw in b2s_builder_new, freed once by contract.
                drop(unsafe { Box::from_raw(builder) });
            }
        },
    )
}

/// Reads an optional NUL-terminated string of a record.
///
/// # Safety
/// `s` is NULL or NUL-terminated.
unsafe fn optional_str<'a>(s: Str, what: &str) -> Result<Option<&'a str>, Error> {
    match s.is_null() {
        true => Ok(None),
        // SAFETY: by the caller's contract.
        false => unsafe { arg_str(s.0, what) }.map(Some),
    }
}

/// Runs one addition to a builder: checks the pointers, stores the new index.
///
/// # Safety
/// `builder` is NULL or a live builder; `record` NULL or valid; `out_index` NULL or
/// writable; `error` NULL or writable.
unsafe fn add<T>(
    builder: *mut BuilderHandle,
    record: *const T,
    out_index: *mut u32,
    error: *mut ErrorInfo,
    add: impl FnOnce(&mut Builder, &T) -> Result<u32, Error>,
) -> Code {
    fallible(error, || {
        // SAFETY: by the caller's contract.
        let (handle, record) = unsafe { (builder.as_mut(), record.as_ref()) };
        let handle = handle.ok_or_else(|| simple_error(Code::NullArgument, "builder is NULL"))?;
        let record =
            record.ok_or_else(|| simple_error(Code::NullArgument, "the record is NULL"))?;
        let index = add(&mut handle.builder, record)?;
        // SAFETY: by the caller's contract.
        if let Some(out) = unsafe { out_index.as_mut() } {
            *out = index;
        }
        Ok(())
    })
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

/// Sets the scene's gravity; NULL means none (the host decides).
///
/// # Safety
/// `builder` is NULL or a live builder; `gravity` NULL or valid; `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_set_gravity(
    builder: *mut BuilderHandle,
    gravity: *const Vec2,
    error: *mut ErrorInfo,
) -> Code {
    fallible(error, || {
        // SAFETY: by the caller's contract.
        let handle = unsafe { builder.as_mut() }
            .ok_or_else(|| simple_error(Code::NullArgument, "builder is NULL"))?;
        // SAFETY: by the caller's contract.
        handle.builder.set_gravity(unsafe { gravity.as_ref() }.copied())
    })
}

/// Adds user data; stores its index in `*out_index` (when not NULL), for the `user_data`
/// field of fixtures, bodies and joints added later. `raw` (XML content, kept verbatim)
/// wins; without it, `type_name` and `value` are written in the editor's form. The
/// stored `type_name` and `value` are those the loader would find in the raw XML.
///
/// # Safety
/// `builder` is NULL or a live builder; `user_data` NULL or valid, its strings NULL or
/// NUL-terminated; `out_index` and `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_user_data(
    builder: *mut BuilderHandle,
    user_data: *const UserData,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, user_data, out_index, error, |b, u| {
            let raw = optional_str(u.raw, "raw")?;
            let (type_name, value) =
                (optional_str(u.type_name, "type_name")?, optional_str(u.value, "value")?);
            b.add_user_data(raw, type_name, value)
        })
    }
}

/// Adds a shape (its `name` is copied; its `vertices` range is ignored: the `count`
/// vertices at `vertices` are copied instead) and stores its index in `*out_index`.
/// Refused with the loader's codes (`bad-radius`, `bad-vertex-count`,
/// `degenerate-polygon`, ...); the message names the shape's index.
///
/// # Safety
/// `builder` is NULL or a live builder; `shape` NULL or valid, its name NULL or
/// NUL-terminated; `vertices` NULL (with `count` 0) or `count` readable vectors;
/// `out_index` and `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_shape(
    builder: *mut BuilderHandle,
    shape: *const Shape,
    vertices: *const Vec2,
    count: u32,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, shape, out_index, error, |b, s| {
            let vertices = arg_slice(vertices, count as usize, "vertices")?;
            b.add_shape(s, optional_str(s.name, "name")?, vertices)
        })
    }
}

/// Adds a fixture on a shape added before; stores its index in `*out_index`.
///
/// # Safety
/// As for `b2s_builder_add_shape`, without vertices.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_fixture(
    builder: *mut BuilderHandle,
    fixture: *const Fixture,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, fixture, out_index, error, |b, f| {
            b.add_fixture(f, optional_str(f.name, "name")?)
        })
    }
}

/// Adds a body (its `fixtures` range is ignored: the `count` fixture indices at
/// `fixtures` are copied instead, each of a fixture added before); stores its index.
///
/// # Safety
/// As for `b2s_builder_add_shape`, with `fixtures` NULL (with `count` 0) or `count`
/// readable indices.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_body(
    builder: *mut BuilderHandle,
    body: *const Body,
    fixtures: *const u32,
    count: u32,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, body, out_index, error, |b, body| {
            let fixtures = arg_slice(fixtures, count as usize, "fixtures")?;
            b.add_body(body, optional_str(body.name, "name")?, fixtures)
        })
    }
}

/// Adds a joint between bodies added before (a gear: after the two joints it couples);
/// stores its index. Fields its kind does not have take that kind's defaults.
///
/// # Safety
/// As for `b2s_builder_add_fixture`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_joint(
    builder: *mut BuilderHandle,
    joint: *const Joint,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, joint, out_index, error, |b, j| b.add_joint(j, optional_str(j.name, "name")?))
    }
}

/// Finishes the builder into an ordinary immutable scene, stored in `*out_scene` (free it
/// with `b2s_scene_free`). The builder is freed in every case.
///
/// # Safety
/// `builder` is NULL or a builder that was not finished or freed yet; `out_scene` NULL or
/// writable; `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_finish(
    builder: *mut BuilderHandle,
    out_scene: *mut *mut SceneHandle,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: made by Box::into_raw in b2s_builder_new; taken once by contract.
    let handle = (!builder.is_null()).then(|| unsafe { Box::from_raw(builder) });
    // SAFETY: by the caller's contract.
    unsafe {
        scene_into(out_scene, error, || match handle {
            Some(handle) => Ok(handle.builder.finish()),
            None => Err(simple_error(Code::NullArgument, "builder is NULL")),
        })
    }
}

/// Writes into `*out` a shape of `kind` with every field at its default. Returns
/// `B2S_CODE_INVALID_ARGUMENT` for an unknown kind, `B2S_CODE_NULL_ARGUMENT` for a NULL
/// `out`.
///
/// # Safety
/// `out` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_shape_default(kind: RawShapeKind, out: *mut Shape) -> Code {
    // SAFETY: by the caller's contract.
    unsafe { write_default(out, ShapeKind::try_from(kind).ok().map(Shape::new)) }
}

/// Writes into `*out` a fixture with every field at its default.
///
/// # Safety
/// `out` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_fixture_default(out: *mut Fixture) -> Code {
    // SAFETY: by the caller's contract.
    unsafe { write_default(out, Some(Fixture::default())) }
}

/// Writes into `*out` a body of `kind` with every field at its default. Returns
/// `B2S_CODE_INVALID_ARGUMENT` for an unknown kind.
///
/// # Safety
/// `out` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_body_default(kind: RawBodyKind, out: *mut Body) -> Code {
    // SAFETY: by the caller's contract.
    unsafe { write_default(out, BodyKind::try_from(kind).ok().map(Body::new)) }
}

/// Writes into `*out` a joint of `kind` with every field at the default of that kind
/// (`docs/format.md` lists them). Returns `B2S_CODE_INVALID_ARGUMENT` for an unknown kind.
///
/// # Safety
/// `out` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_joint_default(kind: RawJointKind, out: *mut Joint) -> Code {
    // SAFETY: by the caller's contract.
    unsafe { write_default(out, JointKind::try_from(kind).ok().map(Joint::new)) }
}

/// # Safety
/// `out` is NULL or writable.
unsafe fn write_default<T>(out: *mut T, value: Option<T>) -> Code {
    guard(
        || Code::Internal,
        || match (out.is_null(), value) {
            (true, _) => Code::NullArgument,
            (false, None) => Code::InvalidArgument,
            (false, Some(value)) => {
                // SAFETY: not NULL, writable by the caller's contract.
                unsafe { out.write(value) };
                Code::Ok
            }
        },
    )
}

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
