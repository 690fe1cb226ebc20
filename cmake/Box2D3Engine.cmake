# Box2D v3.1.1, built from source for the tests and examples of the v3 adapter: the target
# box2scene_box2d3_engine (alias box2d3::box2d3), a static library.
#
# Its C sources come from the registry the crate already uses: tools/box2d3/ is a manifest
# depending on oxybox-sys 0.1.1, whose vendor/box2d is the v3.1.1 release. `cargo fetch`
# puts them in cargo's cache and `cargo metadata` says where, so nothing else is downloaded
# and the version is pinned by that manifest and its Cargo.lock. Box2D's own CMake files are
# not used: they would install Box2D with box2scene.

# The vendor/box2d directory of oxybox-sys, fetched into cargo's cache if it is not there yet.
function(box2scene_box2d3_source_dir out_var)
    set(manifest ${PROJECT_SOURCE_DIR}/tools/box2d3/Cargo.toml)
    # Configure again when the pinned version changes.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
                 ${manifest} ${PROJECT_SOURCE_DIR}/tools/box2d3/Cargo.lock)
    execute_process(
        COMMAND ${CARGO_EXECUTABLE} fetch --locked --manifest-path ${manifest}
        RESULT_VARIABLE result
        ERROR_VARIABLE log)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "cargo could not fetch Box2D v3's sources (oxybox-sys):\n${log}")
    endif()
    execute_process(
        COMMAND ${CARGO_EXECUTABLE} metadata --format-version 1 --locked --offline
                --manifest-path ${manifest}
        RESULT_VARIABLE result
        OUTPUT_VARIABLE metadata
        ERROR_VARIABLE log)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "cargo metadata failed for ${manifest}:\n${log}")
    endif()
    string(JSON package_count LENGTH "${metadata}" packages)
    math(EXPR last "${package_count} - 1")
    foreach(i RANGE ${last})
        string(JSON name GET "${metadata}" packages ${i} name)
        if(name STREQUAL "oxybox-sys")
            string(JSON crate_manifest GET "${metadata}" packages ${i} manifest_path)
            cmake_path(GET crate_manifest PARENT_PATH crate_dir)
            set(source_dir ${crate_dir}/vendor/box2d)
        endif()
    endforeach()
    if(NOT EXISTS "${source_dir}/include/box2d/box2d.h")
        message(FATAL_ERROR "oxybox-sys holds no vendor/box2d/include/box2d/box2d.h "
                            "(looked in '${source_dir}')")
    endif()
    set(${out_var} ${source_dir} PARENT_SCOPE)
endfunction()

function(box2scene_add_box2d3_engine)
    box2scene_box2d3_source_dir(source_dir)
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
