//! The plan for each engine version: its working range, and the plan of a scene, which an
//! executor carries out through its engine's own calls.

use std::ptr;

use super::{ErrorInfo, SceneHandle, fallible, guard, simple_error};
use crate::error::Code;
use crate::plan::{self, Engine, Plan, PlanOptions, PlanView, WorkingRange};
use crate::scene::Vec2;

/// The working range of an engine version (a `b2s_engine` number): the bounds its executor
/// checks, each measured (docs/working-range.md). Static storage, never freed; NULL for a
/// number that is no engine version.
#[unsafe(no_mangle)]
pub extern "C" fn b2s_engine_working_range(engine: u32) -> *const WorkingRange {
    guard(ptr::null, || {
        Engine::try_from(engine).map_or(ptr::null(), |e| ptr::from_ref(e.working_range()))
    })
}

/// A plan (opaque): what one engine version creates for a scene. It needs nothing of the
/// scene once made; free it with `b2s_plan_free`.
pub struct PlanHandle {
    view: PlanView,
    // The view points into it: it is never changed after the view is taken.
    _plan: Plan,
}

// SAFETY: the view's pointers point into the handle's own plan, never mutated after it is
// made; its texts are owned by the plan.
unsafe impl Send for PlanHandle {}
// SAFETY: as above.
unsafe impl Sync for PlanHandle {}

/// Makes the plan of `scene` for the engine version and placement `options` give. On
/// success returns `B2S_CODE_OK` and stores a new plan in `*out_plan`; free it with
/// `b2s_plan_free`. A placement the engine cannot take is no failure: the plan then holds
/// only its report and its view's `placed` is false. An engine number that names no
/// version fails with `B2S_CODE_INVALID_ARGUMENT`. On failure stores NULL there, returns the error's code and,
/// when `error` is not NULL, fills it. Thread-safe.
///
/// # Safety
/// `scene` is NULL or a live scene; `options` NULL or valid; `out_plan` NULL or writable;
/// `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_plan_make(
    scene: *const SceneHandle,
    options: *const PlanOptions,
    out_plan: *mut *mut PlanHandle,
    error: *mut ErrorInfo,
) -> Code {
    fallible(error, || {
        // SAFETY: by the caller's contract.
        let out = unsafe { out_plan.as_mut() }
            .ok_or_else(|| simple_error(Code::NullArgument, "out_plan is NULL"))?;
        *out = ptr::null_mut();
        // SAFETY: by the caller's contract.
        let scene = unsafe { scene.as_ref() }
            .ok_or_else(|| simple_error(Code::NullArgument, "scene is NULL"))?;
        // SAFETY: by the caller's contract.
        let options = unsafe { options.as_ref() }
            .ok_or_else(|| simple_error(Code::NullArgument, "options is NULL"))?;
        let plan = plan::make(&scene.scene, options)?;
        *out = Box::into_raw(Box::new(PlanHandle { view: plan.view(), _plan: plan }));
        Ok(())
    })
}

/// The plan's arrays. NULL for a NULL plan. Valid until the plan is freed.
///
/// # Safety
/// `plan` is NULL or a live plan.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_plan_get_view(plan: *const PlanHandle) -> *const PlanView {
    guard(ptr::null, || {
        // SAFETY: by the caller's contract.
        unsafe { plan.as_ref() }.map_or(ptr::null(), |h| &h.view)
    })
}

/// Frees a plan and everything it owns. NULL is ignored.
///
/// # Safety
/// `plan` is NULL or a plan from `b2s_plan_make` that was not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_plan_free(plan: *mut PlanHandle) {
    guard(
        || (),
        || {
            if !plan.is_null() {
                // SAFETY: made by Box::into_raw in b2s_plan_make, freed once by contract.
                drop(unsafe { Box::from_raw(plan) });
            }
        },
    )
}

/// The gravity a world of engine version `engine` is made with for `scene`: the file's
/// where it gives one within that version's working range, else `fallback` (the host's;
/// the plan reports a gravity beyond the range). `fallback` for a NULL scene or a number
/// that is no engine version.
///
/// # Safety
/// `scene` is NULL or a live scene.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_plan_world_gravity(
    scene: *const SceneHandle,
    engine: u32,
    fallback: Vec2,
) -> Vec2 {
    guard(
        || fallback,
        || {
            // SAFETY: by the caller's contract.
            let scene = unsafe { scene.as_ref() };
            let engine = Engine::try_from(engine).ok();
            scene
                .zip(engine)
                .and_then(|(h, e)| plan::world_gravity(&h.scene, e))
                .unwrap_or(fallback)
        },
    )
}
