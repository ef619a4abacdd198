# Installing (ASPERITY_INSTALL): cmake --install build --prefix P gives P a tree another
# project uses through find_package(asperity 0.2 [COMPONENTS ...]) and asperity::<component>,
# or pkg-config asperity, or `import asperity` (cmake/install_layout.cmake lists the layout).
# Each component has its own export set (asperity-<component>-targets.cmake), so that a program
# asking for the runtime alone loads, and for a static build finds, nothing more.
include(CMakePackageConfigHelpers)
include(${CMAKE_CURRENT_LIST_DIR}/public_headers.cmake)

function(asperity_install_headers component)
  foreach(header IN LISTS ARGN)
    get_filename_component(folder "${header}" DIRECTORY)
    install(FILES "${PROJECT_SOURCE_DIR}/include/asperity/${header}"
            DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/asperity/${folder}" COMPONENT ${component})
  endforeach()
endfunction()

function(asperity_install_library target component)
  install(TARGETS ${target} EXPORT asperity-${component}-targets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${component} NAMELINK_COMPONENT development
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT ${component}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT asperity-${component}-targets NAMESPACE asperity:: DESTINATION "${ASPERITY_INSTALL_CMAKE_DIR}"
          COMPONENT development)
endfunction()

set(ASPERITY_INSTALLED_COMPONENTS runtime)

# ---- runtime ----
asperity_install_library(asperity_runtime runtime)
asperity_install_headers(development ${ASPERITY_RUNTIME_HEADERS})
# The default table, where the installed library looks for it (runtime/table/default_table.cpp).
# ASPERITY_DEFAULT_TABLE is where the build made it (the default_table target).
set(ASPERITY_INSTALLS_TABLE OFF)
if(TARGET default_table)
  set(ASPERITY_INSTALLS_TABLE ON)
  install(FILES "${ASPERITY_DEFAULT_TABLE}" DESTINATION "${ASPERITY_INSTALL_TABLE_DIR}"
          RENAME "${ASPERITY_TABLE_FILE_NAME}" COMPONENT runtime)
endif()

# ---- generator, topography ----
if(TARGET asperity_generator)
  asperity_install_library(asperity_generator generator)
  asperity_install_headers(development ${ASPERITY_GENERATOR_HEADERS})
  list(APPEND ASPERITY_INSTALLED_COMPONENTS generator)
endif()
if(TARGET asperity_topography)
  asperity_install_library(asperity_topography topography)
  asperity_install_headers(development ${ASPERITY_TOPOGRAPHY_HEADERS})
  asperity_install_rpath(asperity_topography "${CMAKE_INSTALL_LIBDIR}")  # the other libraries beside it
  list(APPEND ASPERITY_INSTALLED_COMPONENTS topography)
endif()
if(TARGET asperity_generator)
  asperity_install_rpath(asperity_generator "${CMAKE_INSTALL_LIBDIR}")
endif()

# ---- fortran: gfortran's compiled module beside the headers ----
if(TARGET asperity_fortran_module)
  # `gfortran prog.f90 $(pkg-config --cflags --libs asperity)`, or asperity::fortran in CMake
  install(FILES "${ASPERITY_FORTRAN_MODULE_DIR}/asperity.mod" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          COMPONENT fortran)
  asperity_install_headers(fortran ${ASPERITY_FORTRAN_SOURCES})
  add_library(asperity_fortran INTERFACE)
  target_link_libraries(asperity_fortran INTERFACE asperity_runtime)
  target_include_directories(asperity_fortran INTERFACE $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(asperity_fortran PROPERTIES EXPORT_NAME fortran)
  asperity_install_library(asperity_fortran fortran)
  list(APPEND ASPERITY_INSTALLED_COMPONENTS fortran)
endif()

# ---- commands: asperity and tablegen (imported executables asperity::asperity, asperity::tablegen) ----
if(TARGET asperity AND TARGET tablegen)
  install(TARGETS asperity tablegen EXPORT asperity-commands-targets
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT commands)
  install(EXPORT asperity-commands-targets NAMESPACE asperity:: DESTINATION "${ASPERITY_INSTALL_CMAKE_DIR}"
          COMPONENT development)
  foreach(program asperity tablegen)
    asperity_install_rpath(${program} "${CMAKE_INSTALL_BINDIR}")
  endforeach()
  list(APPEND ASPERITY_INSTALLED_COMPONENTS commands)
endif()

# ---- python: the package's folder (python/CMakeLists.txt installs it) ----
if(ASPERITY_BUILD_PYTHON)
  list(APPEND ASPERITY_INSTALLED_COMPONENTS python)
endif()

# ---- benchmarks: bench_lookup, the lookup's speed on the installed library (bench/CMakeLists.txt) ----
if(ASPERITY_BUILD_BENCHMARKS)
  list(APPEND ASPERITY_INSTALLED_COMPONENTS benchmarks)
endif()

# The CMake package: asperityConfig.cmake (loads the components asked for and, for static
# libraries, finds what they need), asperityConfigVersion.cmake, asperity-<component>-targets.cmake.
if(IS_ABSOLUTE "${ASPERITY_PYTHON_INSTALL_DIR}")
  set(ASPERITY_PYTHON_DIR_IN_PACKAGE "${ASPERITY_PYTHON_INSTALL_DIR}")
elseif(ASPERITY_PYTHON_INSTALL_DIR)
  set(ASPERITY_PYTHON_DIR_IN_PACKAGE "\${PACKAGE_PREFIX_DIR}/${ASPERITY_PYTHON_INSTALL_DIR}")
endif()
configure_package_config_file(cmake/asperityConfig.cmake.in
                              "${PROJECT_BINARY_DIR}/asperityConfig.cmake"
                              INSTALL_DESTINATION "${ASPERITY_INSTALL_CMAKE_DIR}"
                              PATH_VARS ASPERITY_INSTALL_TABLE_DIR)
# Before 1.0 a minor version may change the API: 0.2 asks for 0.2.x.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/asperityConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/asperityConfig.cmake" "${PROJECT_BINARY_DIR}/asperityConfigVersion.cmake"
        DESTINATION "${ASPERITY_INSTALL_CMAKE_DIR}" COMPONENT development)

# pkg-config: `cc prog.c $(pkg-config --cflags --libs asperity)` (the runtime and its C API).
# The prefix is found from the .pc file's own place, so a tree installed with --prefix anywhere
# (or moved) still works.
if(IS_ABSOLUTE "${ASPERITY_INSTALL_PKGCONFIG_DIR}")
  set(pkgconfig_full "${ASPERITY_INSTALL_PKGCONFIG_DIR}")
else()
  set(pkgconfig_full "${CMAKE_INSTALL_PREFIX}/${ASPERITY_INSTALL_PKGCONFIG_DIR}")
endif()
file(RELATIVE_PATH ASPERITY_PC_TO_PREFIX "${pkgconfig_full}" "${CMAKE_INSTALL_PREFIX}")
string(REGEX REPLACE "/$" "" ASPERITY_PC_TO_PREFIX "${ASPERITY_PC_TO_PREFIX}")
file(RELATIVE_PATH ASPERITY_PC_LIBDIR "${CMAKE_INSTALL_PREFIX}" "${CMAKE_INSTALL_FULL_LIBDIR}")
file(RELATIVE_PATH ASPERITY_PC_INCLUDEDIR "${CMAKE_INSTALL_PREFIX}" "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
if(ASPERITY_SHARED)
  set(ASPERITY_PC_PRIVATE "")
else()
  # A static library: the C++ runtime, HDF5 and libcrypto (pkg-config --static --libs asperity).
  set(ASPERITY_PC_PRIVATE "Requires.private: hdf5 libcrypto\nLibs.private: -lstdc++ -lm")
  foreach(library IN LISTS CMAKE_DL_LIBS)
    string(APPEND ASPERITY_PC_PRIVATE " -l${library}")
  endforeach()
endif()
set(ASPERITY_PC_PYTHON "")
if(ASPERITY_BUILD_PYTHON)
  # PYTHONPATH=$(pkg-config --variable=pythondir asperity), for the interpreter named by `python`
  if(IS_ABSOLUTE "${ASPERITY_PYTHON_INSTALL_DIR}")
    set(ASPERITY_PC_PYTHON "pythondir=${ASPERITY_PYTHON_INSTALL_DIR}\npython=${Python_EXECUTABLE}\n")
  else()
    set(ASPERITY_PC_PYTHON "pythondir=\${prefix}/${ASPERITY_PYTHON_INSTALL_DIR}\npython=${Python_EXECUTABLE}\n")
  endif()
endif()
configure_file(cmake/asperity.pc.in "${PROJECT_BINARY_DIR}/asperity.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/asperity.pc" DESTINATION "${ASPERITY_INSTALL_PKGCONFIG_DIR}"
        COMPONENT development)

# The licence, the changes and the model's conventions beside the table.
install(FILES LICENSE CHANGELOG.md README.md docs/model.md DESTINATION "${CMAKE_INSTALL_DOCDIR}"
        COMPONENT runtime)
