/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderMetaImage.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A MetaImage header checked before vtkMetaImageReader reads it: VTK 9.1's MetaIO copies a field
// name of any length into a 255-byte buffer (found by FuzzVolumeReaders), so the header is parsed
// here, line by line up to ElementDataFile, and only what MetaIO reads safely passes.

#ifndef ApertureRenderMetaImage_h
#define ApertureRenderMetaImage_h

#include <string>

namespace ApertureRender
{
// True when the file starts with a MetaImage header of "Name = Value" lines in printable ASCII,
// names shorter than 255 characters, NDims of 1 to 3 before DimSize's as many positive counts
// (at most 2^31 values in all), at most 4 channels, and an ElementDataFile that is LOCAL or one
// file that exists. Otherwise false with one sentence in `error`.
bool CheckMetaImage(const std::string& name, std::string& error);
}

#endif
