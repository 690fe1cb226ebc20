# C sources that a crate of the package registry carries, fetched with cargo: the engines the
# Box2D v3 adapters are tested against come this way (cmake/Box2D3Engine.cmake,
# cmake/Box2D32Engine.cmake), so that nothing else is downloaded.
#
# tools/<tool>/Cargo.toml is a manifest depending on the crate alone, pinned by its
# Cargo.lock. `cargo fetch` puts the crate in cargo's cache and `cargo metadata` says where;
# OUT_VAR gets the crate's folder SUBDIR, which must hold CHECK_FILE.
function(box2scene_crate_sources tool crate subdir check_file out_var)
    set(manifest ${PROJECT_SOURCE_DIR}/tools/${tool}/Cargo.toml)
    # Configure again when the pinned version changes.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
                 ${manifest} ${PROJECT_SOURCE_DIR}/tools/${tool}/Cargo.lock)
    execute_process(
        COMMAND ${CARGO_EXECUTABLE} fetch --locked --manifest-path ${manifest}
        RESULT_VARIABLE result
        ERROR_VARIABLE log)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "cargo could not fetch the sources of ${crate}:\n${log}")
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
    set(source_dir "")
    foreach(i RANGE ${last})
        string(JSON name GET "${metadata}" packages ${i} name)
        if(name STREQUAL crate)
            string(JSON crate_manifest GET "${metadata}" packages ${i} manifest_path)
            cmake_path(GET crate_manifest PARENT_PATH crate_dir)
            set(source_dir ${crate_dir}/${subdir})
        endif()
    endforeach()
    if(NOT EXISTS "${source_dir}/${check_file}")
        message(FATAL_ERROR "${crate} holds no ${subdir}/${check_file} "
                            "(looked in '${source_dir}')")
    endif()
    set(${out_var} ${source_dir} PARENT_SCOPE)
endfunction()
