# The example_simulate, example_simulate_v3 and example_simulate_v32 tests: a short run of
# the bundled scene by SIMULATE (simulate, simulate_v3 or simulate_v32) must succeed and write its SVG. The old SVG is removed first so that a stale file cannot pass.

file(REMOVE "${SVG}")
execute_process(COMMAND "${SIMULATE}" --steps 30 --svg "${SVG}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${SIMULATE} failed: ${result}")
endif()
if(NOT EXISTS "${SVG}")
  message(FATAL_ERROR "simulate succeeded but wrote no ${SVG}")
endif()
