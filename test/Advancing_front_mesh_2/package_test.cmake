# The package as its users get it, run by ctest:
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -DCHECK=afm_check_mesh -P package_test.cmake
# 1. `cmake --install` of the build tree into a prefix, and a consumer
#    project that calls find_package(Advancing_front_mesh_2 COMPONENTS
#    Poisson) against that prefix: configured, built and run,
#    and a consumer of the core package alone, without COMPONENTS: no Eigen
#    looked for, nothing of Eigen on its include path;
# 2. the same consumer against the build tree (Advancing_front_mesh_2_DIR);
# 3. a consumer that adds the repository with add_subdirectory(): the
#    package must define its targets, force no build type and build none of
#    its own tests or examples there.
# Each consumer meshes a square with a hole twice; the meshes go through the
# independent validity checker (afm_check_mesh).
file(REMOVE_RECURSE ${WORK_DIR})
set(consumer ${SOURCE_DIR}/test/Advancing_front_mesh_2/consumer)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(LAST_OUT "${out}" PARENT_SCOPE)
endfunction()

function(consumer name)
  set(dir ${WORK_DIR}/${name})
  run_step("configuring the ${name} consumer" ${CMAKE_COMMAND} -S ${consumer} -B ${dir} -G "${GENERATOR}" ${ARGN})
  if(NOT LAST_OUT MATCHES "found Advancing_front_mesh_2 [0-9]+\\.[0-9]+\\.[0-9]+ in " AND NOT name STREQUAL "subdirectory")
    message(FATAL_ERROR "the ${name} consumer did not report the package it found:\n${LAST_OUT}")
  endif()
  run_step("building the ${name} consumer" ${CMAKE_COMMAND} --build ${dir} --target afm_consumer)
  run_step("running the ${name} consumer" ${dir}/afm_consumer ${dir})
  message(STATUS "${name}: ${LAST_OUT}")
  # every mesh made is checked by the independent validity checker
  foreach(mesh uniform graded)
    run_step("checking the ${name} consumer's ${mesh} mesh" ${CHECK} ${dir}/square.poly ${dir}/${mesh}.off)
  endforeach()
endfunction()

run_step("installing" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
foreach(f include/CGAL/Advancing_front_mesher_2.h share/Advancing_front_mesh_2/cmake/Advancing_front_mesh_2Config.cmake)
  if(NOT EXISTS ${WORK_DIR}/prefix/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
consumer(installed -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
consumer(installed_core_only -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DAFM_CONSUMER_CORE_ONLY=ON)
consumer(build_tree -DAdvancing_front_mesh_2_DIR=${BUILD_DIR})
consumer(subdirectory -DAFM_CONSUMER_MODE=subdirectory -DAFM_SOURCE_DIR=${SOURCE_DIR})
