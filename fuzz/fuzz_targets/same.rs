//! One answer whatever the route: the loads of one input from memory on one thread, from
//! memory on as many as box2scene likes, and from a file give the same scene, warnings and
//! error.

use std::path::PathBuf;

use box2scene::{Error, LoadOptions, load, load_path};

/// A file of this process's own, written anew for each input.
fn file() -> PathBuf {
    std::env::temp_dir().join(format!("box2scene-fuzz-{}.xml", std::process::id()))
}

/// The scene (as JSON: every field, warnings included) or the error.
fn outcome(loaded: Result<box2scene::Scene, Error>) -> Result<String, Error> {
    loaded.map(|scene| scene.to_json())
}

/// Loads `bytes` every way with `options` and panics unless all agree.
pub fn check(bytes: &[u8], options: &LoadOptions) {
    let one = outcome(load(bytes, &LoadOptions { threads: 1, ..*options }));
    let any = outcome(load(bytes, &LoadOptions { threads: 0, ..*options }));
    let path = file();
    std::fs::write(&path, bytes).expect("the temporary directory is writable");
    let from_path = outcome(load_path(&path, options));
    let _ = std::fs::remove_file(&path);
    let first_difference = |a: &Result<String, Error>, b: &Result<String, Error>| match (a, b) {
        (Ok(a), Ok(b)) => a.lines().zip(b.lines()).find(|(x, y)| x != y).map(|d| format!("{d:?}")),
        (Err(a), Err(b)) if a == b => None,
        _ => Some(format!("{:?} against {:?}", a.as_ref().err(), b.as_ref().err())),
    };
    if let Some(d) = first_difference(&one, &any) {
        panic!("one thread and more differ: {d}");
    }
    if let Some(d) = first_difference(&one, &from_path) {
        panic!("memory and path differ: {d}");
    }
}
