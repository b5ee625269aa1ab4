# scripts/pcl_tensor_dask.py on a LocalCluster of 2 workers against one pcl_tensor_model run
# (dask_model.py). Debian's python3-distributed serves /usr/bin/python3, which another python3 first
# on PATH (pyenv, a venv) may lack; without dask.distributed the test says SKIPPED. Left out of the
# sanitizer build: the tools' code is covered there by the pcl_tensor_pairs and prepare tests, and
# two runs of the whole job under the sanitizers would cost CI many minutes.
if(NOT PCL_TENSOR_BUILD_FUZZERS)
  if(EXISTS /usr/bin/python3)
    set(dask_python /usr/bin/python3)
  else()
    set(dask_python ${Python3_EXECUTABLE})
  endif()
  set(PCL_TENSOR_DASK_PYTHON ${dask_python} CACHE FILEPATH "python3 with dask.distributed, for the Dask driver's test")
  if(PCL_TENSOR_DASK_PYTHON)
    add_test(NAME app_dask_same_poses
      COMMAND ${PCL_TENSOR_DASK_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/dask_model.py --bin $<TARGET_FILE_DIR:pcl_tensor_model>
              --driver ${PROJECT_SOURCE_DIR}/scripts/pcl_tensor_dask.py --out ${APP_OUT}/dask)
    set_tests_properties(app_dask_same_poses PROPERTIES TIMEOUT 900 PROCESSORS 2 SKIP_REGULAR_EXPRESSION "SKIPPED \\[")
  else()
    message(STATUS "SKIPPED app_dask_same_poses: no python3")
  endif()
endif()
