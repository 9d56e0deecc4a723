# Python package `terralux`: VTK-wrapped modules plus an __init__.py that
# re-exports every class, usable from the build tree and after installation.

find_package(Python3 REQUIRED COMPONENTS Interpreter Development)

# Debian puts /usr/local/lib/python3.X/dist-packages on sys.path, not site-packages.
set(TERRALUX_PYTHON_DESTINATION
  "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages"
  CACHE STRING "Install (and build-tree) folder, relative to the prefix, of the Python package 'terralux'.")
mark_as_advanced(TERRALUX_PYTHON_DESTINATION)

vtk_module_wrap_python(
  MODULES ${terralux_modules}
  TARGET TerraLux::Python
  WRAPPED_MODULES terralux_wrapped_modules
  PYTHON_PACKAGE terralux
  MODULE_DESTINATION "${TERRALUX_PYTHON_DESTINATION}"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  CMAKE_DESTINATION "${terralux_cmake_destination}"
  INSTALL_HEADERS OFF
  BUILD_STATIC OFF)

set(terralux_python_modules)
foreach (module IN LISTS terralux_wrapped_modules)
  get_property(library_name TARGET "${module}" PROPERTY OUTPUT_NAME)
  if (NOT library_name)
    string(REPLACE "TerraLux::" "TerraLux" library_name "${module}")
  endif ()
  list(APPEND terralux_python_modules "${library_name}")
endforeach ()
string(REPLACE ";" "\", \"" TERRALUX_PYTHON_MODULES "${terralux_python_modules}")

set(terralux_package_dir "${CMAKE_BINARY_DIR}/${TERRALUX_PYTHON_DESTINATION}/terralux")
configure_file("${CMAKE_CURRENT_LIST_DIR}/terralux__init__.py.in"
  "${terralux_package_dir}/__init__.py" @ONLY)
# Pure-Python modules of the package: the irradiation command (python3 -m terralux.irradiation).
configure_file("${CMAKE_SOURCE_DIR}/TimeIntegration/Python/irradiation.py"
  "${terralux_package_dir}/irradiation.py" COPYONLY)
install(FILES "${terralux_package_dir}/__init__.py" "${terralux_package_dir}/irradiation.py"
  DESTINATION "${TERRALUX_PYTHON_DESTINATION}/terralux"
  COMPONENT python)

# Where tests and scripts find the package in the build tree.
set(TERRALUX_BUILD_PYTHONPATH "${CMAKE_BINARY_DIR}/${TERRALUX_PYTHON_DESTINATION}")
