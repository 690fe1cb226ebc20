//! Any bytes into the C API, then a walk over every array of the scene view checking each
//! index, range and string, as a C host reading it would.
#![no_main]

use std::ffi::{CStr, c_char};

use box2scene::ffi::{
    ErrorInfo, SceneView, b2s_code_name, b2s_load_memory, b2s_scene_free, b2s_scene_get_view,
};
use box2scene::{Code, NONE};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut scene = std::ptr::null_mut();
    let mut error: ErrorInfo = unsafe { std::mem::zeroed() };
    let code = unsafe {
        b2s_load_memory(data.as_ptr(), data.len(), std::ptr::null(), &mut scene, &mut error)
    };
    if code != Code::Ok {
        assert!(scene.is_null());
        assert_eq!(error.code, code as u32);
        let message = unsafe { CStr::from_ptr(error.message.as_ptr()) };
        assert!(message.to_str().is_ok_and(|m| !m.is_empty()));
        return;
    }
    let view = unsafe { &*b2s_scene_get_view(scene) };
    walk(view);
    unsafe { b2s_scene_free(scene) };
});

/// The `count` items at `items` (a dangling pointer is fine for an empty array).
fn items<'a, T>(items: *const T, count: u32) -> &'a [T] {
    if count == 0 { &[] } else { unsafe { std::slice::from_raw_parts(items, count as usize) } }
}

fn string(s: *const c_char) {
    if !s.is_null() {
        assert!(unsafe { CStr::from_ptr(s) }.to_str().is_ok());
    }
}

fn within(range: box2scene::Range, count: u32) {
    assert!(range.first as u64 + range.count as u64 <= count as u64);
}

fn walk(v: &SceneView) {
    let user_data = |index: u32| assert!(index == NONE || index < v.user_data_count);
    for s in items(v.shapes, v.shape_count) {
        within(s.vertices, v.vertex_count);
        string(s.name.as_ptr());
    }
    for &point in items(v.vertices, v.vertex_count) {
        assert!(point.x.is_finite() && point.y.is_finite());
    }
    for f in items(v.fixtures, v.fixture_count) {
        assert!(f.shape < v.shape_count);
        user_data(f.user_data);
        string(f.name.as_ptr());
    }
    for &id in items(v.fixture_ids, v.fixture_id_count) {
        assert!(id < v.fixture_count);
    }
    for b in items(v.bodies, v.body_count) {
        within(b.fixtures, v.fixture_id_count);
        user_data(b.user_data);
        string(b.name.as_ptr());
    }
    for j in items(v.joints, v.joint_count) {
        assert!(j.body_a < v.body_count && j.body_b < v.body_count);
        assert!(
            (j.joint_a == NONE || j.joint_a < v.joint_count)
                && (j.joint_b == NONE || j.joint_b < v.joint_count)
        );
        user_data(j.user_data);
        string(j.name.as_ptr());
    }
    for u in items(v.user_data, v.user_data_count) {
        assert!(!u.raw.is_null());
        string(u.raw.as_ptr());
        string(u.type_name.as_ptr());
        string(u.value.as_ptr());
    }
    for d in items(v.diagnostics, v.diagnostic_count) {
        string(d.message.as_ptr());
        let code = unsafe { CStr::from_ptr(b2s_code_name(d.code)) };
        assert_ne!(code.to_bytes(), b"unknown-code");
    }
}
