# Determinism: runs COMMAND (a ;-list ending in --json) RUNS times, alternately with OMP_NUM_THREADS=1
# and 2, and requires every run to exit with EXPECTED_EXIT and to print the same transform, digit for
# digit (JSON prints each float exactly, as its double).
#   cmake -DCOMMAND="app;a.ply;b.ply;--json" -DEXPECTED_EXIT=0 -DRUNS=4 -P same_transform.cmake
set(first "")
foreach(run RANGE 1 ${RUNS})
  math(EXPR threads "1 + ${run} % 2")
  set(ENV{OMP_NUM_THREADS} ${threads})
  execute_process(COMMAND ${COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  if(NOT "${code}" STREQUAL "${EXPECTED_EXIT}")
    message(FATAL_ERROR "run ${run} (OMP_NUM_THREADS=${threads}): exit code ${code}, expected ${EXPECTED_EXIT}\n${err}")
  endif()
  if(NOT out MATCHES "\"transform\": ?\\[[^]]*\\]")
    message(FATAL_ERROR "run ${run}: no transform in the JSON report:\n${out}")
  endif()
  set(transform "${CMAKE_MATCH_0}")
  if(run EQUAL 1)
    set(first "${transform}")
  elseif(NOT transform STREQUAL first)
    message(FATAL_ERROR "run ${run} (OMP_NUM_THREADS=${threads}) gave ${transform}\nrun 1 gave ${first}")
  endif()
endforeach()
message(STATUS "${RUNS} runs gave ${first}")
