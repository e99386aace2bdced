/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzMeshReaders.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The mesh fuzz target's input: a format byte (0: OBJ, 1: PLY, 2: VTP, modulo 3), then the file.

#ifndef FuzzMeshReaders_h
#define FuzzMeshReaders_h

#include <cstddef>
#include <cstdint>
#include <string>

namespace ApertureRender
{
struct Input;
}

// Reads `data` as aperture-render reads a mesh file (through a file of this process's own, since
// VTK's readers read files). False with one sentence in `error` when it is not a usable mesh.
bool ReadFuzzMesh(
  const std::uint8_t* data, std::size_t size, ApertureRender::Input& input, std::string& error);

#endif
