# Installing (ASPERITY_INSTALL): cmake --install build --prefix P gives P a tree another
# project uses through find_package(asperity 0.2) and asperity::runtime, or pkg-config asperity,
# or `import asperity` (cmake/install_layout.cmake lists the layout).
include(CMakePackageConfigHelpers)

install(TARGETS asperity_runtime EXPORT asperityTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)
if(TARGET asperity_fortran_module)
  # gfortran's compiled module beside the headers: `gfortran prog.f90 $(pkg-config --cflags --libs asperity)`
  install(FILES "${ASPERITY_FORTRAN_MODULE_DIR}/asperity.mod" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          COMPONENT development)
endif()
install(TARGETS asperity tablegen RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
foreach(program asperity tablegen)
  asperity_install_rpath(${program} "${CMAKE_INSTALL_BINDIR}")
endforeach()

# The default table, where the installed library looks for it (runtime/table/default_table.cpp).
# ASPERITY_DEFAULT_TABLE is where the build made it (the default_table target).
install(FILES "${ASPERITY_DEFAULT_TABLE}" DESTINATION "${ASPERITY_INSTALL_TABLE_DIR}"
        RENAME "${ASPERITY_TABLE_FILE_NAME}" COMPONENT runtime)

# The CMake package: asperityConfig.cmake (finds what a static library's users need),
# asperityConfigVersion.cmake, asperityTargets.cmake (asperity::runtime).
install(EXPORT asperityTargets NAMESPACE asperity:: DESTINATION "${ASPERITY_INSTALL_CMAKE_DIR}"
        COMPONENT development)
configure_package_config_file(cmake/asperityConfig.cmake.in
                              "${PROJECT_BINARY_DIR}/asperityConfig.cmake"
                              INSTALL_DESTINATION "${ASPERITY_INSTALL_CMAKE_DIR}"
                              PATH_VARS ASPERITY_INSTALL_TABLE_DIR)
# Before 1.0 a minor version may change the API: 0.2 asks for 0.2.x.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/asperityConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/asperityConfig.cmake" "${PROJECT_BINARY_DIR}/asperityConfigVersion.cmake"
        DESTINATION "${ASPERITY_INSTALL_CMAKE_DIR}" COMPONENT development)

# pkg-config: `cc prog.c $(pkg-config --cflags --libs asperity)`. The prefix is found from the
# .pc file's own place, so a tree installed with --prefix anywhere (or moved) still works.
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
