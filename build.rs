//! Gives the shared library its SONAME, from the version in Cargo.toml. (The C header is
//! not made here: it is committed, and `tools/gen-header` regenerates it.)

use std::env;

fn main() {
    // Only the version and the target matter, not the sources.
    println!("cargo:rerun-if-changed=build.rs");
    let version = |part: &str| env::var(format!("CARGO_PKG_VERSION_{part}")).expect("set by cargo");
    set_soname(&version("MAJOR"), &version("MINOR"));
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
