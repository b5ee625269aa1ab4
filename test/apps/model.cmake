# pcl_tensor_model: the whole job on synthetic views of the built-in object (register_views: a ring
# of 12 views 30 degrees apart), a view of another object among them, and the bad-input matrix.
set(MODEL $<TARGET_FILE:pcl_tensor_model>)
set(MODEL_OUT ${APP_OUT}/model)
file(MAKE_DIRECTORY ${MODEL_OUT})
set(RING_VIEWS "")
foreach(i 00 01 02 03 04 05 06 07 08 09 10 11)
  list(APPEND RING_VIEWS ${REG_VIEWS}/view_${i}.ply)
endforeach()

# Every view registered, the loop closed, the model and its poses written.
pcl_tensor_case(app_model_ring 0 EXPECTED_FILE ${MODEL_OUT}/ring.conf
                COMMAND ${MODEL} ${RING_VIEWS} --loop --viewpoint 0,0,0 -o ${MODEL_OUT}/ring.ply --json)

# The same poses on 1, 2 and 4 threads (views' meshes and tensors, and references tried at once), on
# four views of the ring, the third given before the second so that one view is tried against two.
set(THREAD_VIEWS ${REG_VIEWS}/view_00.ply ${REG_VIEWS}/view_02.ply ${REG_VIEWS}/view_01.ply ${REG_VIEWS}/view_03.ply)
add_test(NAME app_model_same_poses_across_threads
  COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${MODEL};${THREAD_VIEWS};--viewpoint;0,0,0;-o;${MODEL_OUT}/threads.ply;--json"
    "-DTHREADS=1;2;4" -DPATTERN=pose -DEXPECTED_EXIT=0 -P ${CMAKE_CURRENT_SOURCE_DIR}/same_across_threads.cmake)
set_tests_properties(app_model_same_poses_across_threads PROPERTIES FIXTURES_REQUIRED register_views TIMEOUT 900)

# A view of another object (other bumps, 0.7 times the size) between two views of the example: it is
# refused (exit 3, one line naming it) and the model is still built from the other two.
set(OTHER_VIEWS ${APP_OUT}/model_other_views)
add_test(NAME app_model_make_other_views
  COMMAND $<TARGET_FILE:pcl_tensor_views> example --example-seed 7 --example-size 0.14 -o ${OTHER_VIEWS}
          --ring 12 --size 300 300)
set_tests_properties(app_model_make_other_views PROPERTIES FIXTURES_SETUP other_views TIMEOUT 300)
pcl_tensor_case(app_model_wrong_view_refused 3 EXPECTED_FILE ${MODEL_OUT}/wrong.ply
                COMMAND ${MODEL} ${REG_VIEWS}/view_00.ply ${OTHER_VIEWS}/view_01.ply ${REG_VIEWS}/view_01.ply
                        --viewpoint 0,0,0 -o ${MODEL_OUT}/wrong.ply)
set_tests_properties(app_model_wrong_view_refused PROPERTIES FIXTURES_REQUIRED "register_views;other_views")

# Usage errors and bad files: exit 2 with one line, before any work. A file that loads but cannot be
# meshed (all points duplicates, or on a line) is one unusable view of many: it is named, left out, and
# the model is built from the others (exit 3).
pcl_tensor_bad_input_tests(app_model COMMAND ${MODEL} ${VIEW0} @INPUT@ -o ${MODEL_OUT}/bad.ply
                           NOT_REGISTERED duplicates.ply collinear.ply)
pcl_tensor_case(app_model_no_output 2 COMMAND ${MODEL} ${VIEW0} ${VIEW1})
pcl_tensor_case(app_model_one_view 2 COMMAND ${MODEL} ${VIEW0} -o ${MODEL_OUT}/one.ply)
pcl_tensor_case(app_model_output_folder_missing 2 COMMAND ${MODEL} ${VIEW0} ${VIEW1} -o /nonexistent/model.ply)
pcl_tensor_case(app_model_missing_pairs_file 2 COMMAND ${MODEL} ${VIEW0} ${VIEW1} -o ${MODEL_OUT}/p.ply --pairs /nonexistent/pairs.txt)
foreach(option "--voxel;-1" "--dims;1;2" "--dims-tolerance;-1" "--faces;3" "--rank-sample;-1")
  string(REGEX REPLACE "[^a-z0-9]+" "_" tag "${option}")
  pcl_tensor_case(app_model_param${tag} 2 COMMAND ${MODEL} ${VIEW0} ${VIEW1} -o ${MODEL_OUT}/param.ply ${option})
endforeach()
pcl_tensor_case(app_model_help 0 COMMAND ${MODEL} --help)
# A view whose name a .conf line cannot hold is refused before any view is read.
pcl_tensor_case(app_model_view_name_with_space 2 COMMAND ${MODEL} ${VIEW0} "/nonexistent/view one.ply" -o ${MODEL_OUT}/space.ply)

# The --json report with file names that need escaping (a quote, a backslash, non-ASCII characters).
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME app_model_json_names
    COMMAND ${CMAKE_COMMAND} -DMODEL=${MODEL} -DPYTHON=${Python3_EXECUTABLE} -DOUT_DIR=${MODEL_OUT}/json_names
      "-DVIEWS=${REG_VIEWS}/view_00.ply;${REG_VIEWS}/view_01.ply;${REG_VIEWS}/view_02.ply"
      -P ${CMAKE_CURRENT_SOURCE_DIR}/json_names.cmake)
  set_tests_properties(app_model_json_names PROPERTIES FIXTURES_REQUIRED register_views TIMEOUT 600)
else()
  message(STATUS "SKIPPED app_model_json_names: no python3 to check the JSON with")
endif()

# --cache: a re-run with nothing new is replayed, one whose outputs changed is made again, the same poses.
add_test(NAME app_model_cache_rerun
  COMMAND ${CMAKE_COMMAND} -DAPP=${MODEL} "-DVIEWS=${REG_VIEWS}/view_00.ply;${REG_VIEWS}/view_01.ply;${REG_VIEWS}/view_02.ply"
    -DOUT=${MODEL_OUT}/cache_rerun -P ${CMAKE_CURRENT_SOURCE_DIR}/model_cache.cmake)
set_tests_properties(app_model_cache_rerun PROPERTIES FIXTURES_REQUIRED register_views TIMEOUT 900)

# --keep-poses: a model extended with a view; the old views keep their poses, their voxels from the cache.
add_test(NAME app_model_keep_poses
  COMMAND ${CMAKE_COMMAND} -DAPP=${MODEL} "-DVIEWS=${REG_VIEWS}/view_00.ply;${REG_VIEWS}/view_01.ply;${REG_VIEWS}/view_02.ply"
    -DNEW=${REG_VIEWS}/view_03.ply -DOUT=${MODEL_OUT}/keep_poses -P ${CMAKE_CURRENT_SOURCE_DIR}/model_keep_poses.cmake)
set_tests_properties(app_model_keep_poses PROPERTIES FIXTURES_REQUIRED register_views TIMEOUT 900)
pcl_tensor_case(app_model_missing_keep_poses 2 COMMAND ${MODEL} ${VIEW0} ${VIEW1} -o ${MODEL_OUT}/k.ply
                --keep-poses /nonexistent/poses.conf)

# Two views of each of two objects: two models (the second beside the first as NAME_part2), exit 3 and
# one line per view of the second model naming it.
add_test(NAME app_model_two_objects_two_models
  COMMAND ${MODEL} ${REG_VIEWS}/view_00.ply ${OTHER_VIEWS}/view_00.ply ${REG_VIEWS}/view_01.ply ${OTHER_VIEWS}/view_01.ply
          --viewpoint 0,0,0 -o ${MODEL_OUT}/two.ply)
set_tests_properties(app_model_two_objects_two_models PROPERTIES FIXTURES_REQUIRED "register_views;other_views" TIMEOUT 900
  PASS_REGULAR_EXPRESSION "in a separate model: [^\n]*model_other_views/view_00.ply: [^\n]*two_part2.ply\npcl_tensor_model: in a separate model: [^\n]*model_other_views/view_01.ply: [^\n]*two_part2.ply")
pcl_tensor_case(app_model_missing_pairs_results 2 COMMAND ${MODEL} ${VIEW0} ${VIEW1} -o ${MODEL_OUT}/r.ply
                --pairs-results /nonexistent/results.jsonl)
pcl_tensor_case(app_model_cache_is_a_file 2 COMMAND ${MODEL} ${VIEW0} ${VIEW1} -o ${MODEL_OUT}/c.ply --cache ${VIEW0})
