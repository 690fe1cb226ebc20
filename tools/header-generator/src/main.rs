//! Generates `include/box2scene.h` from the crate in the current directory (the repository's
//! root, where `tools/gen-header` runs it) with cbindgen and `cbindgen.toml`, adding the `B2S_VERSION_*` macros from the version Cargo reads in
//! `Cargo.toml`. With `--check` it writes nothing and fails when the committed header differs
//! from what it would write.

use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

fn main() -> ExitCode {
    let check = match env::args().nth(1).as_deref() {
        None => false,
        Some("--check") => true,
        Some(other) => {
            eprintln!("gen-header: unknown argument {other:?}; usage: gen-header [--check]");
            return ExitCode::from(2);
        }
    };
    let root = Path::new(".");
    if !root.join("cbindgen.toml").is_file() {
        eprintln!("gen-header: run it from the root of box2scene's repository");
        return ExitCode::from(2);
    }
    let header = root.join("include/box2scene.h");
    let generated = generate(root);
    let committed = fs::read(&header).unwrap_or_default();
    if committed == generated {
        return ExitCode::SUCCESS;
    }
    if check {
        eprintln!(
            "{} differs from what cbindgen generates from the sources: run tools/gen-header \
             and commit the header",
            header.display()
        );
        return ExitCode::FAILURE;
    }
    fs::write(&header, generated).expect("include/box2scene.h is writable");
    println!("wrote {}", header.display());
    ExitCode::SUCCESS
}

/// The header's text, exactly as the committed file must hold it.
fn generate(root: &Path) -> Vec<u8> {
    let mut config = cbindgen::Config::from_file(root.join("cbindgen.toml"))
        .expect("cbindgen.toml is readable and valid");
    let version = package_version(root);
    let mut parts = version.split(['.', '-', '+']);
    let mut part = || parts.next().expect("a semantic version has three numbers");
    config.after_includes = Some(format!(
        "\n#define B2S_VERSION_MAJOR {}\n#define B2S_VERSION_MINOR {}\n#define B2S_VERSION_PATCH {}\n\
         #define B2S_VERSION_STRING \"{version}\"",
        part(),
        part(),
        part(),
    ));
    let mut text = Vec::new();
    cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen can read the crate")
        .write(&mut text);
    text
}

/// The version of the box2scene package as Cargo resolves it (`cargo metadata`), so that
/// the header says what the library built from the same manifest says.
fn package_version(root: &Path) -> String {
    let cargo = env::var_os("CARGO").map_or_else(|| PathBuf::from("cargo"), PathBuf::from);
    let output = Command::new(cargo)
        .args(["metadata", "--no-deps", "--format-version", "1", "--manifest-path"])
        .arg(root.join("Cargo.toml"))
        .output()
        .expect("cargo runs");
    assert!(
        output.status.success(),
        "cargo metadata failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let metadata: serde_json::Value =
        serde_json::from_slice(&output.stdout).expect("cargo metadata prints JSON");
    let packages = metadata["packages"].as_array().expect("cargo metadata lists packages");
    let package = packages
        .iter()
        .find(|package| package["name"] == "box2scene")
        .expect("the manifest is box2scene's");
    package["version"].as_str().expect("a package has a version").to_owned()
}
