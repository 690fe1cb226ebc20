//! The scene builder: a scene rebuilt from the loader's records is the loaded scene;
//! invalid additions are refused with the loader's codes, the message naming the object;
//! what is added is made canonical so that it writes and reads back unchanged.

mod common;

use box2scene::{
    Body, BodyKind, Builder, Code, Fixture, Joint, JointKind, LoadOptions, NONE, Range, Scene,
    Shape, ShapeKind, Vec2, WriteOptions, load, load_path, write,
};
use common::{Random, content, generate};

/// Adds every object of `scene` to a new builder, as a host copying it would.
fn rebuild(scene: &Scene) -> Scene {
    let mut b = Builder::new();
    b.set_gravity(scene.gravity()).unwrap();
    for u in scene.user_data() {
        b.add_user_data(scene.text(u.raw), None, None).unwrap();
    }
    for s in scene.shapes() {
        b.add_shape(s, scene.text(s.name), scene.vertices(s)).unwrap();
    }
    for f in scene.fixtures() {
        b.add_fixture(f, scene.text(f.name)).unwrap();
    }
    for body in scene.bodies() {
        b.add_body(body, scene.text(body.name), scene.body_fixtures(body)).unwrap();
    }
    for j in scene.joints() {
        b.add_joint(j, scene.text(j.name)).unwrap();
    }
    b.finish()
}

#[test]
fn a_loaded_scene_rebuilt_is_the_same_scene() {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    for file in [
        "tests/fixtures/scenes/every-v1-field.xml",
        "tests/fixtures/corpus/renderer-scene-v1.xml",
        "examples/scenes/showcase.xml",
    ] {
        let scene = load_path(root.join(file), &LoadOptions::default()).unwrap();
        let built = rebuild(&scene);
        assert_eq!(content(&built), content(&scene), "{file}");
        assert_eq!(built.version(), 1);
    }
}

#[test]
fn generated_scenes_rebuilt_are_the_same_and_round_trip() {
    let mut random = Random(0xB0_1D);
    for i in 0..2_000 {
        let scene = load(generate(&mut random).as_bytes(), &LoadOptions::default()).unwrap();
        let built = rebuild(&scene);
        assert_eq!(content(&built), content(&scene), "generated scene {i}");
        let written = write(&built, &WriteOptions::default()).unwrap();
        let again = load(written.as_bytes(), &LoadOptions::default()).unwrap();
        assert_eq!(content(&again), content(&built), "generated scene {i}");
    }
}

fn circle(radius: f32) -> Shape {
    Shape { radius, ..Shape::new(ShapeKind::Circle) }
}

/// A builder holding one circle, one fixture and two bodies (static, dynamic).
fn started() -> Builder {
    let mut b = Builder::new();
    b.add_shape(&circle(1.0), None, &[]).unwrap();
    b.add_fixture(&Fixture { shape: 0, density: 1.0, ..Fixture::default() }, None).unwrap();
    b.add_body(&Body::new(BodyKind::Static), None, &[]).unwrap();
    b.add_body(&Body::new(BodyKind::Dynamic), None, &[0]).unwrap();
    b
}

fn joint(kind: JointKind) -> Joint {
    Joint { body_a: 0, body_b: 1, ..Joint::new(kind) }
}

/// Asserts the refusal's code and that its message starts by naming the object.
fn assert_refused<T: std::fmt::Debug>(
    result: Result<T, box2scene::Error>,
    code: Code,
    object: &str,
) -> String {
    let error = result.expect_err("the addition is refused");
    assert_eq!(error.code, code, "{}", error.message);
    assert!(
        error.message.starts_with(object),
        "{:?} does not start with {object:?}",
        error.message
    );
    assert_eq!((error.position.line, error.position.column), (0, 0));
    error.message
}

#[test]
fn shapes_are_refused_with_the_loaders_codes() {
    let mut b = started();
    assert_refused(b.add_shape(&circle(0.0), None, &[]), Code::BadRadius, "shape 1: ");
    assert_refused(b.add_shape(&circle(f32::NAN), None, &[]), Code::NonFiniteFloat, "shape 1: ");
    let polygon = Shape::new(ShapeKind::Polygon);
    let nine: Vec<Vec2> = (0..9).map(|k| Vec2::new((k as f32).cos(), (k as f32).sin())).collect();
    assert_refused(b.add_shape(&polygon, None, &nine), Code::BadVertexCount, "shape 1: ");
    let collinear = [Vec2::new(0.0, 0.0), Vec2::new(1.0, 1.0), Vec2::new(2.0, 2.0)];
    assert_refused(b.add_shape(&polygon, None, &collinear), Code::DegeneratePolygon, "shape 1: ");
    let edge = Shape::new(ShapeKind::Edge);
    assert_refused(b.add_shape(&edge, None, &collinear), Code::BadVertexCount, "shape 1: ");
    assert_refused(
        b.add_shape(&edge, None, &[Vec2::ZERO, Vec2::ZERO]),
        Code::DegenerateEdge,
        "shape 1: ",
    );
    let lonely = Shape { is_loop: true, ..Shape::new(ShapeKind::Chain) };
    assert_refused(b.add_shape(&lonely, None, &collinear[..2]), Code::BadVertexCount, "shape 1: ");
    assert_refused(
        b.add_shape(&Shape { kind: 9, ..circle(1.0) }, None, &[]),
        Code::InvalidArgument,
        "shape 1: ",
    );
    // Nothing refused was added: the next shape is still number 1.
    assert_eq!(b.add_shape(&circle(2.0), None, &[]).unwrap(), 1);
}

#[test]
fn fixtures_and_bodies_are_refused_with_the_loaders_codes() {
    let mut b = started();
    let message = assert_refused(
        b.add_fixture(&Fixture { shape: 5, ..Fixture::default() }, None),
        Code::IdOutOfRange,
        "fixture 1: ",
    );
    assert_eq!(message, "fixture 1: names shape 5, but the scene has 1 shapes");
    assert_refused(
        b.add_fixture(&Fixture { shape: 0, density: -1.0, ..Fixture::default() }, None),
        Code::NegativeValue,
        "fixture 1: ",
    );
    assert_refused(
        b.add_fixture(&Fixture { shape: 0, user_data: 3, ..Fixture::default() }, None),
        Code::IdOutOfRange,
        "fixture 1: ",
    );
    let message = assert_refused(
        b.add_body(&Body::new(BodyKind::Static), None, &[0, 4]),
        Code::IdOutOfRange,
        "body 2: ",
    );
    assert_eq!(message, "body 2: names fixture 4, but the scene has 1 fixtures");
    let mut heavy = Body::new(BodyKind::Dynamic);
    (heavy.mass_data.mass, heavy.mass_data.mass_given) = (-2.0, true);
    assert_refused(b.add_body(&heavy, None, &[]), Code::NegativeValue, "body 2: ");
    let lost = Body { position: Vec2::new(f32::INFINITY, 0.0), ..Body::new(BodyKind::Static) };
    assert_refused(b.add_body(&lost, None, &[]), Code::NonFiniteFloat, "body 2: ");
    assert_refused(
        b.add_body(&Body { kind: 7, ..Body::new(BodyKind::Static) }, None, &[]),
        Code::InvalidArgument,
        "body 2: ",
    );
}

#[test]
fn joints_are_refused_with_the_loaders_codes() {
    let mut b = started();
    assert_refused(
        b.add_joint(&Joint { body_b: 0, ..joint(JointKind::Weld) }, None),
        Code::JointSelfReference,
        "joint 0: ",
    );
    assert_refused(
        b.add_joint(&Joint { body_b: 9, ..joint(JointKind::Weld) }, None),
        Code::IdOutOfRange,
        "joint 0: ",
    );
    let limited = Joint {
        enable_limit: true,
        lower_limit: 1.0,
        upper_limit: -1.0,
        ..joint(JointKind::Revolute)
    };
    assert_refused(b.add_joint(&limited, None), Code::BadLimit, "joint 0: ");
    assert_refused(
        b.add_joint(&Joint { local_axis_a: Vec2::ZERO, ..joint(JointKind::Prismatic) }, None),
        Code::ZeroAxis,
        "joint 0: ",
    );
    assert_refused(
        b.add_joint(&Joint { ratio: 0.0, ..joint(JointKind::Pulley) }, None),
        Code::BadRatio,
        "joint 0: ",
    );
    let message = assert_refused(
        b.add_joint(&Joint { max_motor_torque: -5.0, ..joint(JointKind::Revolute) }, None),
        Code::NegativeValue,
        "joint 0: ",
    );
    assert_eq!(message, "joint 0: <MaxMotorTorque> is -5, but it cannot be negative");
    assert_refused(
        b.add_joint(&joint(JointKind::Unsupported), None),
        Code::InvalidArgument,
        "joint 0: ",
    );
    assert_eq!(b.add_joint(&joint(JointKind::Weld), None).unwrap(), 0);
    let gear = Joint { joint_a: 0, joint_b: 0, ..joint(JointKind::Gear) };
    assert_refused(b.add_joint(&gear, None), Code::BadGearJoint, "joint 1: ");
    assert_eq!(b.add_joint(&joint(JointKind::Revolute), None).unwrap(), 1);
    assert_eq!(
        b.add_joint(&Joint { joint_a: 1, joint_b: 1, ..joint(JointKind::Gear) }, None).unwrap(),
        2
    );
}

#[test]
fn additions_are_made_canonical() {
    let mut b = started();
    let stray = Joint {
        local_axis_a: Vec2::new(3.0, 4.0),
        length: 9.0,
        max_force: 2.0,
        ..joint(JointKind::Revolute)
    };
    b.add_joint(&stray, Some("  hinge\n")).unwrap();
    let data = b.add_user_data(None, Some("System.String"), Some("a < b")).unwrap();
    assert_refused(
        b.add_user_data(Some("<Type>unclosed"), None, None),
        Code::MalformedXml,
        "user data 1: ",
    );
    assert_refused(
        b.add_user_data(None, None, Some("orphan")),
        Code::InvalidArgument,
        "user data 1: ",
    );
    b.add_body(&Body { user_data: data, ..Body::new(BodyKind::Kinematic) }, None, &[]).unwrap();
    let scene = b.finish();
    let hinge = &scene.joints()[0];
    assert_eq!(
        (hinge.local_axis_a, hinge.length, hinge.max_force),
        (Vec2::ZERO, 0.0, 0.0),
        "fields a revolute joint does not have"
    );
    assert_eq!(scene.text(hinge.name), Some("hinge"));
    let u = scene.user_data_at(scene.bodies()[2].user_data).unwrap();
    assert_eq!(
        scene.text(u.raw),
        Some("<Type>System.String</Type><Value><string>a &lt; b</string></Value>")
    );
    assert_eq!(
        (scene.text(u.type_name), scene.text(u.value)),
        (Some("System.String"), Some("a < b"))
    );
    assert_eq!(scene.joints()[0].user_data, NONE);
    assert_eq!(scene.bodies()[2].fixtures, Range { first: 0, count: 0 }, "an empty range");
}

#[test]
fn the_loaders_warnings_are_attached() {
    let mut b = Builder::new();
    let square =
        [Vec2::new(0.0, 0.0), Vec2::new(0.0, 1.0), Vec2::new(1.0, 1.0), Vec2::new(1.0, 0.0)];
    b.add_shape(&Shape::new(ShapeKind::Polygon), None, &square).unwrap();
    b.add_fixture(&Fixture { shape: 0, ..Fixture::default() }, None).unwrap();
    b.add_body(&Body::new(BodyKind::Dynamic), None, &[0]).unwrap();
    let scene = b.finish();
    let found: Vec<_> = scene
        .diagnostics()
        .iter()
        .map(|d| (d.code().unwrap(), d.line, scene.text(d.message).unwrap()))
        .collect();
    assert_eq!(found.len(), 2, "{found:?}");
    assert_eq!((found[0].0, found[0].1), (Code::PolygonNotConvexCcw, 0));
    assert!(found[0].2.starts_with("shape 0: "));
    assert_eq!(found[1].0, Code::DynamicBodyZeroDensity);
    assert!(found[1].2.starts_with("body 0: "));
}

#[test]
fn an_empty_builder_makes_an_empty_scene() {
    let scene = Builder::new().finish();
    assert_eq!((scene.version(), scene.gravity(), scene.bodies().len()), (1, None, 0));
    let written = write(&scene, &WriteOptions::default()).unwrap();
    assert!(written.contains("<Shapes />") && written.contains("<Joints />"), "{written}");
}

/// `text` is well-formed XML to an independent parser, and box2scene loads it back with
/// the default options.
fn assert_readable(text: &str) -> Scene {
    if let Err(e) = roxmltree::Document::parse(text) {
        panic!("an XML parser rejects the written file: {e}\n{text}");
    }
    load(text.as_bytes(), &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

/// Names a file could not hold (characters outside XML's) or that a load would refuse (more
/// than max_text_bytes, once escaped) are refused at the call, naming the object and the
/// field, for every kind of object; nothing refused is added.
#[test]
fn unwritable_names_are_refused() {
    let long = "x".repeat(LoadOptions::default().max_text_bytes as usize + 1);
    // Short enough as given, too long once each `&` is written `&amp;`.
    let escaped = "&".repeat(LoadOptions::default().max_text_bytes as usize / 4);
    let cases = [
        ("a\u{1}b", Code::MalformedXml, "its Name holds the character U+0001"),
        ("\u{1F}", Code::MalformedXml, "its Name holds the character U+001F"),
        ("a\u{FFFE}", Code::MalformedXml, "its Name holds the character U+FFFE"),
        ("\u{FFFF}b", Code::MalformedXml, "its Name holds the character U+FFFF"),
        (long.as_str(), Code::LimitExceeded, "its Name is 1048577 bytes long written"),
        (escaped.as_str(), Code::LimitExceeded, "its Name is 1310720 bytes long written"),
    ];
    for (name, code, why) in cases {
        let mut b = started();
        let m = assert_refused(b.add_shape(&circle(1.0), Some(name), &[]), code, "shape 1: ");
        assert!(m.starts_with(&format!("shape 1: {why}")), "{m}");
        let fixture = Fixture { shape: 0, ..Fixture::default() };
        assert_refused(b.add_fixture(&fixture, Some(name)), code, "fixture 1: ");
        let body = Body::new(BodyKind::Static);
        assert_refused(b.add_body(&body, Some(name), &[]), code, "body 2: ");
        assert_refused(b.add_joint(&joint(JointKind::Weld), Some(name)), code, "joint 0: ");
        let scene = b.finish();
        let counts = [scene.shapes().len(), scene.fixtures().len(), scene.bodies().len()];
        assert_eq!((counts, scene.joints().len()), ([1, 1, 2], 0));
    }
}

/// What XML does allow in a name is written so that a parser and the loader read it back.
#[test]
fn names_with_every_allowed_character_are_written_readably() {
    let name = "tab\there, line\nend, cr\rhere, \u{7F}\u{85}\u{FFFD}\u{10FFFF} <&>\"' ]]> -- end";
    let mut b = started();
    b.add_shape(&circle(1.0), Some(name), &[]).unwrap();
    b.add_body(&Body::new(BodyKind::Static), Some(name), &[]).unwrap();
    let scene = b.finish();
    let written = write(&scene, &WriteOptions::default()).unwrap();
    let again = assert_readable(&written);
    assert_eq!(again.text(again.shapes()[1].name), Some(name));
    assert_eq!(again.text(again.bodies()[2].name), Some(name));
    let at_limit = "n".repeat(LoadOptions::default().max_text_bytes as usize);
    let mut b = started();
    b.add_shape(&circle(1.0), Some(&at_limit), &[]).unwrap();
    assert_readable(&write(&b.finish(), &WriteOptions::default()).unwrap());
}

/// UserData that a written file could not hold as XML, or that a load with the default
/// options would refuse there, is refused at the call, naming it.
#[test]
fn unwritable_user_data_is_refused() {
    let long = format!("<Value>{}</Value>", "v".repeat(1 << 20 | 1));
    let deep = |levels: usize| "<a>".repeat(levels) + &"</a>".repeat(levels);
    let cases = [
        ("<!-- a -- b -->", Code::MalformedXml),
        ("<!-- a --->", Code::MalformedXml),
        ("<Value>a ]]> b</Value>", Code::MalformedXml),
        ("a ]]> b", Code::MalformedXml),
        ("<Value at=\"a<b\"/>", Code::MalformedXml),
        ("<?xml version=\"1.0\"?><Type>x</Type>", Code::MalformedXml),
        ("<Type>a\u{1}</Type>", Code::MalformedXml),
        ("<Type>\u{FFFF}</Type>", Code::MalformedXml),
        ("<Type>a&#x1;</Type>", Code::MalformedXml),
        ("<Value at=\"&#0;\"/>", Code::MalformedXml),
        ("<!DOCTYPE x>", Code::DoctypeForbidden),
        (long.as_str(), Code::LimitExceeded),
        // A written UserData is the fourth level of its file, which may have 64.
        (&deep(61), Code::LimitExceeded),
    ];
    for (raw, code) in cases {
        let mut b = started();
        let added = b.add_user_data(Some(raw), None, None);
        assert!(added.is_err(), "{} is added", &raw[..raw.len().min(40)]);
        let m = assert_refused(added, code, "user data 0: ");
        assert!(m.contains("UserData"), "{m}");
        assert!(b.finish().user_data().is_empty());
    }
    let mut b = started();
    assert_refused(b.add_user_data(None, Some("T\u{8}"), None), Code::MalformedXml, "user data 0");
    assert_refused(b.add_user_data(None, Some("T"), Some("\u{FFFE}")), Code::MalformedXml, "user");

    let deepest = b.add_user_data(Some(&deep(60)), None, None).unwrap();
    let odd = b.add_user_data(
        Some("<![CDATA[ ]] <b> ]]><!-- - --><v a=\"&lt;\" A=\"\">]]&gt;</v>"),
        None,
        None,
    );
    b.add_body(&Body { user_data: deepest, ..Body::new(BodyKind::Static) }, None, &[]).unwrap();
    b.add_body(&Body { user_data: odd.unwrap(), ..Body::new(BodyKind::Static) }, None, &[])
        .unwrap();
    let scene = b.finish();
    let again = assert_readable(&write(&scene, &WriteOptions::default()).unwrap());
    assert_eq!(content(&again), content(&scene));
}
