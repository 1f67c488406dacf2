# SPDX-License-Identifier: Apache-2.0
# The layers of the house: each folder of code is one layer, named by the include prefix its
# headers are reached by ("core/geometry", "bus", "contactd", ...). A layer may include its own
# headers and those of the layers it is declared to depend on (and theirs, transitively), never any
# other: services never include each other, and the core's folders stand in one order, because a
# layer can only depend on layers declared before it. The test `structure.layers`
# (tests/structure/check_layers.cmake) reads every #include of every layer against this.
#
#   wrc_layer(<prefix> <folder> [DEPENDS <prefix>...])
#     declares the layer; <folder> is searched recursively for .hpp and .cpp files.
#   wrc_core_layer(<name> [DEPENDS <name>...])
#     a folder services/core/<name> as layer "core/<name>" and its static library wrc_<name>
#     (an interface library when it has no .cpp), linked to the libraries of its dependencies.

set(WRC_LAYERS "" CACHE INTERNAL "declared layers, in order")

function(wrc_layer prefix folder)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "DEPENDS")
  set(allowed "${prefix}")
  foreach(dependency IN LISTS arg_DEPENDS)
    if(NOT dependency IN_LIST WRC_LAYERS)
      message(FATAL_ERROR "layer ${prefix}: depends on '${dependency}', which is not declared before it")
    endif()
    list(APPEND allowed ${dependency} ${WRC_LAYER_ALLOWED_${dependency}})
  endforeach()
  list(REMOVE_DUPLICATES allowed)
  set(WRC_LAYER_ALLOWED_${prefix} "${allowed}" CACHE INTERNAL "")
  set(WRC_LAYER_FOLDER_${prefix} "${folder}" CACHE INTERNAL "")
  set(layers ${WRC_LAYERS} ${prefix})
  set(WRC_LAYERS "${layers}" CACHE INTERNAL "declared layers, in order")
endfunction()

function(wrc_core_layer name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "DEPENDS")
  set(folder "${CMAKE_CURRENT_SOURCE_DIR}/${name}")
  set(prefixes "")
  set(libraries "")
  foreach(dependency IN LISTS arg_DEPENDS)
    list(APPEND prefixes "core/${dependency}")
    list(APPEND libraries "wrc_${dependency}")
  endforeach()
  wrc_layer("core/${name}" "${folder}" DEPENDS ${prefixes})
  file(GLOB sources CONFIGURE_DEPENDS "${folder}/*.cpp")
  if(sources)
    add_library(wrc_${name} STATIC ${sources})
    target_include_directories(wrc_${name} PUBLIC "${WRC_SERVICES_DIR}")
    target_link_libraries(wrc_${name} PUBLIC ${libraries})
    wrc_warnings(wrc_${name})
  else()
    add_library(wrc_${name} INTERFACE)
    target_include_directories(wrc_${name} INTERFACE "${WRC_SERVICES_DIR}")
    target_link_libraries(wrc_${name} INTERFACE ${libraries})
  endif()
endfunction()

# Writes the declared layers for the structure test: one line per layer,
# "<prefix>|<folder>|<allowed prefixes, ;-separated>".
function(wrc_write_layers file)
  set(text "")
  foreach(prefix IN LISTS WRC_LAYERS)
    string(APPEND text "${prefix}|${WRC_LAYER_FOLDER_${prefix}}|${WRC_LAYER_ALLOWED_${prefix}}\n")
  endforeach()
  file(WRITE "${file}" "${text}")
endfunction()
