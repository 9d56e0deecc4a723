# Installed CMake package: find_package(TerraLux) gives TerraLux::Sources and
# TerraLux::Filters (VTK modules) and TerraLux::SourcesEngine and
# TerraLux::FiltersEngine (the VTK-free engines).
include(CMakePackageConfigHelpers)

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/TerraLuxConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${terralux_cmake_destination}/TerraLuxConfig.cmake"
  INSTALL_DESTINATION "${terralux_cmake_destination}")
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${terralux_cmake_destination}/TerraLuxConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)

install(FILES
  "${CMAKE_BINARY_DIR}/${terralux_cmake_destination}/TerraLuxConfig.cmake"
  "${CMAKE_BINARY_DIR}/${terralux_cmake_destination}/TerraLuxConfigVersion.cmake"
  "${CMAKE_CURRENT_LIST_DIR}/FindGeographicLib.cmake"
  DESTINATION "${terralux_cmake_destination}")
install(EXPORT TerraLuxEngine
  NAMESPACE TerraLux::
  FILE TerraLuxEngine-targets.cmake
  DESTINATION "${terralux_cmake_destination}")
