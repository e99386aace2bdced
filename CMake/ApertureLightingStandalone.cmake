# Standalone build of ApertureLighting against an installed VTK 9.1: its modules (Core/, IO/*/,
# Rendering/, Rendering/Volume/, Volume/ and the umbrella VTK::ApertureLighting), the Python package `aperturelighting`, the
# CMake package `ApertureLighting` and the tests.

include(GNUInstallDirs)

set(_aperture_vtk_components
  CommonCore
  CommonDataModel
  CommonExecutionModel
  CommonMath
  FiltersCore
  IOImage
  ParallelCore
  RenderingCore
  RenderingOpenGL2
  RenderingVolumeOpenGL2
  opengl
  vtksys
  zlib)
set(_aperture_vtk_test_components
  FiltersGeneral
  FiltersGeometry
  FiltersSources
  FiltersTexture
  IOGeometry
  IOLegacy
  IOPLY
  IOXML
  ImagingCore
  ImagingGeneral
  InteractionStyle
  ParallelMPI
  RenderingAnnotation
  RenderingFreeType
  TestingCore
  TestingRendering)
find_package(VTK 9.1 REQUIRED
  COMPONENTS ${_aperture_vtk_components}
  OPTIONAL_COMPONENTS ${_aperture_vtk_test_components} Python WrappingPythonCore)

set(CMAKE_RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}")
set(CMAKE_LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CMAKE_ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
if (NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif ()

option(BUILD_SHARED_LIBS "Build shared libraries" ON)
option(BUILD_TESTING "Build the tests" ON)
if (BUILD_TESTING)
  enable_testing()
endif ()

# vtk_module_build() cannot add the project root as the umbrella module's folder, so it is scanned
# from the driver's copy of vtk.module (named so that VTK's Remote/ glob does not find it twice).
set(_aperture_module_file "${CMAKE_CURRENT_SOURCE_DIR}/CMake/Standalone/ApertureLighting.module")
file(READ "${CMAKE_CURRENT_SOURCE_DIR}/vtk.module" _aperture_module_top)
file(READ "${_aperture_module_file}" _aperture_module_copy)
if (NOT _aperture_module_top STREQUAL _aperture_module_copy)
  message(FATAL_ERROR
    "CMake/Standalone/ApertureLighting.module must be an exact copy of vtk.module.")
endif ()

# Python package `aperturelighting`, for the interpreter VTK's own modules were built for.
set(APERTURELIGHTING_WRAP_PYTHON OFF)
if (VTK_WRAP_PYTHON AND TARGET VTK::WrappingPythonCore)
  set(APERTURELIGHTING_WRAP_PYTHON ON)
endif ()
if (APERTURELIGHTING_WRAP_PYTHON)
  find_package(Python3 "${VTK_PYTHON_VERSION}" REQUIRED COMPONENTS Interpreter)
  if (Python3_SITEARCH MATCHES "dist-packages")
    # Debian-style interpreters read <prefix>/lib/pythonX.Y/dist-packages.
    set(_aperture_python_default
      "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages")
  else ()
    vtk_module_python_default_destination(_aperture_python_default)
  endif ()
  set(APERTURELIGHTING_PYTHON_DESTINATION "${_aperture_python_default}"
    CACHE STRING "Where the aperturelighting Python package goes, relative to the prefix")
endif ()

# The modules first, then the umbrella, which alone holds the tests (Testing/): scanned with
# tests, a module two folders deep would take the same Testing/ folder for its own.
set(APERTURELIGHTING_MODULE_FILES
  "${CMAKE_CURRENT_SOURCE_DIR}/Core/vtk.module"
  "${CMAKE_CURRENT_SOURCE_DIR}/IO/DICOM/vtk.module"
  "${CMAKE_CURRENT_SOURCE_DIR}/IO/GDAL/vtk.module"
  "${CMAKE_CURRENT_SOURCE_DIR}/IO/Image/vtk.module"
  "${CMAKE_CURRENT_SOURCE_DIR}/IO/OpenEXR/vtk.module"
  "${CMAKE_CURRENT_SOURCE_DIR}/Rendering/vtk.module"
  "${CMAKE_CURRENT_SOURCE_DIR}/Rendering/Volume/vtk.module"
  "${CMAKE_CURRENT_SOURCE_DIR}/Volume/vtk.module")
vtk_module_scan(
  MODULE_FILES      ${APERTURELIGHTING_MODULE_FILES}
  REQUEST_MODULES   VTK::ApertureLightingCore VTK::ApertureLightingIODICOM VTK::ApertureLightingIOGDAL
                    VTK::ApertureLightingIOImage VTK::ApertureLightingIOOpenEXR
                    VTK::ApertureLightingRendering VTK::ApertureLightingVolume
                    VTK::ApertureLightingRenderingVolume
  PROVIDES_MODULES  _aperture_parts
  ENABLE_TESTS      OFF)
vtk_module_scan(
  MODULE_FILES      "${_aperture_module_file}"
  REQUEST_MODULES   VTK::ApertureLighting
  PROVIDES_MODULES  _aperture_umbrella
  ENABLE_TESTS      "${BUILD_TESTING}")
set(_aperture_modules ${_aperture_parts} ${_aperture_umbrella})

set(_aperture_cmake_destination "${CMAKE_INSTALL_LIBDIR}/cmake/ApertureLighting")
vtk_module_build(
  MODULES             ${_aperture_modules}
  PACKAGE             ApertureLighting
  INSTALL_EXPORT      ApertureLighting
  CMAKE_DESTINATION   "${_aperture_cmake_destination}"
  HEADERS_DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/ApertureLighting"
  HIERARCHY_DESTINATION "${CMAKE_INSTALL_LIBDIR}/vtk/hierarchy/ApertureLighting"
  VERSION             "${PROJECT_VERSION}"
  SOVERSION           "1"
  # Relative to the driver folder: the repository's Testing/ folder.
  TEST_DIRECTORY_NAME "../../Testing"
  TEST_INPUT_DATA_DIRECTORY  "${CMAKE_CURRENT_SOURCE_DIR}/Testing"
  # Test data live in the source tree (Testing/Data), read in place.
  TEST_OUTPUT_DATA_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/Testing"
  TEST_OUTPUT_DIRECTORY      "${CMAKE_CURRENT_BINARY_DIR}/Testing/Temporary")

vtk_module_export_find_packages(
  CMAKE_DESTINATION "${_aperture_cmake_destination}"
  FILE_NAME         "ApertureLighting-vtk-module-find-packages.cmake"
  MODULES           ${_aperture_modules})

if (APERTURELIGHTING_WRAP_PYTHON)
  vtk_module_wrap_python(
    MODULES             ${_aperture_modules}
    TARGET              ApertureLighting::Python
    WRAPPED_MODULES     _aperture_wrapped_modules
    PYTHON_PACKAGE      "aperturelighting"
    MODULE_DESTINATION  "${APERTURELIGHTING_PYTHON_DESTINATION}"
    LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    CMAKE_DESTINATION   "${_aperture_cmake_destination}"
    INSTALL_EXPORT      ApertureLightingPython
    INSTALL_HEADERS     OFF
    BUILD_STATIC        OFF)

  # The package's __init__ maps each class to its module (from the modules' public headers).
  set(APERTURELIGHTING_PYTHON_CLASSES "")
  foreach (_aperture_module IN LISTS _aperture_parts)
    vtk_module_get_property("${_aperture_module}"
      PROPERTY "INTERFACE_vtk_module_library_name" VARIABLE _library)
    vtk_module_get_property("${_aperture_module}"
      PROPERTY "INTERFACE_vtk_module_headers" VARIABLE _headers)
    foreach (_header IN LISTS _headers)
      get_filename_component(_class "${_header}" NAME_WE)
      if (NOT _class STREQUAL "${_library}Module")
        string(APPEND APERTURELIGHTING_PYTHON_CLASSES "    \"${_class}\": \"${_library}\",\n")
      endif ()
    endforeach ()
  endforeach ()
  set(_aperture_python_package_dir
    "${CMAKE_BINARY_DIR}/${APERTURELIGHTING_PYTHON_DESTINATION}/aperturelighting")
  configure_file("${CMAKE_CURRENT_SOURCE_DIR}/Wrapping/Python/aperturelighting/__init__.py.in"
    "${_aperture_python_package_dir}/__init__.py" @ONLY)
  install(FILES "${_aperture_python_package_dir}/__init__.py"
    DESTINATION "${APERTURELIGHTING_PYTHON_DESTINATION}/aperturelighting"
    COMPONENT python)
endif ()

add_subdirectory(Examples)

# CMake package, usable from the build tree and after installation.
include(CMakePackageConfigHelpers)
# Each component (a module: Core for VTK::ApertureLightingCore) and the VTK modules it and the
# modules it depends on link publicly.
set(APERTURELIGHTING_COMPONENTS)
set(APERTURELIGHTING_COMPONENT_VTK_MODULES "")
foreach (_aperture_module IN LISTS _aperture_parts)
  string(REPLACE "VTK::ApertureLighting" "" _component "${_aperture_module}")
  list(APPEND APERTURELIGHTING_COMPONENTS "${_component}")
  set(_vtk_modules)
  set(_pending "${_aperture_module}")
  while (_pending)
    list(GET _pending 0 _module)
    list(REMOVE_AT _pending 0)
    vtk_module_get_property("${_module}" PROPERTY "INTERFACE_vtk_module_depends"
      VARIABLE _depends)
    foreach (_depend IN LISTS _depends)
      if (_depend IN_LIST _aperture_parts)
        list(APPEND _pending "${_depend}")
      elseif (_depend MATCHES "^VTK::(.*)$")
        list(APPEND _vtk_modules "${CMAKE_MATCH_1}")
      endif ()
    endforeach ()
  endwhile ()
  list(REMOVE_DUPLICATES _vtk_modules)
  list(SORT _vtk_modules)
  string(APPEND APERTURELIGHTING_COMPONENT_VTK_MODULES
    "set(_aperture_vtk_modules_${_component} ${_vtk_modules})\n")
endforeach ()
configure_file("${CMAKE_CURRENT_SOURCE_DIR}/CMake/ApertureLightingConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${_aperture_cmake_destination}/ApertureLightingConfig.cmake" @ONLY)
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${_aperture_cmake_destination}/ApertureLightingConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
install(
  FILES
    "${CMAKE_BINARY_DIR}/${_aperture_cmake_destination}/ApertureLightingConfig.cmake"
    "${CMAKE_BINARY_DIR}/${_aperture_cmake_destination}/ApertureLightingConfigVersion.cmake"
  DESTINATION "${_aperture_cmake_destination}"
  COMPONENT development)
install(FILES "${CMAKE_CURRENT_SOURCE_DIR}/LICENSE"
  DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/doc/ApertureLighting"
  COMPONENT development)

# Environment for using the build tree: `source build/env.sh`.
set(APERTURELIGHTING_ENV_PYTHONPATH "")
if (APERTURELIGHTING_WRAP_PYTHON)
  set(APERTURELIGHTING_ENV_PYTHONPATH "${CMAKE_BINARY_DIR}/${APERTURELIGHTING_PYTHON_DESTINATION}")
endif ()
configure_file("${CMAKE_CURRENT_SOURCE_DIR}/CMake/env.sh.in" "${CMAKE_BINARY_DIR}/env.sh" @ONLY)
