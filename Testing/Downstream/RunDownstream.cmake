# Builds and runs the downstream projects against the build tree's package and against an
# installed copy: the one linking the umbrella, and Headless/, which links only the core and runs
# without a display, with no GL, X11, GDAL or OpenEXR library in its binary's ldd. Then imports
# the Python package from that installation, and its core module alone without a display.
#
# -DBUILD_DIR=<main build> -DSOURCE_DIR=<this folder> -DWORK_DIR=<scratch>
# [-DPYTHON=<interpreter> -DPYTHON_DESTINATION=<relative package folder>] [-DCONFIG=<config>]

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "Failed (${result}): ${command}")
  endif ()
endfunction ()

if (NOT CONFIG)
  set(CONFIG Release)
endif ()
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/install")
run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}" --config "${CONFIG}")

file(GLOB_RECURSE configs "${prefix}/*/ApertureLightingConfig.cmake")
list(LENGTH configs count)
if (NOT count EQUAL 1)
  message(FATAL_ERROR "Expected one installed ApertureLightingConfig.cmake, found: ${configs}")
endif ()
get_filename_component(installed_dir "${configs}" DIRECTORY)

file(GLOB_RECURSE build_configs "${BUILD_DIR}/lib*/cmake/ApertureLighting/ApertureLightingConfig.cmake")
get_filename_component(build_dir "${build_configs}" DIRECTORY)

# Configures, builds and runs project `source` in folder `name` against `package_dir`; `exe` gets
# the program's path.
function (build_and_run name source package_dir program)
  set(binary "${WORK_DIR}/${name}")
  run("${CMAKE_COMMAND}" -S "${source}" -B "${binary}"
    "-DCMAKE_BUILD_TYPE=${CONFIG}" "-DApertureLighting_DIR=${package_dir}")
  run("${CMAKE_COMMAND}" --build "${binary}" --config "${CONFIG}")
  find_program(found_${name} "${program}" PATHS "${binary}" "${binary}/${CONFIG}"
    NO_DEFAULT_PATH)
  run("${CMAKE_COMMAND}" -E env --unset=DISPLAY "${found_${name}}")
  set(exe "${found_${name}}" PARENT_SCOPE)
endfunction ()

# Fails when `exe` loads a library of a display, of GL, or of GDAL or OpenEXR.
function (check_headless exe)
  execute_process(COMMAND ldd "${exe}" OUTPUT_VARIABLE libraries RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "ldd failed on ${exe}")
  endif ()
  string(REGEX MATCHALL "lib(GL|GLX|EGL|OpenGL|OSMesa|X11|gdal|OpenEXR|vtkRendering)[^ ]*"
    forbidden "${libraries}")
  if (forbidden)
    message(FATAL_ERROR "${exe} links ${forbidden}:\n${libraries}")
  endif ()
  string(REGEX MATCHALL "libvtkApertureLightingCore[^ ]*" core "${libraries}")
  if (NOT core)
    message(FATAL_ERROR "${exe} does not link the core:\n${libraries}")
  endif ()
  message(STATUS "${exe}: no GL, X11, GDAL or OpenEXR library")
endfunction ()

foreach (kind IN ITEMS build install)
  if (kind STREQUAL "build")
    set(package_dir "${build_dir}")
  else ()
    set(package_dir "${installed_dir}")
  endif ()
  message(STATUS "Downstream projects against the ${kind} tree: ${package_dir}")
  build_and_run("${kind}" "${SOURCE_DIR}" "${package_dir}" downstream)
  build_and_run("${kind}-headless" "${SOURCE_DIR}/Headless" "${package_dir}" headless)
  check_headless("${exe}")
endforeach ()

if (PYTHON)
  message(STATUS "Python package from the installation")
  set(script
    "import aperturelighting, os, sys\n"
    "from aperturelighting import vtkSphericalCap as C\n"
    "assert os.path.realpath(aperturelighting.__file__).startswith(os.path.realpath(sys.argv[1]))\n"
    "print(C.IntersectionArea(0.5, 0.3, 0.4))\n")
  string(CONCAT script ${script})
  run("${CMAKE_COMMAND}" -E env "PYTHONPATH=${prefix}/${PYTHON_DESTINATION}"
    "${PYTHON}" -c "${script}" "${prefix}")
  message(STATUS "The core's Python module without a display")
  run("${CMAKE_COMMAND}" -E env --unset=DISPLAY "PYTHONPATH=${prefix}/${PYTHON_DESTINATION}"
    "${PYTHON}" "${SOURCE_DIR}/headless.py")
endif ()
