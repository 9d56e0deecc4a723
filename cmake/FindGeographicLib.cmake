# FindGeographicLib
# -----------------
# Debian's libgeographiclib-dev installs no CMake package configuration, so this
# module locates the header and library and provides the imported target
# GeographicLib::GeographicLib. Result variables: GeographicLib_FOUND,
# GeographicLib_INCLUDE_DIR, GeographicLib_LIBRARY, GeographicLib_VERSION.

find_path(GeographicLib_INCLUDE_DIR
  NAMES GeographicLib/LocalCartesian.hpp)
find_library(GeographicLib_LIBRARY
  NAMES GeographicLib Geographic)

if (GeographicLib_INCLUDE_DIR AND EXISTS "${GeographicLib_INCLUDE_DIR}/GeographicLib/Config.h")
  file(STRINGS "${GeographicLib_INCLUDE_DIR}/GeographicLib/Config.h" _geographiclib_version_line
    REGEX "#define GEOGRAPHICLIB_VERSION_STRING")
  string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" GeographicLib_VERSION "${_geographiclib_version_line}")
  unset(_geographiclib_version_line)
endif ()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(GeographicLib
  REQUIRED_VARS GeographicLib_LIBRARY GeographicLib_INCLUDE_DIR
  VERSION_VAR GeographicLib_VERSION)

if (GeographicLib_FOUND AND NOT TARGET GeographicLib::GeographicLib)
  add_library(GeographicLib::GeographicLib UNKNOWN IMPORTED)
  set_target_properties(GeographicLib::GeographicLib PROPERTIES
    IMPORTED_LOCATION "${GeographicLib_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${GeographicLib_INCLUDE_DIR}")
endif ()

mark_as_advanced(GeographicLib_INCLUDE_DIR GeographicLib_LIBRARY)
