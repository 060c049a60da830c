# ConsumerProject test (cmake -P): installs this build's Facet package to a prefix, configures
# examples/consumer against it with find_package(Facet), builds it, and checks the depfile-driven
# rebuilds: nothing to do when nothing changed; touching one material rebuilds only its package.
# Inputs: -DFACET_BINARY_DIR -DFACET_SOURCE_DIR -DWORK (a scratch folder, recreated).
cmake_minimum_required(VERSION 3.25)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
set(ENV{XDG_CACHE_HOME} ${WORK}/cache)  # matc's variant cache stays in the scratch folder
run(${CMAKE_COMMAND} --install ${FACET_BINARY_DIR} --prefix ${WORK}/install)
foreach(f bin/matc lib/cmake/Facet/FacetConfig.cmake lib/cmake/Facet/FacetMaterials.cmake)
  if(NOT EXISTS ${WORK}/install/${f})
    message(FATAL_ERROR "install did not produce ${f}")
  endif()
endforeach()

# The consumer and its materials are copied, so touching them leaves the source tree alone.
file(COPY ${FACET_SOURCE_DIR}/examples/consumer/CMakeLists.txt DESTINATION ${WORK}/src)
file(COPY ${FACET_SOURCE_DIR}/examples/materials/red_plastic.mat ${FACET_SOURCE_DIR}/examples/materials/brushed_gold.mat
     DESTINATION ${WORK}/materials)
run(${CMAKE_COMMAND} -S ${WORK}/src -B ${WORK}/build -G Ninja -DCMAKE_PREFIX_PATH=${WORK}/install
    -DFACET_CONSUMER_MATERIALS_DIR=${WORK}/materials)
run(${CMAKE_COMMAND} --build ${WORK}/build)
foreach(name red_plastic brushed_gold)
  if(NOT EXISTS ${WORK}/build/packages/${name}.matpkg OR NOT EXISTS ${WORK}/build/packages/${name}.matpkg.d)
    message(FATAL_ERROR "the consumer build did not write ${name}.matpkg and its depfile")
  endif()
endforeach()

run(${CMAKE_COMMAND} --build ${WORK}/build)
if(NOT out MATCHES "no work to do")
  message(FATAL_ERROR "a second build with nothing changed did work:\n${out}")
endif()

file(TOUCH ${WORK}/materials/red_plastic.mat)
run(${CMAKE_COMMAND} --build ${WORK}/build)
if(NOT out MATCHES "Compiling Facet material red_plastic" OR out MATCHES "brushed_gold")
  message(FATAL_ERROR "touching red_plastic.mat should rebuild exactly its package:\n${out}")
endif()
message(STATUS "consumer project: built, no-op rebuild, one-material rebuild all as expected")
