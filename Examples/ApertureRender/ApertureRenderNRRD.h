/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderNRRD.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A NRRD header checked before vtkNrrdReader reads it: VTK 9.1's reader trusts its header. One
// whose last line has no line break hangs it; a file pattern with a zero step loops forever and
// hands its name to printf as the format; sizes before the dimension, or none, make it index an
// empty vector; an empty origin or data file reads out of bounds. The header is parsed here as
// the reader parses it, and only what it reads safely passes.

#ifndef ApertureRenderNRRD_h
#define ApertureRenderNRRD_h

#include <string>

namespace ApertureRender
{
// True when the file's header is one vtkNrrdReader reads safely: ended by a line break, a
// dimension of 1 to 4 before sizes of as many positive counts (at most 2^31 values in all),
// fields in printable ASCII, an origin where one is given, and its data in the file or in one
// named file. Otherwise false with one sentence in `error`.
bool CheckNRRD(const std::string& name, std::string& error);
}

#endif
