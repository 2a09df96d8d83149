# Builds and runs tests/install/consumer twice: against the source tree (add_subdirectory) and
# against an installed copy (find_package). Invoked by ctest with SOURCE_DIR and WORK_DIR set.
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(consumer ${SOURCE_DIR}/tests/install/consumer)
# The consumer builds unoptimised (no build type: no -O, and photon's assertions on): this test is
# about the package (targets, include paths, links), and -O0 halves the compile of its header-only
# render; examples/cornell.cpp is the optimised header-only build.
set(consumer_build_type -DCMAKE_BUILD_TYPE=)

# 1. add_subdirectory. The consumer does not render here: the render's headers are the source
# tree's, which examples/cornell.cpp already compiles header-only (optimised); step 2 renders
# from the installed headers.
step(${CMAKE_COMMAND} -S ${consumer} -B ${WORK_DIR}/subdir ${consumer_build_type} -DPHOTON_SOURCE_DIR=${SOURCE_DIR}
     -DCONSUMER_RENDER=OFF)
step(${CMAKE_COMMAND} --build ${WORK_DIR}/subdir)
step(${WORK_DIR}/subdir/consumer)
step(${WORK_DIR}/subdir/consumer_obj ${SOURCE_DIR}/tests/data/tetrahedron.obj)

# 2. install, then find_package
step(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/photon -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_TESTS=OFF
     -DPHOTON_BUILD_EXAMPLES=OFF -DPHOTON_BUILD_CLI=OFF -DPHOTON_INSTALL=ON -DCMAKE_INSTALL_PREFIX=${WORK_DIR}/prefix)
step(${CMAKE_COMMAND} --install ${WORK_DIR}/photon)
step(${CMAKE_COMMAND} -S ${consumer} -B ${WORK_DIR}/installed ${consumer_build_type} -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
step(${CMAKE_COMMAND} --build ${WORK_DIR}/installed)
step(${WORK_DIR}/installed/consumer)
step(${WORK_DIR}/installed/consumer_obj ${SOURCE_DIR}/tests/data/tetrahedron.obj)
