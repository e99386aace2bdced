/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderMesh.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's meshes: OBJ, PLY, STL, VTP and VTK legacy files read with VTK's readers, each
// file checked first where VTK 9.1's reader would crash on it or read it wrongly (OBJ and PLY
// faces naming elements that are not there, truncated PLY and STL, cells past the points). The
// mesh fuzzer reads through the same path.

#ifndef ApertureRenderMesh_h
#define ApertureRenderMesh_h

#include <string>

namespace ApertureRender
{
struct Input;
class MessageCapture;

// Reads a mesh file whose lower-case extension is `extension` into input.Mesh, with its
// description and notes (points that are not finite). Returns false with one sentence in `error`
// when the file cannot be used.
bool LoadMesh(const std::string& name, const std::string& extension, MessageCapture& messages,
  Input& input, std::string& error);
}

#endif
