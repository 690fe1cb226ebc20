//! Regenerates `include/box2scene.h` from the crate with cbindgen, writing it only when its
//! text changed, so that a rebuild of an unchanged tree leaves the committed header as is.
//! The version macros come from Cargo.toml through Cargo's environment, and so does the
//! shared library's SONAME.

use std::env;
use std::path::Path;

fn main() {
    let root = env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let root = Path::new(&root);
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=cbindgen.toml");

    let mut config = cbindgen::Config::from_file(root.join("cbindgen.toml"))
        .expect("cbindgen.toml is readable and valid");
    let version = |part: &str| env::var(format!("CARGO_PKG_VERSION_{part}")).expect("set by cargo");
    set_soname(&version("MAJOR"), &version("MINOR"));
    config.after_includes = Some(format!(
        "\n#define B2S_VERSION_MAJOR {}\n#define B2S_VERSION_MINOR {}\n#define B2S_VERSION_PATCH {}\n\
         #define B2S_VERSION_STRING \"{}\"",
        version("MAJOR"),
        version("MINOR"),
        version("PATCH"),
        env::var("CARGO_PKG_VERSION").expect("set by cargo"),
    ));
    cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen can read the crate")
        .write_to_file(root.join("include/box2scene.h"));
}

/// The ABI changes with every minor version while the version is 0.x, then only with the
/// major one: libbox2scene.so.0.N, then libbox2scene.so.N. CMakeLists.txt names the installed
/// files after the same rule. Only ELF targets have a SONAME.
fn set_soname(major: &str, minor: &str) {
    let family = env::var("CARGO_CFG_TARGET_FAMILY").unwrap_or_default();
    let vendor = env::var("CARGO_CFG_TARGET_VENDOR").unwrap_or_default();
    if !family.split(',').any(|f| f == "unix") || vendor == "apple" {
        return;
    }
    let abi = if major == "0" { format!("0.{minor}") } else { major.to_owned() };
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libbox2scene.so.{abi}");
}
