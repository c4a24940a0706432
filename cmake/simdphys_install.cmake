include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS simdphys EXPORT simdphysTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/simdphys DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT simdphysTargets NAMESPACE simdphys::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/simdphys)
configure_package_config_file(cmake/simdphysConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/simdphysConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/simdphys)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/simdphysConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/simdphysConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/simdphysConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/simdphys)
