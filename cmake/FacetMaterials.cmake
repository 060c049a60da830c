# facet_add_materials: compile Facet materials (.mat) into packages (.matpkg) at build time.
#
#   facet_add_materials(TARGET <name>
#                       MATERIALS <a.mat> [<b.mat> ...]
#                       [TIERS <reference|high|mid|low> ...]
#                       [SCENE <scene.json>]            # build only what this scene asks for
#                       [POINT_LIGHTS <0|1|2|4> ...]
#                       [OUTPUT_DIR <dir>])             # default: ${CMAKE_CURRENT_BINARY_DIR}/materials
#
# Adds the custom target <name> (built by `all`) producing <OUTPUT_DIR>/<material>.matpkg per
# material. Each package is rebuilt when its material, the scene, matc, or any template/chunk its
# variants used changes: matc writes a depfile (matc compile --depfile) that Ninja and Make read.
# Works in Facet's own tree and through find_package(Facet) (docs/build-integration.md).
function(facet_add_materials)
  cmake_parse_arguments(FA "" "TARGET;SCENE;OUTPUT_DIR" "MATERIALS;TIERS;POINT_LIGHTS" ${ARGN})
  if(NOT FA_TARGET OR NOT FA_MATERIALS)
    message(FATAL_ERROR "facet_add_materials: TARGET and MATERIALS are required")
  endif()
  if(FA_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "facet_add_materials: unknown arguments ${FA_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET Facet::matc)
    message(FATAL_ERROR "facet_add_materials: the Facet::matc target is missing (find_package(Facet) first)")
  endif()
  if(NOT FA_OUTPUT_DIR)
    set(FA_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/materials)
  endif()
  get_filename_component(FA_OUTPUT_DIR "${FA_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")

  set(options)
  set(depends)
  if(FA_TIERS)
    list(JOIN FA_TIERS "," tiers)
    list(APPEND options --tiers ${tiers})
  endif()
  if(FA_POINT_LIGHTS)
    list(JOIN FA_POINT_LIGHTS "," lights)
    list(APPEND options --point-lights ${lights})
  endif()
  if(FA_SCENE)
    get_filename_component(scene "${FA_SCENE}" ABSOLUTE)
    list(APPEND options --scene ${scene})
    list(APPEND depends ${scene})
  endif()

  set(packages)
  foreach(material IN LISTS FA_MATERIALS)
    get_filename_component(source "${material}" ABSOLUTE)
    get_filename_component(name "${material}" NAME_WE)
    set(package ${FA_OUTPUT_DIR}/${name}.matpkg)
    add_custom_command(
      OUTPUT ${package}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${FA_OUTPUT_DIR}
      COMMAND Facet::matc compile ${source} -o ${package} --depfile ${package}.d ${options}
      DEPENDS ${source} ${depends} Facet::matc
      DEPFILE ${package}.d
      COMMENT "Compiling Facet material ${name}"
      VERBATIM)
    list(APPEND packages ${package})
  endforeach()
  add_custom_target(${FA_TARGET} ALL DEPENDS ${packages})
endfunction()
