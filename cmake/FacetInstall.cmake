# `cmake --install`: matc (and facet-eval, which `matc eval` runs), the runtime an app embeds, its
# public headers and the CMake package that finds them (FacetConfig.cmake.in). Included from the
# top-level CMakeLists.txt once every target exists.
#
# Components, one export file each, all in namespace Facet::
#   (always)  matc                  FacetTargets.cmake
#   core      runtime_core          materials, instances, frame description, IBL, PNG; with what it
#                                   links: package, package_checks, ibl, ibl_embedded_dfg,
#                                   shader_abi (headers), permutations (variant keys, linked by
#                                   package)
#   vulkan    runtime_vulkan        the Vulkan backend (createVulkanBackend, vulkan_backend.h)
#   gl        runtime_gl            the GL backend (createGlBackend)
#   gltf      runtime_gltf          glTF meshes (tinygltf; links scene: its JSON reader, path rule)
#   scene     scene                 the scene reader (scene.h's parse/load functions; JSON)
# The scene's types (scene_types: scene.h, post_settings.h, texture_sampler.h) are core's: its frames are made from them.
# The libraries are static, so their private dependencies (zstd, xxHash, SPIRV-Tools, SPIRV-Cross, ...) are
# exported as link-only dependencies, and FacetConfig.cmake finds them again in the app's build.
include(CMakePackageConfigHelpers)
set(FACET_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Facet)

set(FACET_COMPONENTS core vulkan gl gltf scene)
# facet_warnings: linked PRIVATE by every library, so an exported link-only entry; its flags are
# BUILD_INTERFACE only, so the exported target is empty.
set(FACET_COMPONENT_TARGETS_core facet_warnings facet_shader_abi facet_permutations facet_package
    facet_package_checks facet_scene_types facet_ibl facet_ibl_embedded_dfg facet_ktx2 facet_astc facet_runtime_core)
set(FACET_COMPONENT_TARGETS_vulkan facet_runtime_vulkan)
set(FACET_COMPONENT_TARGETS_gl facet_runtime_gl)
set(FACET_COMPONENT_TARGETS_gltf facet_mikktspace facet_runtime_gltf)
set(FACET_COMPONENT_TARGETS_scene facet_scene)

# Public headers per component, as they sit under <folder>/include/facet/<folder>/ in the source
# tree (runtime/ and scene/), installed under include/facet/<folder>/. Only these are installed; a
# header listed here that includes one not installed fails the consumer test
# (tests/examples/consumer_project.cmake compiles every installed header).
set(FACET_RUNTIME_HEADERS_core content_hash.h frame_eviction.h frame_graph.h render_backend.h render_path.h
    texture_checks.h compressed_texture.h environment.h exposure.h image_texture.h material.h material_instance.h mesh.h png.h
    preshader.h color_grading.h vignette.h vertex_packing.h mesh_optimize.h)
# The Scene type environment.h takes and the post settings; their reader is the scene component.
set(FACET_SCENE_HEADERS_core scene.h post_settings.h texture_sampler.h)
set(FACET_RUNTIME_HEADERS_vulkan vulkan_backend.h)
set(FACET_RUNTIME_HEADERS_gl gl_backend.h)
set(FACET_RUNTIME_HEADERS_gltf gltf_mesh.h)

# How FacetConfig.cmake finds each outside target the exported libraries link: "target|how|what",
# how = package (find_package(what)) or pkg-config (pkg_check_modules(<prefix> IMPORTED_TARGET what),
# which names the target PkgConfig::<prefix>). A library linking something not listed here stops
# the configure: add it, or the installed package would fail to link in an app.
set(FACET_EXTERNAL_DEPENDENCIES
  "PkgConfig::ZSTD|pkg-config|libzstd"
  "PkgConfig::XXHASH|pkg-config|libxxhash"
  "PkgConfig::JPEG|pkg-config|libjpeg"
  "PkgConfig::OSMESA|pkg-config|osmesa"
  "PkgConfig::EGL|pkg-config|egl"
  "PkgConfig::GLESV2|pkg-config|glesv2"
  "SPIRV-Tools-static|package|SPIRV-Tools"
  "PkgConfig::SPIRV_CROSS_C|pkg-config|spirv-cross-c-shared"
  "Vulkan::Vulkan|package|Vulkan"
  "TinyGLTF::TinyGLTF|package|TinyGLTF"
  "meshoptimizer::meshoptimizer|package|meshoptimizer"
  "nlohmann_json::nlohmann_json|package|nlohmann_json"
  "Threads::Threads|package|Threads"
  "astcenc::astcenc|package|astcenc")

# The outside dependencies of one component's targets, as "target|how|what" entries.
function(facet_component_dependencies component out)
  set(found)
  foreach(target IN LISTS FACET_COMPONENT_TARGETS_${component})
    get_target_property(direct ${target} LINK_LIBRARIES)
    get_target_property(interface ${target} INTERFACE_LINK_LIBRARIES)
    foreach(item IN LISTS direct interface)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
      if(NOT item OR item MATCHES "NOTFOUND$" OR item MATCHES "^\\$<BUILD_INTERFACE:" OR item MATCHES "^facet_")
        continue()
      endif()
      set(known FALSE)
      foreach(entry IN LISTS FACET_EXTERNAL_DEPENDENCIES)
        if(entry MATCHES "^([^|]+)\\|" AND CMAKE_MATCH_1 STREQUAL item)
          list(APPEND found "${entry}")
          set(known TRUE)
        endif()
      endforeach()
      if(NOT known)
        message(FATAL_ERROR "${target} (installed component '${component}') links '${item}', which "
                            "FacetConfig.cmake does not know how to find: add it to FACET_EXTERNAL_DEPENDENCIES "
                            "in cmake/FacetInstall.cmake")
      endif()
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES found)
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# The public headers are C++20 (std::span, defaulted comparisons): an app compiles them as such.
foreach(target facet_shader_abi facet_package facet_package_checks facet_scene_types facet_ibl facet_runtime_core)
  target_compile_features(${target} INTERFACE cxx_std_20)
endforeach()

set_target_properties(facet_warnings PROPERTIES EXPORT_NAME warnings)
set_target_properties(facet_shader_abi PROPERTIES EXPORT_NAME shader_abi)
set_target_properties(facet_permutations PROPERTIES EXPORT_NAME permutations)
set_target_properties(facet_package PROPERTIES EXPORT_NAME package)
set_target_properties(facet_package_checks PROPERTIES EXPORT_NAME package_checks)
set_target_properties(facet_ibl PROPERTIES EXPORT_NAME ibl)
set_target_properties(facet_ibl_embedded_dfg PROPERTIES EXPORT_NAME ibl_embedded_dfg)
set_target_properties(facet_ktx2 PROPERTIES EXPORT_NAME ktx2)
set_target_properties(facet_astc PROPERTIES EXPORT_NAME astc)
set_target_properties(facet_runtime_core PROPERTIES EXPORT_NAME runtime_core)
set_target_properties(facet_runtime_vulkan PROPERTIES EXPORT_NAME runtime_vulkan)
set_target_properties(facet_runtime_gl PROPERTIES EXPORT_NAME runtime_gl)
set_target_properties(facet_runtime_gltf PROPERTIES EXPORT_NAME runtime_gltf)
set_target_properties(facet_mikktspace PROPERTIES EXPORT_NAME mikktspace)
set_target_properties(facet_scene_types PROPERTIES EXPORT_NAME scene_types)
set_target_properties(facet_scene PROPERTIES EXPORT_NAME scene)

install(TARGETS matc EXPORT FacetTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# `matc eval` runs the facet-eval beside it (matc/run_helper_program.cpp): a program, not an export.
install(TARGETS facet-eval RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# `matc texture` runs the facet-texture beside it in the same way (texture/tool/).
install(TARGETS facet-texture RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# and `matc import` the facet-gltf-import beside it (runtime/gltf_import/).
install(TARGETS facet-gltf-import RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT FacetTargets NAMESPACE Facet:: DESTINATION ${FACET_CMAKE_INSTALL_DIR})

set(FACET_CONFIG_COMPONENT_DEPENDENCIES "")
foreach(component IN LISTS FACET_COMPONENTS)
  string(SUBSTRING ${component} 0 1 first)
  string(TOUPPER ${first} first)
  string(SUBSTRING ${component} 1 -1 rest)
  set(export Facet${first}${rest}Targets)  # FacetCoreTargets, FacetVulkanTargets, ...
  install(TARGETS ${FACET_COMPONENT_TARGETS_${component}} EXPORT ${export}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(EXPORT ${export} NAMESPACE Facet:: DESTINATION ${FACET_CMAKE_INSTALL_DIR})
  foreach(folder IN ITEMS runtime scene)
    string(TOUPPER ${folder} list)
    list(TRANSFORM FACET_${list}_HEADERS_${component} PREPEND ${PROJECT_SOURCE_DIR}/${folder}/include/facet/${folder}/
         OUTPUT_VARIABLE headers)
    if(headers)
      install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/facet/${folder})
    endif()
  endforeach()
  facet_component_dependencies(${component} deps)
  string(APPEND FACET_CONFIG_COMPONENT_DEPENDENCIES "set(_facet_dependencies_${component} \"${deps}\")\n")
endforeach()
# Every header of the libraries the core exports is public (package reader and checks, IBL maths,
# the ABI).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/abi/include/ ${PROJECT_SOURCE_DIR}/ibl/include/
                  ${PROJECT_SOURCE_DIR}/package/include/ ${PROJECT_SOURCE_DIR}/package/checks/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The paths apps included before the public headers moved under facet/<library>/, for one release:
# each forwards to its header's new path (tests/examples/consumer_old_include_paths.cpp compiles them).
# Only installed: Facet's own sources use the new paths.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cmake/forwarding_headers/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

configure_package_config_file(cmake/FacetConfig.cmake.in ${PROJECT_BINARY_DIR}/FacetConfig.cmake
  INSTALL_DESTINATION ${FACET_CMAKE_INSTALL_DIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/FacetConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/FacetConfig.cmake ${PROJECT_BINARY_DIR}/FacetConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FacetMaterials.cmake DESTINATION ${FACET_CMAKE_INSTALL_DIR})
