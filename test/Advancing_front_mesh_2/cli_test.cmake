# End-to-end test of afmesh_2's documented interface, run by ctest as
# cmake -DAFMESH=... -DMAKE_INPUT=... -DCHECK=... -DWORK_DIR=... -P cli_test.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(expect_exit code)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${WORK_DIR})
  if(NOT rc EQUAL ${code})
    message(FATAL_ERROR "expected exit ${code}, got ${rc}: ${ARGN}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(LAST_OUT "${out}" PARENT_SCOPE)
  set(LAST_ERR "${err}" PARENT_SCOPE)
endfunction()

expect_exit(0 ${MAKE_INPUT} square-with-hole ${WORK_DIR}/sq.poly)
expect_exit(0 ${AFMESH} ${WORK_DIR}/sq.poly --size 0.03 -o ${WORK_DIR}/sq.off -o ${WORK_DIR}/sq.vtu
            -o ${WORK_DIR}/sq.svg -o ${WORK_DIR}/sq.msh -o ${WORK_DIR}/sq.node --stats)
if(NOT LAST_OUT MATCHES "^{\"input\".*\"triangles\": [0-9]+.*\"largest_front\".*}")
  message(FATAL_ERROR "--stats did not print one JSON object: ${LAST_OUT}")
endif()
foreach(f sq.off sq.vtu sq.svg sq.msh sq.node sq.ele)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "missing output ${f}")
  endif()
endforeach()
expect_exit(0 ${CHECK} ${WORK_DIR}/sq.poly ${WORK_DIR}/sq.off)

foreach(kernel epeck exact-rational)
  expect_exit(0 ${AFMESH} ${WORK_DIR}/sq.poly --size 0.08 -o ${WORK_DIR}/sq_${kernel}.off --kernel ${kernel})
  expect_exit(0 ${CHECK} ${WORK_DIR}/sq.poly ${WORK_DIR}/sq_${kernel}.off)
endforeach()

# bad usage: exit 2
expect_exit(2 ${AFMESH})
expect_exit(2 ${AFMESH} ${WORK_DIR}/sq.poly -o ${WORK_DIR}/x.off)
expect_exit(2 ${AFMESH} ${WORK_DIR}/sq.poly --size -1 -o ${WORK_DIR}/x.off)
expect_exit(2 ${AFMESH} ${WORK_DIR}/sq.poly --size 0.1 -o ${WORK_DIR}/x.xyz)
expect_exit(2 ${AFMESH} ${WORK_DIR}/sq.poly --size 0.1 --kernel float)
expect_exit(2 ${AFMESH} ${WORK_DIR}/sq.poly --size 0.1 --no-such-option)

# invalid input: exit 1 and one line naming the file and line
file(WRITE ${WORK_DIR}/bad.poly "4 2 0 0\n1 0 0\n2 1 0\n3 1 x1\n4 0 1\n")
expect_exit(1 ${AFMESH} ${WORK_DIR}/bad.poly --size 0.1 -o ${WORK_DIR}/x.off)
if(NOT LAST_ERR MATCHES "^afmesh_2: error: .*bad.poly:4: ")
  message(FATAL_ERROR "unexpected error line: ${LAST_ERR}")
endif()
expect_exit(1 ${AFMESH} ${WORK_DIR}/missing.poly --size 0.1 -o ${WORK_DIR}/x.off)
file(WRITE ${WORK_DIR}/cross.poly "4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n2 0\n1 1 2\n2 3 4\n0\n")
expect_exit(1 ${AFMESH} ${WORK_DIR}/cross.poly --size 0.1 -o ${WORK_DIR}/x.off)
if(NOT LAST_ERR MATCHES "^afmesh_2: error: .*cross.poly: segment 2 .*crosses")
  message(FATAL_ERROR "unexpected error line: ${LAST_ERR}")
endif()
message(STATUS "afmesh_2 command-line interface: all checks passed")
