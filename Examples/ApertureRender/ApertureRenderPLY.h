/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderPLY.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A PLY file checked before vtkPLYReader reads it: VTK 9.1's reader corrupts its heap on a
// truncated file, so the header is parsed here and the body walked element by element.

#ifndef ApertureRenderPLY_h
#define ApertureRenderPLY_h

#include <string>

namespace ApertureRender
{
// True when the file's header is valid and its body holds every element the header declares;
// otherwise false with one sentence in `error`.
bool CheckPLY(const std::string& name, std::string& error);
}

#endif
