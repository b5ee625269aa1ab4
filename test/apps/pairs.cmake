# pcl_tensor_pairs: ranking and registering pairs from the cache (pairs_results.cmake) on two views of
# the ring pcl_tensor_views renders (register_views), and the bad-input matrix.
set(PAIRS $<TARGET_FILE:pcl_tensor_pairs>)
set(PAIRS_OUT ${APP_OUT}/pairs)
file(MAKE_DIRECTORY ${PAIRS_OUT}/empty_cache)

if(Python3_Interpreter_FOUND)
  add_test(NAME app_pairs_rank_and_register
    COMMAND ${CMAKE_COMMAND} -DPREPARE=$<TARGET_FILE:pcl_tensor_prepare> -DPAIRS=${PAIRS} -DREGISTER=${REGISTER}
      -DPYTHON=${Python3_EXECUTABLE} "-DVIEWS=${VIEW0};${VIEW1}" -DOUT_DIR=${PAIRS_OUT}/two_views
      -P ${CMAKE_CURRENT_SOURCE_DIR}/pairs_results.cmake)
  set_tests_properties(app_pairs_rank_and_register PROPERTIES FIXTURES_REQUIRED register_views TIMEOUT 900)
else()
  message(STATUS "SKIPPED app_pairs_rank_and_register: no python3 to compare the transforms with")
endif()

# Every bad file beside a good view: exit 2, one line (before the cache is looked at).
pcl_tensor_bad_input_tests(app_pairs COMMAND ${PAIRS} ${VIEW0} @INPUT@ --cache ${PAIRS_OUT}/empty_cache --rank 1)
pcl_tensor_case(app_pairs_no_cache 2 COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --rank 1)
pcl_tensor_case(app_pairs_cache_missing 2 COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache /nonexistent/cache --rank 1)
pcl_tensor_case(app_pairs_views_not_prepared 2 COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache ${PAIRS_OUT}/empty_cache --rank 1)
pcl_tensor_case(app_pairs_one_view 2 COMMAND ${PAIRS} ${VIEW0} --cache ${PAIRS_OUT}/empty_cache --rank 1)
pcl_tensor_case(app_pairs_no_mode 2 COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache ${PAIRS_OUT}/empty_cache)
pcl_tensor_case(app_pairs_both_modes 2
                COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache ${PAIRS_OUT}/empty_cache --rank 1 --pairs ${PAIRS_OUT}/p.txt)
pcl_tensor_case(app_pairs_missing_pairs_file 2
                COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache ${PAIRS_OUT}/empty_cache --pairs /nonexistent/pairs.txt)
pcl_tensor_case(app_pairs_json_without_output 2 COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache ${PAIRS_OUT}/empty_cache --rank 1 --json)
pcl_tensor_case(app_pairs_output_folder_missing 2
                COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache ${PAIRS_OUT}/empty_cache --rank 1 -o /nonexistent/pairs.txt)
pcl_tensor_case(app_pairs_param_rank_0 2 COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache ${PAIRS_OUT}/empty_cache --rank 0)
foreach(option "--faces;3" "--dims;0,1,1" "--dims-tolerance;-1" "--viewpoint;1,2" "-j;-1" "--rank-sample;-1")
  string(REGEX REPLACE "[^a-z0-9]+" "_" tag "${option}")
  pcl_tensor_case(app_pairs_param${tag} 2 COMMAND ${PAIRS} ${VIEW0} ${VIEW1} --cache ${PAIRS_OUT}/empty_cache --rank 1 ${option})
endforeach()
pcl_tensor_case(app_pairs_help 0 COMMAND ${PAIRS} --help)
