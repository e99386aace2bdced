/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderOBJ.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// An OBJ file checked before vtkOBJReader reads it: VTK 9.1's reader writes outside its texture
// coordinates for a face that names one that is not there, reads a word ending in '/' together
// with the next one (its sscanf skips the space between), copies a material name into a 100-byte
// buffer, and looks up an undefined material for a textured face before the first usemtl. The
// file is read here line by line, as the reader tokenises it, and such files refused.

#ifndef ApertureRenderOBJ_h
#define ApertureRenderOBJ_h

#include <string>

namespace ApertureRender
{
// True when every v, vt and vn line holds its numbers and every face, line and point names
// elements the file has (positive from the start, negative back from the last one read), in words
// the reader reads alone, and the materials are as the reader needs them; otherwise false with one
// sentence in `error`.
bool CheckOBJ(const std::string& name, std::string& error);
}

#endif
