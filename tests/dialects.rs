//! The writer's dialects (docs/format.md, "Dialects"): the hand-made example of each engine's
//! form in tests/fixtures/dialects/ loads to the scene it describes and comes back out equal to
//! itself; and every scene file of the project, written for each engine's reader, keeps
//! that reader's rules, one test per rule, and reads back to the same world.

// Only the random numbers and the comparison of scenes: the generator of every field is
// the other tests'.
#[allow(dead_code)]
mod common;

use std::path::{Path, PathBuf};

use common::{Random, content};

use box2scene::{
    Code, Dialect, JointKind, LoadOptions, Scene, ShapeKind, Vec2, WriteOptions, load, load_path,
    write,
};

const ENGINES: [Dialect; 4] =
    [Dialect::Farseer33, Dialect::Farseer2013, Dialect::Farseer35, Dialect::Aether];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn example(dialect: Dialect) -> PathBuf {
    root().join("tests/fixtures/dialects").join(format!("{}.xml", dialect.name()))
}

/// Every scene file of the project: its scenes, the examples', the C tests', the editor's
/// corpus, and the dialect examples.
fn scene_files() -> Vec<PathBuf> {
    let dirs = [
        "tests/fixtures/scenes",
        "examples/scenes",
        "tests/fixtures/adapter",
        "tests/fixtures/corpus",
    ];
    let mut files: Vec<PathBuf> = dirs
        .iter()
        .flat_map(|dir| std::fs::read_dir(root().join(dir)).unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "xml"))
        .chain(ENGINES.map(example))
        .collect();
    files.sort();
    assert!(files.len() >= 15, "{files:?}");
    files
}

fn options(dialect: Dialect) -> WriteOptions {
    WriteOptions { dialect: dialect as u32, ..WriteOptions::default() }
}

/// Each scene file that loads, written for `dialect`: the texts written, after checking that
/// every refusal is `dialect-cannot-hold` naming an object.
fn written(dialect: Dialect) -> Vec<(PathBuf, Scene, String)> {
    let mut out = Vec::new();
    for path in scene_files() {
        let Ok(scene) = load_path(&path, &LoadOptions::default()) else { continue };
        match write(&scene, &options(dialect)) {
            Ok(text) => out.push((path, scene, text)),
            Err(e) => {
                assert_eq!(e.code, Code::DialectCannotHold, "{}: {e}", path.display());
                let names_object = ["the world", "shape ", "fixture ", "body ", "joint "]
                    .iter()
                    .any(|o| e.message.starts_with(o));
                assert!(names_object && e.message.contains(dialect.name()), "{}", e.message);
            }
        }
    }
    assert!(out.len() >= 2, "{} wrote only {} files", dialect.name(), out.len());
    out
}

/// For every engine, every file written for it: `check(dialect, file, text)`.
fn each_written(mut check: impl FnMut(Dialect, &Path, &str)) {
    for dialect in ENGINES {
        for (path, _, text) in written(dialect) {
            check(dialect, &path, &text);
        }
    }
}

/// The part of `text` the readers' tokenizer reads: up to `</World>`.
fn read_part(text: &str) -> &str {
    &text[..text.find("</World>").expect("a world") + "</World>".len()]
}

/// The start tags of `text`, each as its name and its attributes in order.
fn start_tags(text: &str) -> Vec<(String, Vec<(String, String)>)> {
    let document = roxmltree::Document::parse(text).unwrap();
    document
        .descendants()
        // A fixture's `<Shape>` is a value, not a shape.
        .filter(|n| {
            n.is_element() && n.parent_element().is_none_or(|p| p.tag_name().name() != "Fixture")
        })
        .map(|n| {
            let attributes =
                n.attributes().map(|a| (a.name().to_owned(), a.value().to_owned())).collect();
            (n.tag_name().name().to_owned(), attributes)
        })
        .collect()
}

#[test]
fn each_example_is_read_in_its_dialect_and_formatted_to_itself() {
    for dialect in ENGINES {
        let path = example(dialect);
        let text = std::fs::read_to_string(&path).unwrap();
        let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
        assert_eq!(scene.dialect(), dialect, "{}", path.display());
        assert_eq!(write(&scene, &WriteOptions::default()).unwrap(), text, "{}", path.display());
        assert_eq!(write(&scene, &options(dialect)).unwrap(), text);
    }
}

#[test]
fn the_examples_describe_their_scenes() {
    for dialect in ENGINES {
        let scene = load_path(example(dialect), &LoadOptions::default()).unwrap();
        let what = dialect.name();
        assert_eq!(scene.gravity(), Some(Vec2::new(0.0, -9.5)), "{what}");
        let dynamic = &scene.bodies()[1];
        assert_eq!((dynamic.angle, dynamic.position), (0.25, Vec2::new(-2.5, 3.0)), "{what}");
        let ud = scene.user_data_at(dynamic.user_data).unwrap();
        assert_eq!(
            (scene.text(ud.type_name), scene.text(ud.value)),
            (Some("System.Int32"), Some("7")),
            "{what}"
        );
        let f = scene.fixtures();
        assert_eq!((f[1].density, f[1].restitution, f[1].friction), (2.5, 0.5, 0.2), "{what}");
        assert_eq!((f[1].filter.category_bits, f[1].filter.mask_bits), (2, 5), "{what}");
        assert_eq!(f[1].filter.group_index, -3, "{what}");
        assert_eq!(f[1].is_sensor, dialect != Dialect::Farseer33, "{what}");
        assert_eq!(scene.body_fixtures(dynamic), [1, 2], "{what}: fixtures in their places");
        let prismatic = &scene.joints()[1];
        assert_eq!(prismatic.kind(), Some(JointKind::Prismatic));
        if dialect == Dialect::Farseer33 {
            assert_eq!(prismatic.local_axis_a, Vec2::new(1.0, 0.0));
            continue;
        }
        // The world axis (0.9689124, 0.247404) of a body A turned by 0.25 rad.
        let axis = prismatic.local_axis_a;
        assert!((axis.x - 1.0).abs() < 1e-6 && axis.y.abs() < 1e-6, "{what}: {axis:?}");
        let wheel = &scene.joints()[4];
        assert_eq!(wheel.kind(), Some(JointKind::Wheel));
        let axis = wheel.local_axis_a;
        assert!(axis.x.abs() < 1e-6 && (axis.y - 1.0).abs() < 1e-6, "{what}: {axis:?}");
        let open = &scene.shapes()[3];
        assert_eq!((open.kind(), open.is_loop), (Some(ShapeKind::Chain), false));
        assert!(!open.has_prev_vertex && !open.has_next_vertex, "{what}");
        let closed = &scene.shapes()[4];
        assert!(closed.is_loop, "{what}: first vertex repeated at the end");
        assert_eq!(scene.vertices(closed).len(), 4, "{what}");
    }
}

/// An open chain's ghosts without `Has` flags count unless they are (0, 0).
#[test]
fn flagless_ghosts_of_an_engine_file_are_present_unless_zero() {
    let text = std::fs::read_to_string(example(Dialect::Farseer35)).unwrap().replace(
        "<Vertex>0 5</Vertex></Vertices></Shape>",
        "<Vertex>0 5</Vertex></Vertices><NextVertex>5 6</NextVertex><PrevVertex>0 0</PrevVertex></Shape>",
    );
    let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
    let chain = &scene.shapes()[3];
    assert_eq!((chain.has_next_vertex, chain.next_vertex), (true, Vec2::new(5.0, 6.0)));
    assert!(!chain.has_prev_vertex);
    assert_eq!(
        write(&scene, &WriteOptions::default())
            .unwrap()
            .replace("<PrevVertex>0 0</PrevVertex>", ""),
        text.replace("<PrevVertex>0 0</PrevVertex>", "")
    );
}

/// A UserData of a program's own class keeps the type name its file states.
#[test]
fn user_data_of_a_programs_own_class_keeps_its_type_name() {
    let payload = "<Type>Game.Payload, Game, Version=1.0.0.0</Type><Value><Payload><Hp>3</Hp><Tag>boss</Tag></Payload></Value>";
    let text = std::fs::read_to_string(example(Dialect::Farseer35))
        .unwrap()
        .replace("<Type>System.Int32</Type><Value><int>7</int></Value>", payload);
    let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
    let ud = scene.user_data_at(scene.bodies()[1].user_data).unwrap();
    assert_eq!(scene.text(ud.type_name), Some("Game.Payload, Game, Version=1.0.0.0"));
    assert_eq!(scene.text(ud.value), None, "an object has no text of its own");
    assert_eq!(scene.text(ud.raw), Some(payload));
}

/// Body A turned: the world axis of a built scene is written so that it reads back to the
/// same local axis, bit for bit.
#[test]
fn a_built_local_axis_reads_back_exactly_through_a_world_axis() {
    let text = std::fs::read_to_string(example(Dialect::Farseer2013)).unwrap();
    let mut scene_text = text.clone();
    for (angle, axis) in [("0.7", "0.6 0.8"), ("-2.5", "0.28 -0.96"), ("3", "1 0")] {
        scene_text = scene_text
            .replace("<Angle>0.25</Angle>", &format!("<Angle>{angle}</Angle>"))
            .replace("<Axis>0.9689124 0.247404</Axis>", &format!("<Axis>{axis}</Axis>"));
        let scene = load(scene_text.as_bytes(), &LoadOptions::default()).unwrap();
        let rebuilt = write(&scene, &options(Dialect::Box2scene)).unwrap();
        let local = load(rebuilt.as_bytes(), &LoadOptions::default()).unwrap();
        let again = write(&local, &options(Dialect::Farseer2013)).unwrap();
        let back = load(again.as_bytes(), &LoadOptions::default()).unwrap();
        let bits = |s: &Scene| {
            let a = s.joints()[1].local_axis_a;
            (a.x.to_bits(), a.y.to_bits())
        };
        assert_eq!(bits(&back), bits(&local), "{angle} {axis}");
        scene_text = text.clone();
    }
}

#[test]
fn no_target_writes_an_xml_declaration() {
    for dialect in Dialect::ALL {
        for path in scene_files() {
            let Ok(scene) = load_path(&path, &LoadOptions::default()) else { continue };
            if let Ok(text) = write(&scene, &options(dialect)) {
                assert!(!text.contains("<?xml"), "{} {}", dialect.name(), path.display());
            }
        }
    }
}

/// What is written reads back through box2scene to the same world: every body with its
/// fixtures and their shapes (a two-vertex polygon comes back as the edge it is), every
/// joint (a plain 2.1 line joint comes back as the 0 Hz wheel joint the engines have), the
/// gravity, the user data.
#[test]
fn rule_reads_back_to_the_same_world() {
    for dialect in ENGINES {
        for (path, scene, text) in written(dialect) {
            let again = load(text.as_bytes(), &LoadOptions::default())
                .unwrap_or_else(|e| panic!("{} {}: {e}\n{text}", dialect.name(), path.display()));
            assert_eq!(world(&again), world(&scene), "{} {}", dialect.name(), path.display());
            assert_eq!(write(&again, &options(dialect)).unwrap(), text, "written stably");
        }
    }
}

fn world(scene: &Scene) -> String {
    let text = |s| scene.text(s).map(str::to_owned);
    let user = |i| scene.user_data_at(i).map(|u| (text(u.raw), text(u.type_name), text(u.value)));
    let mut out = format!("{:?}\n", scene.gravity());
    for body in scene.bodies() {
        let b = box2scene::Body {
            name: box2scene::Str::NULL,
            fixtures: Default::default(),
            user_data: 0,
            ..*body
        };
        out += &format!("{b:?} {:?} {:?}\n", text(body.name), user(body.user_data));
        for &f in scene.body_fixtures(body) {
            let fixture = scene.fixtures()[f as usize];
            let mut shape = scene.shapes()[fixture.shape as usize];
            // A two-vertex polygon is the line segment an edge is.
            if shape.kind() == Some(ShapeKind::Polygon) && shape.vertices.count == 2 {
                shape.kind = ShapeKind::Edge as u32;
                shape.centroid_given = false;
            }
            let (has_prev, has_next) = (shape.has_prev_vertex, shape.has_next_vertex);
            out += &format!(
                "  {:?} {:?} {:?} {:?} {} {:?} {:?} {:?} {:?} {:?} {:?} {:?} {:?}\n",
                (fixture.density, fixture.friction, fixture.restitution, fixture.filter),
                (fixture.is_sensor, text(fixture.name), user(fixture.user_data)),
                (shape.kind, shape.radius, shape.position, text(shape.name)),
                scene.vertices(&shape),
                shape.centroid_given,
                shape.centroid_given.then_some(shape.centroid),
                shape.is_loop,
                has_prev,
                has_next,
                has_prev.then_some(shape.prev_vertex),
                has_next.then_some(shape.next_vertex),
                (),
                (),
            );
        }
    }
    for joint in scene.joints() {
        let mut j = box2scene::Joint { name: box2scene::Str::NULL, user_data: 0, ..*joint };
        if j.kind() == Some(JointKind::Line) {
            j.kind = JointKind::Wheel as u32;
            (j.frequency_hz, j.damping_ratio) = (0.0, 0.0);
        }
        if j.kind() == Some(JointKind::Unsupported) {
            j = box2scene::Joint {
                body_a: j.body_a,
                body_b: j.body_b,
                ..box2scene::Joint::new(JointKind::Unsupported)
            };
        }
        out += &format!("{j:?} {:?} {:?}\n", text(joint.name), user(joint.user_data));
    }
    out
}

#[test]
fn rule_no_markup_the_tokenizer_cannot_take() {
    each_written(|dialect, path, text| {
        let read = read_part(text);
        let what = format!("{} {}", dialect.name(), path.display());
        for markup in ["<?", "<!", "]]>"] {
            assert!(!read.contains(markup), "{what}: {markup}");
        }
        // Entities only inside user data, which goes to an XML parser of its own.
        let mut outside = read.to_owned();
        for element in ["UserData", "Tag"] {
            while let (Some(a), Some(b)) =
                (outside.find(&format!("<{element}>")), outside.find(&format!("</{element}>")))
            {
                outside.replace_range(a..b + element.len() + 3, "");
            }
        }
        let names_only = outside.contains("<Name>");
        assert!(!outside.contains('&') || names_only, "{what}: an entity outside UserData");
        roxmltree::Document::parse(text).unwrap_or_else(|e| panic!("{what}: {e}"));
        for (name, attributes) in start_tags(read) {
            for (key, value) in attributes {
                let bad = value.contains(|c: char| c.is_whitespace() || "/<>=\"'".contains(c));
                assert!(!bad && !value.is_empty(), "{what}: <{name} {key}=\"{value}\">");
            }
        }
        assert!(!read.contains('\''), "{what}: attributes are double-quoted");
    });
}

#[test]
fn rule_attributes_in_the_order_read() {
    each_written(|dialect, path, text| {
        let what = format!("{} {}", dialect.name(), path.display());
        let v3 = matches!(dialect, Dialect::Farseer35 | Dialect::Aether);
        for (name, attributes) in start_tags(read_part(text)) {
            let keys: Vec<&str> = attributes.iter().map(|(k, _)| k.as_str()).collect();
            let expected: &[&str] = match name.as_str() {
                "World" => &["Version"],
                "Shape" if v3 => &["Type", "Density"],
                "Shape" | "Joint" => &["Type"],
                "Fixture" if dialect == Dialect::Farseer33 => &[],
                "Fixture" => &["Id"],
                "Body" if dialect == Dialect::Farseer2013 => &["Id", "Type"],
                "Body" => &["Type"],
                "Pair" => &["FixtureId", "ShapeId"],
                _ => &[],
            };
            assert_eq!(keys, expected, "{what}: <{name}>");
        }
    });
}

/// The readers give an omitted element 0, false or (0, 0): every field they read is there.
#[test]
fn rule_every_field_present() {
    each_written(|dialect, path, text| {
        let what = format!("{} {}", dialect.name(), path.display());
        let document = roxmltree::Document::parse(text).unwrap();
        let v2 = matches!(dialect, Dialect::Farseer33 | Dialect::Farseer2013);
        let has = |node: roxmltree::Node, names: &[&str]| {
            for name in names {
                let found = node.children().any(|c| c.tag_name().name() == *name);
                assert!(found, "{what}: <{}> without <{name}>", node.tag_name().name());
            }
        };
        for node in document.descendants().filter(|n| n.is_element()) {
            let ty = node.attribute("Type").unwrap_or_default();
            match node.tag_name().name() {
                "Fixture" => {
                    has(node, &["FilterData", "Friction", "IsSensor", "Restitution"]);
                    if v2 {
                        has(node, &["Shape", "Density"]);
                    }
                }
                "FilterData" => has(node, &["CategoryBits", "MaskBits", "GroupIndex"]),
                "Body" => has(
                    node,
                    &[
                        "Active",
                        "AllowSleep",
                        "Angle",
                        "AngularDamping",
                        "AngularVelocity",
                        "Awake",
                        "Bullet",
                        "FixedRotation",
                        "LinearDamping",
                        "LinearVelocity",
                        "Position",
                    ],
                ),
                "Shape" if ty == "Circle" => has(node, &["Radius", "Position"]),
                "Shape" if ty == "Polygon" || ty == "Chain" => has(node, &["Vertices"]),
                "Shape" if ty == "Edge" => has(node, &["Vertex1", "Vertex2"]),
                "Joint" => {
                    has(node, &["BodyA", "BodyB", "CollideConnected"]);
                    let axis = if dialect == Dialect::Farseer33 { "LocalXAxis" } else { "Axis" };
                    let prismatic_axis =
                        if dialect == Dialect::Farseer33 { "LocalXAxis1" } else { "Axis" };
                    let fields: &[&str] = match ty {
                        "Revolute" => &[
                            "EnableLimit",
                            "EnableMotor",
                            "LocalAnchorA",
                            "LocalAnchorB",
                            "LowerAngle",
                            "MaxMotorTorque",
                            "MotorSpeed",
                            "ReferenceAngle",
                            "UpperAngle",
                        ],
                        "Prismatic" => &[
                            "EnableLimit",
                            "EnableMotor",
                            "LocalAnchorA",
                            "LocalAnchorB",
                            prismatic_axis,
                            "LowerTranslation",
                            "UpperTranslation",
                            "MaxMotorForce",
                            "MotorSpeed",
                            "ReferenceAngle",
                        ],
                        "Distance" => &[
                            "DampingRatio",
                            "FrequencyHz",
                            "Length",
                            "LocalAnchorA",
                            "LocalAnchorB",
                        ],
                        "Pulley" if dialect == Dialect::Farseer33 => &[
                            "GroundAnchorA",
                            "GroundAnchorB",
                            "LengthA",
                            "LengthB",
                            "LocalAnchorA",
                            "LocalAnchorB",
                            "MaxLengthA",
                            "MaxLengthB",
                            "Ratio",
                        ],
                        "Pulley" => &[
                            "WorldAnchorA",
                            "WorldAnchorB",
                            "LengthA",
                            "LengthB",
                            "LocalAnchorA",
                            "LocalAnchorB",
                            "Ratio",
                            "Constant",
                        ],
                        "Line" | "Wheel" => &[
                            "EnableMotor",
                            "LocalAnchorA",
                            "LocalAnchorB",
                            "MotorSpeed",
                            "DampingRatio",
                            "MaxMotorTorque",
                            "FrequencyHz",
                            axis,
                        ],
                        "Weld" => &["LocalAnchorA", "LocalAnchorB"],
                        "Friction" => &["LocalAnchorA", "LocalAnchorB", "MaxForce", "MaxTorque"],
                        "Rope" => &["LocalAnchorA", "LocalAnchorB", "MaxLength"],
                        "Motor" => &[
                            "AngularOffset",
                            "LinearOffset",
                            "MaxForce",
                            "MaxTorque",
                            "CorrectionFactor",
                        ],
                        _ => &[],
                    };
                    has(node, fields);
                }
                _ => {}
            }
        }
    });
}

/// Vectors `X Y` with one space and nothing before X; floats with a point; bools
/// `true`/`false`; filter bits decimal Int32, groups Int16; no empty value.
#[test]
fn rule_value_formats() {
    let vectors = [
        "Gravity",
        "Position",
        "Vertex",
        "Vertex0",
        "Vertex1",
        "Vertex2",
        "Centroid",
        "NextVertex",
        "PrevVertex",
        "LinearVelocity",
        "LocalAnchorA",
        "LocalAnchorB",
        "Axis",
        "LocalXAxis",
        "LocalXAxis1",
        "GroundAnchorA",
        "GroundAnchorB",
        "WorldAnchorA",
        "WorldAnchorB",
        "LinearOffset",
    ];
    let bools = [
        "Active",
        "AllowSleep",
        "Awake",
        "Bullet",
        "FixedRotation",
        "IsSensor",
        "HasVertex0",
        "CollideConnected",
        "EnableLimit",
        "EnableMotor",
    ];
    let float =
        |t: &str| !t.contains(',') && t.parse::<f32>().is_ok_and(f32::is_finite) && t.trim() == t;
    each_written(|dialect, path, text| {
        let what = format!("{} {}", dialect.name(), path.display());
        let document = roxmltree::Document::parse(text).unwrap();
        let in_user_data = |n: roxmltree::Node| {
            n.ancestors().any(|a| matches!(a.tag_name().name(), "UserData" | "Tag"))
        };
        for node in document.descendants().filter(|n| n.is_element() && !in_user_data(*n)) {
            let name = node.tag_name().name();
            let leaf = node.children().all(|c| !c.is_element());
            if !leaf || matches!(name, "Pair" | "Fixtures" | "Bindings" | "Name") {
                continue;
            }
            let value = node.text().unwrap_or_default();
            let ok = if vectors.contains(&name) {
                value.split_once(' ').is_some_and(|(x, y)| float(x) && float(y))
            } else if bools.contains(&name) {
                value == "true" || value == "false"
            } else if matches!(
                name,
                "CategoryBits" | "MaskBits" | "Shape" | "ID" | "BodyA" | "BodyB"
            ) {
                value.parse::<i32>().is_ok_and(|v| v >= 0)
            } else if name == "GroupIndex" {
                value.parse::<i16>().is_ok()
            } else {
                float(value)
            };
            assert!(ok, "{what}: <{name}>{value}</{name}>");
        }
        for (name, attributes) in start_tags(read_part(text)) {
            if let Some((_, density)) = attributes.iter().find(|(k, _)| k == "Density") {
                assert!(float(density), "{what}: <{name} Density=\"{density}\">");
            }
        }
    });
}

/// Circle, Edge and Chain shapes throw on any child they do not read; chains have no `Has`
/// or loop flags, edges no `Vertex3` ghost.
#[test]
fn rule_shapes_hold_only_what_their_reader_reads() {
    each_written(|dialect, path, text| {
        let what = format!("{} {}", dialect.name(), path.display());
        let document = roxmltree::Document::parse(text).unwrap();
        let shapes = document.descendants().filter(|n| {
            n.tag_name().name() == "Shape"
                && n.parent_element().is_some_and(|p| p.tag_name().name() == "Shapes")
        });
        for shape in shapes {
            let allowed: &[&str] = match shape.attribute("Type").unwrap() {
                "Circle" => &["Radius", "Position"],
                "Edge" => &["Vertex1", "Vertex2", "HasVertex0", "Vertex0"],
                "Chain" => &["Vertices", "NextVertex", "PrevVertex"],
                "Polygon" => &["Vertices", "Centroid", "Name"],
                other => panic!("{what}: shape type {other}"),
            };
            for child in shape.children().filter(|c| c.is_element()) {
                assert!(allowed.contains(&child.tag_name().name()), "{what}: {:?}", child);
            }
        }
    });
}

/// The joint types and the user data element each reader knows.
#[test]
fn rule_joint_types_and_user_data_the_reader_knows() {
    each_written(|dialect, path, text| {
        let what = format!("{} {}", dialect.name(), path.display());
        let document = roxmltree::Document::parse(text).unwrap();
        let known: &[&str] = match dialect {
            Dialect::Farseer33 => &[
                "Revolute",
                "Prismatic",
                "Distance",
                "Pulley",
                "Line",
                "Weld",
                "Friction",
                "Rope",
                "Angle",
                "Slider",
            ],
            _ => &[
                "Revolute",
                "Prismatic",
                "Distance",
                "Pulley",
                "Wheel",
                "Weld",
                "Friction",
                "Rope",
                "Motor",
                "Angle",
            ],
        };
        for joint in document.descendants().filter(|n| n.tag_name().name() == "Joint") {
            let ty = joint.attribute("Type").unwrap();
            assert!(known.contains(&ty), "{what}: a {ty} joint");
        }
        let (wanted, other) =
            if dialect == Dialect::Aether { ("Tag", "UserData") } else { ("UserData", "Tag") };
        for node in document.descendants().filter(|n| n.tag_name().name() == wanted) {
            let first = node.children().find(|c| c.is_element()).unwrap();
            assert_eq!(first.tag_name().name(), "Type", "{what}");
        }
        let outside =
            |n: &roxmltree::Node| n.ancestors().skip(1).all(|a| a.tag_name().name() != wanted);
        assert!(
            document.descendants().filter(|n| n.tag_name().name() == other).all(|n| !outside(&n)),
            "{what}: <{other}>"
        );
    });
}

/// What a reader cannot hold is refused with an error naming the object.
#[test]
fn what_a_reader_cannot_hold_is_refused_naming_the_object() {
    let base = std::fs::read_to_string(example(Dialect::Farseer2013)).unwrap();
    let cases = [
        (Dialect::Farseer33, base.clone(), "shape 3 is a chain"),
        (Dialect::Farseer33, base.clone(), "shape 3"),
        (Dialect::Farseer2013, base.replace("<Joints>", "<Joints>\n<!-- hinges -->"), "joint 0 holds comments"),
        (Dialect::Farseer35, base.replace("<Angle>0.25</Angle>", "<Angle>0.25</Angle><GravityScale>2</GravityScale>"), "body 1 has a GravityScale"),
        (Dialect::Farseer35, base.replace("<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB>", "<Joint Type=\"Gear\"><BodyA>0</BodyA><BodyB>1</BodyB><JointA>0</JointA><JointB>1</JointB>").replace("<LocalAnchorA>3 0</LocalAnchorA><LocalAnchorB>-3 0</LocalAnchorB></Joint>", "</Joint>"), "joint 5 is a gear joint"),
    ];
    for (dialect, text, message) in cases {
        let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
        let error = write(&scene, &options(dialect)).unwrap_err();
        assert_eq!(error.code, Code::DialectCannotHold, "{}", error.message);
        assert!(error.message.starts_with(message), "{}", error.message);
    }
    let scene = load(base.as_bytes(), &LoadOptions::default()).unwrap();
    let error = write(&scene, &WriteOptions { dialect: 9, ..Default::default() }).unwrap_err();
    assert_eq!(error.code, Code::InvalidArgument);
}

/// A file of an engine's dialect given a comment is no longer one its reader takes: written
/// with no dialect asked, it keeps its dialect and is refused naming the object, never
/// written in box2scene's form unasked; asked for box2scene's form, it is, losing nothing.
#[test]
fn fmt_keeps_an_engine_files_dialect_or_fails_naming_the_object() {
    for dialect in ENGINES {
        let text = std::fs::read_to_string(example(dialect))
            .unwrap()
            .replace("<Joints>", "<Joints>\n    <!-- hinges -->");
        let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
        assert_eq!(scene.dialect(), dialect);
        let error = write(&scene, &WriteOptions::default()).unwrap_err();
        assert_eq!(error.code, Code::DialectCannotHold, "{}: {}", dialect.name(), error.message);
        assert!(error.message.starts_with("joint 0 holds comments"), "{}", error.message);
        assert!(error.message.contains(dialect.name()), "{}", error.message);
        let written = write(&scene, &options(Dialect::Box2scene)).unwrap();
        assert!(
            written.starts_with("<World Version=\"2\">") && written.contains("<!-- hinges -->")
        );
    }
}

/// Farseer's `Axis` is a world axis: (0.6, 0.8) on a body A turned by 0.25 rad is
/// (0.779, 0.627) in body A's frame, for prismatic and wheel joints alike; on an unturned
/// body A it reads as written.
#[test]
fn an_axis_is_turned_into_body_as_frame() {
    for (kind, angle, expected) in [
        ("Prismatic", "0.25", Vec2::new(0.779, 0.627)),
        ("Wheel", "0.25", Vec2::new(0.779, 0.627)),
        ("Prismatic", "0", Vec2::new(0.6, 0.8)),
    ] {
        let text = format!(
            "<World Version=\"2\"><Shapes/><Fixtures/><Bodies>\
             <Body Type=\"Dynamic\"><Angle>{angle}</Angle></Body><Body Type=\"Dynamic\"/>\
             </Bodies><Joints><Joint Type=\"{kind}\"><BodyA>0</BodyA><BodyB>1</BodyB>\
             <Axis>0.6 0.8</Axis></Joint></Joints></World>"
        );
        let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
        let axis = scene.joints()[0].local_axis_a;
        let near = (axis.x - expected.x).abs() < 5e-4 && (axis.y - expected.y).abs() < 5e-4;
        assert!(near, "{kind} at {angle}: {axis:?}");
        // The world axis goes back out as the file gave it.
        let again = write(&scene, &options(Dialect::Farseer2013)).unwrap();
        assert!(again.contains("<Axis>0.6 0.8</Axis>"), "{again}");
    }
}

/// An engine's file rewritten in box2scene's form is a file of that form: formatting it
/// again gives it again.
#[test]
fn an_engine_file_rewritten_in_box2scenes_form_stays_in_it() {
    for dialect in ENGINES {
        let scene = load_path(example(dialect), &LoadOptions::default()).unwrap();
        let text = write(&scene, &options(Dialect::Box2scene)).unwrap();
        let again = load(text.as_bytes(), &LoadOptions::default()).unwrap();
        assert_eq!(again.dialect(), Dialect::Box2scene, "{}:\n{text}", dialect.name());
        assert_eq!(write(&again, &WriteOptions::default()).unwrap(), text);
    }
}

/// A Version 3 template that two bodies bind to one shape is one fixture, in its place,
/// shared by both; what a template held beyond its fields stays with its own fixture.
#[test]
fn a_template_bound_twice_to_one_shape_is_one_shared_fixture() {
    let text = "<World Version=\"3\"><Shapes>\
        <Shape Type=\"Circle\" Density=\"2\"><Radius>1</Radius><Position>0 0</Position></Shape>\
        </Shapes><Fixtures>\
        <Fixture Id=\"0\"><Friction>0.5</Friction></Fixture>\
        <Fixture Id=\"1\"><Friction>0.7</Friction><Paint>red</Paint></Fixture>\
        </Fixtures><Bodies>\
        <Body Type=\"Dynamic\"><Bindings><Pair FixtureId=\"0\" ShapeId=\"0\"/></Bindings></Body>\
        <Body Type=\"Dynamic\"><Bindings><Pair FixtureId=\"0\" ShapeId=\"0\"/></Bindings></Body>\
        <Body Type=\"Dynamic\"><Bindings><Pair FixtureId=\"1\" ShapeId=\"0\"/></Bindings></Body>\
        </Bodies><Joints/></World>";
    let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
    let frictions: Vec<f32> = scene.fixtures().iter().map(|f| f.friction).collect();
    assert_eq!(frictions, [0.5, 0.7]);
    let lists: Vec<_> = scene.bodies().iter().map(|b| scene.body_fixtures(b).to_vec()).collect();
    assert_eq!(lists, [vec![0], vec![0], vec![1]]);
    let written = write(&scene, &options(Dialect::Box2scene)).unwrap();
    let paint = written.find("<Paint>red</Paint>").unwrap();
    let second = written.match_indices("<Fixture>").nth(1).unwrap().0;
    let end = written.find("</Fixtures>").unwrap();
    assert!(second < paint && paint < end, "the unknown element stays in fixture 1:\n{written}");
}

/// Many fixtures of different densities on one shape are one written shape each, found in
/// one look-up per fixture: 300,000 of them are written in each engine dialect in a time
/// that grows with the file, seconds at most (a writer that searched the densities written
/// so far for each fixture took minutes here). Each fixture names its own shape, of its
/// own density.
#[test]
fn fixtures_of_many_densities_on_one_shape_are_written_in_linear_time() {
    const N: usize = 300_000;
    let mut text = String::from(
        "<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes><Fixtures>",
    );
    for i in 0..N {
        text += &format!("<Fixture><Shape>0</Shape><Density>{}</Density></Fixture>", i + 1);
    }
    text += "</Fixtures><Bodies><Body Type=\"Dynamic\"><Fixtures>";
    for i in 0..N {
        text += &format!("<ID>{i}</ID>");
    }
    text += "</Fixtures></Body></Bodies><Joints/></World>";
    let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
    let started = std::time::Instant::now();
    for dialect in ENGINES {
        let written = write(&scene, &options(dialect)).unwrap();
        let shapes = written.matches("<Shape Type=\"Circle\"").count();
        assert_eq!(shapes, N, "{}: one written shape per density", dialect.name());
        let last = match dialect {
            Dialect::Farseer33 | Dialect::Farseer2013 => {
                format!("<Shape>{}</Shape><Density>{N}</Density>", N - 1)
            }
            _ => format!("<Pair FixtureId=\"{}\" ShapeId=\"{}\" />", N - 1, N - 1),
        };
        assert!(written.contains(&last), "{}: {last}", dialect.name());
    }
    let seconds = started.elapsed().as_secs();
    assert!(seconds < 30, "{seconds} s to write {N} fixtures in four dialects");
}

/// A small scene of one dynamic body, asleep, with one circle; `joint` adds a weld to a
/// static second body.
fn asleep(joint: bool) -> Scene {
    let joints = match joint {
        true => "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>",
        false => "",
    };
    let text = format!(
        "<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>\
         <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>\
         <Bodies><Body Type=\"Dynamic\"><Awake>false</Awake><Fixtures><ID>0</ID></Fixtures></Body><Body Type=\"Static\"/></Bodies>\
         <Joints>{joints}</Joints></World>"
    );
    load(text.as_bytes(), &LoadOptions::default()).unwrap()
}

/// Farseer 3.3.1's and Aether's readers (and Velcro's) keep a body of no joint asleep;
/// Farseer 2013's and 3.5's wake it, and a joint's fields wake its bodies in every reader:
/// only those are refused.
#[test]
fn an_asleep_body_is_refused_only_where_its_reader_wakes_it() {
    for dialect in ENGINES {
        let keeps = matches!(dialect, Dialect::Farseer33 | Dialect::Aether);
        match write(&asleep(false), &options(dialect)) {
            Ok(text) => {
                assert!(keeps, "{}: {text}", dialect.name());
                assert!(text.contains("<Awake>false</Awake>"), "{text}");
            }
            Err(e) => {
                assert!(!keeps, "{}: {}", dialect.name(), e.message);
                assert!(
                    e.message.starts_with("body 0 is asleep (the reader wakes it)"),
                    "{}",
                    e.message
                );
            }
        }
        let error = write(&asleep(true), &options(dialect)).unwrap_err();
        assert_eq!(error.code, Code::DialectCannotHold);
        let why = if keeps { "body 0 is asleep and in a joint" } else { "body 0 is asleep (the" };
        assert!(error.message.starts_with(why), "{}: {}", dialect.name(), error.message);
    }
}

/// A square of corners (0, 0) and (2, 2) with the `Centroid` (0, 0) on a fixture of
/// `density`.
fn square_with_centroid_0(density: &str) -> Scene {
    let text = format!(
        "<World Version=\"1\"><Shapes><Shape Type=\"Polygon\"><Vertices><Vertex>0 0</Vertex><Vertex>2 0</Vertex>\
         <Vertex>2 2</Vertex><Vertex>0 2</Vertex></Vertices><Centroid>0 0</Centroid></Shape></Shapes>\
         <Fixtures><Fixture><Shape>0</Shape><Density>{density}</Density></Fixture></Fixtures>\
         <Bodies><Body Type=\"Static\"><Fixtures><ID>0</ID></Fixtures></Body></Bodies><Joints/></World>"
    );
    load(text.as_bytes(), &LoadOptions::default()).unwrap()
}

/// Farseer computes no mass data for a polygon of density 0, so its Version 2 readers keep
/// the file's `Centroid` there (the engine's own files say `0 0`): only a weighed polygon's
/// centroid other than its own is refused.
#[test]
fn a_density_0_polygon_keeps_its_centroid_in_version_2_dialects() {
    for dialect in [Dialect::Farseer33, Dialect::Farseer2013] {
        let text = write(&square_with_centroid_0("0"), &options(dialect)).unwrap();
        assert!(text.contains("<Centroid>0 0</Centroid>"), "{}: {text}", dialect.name());
        let again = load(text.as_bytes(), &LoadOptions::default()).unwrap();
        assert_eq!(write(&again, &WriteOptions::default()).unwrap(), text);
        let error = write(&square_with_centroid_0("1"), &options(dialect)).unwrap_err();
        assert!(
            error.message.starts_with("shape 0 has a Centroid other than its own"),
            "{}",
            error.message
        );
    }
}

/// Farseer 3.3.1's file with no joint (nothing of its own spelling) is told by its order, a
/// fixture's filter before its friction, and written back as it came: every field, the
/// friction 0.2 and category 1 that its reader would read as 0 if left out.
#[test]
fn a_farseer_3_3_file_without_joints_keeps_its_dialect_and_fields() {
    let text = std::fs::read_to_string(example(Dialect::Farseer33)).unwrap();
    let (head, rest) = text.split_once("  <Joints>\n").unwrap();
    let (_, tail) = rest.split_once("  </Joints>\n").unwrap();
    let text = format!("{head}  <Joints>\n  </Joints>\n{tail}");
    let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(scene.dialect(), Dialect::Farseer33);
    let written = write(&scene, &WriteOptions::default()).unwrap();
    assert_eq!(written, text);
    assert!(written.contains("<CategoryBits>1</CategoryBits><MaskBits>65535</MaskBits>"));
    assert!(written.contains("<Friction>0.2</Friction>"));
}

/// A fixture no body binds cannot be a Version 3 fixture (the readers make fixtures from
/// Pairs only): refused naming it, where the Version 2 dialects write it as a fixture.
#[test]
fn an_unbound_fixture_is_refused_in_version_3_dialects() {
    let text = "<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>\
        <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture><Fixture><Shape>0</Shape><Density>2</Density></Fixture></Fixtures>\
        <Bodies><Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body></Bodies><Joints/></World>";
    let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
    for dialect in ENGINES {
        match write(&scene, &options(dialect)) {
            Ok(written) => {
                assert!(matches!(dialect, Dialect::Farseer33 | Dialect::Farseer2013));
                let again = load(written.as_bytes(), &LoadOptions::default()).unwrap();
                assert_eq!(again.fixtures().len(), 2, "{}", dialect.name());
            }
            Err(e) => {
                assert!(matches!(dialect, Dialect::Farseer35 | Dialect::Aether));
                assert_eq!(e.code, Code::DialectCannotHold);
                assert!(e.message.starts_with("fixture 1 is on no body"), "{}", e.message);
            }
        }
    }
}

/// A random scene of what the engines' dialects can hold: circles, polygons and edges,
/// fixtures of random densities (shapes shared at several), on random bodies (some on
/// none, some on two), joints of the kinds every engine reads, user data of a string.
fn engine_scene(r: &mut Random) -> String {
    let mut x = String::from("<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>");
    let num = |v: f32| format!("{v}");
    let shapes = 1 + r.below(4);
    for _ in 0..shapes {
        match r.below(3) {
            0 => {
                let radius = 0.1 + r.ordinary(1.0).abs();
                let p = (r.ordinary(5.0), r.ordinary(5.0));
                x += &format!(
                    "<Shape Type=\"Circle\"><Radius>{}</Radius><Position>{} {}</Position></Shape>",
                    num(radius),
                    num(p.0),
                    num(p.1)
                );
            }
            1 => {
                let n = 3 + r.below(6);
                x += "<Shape Type=\"Polygon\"><Vertices>";
                for k in 0..n {
                    let angle = std::f32::consts::TAU * k as f32 / n as f32;
                    x += &format!("<Vertex>{} {}</Vertex>", num(angle.cos()), num(angle.sin()));
                }
                x += "</Vertices></Shape>";
            }
            _ => {
                let (a, b) = (r.ordinary(10.0), r.ordinary(10.0));
                x += &format!(
                    "<Shape Type=\"Edge\"><Vertex1>-10 {}</Vertex1><Vertex2>10 {}</Vertex2></Shape>",
                    num(a),
                    num(b)
                );
            }
        }
    }
    x += "</Shapes><Fixtures>";
    let fixtures = 1 + r.below(6);
    for _ in 0..fixtures {
        let any = r.ordinary(10.0).abs();
        let density = r.pick(&[0.0, 1.0, 2.5, any]);
        x += &format!(
            "<Fixture><Shape>{}</Shape><Density>{}</Density><Friction>{}</Friction><Restitution>{}</Restitution>\
             <FilterData><CategoryBits>{}</CategoryBits><MaskBits>{}</MaskBits><GroupIndex>{}</GroupIndex></FilterData>",
            r.below(shapes),
            num(density),
            num(r.non_negative()),
            num(r.ordinary(1.0).abs()),
            r.below(65536),
            r.below(65536),
            r.below(65536) as i64 - 32768,
        );
        if r.chance(20) {
            x += "<UserData><Type>System.String</Type><Value><string>crate</string></Value></UserData>";
        }
        x += "</Fixture>";
    }
    x += "</Fixtures><Bodies>";
    let bodies = 2 + r.below(3);
    for _ in 0..bodies {
        let kind = r.pick(&["Static", "Dynamic", "Kinematic"]);
        x += &format!(
            "<Body Type=\"{kind}\"><Angle>{}</Angle><Position>{} {}</Position><LinearVelocity>{} {}</LinearVelocity><Fixtures>",
            num(r.ordinary(3.0)),
            num(r.ordinary(10.0)),
            num(r.ordinary(10.0)),
            num(r.ordinary(2.0)),
            num(r.ordinary(2.0)),
        );
        for id in 0..fixtures {
            if r.chance(40) {
                x += &format!("<ID>{id}</ID>");
            }
        }
        x += "</Fixtures></Body>";
    }
    x += "</Bodies><Joints>";
    for _ in 0..r.below(4) {
        let a = r.below(bodies);
        let b = (a + 1 + r.below(bodies - 1)) % bodies;
        let anchors = format!(
            "<LocalAnchorA>{} 0</LocalAnchorA><LocalAnchorB>0 {}</LocalAnchorB>",
            num(r.ordinary(2.0)),
            num(r.ordinary(2.0))
        );
        let (kind, fields) = match r.below(4) {
            0 => (
                "Revolute",
                format!(
                    "<EnableLimit>true</EnableLimit><LowerAngle>-0.5</LowerAngle><UpperAngle>{}</UpperAngle>",
                    num(r.ordinary(1.0).abs())
                ),
            ),
            1 => ("Distance", format!("<Length>{}</Length>", num(0.5 + r.ordinary(3.0).abs()))),
            2 => ("Rope", format!("<MaxLength>{}</MaxLength>", num(1.0 + r.ordinary(3.0).abs()))),
            _ => ("Weld", String::new()),
        };
        x += &format!(
            "<Joint Type=\"{kind}\"><BodyA>{a}</BodyA><BodyB>{b}</BodyB>{anchors}{fields}</Joint>"
        );
    }
    x += "</Joints></World>";
    x
}

/// Random scenes of what the engines' dialects hold, written in each engine's dialect:
/// each either refused naming an object, or written as a file that loads in that dialect
/// and formats to itself, to the same scene.
#[test]
fn generated_scenes_written_in_each_dialect_format_to_themselves() {
    let mut random = Random(0xD1A1_EC75);
    let mut written_files = [0; ENGINES.len()];
    for i in 0..300 {
        let source = engine_scene(&mut random);
        let scene = load(source.as_bytes(), &LoadOptions::default())
            .unwrap_or_else(|e| panic!("scene {i}: {e}\n{source}"));
        for (d, dialect) in ENGINES.into_iter().enumerate() {
            let what = format!("generated scene {i} in {}", dialect.name());
            let text = match write(&scene, &options(dialect)) {
                Ok(text) => text,
                Err(e) => {
                    assert_eq!(e.code, Code::DialectCannotHold, "{what}: {}", e.message);
                    continue;
                }
            };
            written_files[d] += 1;
            let again = load(text.as_bytes(), &LoadOptions::default())
                .unwrap_or_else(|e| panic!("{what}: {e}\n{text}"));
            // Without user data, Farseer 3.5's text is Aether's, and read as Aether's.
            let alike = dialect == Dialect::Farseer35 && !text.contains("<UserData>");
            let read_as = if alike { Dialect::Aether } else { dialect };
            assert_eq!(again.dialect(), read_as, "{what}");
            let twice = write(&again, &WriteOptions::default()).unwrap();
            assert_eq!(twice, text, "{what}: formatted twice");
            let third = load(twice.as_bytes(), &LoadOptions::default()).unwrap();
            assert_eq!(content(&third), content(&again), "{what}");
        }
    }
    assert!(written_files.iter().all(|&n| n >= 30), "written: {written_files:?}");
}

/// A two-vertex polygon is written as the edge it is, whose centroid every reader computes
/// as its middle: another given `Centroid` is refused, as for every other polygon.
#[test]
fn a_two_vertex_polygons_centroid_other_than_its_middle_is_refused() {
    for (centroid, refused) in [("5 5", true), ("0 0", false)] {
        let text = format!(
            "<World Version=\"1\"><Shapes><Shape Type=\"Polygon\"><Vertices><Vertex>-40 0</Vertex><Vertex>40 0</Vertex></Vertices>\
             <Centroid>{centroid}</Centroid></Shape></Shapes><Fixtures><Fixture><Shape>0</Shape></Fixture></Fixtures>\
             <Bodies><Body Type=\"Static\"><Fixtures><ID>0</ID></Fixtures></Body></Bodies><Joints/></World>"
        );
        let scene = load(text.as_bytes(), &LoadOptions::default()).unwrap();
        for dialect in ENGINES {
            match write(&scene, &options(dialect)) {
                Err(e) => {
                    assert!(refused, "{}: {}", dialect.name(), e.message);
                    let why =
                        "shape 0 is a two-vertex polygon with a Centroid other than its middle";
                    assert!(e.message.starts_with(why), "{}", e.message);
                }
                Ok(written) => assert!(!refused && written.contains("<Vertex2>40 0</Vertex2>")),
            }
        }
    }
}

/// Aether's `<Tag>` of a Farseer-only joint is its user data; box2scene's dialect reads
/// `<UserData>` only, so written there the joint's text says `<UserData>`, and reads back
/// with the same user data.
#[test]
fn a_farseer_only_joints_tag_is_written_as_user_data_in_box2scenes_form() {
    let scene = load_path(example(Dialect::Aether), &LoadOptions::default()).unwrap();
    let angle =
        scene.joints().iter().position(|j| j.kind() == Some(JointKind::Unsupported)).unwrap();
    let user_data = |s: &Scene| {
        let ud = s.user_data_at(s.joints()[angle].user_data).expect("user data");
        (s.text(ud.type_name).map(str::to_owned), s.text(ud.value).map(str::to_owned))
    };
    let text = write(&scene, &options(Dialect::Box2scene)).unwrap();
    assert!(!text.contains("<Tag>"), "{text}");
    let again = load(text.as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(user_data(&again), user_data(&scene));
    assert_eq!(user_data(&again).0.as_deref(), Some("System.String"));
    assert_eq!(write(&again, &WriteOptions::default()).unwrap(), text);
}
