# The package files find_package(aloft) reads: aloftConfig.cmake, aloftConfigVersion.cmake
# and the exported targets, aloft::core (component core, always) and aloft::port
# (component port, optional: present when the port was built and installed).
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)
set(ALOFT_CONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/aloft)

install(EXPORT aloftCoreTargets NAMESPACE aloft:: DESTINATION ${ALOFT_CONFIG_DIR} COMPONENT core)
if(ALOFT_BUILD_PORT)
  install(EXPORT aloftPortTargets NAMESPACE aloft:: DESTINATION ${ALOFT_CONFIG_DIR} COMPONENT port)
endif()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/aloftConfig.cmake.in
  ${PROJECT_BINARY_DIR}/aloftConfig.cmake INSTALL_DESTINATION ${ALOFT_CONFIG_DIR})
# 0.x: a minor version may break the interface. The core is headers only; the port's
# objects are for the ALOFT_PORT this prefix was installed from.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/aloftConfigVersion.cmake
  COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES ${PROJECT_BINARY_DIR}/aloftConfig.cmake ${PROJECT_BINARY_DIR}/aloftConfigVersion.cmake
  DESTINATION ${ALOFT_CONFIG_DIR} COMPONENT core)
