# The per-pair tools must not load libpcl_io or libpcl_surface: the VTK libraries behind them take
# about 27 ms to load, a tenth of a pair's registration (doc/log.md, 2026-12-07).
# Usage: cmake -DAPPS="a;b" -P light_startup.cmake
foreach(app ${APPS})
  execute_process(COMMAND ldd ${app} OUTPUT_VARIABLE libraries RESULT_VARIABLE rc ERROR_QUIET)
  if(NOT rc EQUAL 0)
    message("SKIPPED: ldd cannot list the libraries of ${app}")
    return()
  endif()
  string(REGEX MATCHALL "lib(vtk[A-Za-z]*|pcl_io|pcl_surface)[^ ]*\\.so" heavy "${libraries}")
  if(heavy)
    list(REMOVE_DUPLICATES heavy)
    message(FATAL_ERROR "${app} loads ${heavy}")
  endif()
  message(STATUS "${app}: no VTK, libpcl_io or libpcl_surface")
endforeach()
