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
# material. Each package is rebuilt when its material, its tuning file (<stem>.tuning.json, when
# it has one, or once one is added), the scene, matc, or any template/chunk its
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
    # The depfile names the tuning file only once a compile has read it, so one added beside the
    # material later would not rebuild its package: the glob finds it at configure time, and
    # CONFIGURE_DEPENDS re-runs the glob on every build, reconfiguring when the file appears.
    get_filename_component(folder "${source}" DIRECTORY)
    file(GLOB tuning CONFIGURE_DEPENDS "${folder}/${name}.tuning.json")
    add_custom_command(
      OUTPUT ${package}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${FA_OUTPUT_DIR}
      COMMAND Facet::matc compile ${source} -o ${package} --depfile ${package}.d ${options}
      DEPENDS ${source} ${tuning} ${depends} Facet::matc
      DEPFILE ${package}.d
      COMMENT "Compiling Facet material ${name}"
      VERBATIM)
    list(APPEND packages ${package})
  endforeach()
  add_custom_target(${FA_TARGET} ALL DEPENDS ${packages})
endfunction()

# facet_add_textures: encode PNG images into ASTC KTX2 textures (with their mip levels) at build
# time, through `matc texture` (facet-texture, docs/texture-format.md).
#
#   facet_add_textures(TARGET <name>
#                      USAGE <color|normal|data>          # how the material samples them
#                      TEXTURES <a.png> [<b.png> ...]
#                      [BLOCK <4x4|5x5|6x6|8x8>]           # default: the usage's (color 6x6, normal 5x5, data 6x6)
#                      [QUALITY <fastest|fast|medium|thorough|exhaustive>]
#                      [OUTPUT_DIR <dir>])                 # default: ${CMAKE_CURRENT_BINARY_DIR}/textures
#
# Adds the custom target <name> (built by `all`) producing <OUTPUT_DIR>/<image>.ktx2 per image,
# rebuilt when its image or matc changes. The output is the same bytes on every run.
function(facet_add_textures)
  cmake_parse_arguments(FT "" "TARGET;USAGE;BLOCK;QUALITY;OUTPUT_DIR" "TEXTURES" ${ARGN})
  if(NOT FT_TARGET OR NOT FT_USAGE OR NOT FT_TEXTURES)
    message(FATAL_ERROR "facet_add_textures: TARGET, USAGE and TEXTURES are required")
  endif()
  if(FT_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "facet_add_textures: unknown arguments ${FT_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET Facet::matc)
    message(FATAL_ERROR "facet_add_textures: the Facet::matc target is missing (find_package(Facet) first)")
  endif()
  if(NOT FT_OUTPUT_DIR)
    set(FT_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/textures)
  endif()
  get_filename_component(FT_OUTPUT_DIR "${FT_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  set(options --usage ${FT_USAGE})
  if(FT_BLOCK)
    list(APPEND options --block ${FT_BLOCK})
  endif()
  if(FT_QUALITY)
    list(APPEND options --quality ${FT_QUALITY})
  endif()
  # In Facet's own tree matc runs the facet-texture built beside it; installed, it sits there.
  set(tool Facet::matc)
  if(TARGET facet-texture)
    list(APPEND tool facet-texture)
  endif()

  set(outputs)
  foreach(image IN LISTS FT_TEXTURES)
    get_filename_component(source "${image}" ABSOLUTE)
    get_filename_component(name "${image}" NAME_WE)
    set(output ${FT_OUTPUT_DIR}/${name}.ktx2)
    add_custom_command(
      OUTPUT ${output}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${FT_OUTPUT_DIR}
      COMMAND Facet::matc texture ${source} -o ${output} ${options}
      DEPENDS ${source} ${tool}
      COMMENT "Encoding Facet texture ${name}"
      VERBATIM)
    list(APPEND outputs ${output})
  endforeach()
  add_custom_target(${FT_TARGET} ALL DEPENDS ${outputs})
endfunction()
