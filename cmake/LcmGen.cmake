# SPDX-License-Identifier: Apache-2.0
# lcm-gen support for Debian's LCM 1.3.1, which ships no CMake package config
# (no CMake config, broken pkg-config without glib). Generates C++ headers (INTERFACE target) and a
# Java jar of all types so that lcm-spy can decode every message.

function(find_lcm)
  find_program(LCM_GEN_EXECUTABLE lcm-gen REQUIRED)
  find_path(LCM_INCLUDE_DIR lcm/lcm-cpp.hpp REQUIRED)
  find_library(LCM_LIBRARY lcm REQUIRED)
  find_file(LCM_JAR lcm.jar PATHS /usr/share/java /usr/local/share/java)
  set(LCM_JAR "${LCM_JAR}" PARENT_SCOPE)
  if(NOT TARGET lcm::lcm)
    add_library(lcm::lcm UNKNOWN IMPORTED GLOBAL)
    set_target_properties(lcm::lcm PROPERTIES
      IMPORTED_LOCATION "${LCM_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${LCM_INCLUDE_DIR}")
  endif()
endfunction()

# The generated file names follow from the package and struct names, scanned at configure time.
function(_lcm_type_paths out_var)
  set(paths)
  foreach(f IN LISTS ARGN)
    file(READ "${f}" text)
    string(REGEX REPLACE "//[^\n]*" "" text "${text}")
    string(REGEX REPLACE "/\\*([^*]|\\*[^/])*\\*/" "" text "${text}")
    set(pkg "")
    if(text MATCHES "package[ \t\r\n]+([A-Za-z0-9_.]+)[ \t\r\n]*;")
      string(REPLACE "." "/" pkg "${CMAKE_MATCH_1}/")
    endif()
    string(REGEX MATCHALL "(struct|enum)[ \t\r\n]+[A-Za-z0-9_]+" decls "${text}")
    foreach(d IN LISTS decls)
      string(REGEX REPLACE "(struct|enum)[ \t\r\n]+" "" name "${d}")
      list(APPEND paths "${pkg}${name}")
    endforeach()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${f}")
  endforeach()
  set(${out_var} ${paths} PARENT_SCOPE)
endfunction()

function(lcm_generate_cpp target)
  cmake_parse_arguments(ARG "" "" "FILES" ${ARGN})
  set(outdir "${CMAKE_CURRENT_BINARY_DIR}/${target}")
  _lcm_type_paths(types ${ARG_FILES})
  list(TRANSFORM types PREPEND "${outdir}/")
  list(TRANSFORM types APPEND ".hpp" OUTPUT_VARIABLE headers)
  add_custom_command(
    OUTPUT ${headers}
    COMMAND ${LCM_GEN_EXECUTABLE} --cpp --cpp-std=c++11 --cpp-hpath "${outdir}" ${ARG_FILES}
    DEPENDS ${ARG_FILES}
    COMMENT "lcm-gen (C++) for ${target}" VERBATIM)
  add_library(${target} INTERFACE ${headers})
  # SYSTEM: lcm-gen 1.3.1 compares a void* with a function pointer in nested types' _computeHash,
  # which -Wpedantic rejects; the generated code is not ours to fix, our own code stays checked.
  target_include_directories(${target} SYSTEM INTERFACE "${outdir}")
  target_link_libraries(${target} INTERFACE lcm::lcm)
endfunction()

function(lcm_generate_jar target)
  cmake_parse_arguments(ARG "" "" "FILES" ${ARGN})
  find_package(Java 1.8 REQUIRED COMPONENTS Development)
  set(srcdir "${CMAKE_CURRENT_BINARY_DIR}/${target}_java")
  set(clsdir "${CMAKE_CURRENT_BINARY_DIR}/${target}_classes")
  set(jar "${CMAKE_CURRENT_BINARY_DIR}/${target}.jar")
  _lcm_type_paths(types ${ARG_FILES})
  list(TRANSFORM types PREPEND "${srcdir}/")
  list(TRANSFORM types APPEND ".java" OUTPUT_VARIABLE java_files)
  add_custom_command(
    OUTPUT ${java_files}
    COMMAND ${LCM_GEN_EXECUTABLE} --java --jpath "${srcdir}" ${ARG_FILES}
    DEPENDS ${ARG_FILES}
    COMMENT "lcm-gen (Java) for ${target}" VERBATIM)
  add_custom_command(
    OUTPUT "${jar}"
    COMMAND ${CMAKE_COMMAND} -E rm -rf "${clsdir}"
    COMMAND ${CMAKE_COMMAND} -E make_directory "${clsdir}"
    COMMAND ${Java_JAVAC_EXECUTABLE} -nowarn --release 8 -cp "${LCM_JAR}" -d "${clsdir}" ${java_files}
    COMMAND ${Java_JAR_EXECUTABLE} cf "${jar}" -C "${clsdir}" .
    DEPENDS ${java_files}
    COMMENT "javac + jar -> ${target}.jar" VERBATIM)
  add_custom_target(${target} ALL DEPENDS "${jar}")
  set_target_properties(${target} PROPERTIES JAR_FILE "${jar}")
endfunction()
