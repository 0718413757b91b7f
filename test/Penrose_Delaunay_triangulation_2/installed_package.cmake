# Installs the package into a fresh prefix, builds an example there as a user
# would (find_package, then the targets), and runs it. The project under
# USER_PROJECT cannot see the source tree, so its headers come from the prefix.
file(REMOVE_RECURSE ${WORK})
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()
run("install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix)
if(NOT EXISTS ${WORK}/prefix/include/CGAL/Penrose_Delaunay_triangulation_2.h)
  message(FATAL_ERROR "the headers were not installed")
endif()
run("configure" ${CMAKE_COMMAND} -S ${USER_PROJECT} -B ${WORK}/build -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX}
                -DCMAKE_PREFIX_PATH=${WORK}/prefix -DEXAMPLE_SOURCE=${EXAMPLE_SOURCE})
run("build" ${CMAKE_COMMAND} --build ${WORK}/build)
run("the example" ${WORK}/build/triangulate_image ${IMAGE} 3000)
if(NOT output MATCHES "^[0-9]+ vertices, [0-9]+ triangles")
  message(FATAL_ERROR "unexpected output: ${output}")
endif()
# A version the package does not promise to be compatible with is refused.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${USER_PROJECT} -B ${WORK}/build_too_new
                        -DCMAKE_PREFIX_PATH=${WORK}/prefix -DEXAMPLE_SOURCE=${EXAMPLE_SOURCE}
                        -DPENROSE_REQUIRED_VERSION=9.0
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(rc EQUAL 0)
  message(FATAL_ERROR "find_package accepted version 9.0 of a 0.1 package")
endif()
