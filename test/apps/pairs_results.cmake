# pcl_tensor_pairs on two views: refused (exit 2, one line naming the view) before pcl_tensor_prepare
# --tensors filled the cache; then --rank 1 gives the pair, and --pairs a results file whose transform is
# pcl_tensor_register's on the same files (within 1e-4: pcl_tensor_register computes the scene's tensors
# in batches as it needs them, pcl_tensor_pairs takes them all from the cache).
#   cmake -DPREPARE=app -DPAIRS=app -DREGISTER=app -DPYTHON=python3 "-DVIEWS=a.ply;b.ply" -DOUT_DIR=dir -P pairs_results.cmake
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
set(CACHE_DIR ${OUT_DIR}/cache)
file(MAKE_DIRECTORY ${CACHE_DIR})
list(GET VIEWS 0 first)
list(GET VIEWS 1 second)

function(run_tool step expected_exit)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  if(NOT code EQUAL expected_exit)
    message(FATAL_ERROR "${step}: exit code ${code}, expected ${expected_exit}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# Nothing in the cache yet: one line that names the first view and says what to run.
run_tool("before pcl_tensor_prepare" 2 ${PAIRS} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0 --rank 1)
string(STRIP "${err}" err)
if(err MATCHES "\n" OR NOT err MATCHES "${first}" OR NOT err MATCHES "pcl_tensor_prepare --tensors")
  message(FATAL_ERROR "expected one line naming ${first} and pcl_tensor_prepare --tensors, got:\n${err}")
endif()
# --only reads the other views' extents from the cache: without their meshes there, it names the first.
run_tool("--only before the other views' meshes" 2 ${PREPARE} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0 --tensors
         --only ${second})
if(NOT err MATCHES "${first}")
  message(FATAL_ERROR "expected ${first}, whose meshes are missing, to be named, got:\n${err}")
endif()
# Meshes alone are not enough.
run_tool("meshes only" 0 ${PREPARE} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0)
run_tool("without tensors" 2 ${PAIRS} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0 --rank 1)
if(NOT err MATCHES "tensors")
  message(FATAL_ERROR "expected the missing tensors to be named, got:\n${err}")
endif()
# The tensors one view at a time (--only), as one job per view would: D from both views' extents, so
# that a run over all of them keeps every entry.
foreach(view ${VIEWS})
  run_tool("pcl_tensor_prepare --tensors --only ${view}" 0
           ${PREPARE} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0 --tensors --only ${view} --json)
  string(JSON n LENGTH "${out}")
  string(JSON tensors GET "${out}" 0 tensors_action)
  if(NOT n EQUAL 1 OR NOT tensors STREQUAL "computed")
    message(FATAL_ERROR "--only ${view}: expected that view's tensors computed, alone, got:\n${out}")
  endif()
endforeach()
run_tool("pcl_tensor_prepare --tensors" 0 ${PREPARE} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0 --tensors --json)
if(out MATCHES "computed")
  message(FATAL_ERROR "the entries --only wrote are not those of a run over all views:\n${out}")
endif()

# --rank 1: the only pair, in view_pairs_io's format.
run_tool("--rank 1" 0 ${PAIRS} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0 --rank 1 -o ${OUT_DIR}/pairs.txt -j 2)
file(STRINGS ${OUT_DIR}/pairs.txt pairs REGEX "^[^#]")
string(REPLACE ";" " " expected_pair "${VIEWS}")
if(NOT pairs STREQUAL expected_pair)
  message(FATAL_ERROR "--rank 1 wrote \"${pairs}\", expected \"${expected_pair}\"")
endif()

# --pairs: one result line, registered, with pcl_tensor_register's transform.
run_tool("--pairs" 0 ${PAIRS} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0 --pairs ${OUT_DIR}/pairs.txt
         -o ${OUT_DIR}/results.jsonl --json)
string(JSON registered GET "${out}" registered)
if(NOT registered EQUAL 1)
  message(FATAL_ERROR "expected the pair registered, got:\n${out}")
endif()
run_tool("pcl_tensor_register" 0 ${REGISTER} ${VIEWS} --viewpoint 0,0,0 --json)
file(WRITE ${OUT_DIR}/register.json "${out}")
execute_process(COMMAND ${PYTHON} -c [=[
import json, sys
lines = [l for l in open(sys.argv[1]) if l.strip()]
if len(lines) != 1:
    sys.exit("expected one result line, got %d" % len(lines))
result = json.loads(lines[0])
expected = json.load(open(sys.argv[2]))["transform"]
got = result["report"]["transform"]
if result["report"]["status"] != "registered" or max(abs(a - b) for a, b in zip(got, expected)) > 1e-4:
    sys.exit("results file: %s %r, pcl_tensor_register: %r" % (result["report"]["status"], got, expected))
]=] ${OUT_DIR}/results.jsonl ${OUT_DIR}/register.json RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "${err}")
endif()

# The same results on stdout, and on one thread: byte for byte but the timings.
run_tool("--pairs to stdout" 0 ${PAIRS} ${VIEWS} --cache ${CACHE_DIR} --viewpoint 0,0,0 --pairs ${OUT_DIR}/pairs.txt -j 1)
file(READ ${OUT_DIR}/results.jsonl written)
string(REGEX REPLACE "\"timings_ms\":{[^}]*}" "" out "${out}")
string(REGEX REPLACE "\"timings_ms\":{[^}]*}" "" written "${written}")
if(NOT out STREQUAL written)
  message(FATAL_ERROR "stdout:\n${out}\ndiffers from -o:\n${written}")
endif()
message(STATUS "the pair ranked, registered as pcl_tensor_register registers it, and written the same to -o and stdout")
