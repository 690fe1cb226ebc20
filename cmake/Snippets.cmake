# The code blocks of README.md and docs/*.md as CTest tests: each ```c, ```cpp and ```cmake
# block is written to snippets/PAGE_N/ in the build folder (the Nth such block of PAGE.md)
# and tested as snippet_PAGE_N, so that what a reader copies builds and runs.
#
# The line before a block (blank lines aside) says how it is tested:
#   <!-- snippet: HARNESS -->         tests/snippets/HARNESS, a C file for a c block, C++
#                                     for cpp, that includes the block's #include lines,
#                                     snippet_head.h, at its top and the rest, snippet_body.h,
#                                     where the block's variables are: as main's body, with a
#                                     scene loaded, beside a built world (see each harness);
#   <!-- snippet: consumer CHECK -->  a whole CMakeLists.txt, put in place of the one of
#                                     tests/consumers/ that the test consumer_CHECK builds,
#                                     then built and run as that test does
#                                     (tests/consumers/run.sh CHECK).
# A C or C++ block that is a whole program (it defines main) needs none, and gets level.xml
# as its argument. Any other block without one stops the configuration, so that no snippet
# goes untested.
#
# A C or C++ snippet is compiled with -Wall -Wextra -Werror, and with AddressSanitizer and
# UndefinedBehaviorSanitizer where the compiler has them (a use after free, a leak or a
# misaligned read fails it), against box2scene::box2scene and the Box2D that its and its
# harness's includes name: <box2scene/box2d.hpp> Box2D 2.4 (box2d::box2d), <box2scene/box2d3.h>
# v3.1 (box2scene::box2d3, box2d3::box2d3), <box2scene/box2d32.h> v3.2 (box2scene::box2d32,
# box2d32::box2d32). Its diagnostics point into the page (#line). It runs in its own folder,
# where level.xml is a fresh copy of examples/scenes/showcase.xml, and passes when it exits
# with 0 and leaves level.xml as it was (tests/snippets/run.cmake).

set(BOX2SCENE_SNIPPET_SANITIZERS "")
if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang" AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    set(BOX2SCENE_SNIPPET_SANITIZERS
        -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
endif()

# Every page's snippets, tested.
function(box2scene_add_snippet_tests)
    # A page edited, or one added, configures again.
    file(GLOB pages CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md)
    list(PREPEND pages ${PROJECT_SOURCE_DIR}/README.md)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${pages})
    foreach(page IN LISTS pages)
        box2scene_snippets_of_page(${page})
    endforeach()
endfunction()

# The blocks of one page, read a line at a time (the text is cut with string(FIND), never
# made a list: C's semicolons and brackets would cut it elsewhere).
function(box2scene_snippets_of_page page)
    file(READ ${page} text)
    cmake_path(GET page STEM stem)
    set(line_number 0)
    set(count 0)        # the c, cpp and cmake blocks so far
    set(marker "")      # the marker of the block to come
    set(fenced OFF)     # inside a fenced block
    set(language "")    # ... of c, cpp or cmake
    while(NOT text STREQUAL "")
        string(FIND "${text}" "\n" end)
        if(end EQUAL -1)
            set(line "${text}")
            set(text "")
        else()
            string(SUBSTRING "${text}" 0 ${end} line)
            math(EXPR end "${end} + 1")
            string(SUBSTRING "${text}" ${end} -1 text)
        endif()
        math(EXPR line_number "${line_number} + 1")
        if(fenced)
            if(line STREQUAL "```")
                set(fenced OFF)
                if(language)
                    math(EXPR count "${count} + 1")
                    box2scene_add_snippet(${page} ${stem}_${count} ${language} ${first_line}
                                          "${marker}" "${block}")
                    set(marker "")
                endif()
            elseif(language)
                string(APPEND block "${line}\n")
            endif()
        elseif(line MATCHES "^```(.*)$")
            set(fenced ON)
            set(language "")
            if(CMAKE_MATCH_1 MATCHES "^(c|cpp|cmake)$")
                set(language ${CMAKE_MATCH_1})
                math(EXPR first_line "${line_number} + 1")
                set(block "")
            elseif(NOT marker STREQUAL "")
                message(FATAL_ERROR "${page}:${line_number}: a snippet marker before a block "
                                    "that is not c, cpp or cmake")
            endif()
        elseif(line MATCHES "^<!-- snippet: (.*) -->$")
            set(marker "${CMAKE_MATCH_1}")
        elseif(NOT line STREQUAL "")
            set(marker "")
        endif()
    endwhile()
    if(fenced)
        message(FATAL_ERROR "${page}: a fenced block is not closed")
    endif()
endfunction()

# One block: LANGUAGE c, cpp or cmake, its text BLOCK from line FIRST_LINE of PAGE, tested
# as snippet_NAME as MARKER says.
function(box2scene_add_snippet page name language first_line marker block)
    set(dir ${CMAKE_CURRENT_BINARY_DIR}/snippets/${name})
    set(where "${page}:${first_line}")
    if(language STREQUAL "cmake")
        if(NOT marker MATCHES "^consumer ([a-z0-9_]+)$")
            message(FATAL_ERROR "${where}: a cmake block needs <!-- snippet: consumer CHECK -->"
                                " before it, CHECK a check of tests/consumers/run.sh")
        endif()
        set(check ${CMAKE_MATCH_1})
        get_test_property(consumer_${check} ENVIRONMENT environment)
        get_test_property(consumer_${check} FIXTURES_REQUIRED fixtures)
        if(NOT environment)
            message(FATAL_ERROR "${where}: there is no test consumer_${check}")
        endif()
        file(WRITE ${dir}/CMakeLists.txt "${block}")
        add_test(NAME snippet_${name}
                 COMMAND bash ${PROJECT_SOURCE_DIR}/tests/consumers/run.sh ${check})
        set_tests_properties(snippet_${name} PROPERTIES
            ENVIRONMENT "${environment};CMAKELISTS=${dir}/CMakeLists.txt")
        if(fixtures)
            set_tests_properties(snippet_${name} PROPERTIES FIXTURES_REQUIRED "${fixtures}")
        endif()
        return()
    endif()

    set(arguments "")
    if(NOT marker STREQUAL "")
        # The block's #include lines go to the top of the harness, the rest where it puts it.
        set(harness ${PROJECT_SOURCE_DIR}/tests/snippets/${marker})
        cmake_path(GET harness EXTENSION LAST_ONLY extension)
        if(NOT EXISTS ${harness} OR NOT extension STREQUAL ".${language}")
            message(FATAL_ERROR "${where}: the harness of a ${language} block is a "
                                ".${language} file of tests/snippets/, not ${marker}")
        endif()
        file(READ ${harness} harness_text)
        set(head "")
        set(body "#line ${first_line} \"${page}\"\n")
        set(rest "${block}")
        set(number ${first_line})
        while(NOT rest STREQUAL "")
            string(FIND "${rest}" "\n" end)
            string(SUBSTRING "${rest}" 0 ${end} line)
            math(EXPR end "${end} + 1")
            string(SUBSTRING "${rest}" ${end} -1 rest)
            if(line MATCHES "^#include ")
                string(APPEND head "#line ${number} \"${page}\"\n${line}\n")
                string(APPEND body "\n")
            else()
                string(APPEND body "${line}\n")
            endif()
            math(EXPR number "${number} + 1")
        endwhile()
        file(WRITE ${dir}/snippet_head.h "${head}")
        file(WRITE ${dir}/snippet_body.h "${body}")
        set(source ${harness})
    elseif(block MATCHES "(^|\n)int main\\(")
        set(harness_text "")
        set(source ${dir}/snippet.${language})
        file(WRITE ${source} "#line ${first_line} \"${page}\"\n${block}")
        set(arguments level.xml)
    else()
        message(FATAL_ERROR "${where}: a ${language} block that is not a whole program needs "
                            "<!-- snippet: HARNESS --> before it, HARNESS a file of "
                            "tests/snippets/")
    endif()

    add_executable(snippet_${name} ${source})
    target_include_directories(snippet_${name} PRIVATE ${dir})
    target_link_libraries(snippet_${name} PRIVATE box2scene::box2scene)
    # The Box2D the includes name.
    set(includes "${block}${harness_text}")
    if(includes MATCHES "<box2scene/box2d32\\.h>")
        target_link_libraries(snippet_${name} PRIVATE box2scene::box2d32 box2d32::box2d32)
    elseif(includes MATCHES "<box2scene/box2d3\\.h>")
        target_link_libraries(snippet_${name} PRIVATE box2scene::box2d3 box2d3::box2d3)
    elseif(includes MATCHES "<box2scene/box2d\\.hpp>")
        target_link_libraries(snippet_${name} PRIVATE box2d::box2d)
    endif()
    target_compile_options(snippet_${name} PRIVATE -Wall -Wextra -Werror
                           ${BOX2SCENE_SNIPPET_SANITIZERS})
    target_link_options(snippet_${name} PRIVATE ${BOX2SCENE_SNIPPET_SANITIZERS})
    set_target_properties(snippet_${name} PROPERTIES
        RUNTIME_OUTPUT_DIRECTORY ${dir}
        C_STANDARD 11 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF
        CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON CXX_EXTENSIONS OFF)
    add_test(NAME snippet_${name}
             COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:snippet_${name}>
                     -DSCENE=${PROJECT_SOURCE_DIR}/examples/scenes/showcase.xml
                     "-DARGS=${arguments}" -P ${PROJECT_SOURCE_DIR}/tests/snippets/run.cmake
             WORKING_DIRECTORY ${dir})
endfunction()
