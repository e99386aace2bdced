# Writes a C++ source that holds a file's bytes as an array, for aperture-render's embedded
# default scene. Run as: cmake -DINPUT=file -DOUTPUT=file.cxx -DNAME=Symbol -P EmbedFile.cmake
file(READ "${INPUT}" _hex HEX)
string(LENGTH "${_hex}" _length)
math(EXPR _size "${_length} / 2")
# Sixteen bytes per line.
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," _bytes "${_hex}")
string(REPEAT "0x..," 16 _line)
string(REGEX REPLACE "(${_line})" "\\1\n  " _bytes "${_bytes}")
get_filename_component(_name "${INPUT}" NAME)
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${_name} by EmbedFile.cmake; do not edit.\n"
  "#include <cstddef>\n\n"
  "namespace ApertureRender\n{\n"
  "extern const unsigned char ${NAME}[];\n"
  "extern const std::size_t ${NAME}Size;\n"
  "const unsigned char ${NAME}[] = {\n  ${_bytes}\n};\n"
  "const std::size_t ${NAME}Size = ${_size};\n}\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
