# Box2D v3.1.1, built from source for the tests and examples of the v3 adapter: the target
# box2scene_box2d3_engine (alias box2d3::box2d3), a static library.
#
# Its C sources come from the registry the crate already uses: tools/box2d3/ is a manifest
# depending on oxybox-sys 0.1.1, whose vendor/box2d is the v3.1.1 release. `cargo fetch`
# puts them in cargo's cache and `cargo metadata` says where, so nothing else is downloaded
# and the version is pinned by that manifest and its Cargo.lock. Box2D's own CMake files are
# not used: they would install Box2D with box2scene.

include(${CMAKE_CURRENT_LIST_DIR}/CrateSources.cmake)

function(box2scene_add_box2d3_engine)
    box2scene_crate_sources(box2d3 oxybox-sys vendor/box2d include/box2d/box2d.h source_dir)
    message(STATUS "Box2D v3 (the v3 adapter's tests): ${source_dir}")
    file(GLOB sources ${source_dir}/src/*.c)
    add_library(box2scene_box2d3_engine STATIC ${sources})
    # Box2D v3 is C17 with GNU extensions, and its own build turns contraction of floating
    # point operations into FMA off, which keeps its results the same on every machine.
    set_target_properties(box2scene_box2d3_engine PROPERTIES
        C_STANDARD 17 C_STANDARD_REQUIRED ON C_EXTENSIONS ON)
    target_compile_options(box2scene_box2d3_engine PRIVATE -ffp-contract=off)
    # BEFORE: Debian's Box2D 2.4 has the same <box2d/box2d.h> in /usr/include, and a v3
    # target must never see it.
    target_include_directories(box2scene_box2d3_engine BEFORE
        PUBLIC ${source_dir}/include
        PRIVATE ${source_dir}/src)
    # B2_ASSERT stays live in every configuration, NDEBUG or not (src/core.h, box2d/base.h):
    # a value the adapter hands v3 that trips an assertion must fail the test, not pass
    # unnoticed in a release build. PUBLIC, as box2d/*.h assert in inline functions too.
    target_compile_definitions(box2scene_box2d3_engine PUBLIC B2_ENABLE_ASSERT)
    # sqrtf, cosf and the like.
    target_link_libraries(box2scene_box2d3_engine PUBLIC m)
    add_library(box2d3::box2d3 ALIAS box2scene_box2d3_engine)
endfunction()
