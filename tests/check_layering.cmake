cmake_minimum_required(VERSION 3.18)
# No folder reaches into another's private files, and every include looks down.
#   cmake -DSOURCE_DIR=<project> -P tests/check_layering.cmake
#
# 1. The runtime's layers (runtime/CMakeLists.txt) only look down: a source or public header of
#    a layer includes asperity headers of its own layer or of the layers it links, never above.
# 2. Every folder includes only the components it links (generator: the runtime; topography: the
#    runtime and the generator; the commands and Python: the public headers only), and the
#    runtime's internals (runtime/include/asperity/detail/) only where it is one of the
#    project's own libraries, tests or benchmarks.
# 2a. The topography's parts (topography/CMakeLists.txt) only look down: input < statistics <
#    verdict < contact < report. A part's sources and its public headers (each header of
#    include/asperity/topography/ is one part's, listed below) include the headers of their own
#    part and of the parts below, never above; the generator from contact up.
# 3. A quoted include without "asperity/" is a header of the file's own folder; a topography
#    part's file may also include "PART/name.hpp" of a part at or below its own; the commands
#    also share apps/common/; tests, benchmarks and fuzzers may use the seams named below.
# 4. The public face: every header under include/ is in cmake/public_headers.cmake once, and a
#    public header includes only public headers.
set(layer_core integrals model layout curve asymptotic instruction_set error contact_scales number_text
    interrupt output record_fields
    contact_law contact_law_registry law_combination)
set(layer_table table table_data table_file table_writer contact_curves_data)
set(layer_physics contact contact_model physical_state_fields inverse surface persson separation_datum plausibility
    contact_curves)
set(layer_scene scene scene_curves)
set(layer_fe_export pressure_overclosure)
set(layer_c_api asperity)
set(runtime_layers core table physics scene fe_export c_api)

set(allowed_core core detail)
set(allowed_table core table detail)
set(allowed_physics core table physics detail)
set(allowed_scene core table scene detail)
set(allowed_fe_export core table physics fe_export detail)
set(allowed_c_api core table physics scene fe_export c_api detail)
set(runtime_public core table physics scene fe_export c_api)
set(allowed_generator ${runtime_public} detail generator)

# The topography's parts from the bottom up, each public header's part (by the part that
# implements it), and what each part's sources and headers may include: the parts at or below.
set(topography_parts input statistics verdict contact report)
set(part_input height_map height_map_io surface_formats units)
set(part_statistics statistics summits leveling synthetic self_affine)
set(part_verdict distribution_fit goodness_of_fit surrogates surface_tests surface_verdict)
set(part_contact summit_contact contact_comparison law_contact persson_contact exact_contact exact_contact_table)
set(part_report analysis surface_report exact_contact_report next_steps)
set(topography_groups "")
foreach(part IN LISTS topography_parts)
  list(APPEND topography_groups topography_${part})
  set(public_topography_${part} ${runtime_public} ${topography_groups})
  set(allowed_topography_${part} ${public_topography_${part}} detail)
  if(part STREQUAL "contact" OR part STREQUAL "report")
    list(APPEND allowed_topography_${part} generator)  # the scene and law tables of the fits
  endif()
endforeach()
set(allowed_commands ${runtime_public} generator ${topography_groups})
set(allowed_python ${runtime_public} generator ${topography_groups})
set(allowed_white_box ${runtime_public} detail generator ${topography_groups})

# The private headers tests, benchmarks and fuzzers may use (their CMake targets say so too:
# asperity_runtime_test_seams, asperity_topography_test_seams).
# A seam is included by its name, or (the topography's) as "PART/name.hpp".
set(seams runtime/table/replace_file.hpp runtime/core/kernel/kernels.hpp runtime/core/kernel/exp_x86.hpp
    topography/input/md5.hpp
    topography/verdict/spacing_fit.hpp topography/verdict/vector_math.hpp topography/statistics/fft.hpp
    apps/asperity/eval_csv.hpp
    apps/asperity/law_options.hpp tests/reference.hpp
    tests/accuracy_harness.hpp)

set(failures "")
function(header_group header out)
  if(header MATCHES "^detail/")
    set(${out} detail PARENT_SCOPE)
    return()
  elseif(header MATCHES "^generator/")
    set(${out} generator PARENT_SCOPE)
    return()
  elseif(header MATCHES "^topography/(.+)\\.hpp$")
    set(name "${CMAKE_MATCH_1}")
    foreach(part IN LISTS topography_parts)
      if(name IN_LIST part_${part})
        set(${out} topography_${part} PARENT_SCOPE)
        return()
      endif()
    endforeach()
    set(${out} unknown PARENT_SCOPE)
    return()
  endif()
  foreach(layer IN LISTS runtime_layers)
    foreach(name IN LISTS layer_${layer})
      if(header STREQUAL "${name}.hpp" OR header STREQUAL "${name}.h")
        set(${out} ${layer} PARENT_SCOPE)
        return()
      endif()
    endforeach()
  endforeach()
  set(${out} unknown PARENT_SCOPE)
endfunction()

# check_file(FILE GROUP ALLOWED...): FILE's includes against the groups ALLOWED
function(check_file file group)
  set(allowed ${ARGN})
  get_filename_component(folder "${file}" DIRECTORY)
  file(RELATIVE_PATH relative_folder "${SOURCE_DIR}" "${folder}")
  file(STRINGS "${file}" lines REGEX "^#include \"")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" header "${line}")
    if(header MATCHES "^asperity/")
      string(REGEX REPLACE "^asperity/" "" header "${header}")
      header_group("${header}" included)
      if(included STREQUAL "unknown")
        string(APPEND failures "\n  ${file}: asperity/${header} belongs to no layer or component (tests/check_layering.cmake)")
      elseif(NOT included IN_LIST allowed)
        string(APPEND failures "\n  ${file} (${group}) includes asperity/${header} (${included})")
      endif()
    elseif(header MATCHES "\\.\\./")
      string(APPEND failures "\n  ${file} includes ${header}: another folder's file by a relative path")
    elseif(EXISTS "${folder}/${header}")
      # its own folder's
    elseif(group MATCHES "^topography_" AND header MATCHES "^([a-z_]+)/[^/]+$"
           AND EXISTS "${SOURCE_DIR}/topography/${header}")
      # another topography part's private header, as "PART/name.hpp"
      set(included "topography_${CMAKE_MATCH_1}")
      if(NOT included IN_LIST allowed)
        string(APPEND failures "\n  ${file} (${group}) includes \"${header}\" (${included})")
      endif()
    elseif(group STREQUAL "commands" AND EXISTS "${SOURCE_DIR}/apps/common/${header}")
      # what the commands share
    elseif(group STREQUAL "white_box" AND header MATCHES "^(default_table_config|CLI/|pybind11|gtest|benchmark|hwy)")
    elseif(header MATCHES "^default_table_config.hpp$" AND relative_folder STREQUAL "runtime/table")
      # generated into the build tree (runtime/CMakeLists.txt)
    else()
      set(seam "")
      foreach(candidate IN LISTS seams)
        get_filename_component(name "${candidate}" NAME)
        if(name STREQUAL header OR candidate STREQUAL "topography/${header}")
          set(seam "${candidate}")
        endif()
      endforeach()
      if(NOT (group STREQUAL "white_box" AND seam))
        string(APPEND failures "\n  ${file} (${group}) includes \"${header}\": not its own folder's${seam}")
      endif()
    endif()
  endforeach()
  set(failures "${failures}" PARENT_SCOPE)
endfunction()

function(check_folder folder group)
  if(NOT IS_DIRECTORY "${SOURCE_DIR}/${folder}")
    string(APPEND failures "\n  ${folder}/ does not exist: tests/check_layering.cmake names a folder that moved")
    set(failures "${failures}" PARENT_SCOPE)
    return()
  endif()
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${folder}/*.cpp" "${SOURCE_DIR}/${folder}/*.hpp"
       "${SOURCE_DIR}/${folder}/*.h" "${SOURCE_DIR}/${folder}/*.c")
  foreach(file IN LISTS sources)
    check_file("${file}" ${group} ${ARGN})
  endforeach()
  set(failures "${failures}" PARENT_SCOPE)
endfunction()

# 1. the runtime's layers, their sources and public headers; its internal headers as core
foreach(layer IN LISTS runtime_layers)
  check_folder(runtime/${layer} ${layer} ${allowed_${layer}})
  foreach(name IN LISTS layer_${layer})
    foreach(extension hpp h)
      if(EXISTS "${SOURCE_DIR}/include/asperity/${name}.${extension}")
        check_file("${SOURCE_DIR}/include/asperity/${name}.${extension}" ${layer} ${allowed_${layer}})
      endif()
    endforeach()
  endforeach()
endforeach()
check_folder(runtime/include core ${allowed_core})
# 2, 3. every other folder
check_folder(tablegen generator ${allowed_generator})
check_folder(include/asperity/generator generator ${runtime_public} generator)
# 2a. the topography's parts, their sources and public headers; nothing outside a part
foreach(part IN LISTS topography_parts)
  check_folder(topography/${part} topography_${part} ${allowed_topography_${part}})
  foreach(name IN LISTS part_${part})
    if(EXISTS "${SOURCE_DIR}/include/asperity/topography/${name}.hpp")
      check_file("${SOURCE_DIR}/include/asperity/topography/${name}.hpp" topography_${part}
                 ${public_topography_${part}})
    endif()
  endforeach()
endforeach()
file(GLOB_RECURSE topography_files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/topography/*.cpp"
     "${SOURCE_DIR}/topography/*.hpp" "${SOURCE_DIR}/include/asperity/topography/*.hpp")
foreach(file IN LISTS topography_files)
  if(file MATCHES "^include/asperity/topography/(.+)\\.hpp$")
    header_group("topography/${CMAKE_MATCH_1}.hpp" part)
    if(part STREQUAL "unknown")
      string(APPEND failures "\n  ${file} is no part's: name it in a part_* list (tests/check_layering.cmake)")
    endif()
  elseif(NOT file MATCHES "^topography/([a-z_]+)/" OR NOT CMAKE_MATCH_1 IN_LIST topography_parts)
    string(APPEND failures "\n  ${file} is in no part's folder (topography/CMakeLists.txt: ${topography_parts})")
  endif()
endforeach()
check_folder(apps commands ${allowed_commands})
check_folder(python/src python ${allowed_python})
foreach(folder tests bench fuzz examples)
  check_folder(${folder} white_box ${allowed_white_box})
endforeach()

# 4. the public face: listed once each, and needing nothing unlisted
include("${SOURCE_DIR}/cmake/public_headers.cmake")
set(listed ${ASPERITY_RUNTIME_HEADERS} ${ASPERITY_GENERATOR_HEADERS} ${ASPERITY_TOPOGRAPHY_HEADERS}
    ${ASPERITY_FORTRAN_SOURCES})
file(GLOB_RECURSE present RELATIVE "${SOURCE_DIR}/include/asperity" "${SOURCE_DIR}/include/asperity/*")
foreach(header IN LISTS present)
  list(FIND listed "${header}" at)
  if(at EQUAL -1)
    string(APPEND failures "\n  include/asperity/${header} is not in cmake/public_headers.cmake (installed headers are listed)")
  endif()
endforeach()
foreach(header IN LISTS listed)
  if(NOT EXISTS "${SOURCE_DIR}/include/asperity/${header}")
    string(APPEND failures "\n  cmake/public_headers.cmake lists ${header}, which is not in include/asperity/")
  endif()
  set(copies ${listed})
  list(FILTER copies INCLUDE REGEX "^${header}$")
  list(LENGTH copies count)
  if(count GREATER 1)
    string(APPEND failures "\n  cmake/public_headers.cmake lists ${header} ${count} times")
  endif()
  if(header MATCHES "\\.(hpp|h)$")
    file(STRINGS "${SOURCE_DIR}/include/asperity/${header}" lines REGEX "^#include \"")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^#include \"asperity/([^\"]+)\".*" "\\1" included "${line}")
      list(FIND listed "${included}" at)
      if(at EQUAL -1)
        string(APPEND failures "\n  include/asperity/${header} includes ${line}: not a public header (not installed)")
      endif()
    endforeach()
  endif()
endforeach()

if(failures)
  message(FATAL_ERROR "layering violations:${failures}")
endif()
message(STATUS "layering: every include looks down, no folder reaches into another's private files, "
               "the public face is the installed list")
