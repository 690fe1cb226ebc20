//! Every export of the C API, called as a C host would, through raw pointers: the test Miri
//! runs over the FFI module (`cargo +nightly miri test --test ffi`).

use std::ffi::{CStr, CString, c_char};
use std::ptr::{null, null_mut};

use box2scene::ffi::*;
use box2scene::{
    Body, BodyKind, Code, Fixture, Joint, JointKind, NONE, Shape, ShapeKind, Str, UserData, Vec2,
};

const SCENE: &str = r#"<World Version="1"><Gravity>0 -10</Gravity>
<Shapes><Shape Type="Circle"><Name>ball</Name><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
<Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
<Bodies><Body Type="Static"><Name>ground</Name></Body><Body Type="Dynamic"><Name>ball</Name><Fixtures><ID>0</ID></Fixtures>
<UserData><Type>System.String</Type><Value><string>hi</string></Value></UserData></Body></Bodies>
<Joints><Joint Type="Revolute"><Name>pin</Name><BodyA>0</BodyA><BodyB>1</BodyB></Joint></Joints></World>"#;

fn no_error() -> ErrorInfo {
    ErrorInfo { code: 0, line: 0, column: 0, byte_offset: 0, message: [0; ERROR_MESSAGE_SIZE] }
}

fn text<'a>(s: *const c_char) -> &'a str {
    assert!(!s.is_null());
    unsafe { CStr::from_ptr(s) }.to_str().unwrap()
}

fn load_text(xml: &str) -> (*mut SceneHandle, Code, ErrorInfo) {
    let mut scene = null_mut();
    let mut error = no_error();
    let code = unsafe { b2s_load_memory(xml.as_ptr(), xml.len(), null(), &mut scene, &mut error) };
    (scene, code, error)
}

fn slice<'a, T>(items: *const T, count: u32) -> &'a [T] {
    if count == 0 { &[] } else { unsafe { std::slice::from_raw_parts(items, count as usize) } }
}

#[test]
fn a_scene_loads_and_is_read_through_its_view() {
    let (scene, code, error) = load_text(SCENE);
    assert_eq!((code, error.code), (Code::Ok, 0));
    let view = unsafe { &*b2s_scene_get_view(scene) };
    assert_eq!(
        (view.shape_count, view.fixture_count, view.body_count, view.joint_count),
        (1, 1, 2, 1)
    );
    assert!(view.gravity_given && view.gravity == Vec2::new(0.0, -10.0));
    let bodies = slice(view.bodies, view.body_count);
    assert_eq!(text(bodies[1].name.as_ptr()), "ball");
    let ids = slice(view.fixture_ids, view.fixture_id_count);
    assert_eq!(ids[bodies[1].fixtures.first as usize], 0);
    let user_data = &slice(view.user_data, view.user_data_count)[bodies[1].user_data as usize];
    assert_eq!(
        (text(user_data.type_name.as_ptr()), text(user_data.value.as_ptr())),
        ("System.String", "hi")
    );
    let name = CString::new("pin").unwrap();
    unsafe {
        assert_eq!(b2s_scene_find_joint(scene, name.as_ptr()), 0);
        assert_eq!(b2s_scene_find_body(scene, c"ball".as_ptr()), 1);
        assert_eq!(b2s_scene_find_shape(scene, c"ball".as_ptr()), 0);
        assert_eq!(b2s_scene_find_fixture(scene, c"none".as_ptr()), NONE);
        assert_eq!(b2s_scene_find_body(scene, null()), NONE);
        assert_eq!(b2s_scene_find_body(null(), c"ball".as_ptr()), NONE);
        b2s_scene_free(scene);
    }
}

#[test]
fn a_failed_load_fills_the_error_and_stores_no_scene() {
    let (scene, code, error) = load_text("<World Version=\"1\">\n<Shapes>x</Shapes></World>");
    assert!(scene.is_null());
    assert_eq!(
        (code, error.code, error.line, error.column),
        (Code::UnexpectedText, code as u32, 2, 9)
    );
    assert!(text(error.message.as_ptr()).contains("'x'"));
    // A message longer than the buffer is cut at a character boundary and NUL-terminated.
    let long = format!(
        "<World Version=\"1\"><Shapes><Shape Type=\"{}\"/></Shapes></World>",
        "é".repeat(300)
    );
    let (_, code, error) = load_text(&long);
    assert_eq!(code, Code::UnknownType);
    assert!(text(error.message.as_ptr()).len() < ERROR_MESSAGE_SIZE);
}

#[test]
fn null_arguments_are_refused_not_followed() {
    let mut scene = null_mut();
    let mut error = no_error();
    unsafe {
        assert_eq!(b2s_load_memory(null(), 5, null(), &mut scene, &mut error), Code::NullArgument);
        assert_eq!(
            b2s_load_memory(b"x".as_ptr(), 1, null(), null_mut(), null_mut()),
            Code::NullArgument
        );
        assert_eq!(b2s_load_file(null(), null(), &mut scene, &mut error), Code::NullArgument);
        assert_eq!(error.code, Code::NullArgument as u32);
        assert_eq!(
            b2s_load_memory(null(), 0, null(), &mut scene, null_mut()),
            Code::MalformedXml,
            "no bytes: no root"
        );
        assert!(b2s_scene_get_view(null()).is_null());
        b2s_scene_free(null_mut());
        b2s_text_free(null_mut());
        b2s_builder_free(null_mut());
        assert_eq!(
            b2s_write_memory(null(), null(), null_mut(), null_mut(), null_mut()),
            Code::NullArgument
        );
        assert_eq!(b2s_joint_default(0, null_mut()), Code::NullArgument);
    }
}

#[test]
fn defaults_names_and_version() {
    let mut joint = Joint::new(JointKind::Revolute);
    let mut body = Body::new(BodyKind::Static);
    let mut fixture = Fixture::default();
    let mut shape = Shape::new(ShapeKind::Circle);
    unsafe {
        assert_eq!(b2s_joint_default(JointKind::Wheel as u32, &mut joint), Code::Ok);
        assert_eq!((joint.frequency_hz, joint.damping_ratio), (2.0, 0.7));
        assert_eq!(b2s_joint_default(99, &mut joint), Code::InvalidArgument);
        assert_eq!(b2s_body_default(BodyKind::Dynamic as u32, &mut body), Code::Ok);
        assert_eq!(
            (body.kind, body.gravity_scale, body.awake),
            (BodyKind::Dynamic as u32, 1.0, true)
        );
        assert_eq!(b2s_fixture_default(&mut fixture), Code::Ok);
        assert_eq!(fixture.friction, 0.2);
        assert_eq!(b2s_shape_default(ShapeKind::Chain as u32, &mut shape), Code::Ok);
        assert_eq!(b2s_shape_default(4, &mut shape), Code::InvalidArgument);
    }
    assert_eq!(text(b2s_code_name(Code::IdOutOfRange as u32)), "id-out-of-range");
    assert_eq!(text(b2s_code_name(12345)), "unknown-code");
    assert_eq!(text(b2s_version()), env!("CARGO_PKG_VERSION"));
    assert!(b2s_load_options_default().max_depth == 64 && !b2s_write_options_default().all_fields);
}

#[test]
fn a_scene_is_written_to_a_library_owned_text() {
    let (scene, _, _) = load_text(SCENE);
    let mut written = null_mut();
    let mut size = 0usize;
    let options = box2scene::WriteOptions { all_fields: true, ..Default::default() };
    unsafe {
        assert_eq!(
            b2s_write_memory(scene, &options, &mut written, &mut size, null_mut()),
            Code::Ok
        );
        let xml = text(written);
        assert_eq!(xml.len(), size);
        assert!(xml.contains("<Name>pin</Name>") && xml.contains("<AllowSleep>true</AllowSleep>"));
        let (again, code, _) = load_text(xml);
        assert_eq!(code, Code::Ok);
        b2s_text_free(written);
        b2s_scene_free(again);
        b2s_scene_free(scene);
    }
}

/// `b2s_draw_svg` hands out the library's picture (`tests/draw.rs` says what it holds) for
/// the poses, flags and samples it is given, and refuses what it cannot read.
#[test]
fn a_picture_is_drawn_into_a_library_owned_text() {
    let (scene, _, _) = load_text(SCENE);
    let loaded = box2scene::load(SCENE.as_bytes(), &box2scene::LoadOptions::default()).unwrap();
    let start = [box2scene::draw::Pose::default(); 2];
    let end = [
        box2scene::draw::Pose::default(),
        box2scene::draw::Pose { position: Vec2 { x: 0.0, y: -3.0 }, angle: 1.0 },
    ];
    let samples = [
        Vec2 { x: 0.0, y: 0.0 },
        Vec2 { x: 0.0, y: 0.0 },
        Vec2 { x: 0.0, y: 0.0 },
        Vec2 { x: 0.0, y: -3.0 },
    ];
    let created = [false];
    let title = c"fall";
    let mut picture = b2s_picture_default();
    assert!(picture.title.is_null() && picture.start.is_null() && picture.trajectory_samples == 0);
    picture.title = title.as_ptr();
    picture.start = start.as_ptr();
    picture.end = end.as_ptr();
    picture.joints_created = created.as_ptr();
    picture.trajectories = samples.as_ptr();
    picture.trajectory_samples = 2;
    let expected = box2scene::draw::Picture {
        title: "fall",
        start: Some(&start),
        end: Some(&end),
        joints: Some(&created),
        trajectories: &samples,
    };
    let mut drawn = null_mut();
    let mut size = 0usize;
    let mut error = no_error();
    unsafe {
        assert_eq!(b2s_draw_svg(scene, &picture, &mut drawn, &mut size, &mut error), Code::Ok);
        assert_eq!(text(drawn), box2scene::draw::svg(&loaded, &expected).unwrap());
        assert_eq!(text(drawn).len(), size);
        b2s_text_free(drawn);

        // NULL: the default picture, the scene where its file puts every body.
        assert_eq!(b2s_draw_svg(scene, null(), &mut drawn, null_mut(), null_mut()), Code::Ok);
        let plain = box2scene::draw::svg(&loaded, &Default::default()).unwrap();
        assert_eq!(text(drawn), plain);
        b2s_text_free(drawn);

        picture.trajectories = null();
        assert_eq!(
            b2s_draw_svg(scene, &picture, &mut drawn, null_mut(), &mut error),
            Code::NullArgument
        );
        assert!(drawn.is_null());
        assert_eq!(text(error.message.as_ptr()), "trajectories is NULL");
        picture.trajectory_samples = usize::MAX;
        assert_eq!(
            b2s_draw_svg(scene, &picture, &mut drawn, null_mut(), &mut error),
            Code::InvalidArgument
        );
        assert_eq!(text(error.message.as_ptr()), "trajectory_samples is too large");
        picture.trajectory_samples = 0;
        let not_utf8 = [0xFFu8 as c_char, 0];
        picture.title = not_utf8.as_ptr();
        assert_eq!(
            b2s_draw_svg(scene, &picture, &mut drawn, null_mut(), &mut error),
            Code::InvalidArgument
        );
        assert_eq!(text(error.message.as_ptr()), "the title is not valid UTF-8");
        assert_eq!(
            b2s_draw_svg(null(), null(), &mut drawn, null_mut(), null_mut()),
            Code::NullArgument
        );
        assert_eq!(
            b2s_draw_svg(scene, null(), null_mut(), null_mut(), null_mut()),
            Code::NullArgument
        );
        b2s_scene_free(scene);
    }
}

#[test]
#[cfg_attr(miri, ignore = "Miri isolates the process from the file system")]
fn files_are_loaded_and_written() {
    let path = std::env::temp_dir().join(format!("box2scene-ffi-{}.xml", std::process::id()));
    let c_path = CString::new(path.to_str().unwrap()).unwrap();
    let (scene, _, _) = load_text(SCENE);
    let mut error = no_error();
    let mut again = null_mut();
    unsafe {
        assert_eq!(b2s_write_file(scene, c_path.as_ptr(), null(), &mut error), Code::Ok);
        assert_eq!(b2s_load_file(c_path.as_ptr(), null(), &mut again, &mut error), Code::Ok);
        assert_eq!((*b2s_scene_get_view(again)).joint_count, 1);
        b2s_scene_free(again);
        b2s_scene_free(scene);
        assert_eq!(
            b2s_load_file(c"/nonexistent/x.xml".as_ptr(), null(), &mut again, &mut error),
            Code::Io
        );
        assert!(again.is_null());
    }
    std::fs::remove_file(path).unwrap();
}

#[test]
fn a_scene_is_built_through_the_builder() {
    let mut error = no_error();
    let mut index = NONE;
    unsafe {
        let builder = b2s_builder_new();
        assert_eq!(b2s_builder_set_gravity(builder, &Vec2::new(0.0, -9.8), &mut error), Code::Ok);
        let note = UserData {
            raw: Str::NULL,
            type_name: Str::from_ptr(c"System.String".as_ptr()),
            value: Str::from_ptr(c"crate".as_ptr()),
        };
        assert_eq!(b2s_builder_add_user_data(builder, &note, &mut index, &mut error), Code::Ok);
        let square = [
            Vec2::new(-1.0, -1.0),
            Vec2::new(1.0, -1.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(-1.0, 1.0),
        ];
        let shape = Shape::new(ShapeKind::Polygon);
        assert_eq!(
            b2s_builder_add_shape(builder, &shape, square.as_ptr(), 4, &mut index, &mut error),
            Code::Ok
        );
        assert_eq!(
            b2s_builder_add_shape(builder, &shape, square.as_ptr(), 1, &mut index, &mut error),
            Code::BadVertexCount
        );
        assert!(text(error.message.as_ptr()).starts_with("shape 1: "));
        let fixture = Fixture { shape: 0, density: 1.0, ..Fixture::default() };
        assert_eq!(b2s_builder_add_fixture(builder, &fixture, &mut index, &mut error), Code::Ok);
        let body = Body {
            name: Str::from_ptr(c"box".as_ptr()),
            user_data: 0,
            ..Body::new(BodyKind::Dynamic)
        };
        let ids = [0u32];
        assert_eq!(
            b2s_builder_add_body(builder, &body, ids.as_ptr(), 1, &mut index, &mut error),
            Code::Ok
        );
        assert_eq!(
            b2s_builder_add_body(builder, &body, null(), 1, &mut index, &mut error),
            Code::NullArgument
        );
        assert_eq!(
            b2s_builder_add_body(
                builder,
                &Body::new(BodyKind::Static),
                null(),
                0,
                &mut index,
                &mut error
            ),
            Code::Ok
        );
        assert_eq!(index, 1);
        let joint = Joint { body_a: 1, body_b: 0, ..Joint::new(JointKind::Weld) };
        assert_eq!(b2s_builder_add_joint(builder, &joint, &mut index, &mut error), Code::Ok);
        let mut scene = null_mut();
        assert_eq!(b2s_builder_finish(builder, &mut scene, &mut error), Code::Ok);
        let view = &*b2s_scene_get_view(scene);
        assert_eq!((view.body_count, view.joint_count, view.user_data_count), (2, 1, 1));
        assert_eq!(text((*view.bodies).name.as_ptr()), "box");
        let stored = &*view.user_data;
        assert_eq!(
            text(stored.raw.as_ptr()),
            "<Type>System.String</Type><Value><string>crate</string></Value>"
        );
        b2s_scene_free(scene);

        let abandoned = b2s_builder_new();
        b2s_builder_free(abandoned);
        assert_eq!(b2s_builder_finish(null_mut(), &mut scene, &mut error), Code::NullArgument);
        assert!(scene.is_null());
    }
}

#[test]
fn a_scene_is_written_in_the_dialect_its_options_name_or_in_its_own() {
    // Aether's reader throws on a circle's name.
    let (scene, _, _) = load_text(&SCENE.replace("<Name>ball</Name><Radius>", "<Radius>"));
    let write = |dialect: u32| {
        let options = box2scene::WriteOptions { dialect, ..Default::default() };
        let mut written = null_mut();
        let mut error = no_error();
        let code =
            unsafe { b2s_write_memory(scene, &options, &mut written, null_mut(), &mut error) };
        let xml = (!written.is_null()).then(|| text(written).to_owned());
        unsafe { b2s_text_free(written) };
        (code, xml, error.code)
    };
    unsafe {
        assert_eq!(b2s_scene_dialect(scene), box2scene::Dialect::Box2scene as u32);
        assert_eq!(b2s_scene_dialect(null()), 0);
    }
    let (code, own, _) = write(0);
    assert_eq!(code, Code::Ok);
    assert!(own.unwrap().starts_with("<World Version=\"1\">\n"));
    let (code, aether, _) = write(box2scene::Dialect::Aether as u32);
    assert_eq!(code, Code::Ok);
    let aether = aether.unwrap();
    assert!(aether.starts_with("<World Version=\"3\">") && aether.contains("<Tag><Type>"));
    let (again, _, _) = load_text(&aether);
    unsafe {
        assert_eq!(b2s_scene_dialect(again), box2scene::Dialect::Aether as u32);
        b2s_scene_free(again);
    }
    let (code, none, error) = write(6);
    assert_eq!((code, none, error), (Code::InvalidArgument, None, Code::InvalidArgument as u32));
    unsafe { b2s_scene_free(scene) };
}

fn plan_options(engine: u32) -> box2scene::plan::PlanOptions {
    use box2scene::plan::{PlanOptions, Rot, Transform};
    PlanOptions {
        engine,
        placement: Transform { p: Vec2 { x: 0.0, y: 0.0 }, q: Rot { c: 1.0, s: 0.0 } },
        gravity: Vec2 { x: 0.0, y: -10.0 },
        max_linear_speed: f32::MAX,
        name_bytes: 0,
    }
}

#[test]
fn a_plan_refuses_null_arguments_and_engines_it_does_not_map() {
    let (scene, code, _) = load_text(SCENE);
    assert_eq!(code, Code::Ok);
    let mut plan = null_mut();
    let mut error = no_error();
    let options = plan_options(0);
    unsafe {
        assert_eq!(b2s_plan_make(null(), &options, &mut plan, &mut error), Code::NullArgument);
        assert_eq!(text(error.message.as_ptr()), "scene is NULL");
        assert_eq!(b2s_plan_make(scene, null(), &mut plan, &mut error), Code::NullArgument);
        assert_eq!(b2s_plan_make(scene, &options, null_mut(), null_mut()), Code::NullArgument);
        plan = std::ptr::NonNull::dangling().as_ptr();
        assert_eq!(b2s_plan_make(scene, &options, &mut plan, &mut error), Code::InvalidArgument);
        assert!(plan.is_null(), "a failed make stores NULL");
        assert_eq!(error.code, Code::InvalidArgument as u32);
        assert!(text(error.message.as_ptr()).starts_with("engine 0 is no b2s_engine"));
        assert!(b2s_plan_get_view(null()).is_null());
        b2s_plan_free(null_mut());
        b2s_scene_free(scene);
    }
}

#[test]
fn a_v3_plan_is_read_through_its_view_after_its_scene_is_freed() {
    let (scene, code, _) = load_text(SCENE);
    assert_eq!(code, Code::Ok);
    let mut plan = null_mut();
    let mut error = no_error();
    let options = plan_options(box2scene::Engine::Box2d32 as u32);
    unsafe {
        assert_eq!(b2s_plan_make(scene, &options, &mut plan, &mut error), Code::Ok);
        b2s_scene_free(scene);
        let view = &*b2s_plan_get_view(plan);
        assert!(view.placed);
        let bodies = slice(view.bodies, view.body_count);
        assert_eq!(bodies.len(), 2);
        assert_eq!(text(bodies[0].name.as_ptr()), "ground");
        assert_eq!(text(bodies[1].name.as_ptr()), "ball");
        assert_eq!(bodies[1].shapes.count, 1);
        let shape = slice(view.shapes, view.shape_count)[0];
        assert_eq!((shape.kind, shape.radius), (0, 0.5));
        let joints = slice(view.joints, view.joint_count);
        assert_eq!((joints.len(), joints[0].body_a, joints[0].body_b), (1, 0, 1));
        assert_eq!(view.report_count, 0);
        b2s_plan_free(plan);
    }
}

#[test]
fn a_worlds_gravity_is_the_files_where_the_engine_holds_it() {
    let fallback = Vec2 { x: 1.0, y: 2.0 };
    let (scene, _, _) = load_text(SCENE);
    let (strong, _, _) = load_text(r#"<World Version="1"><Gravity>0 -5000</Gravity></World>"#);
    unsafe {
        let g = b2s_plan_world_gravity(scene, box2scene::Engine::Box2d31 as u32, fallback);
        assert_eq!((g.x, g.y), (0.0, -10.0));
        let g = b2s_plan_world_gravity(strong, box2scene::Engine::Box2d32 as u32, fallback);
        assert_eq!((g.x, g.y), (1.0, 2.0), "beyond v3.2's range: the fallback");
        let g = b2s_plan_world_gravity(null(), box2scene::Engine::Box2d31 as u32, fallback);
        assert_eq!((g.x, g.y), (1.0, 2.0));
        let g = b2s_plan_world_gravity(scene, 9, fallback);
        assert_eq!((g.x, g.y), (1.0, 2.0));
        b2s_scene_free(scene);
        b2s_scene_free(strong);
    }
}

fn unlabelled() -> box2scene::capture::HeldLabel {
    box2scene::capture::HeldLabel {
        name: Str::NULL,
        user_data: UserData { raw: Str::NULL, type_name: Str::NULL, value: Str::NULL },
    }
}

#[test]
fn a_capture_of_a_built_world_is_labelled_from_its_level_and_its_scene_taken_once() {
    use box2scene::capture::{HeldBody, HeldJoint, HeldShape, HeldWorld};
    let (scene, code, _) = load_text(SCENE);
    assert_eq!(code, Code::Ok);
    let engine = box2scene::Engine::Box2d24 as u32;
    let mut plan = null_mut();
    let mut capture = null_mut();
    let mut error = no_error();
    unsafe {
        assert_eq!(b2s_plan_make(scene, &plan_options(engine), &mut plan, &mut error), Code::Ok);
        // what Box2D 2.4 holds once it has made the plan, unlabelled
        let view = &*b2s_plan_get_view(plan);
        let bodies: Vec<HeldBody> = slice(view.bodies, view.body_count)
            .iter()
            .map(|&body| HeldBody { body, label: unlabelled() })
            .collect();
        let shapes: Vec<HeldShape> = slice(view.shapes, view.shape_count)
            .iter()
            .map(|&shape| HeldShape {
                shape,
                category_bits: 1,
                mask_bits: 0xFFFF,
                group_index: 0,
                restitution_threshold: 1.0,
                chain: NONE,
                other: Str::NULL,
                label: unlabelled(),
                shape_name: Str::NULL,
            })
            .collect();
        let joints: Vec<HeldJoint> = slice(view.joints, view.joint_count)
            .iter()
            .map(|&joint| HeldJoint {
                joint,
                linear_hertz: 0.0,
                linear_damping_ratio: 0.0,
                linear_velocity: Vec2 { x: 0.0, y: 0.0 },
                angular_velocity: 0.0,
                max_velocity_force: 0.0,
                max_velocity_torque: 0.0,
                other: Str::NULL,
                label: unlabelled(),
            })
            .collect();
        let world = HeldWorld {
            engine,
            gravity: Vec2 { x: 0.0, y: -10.0 },
            bodies: bodies.as_ptr(),
            shapes: shapes.as_ptr(),
            points: view.points,
            joints: joints.as_ptr(),
            skipped_joints: null(),
            body_count: view.body_count,
            shape_count: view.shape_count,
            point_count: view.point_count,
            joint_count: view.joint_count,
            skipped_count: 0,
        };
        assert_eq!(b2s_capture_make(null(), scene, &mut capture, &mut error), Code::NullArgument);
        assert!(capture.is_null());
        assert_eq!(b2s_capture_make(&world, scene, &mut capture, &mut error), Code::Ok);
        b2s_plan_free(plan);
        let reports = &*b2s_capture_get_view(capture);
        assert_eq!(reports.report_count, 0);
        let saved = b2s_capture_take_scene(capture);
        assert!(b2s_capture_take_scene(capture).is_null(), "a capture's scene is taken once");
        b2s_capture_free(capture);
        let view = &*b2s_scene_get_view(saved);
        let saved_bodies = slice(view.bodies, view.body_count);
        assert_eq!(text(saved_bodies[0].name.as_ptr()), "ground");
        assert_eq!(text(saved_bodies[1].name.as_ptr()), "ball");
        assert_ne!(saved_bodies[1].user_data, NONE);
        assert_eq!(text(slice(view.joints, view.joint_count)[0].name.as_ptr()), "pin");
        b2s_scene_free(saved);
        let unknown = HeldWorld { engine: 99, ..world };
        assert_eq!(
            b2s_capture_make(&unknown, null(), &mut capture, &mut error),
            Code::InvalidArgument
        );
        assert!(b2s_capture_get_view(null()).is_null());
        b2s_capture_free(null_mut());
        b2s_scene_free(scene);
    }
}
