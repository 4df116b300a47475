# Install rules: headers, the port libraries and a CMake package, so that
#   find_package(hider 0.2 CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE hider::hider)        # + hider::port_display / port_host / port_semihost
# works against `cmake --install <build> --prefix <prefix>`. The version file accepts any 0.2.x for a
# request of 0.2 (SameMinorVersion: before 1.0 a minor version may break the API).
include(CMakePackageConfigHelpers)
set(_hider_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/hider)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/hider DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "*.md")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/port/display DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hider-port
        FILES_MATCHING PATTERN "*.hpp")
if(TARGET hider_port_host)
  install(FILES ${PROJECT_SOURCE_DIR}/port/host/ppm.hpp ${PROJECT_SOURCE_DIR}/port/host/png.hpp
                ${PROJECT_SOURCE_DIR}/port/host/assert.hpp
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hider-port/host)
endif()
if(TARGET hider_port_semihost)
  install(FILES ${PROJECT_SOURCE_DIR}/port/semihost/semihost.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hider-port/semihost)
endif()

install(TARGETS hider ${HIDER_PORT_TARGETS} EXPORT hiderTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT hiderTargets NAMESPACE hider:: DESTINATION ${_hider_cmake_dir})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/hiderConfig.cmake.in
  ${PROJECT_BINARY_DIR}/hiderConfig.cmake INSTALL_DESTINATION ${_hider_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/hiderConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/hiderConfig.cmake ${PROJECT_BINARY_DIR}/hiderConfigVersion.cmake
        DESTINATION ${_hider_cmake_dir})
