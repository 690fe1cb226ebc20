//! Loading, and a loaded scene's view, names and dialect.

use std::ffi::c_char;
use std::path::Path;

use super::{ErrorInfo, arg_str, guard, scene_into, simple_error};
use crate::error::Code;
use crate::options::LoadOptions;
use crate::scene::{Body, Fixture, Joint, Scene, Shape};
use crate::scene::{Diagnostic, NONE, UserData, Vec2};
use crate::{load, load_path};

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
    pub(super) scene: Scene,
    view: SceneView,
}

impl SceneHandle {
    pub(super) fn new(scene: Scene) -> Box<SceneHandle> {
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

/// # Safety
/// `options` is NULL or points to a `b2s_load_options`.
unsafe fn arg_options(options: *const LoadOptions) -> LoadOptions {
    // SAFETY: by the caller's contract.
    unsafe { options.as_ref() }.copied().unwrap_or_default()
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
