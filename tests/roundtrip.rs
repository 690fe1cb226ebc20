//! The writer's contract: `load(write(s))` is `s` in every field, bit for bit, in both
//! modes, and `write(load(write(s)))` is `write(s)` byte for byte; for every test scene,
//! every editor file, and 10 000 generated scenes.

mod common;

use std::path::PathBuf;

use common::{Random, content, generate};

use box2scene::{Code, JointKind, LoadOptions, Scene, WriteOptions, load, load_path, write};

const MODES: [WriteOptions; 2] =
    [WriteOptions { all_fields: false, threads: 0 }, WriteOptions { all_fields: true, threads: 0 }];

fn load_text(xml: &str) -> Scene {
    load(xml.as_bytes(), &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}\nin:\n{xml}"))
}

/// Checks both halves of the contract for `scene`; returns the first written text.
fn assert_round_trip(scene: &Scene, what: &str) -> String {
    let mut first = String::new();
    for options in MODES {
        let written = write(scene, &options).unwrap();
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
    let mut files: Vec<PathBuf> = ["tests/scenes", "tests/data/corpus", "examples/scenes"]
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
    let legacy =
        load_path(root.join("tests/data/corpus/legacy-unversioned.xml"), &LoadOptions::default())
            .unwrap();
    let written = write(&legacy, &WriteOptions::default()).unwrap();
    assert!(
        written.contains("<World Version=\"1\">") && !written.contains("<JointA>"),
        "{written}"
    );
    assert!(load_text(&written).diagnostics().is_empty());

    let v3 = load_path(root.join("tests/scenes/farseer-v3.xml"), &LoadOptions::default()).unwrap();
    let written = write(&v3, &WriteOptions::default()).unwrap();
    assert!(
        written.contains("<World Version=\"2\">") && !written.contains("Bindings"),
        "{written}"
    );

    let v2 = load_path(root.join("tests/scenes/farseer-v2.xml"), &LoadOptions::default()).unwrap();
    let source = std::fs::read_to_string(root.join("tests/scenes/farseer-v2.xml")).unwrap();
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
        for farseer in ["Breakpoint", "LocalXAxis", "WorldAnchor", "Constant", "2147483647"] {
            assert!(!rest.contains(farseer), "{farseer} in:\n{written}");
        }
        let again = load_text(&written);
        let codes: Vec<_> = again.diagnostics().iter().map(|d| d.code()).collect();
        assert_eq!(codes, [Some(Code::FarseerOnlyJoint); 2]);
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
