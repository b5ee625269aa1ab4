# The bad-input matrix (doc/hardening.md): every app is run on every bad file, which
# make_bad_inputs.cmake writes at test time, and must exit 2 with one line on stderr; never abort,
# crash or hang. A new app adds one pcl_tensor_bad_input_tests() call.
set(BAD ${APP_OUT}/bad_inputs)
add_test(NAME app_make_bad_inputs
  COMMAND ${CMAKE_COMMAND} -DOUT_DIR=${BAD} -DVALID_SCAN=${REG_VIEWS}/view_01.ply
          -P ${CMAKE_CURRENT_SOURCE_DIR}/make_bad_inputs.cmake)
set_tests_properties(app_make_bad_inputs PROPERTIES FIXTURES_SETUP bad_inputs FIXTURES_REQUIRED register_views)

# Files every app must refuse with exit code 2.
set(PCL_TENSOR_BAD_INPUTS empty.ply directory.ply read_error.ply truncated.ply wrong_count.ply garbage.ply all_nonfinite.ply
    duplicates.ply two_points.ply collinear.ply empty.pcd garbage.pcd)

# pcl_tensor_bad_input_tests(PREFIX COMMAND app args... @INPUT@ args...): one test PREFIX_bad_<file> per
# bad file (@INPUT@ is replaced by its path), a missing file and an unreadable one; all expect exit 2,
# but those listed after NOT_REGISTERED: files that load but hold no usable scan, which an app that
# goes on with the other views reports as not registered (exit 3).
function(pcl_tensor_bad_input_tests prefix)
  cmake_parse_arguments(ARG "" "" "COMMAND;NOT_REGISTERED" ${ARGN})
  foreach(file IN LISTS PCL_TENSOR_BAD_INPUTS ITEMS missing.ply unreadable.ply)
    set(input ${BAD}/${file})
    string(REPLACE "." "_" case "${file}")
    string(REPLACE "@INPUT@" "${input}" command "${ARG_COMMAND}")
    set(unreadable "")
    if(file STREQUAL "unreadable.ply")
      set(unreadable ${input})
    endif()
    set(expected 2)
    if(file IN_LIST ARG_NOT_REGISTERED)
      set(expected 3)
    endif()
    pcl_tensor_app_test(${prefix}_bad_${case} ${expected} UNREADABLE "${unreadable}" COMMAND ${command})
    set_tests_properties(${prefix}_bad_${case} PROPERTIES FIXTURES_REQUIRED "bad_inputs;register_views" TIMEOUT 300)
  endforeach()
endfunction()

# pcl_tensor_case(NAME EXIT COMMAND ...): one more case of the matrix, run once the files exist.
function(pcl_tensor_case name expected_exit)
  pcl_tensor_app_test(${name} ${expected_exit} ${ARGN})
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED "bad_inputs;register_views" TIMEOUT 1500)
endfunction()

set(REGISTER $<TARGET_FILE:pcl_tensor_register>)
set(MESH $<TARGET_FILE:pcl_tensor_mesh>)
set(VIEW0 ${REG_VIEWS}/view_00.ply)
set(VIEW1 ${REG_VIEWS}/view_01.ply)

# pcl_tensor_register: a bad scene, and a bad model, beside a good view.
pcl_tensor_bad_input_tests(app_register_scene COMMAND ${REGISTER} ${VIEW0} @INPUT@)
pcl_tensor_bad_input_tests(app_register_model COMMAND ${REGISTER} @INPUT@ ${VIEW0})
# A plane has no distinctive shape: against a view of the object, and against itself, nothing
# may be reported as registered.
pcl_tensor_case(app_register_coplanar_scene 3 COMMAND ${REGISTER} ${VIEW0} ${BAD}/coplanar.ply)
pcl_tensor_case(app_register_coplanar_twice 3 COMMAND ${REGISTER} ${BAD}/coplanar.ply ${BAD}/coplanar_with_nonfinite.ply)
# The same view twice (one file, and two copies) registers; the pose is checked in test_hardening.
pcl_tensor_case(app_register_same_file_twice 0 COMMAND ${REGISTER} ${VIEW1} ${VIEW1})
pcl_tensor_case(app_register_identical_copies 0 COMMAND ${REGISTER} ${VIEW1} ${BAD}/copy/view_01.ply)
# Parameters out of range.
foreach(option "--grid;0" "--grid;-3" "--faces;3" "--faces;-1" "--tr;1.5" "--tc;2" "--fallback;-0.1" "--nc;0" "--max-hypotheses;-1"
               "--count;all"
               "--dims;0,1,1" "--viewpoint;1,2")
  string(REGEX REPLACE "[^a-z0-9]+" "_" tag "${option}")
  pcl_tensor_case(app_register_param${tag} 2 COMMAND ${REGISTER} ${VIEW0} ${VIEW1} ${option})
endforeach()
# Views of two different objects: the example object against a bunny scan.
if(EXISTS ${BUN000})
  pcl_tensor_case(app_register_different_objects 3 COMMAND ${REGISTER} ${VIEW0} ${BUN000})
endif()
# Determinism: bit-identical transforms over repeated runs with OMP_NUM_THREADS 1 and 2.
add_test(NAME app_register_deterministic
  COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${REGISTER};${VIEW0};${VIEW1};--json" -DEXPECTED_EXIT=0 -DRUNS=4
          -P ${CMAKE_CURRENT_SOURCE_DIR}/same_transform.cmake)
set_tests_properties(app_register_deterministic PROPERTIES FIXTURES_REQUIRED register_views TIMEOUT 900)

# pcl_tensor_mesh: bad scans; a plane (with NaN and Inf points mixed in) is a valid scan.
pcl_tensor_bad_input_tests(app_mesh COMMAND ${MESH} @INPUT@ -o ${APP_OUT}/bad_mesh_out.ply)
pcl_tensor_case(app_mesh_coplanar_with_nonfinite 0 EXPECTED_FILE ${APP_OUT}/plane_reduced.ply
                COMMAND ${MESH} ${BAD}/coplanar_with_nonfinite.ply -o ${APP_OUT}/plane_reduced.ply)
foreach(option "--faces;3" "--faces;0" "--edge-std;nan" "--normal-radius;0" "--normal-radius;-2")
  string(REGEX REPLACE "[^a-z0-9]+" "_" tag "${option}")
  pcl_tensor_case(app_mesh_param${tag} 2 COMMAND ${MESH} ${VIEW0} -o ${APP_OUT}/bad_param_mesh.ply ${option})
endforeach()

# pcl_tensor_views: bad meshes; a point cloud without faces is not a mesh.
pcl_tensor_bad_input_tests(app_views COMMAND $<TARGET_FILE:pcl_tensor_views> @INPUT@ -o ${APP_OUT}/bad_views_out --ring 2 --size 32 32)
pcl_tensor_case(app_views_no_faces 2 COMMAND $<TARGET_FILE:pcl_tensor_views> ${BAD}/coplanar.ply -o ${APP_OUT}/bad_views_out --ring 2)
foreach(option "--ring;0" "--ring;-4" "--noise;-1" "--fov;0" "--fov;180" "--size;-5;10")
  string(REGEX REPLACE "[^a-z0-9]+" "_" tag "${option}")
  pcl_tensor_case(app_views_param${tag} 2 COMMAND $<TARGET_FILE:pcl_tensor_views> example -o ${APP_OUT}/bad_views_out ${option})
endforeach()
