# Install rules and a CMake package, so a user's project can find_package(cbbg) and link
# cbbg::framework. Headers install under include/cbbg/ with their tree (framework/...).
include(CMakePackageConfigHelpers)

install(TARGETS cbbg_framework EXPORT cbbgTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY framework/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cbbg/framework
        FILES_MATCHING PATTERN "*.h")
install(EXPORT cbbgTargets NAMESPACE cbbg:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/cbbg)

configure_package_config_file(cmake/cbbgConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/cbbgConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/cbbg)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/cbbgConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/cbbgConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/cbbgConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/cbbg)
