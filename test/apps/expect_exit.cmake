# Runs COMMAND (a ;-list) and checks that it exits with EXPECTED_EXIT. A failing run must say why
# in exactly one line on stderr, as the apps promise.
#   cmake -DCOMMAND="app;arg1;arg2" -DEXPECTED_EXIT=2 -P expect_exit.cmake
# With -DUNREADABLE=FILE the case is about a file this user must not be able to read: when it can
# (root reads mode-000 files) the run is pointless and the test reports itself SKIPPED.
if(UNREADABLE)
  execute_process(COMMAND test -r ${UNREADABLE} RESULT_VARIABLE readable)
  if(readable EQUAL 0)
    message("SKIPPED: ${UNREADABLE} is mode 000 but this user (root?) can read it")
    return()
  endif()
endif()
# A hang guard. Under the sanitizers a run takes about 12 times as long as in Release: the refusal of
# app_model_wrong_view_refused (23 s) took 282-300 s, and 300 s cut it off.
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 1200)
if(NOT "${code}" STREQUAL "${EXPECTED_EXIT}")
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECTED_EXIT}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(NOT EXPECTED_EXIT EQUAL 0)
  string(STRIP "${err}" err)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines extra_lines)
  if(err STREQUAL "" OR extra_lines GREATER 0)
    message(FATAL_ERROR "expected one line on stderr, got:\n${err}")
  endif()
endif()
if(EXPECTED_FILE AND NOT EXISTS "${EXPECTED_FILE}")
  message(FATAL_ERROR "expected output file ${EXPECTED_FILE} was not written")
endif()
