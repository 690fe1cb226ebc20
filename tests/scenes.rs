//! Scene files and their expected results: every `tests/fixtures/scenes/*.xml` and every
//! editor file in `tests/fixtures/corpus/` loads to the JSON dump beside it (`NAME.json`;
//! run with `BOX2SCENE_BLESS=1` to write a missing one, then read it before committing).
//! Plus exact values, container order and letter case, and the fixtures' index complete.

// The files hold the editor's own text of pi/2 and -pi/4, compared exactly.
#![allow(clippy::approx_constant)]

use std::path::{Path, PathBuf};

use box2scene::{
    BodyKind, Code, JointKind, LoadOptions, Range, Scene, ShapeKind, Vec2, load, load_path,
};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn load_file(path: &Path) -> Scene {
    load_path(path, &LoadOptions::default()).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn xml_files(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "xml"))
        .collect();
    files.sort();
    files
}

/// The fixtures' index (`tests/fixtures/README.md`) names every file under the folder,
/// a JSON dump through its scene's line, and nothing that is not there.
#[test]
fn the_fixture_index_names_every_fixture() {
    let fixtures = root().join("tests/fixtures");
    let index = std::fs::read_to_string(fixtures.join("README.md")).unwrap();
    let listed: Vec<&str> =
        (index.lines()).filter_map(|line| line.strip_prefix("| `")?.split('`').next()).collect();
    let mut present = Vec::new();
    for folder in std::fs::read_dir(&fixtures).unwrap() {
        let folder = folder.unwrap().path();
        if !folder.is_dir() {
            continue;
        }
        for file in std::fs::read_dir(&folder).unwrap() {
            let file = file.unwrap().path();
            let relative = file.strip_prefix(&fixtures).unwrap().to_str().unwrap().to_owned();
            present.push(relative);
        }
    }
    for file in &present {
        let scene = file.strip_suffix(".json").map(|stem| format!("{stem}.xml"));
        let named = listed.contains(&file.as_str())
            || scene.is_some_and(|xml| listed.contains(&xml.as_str()) && present.contains(&xml));
        assert!(named, "tests/fixtures/{file} is not in tests/fixtures/README.md");
    }
    for file in listed {
        assert!(present.iter().any(|p| p == file), "the index names {file}, which is not there");
    }
}

#[test]
fn every_scene_matches_its_golden_dump() {
    let files: Vec<PathBuf> =
        [root().join("tests/fixtures/scenes"), root().join("tests/fixtures/corpus")]
            .iter()
            .flat_map(|dir| xml_files(dir))
            .collect();
    assert!(files.len() >= 7, "scenes and the four editor files: {files:?}");
    for xml in files {
        let golden = xml.with_extension("json");
        let dump = load_file(&xml).to_json();
        if !golden.exists() && std::env::var_os("BOX2SCENE_BLESS").is_some() {
            std::fs::write(&golden, &dump).unwrap();
        }
        let expected = std::fs::read_to_string(&golden)
            .unwrap_or_else(|e| panic!("{}: {e} (BOX2SCENE_BLESS=1 writes it)", golden.display()));
        assert!(dump == expected, "{} differs from {}:\n{dump}", xml.display(), golden.display());
    }
}

#[test]
fn the_editor_files_load_with_their_values() {
    let corpus = root().join("tests/fixtures/corpus");
    let scene = load_file(&corpus.join("renderer-scene-v1.xml"));
    let counts =
        |s: &Scene| (s.shapes().len(), s.fixtures().len(), s.bodies().len(), s.joints().len());
    assert_eq!(counts(&scene), (38, 38, 17, 12));
    let kinematic = scene.find_body("Kinematic test").expect("the kinematic body is named");
    let body = &scene.bodies()[kinematic as usize];
    assert_eq!((body.kind(), body.angular_velocity), (Some(BodyKind::Kinematic), -0.5));
    assert_eq!(scene.body_fixtures(body), &[5, 6, 7, 8, 9, 10, 11, 12]);
    assert_eq!(scene.gravity(), Some(Vec2::new(8.369571e-36, 1.001022e-38)));
    assert!(scene.diagnostics().is_empty());

    let legacy = load_file(&corpus.join("legacy-unversioned.xml"));
    assert_eq!((legacy.version(), counts(&legacy)), (0, (38, 38, 17, 12)));
    assert_eq!(legacy.gravity(), None);
    let codes: Vec<_> = legacy.diagnostics().iter().map(|d| d.code()).collect();
    assert_eq!(codes, [Some(Code::LegacyUnversioned)]);
    // Legacy joints name their bodies with JointA/JointB: the same bodies as Version 1.
    let bodies = |s: &Scene| s.joints().iter().map(|j| (j.body_a, j.body_b)).collect::<Vec<_>>();
    assert_eq!(bodies(&legacy), bodies(&scene));

    for name in ["revolute-all-fields-v1.xml", "revolute-defaults-omitted-v1.xml"] {
        let scene = load_file(&corpus.join(name));
        let j = &scene.joints()[0];
        assert_eq!(j.kind(), Some(JointKind::Revolute), "{name}");
        assert_eq!((j.body_a, j.body_b, j.collide_connected, j.enable_limit), (1, 0, true, true));
        assert_eq!((j.lower_limit, j.upper_limit), (-0.7853982, 1.570796));
        assert_eq!((j.motor_speed, j.max_motor_torque, j.enable_motor), (3.141593, 10000.0, false));
        assert_eq!(
            (j.local_anchor_a, j.local_anchor_b),
            (Vec2::new(0.0, 12.0), Vec2::new(0.0, -8.0))
        );
        let ground = &scene.shapes()[1];
        assert_eq!(scene.vertices(ground), &[Vec2::new(-40.0, 0.0), Vec2::new(40.0, 0.0)]);
        let user_data = scene.user_data_at(scene.bodies()[2].user_data).unwrap();
        assert_eq!(scene.text(user_data.type_name), Some("System.String"));
        assert_eq!(scene.text(user_data.value), Some("Ground"));
        assert_eq!(scene.bodies()[0].linear_velocity, Vec2::new(-800.0, 0.0));
    }
}

#[test]
fn every_value_spelling_reads_exactly() {
    let scene = load_file(&root().join("tests/fixtures/scenes/value-spellings.xml"));
    let shapes = scene.shapes();
    assert_eq!(
        (shapes[0].kind(), shapes[0].radius, shapes[0].position),
        (Some(ShapeKind::Circle), 0.5, Vec2::ZERO)
    );
    assert_eq!(
        scene.vertices(&shapes[1]),
        &[Vec2::new(-1.0, -1.0), Vec2::new(1.0, -1.0), Vec2::new(1.0, 1.0), Vec2::new(-1.0, 1.0)]
    );
    assert!(!shapes[1].centroid_given);
    assert_eq!(shapes[2].radius.to_bits(), 8.369571e-36f32.to_bits());
    assert_eq!(shapes[2].position.y.to_bits(), (-0.0f32).to_bits());
    let f = scene.fixtures();
    assert_eq!((f[0].density, f[0].is_sensor), (10.0, true));
    assert_eq!(
        (f[0].filter.category_bits, f[0].filter.mask_bits, f[0].filter.group_index),
        (16, 255, -32768)
    );
    assert_eq!((f[1].shape, f[1].friction, f[1].is_sensor), (1, 0.25, true));
    assert_eq!((f[2].restitution, f[2].is_sensor), (0.5, false));
    let b = &scene.bodies()[0];
    assert_eq!(scene.text(b.name), Some("A <quoted> \"name\" é€"));
    assert_eq!((b.kind(), b.awake, b.angle), (Some(BodyKind::Dynamic), false, f32::MAX));
    assert_eq!(b.angular_velocity.to_bits(), 1);
    assert_eq!(scene.body_fixtures(b), &[0, 1, 2]);
    assert_eq!(scene.text(scene.bodies()[1].name), Some(""));
    assert_eq!(scene.bodies()[1].fixtures.count, 0);
}

#[test]
fn joint_defaults_follow_the_spec_per_kind() {
    let scene = load_file(&root().join("tests/fixtures/scenes/defaults-per-joint-kind.xml"));
    let j = scene.joints();
    let v = Vec2::new;
    assert_eq!(
        (j[1].local_axis_a, j[4].local_axis_a, j[8].local_axis_a),
        (v(1.0, 0.0), v(1.0, 0.0), v(1.0, 0.0))
    );
    assert_eq!(j[2].length, 1.0);
    assert_eq!((j[3].ground_anchor_a, j[3].ground_anchor_b), (v(-1.0, 1.0), v(1.0, 1.0)));
    assert_eq!(
        (j[3].local_anchor_a, j[3].local_anchor_b, j[3].ratio),
        (v(-1.0, 0.0), v(1.0, 0.0), 1.0)
    );
    assert!(
        !j[3].collide_connected,
        "the editor reads an absent CollideConnected as false, even for pulleys"
    );
    assert_eq!((j[7].ratio, j[7].joint_a, j[7].joint_b), (1.0, 0, 1));
    assert_eq!((j[8].frequency_hz, j[8].damping_ratio), (2.0, 0.7));
    assert_eq!((j[9].local_anchor_a, j[9].local_anchor_b), (v(-1.0, 0.0), v(1.0, 0.0)));
    assert_eq!((j[10].max_force, j[10].max_torque, j[10].correction_factor), (1.0, 1.0, 0.3));
    assert!(j.iter().all(|j| !j.collide_connected && !j.enable_limit && !j.enable_motor));
}

/// The four containers of `xml` as separate strings, in file order, and the text around them.
fn split_containers(xml: &str) -> (String, Vec<String>, String) {
    let mut parts = Vec::new();
    let start = xml.find("<Shapes>").unwrap();
    let mut rest = &xml[start..];
    for name in ["Shapes", "Fixtures", "Bodies", "Joints"] {
        let end = rest.find(&format!("</{name}>")).unwrap() + name.len() + 3;
        parts.push(rest[..end].to_string());
        rest = &rest[end..];
    }
    (xml[..start].to_string(), parts, rest.to_string())
}

fn permutations(n: usize) -> Vec<Vec<usize>> {
    if n == 0 {
        return vec![vec![]];
    }
    permutations(n - 1)
        .into_iter()
        .flat_map(|p| {
            (0..n).map(move |i| {
                let mut q = p.clone();
                q.insert(i, n - 1);
                q
            })
        })
        .collect()
}

#[test]
fn all_24_container_orders_give_identical_scenes() {
    let xml =
        std::fs::read_to_string(root().join("tests/fixtures/scenes/every-v1-field.xml")).unwrap();
    let expected = load(xml.as_bytes(), &LoadOptions::default()).unwrap().to_json();
    let (head, parts, tail) = split_containers(&xml);
    let orders = permutations(4);
    assert_eq!(orders.len(), 24);
    for order in orders {
        let body: String =
            order.iter().map(|&i| parts[i].as_str()).collect::<Vec<_>>().join("\n  ");
        let reordered = format!("{head}{body}{tail}");
        let scene = load(reordered.as_bytes(), &LoadOptions::default()).unwrap();
        assert_eq!(violated_joints(&scene), 4, "{order:?}");
        // The warnings are placed where each order puts the joints.
        let values = |json: &str| json[..json.find("\"diagnostics\"").unwrap()].to_string();
        assert_eq!(values(&scene.to_json()), values(&expected), "order {order:?}");
    }
}

/// Every character inside markup (names, attribute names and values) changed by `case`,
/// except inside UserData, which is kept verbatim.
fn recase_markup(xml: &str, case: fn(&char) -> char) -> String {
    let (mut out, mut rest) = (String::new(), xml);
    while let Some(start) = rest.find("<UserData>") {
        let end = rest.find("</UserData>").unwrap();
        out += &recase(&rest[..start], case);
        out += &rest[start..end + "</UserData>".len()];
        rest = &rest[end + "</UserData>".len()..];
    }
    out + &recase(rest, case)
}

fn recase(xml: &str, case: fn(&char) -> char) -> String {
    let mut inside = false;
    xml.chars()
        .map(|c| {
            match c {
                '<' => inside = true,
                '>' => inside = false,
                _ => {}
            }
            if inside { case(&c) } else { c }
        })
        .collect()
}

#[test]
fn names_and_enumerations_are_case_insensitive() {
    let xml =
        std::fs::read_to_string(root().join("tests/fixtures/scenes/every-v1-field.xml")).unwrap();
    let expected = load(xml.as_bytes(), &LoadOptions::default()).unwrap().to_json();
    let upper = recase_markup(&xml, char::to_ascii_uppercase);
    let lower = recase_markup(&xml, char::to_ascii_lowercase);
    assert!(upper.contains("<SHAPE TYPE=\"CIRCLE\">") && lower.contains("<shape type=\"circle\">"));
    for recased in [upper, lower] {
        let scene = load(recased.as_bytes(), &LoadOptions::default()).unwrap();
        assert_eq!(scene.to_json(), expected);
    }
}

/// Circles and bodies without fixtures have nothing in their pools: `{0, 0}`, wherever in
/// the pool the scene was when they were read.
#[test]
fn an_empty_range_is_zero_zero() {
    let xml = r#"<World Version="2"><Shapes>
        <Shape Type="Polygon"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>0 1</Vertex></Vertices></Shape>
        <Shape Type="Circle"><Radius>1</Radius><Position>0 0</Position></Shape>
      </Shapes><Fixtures><Fixture><Shape>1</Shape></Fixture></Fixtures>
      <Bodies><Body Type="Static"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Static"><Fixtures /></Body></Bodies><Joints /></World>"#;
    let scene = load(xml.as_bytes(), &LoadOptions::default()).unwrap();
    let empty = Range { first: 0, count: 0 };
    assert_eq!(scene.shapes()[0].vertices, Range { first: 0, count: 3 });
    assert_eq!(scene.shapes()[1].vertices, empty);
    assert_eq!(scene.bodies()[0].fixtures, Range { first: 0, count: 1 });
    assert_eq!(scene.bodies()[1].fixtures, empty);
}

/// How many joints the scene warns start violated; 0 when it has any other warning.
fn violated_joints(scene: &Scene) -> usize {
    let codes: Vec<_> = scene.diagnostics().iter().map(|d| d.code()).collect();
    match codes.iter().all(|&c| c == Some(Code::JointStartsViolated)) {
        true => codes.len(),
        false => 0,
    }
}

#[test]
fn every_v1_field_is_read() {
    let scene = load_file(&root().join("tests/fixtures/scenes/every-v1-field.xml"));
    // The axle, the slider, the pulley and the suspension start apart.
    assert_eq!(violated_joints(&scene), 4);
    let cart = &scene.bodies()[scene.find_body("cart").unwrap() as usize];
    let m = cart.mass_data;
    assert_eq!((m.mass, m.center, m.inertia), (12.0, Vec2::new(0.1, -0.2), 4.5));
    assert!(m.mass_given && m.center_given && m.inertia_given);
    let wheel = &scene.bodies()[2].mass_data;
    assert_eq!(
        (wheel.mass_given, wheel.center_given, wheel.inertia_given, wheel.inertia),
        (false, false, true, 0.25)
    );
    assert_eq!(
        (cart.allow_sleep, cart.awake, cart.bullet, cart.inertia_scale),
        (false, false, true, 1.5)
    );
    let rubber = scene.user_data_at(scene.fixtures()[0].user_data).unwrap();
    assert_eq!(scene.text(rubber.value), Some("tyre & rim"));
    assert!(scene.text(rubber.raw).unwrap().contains("<string>tyre &amp; rim</string>"));
    let plain = scene.user_data_at(scene.joints()[0].user_data).unwrap();
    assert_eq!((scene.text(plain.raw), plain.type_name.is_null()), (Some("plain text"), true));
    let gear = &scene.joints()[scene.find_joint("gear").unwrap() as usize];
    assert_eq!((gear.joint_a, gear.joint_b, gear.ratio), (0, 1, -2.0));
    assert_eq!(scene.find_shape("box"), Some(1));
    assert_eq!(scene.find_fixture("crate"), Some(1));
    assert_eq!(scene.find_body("nobody"), None);
}

#[test]
fn farseer_version_2_spellings_are_read() {
    let scene = load_file(&root().join("tests/fixtures/scenes/farseer-v2.xml"));
    let j = scene.joints();
    let kinds: Vec<_> = j.iter().map(|j| j.kind().unwrap()).collect();
    use JointKind::*;
    assert_eq!(
        kinds,
        [
            Revolute,
            Prismatic,
            Distance,
            Pulley,
            Wheel,
            Wheel,
            Weld,
            Friction,
            Gear,
            Rope,
            Unsupported,
            Unsupported,
            Motor
        ]
    );
    assert_eq!(j[1].local_axis_a, Vec2::new(0.0, 1.0), "LocalXAxis1");
    assert_eq!(
        (j[3].ground_anchor_a, j[3].ground_anchor_b),
        (Vec2::new(-1.0, 10.0), Vec2::new(1.0, 10.0)),
        "WorldAnchorA/B"
    );
    assert_eq!(
        (j[4].frequency_hz, j[4].max_motor_torque, j[4].local_axis_a),
        (5.0, 20.0, Vec2::new(0.0, 1.0)),
        "Line read as Wheel"
    );
    assert_eq!(j[5].local_axis_a, Vec2::new(0.0, 1.0), "Axis");
    assert_eq!((j[6].frequency_hz, j[6].damping_ratio), (2.0, 0.3), "soft weld");
    assert_eq!((j[10].body_a, j[10].body_b), (0, 2), "an unsupported joint keeps its bodies");
    assert_eq!(
        (j[12].linear_offset, j[12].angular_offset, j[12].correction_factor),
        (Vec2::new(-1.0, 2.0), 0.5, 0.4)
    );
    let s = scene.shapes();
    assert_eq!(
        (s[0].kind(), s[0].has_prev_vertex, s[0].has_next_vertex),
        (Some(ShapeKind::Edge), false, false)
    );
    assert_eq!(
        (s[1].has_prev_vertex, s[1].prev_vertex),
        (true, Vec2::new(-20.0, 0.0)),
        "a ghost counts only with its own flag"
    );
    assert!(!s[1].has_next_vertex);
    assert_eq!(
        (s[2].is_loop, s[2].has_prev_vertex, s[2].next_vertex),
        (false, true, Vec2::new(-15.0, 4.0))
    );
    assert_eq!(
        (s[3].kind(), s[3].is_loop, scene.vertices(&s[3]).len()),
        (Some(ShapeKind::Chain), true, 4)
    );
    assert_eq!(scene.bodies()[1].gravity_scale, 0.5);
    let codes: Vec<_> = scene.diagnostics().iter().map(|d| d.code().unwrap()).collect();
    assert_eq!(
        codes,
        [
            Code::JointStartsViolated, // the prismatic slider starts 1 m off its axis
            Code::LineJointIsWheel,
            Code::FarseerOnlyJoint,
            Code::FarseerOnlyJoint
        ]
    );
}

#[test]
fn farseer_version_3_pairs_become_fixtures() {
    let scene = load_file(&root().join("tests/fixtures/scenes/farseer-v3.xml"));
    let f = scene.fixtures();
    let made: Vec<_> = f.iter().map(|f| (f.shape, f.density, f.friction)).collect();
    assert_eq!(made, [(0, 0.0, 0.2), (2, 1.0, 0.8), (1, 2.5, 0.8), (1, 2.5, 0.2)]);
    let lists: Vec<_> = scene.bodies().iter().map(|b| scene.body_fixtures(b).to_vec()).collect();
    assert_eq!(lists, [vec![0], vec![1, 2], vec![3]]);
    assert_eq!(f[1].filter.group_index, -2);
}

/// Farseer's fixture Ids (17, 23, 24) are a counter; Pairs name positions (0, 1, 2), and
/// each template is shared by several bodies. Aether's `Tag` is the UserData.
#[test]
fn farseer_version_3_pairs_bind_by_position_not_id() {
    let scene = load_file(&root().join("tests/fixtures/scenes/farseer-v3-counter-ids.xml"));
    let f = scene.fixtures();
    let made: Vec<_> = f.iter().map(|f| (f.shape, f.density, f.friction, f.is_sensor)).collect();
    assert_eq!(
        made,
        [
            (0, 0.0, 0.9, false),
            (2, 3.0, 0.3, false),
            (1, 2.0, 0.0, true),
            (1, 2.0, 0.3, false),
            (2, 3.0, 0.0, true)
        ]
    );
    let groups: Vec<_> = f.iter().map(|f| f.filter.group_index).collect();
    assert_eq!(groups, [0, -1, 0, -1, 0]);
    let lists: Vec<_> = scene.bodies().iter().map(|b| scene.body_fixtures(b).to_vec()).collect();
    assert_eq!(lists, [vec![0], vec![1, 2], vec![3, 4]]);
    let value = |index: u32| {
        let user_data = scene.user_data_at(index).unwrap();
        (scene.text(user_data.type_name).unwrap(), scene.text(user_data.value).unwrap())
    };
    assert_eq!(value(f[0].user_data), ("System.String", "ground"));
    assert_eq!(value(scene.bodies()[0].user_data), ("System.String", "floor"));
    assert_eq!(value(scene.joints()[0].user_data), ("System.Int32", "7"));
    let chain = &scene.shapes()[0];
    assert!(!chain.has_prev_vertex && !chain.has_next_vertex, "ghosts without flags are absent");
    let codes: Vec<_> = scene.diagnostics().iter().map(|d| d.code()).collect();
    assert_eq!(codes, [], "Ids, Tags and 32-bit filter bits are silent");

    let v2 = load_file(&root().join("tests/fixtures/scenes/farseer-v2-2013-ids.xml"));
    assert!(v2.diagnostics().is_empty(), "Ids on fixtures and bodies are silent");
    assert_eq!(v2.fixtures()[0].friction, 0.4);
}
