# Box2D v3.2, built from source for the tests and examples of the v3.2 adapter: the target
# box2scene_box2d32_engine (alias box2d32::box2d32), a static library.
#
# The only v3.2 C sources on the registry are those of boxdd-sys 0.6.0 (third-party/box2d:
# upstream commit 56edae79 of June 2026, MIT; not the 3.2.0 release of October 2026):
# tools/box2d32/ is a manifest depending on it, fetched and located as the v3.1.1 engine's
# sources are (cmake/CrateSources.cmake). Its patches/ are not applied: they touch recording,
# snapshots, allocation and timers only.
# Box2D v3.1.1 and v3.2 define the same symbols, so no target links both.

include(${CMAKE_CURRENT_LIST_DIR}/CrateSources.cmake)

function(box2scene_add_box2d32_engine)
    box2scene_crate_sources(box2d32 boxdd-sys third-party/box2d include/box2d/box2d.h
                            source_dir)
    message(STATUS "Box2D v3.2 (the v3.2 adapter's tests): ${source_dir}")
    file(GLOB sources ${source_dir}/src/*.c)
    add_library(box2scene_box2d32_engine STATIC ${sources})
    # As upstream builds it: C17 with GNU extensions, no contraction into FMA (the same results
    # on every machine), and B2_UNUSED's casts not warned about.
    set_target_properties(box2scene_box2d32_engine PROPERTIES
        C_STANDARD 17 C_STANDARD_REQUIRED ON C_EXTENSIONS ON)
    target_compile_options(box2scene_box2d32_engine PRIVATE -ffp-contract=off -Wno-unused-value)
    # BEFORE: Debian's Box2D 2.4 has the same <box2d/box2d.h> in /usr/include. src/ is private:
    # recording.c includes recording_ops.inl from there.
    target_include_directories(box2scene_box2d32_engine BEFORE
        PUBLIC ${source_dir}/include
        PRIVATE ${source_dir}/src)
    # B2_ASSERT live in every configuration; PUBLIC, as the library defines b2InternalAssert
    # only when it is built with assertions and box2d/*.h assert in inline functions.
    target_compile_definitions(box2scene_box2d32_engine PUBLIC B2_ENABLE_ASSERT)
    # sqrtf and the like; the built-in task scheduler runs on pthreads.
    find_package(Threads REQUIRED)
    target_link_libraries(box2scene_box2d32_engine PUBLIC m Threads::Threads)
    add_library(box2d32::box2d32 ALIAS box2scene_box2d32_engine)
endfunction()
