# Every core, the same answer: runs COMMAND (a ;-list printing JSON) once per thread count in THREADS,
# with "-j N" appended, and requires every run to exit with EXPECTED_EXIT and to print the same numbers
# for every match of PATTERN (e.g. each view's "pose"), digit for digit.
#   cmake "-DCOMMAND=app;a.ply;b.ply;--json" -DTHREADS="1;2;4" -DPATTERN=pose -DEXPECTED_EXIT=0 -P same_across_threads.cmake
set(first "")
foreach(threads ${THREADS})
  execute_process(COMMAND ${COMMAND} -j ${threads} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 900)
  if(NOT "${code}" STREQUAL "${EXPECTED_EXIT}")
    message(FATAL_ERROR "-j ${threads}: exit code ${code}, expected ${EXPECTED_EXIT}\n${err}")
  endif()
  string(REGEX MATCHALL "\"${PATTERN}\": ?\\[[^]]*\\]" found "${out}")
  if(NOT found)
    message(FATAL_ERROR "-j ${threads}: no \"${PATTERN}\" in the JSON report:\n${out}")
  endif()
  if(first STREQUAL "")
    set(first "${found}")
  elseif(NOT found STREQUAL first)
    message(FATAL_ERROR "-j ${threads} gave ${found}\n-j ${THREADS} (first) gave ${first}")
  endif()
endforeach()
list(LENGTH first count)
message(STATUS "${count} \"${PATTERN}\" the same at -j ${THREADS}")
