# pcl_tensor_model --json with view and output paths holding a quote, a backslash and non-ASCII
# characters (no white space: a .conf line cannot hold it): the report must be JSON that python3 -m json.tool accepts, and must give the names back.
#   cmake -DMODEL=app -DPYTHON=python3 -DVIEWS="a.ply;b.ply;c.ply" -DOUT_DIR=dir -P json_names.cmake
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
set(names "view\"quoted\".ply" "back\\slash.ply" "vue_été_视图.ply")
set(copies "")
foreach(view name IN ZIP_LISTS VIEWS names)
  file(COPY_FILE ${view} "${OUT_DIR}/${name}")
  list(APPEND copies "${OUT_DIR}/${name}")
endforeach()
execute_process(COMMAND ${MODEL} ${copies} --viewpoint 0,0,0 -o "${OUT_DIR}/model\"q\"é.ply" --json
                RESULT_VARIABLE code OUTPUT_FILE ${OUT_DIR}/report.json ERROR_VARIABLE err TIMEOUT 600)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "pcl_tensor_model exited ${code}, expected 0:\n${err}")
endif()
execute_process(COMMAND ${PYTHON} -m json.tool ${OUT_DIR}/report.json RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  file(READ ${OUT_DIR}/report.json report)
  message(FATAL_ERROR "python3 -m json.tool refused the report (${code}): ${err}\n${report}")
endif()
execute_process(COMMAND ${PYTHON} -c
  "import json, sys; r = json.load(open(sys.argv[1], encoding='utf-8')); got = [v['file'] for v in r['views']]; sys.exit(0 if got == sys.argv[2:] else 'names: %r, expected %r' % (got, sys.argv[2:]))"
  ${OUT_DIR}/report.json ${copies} RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the report does not give the file names back: ${err}")
endif()
message(STATUS "valid JSON with the names given back")
