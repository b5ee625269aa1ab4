# pcl_tensor_prepare --tensors on the same views, run after run: the first writes every entry, the next
# keeps them all, a corrupted entry file is made again alone, and another D remakes the tensors alone.
#   cmake -DAPP=pcl_tensor_prepare "-DVIEWS=a.ply;b.ply" -DCACHE=dir -P prepare_cache.cmake
file(REMOVE_RECURSE ${CACHE})
list(LENGTH VIEWS n_views)
math(EXPR last "${n_views} - 1")

# Run once; EXPECTED holds one "meshes:action tensors:action" per view, e.g. "missing:computed missing:computed".
function(prepare_run step)
  cmake_parse_arguments(ARG "" "" "EXPECTED;OPTIONS" ${ARGN})
  execute_process(COMMAND ${APP} ${VIEWS} --cache ${CACHE} --tensors --viewpoint 0,0,0 --json -j 2 ${ARG_OPTIONS}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${step}: exit code ${code}, expected 0\n${err}")
  endif()
  string(JSON n ERROR_VARIABLE json_error LENGTH "${out}")
  if(json_error OR NOT n EQUAL n_views)
    message(FATAL_ERROR "${step}: expected a JSON array of ${n_views} views, got:\n${out}")
  endif()
  foreach(i RANGE ${last})
    foreach(key meshes meshes_action tensors tensors_action)
      string(JSON ${key} GET "${out}" ${i} ${key})
    endforeach()
    list(GET ARG_EXPECTED ${i} expected)
    if(NOT "${meshes}:${meshes_action} ${tensors}:${tensors_action}" STREQUAL expected)
      message(FATAL_ERROR "${step}: view ${i}: got \"${meshes}:${meshes_action} ${tensors}:${tensors_action}\", "
                          "expected \"${expected}\"\n${out}")
    endif()
  endforeach()
  message(STATUS "${step}: ${ARG_EXPECTED}")
endfunction()

# Flip one byte in the middle of FILE (through dd: CMake strings cannot hold every byte).
function(flip_middle_byte file)
  file(SIZE ${file} size)
  math(EXPR middle "${size} / 2")
  file(READ ${file} old OFFSET ${middle} LIMIT 1 HEX)
  if(old STREQUAL "41")
    file(WRITE ${CACHE}/byte "B")
  else()
    file(WRITE ${CACHE}/byte "A")
  endif()
  execute_process(COMMAND dd if=${CACHE}/byte of=${file} bs=1 seek=${middle} count=1 conv=notrunc status=none
                  RESULT_VARIABLE code)
  file(REMOVE ${CACHE}/byte)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "dd could not patch ${file}")
  endif()
endfunction()

# One "view:kind" file of the cache, by the view's file name (an id starts with the stem).
function(entry_file view kind out)
  get_filename_component(stem ${view} NAME_WE)
  file(GLOB found ${CACHE}/${stem}-*.${kind}.tvc)
  list(LENGTH found n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "expected one ${kind} entry for ${stem}, found: ${found}")
  endif()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

prepare_run("first run" EXPECTED "missing:computed missing:computed" "missing:computed missing:computed")
file(GLOB written RELATIVE ${CACHE} ${CACHE}/*)
list(LENGTH written n_written)
math(EXPR n_expected "2 * ${n_views}")
if(NOT n_written EQUAL n_expected)
  message(FATAL_ERROR "expected ${n_expected} entry files (and no temporary), found: ${written}")
endif()
prepare_run("second run" EXPECTED "valid:kept valid:kept" "valid:kept valid:kept")

list(GET VIEWS 1 second)
entry_file(${second} meshes meshes_entry)
flip_middle_byte(${meshes_entry})
# The meshes are made again under the same key: the tensors made from them stay valid.
prepare_run("view 1's meshes corrupted" EXPECTED "valid:kept valid:kept" "corrupt:computed valid:kept")

list(GET VIEWS 0 first)
entry_file(${first} tensors tensors_entry)
flip_middle_byte(${tensors_entry})
prepare_run("view 0's tensors corrupted" EXPECTED "valid:kept corrupt:computed" "valid:kept valid:kept")

# Another D: every view's tensors are stale, its meshes are kept.
prepare_run("another D" OPTIONS --dims 0.3,0.2,0.1 EXPECTED "valid:kept stale:computed" "valid:kept stale:computed")
prepare_run("another D again" OPTIONS --dims 0.3,0.2,0.1 EXPECTED "valid:kept valid:kept" "valid:kept valid:kept")
