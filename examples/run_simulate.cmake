# The example_simulate, example_simulate_v3 and example_simulate_v32 tests, for SIMULATE
# (simulate, simulate_v3 or simulate_v32):
# - `--help` prints the usage on standard output and succeeds;
# - a short run of the bundled scene succeeds and writes SVG (given with --svg), the
#   library's picture of it;
# - the same run without --svg, started in WORKDIR, writes DEFAULT_SVG (the build folder's)
#   and nothing in WORKDIR.
# Old pictures are removed first so that a stale file cannot pass.

execute_process(COMMAND "${SIMULATE}" --help RESULT_VARIABLE result
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 0 OR NOT out MATCHES "^usage: " OR NOT err STREQUAL "")
  message(FATAL_ERROR "${SIMULATE} --help: exit ${result}, stdout '${out}', stderr '${err}'")
endif()

file(REMOVE "${SVG}")
execute_process(COMMAND "${SIMULATE}" --steps 30 --svg "${SVG}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${SIMULATE} failed: ${result}")
endif()
if(NOT EXISTS "${SVG}")
  message(FATAL_ERROR "simulate succeeded but wrote no ${SVG}")
endif()
# The library's picture of the run: titled, keyed, the start faint under the end, the paths.
file(READ "${SVG}" picture)
foreach(part "<title>showcase.xml: 30 steps of 1/60 s in Box2D [0-9.v]+</title>"
             "<g class=\"key\">" "<g class=\"start\" opacity=\"0.3\">" "<g class=\"end\">"
             "<g class=\"paths\"" "<g class=\"labels\"")
  if(NOT picture MATCHES "${part}")
    message(FATAL_ERROR "${SVG} has no ${part}")
  endif()
endforeach()

file(REMOVE "${DEFAULT_SVG}")
file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
execute_process(COMMAND "${SIMULATE}" --steps 30 RESULT_VARIABLE result
                WORKING_DIRECTORY "${WORKDIR}")
file(GLOB left "${WORKDIR}/*")
if(NOT result EQUAL 0 OR NOT EXISTS "${DEFAULT_SVG}" OR left)
  message(FATAL_ERROR
          "${SIMULATE} without --svg: exit ${result}, expected ${DEFAULT_SVG}, "
          "found in its working directory: ${left}")
endif()
