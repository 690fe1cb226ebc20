//! Any bytes into the Rust loader: it returns a scene or an error, never panics, hangs or
//! runs out of memory; a scene's cross references all hold. A check of the same bytes
//! gives the same scene, or errors among which is the load's.
#![no_main]

use box2scene::{LoadOptions, NONE, Scene, check, load};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    for strict in [false, true] {
        let options = LoadOptions { strict, ..LoadOptions::default() };
        let checked = check(data, &options);
        match load(data, &options) {
            Ok(scene) => {
                check_references(&scene);
                assert!(
                    !strict || scene.diagnostics().is_empty(),
                    "strict mode turns warnings into errors"
                );
                let same = checked.scene.expect("a file that loads checks without errors");
                assert_eq!(same.to_json(), scene.to_json());
            }
            Err(error) => {
                assert!(checked.scene.is_none() && checked.errors.len() <= 101);
                assert!(checked.errors.contains(&error), "{error:?} not in {:?}", checked.errors);
            }
        }
    }
});

fn check_references(scene: &Scene) {
    let (shapes, fixtures, bodies, joints) =
        (scene.shapes().len(), scene.fixtures().len(), scene.bodies().len(), scene.joints().len());
    let user_data = |index: u32| assert!(index == NONE || scene.user_data_at(index).is_some());
    for s in scene.shapes() {
        assert!(s.vertices.indices().end <= scene.vertex_pool().len());
        assert!(s.kind().is_some());
    }
    for f in scene.fixtures() {
        assert!((f.shape as usize) < shapes);
        user_data(f.user_data);
    }
    for b in scene.bodies() {
        assert!(scene.body_fixtures(b).iter().all(|&f| (f as usize) < fixtures));
        user_data(b.user_data);
    }
    for j in scene.joints() {
        assert!(
            (j.body_a as usize) < bodies && (j.body_b as usize) < bodies && j.body_a != j.body_b
        );
        for target in [j.joint_a, j.joint_b] {
            assert!(target == NONE || (target as usize) < joints);
        }
        user_data(j.user_data);
    }
    for d in scene.diagnostics() {
        assert!(d.code().is_some() && d.line >= 1 && scene.text(d.message).is_some());
    }
}
