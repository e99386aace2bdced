# Builds and runs the downstream project against the build tree's package and against an
# installed copy, then imports the Python package from that installation.
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

foreach (kind IN ITEMS build install)
  if (kind STREQUAL "build")
    set(package_dir "${build_dir}")
  else ()
    set(package_dir "${installed_dir}")
  endif ()
  set(binary "${WORK_DIR}/${kind}")
  message(STATUS "Downstream project against the ${kind} tree: ${package_dir}")
  run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${binary}"
    "-DCMAKE_BUILD_TYPE=${CONFIG}" "-DApertureLighting_DIR=${package_dir}")
  run("${CMAKE_COMMAND}" --build "${binary}" --config "${CONFIG}")
  find_program(exe downstream PATHS "${binary}" "${binary}/${CONFIG}" NO_DEFAULT_PATH)
  run("${exe}")
  unset(exe CACHE)
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
endif ()
