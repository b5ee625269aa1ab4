# pcl_tensor_model --cache, run after run: the first computes and writes the model and poses; a second
# with nothing new replays the first (the same report, nothing computed); a changed output is made again.
#   cmake -DAPP=pcl_tensor_model "-DVIEWS=a.ply;b.ply;c.ply" -DOUT=dir -P model_cache.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

function(model_run step expected_replay)
  execute_process(COMMAND ${APP} ${VIEWS} --cache ${OUT}/cache --viewpoint 0,0,0 -o ${OUT}/model.ply -j 2 ${ARGN}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${step}: exit code ${code}, expected 0\n${out}\n${err}")
  endif()
  string(FIND "${out}" "Nothing new since the last run" replayed)
  if(expected_replay AND replayed EQUAL -1)
    message(FATAL_ERROR "${step}: expected the run to be replayed from the cache, got:\n${out}")
  elseif(NOT expected_replay AND NOT replayed EQUAL -1)
    message(FATAL_ERROR "${step}: expected the run to be made, it was replayed:\n${out}")
  endif()
  file(SHA256 ${OUT}/model.conf conf_hash)
  set(conf_hash ${conf_hash} PARENT_SCOPE)
  set(run_output "${out}" PARENT_SCOPE)
  message(STATUS "${step}: ${out}")
endfunction()

model_run ("first run" FALSE)
set(first_conf ${conf_hash})
model_run ("second run, nothing new" TRUE)
if(NOT conf_hash STREQUAL first_conf)
  message(FATAL_ERROR "the replayed run changed the poses")
endif()
# Poses edited by hand are not those the run wrote: the run is made again (its pairs from the cache).
file(APPEND ${OUT}/model.conf "# edited\n")
model_run ("third run, an output changed" FALSE)
if(NOT conf_hash STREQUAL first_conf)
  message(FATAL_ERROR "the run made again from the cache gave other poses")
endif()
# Made again, with every pair's ranking score from the cache: none is computed.
file(APPEND ${OUT}/model.conf "# edited\n")
model_run ("fourth run, an output changed, JSON" FALSE --json)
string(JSON scored GET "${run_output}" candidate_pairs_scored)
string(JSON candidates GET "${run_output}" candidate_pairs)
if(NOT scored EQUAL 0 OR candidates EQUAL 0)
  message(FATAL_ERROR "expected every one of the ${candidates} ranking scores from the cache, ${scored} were computed")
endif()
