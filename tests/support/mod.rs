//! Helpers shared by the tests of hostile input and of what a load holds.

use box2scene::{Code, Error, LoadOptions, Scene, load};

/// Loads `bytes` from memory with the default options.
pub fn load_bytes(bytes: &[u8]) -> Result<Scene, Error> {
    load(bytes, &LoadOptions::default())
}

/// `bytes` fail with `code` at `line` and `column`, loaded from memory.
pub fn expect(bytes: &[u8], code: Code, line: u32, column: u32) -> Error {
    let error = load_bytes(bytes).expect_err("hostile input must not load");
    assert_eq!(
        (error.code, error.position.line, error.position.column),
        (code, line, column),
        "{}",
        error.message
    );
    error
}

/// Loads `bytes` through a file of their own, with the default options.
pub fn load_from_a_file(bytes: &[u8], name: &str) -> Result<Scene, Error> {
    let file = std::env::temp_dir().join(format!("box2scene-{name}-{}.xml", std::process::id()));
    std::fs::write(&file, bytes).unwrap();
    let scene = box2scene::load_path(&file, &LoadOptions::default());
    std::fs::remove_file(&file).unwrap();
    scene
}

/// A new named pipe in the temporary directory.
#[cfg(unix)]
pub fn named_pipe(name: &str) -> std::path::PathBuf {
    let path = std::env::temp_dir().join(format!("box2scene-fifo-{}-{name}", std::process::id()));
    let _ = std::fs::remove_file(&path);
    let made = std::process::Command::new("mkfifo").arg(&path).status().unwrap();
    assert!(made.success(), "mkfifo {}", path.display());
    path
}
