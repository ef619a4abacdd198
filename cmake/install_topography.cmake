# Installing the topography library (topography/CMakeLists.txt, with ASPERITY_INSTALL):
# asperity::topography in the same CMake package as asperity::runtime (asperityTargets), its
# headers with the include folder (cmake/install.cmake installs include/ whole, topography/
# included). The report's plots are drawn by the library itself: nothing else is installed.
install(TARGETS asperity_topography EXPORT asperityTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(NOT ASPERITY_SHARED)
  # A static topography library carries tablegen's code as a link-only dependency: it is
  # installed with it (no headers: the public headers never name it).
  set_target_properties(asperity_tablegen PROPERTIES EXPORT_NAME tablegen_internal)
  install(TARGETS asperity_tablegen EXPORT asperityTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
endif()
# libasperity.so.0 beside it, wherever the installed tree is
asperity_install_rpath(asperity_topography "${CMAKE_INSTALL_LIBDIR}")
