#!/usr/bin/env bash
# The consumers of an installed box2scene: `run.sh CHECK`, one CTest test per CHECK (see
# CMakeLists.txt, which sets the environment below). `install` installs the build into
# PREFIX; every other check but `subdirectory` builds a host against PREFIX alone, from a
# copy of this folder in a temporary directory, runs it and checks what it prints. With
# CMAKELISTS set, the check builds that file in place of its consumer's CMakeLists.txt (the
# snippet_* tests: a CMakeLists.txt a page shows, built and run as this check's).
set -euo pipefail

: "${CMAKE:?}" "${RUSTC:?}" "${BOX2SCENE_SOURCE_DIR:?}" "${BOX2SCENE_BUILD_DIR:?}"
: "${BOX2SCENE_CARGO_TARGET_DIR:?}" "${CARGO_PROFILE_DIR:?}" "${PREFIX:?}" "${LIBDIR:?}"
: "${VERSION:?}" "${ABI_VERSION:?}"

here=$(cd "$(dirname "$0")" && pwd)
libdir=$PREFIX/$LIBDIR
soname=libbox2scene.so.$ABI_VERSION
work=$(mktemp -d "${TMPDIR:-/tmp}/box2scene-consumer.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp -R "$here" "$work/src"

fail() {
  printf 'FAIL: %s\n' "$@" >&2
  exit 1
}

# What the C consumers print for scene.xml.
c_output="box2scene $VERSION (header $VERSION)
2 shapes, 2 fixtures, 2 bodies, 0 joints, 0 diagnostics
body 0: Ground
body 1: Ball"

# Configures the project in folder $1 with the other arguments and builds it into
# $work/build, or fails with its log.
configure_and_build() {
  local name=$1
  shift
  if [ -n "${CMAKELISTS:-}" ]; then
    cp "$CMAKELISTS" "$work/src/$name/CMakeLists.txt"
    cmakelists_built=yes
  fi
  if ! "$CMAKE" -S "$work/src/$name" -B "$work/build" -G "Unix Makefiles" "$@" \
      >"$work/log" 2>&1 ||
    ! "$CMAKE" --build "$work/build" -j2 >>"$work/log" 2>&1; then
    cat "$work/log" >&2
    fail "the $name consumer did not build"
  fi
}

# Configures and builds the consumer in folder $1 against PREFIX alone, into $work/build.
build_consumer() {
  local name=$1
  shift
  configure_and_build "$name" -DCMAKE_PREFIX_PATH="$PREFIX" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "$@"
}

# A parent project that built box2scene's sources into $1 built none of its tests, and its
# scene_info runs.
expect_parent_project() {
  [ ! -e "$1/c_tests" ] || fail "box2scene's tests were built"
  expect_shared "$work/build/scene_info"
  expect_output "$c_output" "$work/build/scene_info" "$work/src/scene.xml"
}

# Runs a program and compares what it prints with $1.
expect_output() {
  local expected=$1 actual
  shift
  actual=$("$@") || fail "$* exited with status $?"
  [ "$actual" = "$expected" ] || fail "$* printed" "$actual" "instead of" "$expected"
  printf '%s\n' "$actual"
}

needed() {
  readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]$/\1/p'
}

expect_shared() {
  needed "$1" | grep -qx "$soname" || fail "$1 does not load $soname"
}

expect_static() {
  if needed "$1" | grep -q libbox2scene; then fail "$1 loads libbox2scene"; fi
}

# `rustc --print native-static-libs` for a static library of the crate as built (in cargo's
# CARGO_PROFILE_DIR, debug or release), its dependencies included: "-lgcc_s -lutil ...".
rust_native_libs() {
  local built=$BOX2SCENE_CARGO_TARGET_DIR/$CARGO_PROFILE_DIR
  echo 'extern crate box2scene;' >"$work/probe.rs"
  "$RUSTC" --edition 2021 --crate-type staticlib --crate-name probe \
    --extern box2scene="$built/libbox2scene.rlib" -L dependency="$built/deps" \
    --print native-static-libs -o "$work/libprobe.a" "$work/probe.rs" 2>&1 |
    sed -n 's/.*native-static-libs: //p'
}

check_install() {
  rm -rf "$PREFIX"
  "$CMAKE" --install "$BOX2SCENE_BUILD_DIR" --prefix "$PREFIX"
}

check_layout() {
  local file
  for file in include/box2scene.h include/box2scene/box2d.hpp include/box2scene/box2d3.h \
    include/box2scene/detail/box2d3/v31.h share/box2scene/box2d3.c \
    include/box2scene/box2d32.h include/box2scene/detail/box2d3/v32.h \
    include/box2scene/detail/box2d3/adapter.c include/box2scene/detail/box2d3/capture.c \
    share/box2scene/box2d32.c \
    "$LIBDIR/libbox2scene.a" "$LIBDIR/libbox2scene.so.$VERSION" \
    "$LIBDIR/cmake/box2scene/box2sceneConfig.cmake" \
    "$LIBDIR/cmake/box2scene/box2sceneConfigVersion.cmake" \
    "$LIBDIR/pkgconfig/box2scene.pc" "$LIBDIR/pkgconfig/box2scene-static.pc" \
    share/doc/box2scene/LICENSE bin/box2scene; do
    [ -f "$PREFIX/$file" ] && [ ! -L "$PREFIX/$file" ] || fail "no file $PREFIX/$file"
  done
  [ "$(readlink "$libdir/$soname")" = "libbox2scene.so.$VERSION" ] ||
    fail "$soname does not link to libbox2scene.so.$VERSION"
  [ "$(readlink "$libdir/libbox2scene.so")" = "$soname" ] ||
    fail "libbox2scene.so does not link to $soname"
  readelf -d "$libdir/libbox2scene.so.$VERSION" | grep -q "(SONAME).*\[$soname\]" ||
    fail "the SONAME of libbox2scene.so.$VERSION is not $soname"
  cmp "$BOX2SCENE_SOURCE_DIR/include/box2scene.h" "$PREFIX/include/box2scene.h"
  echo "installed with SONAME $soname"
}

# The shared library exports exactly the functions box2scene.h declares.
check_symbols() {
  local exported declared
  exported=$(nm -D --defined-only "$libdir/libbox2scene.so.$VERSION" | awk '{print $3}' | sort)
  declared=$(grep -E '^[a-z].*\bb2s_[a-z0-9_]+\(' "$PREFIX/include/box2scene.h" |
    grep -oE '\bb2s_[a-z0-9_]+\(' | tr -d '(' | sort)
  [ -n "$declared" ] || fail "box2scene.h declares no function"
  [ "$exported" = "$declared" ] ||
    fail "exported (<) and declared (>) differ:" "$(diff <(echo "$exported") <(echo "$declared"))"
  echo "exports the $(echo "$exported" | wc -l) functions of box2scene.h and nothing else"
}

# A release build installs its library and command without debug info; `--strip` also drops
# their symbol tables, and what it installs still loads and runs.
check_strip() {
  local stripped=$work/stripped file
  if [ "$CARGO_PROFILE_DIR" = release ]; then
    for file in "$libdir/libbox2scene.so.$VERSION" "$PREFIX/bin/box2scene"; do
      ! readelf -S "$file" | grep -q '\.debug_' || fail "$file carries debug info"
    done
  fi
  "$CMAKE" --install "$BOX2SCENE_BUILD_DIR" --prefix "$stripped" --strip >"$work/log"
  for file in "$stripped/$LIBDIR/libbox2scene.so.$VERSION" "$stripped/bin/box2scene"; do
    ! readelf -S "$file" | grep -qE '\.(symtab|debug_)' || fail "--strip left $file unstripped"
    [ "$(stat -c %s "$file")" -lt "$(stat -c %s "$PREFIX/${file#"$stripped/"}")" ] ||
      fail "--strip did not make $file smaller"
  done
  nm -D --defined-only "$stripped/$LIBDIR/libbox2scene.so.$VERSION" | grep -q ' b2s_load_file$' ||
    fail "the stripped library lost its exports"
  "$stripped/bin/box2scene" --version | grep -q "box2scene $VERSION" ||
    fail "the stripped command does not run"
  echo "installed without debug info; --strip: $(stat -c %s "$stripped/$LIBDIR/libbox2scene.so.$VERSION") bytes of library"
}

# The package's box2scene::cli is the installed command, and it runs.
check_cli() {
  local cli
  build_consumer cli
  cli=$(cat "$work/build/cli-path.txt")
  [ "$cli" = "$PREFIX/bin/box2scene" ] || fail "box2scene::cli is $cli, not $PREFIX/bin/box2scene"
  [ -x "$cli" ] || fail "$cli is not an executable"
  "$cli" --version | head -n 1 | grep -qx "box2scene $VERSION" ||
    fail "$cli --version does not print box2scene $VERSION" "$("$cli" --version)"
  grep -q "box2scene $VERSION" "$work/log" || fail "the build did not run box2scene --version"
  echo "box2scene::cli is $cli: $("$cli" --version | head -n 1)"
}

check_c_shared() {
  build_consumer c
  expect_shared "$work/build/scene_info"
  expect_output "$c_output" "$work/build/scene_info" "$work/src/scene.xml"
}

check_c_static() {
  local libs
  build_consumer static
  expect_static "$work/build/scene_info_static"
  libs=$(rust_native_libs)
  [ -n "$libs" ] || fail "rustc printed no native-static-libs"
  grep -qF "libbox2scene.a $libs" "$work/build/CMakeFiles/scene_info_static.dir/link.txt" ||
    fail "box2scene::static does not link rustc's native-static-libs: $libs" \
      "$(cat "$work/build/CMakeFiles/scene_info_static.dir/link.txt")"
  echo "links libbox2scene.a $libs"
  expect_output "$c_output" "$work/build/scene_info_static" "$work/src/scene.xml"
}

check_c_build_shared_libs_off() {
  build_consumer c -DBUILD_SHARED_LIBS=OFF
  expect_static "$work/build/scene_info"
  expect_output "$c_output" "$work/build/scene_info" "$work/src/scene.xml"
}

check_cpp_adapter() {
  build_consumer cpp
  expect_shared "$work/build/fall"
  needed "$work/build/fall" | grep -q '^libbox2d\.so' || fail "fall does not load Box2D"
  expect_output "2 bodies; after 1 s the ball is at (0.000, 4.917)" \
    "$work/build/fall" "$work/src/scene.xml"
}

# A C host with its own Box2D v3 (BOX2D3_INCLUDE_DIR, BOX2D3_LIBRARY: the static library the
# build compiled) and the v3 adapter from box2scene::box2d3; Debian's Box2D 2.4 stays out.
check_c_box2d3() {
  : "${BOX2D3_INCLUDE_DIR:?}" "${BOX2D3_LIBRARY:?}"
  build_consumer box2d3 -DBOX2D3_INCLUDE_DIR="$BOX2D3_INCLUDE_DIR" \
    -DBOX2D3_LIBRARY="$BOX2D3_LIBRARY"
  expect_shared "$work/build/fall_v3"
  if needed "$work/build/fall_v3" | grep -q '^libbox2d\.so'; then
    fail "fall_v3 loads Box2D 2.4"
  fi
  expect_output "2 bodies; after 1 s the ball is at (0.000, 4.979)" \
    "$work/build/fall_v3" "$work/src/scene.xml"
}

# The same host with Box2D v3.1 built and installed by Box2D's own CMake, found with
# find_package(box2d 3.1) as box2d::box2d, whose export does not link the maths library
# the adapter needs.
check_box2d3_package() {
  : "${BOX2D3_INCLUDE_DIR:?}"
  local box2d=$work/box2d-prefix
  if ! "$CMAKE" -S "$work/src/box2d3_package/box2d" -B "$work/box2d-build" \
      -DBOX2D_SOURCE_DIR="$BOX2D3_INCLUDE_DIR/.." -DCMAKE_BUILD_TYPE=Release >"$work/log" 2>&1 ||
    ! "$CMAKE" --build "$work/box2d-build" -j2 >>"$work/log" 2>&1 ||
    ! "$CMAKE" --install "$work/box2d-build" --prefix "$box2d" >>"$work/log" 2>&1; then
    cat "$work/log" >&2
    fail "Box2D v3.1 did not build and install with its own CMake"
  fi
  [ -f "$box2d/lib/cmake/box2d/box2dConfig.cmake" ] || fail "Box2D installed no box2dConfig.cmake"
  build_consumer box2d3_package -DCMAKE_PREFIX_PATH="$PREFIX;$box2d"
  expect_output "2 bodies; after 1 s the ball is at (0.000, 4.979)" \
    "$work/build/fall_v3" "$work/src/scene.xml"
}

# The same host with Box2D v3.1.1 fetched by FetchContent and built by Box2D's own CMake
# (docs/install.md's recipe, unchanged). Only the package registries are reachable, so
# FETCHCONTENT_SOURCE_DIR_BOX2D hands FetchContent, as a host with a copy of Box2D's
# repository would, the v3.1.1 sources the tests build (the registry crate's, beside
# BOX2D3_INCLUDE_DIR), whose src/CMakeLists.txt is Box2D's own; nothing is downloaded.
check_box2d3_fetchcontent() {
  : "${BOX2D3_INCLUDE_DIR:?}"
  local box2d
  box2d=$(cd "$BOX2D3_INCLUDE_DIR/.." && pwd)
  [ -f "$box2d/src/CMakeLists.txt" ] || fail "$box2d carries no Box2D CMake project"
  build_consumer box2d3_fetchcontent -DFETCHCONTENT_SOURCE_DIR_BOX2D="$box2d" \
    -DFETCHCONTENT_FULLY_DISCONNECTED=ON
  [ -f "$work/build/_deps/box2d-build/libbox2d.a" ] ||
    fail "Box2D's own CMake did not build libbox2d.a in the host's build"
  if needed "$work/build/fall_v3" | grep -q '^libbox2d\.so'; then
    fail "fall_v3 loads Box2D 2.4"
  fi
  expect_output "2 bodies; after 1 s the ball is at (0.000, 4.979)" \
    "$work/build/fall_v3" "$work/src/scene.xml"
}

# The same with Box2D v3.2 (BOX2D32_INCLUDE_DIR, BOX2D32_LIBRARY) and box2scene::box2d32.
check_c_box2d32() {
  : "${BOX2D32_INCLUDE_DIR:?}" "${BOX2D32_LIBRARY:?}"
  build_consumer box2d32 -DBOX2D32_INCLUDE_DIR="$BOX2D32_INCLUDE_DIR" \
    -DBOX2D32_LIBRARY="$BOX2D32_LIBRARY"
  expect_shared "$work/build/fall_v32"
  if needed "$work/build/fall_v32" | grep -q '^libbox2d\.so'; then
    fail "fall_v32 loads Box2D 2.4"
  fi
  expect_output "2 bodies; after 1 s the ball is at (0.000, 4.979)" \
    "$work/build/fall_v32" "$work/src/scene.xml"
}

check_pkg_config() {
  local libs
  export PKG_CONFIG_LIBDIR=$libdir/pkgconfig PKG_CONFIG_PATH=
  [ "$(pkg-config --modversion box2scene)" = "$VERSION" ] || fail "pkg-config: wrong version"
  libs=$(rust_native_libs)
  pkg-config --libs --static box2scene | grep -qF -- "-lbox2scene $libs" ||
    fail "box2scene.pc's Libs.private are not rustc's native-static-libs: $libs"
  cd "$work/src/c"
  cc -o scene_info main.c $(pkg-config --cflags --libs box2scene)
  expect_shared scene_info
  LD_LIBRARY_PATH=$libdir expect_output "$c_output" ./scene_info ../scene.xml
}

# box2scene-static.pc links the archive itself, though the shared library lies beside it.
check_pkg_config_static() {
  local libs
  export PKG_CONFIG_LIBDIR=$libdir/pkgconfig PKG_CONFIG_PATH=
  [ "$(pkg-config --modversion box2scene-static)" = "$VERSION" ] ||
    fail "pkg-config: wrong version of box2scene-static"
  [ -e "$libdir/libbox2scene.so" ] || fail "no shared library beside the static one"
  libs=$(rust_native_libs)
  pkg-config --libs box2scene-static | grep -qF -- "libbox2scene.a $libs" ||
    fail "box2scene-static.pc does not link the archive and $libs"
  cd "$work/src/c"
  cc -o scene_info main.c $(pkg-config --cflags --libs box2scene-static)
  expect_static scene_info
  expect_output "$c_output" ./scene_info ../scene.xml
  echo "links $(pkg-config --libs box2scene-static)"
}

# cargo-c installs as docs/install.md says (cargo cinstall from the source tree) the headers
# and C files cmake --install installs, and the README's C example builds against that
# prefix with pkg-config and runs. cargo-c is
# installed once under the build folder, unoptimised and without debug information (a build
# of cargo itself: a few minutes; 0.10.24 is the newest that builds with Rust 1.95).
# Debian's cargo-c (0.9.14, `apt-get install cargo-c`) would spare that build but cannot
# serve: it carries the cargo of its day, which reads no edition 2024 manifest, and stops on
# this workspace's Cargo.toml ("this version of Cargo is older than the `2024` edition")
# before it installs a file.
check_cargo_c() {
  : "${CARGO:?}"
  local tools=$BOX2SCENE_BUILD_DIR/tools/cargo-c prefix=$work/cargo-c-prefix folder file cflags
  if [ ! -x "$tools/bin/cargo-cinstall" ]; then
    CARGO_TARGET_DIR=$BOX2SCENE_BUILD_DIR/tools/cargo-c-build CARGO_PROFILE_DEV_DEBUG=0 \
      "$CARGO" install cargo-c \
      --version 0.10.24 --locked --debug --root "$tools" >"$work/log" 2>&1 ||
      { cat "$work/log" >&2; fail "cargo-c did not install"; }
  fi
  (cd "$BOX2SCENE_SOURCE_DIR" &&
    PATH=$tools/bin:$PATH CARGO_TARGET_DIR=$BOX2SCENE_BUILD_DIR/cargo-c \
      "$CARGO" cinstall -p box2scene --release --locked --prefix "$prefix" --libdir lib) \
    >"$work/log" 2>&1 ||
    { cat "$work/log" >&2; fail "cargo cinstall failed"; }
  # The headers and the adapters' C files as cmake --install installs them.
  for folder in include share/box2scene; do
    diff -r "$PREFIX/$folder" "$prefix/$folder" >&2 ||
      fail "cargo cinstall's $folder differs from cmake --install's"
  done
  for file in lib/libbox2scene.a "lib/libbox2scene.so.$ABI_VERSION" lib/pkgconfig/box2scene.pc; do
    [ -e "$prefix/$file" ] || fail "cargo cinstall installed no $file"
  done
  export PKG_CONFIG_LIBDIR=$prefix/lib/pkgconfig PKG_CONFIG_PATH=
  [ "$(pkg-config --modversion box2scene)" = "$VERSION" ] || fail "cargo-c's box2scene.pc: wrong version"
  cflags=$(pkg-config --cflags box2scene)
  [ "${cflags% }" = "-I$prefix/include" ] || fail "cargo-c's box2scene.pc gives the flags $cflags"
  cd "$work/src/c"
  cc -Wall -Wextra -Werror -o scene_info main.c $(pkg-config --cflags --libs box2scene)
  expect_shared scene_info
  LD_LIBRARY_PATH=$prefix/lib expect_output "$c_output" ./scene_info ../scene.xml
  echo "$("$tools/bin/cargo-cinstall" cinstall --version 2>/dev/null | head -1) installed into a prefix the C example builds against"
}

check_subdirectory() {
  configure_and_build subdirectory -DBOX2SCENE_SOURCE_DIR="$BOX2SCENE_SOURCE_DIR" \
    -DBOX2SCENE_CARGO_TARGET_DIR="$BOX2SCENE_CARGO_TARGET_DIR"
  expect_parent_project "$work/build/box2scene"
}

# FetchContent clones this source tree's repository at its HEAD, as a host clones a release.
check_fetchcontent() {
  local head
  head=$(git -C "$BOX2SCENE_SOURCE_DIR" rev-parse HEAD) || fail "the source tree is no git repository"
  configure_and_build fetchcontent -DBOX2SCENE_GIT_REPOSITORY="file://$BOX2SCENE_SOURCE_DIR" \
    -DBOX2SCENE_GIT_TAG="$head" -DBOX2SCENE_CARGO_TARGET_DIR="$work/cargo"
  expect_parent_project "$work/build/_deps/box2scene-build"
  echo "built box2scene $head through FetchContent"
}

# The README and docs/install.md show these files as they are.
check_readme() {
  local readme install file
  readme=$(cat "$BOX2SCENE_SOURCE_DIR/README.md")
  install=$(cat "$BOX2SCENE_SOURCE_DIR/docs/install.md")
  for file in c/main.c c/CMakeLists.txt; do
    [[ $readme == *"$(cat "$here/$file")"* ]] || fail "README.md does not show $file as it is"
  done
  for file in c/CMakeLists.txt cpp/CMakeLists.txt static/CMakeLists.txt box2d3/CMakeLists.txt \
    box2d32/CMakeLists.txt fetchcontent/CMakeLists.txt box2d3_package/CMakeLists.txt \
    box2d3_fetchcontent/CMakeLists.txt; do
    [[ $install == *"$(cat "$here/$file")"* ]] ||
      fail "docs/install.md does not show $file as it is"
  done
  [[ $install == *'cc -o scene_info main.c $(pkg-config --cflags --libs box2scene-static)'* ]] ||
    fail "docs/install.md does not show the static pkg-config command line"
  for text in "$readme" "$install"; do
    [[ $text == *'cc -o scene_info main.c $(pkg-config --cflags --libs box2scene)'* ]] ||
      fail "README.md or docs/install.md does not show the pkg-config command line"
  done
  echo "README.md and docs/install.md show the consumers as they are"
}

[ $# -eq 1 ] && declare -F "check_$1" >/dev/null || fail "usage: $0 CHECK"
"check_$1"
if [ -n "${CMAKELISTS:-}" ] && [ -z "${cmakelists_built:-}" ]; then
  fail "the $1 check builds no consumer's CMakeLists.txt, so not $CMAKELISTS"
fi
