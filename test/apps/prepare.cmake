# pcl_tensor_prepare: a per-view cache made, kept and repaired (prepare_cache.cmake) on two views of
# the ring pcl_tensor_views renders (register_views), and the bad-input matrix.
set(PREPARE $<TARGET_FILE:pcl_tensor_prepare>)
set(PREPARE_OUT ${APP_OUT}/prepare)

add_test(NAME app_prepare_cache_kept_and_repaired
  COMMAND ${CMAKE_COMMAND} -DAPP=${PREPARE} "-DVIEWS=${REG_VIEWS}/view_00.ply;${REG_VIEWS}/view_01.ply"
    -DCACHE=${PREPARE_OUT}/cache -P ${CMAKE_CURRENT_SOURCE_DIR}/prepare_cache.cmake)
set_tests_properties(app_prepare_cache_kept_and_repaired PROPERTIES FIXTURES_REQUIRED register_views TIMEOUT 900)

# Every bad file beside a good view: exit 2, one line (the good view's entries are written meanwhile).
pcl_tensor_bad_input_tests(app_prepare COMMAND ${PREPARE} ${VIEW0} @INPUT@ --cache ${PREPARE_OUT}/bad_cache)
pcl_tensor_case(app_prepare_no_cache 2 COMMAND ${PREPARE} ${VIEW0})
pcl_tensor_case(app_prepare_no_view 2 COMMAND ${PREPARE} --cache ${PREPARE_OUT}/none)
pcl_tensor_case(app_prepare_cache_is_a_file 2 COMMAND ${PREPARE} ${VIEW0} --cache ${VIEW1})
pcl_tensor_case(app_prepare_dims_without_tensors 2 COMMAND ${PREPARE} ${VIEW0} --cache ${PREPARE_OUT}/p --dims 1,1,1)
foreach(option "--faces;3" "--dims;0,1,1;--tensors" "--viewpoint;1,2" "-j;-1")
  string(REGEX REPLACE "[^a-z0-9]+" "_" tag "${option}")
  pcl_tensor_case(app_prepare_param${tag} 2 COMMAND ${PREPARE} ${VIEW0} --cache ${PREPARE_OUT}/param ${option})
endforeach()
# --only names one of the views given, and picks the views whose tensors to compute.
pcl_tensor_case(app_prepare_only_not_a_view 2 COMMAND ${PREPARE} ${VIEW0} --cache ${PREPARE_OUT}/only --tensors --only ${VIEW1})
pcl_tensor_case(app_prepare_only_without_tensors 2 COMMAND ${PREPARE} ${VIEW0} ${VIEW1} --cache ${PREPARE_OUT}/only --only ${VIEW1})
pcl_tensor_case(app_prepare_help 0 COMMAND ${PREPARE} --help)
