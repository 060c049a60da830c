# ConsumerProject test (cmake -P): installs this build's Facet package to a prefix, configures
# examples/consumer against it with find_package(Facet COMPONENTS vulkan), builds it, and checks
# the install (runtime libraries, headers, one export file per component; the installed `matc eval`
# runs the installed facet-eval), the textures facet_add_textures encodes (the installed
# facet-texture), that every installed header compiles from the prefix (no private
# header included), that an app including the headers' old paths still compiles
# (consumer_old_include_paths.cpp), the depfile-driven rebuilds
# (nothing to do when nothing changed; touching one material, or adding its tuning file, rebuilds
# only its package), and
# runs the consumer's program: it lists both packages and renders one frame with the runtime on
# lavapipe (FACET_VK_VALIDATION from the test's environment: a validation error fails it).
# Inputs: -DFACET_BINARY_DIR -DFACET_SOURCE_DIR -DWORK (a scratch folder, recreated),
# -DCXX (the compiler Facet was built with), -DSANITIZE (ON: Facet was built with ASan + UBSan).
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
foreach(f bin/matc bin/facet-eval bin/facet-texture lib/cmake/Facet/FacetConfig.cmake lib/cmake/Facet/FacetMaterials.cmake
        lib/cmake/Facet/FacetCoreTargets.cmake lib/cmake/Facet/FacetVulkanTargets.cmake
        lib/cmake/Facet/FacetGlTargets.cmake lib/cmake/Facet/FacetGltfTargets.cmake
        lib/cmake/Facet/FacetSceneTargets.cmake
        lib/libfacet_runtime_core.a lib/libfacet_runtime_vulkan.a lib/libfacet_runtime_gl.a
        lib/libfacet_runtime_gltf.a lib/libfacet_package.a lib/libfacet_package_checks.a
        include/facet/package/checks.h include/facet/scene/scene.h include/facet/runtime/render_backend.h
        include/facet/runtime/vulkan_backend.h include/facet/runtime/material.h include/facet/package/package_reader.h
        include/facet/abi/shader_abi.h include/facet/ibl/dfg_lut.h include/facet/render_backend.h)
  if(NOT EXISTS ${WORK}/install/${f})
    message(FATAL_ERROR "install did not produce ${f}")
  endif()
endforeach()

# The installed matc runs the installed facet-eval beside it for `matc eval`.
run(${WORK}/install/bin/matc eval --help)
if(NOT out MATCHES "Usage: ${WORK}/install/bin/matc eval \\[OPTIONS\\] input")
  message(FATAL_ERROR "the installed matc eval did not run the installed facet-eval:\n${out}")
endif()

# The consumer and its materials are copied, so touching them leaves the source tree alone.
file(COPY ${FACET_SOURCE_DIR}/examples/consumer/CMakeLists.txt ${FACET_SOURCE_DIR}/examples/consumer/main.cpp
     DESTINATION ${WORK}/src)
file(COPY ${FACET_SOURCE_DIR}/examples/materials/red_plastic.mat ${FACET_SOURCE_DIR}/examples/materials/brushed_gold.mat
     DESTINATION ${WORK}/materials)
file(COPY ${FACET_SOURCE_DIR}/examples/scenes/textures/tiles.png DESTINATION ${WORK}/textures)
set(compile_options -DCMAKE_CXX_COMPILER=${CXX})
find_program(CCACHE ccache)
if(CCACHE)
  list(APPEND compile_options -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE})
endif()
if(SANITIZE)
  list(APPEND compile_options "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
       "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()
run(${CMAKE_COMMAND} -S ${WORK}/src -B ${WORK}/build -G Ninja -DCMAKE_PREFIX_PATH=${WORK}/install
    -DFACET_CONSUMER_MATERIALS_DIR=${WORK}/materials -DFACET_CONSUMER_TEXTURES_DIR=${WORK}/textures
    -DFACET_CONSUMER_CHECK_HEADERS=ON
    -DFACET_CONSUMER_CHECK_SOURCES=${CMAKE_CURRENT_LIST_DIR}/consumer_old_include_paths.cpp ${compile_options})
run(${CMAKE_COMMAND} --build ${WORK}/build)
foreach(name red_plastic brushed_gold)
  if(NOT EXISTS ${WORK}/build/packages/${name}.matpkg OR NOT EXISTS ${WORK}/build/packages/${name}.matpkg.d)
    message(FATAL_ERROR "the consumer build did not write ${name}.matpkg and its depfile")
  endif()
endforeach()

# facet_add_textures ran the installed matc texture: the same bytes as the example's KTX2.
file(READ ${WORK}/build/textures/tiles.ktx2 built HEX)
file(READ ${FACET_SOURCE_DIR}/examples/scenes/textures/tiles.ktx2 committed HEX)
if(NOT built STREQUAL committed)
  message(FATAL_ERROR "the consumer's textures/tiles.ktx2 differs from examples/scenes/textures/tiles.ktx2")
endif()

run(${CMAKE_COMMAND} --build ${WORK}/build)
if(NOT out MATCHES "no work to do")
  message(FATAL_ERROR "a second build with nothing changed did work:\n${out}")
endif()

file(TOUCH ${WORK}/materials/red_plastic.mat)
run(${CMAKE_COMMAND} --build ${WORK}/build)
if(NOT out MATCHES "Compiling Facet material red_plastic" OR out MATCHES "brushed_gold")
  message(FATAL_ERROR "touching red_plastic.mat should rebuild exactly its package:\n${out}")
endif()

# A tuning file added beside a material (matc tune --write) rebuilds exactly its package, with its tiers.
file(READ ${WORK}/build/packages/red_plastic.matpkg presets HEX)
# (written, as matc tune --write writes it: file(COPY) would keep the source's older time)
file(READ ${FACET_SOURCE_DIR}/examples/materials/red_plastic.tuning.json tuning)
file(WRITE ${WORK}/materials/red_plastic.tuning.json "${tuning}")
run(${CMAKE_COMMAND} --build ${WORK}/build)
file(READ ${WORK}/build/packages/red_plastic.matpkg tuned HEX)
if(NOT out MATCHES "Compiling Facet material red_plastic" OR out MATCHES "brushed_gold" OR tuned STREQUAL presets)
  message(FATAL_ERROR "adding red_plastic.tuning.json should rebuild exactly its package, tuned:\n${out}")
endif()

# The app's program against the packages its build made. Under ASan the driver's per-load bytes
# would be reported as leaks from an unloaded module (runtime/vulkan/keep_driver_loaded_under_sanitizers.cpp
# explains; Facet's own tests hold the driver loaded instead), so leak detection is off for it.
if(SANITIZE)
  set(ENV{ASAN_OPTIONS} "detect_leaks=0")
endif()
run(${WORK}/build/facet-consumer --render ${WORK}/sphere.png
    ${WORK}/build/packages/red_plastic.matpkg ${WORK}/build/packages/brushed_gold.matpkg)
foreach(line "material red_plastic \\(lit, opaque\\)" "parameter roughness: float" "variant high.dir0:"
        "variant high.dir1:" "variant low.dir0:" "variant low.dir1:" "material brushed_gold"
        "rendered red_plastic with vulkan \\(high.dir1\\)")
  if(NOT out MATCHES "${line}")
    message(FATAL_ERROR "facet-consumer's output lacks '${line}':\n${out}")
  endif()
endforeach()
if(NOT EXISTS ${WORK}/sphere.png)
  message(FATAL_ERROR "facet-consumer did not write its frame")
endif()
message(STATUS "consumer project: installed runtime and headers, built, no-op rebuild, one-material rebuild, "
               "listed and rendered, all as expected")
