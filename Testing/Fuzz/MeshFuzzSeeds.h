/*=========================================================================

  Program:   ApertureLighting
  Module:    MeshFuzzSeeds.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Small meshes to start fuzzing the mesh path from, each prefixed by FuzzMeshReaders' format
// byte: OBJ with texture seams, quads and normals; PLY ASCII and binary with faces and triangle
// strips; VTP in ASCII, base64 and raw appended encodings, with point and cell data.

#ifndef MeshFuzzSeeds_h
#define MeshFuzzSeeds_h

#include "FuzzReplay.h"

#include <vector>

std::vector<FuzzSeed> MeshFuzzSeeds();

#endif
