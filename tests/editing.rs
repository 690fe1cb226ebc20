//! Editing a loaded scene: a builder started from it holds everything it holds, the text
//! its file held beyond the records too, and records replaced, added or taken out change
//! only themselves, so the scene written keeps every comment and unknown element `fmt`
//! keeps for the records left unchanged.

use box2scene::{
    Body, BodyKind, Builder, Code, Fixture, JointKind, LoadOptions, Scene, Vec2, WriteOptions,
    load, load_path,
};

fn showcase() -> Scene {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    load_path(root.join("examples/scenes/showcase.xml"), &LoadOptions::default()).unwrap()
}

fn xml(scene: &Scene) -> String {
    scene.to_xml(&WriteOptions::default()).unwrap()
}

/// The comments of a written scene, in order.
fn comments(text: &str) -> Vec<&str> {
    text.split("<!--").skip(1).map(|rest| &rest[..rest.find("-->").unwrap()]).collect()
}

fn body_named(scene: &Scene, name: &str) -> u32 {
    scene.find_body(name).unwrap()
}

#[test]
fn a_scene_started_from_and_finished_unchanged_writes_as_fmt() {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    for file in [
        "examples/scenes/showcase.xml",
        "tests/fixtures/scenes/every-v1-field.xml",
        "tests/fixtures/corpus/renderer-scene-v1.xml",
    ] {
        let scene = load_path(root.join(file), &LoadOptions::default()).unwrap();
        let unchanged = Builder::from_scene(&scene).finish();
        assert_eq!(xml(&unchanged), xml(&scene), "{file}");
        // The same records; only the diagnostics, which describe the file, are not kept.
        let records = |s: &Scene| s.to_json().split("\"diagnostics\"").next().unwrap().to_owned();
        assert_eq!(records(&unchanged), records(&scene), "{file}");
        assert!(unchanged.diagnostics().is_empty());
    }
    let with_unknown = br#"<World Version="1" Mood="calm">
  <!-- one body -->
  <Shapes><Shape Type="Circle"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>
  <Fixtures><Fixture><Shape>0</Shape></Fixture></Fixtures>
  <Bodies>
    <!-- the ball -->
    <Body Type="Dynamic" Colour="red"><Position>1 2</Position><Fixtures><ID>0</ID></Fixtures><Sparkle/></Body>
  </Bodies>
  <Joints/>
</World>
"#;
    let scene = load(with_unknown, &LoadOptions::default()).unwrap();
    assert_eq!(xml(&Builder::from_scene(&scene).finish()), xml(&scene));
    assert!(xml(&scene).contains("Colour=\"red\"") && xml(&scene).contains("<Sparkle/>"));
}

#[test]
fn a_replaced_body_changes_only_itself() {
    let scene = showcase();
    let index = body_named(&scene, "GearDriver");
    let old = scene.bodies()[index as usize];
    let mut b = Builder::from_scene(&scene);
    let moved = Body { position: Vec2::new(-3.5, 7.25), ..old };
    b.replace_body(index, &moved, Some("MovedDriver"), scene.body_fixtures(&old)).unwrap();
    let edited = b.finish();
    let (before, after) = (xml(&scene), xml(&edited));
    assert_eq!(comments(&after), comments(&before));
    assert_eq!(comments(&after).len(), 20);
    let reloaded = load(after.as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(reloaded.bodies()[index as usize].position, Vec2::new(-3.5, 7.25));
    assert_eq!(reloaded.find_body("MovedDriver"), Some(index));
    assert_eq!(reloaded.find_body("GearDriver"), None);
    for (i, (a, b)) in scene.bodies().iter().zip(reloaded.bodies()).enumerate() {
        if i != index as usize {
            assert_eq!(
                (a.position, a.angle, scene.text(a.name)),
                (b.position, b.angle, reloaded.text(b.name))
            );
        }
    }
    // Only the body's own lines differ.
    let changed = before.lines().zip(after.lines()).filter(|(a, b)| a != b).count();
    assert!(
        before.lines().count() == after.lines().count() && changed <= 2,
        "{changed} lines changed"
    );
}

#[test]
fn records_added_to_a_loaded_scene_keep_its_comments() {
    let scene = showcase();
    let mut b = Builder::from_scene(&scene);
    let fixture =
        b.add_fixture(&Fixture { density: 2.0, ..scene.fixtures()[0] }, Some("Extra")).unwrap();
    let body = b.add_body(&Body::new(BodyKind::Dynamic), Some("Newcomer"), &[fixture]).unwrap();
    let edited = b.finish();
    assert_eq!(comments(&xml(&edited)), comments(&xml(&scene)));
    let reloaded = load(xml(&edited).as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(reloaded.find_body("Newcomer"), Some(body));
    assert_eq!(reloaded.bodies().len(), scene.bodies().len() + 1);
}

#[test]
fn a_record_taken_out_moves_the_later_ones_and_their_references_down() {
    let scene = showcase();
    let weld =
        scene.joints().iter().position(|j| j.kind() == Some(JointKind::Weld)).unwrap() as u32;
    let gear = scene.find_joint("GearMesh").unwrap();
    assert!(weld < gear);
    let mut b = Builder::from_scene(&scene);
    b.remove_joint(weld).unwrap();
    let edited = b.finish();
    let reloaded = load(xml(&edited).as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(reloaded.joints().len(), scene.joints().len() - 1);
    let mesh = reloaded.joints()[reloaded.find_joint("GearMesh").unwrap() as usize];
    assert_eq!(mesh.joint_a, reloaded.find_joint("GearDriverAxle").unwrap());
    assert_eq!(mesh.joint_b, reloaded.find_joint("GearFollowerAxle").unwrap());
    let (before, after) = (xml(&scene), xml(&edited));
    let kept = comments(&after);
    let gone: Vec<&str> = comments(&before).into_iter().filter(|c| !kept.contains(c)).collect();
    assert_eq!(gone, [" Weld "]);
}

#[test]
fn what_others_refer_to_is_not_taken_out() {
    let scene = showcase();
    let mut b = Builder::from_scene(&scene);
    let axle = scene.find_joint("GearDriverAxle").unwrap();
    let gear = scene.find_joint("GearMesh").unwrap();
    let refused = b.remove_joint(axle).unwrap_err();
    assert_eq!(refused.code, Code::InvalidArgument);
    assert_eq!(
        refused.message,
        format!("joint {axle}: gear joint {gear} refers to it; replace or take that out first")
    );
    let weld = box2scene::Joint::new(JointKind::Weld);
    let weld = box2scene::Joint { body_a: 0, body_b: 1, ..weld };
    assert_eq!(b.replace_joint(axle, &weld, None).unwrap_err().code, Code::InvalidArgument);
    assert!(b.remove_shape(0).unwrap_err().message.starts_with("shape 0: fixture "));
    assert!(b.remove_fixture(0).unwrap_err().message.starts_with("fixture 0: body "));
    assert!(
        b.remove_body(body_named(&scene, "GearDriver")).unwrap_err().message.contains(": joint ")
    );
    let missing = b.remove_body(1000).unwrap_err();
    assert_eq!(
        (missing.code, missing.message.as_str()),
        (Code::IdOutOfRange, "body 1000: there is no body 1000: the scene has 34")
    );
    assert_eq!(xml(&b.finish()), xml(&scene));
}
