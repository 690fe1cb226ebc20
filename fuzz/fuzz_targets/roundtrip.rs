//! Whatever loads writes, in both modes and with everything the file held beyond the records
//! (comments, unknown content, Farseer-only joints), to a file that reads back to the same
//! scene and is written again byte for byte.
#![no_main]

use box2scene::{Code, Dialect, LoadOptions, Scene, WriteOptions, load, write};
use libfuzzer_sys::fuzz_target;

/// Everything but the version and the diagnostics, bit for bit.
fn content(scene: &Scene) -> String {
    let json = scene.to_json();
    let body = json.split_once("\n  \"gravity\"").unwrap().1;
    body.split_once("\n  \"diagnostics\"").unwrap().0.to_string()
}

fuzz_target!(|data: &[u8]| {
    let Ok(scene) = load(data, &LoadOptions::default()) else { return };
    for all_fields in [false, true] {
        let mut options = WriteOptions { all_fields, ..WriteOptions::default() };
        let mut result = write(&scene, &options);
        // An engine's file that its own dialect cannot hold (a comment, say) is refused
        // unless another dialect is asked for; box2scene's holds every scene.
        if matches!(&result, Err(e) if e.code == Code::DialectCannotHold) {
            options.dialect = Dialect::Box2scene as u32;
            result = write(&scene, &options);
        }
        let written = match result {
            Ok(written) => written,
            // Unknown attributes of one name from two places of the file (a Version 3 body
            // gets its Pairs'): refused, as a file carrying both could not be read.
            Err(e) if e.code == Code::DuplicateAttribute => return,
            Err(e) => panic!("a loaded scene is not written: {e}"),
        };
        let again = load(written.as_bytes(), &LoadOptions::default())
            .unwrap_or_else(|e| panic!("the written file does not load: {e}\n{written}"));
        assert_eq!(content(&again), content(&scene), "{written}");
        assert_eq!(write(&again, &options).expect("a reloaded scene is written"), written);
    }
});
