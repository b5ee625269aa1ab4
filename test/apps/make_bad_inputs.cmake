# Writes the bad-input files of the hardening matrix (doc/hardening.md) into OUT_DIR at test time,
# so that no broken file is committed:
#   cmake -DOUT_DIR=... [-DVALID_SCAN=view.ply] -P make_bad_inputs.cmake
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})

function(write_ascii_ply name points)
  list(LENGTH points n)
  string(REPLACE ";" "\n" body "${points}")
  file(WRITE ${OUT_DIR}/${name}.ply
       "ply\nformat ascii 1.0\nelement vertex ${n}\nproperty float x\nproperty float y\nproperty float z\nend_header\n${body}\n")
endfunction()

# files
file(WRITE ${OUT_DIR}/empty.ply "")
file(MAKE_DIRECTORY ${OUT_DIR}/directory.ply)  # a folder named like a scan: open succeeds, read fails
file(WRITE ${OUT_DIR}/truncated.ply "ply\nformat binary_little_endian 1.0\nelement vert")
# A binary PLY whose header promises 1000 vertices while the body holds 10.
string(REPEAT "AAAABBBBCCCC" 10 ten_vertices)
file(WRITE ${OUT_DIR}/wrong_count.ply
     "ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\nproperty float y\nproperty float z\nend_header\n${ten_vertices}")
# Garbage: printable and control bytes (no NUL, which CMake strings cannot hold), fixed seed.
set(codes "")
foreach(c RANGE 1 126)
  list(APPEND codes ${c})
endforeach()
string(ASCII ${codes} alphabet)
string(RANDOM LENGTH 4096 ALPHABET "${alphabet}" RANDOM_SEED 2006 garbage)
file(WRITE ${OUT_DIR}/garbage.ply "${garbage}")
# A file that opens but fails to read (EIO), which root cannot read either, unlike a mode-000 file:
# /proc/self/mem read at offset 0, the unmapped page of whichever process reads it.
file(CREATE_LINK /proc/self/mem ${OUT_DIR}/read_error.ply SYMBOLIC)
# PCL 1.13's PCD reader crashed on these two (the loader now checks the header first).
file(WRITE ${OUT_DIR}/empty.pcd "")
file(WRITE ${OUT_DIR}/garbage.pcd "${garbage}")

# coordinates
write_ascii_ply(all_nonfinite "nan nan nan;inf 0 0;0 -inf 0;nan 1 2;1 2 inf")
set(dups "")
foreach(i RANGE 1 200)
  list(APPEND dups "0.1 0.2 0.3")
endforeach()
write_ascii_ply(duplicates "${dups}")
write_ascii_ply(two_points "0 0 0;1 1 1")
set(line "")
foreach(i RANGE 0 199)
  list(APPEND line "${i} ${i} 1")
endforeach()
write_ascii_ply(collinear "${line}")
# A 40 x 40 unit grid on the plane z = 1 (unorganized: triangulated by Delaunay), and the same grid with
# NaN and Inf points mixed in, which the loader must drop.
set(plane "")
foreach(i RANGE 0 39)
  foreach(j RANGE 0 39)
    list(APPEND plane "${i} ${j} 1")
  endforeach()
endforeach()
write_ascii_ply(coplanar "${plane}")
write_ascii_ply(coplanar_with_nonfinite "${plane};nan 0 1;inf 1 1;0 -inf 1")

# A readable scan made unreadable (mode 000); root reads it anyway, so its tests skip themselves.
if(VALID_SCAN)
  file(COPY ${VALID_SCAN} DESTINATION ${OUT_DIR})
  get_filename_component(valid_name ${VALID_SCAN} NAME)
  file(RENAME ${OUT_DIR}/${valid_name} ${OUT_DIR}/unreadable.ply)
  execute_process(COMMAND chmod 000 ${OUT_DIR}/unreadable.ply)
  # The same scan under another name: "the same view given twice" as two files.
  file(COPY ${VALID_SCAN} DESTINATION ${OUT_DIR}/copy)
endif()
