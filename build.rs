//! Regenerates `include/box2scene.h` from the crate with cbindgen, writing it only when its
//! text changed, so that a rebuild of an unchanged tree leaves the committed header as is.
//! The version macros come from Cargo.toml through Cargo's environment.

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
