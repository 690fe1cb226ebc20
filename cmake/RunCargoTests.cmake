# Runs one suite of the crates' Rust tests for CTest and says how many of its tests passed:
#   cmake -DCARGO=... -DMANIFEST=... -DTARGET_DIR=... "-DSELECT=-p box2scene --test hostile"
#         -P RunCargoTests.cmake
# The suite fails when cargo fails, and when it ran no test at all (a selection that matches
# nothing passes in cargo).
separate_arguments(SELECT UNIX_COMMAND "${SELECT}")
execute_process(
    COMMAND ${CMAKE_COMMAND} -E env CARGO_TARGET_DIR=${TARGET_DIR}
            ${CARGO} test --locked --manifest-path ${MANIFEST} ${SELECT}
    RESULT_VARIABLE status
    OUTPUT_VARIABLE output
    ERROR_VARIABLE errors)
# Each binary's summary, "test result: ok. 3 passed; 0 failed; 1 ignored; ...", its
# semicolons made commas so that it stays one item of a CMake list.
string(REPLACE ";" "," summaries "${output}")
string(REGEX MATCHALL "test result: [a-zA-Z]+\\. [0-9]+ passed, [0-9]+ failed, [0-9]+ ignored"
       results "${summaries}")
set(passed 0)
set(failed 0)
set(ignored 0)
foreach(result IN LISTS results)
    string(REGEX MATCH "([0-9]+) passed, ([0-9]+) failed, ([0-9]+) ignored" _ "${result}")
    math(EXPR passed "${passed} + ${CMAKE_MATCH_1}")
    math(EXPR failed "${failed} + ${CMAKE_MATCH_2}")
    math(EXPR ignored "${ignored} + ${CMAKE_MATCH_3}")
endforeach()
if(NOT status EQUAL 0)
    message("${output}")
    message("${errors}")
    message(FATAL_ERROR "cargo test ${SELECT}: ${passed} passed, ${failed} failed (${status})")
endif()
if(passed EQUAL 0)
    message("${output}")
    message(FATAL_ERROR "cargo test ${SELECT} ran no test")
endif()
message("${passed} passed, ${ignored} ignored")
