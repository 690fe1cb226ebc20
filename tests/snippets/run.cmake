# Runs one snippet's program: `cmake -DPROGRAM=... -DSCENE=... [-DARGS=...] -P run.cmake`, in
# the snippet's own folder. level.xml there is a fresh copy of SCENE, the level the snippet
# loads; the test fails when the program exits otherwise than with 0 or changes level.xml.
cmake_minimum_required(VERSION 3.21)

file(COPY_FILE ${SCENE} level.xml)
execute_process(COMMAND ${PROGRAM} ${ARGS} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} exited with ${result}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${SCENE} level.xml
                RESULT_VARIABLE changed)
if(changed)
    message(FATAL_ERROR "${PROGRAM} changed level.xml, the level it loaded")
endif()
