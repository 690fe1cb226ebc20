//! Any bytes into the C API, then a walk over every array of the scene view checking each
//! index, range and string, as a C host reading it would, and the scene drawn
//! (`b2s_draw_svg`) with poses and paths made of the input's own bytes.
#![no_main]

use std::ffi::{CStr, c_char};

use box2scene::draw::Pose;
use box2scene::ffi::{
    ErrorInfo, SceneHandle, SceneView, b2s_code_name, b2s_draw_svg, b2s_load_memory,
    b2s_picture_default, b2s_scene_free, b2s_scene_get_view, b2s_text_free,
};
use box2scene::{Code, NONE, Vec2};
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
    draw(scene, view, data);
    unsafe { b2s_scene_free(scene) };
});

/// The scene drawn where a host's simulation says, its poses and paths any floats (NaN,
/// the infinities, the largest) read from `data`: a document that parses, every number in
/// it finite.
fn draw(scene: *const SceneHandle, v: &SceneView, data: &[u8]) {
    let mut floats =
        data.chunks_exact(4).map(|c| f32::from_le_bytes(c.try_into().unwrap())).cycle();
    let mut next = || floats.next().unwrap_or(0.0);
    let bodies = v.body_count as usize;
    let mut pose = || Pose { position: Vec2 { x: next(), y: next() }, angle: next() };
    let start: Vec<Pose> = (0..bodies).map(|_| pose()).collect();
    let end: Vec<Pose> = (0..bodies).map(|_| pose()).collect();
    let samples = 3;
    let paths: Vec<Vec2> = (0..samples * bodies).map(|_| Vec2 { x: next(), y: next() }).collect();
    let created: Vec<bool> = (0..v.joint_count).map(|i| i % 2 == 0).collect();
    let mut picture = b2s_picture_default();
    picture.title = c"fuzz".as_ptr();
    picture.start = start.as_ptr();
    picture.end = end.as_ptr();
    picture.joints_created = created.as_ptr();
    picture.trajectories = paths.as_ptr();
    picture.trajectory_samples = samples;
    let mut text = std::ptr::null_mut();
    let mut size = 0;
    let code = unsafe { b2s_draw_svg(scene, &picture, &mut text, &mut size, std::ptr::null_mut()) };
    assert_eq!(code, Code::Ok);
    let svg = unsafe { CStr::from_ptr(text) }.to_str().expect("UTF-8");
    assert_eq!(svg.len(), size);
    let document = roxmltree::Document::parse(svg).expect("the SVG parses");
    for node in document.descendants().filter(|n| n.is_element()) {
        for attribute in node.attributes() {
            let numbers: Vec<&str> = match attribute.name() {
                "viewBox" | "points" | "d" => {
                    attribute.value().split([' ', ',', 'M']).filter(|n| !n.is_empty()).collect()
                }
                "x" | "y" | "cx" | "cy" | "r" | "x1" | "y1" | "x2" | "y2" | "width" | "height"
                | "font-size" | "stroke-width" => vec![attribute.value()],
                _ => continue,
            };
            for number in numbers {
                let value: f32 = number.parse().unwrap_or_else(|_| panic!("{number:?} in {svg}"));
                assert!(value.is_finite(), "{number} in {svg}");
            }
        }
    }
    unsafe { b2s_text_free(text) };
}

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
