//! The writer's contract: `load(write(s))` is `s` in every field, bit for bit, in both
//! modes, and `write(load(write(s)))` is `write(s)` byte for byte; for every test scene,
//! every editor file, and 10 000 generated scenes. What it writes is well-formed XML to an
//! independent parser (roxmltree), and what it cannot write so is refused.

mod common;

use std::path::PathBuf;

use common::{Random, content, generate};

use box2scene::{
    Code, Dialect, JointKind, LoadOptions, Scene, WriteOptions, load, load_path, write,
};

/// box2scene's own dialect, with and without the defaults.
const MODES: [WriteOptions; 2] = [
    WriteOptions { all_fields: false, threads: 0, dialect: Dialect::Box2scene as u32 },
    WriteOptions { all_fields: true, threads: 0, dialect: Dialect::Box2scene as u32 },
];

fn load_text(xml: &str) -> Scene {
    load(xml.as_bytes(), &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}\nin:\n{xml}"))
}

/// Checks both halves of the contract for `scene`; returns the first written text.
fn assert_round_trip(scene: &Scene, what: &str) -> String {
    let mut first = String::new();
    for options in MODES {
        let written = write(scene, &options).unwrap();
        if let Err(e) = roxmltree::Document::parse(&written) {
            panic!("{what} ({options:?}) is written as a file an XML parser rejects: {e}");
        }
        let again = load_text(&written);
        assert_eq!(
            content(&again),
            content(scene),
            "{what} ({options:?}) read back differently:\n{written}"
        );
        assert_eq!(
            write(&again, &options).unwrap(),
            written,
            "{what} ({options:?}) is not written stably"
        );
        if first.is_empty() {
            first = written;
        }
    }
    first
}

fn scene_files() -> Vec<PathBuf> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<PathBuf> =
        ["tests/fixtures/scenes", "tests/fixtures/corpus", "examples/scenes"]
            .iter()
            .flat_map(|dir| std::fs::read_dir(root.join(dir)).unwrap())
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "xml"))
            .collect();
    files.sort();
    files
}

#[test]
fn every_scene_file_round_trips_exactly() {
    let mut checked = 0;
    for path in scene_files() {
        let scene = load_path(&path, &LoadOptions::default()).unwrap();
        let written = assert_round_trip(&scene, &path.display().to_string());
        assert!(
            written.contains("<World Version=\"1\">") || written.contains("<World Version=\"2\">")
        );
        checked += 1;
    }
    assert!(checked >= 9, "{checked} files");
}

#[test]
fn legacy_and_farseer_files_come_out_clean() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let legacy = load_path(
        root.join("tests/fixtures/corpus/legacy-unversioned.xml"),
        &LoadOptions::default(),
    )
    .unwrap();
    let written = write(&legacy, &WriteOptions::default()).unwrap();
    assert!(
        written.contains("<World Version=\"1\">") && !written.contains("<JointA>"),
        "{written}"
    );
    assert!(load_text(&written).diagnostics().is_empty());

    let v3 = load_path(root.join("tests/fixtures/scenes/farseer-v3.xml"), &LoadOptions::default())
        .unwrap();
    // Written in its own dialect unless another is asked for.
    let kept = write(&v3, &WriteOptions::default()).unwrap();
    assert!(kept.starts_with("<World Version=\"3\">") && kept.contains("<Bindings>"), "{kept}");
    let box2scene = WriteOptions { dialect: Dialect::Box2scene as u32, ..Default::default() };
    let written = write(&v3, &box2scene).unwrap();
    assert!(
        written.contains("<World Version=\"2\">") && !written.contains("Bindings"),
        "{written}"
    );

    let v2 = load_path(root.join("tests/fixtures/scenes/farseer-v2.xml"), &LoadOptions::default())
        .unwrap();
    let source =
        std::fs::read_to_string(root.join("tests/fixtures/scenes/farseer-v2.xml")).unwrap();
    let farseer_only = |text: &str| -> Vec<String> {
        ["<Joint Type=\"Angle\">", "<Joint Type=\"Slider\">"]
            .iter()
            .map(|start| {
                let at = text.find(start).unwrap();
                text[at..at + text[at..].find("</Joint>").unwrap()].to_string()
            })
            .collect()
    };
    for options in MODES {
        let written = write(&v2, &options).unwrap();
        assert!(written.contains("<World Version=\"2\">"));
        // The Angle and Slider joints are written back as Farseer wrote them, in place.
        assert_eq!(farseer_only(&written), farseer_only(&source));
        let mut rest = written.clone();
        for joint in farseer_only(&written) {
            rest = rest.replace(&joint, "");
        }
        for farseer in ["Breakpoint", "LocalXAxis", "WorldAnchor", "Constant"] {
            assert!(!rest.contains(farseer), "{farseer} in:\n{written}");
        }
        let again = load_text(&written);
        let codes: Vec<_> = again.diagnostics().iter().map(|d| d.code()).collect();
        // The prismatic slider starts 1 m off its axis, as in the source.
        let violated = Some(Code::JointStartsViolated);
        assert_eq!(codes, [violated, Some(Code::FarseerOnlyJoint), Some(Code::FarseerOnlyJoint)]);
        let kinds = |s: &Scene| s.joints().iter().map(|j| j.kind().unwrap()).collect::<Vec<_>>();
        assert_eq!(kinds(&again), kinds(&v2), "joint indices stay");
        assert_eq!(kinds(&again)[10..12], [JointKind::Unsupported; 2]);
        let motor = again.joints().last().unwrap();
        assert_eq!((motor.max_force, motor.correction_factor), (50.0, 0.4));
        assert_eq!(write(&again, &options).unwrap(), written);
    }
}

#[test]
fn ten_thousand_generated_scenes_round_trip_exactly() {
    let mut random = Random(0x5EED_B0C5);
    for i in 0..10_000 {
        let xml = generate(&mut random);
        let scene = load_text(&xml);
        assert_round_trip(&scene, &format!("generated scene {i}"));
    }
}

/// The `<!-- ... -->` comments of a text, in order.
fn comments(text: &str) -> Vec<&str> {
    text.match_indices("<!--")
        .map(|(at, _)| &text[at..at + text[at..].find("-->").unwrap() + 3])
        .collect()
}

/// The unknown-element warnings of a scene, by message (elements and attributes named
/// with the object they were in).
fn unknown_content(scene: &Scene) -> Vec<String> {
    let mut found: Vec<String> = (scene.diagnostics().iter())
        .filter(|d| d.code() == Some(Code::UnknownElement))
        .map(|d| scene.text(d.message).unwrap().to_string())
        .collect();
    found.sort();
    found
}

/// What `fmt` does, over every scene file of the project: nothing the file said is lost
/// (its comments, its unknown elements and attributes, its joints), the result loads to
/// the same scene, and formatting it again gives it again.
#[test]
fn fmt_of_every_scene_file_loses_nothing_the_file_said() {
    for path in scene_files() {
        let source = std::fs::read_to_string(&path).unwrap();
        let scene = load_path(&path, &LoadOptions::default()).unwrap();
        for options in MODES {
            let what = format!("{} ({options:?})", path.display());
            let written = write(&scene, &options).unwrap();
            let mut expected = comments(&source);
            let mut got = comments(&written);
            expected.sort();
            got.sort();
            assert_eq!(got, expected, "{what}: the comments");
            let again = load_text(&written);
            assert_eq!(unknown_content(&again), unknown_content(&scene), "{what}: unknown content");
            for d in scene.diagnostics().iter().filter(|d| d.code() == Some(Code::UnknownElement)) {
                let line = source.lines().nth(d.line as usize - 1).unwrap();
                let element = line[d.column as usize - 1..].split(['>', '"']).next().unwrap();
                assert!(written.contains(element), "{what}: {element} is not written");
            }
            let kinds = |s: &Scene| s.joints().iter().map(|j| j.kind()).collect::<Vec<_>>();
            assert_eq!(kinds(&again), kinds(&scene), "{what}: the joints");
            assert_eq!(content(&again), content(&scene), "{what}: the scene");
            assert_eq!(write(&again, &options).unwrap(), written, "{what}: formatted twice");
        }
    }
}

/// Panics unless each `(before, after)` of `pairs` is written in `written` with only white
/// space between them.
#[track_caller]
fn assert_just_before(written: &str, pairs: &[(&str, &str)]) {
    for &(before, after) in pairs {
        let (b, a) = (written.find(before), written.find(after));
        assert!(
            b.zip(a).is_some_and(|(b, a)| b < a && written[b + before.len()..a].trim().is_empty()),
            "{before} is not just before {after}:\n{written}"
        );
    }
}

#[test]
fn kept_content_goes_back_where_it_was() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let scene =
        load_path(root.join("tests/fixtures/scenes/kept-content.xml"), &LoadOptions::default())
            .unwrap();
    let written = write(&scene, &WriteOptions::default()).unwrap();
    assert_just_before(
        &written,
        &[
            ("<!-- before the world -->", "<World Version=\"2\">"),
            ("<Body Type=\"Static\" Author=\"level-tool\">", "<Fixtures />"),
            ("<!-- before the gravity -->", "<Gravity>"),
            ("<!-- the first shape -->", "<Shape Type=\"Circle\" Layer=\"front\">"),
            ("<!-- before the position -->", "<Position>"),
            ("<!-- between shapes -->", "<Shape Type=\"Polygon\">"),
            ("<!-- before the end of the shapes -->", "</Shapes>"),
            ("<!-- inside the filter -->", "<Priority>2</Priority>"),
            ("<Priority>2</Priority>", "</FilterData>"),
            ("<Spin>1</Spin>", "</MassData>"),
            ("<!-- at the end of the body -->", "</Body>"),
            ("<Wind Strength=\"3\">east</Wind>", "<!-- before the end of the world -->"),
            ("<!-- before the end of the world -->", "</World>"),
            ("</World>", "<!-- after the world -->"),
        ],
    );
    let angle = "<TargetAngle>0.5</TargetAngle>\n    </Joint>\n    <Joint Type=\"Revolute\">";
    assert!(written.contains(angle), "the Angle joint in its place:\n{written}");
    let gear = scene.joints()[3];
    let again = load_text(&written);
    assert_eq!(
        (again.joints()[3].joint_a, again.joints()[3].joint_b),
        (gear.joint_a, gear.joint_b)
    );
    assert_eq!((gear.joint_a, gear.joint_b), (1, 2), "past the Angle joint, in place");
}

/// A joint of the unsupported kind has no form a host could build: it is refused, naming
/// it, before any scene could hold it without its text.
#[test]
fn a_built_unsupported_joint_is_refused_naming_it() {
    let mut builder = box2scene::Builder::new();
    let body = box2scene::Body::new(box2scene::BodyKind::Static);
    for _ in 0..2 {
        builder.add_body(&body, None, &[]).unwrap();
    }
    let joint =
        box2scene::Joint { body_a: 0, body_b: 1, ..box2scene::Joint::new(JointKind::Unsupported) };
    let error = builder.add_joint(&joint, Some("slider")).unwrap_err();
    assert!(error.message.starts_with("joint 0: "), "{error}");
}

/// A Version 3 body with the unknown attributes of its `<Pair>`s: the attribute of one Pair
/// goes onto the body's start tag and reads back; two of one name (or one named as the
/// writer's own `Type`) would make a file no XML parser reads, so the scene is refused,
/// naming the body, and nothing is written.
#[test]
fn pair_attributes_go_onto_their_body_and_never_twice() {
    let with_pairs = |pairs: &str| {
        format!(
            r#"<World Version="3">
  <Shapes><Shape Type="Circle" Density="1"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>
  <Fixtures><Fixture Id="7"/></Fixtures>
  <Bodies><Body Type="Dynamic"><Bindings>{pairs}</Bindings></Body></Bodies>
  <Joints/>
</World>"#
        )
    };
    let one = load_text(&with_pairs(r#"<Pair FixtureId="0" ShapeId="0" Layer="front"/>"#));
    let written = assert_round_trip(&one, "one Pair attribute");
    assert!(written.contains(r#"<Body Type="Dynamic" Layer="front">"#), "{written}");

    for pairs in [
        r#"<Pair FixtureId="0" ShapeId="0" Layer="a"/><Pair FixtureId="0" ShapeId="0" layer="b"/>"#,
        r#"<Pair FixtureId="0" ShapeId="0" Type="x"/>"#,
    ] {
        let scene = load_text(&with_pairs(pairs));
        for options in MODES {
            let error = write(&scene, &options).unwrap_err();
            assert_eq!(error.code, Code::DuplicateAttribute, "{pairs}: {error}");
            assert!(error.message.starts_with("body 0 would carry the attribute "), "{error}");
        }
    }
}

/// Fuzz finding (roundtrip target): what a Version 3 fixture template that no Pair names
/// held beyond its records has no fixture to go back into. Its unknown elements went to
/// the end of `<Fixtures>`, where a container allows nothing but its items, so the file
/// written did not load; they go to the end of the world now, its unknown attributes onto
/// `<World>` and the comments around it to the end of `<Fixtures>`, and all of it reads
/// back there.
#[test]
fn fuzz_roundtrip_what_an_unnamed_template_held_is_written_where_it_reads_back() {
    let xml = r#"<World Version="3">
  <Shapes><Shape Type="Circle" Density="1"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>
  <Fixtures>
    <!-- the unnamed one -->
    <Fixture Id="1" Layer="back"><FilterData><Ignores/></FilterData><Sound>thud</Sound></Fixture>
    <Fixture Id="2"><Hint>a</Hint></Fixture>
  </Fixtures>
  <Bodies><Body Type="Dynamic"><Bindings><Pair FixtureId="1" ShapeId="0"/></Bindings></Body></Bodies>
  <Joints/>
</World>"#;
    let scene = load_text(xml);
    assert_eq!(scene.fixtures().len(), 1);
    let written = assert_round_trip(&scene, "an unnamed template's content");
    assert_just_before(
        &written,
        &[
            ("<World Version=\"1\" Layer=\"back\">", "<Shapes>"),
            ("<Hint>a</Hint>", "</Fixture>"),
            ("<!-- the unnamed one -->", "</Fixtures>"),
            ("<Joints />", "<Ignores/>"),
            ("<Ignores/>", "<Sound>thud</Sound>"),
            ("<Sound>thud</Sound>", "</World>"),
        ],
    );
    let again = load_text(&written);
    assert_eq!(unknown_content(&again).len(), unknown_content(&scene).len());
}

/// Fuzz finding: a `<Centroid>` on a circle or an edge is ignored with a warning, so it must
/// not mark the centroid as given, or the scene written reads back differently.
#[test]
fn an_ignored_centroid_round_trips() {
    let circle = "<Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position>\
                  <Centroid>1 2</Centroid></Shape>";
    let edge = "<Shape Type=\"Edge\"><Centroid>1 2</Centroid><Vertex1>0 0</Vertex1>\
                <Vertex2>1 0</Vertex2></Shape>";
    for shape in [circle, edge] {
        let xml = format!(
            "<World Version=\"2\"><Shapes>{shape}</Shapes><Fixtures/><Bodies/><Joints/></World>"
        );
        let scene = load_text(&xml);
        let shape = &scene.shapes()[0];
        assert!(!shape.centroid_given, "{xml}");
        assert_eq!(shape.centroid, box2scene::Vec2::ZERO);
        assert_round_trip(&scene, &xml);
    }
}

/// A scene of one Line joint, between a static and a dynamic body, with `children` after
/// its bodies.
fn line_joint(children: &str) -> String {
    format!(
        "<World Version=\"2\"><Shapes/><Fixtures/><Bodies><Body Type=\"Static\"/>\
         <Body Type=\"Dynamic\"/></Bodies><Joints><Joint Type=\"Line\"><BodyA>0</BodyA>\
         <BodyB>1</BodyB>{children}</Joint></Joints></World>"
    )
}

/// The `unknown-element` warnings of `scene`: their messages and byte offsets.
fn ignored(scene: &Scene) -> Vec<(String, usize)> {
    (scene.diagnostics().iter())
        .filter(|d| d.code() == Some(Code::UnknownElement))
        .map(|d| (scene.text(d.message).unwrap().to_string(), d.byte_offset as usize))
        .collect()
}

/// Fuzz finding (roundtrip target): a `Line` joint with a spring is read as a Wheel joint,
/// but its children are read as a Line joint's, so an `<Axis>` in it (a Wheel's, not a
/// Line's) was ignored and kept, then written back inside the `Wheel` joint, where it is
/// read: the axis changed. An element that does not belong in a Line joint but does in a
/// Wheel joint is not kept; one that belongs in neither still is.
#[test]
fn fuzz_roundtrip_a_line_joints_wheel_element_is_not_written_back() {
    let joint =
        |extra: &str| line_joint(&format!("{extra}<Axis>1 1</Axis><LowerAngle>1</LowerAngle>"));
    for (extra, kind) in [("<FrequencyHz>4</FrequencyHz>", JointKind::Wheel), ("", JointKind::Line)]
    {
        let xml = joint(extra);
        let scene = load_text(&xml);
        let j = &scene.joints()[0];
        assert_eq!((j.kind(), j.local_axis_a), (Some(kind), box2scene::Vec2 { x: 1.0, y: 0.0 }));
        let ignored: Vec<_> = ignored(&scene).into_iter().map(|(message, _)| message).collect();
        assert_eq!(
            ignored,
            [
                "<Axis> does not belong in a Line joint; ignored",
                "<LowerAngle> does not belong in a Line joint; ignored"
            ]
        );
        let written = assert_round_trip(&scene, &xml);
        assert!(!written.contains("<Axis>"), "{written}");
        assert!(written.contains("<LowerAngle>1</LowerAngle>"), "{written}");
    }
}

/// Fuzz finding (roundtrip target): a Line joint read as a Wheel joint, for a spring or a
/// motor torque, kept the limit and the linear motor's force it was given as a Line joint;
/// the writer, which writes a Wheel joint, wrote neither, and the scene read back without
/// its limit. A Wheel joint holds neither: each element is ignored with a warning where it
/// is written, and the field keeps the wheel's default. Without the wheel's element the
/// joint is a Line joint and keeps them all.
#[test]
fn fuzz_roundtrip_a_line_joint_read_as_wheel_keeps_no_limit() {
    let joint = |extra: &str| {
        line_joint(&format!(
            "<EnableLimit>true</EnableLimit><LowerTranslation>-1</LowerTranslation>{extra}\
             <UpperTranslation>2</UpperTranslation><MaxMotorForce>5</MaxMotorForce>"
        ))
    };
    let limits =
        |j: &box2scene::Joint| (j.enable_limit, j.lower_limit, j.upper_limit, j.max_motor_force);
    for (extra, kind, held) in [
        ("<MaxMotorTorque>3</MaxMotorTorque>", JointKind::Wheel, (false, 0.0, 0.0, 0.0)),
        ("<FrequencyHz>4</FrequencyHz>", JointKind::Wheel, (false, 0.0, 0.0, 0.0)),
        ("", JointKind::Line, (true, -1.0, 2.0, 5.0)),
    ] {
        let xml = joint(extra);
        let scene = load_text(&xml);
        let j = &scene.joints()[0];
        assert_eq!((j.kind(), limits(j)), (Some(kind), held), "{xml}");
        let expected: Vec<_> = match kind {
            JointKind::Wheel => {
                ["EnableLimit", "LowerTranslation", "UpperTranslation", "MaxMotorForce"]
                    .map(|name| {
                        (
                            format!(
                                "<{name}> does not belong in a Wheel joint, which this Line joint \
                             is read as; ignored"
                            ),
                            xml.find(&format!("<{name}>")).unwrap(),
                        )
                    })
                    .to_vec()
            }
            _ => vec![],
        };
        assert_eq!(ignored(&scene), expected, "{xml}");
        let written = assert_round_trip(&scene, &xml);
        assert_eq!(written.contains("<EnableLimit>"), kind == JointKind::Line, "{written}");
    }
}

/// A scene loaded with limits above the defaults may hold a name or UserData that a load
/// with the default options would refuse from the written file: the writer refuses the
/// scene, naming the object and the field, rather than write a file that does not load.
#[test]
fn what_a_default_load_would_refuse_is_not_written() {
    let most = LoadOptions::default().max_text_bytes as usize;
    let generous =
        LoadOptions { max_text_bytes: 4 << 20, max_depth: 200, ..LoadOptions::default() };
    let name = "n".repeat(most + 1);
    let long_name = format!(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies><Body Type=\"Static\"/>\
         <Body Type=\"Static\"><Name>{name}</Name></Body></Bodies><Joints/></World>"
    );
    let deep = "<a>".repeat(61) + &"</a>".repeat(61);
    let deep_user_data = format!(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies/><Joints><Joint Type=\"Weld\">\
         <BodyA>0</BodyA><BodyB>1</BodyB><UserData>{deep}</UserData></Joint></Joints></World>"
    )
    .replace("<Bodies/>", "<Bodies><Body Type=\"Static\"/><Body Type=\"Static\"/></Bodies>");
    // <World>, <Odd> and 63 more: one level past the limit.
    let deep_unknown = format!(
        "<World Version=\"1\"><Odd>{}</Odd><Shapes/><Fixtures/><Bodies/><Joints/></World>",
        "<a>".repeat(63) + &"</a>".repeat(63)
    );
    let cases = [
        (long_name, Code::LimitExceeded, "body 1: its Name is 1048577 bytes long written"),
        (deep_user_data, Code::LimitExceeded, "joint 0: its UserData: "),
        (deep_unknown, Code::LimitExceeded, "the world: what its file held beyond the records: "),
    ];
    for (xml, code, start) in cases {
        let scene = load(xml.as_bytes(), &generous).unwrap();
        for options in MODES {
            let Err(error) = write(&scene, &options) else {
                panic!("{start}... is written");
            };
            assert_eq!(error.code, code, "{}", error.message);
            assert!(error.message.starts_with(start), "{}", error.message);
            assert!(error.message.ends_with("so the scene cannot be written"), "{}", error.message);
        }
    }
    // Just within the defaults: written, and read back.
    let at_limit = format!(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies><Body Type=\"Static\">\
         <Name>{}</Name><UserData>{}</UserData></Body></Bodies><Joints/></World>",
        "n".repeat(most),
        "<a>".repeat(60) + &"</a>".repeat(60)
    )
    .replace(
        "<Shapes/>",
        &format!("<Odd>{}</Odd><Shapes/>", "<a>".repeat(62) + &"</a>".repeat(62)),
    );
    assert_round_trip(
        &load(at_limit.as_bytes(), &generous).unwrap(),
        "names and UserData at the limits",
    );
}
