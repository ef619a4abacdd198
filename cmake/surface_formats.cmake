# The surface formats' IDs for CMake, read from the one list ASPERITY_SURFACE_FORMATS
# (include/asperity/topography/height_map_io.hpp: one entry per line starting "X(ID,"), in its
# order. The fuzz targets (fuzz/CMakeLists.txt) and the registry's test (tests/) are made from it;
# the build configures again when the list changes.
function(asperity_surface_format_ids out_var)
  set(list_file ${PROJECT_SOURCE_DIR}/include/asperity/topography/height_map_io.hpp)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${list_file})
  # the file as one string (its lines end in backslashes, which would escape a list's separators)
  file(READ ${list_file} text)
  string(REGEX MATCHALL "\n *X\\([a-z0-9_]+," entries "${text}")
  set(ids "")
  foreach(entry IN LISTS entries)
    string(REGEX REPLACE "^\n *X\\(([a-z0-9_]+),$" "\\1" id "${entry}")
    list(APPEND ids ${id})
  endforeach()
  if(NOT ids)
    message(FATAL_ERROR "no surface format in ASPERITY_SURFACE_FORMATS (${list_file})")
  endif()
  set(${out_var} ${ids} PARENT_SCOPE)
endfunction()
