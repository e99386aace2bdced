/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderPLY.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A PLY file checked before vtkPLYReader reads it: VTK 9.1's reader corrupts its heap on a
// truncated file and reads out of bounds through a face's bad vertex index, so the header is
// parsed here and the body walked element by element, every face and strip index checked. The
// reader ignores triangle strips (a "tristrips" element, as scanners write them): they are read
// here.

#ifndef ApertureRenderPLY_h
#define ApertureRenderPLY_h

#include <string>

class vtkCellArray;

namespace ApertureRender
{
// True when the file's header is valid, its body holds every element the header declares and
// every face and strip names existing vertices; otherwise false with one sentence in `error`.
// The file's triangle strips go into `strips` (may be null).
bool CheckPLY(const std::string& name, vtkCellArray* strips, std::string& error);
}

#endif
