# Fails when a C++ source of the project differs from what clang-format makes of it with the
# project's .clang-format (VTK 9.1's style). `make format` applies it.
file(GLOB_RECURSE sources
  "${SOURCE_DIR}/Core/*.h" "${SOURCE_DIR}/Core/*.cxx"
  "${SOURCE_DIR}/IO/*.h" "${SOURCE_DIR}/IO/*.cxx"
  "${SOURCE_DIR}/Rendering/*.h" "${SOURCE_DIR}/Rendering/*.cxx"
  "${SOURCE_DIR}/Volume/*.h" "${SOURCE_DIR}/Volume/*.cxx"
  "${SOURCE_DIR}/ParaView/*.h" "${SOURCE_DIR}/ParaView/*.cxx"
  "${SOURCE_DIR}/Testing/*.h" "${SOURCE_DIR}/Testing/*.cxx"
  "${SOURCE_DIR}/Examples/*.h" "${SOURCE_DIR}/Examples/*.cxx")
list(LENGTH sources count)
if (count EQUAL 0)
  message(FATAL_ERROR "No sources found under ${SOURCE_DIR}")
endif ()
execute_process(
  COMMAND "${CLANG_FORMAT}" --style=file --dry-run --Werror ${sources}
  WORKING_DIRECTORY "${SOURCE_DIR}"
  RESULT_VARIABLE result)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "Sources are not formatted; run `make format`.")
endif ()
message(STATUS "${count} sources formatted as .clang-format asks")
