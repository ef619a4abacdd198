# The installed tree: where each part goes (GNUInstallDirs), how the installed library and
# commands find the default table and each other wherever the tree is put.
#
#   lib/libasperity.so.0.2.0 (.so.0, .so)      include/asperity/*.h, *.hpp (cmake/public_headers.cmake)
#   lib/libasperity_generator.so.0, _topography include/asperity/generator/, topography/
#   lib/cmake/asperity/ (one file a component)  include/asperity.mod, asperity.f90 (gfortran)
#   lib/pkgconfig/asperity.pc                  share/asperity/asperity-default.h5
#   bin/asperity, bin/tablegen                 lib/pythonX.Y/<site>/asperity/ (the Python package)

set(ASPERITY_TABLE_FILE_NAME asperity-default.h5)
set(ASPERITY_INSTALL_TABLE_DIR "${CMAKE_INSTALL_DATADIR}/asperity")
set(ASPERITY_INSTALL_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/asperity")
set(ASPERITY_INSTALL_PKGCONFIG_DIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")

if(ASPERITY_BUILD_PYTHON)
  include(${CMAKE_CURRENT_LIST_DIR}/python_interpreter.cmake)
  if(NOT ASPERITY_PYTHON_FOUND)
    set(ASPERITY_BUILD_PYTHON OFF)
  endif()
endif()

# Paths to share/asperity/ from the installed places that can hold the library's code: the
# library's folder (shared), or, for a static library, also the commands' and the Python
# package's, which link it in. Relative, so a moved tree still works.
function(asperity_relative_to_table out from)
  if(IS_ABSOLUTE "${from}")
    set(from_full "${from}")
  else()
    set(from_full "${CMAKE_INSTALL_PREFIX}/${from}")
  endif()
  if(IS_ABSOLUTE "${ASPERITY_INSTALL_TABLE_DIR}")
    set(table_full "${ASPERITY_INSTALL_TABLE_DIR}")
  else()
    set(table_full "${CMAKE_INSTALL_PREFIX}/${ASPERITY_INSTALL_TABLE_DIR}")
  endif()
  file(RELATIVE_PATH relative "${from_full}" "${table_full}")
  set(${out} "${relative}" PARENT_SCOPE)
endfunction()
asperity_relative_to_table(from_lib "${CMAKE_INSTALL_LIBDIR}")
asperity_relative_to_table(from_bin "${CMAKE_INSTALL_BINDIR}")
set(ASPERITY_RELATIVE_TABLE_DIRS "\"${from_lib}\"")
if(NOT ASPERITY_SHARED AND NOT from_bin STREQUAL from_lib)
  set(ASPERITY_RELATIVE_TABLE_DIRS "${ASPERITY_RELATIVE_TABLE_DIRS}, \"${from_bin}\"")
endif()
if(NOT ASPERITY_SHARED AND ASPERITY_BUILD_PYTHON)
  asperity_relative_to_table(from_python "${ASPERITY_PYTHON_INSTALL_DIR}/asperity")
  set(ASPERITY_RELATIVE_TABLE_DIRS "${ASPERITY_RELATIVE_TABLE_DIRS}, \"${from_python}\"")
endif()
# `pip install .` (setup.py): a self-contained Python package, the libraries linked into its module
# and the default table beside it in the package's own folder, wherever pip puts the package.
option(ASPERITY_PYTHON_PACKAGE_TABLE "The default table in the Python module's own folder (setup.py sets it)" OFF)
if(ASPERITY_PYTHON_PACKAGE_TABLE)
  if(ASPERITY_SHARED)
    message(FATAL_ERROR "asperity: ASPERITY_PYTHON_PACKAGE_TABLE=ON needs ASPERITY_SHARED=OFF (the module holds the library)")
  endif()
  set(ASPERITY_RELATIVE_TABLE_DIRS "\".\", ${ASPERITY_RELATIVE_TABLE_DIRS}")
endif()
if(IS_ABSOLUTE "${ASPERITY_INSTALL_TABLE_DIR}")
  set(ASPERITY_INSTALL_TABLE_DIR_FULL "${ASPERITY_INSTALL_TABLE_DIR}")
else()
  set(ASPERITY_INSTALL_TABLE_DIR_FULL "${CMAKE_INSTALL_PREFIX}/${ASPERITY_INSTALL_TABLE_DIR}")
endif()

# Installed programs find libasperity.so through a run path relative to themselves.
function(asperity_install_rpath target from)
  if(IS_ABSOLUTE "${from}")
    set(from_full "${from}")
  else()
    set(from_full "${CMAKE_INSTALL_PREFIX}/${from}")
  endif()
  file(RELATIVE_PATH to_lib "${from_full}" "${CMAKE_INSTALL_FULL_LIBDIR}")
  if(APPLE)
    set_target_properties(${target} PROPERTIES INSTALL_RPATH "@loader_path/${to_lib}")
  else()
    set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/${to_lib}")
  endif()
endfunction()
