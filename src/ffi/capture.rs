//! A capture: the records an adapter read a live world into, turned into a scene and the
//! reports of what it cannot hold exactly.

use std::ffi::CStr;
use std::ptr;

use super::{ErrorInfo, SceneHandle, arg_slice, fallible, guard, simple_error};
use crate::capture::{self, Held, HeldLabel, HeldWorld, Label};
use crate::error::{Code, Error};
use crate::plan::{Engine, Plan, PlanReport};
use crate::scene::Str;

/// A capture's reports: what the scene could not hold exactly or did not write, in the
/// order met, each `index` counting the held objects of its kind (a joint the build
/// skipped: its index in the level's joints).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct CaptureView {
    /// The `report_count` reports.
    pub reports: *const PlanReport,
    /// Number of items in `reports`.
    pub report_count: u32,
}

/// A capture (opaque): the scene made of what a world holds, until taken, and the
/// reports. Free it with `b2s_capture_free`.
pub struct CaptureHandle {
    view: CaptureView,
    // The view points into it: it is never changed after the view is taken.
    _reports: Plan,
    scene: Option<crate::scene::Scene>,
}

// SAFETY: the view's pointers point into the handle's own reports, never mutated after it
// is made; their texts are owned by them.
unsafe impl Send for CaptureHandle {}
// SAFETY: as above.
unsafe impl Sync for CaptureHandle {}

/// A text a held record points at: NULL is none, invalid UTF-8 an error.
///
/// # Safety
/// `s` is NULL or points to a NUL-terminated string.
unsafe fn held_text<'a>(s: Str, what: &str) -> Result<Option<&'a str>, Error> {
    if s.is_null() {
        return Ok(None);
    }
    // SAFETY: not NULL, and NUL-terminated by the caller's contract.
    let text = unsafe { CStr::from_ptr(s.as_ptr()) };
    text.to_str()
        .map(Some)
        .map_err(|_| simple_error(Code::InvalidArgument, &format!("{what} is not valid UTF-8")))
}

/// # Safety
/// The label's texts are NULL or NUL-terminated.
unsafe fn held_label<'a>(label: &HeldLabel, what: &str) -> Result<Label<'a>, Error> {
    let data = &label.user_data;
    // SAFETY: by the caller's contract.
    unsafe {
        Ok(Label {
            name: held_text(label.name, what)?,
            user_data_raw: held_text(data.raw, what)?,
            user_data_type: held_text(data.type_name, what)?,
            user_data_value: held_text(data.value, what)?,
        })
    }
}

/// Makes the scene of what `world` holds and the reports of what it cannot hold exactly.
/// `level` is the scene the world was built from, or NULL: given, the held records that
/// name its records (`body.body`, `shape.slot`, `joint.joint`) take its Names and UserData
/// where they carry none, its joints are written in its order and the ones the build
/// skipped (`skipped_joints`) written back as it has them. On success returns
/// `B2S_CODE_OK` and stores a new capture in `*out_capture`; free it with
/// `b2s_capture_free`. An engine number that names no engine version, or a text
/// that is not UTF-8, fails with `B2S_CODE_INVALID_ARGUMENT`. On failure stores NULL there,
/// returns the error's code and, when `error` is not NULL, fills it. Thread-safe.
///
/// # Safety
/// `world` is NULL or valid, each array holding its count of records and each text NULL or
/// NUL-terminated; `level` NULL or a live scene; `out_capture` NULL or writable; `error`
/// NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_capture_make(
    world: *const HeldWorld,
    level: *const SceneHandle,
    out_capture: *mut *mut CaptureHandle,
    error: *mut ErrorInfo,
) -> Code {
    fallible(error, || {
        // SAFETY: by the caller's contract.
        let out = unsafe { out_capture.as_mut() }
            .ok_or_else(|| simple_error(Code::NullArgument, "out_capture is NULL"))?;
        *out = ptr::null_mut();
        // SAFETY: by the caller's contract.
        let w = unsafe { world.as_ref() }
            .ok_or_else(|| simple_error(Code::NullArgument, "world is NULL"))?;
        let engine = Engine::try_from(w.engine).map_err(|n| {
            simple_error(Code::InvalidArgument, &format!("engine {n} is no b2s_engine"))
        })?;
        // SAFETY: by the caller's contract, for every array and text below.
        let captured = unsafe {
            let bodies = arg_slice(w.bodies, w.body_count as usize, "world->bodies")?;
            let shapes = arg_slice(w.shapes, w.shape_count as usize, "world->shapes")?;
            let joints = arg_slice(w.joints, w.joint_count as usize, "world->joints")?;
            let body_labels = bodies
                .iter()
                .map(|b| held_label(&b.label, "a body's label"))
                .collect::<Result<Vec<_>, _>>()?;
            let fixture_labels = shapes
                .iter()
                .map(|s| held_label(&s.label, "a fixture's label"))
                .collect::<Result<Vec<_>, _>>()?;
            let shape_names = shapes
                .iter()
                .map(|s| held_text(s.shape_name, "a shape's name"))
                .collect::<Result<Vec<_>, _>>()?;
            let shape_others = shapes
                .iter()
                .map(|s| held_text(s.other, "a shape's other"))
                .collect::<Result<Vec<_>, _>>()?;
            let joint_labels = joints
                .iter()
                .map(|j| held_label(&j.label, "a joint's label"))
                .collect::<Result<Vec<_>, _>>()?;
            let joint_others = joints
                .iter()
                .map(|j| held_text(j.other, "a joint's other"))
                .collect::<Result<Vec<_>, _>>()?;
            let held = Held {
                engine,
                gravity: w.gravity,
                bodies,
                shapes,
                points: arg_slice(w.points, w.point_count as usize, "world->points")?,
                joints,
                skipped_joints: arg_slice(
                    w.skipped_joints,
                    w.skipped_count as usize,
                    "world->skipped_joints",
                )?,
                body_labels: &body_labels,
                fixture_labels: &fixture_labels,
                shape_names: &shape_names,
                shape_others: &shape_others,
                joint_labels: &joint_labels,
                joint_others: &joint_others,
            };
            let level = level.as_ref().map(|h| &h.scene);
            capture::capture(&held, level)?
        };
        let reports = captured.reports;
        let view = CaptureView {
            reports: reports.reports().as_ptr(),
            report_count: u32::try_from(reports.reports().len())
                .expect("a capture reports fewer than 2^32 things"),
        };
        let handle = CaptureHandle { view, _reports: reports, scene: Some(captured.scene) };
        *out = Box::into_raw(Box::new(handle));
        Ok(())
    })
}

/// The capture's reports. NULL for a NULL capture. Valid until the capture is freed.
///
/// # Safety
/// `capture` is NULL or a live capture.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_capture_get_view(capture: *const CaptureHandle) -> *const CaptureView {
    guard(ptr::null, || {
        // SAFETY: by the caller's contract.
        unsafe { capture.as_ref() }.map_or(ptr::null(), |h| &h.view)
    })
}

/// The captured scene, once: the caller owns it (`b2s_scene_free`). NULL for a NULL
/// capture or one whose scene was taken.
///
/// # Safety
/// `capture` is NULL or a live capture.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_capture_take_scene(capture: *mut CaptureHandle) -> *mut SceneHandle {
    guard(ptr::null_mut, || {
        // SAFETY: by the caller's contract.
        let scene = unsafe { capture.as_mut() }.and_then(|h| h.scene.take());
        scene.map_or(ptr::null_mut(), |s| Box::into_raw(SceneHandle::new(s)))
    })
}

/// Frees a capture, its reports and its scene unless taken. NULL is ignored.
///
/// # Safety
/// `capture` is NULL or a capture from `b2s_capture_make` that was not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_capture_free(capture: *mut CaptureHandle) {
    guard(
        || (),
        || {
            if !capture.is_null() {
                // SAFETY: made by Box::into_raw in b2s_capture_make, freed once by contract.
                drop(unsafe { Box::from_raw(capture) });
            }
        },
    )
}
