# The ParaView plugin ApertureLightingPlugin: VTK::ApertureLighting built against ParaView's own
# VTK (its libraries cannot mix with another VTK's), the "Aperture Lighting" representation
# module and the server-manager XML, then the plugin's tests and an env.sh giving pvpython and
# pvbatch that load this ParaView's Python modules and find the plugin.

include(GNUInstallDirs)

# ParaView's CMake package imports its Python modules' and tools' targets, among them files that
# come with python3-paraview (pvpython, the Python modules), which is not installed: it conflicts
# with python3-vtk9 (see Utilities/install-dependencies.sh). The plugin links none of them: they
# are declared here, empty, so that the package's target files, finding them all defined, load.
function (aperture_declare_empty_targets targets_file)
  file(STRINGS "${targets_file}" _line REGEX "^foreach\\(_cmake_expected_target IN ITEMS ")
  string(REGEX REPLACE "^foreach\\(_cmake_expected_target IN ITEMS (.*)\\)$" "\\1" _line "${_line}")
  separate_arguments(_targets UNIX_COMMAND "${_line}")
  foreach (_target IN LISTS _targets)
    if (NOT TARGET "${_target}")
      add_library("${_target}" INTERFACE IMPORTED)
    endif ()
  endforeach ()
endfunction ()
find_path(APERTURELIGHTING_PARAVIEW_CMAKE_DIR paraview-config.cmake
  PATH_SUFFIXES cmake/paraview-5.11
  PATHS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE})
if (APERTURELIGHTING_PARAVIEW_CMAKE_DIR AND
    NOT EXISTS "/usr/lib/python3/dist-packages/paraview/__init__.py")
  aperture_declare_empty_targets("${APERTURELIGHTING_PARAVIEW_CMAKE_DIR}/vtk/VTKPython-targets.cmake")
  aperture_declare_empty_targets("${APERTURELIGHTING_PARAVIEW_CMAKE_DIR}/ParaViewPython-targets.cmake")
  aperture_declare_empty_targets("${APERTURELIGHTING_PARAVIEW_CMAKE_DIR}/ParaViewTools-targets.cmake")
endif ()

find_package(ParaView 5.11 REQUIRED
  COMPONENTS RemotingCore RemotingServerManager RemotingViews)

# The wrap hierarchies of ParaView's modules (which the client-server wrapping reads) come with
# python3-paraview too: they are read from its unpacked copy (see below).
set(APERTURELIGHTING_PARAVIEW_ROOT "${CMAKE_BINARY_DIR}/python3-paraview/usr"
  CACHE PATH "Where python3-paraview is unpacked (Utilities/ParaView/unpack-pvpython.sh)")
get_property(_aperture_imported DIRECTORY PROPERTY IMPORTED_TARGETS)
foreach (_target IN LISTS _aperture_imported)
  get_property(_hierarchy TARGET "${_target}" PROPERTY "INTERFACE_vtk_module_hierarchy")
  if (_hierarchy AND NOT EXISTS "${_hierarchy}")
    string(REGEX REPLACE "^/usr/" "${APERTURELIGHTING_PARAVIEW_ROOT}/" _hierarchy "${_hierarchy}")
    set_property(TARGET "${_target}" PROPERTY "INTERFACE_vtk_module_hierarchy" "${_hierarchy}")
  endif ()
endforeach ()

set(CMAKE_RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}")
set(CMAKE_LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CMAKE_ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
if (NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif ()
set(BUILD_SHARED_LIBS ON)
option(BUILD_TESTING "Build the plugin's tests" ON)
if (BUILD_TESTING)
  enable_testing()
endif ()

paraview_plugin_scan(
  PLUGIN_FILES      "${CMAKE_CURRENT_SOURCE_DIR}/ParaView/Plugin/paraview.plugin"
  PROVIDES_PLUGINS  _aperture_plugins
  ENABLE_BY_DEFAULT ON)
paraview_plugin_build(
  PLUGINS              ${_aperture_plugins}
  RUNTIME_DESTINATION  "${CMAKE_INSTALL_BINDIR}"
  LIBRARY_DESTINATION  "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY_SUBDIRECTORY "paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/plugins"
  PLUGINS_FILE_NAME    "ApertureLighting.plugins.xml")

set(APERTURELIGHTING_PLUGIN_DIR
  "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/plugins/ApertureLightingPlugin")

# pvpython from python3-paraview unpacked here (Utilities/ParaView/unpack-pvpython.sh), pvbatch
# from the paraview package; both through a wrapper that fixes sys.path and finds the plugin.
set(APERTURELIGHTING_PARAVIEW_PYTHONPATH
  "${APERTURELIGHTING_PARAVIEW_ROOT}/lib/python3/dist-packages")
set(APERTURELIGHTING_PARAVIEW_BOOT "${CMAKE_BINARY_DIR}/lib/aperture-pvboot.py")
configure_file("${CMAKE_CURRENT_SOURCE_DIR}/Utilities/ParaView/pvboot.py.in"
  "${APERTURELIGHTING_PARAVIEW_BOOT}" @ONLY)
find_program(APERTURELIGHTING_PVBATCH pvbatch REQUIRED)
foreach (tool IN ITEMS pvpython pvbatch)
  set(APERTURELIGHTING_PARAVIEW_TOOL "${tool}")
  if (tool STREQUAL "pvpython")
    set(APERTURELIGHTING_PARAVIEW_EXECUTABLE "${APERTURELIGHTING_PARAVIEW_ROOT}/bin/pvpython")
  else ()
    set(APERTURELIGHTING_PARAVIEW_EXECUTABLE "${APERTURELIGHTING_PVBATCH}")
  endif ()
  configure_file("${CMAKE_CURRENT_SOURCE_DIR}/Utilities/ParaView/pvwrapper.in"
    "${CMAKE_BINARY_DIR}/bin/${tool}" @ONLY
    FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ
      WORLD_EXECUTE)
endforeach ()
configure_file("${CMAKE_CURRENT_SOURCE_DIR}/Utilities/ParaView/env.sh.in"
  "${CMAKE_BINARY_DIR}/env.sh" @ONLY)

if (BUILD_TESTING)
  add_subdirectory(ParaView/Testing)
endif ()
