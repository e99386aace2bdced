/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderText.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// What the header checks of aperture-render's readers (PLY, NRRD, MetaImage) take as text.

#ifndef ApertureRenderText_h
#define ApertureRenderText_h

#include <algorithm>
#include <string>

namespace ApertureRender
{
// Whether `text` is printable ASCII, tabs and line breaks only: VTK's text parsers run past NUL
// and control bytes, and hand bytes above 0x7f to isspace as negative values.
inline bool IsPrintableText(const std::string& text)
{
  return std::all_of(text.begin(), text.end(),
    [](char c)
    {
      const auto u = static_cast<unsigned char>(c);
      return (u >= 0x20 && u < 0x7f) || c == '\t' || c == '\r' || c == '\n';
    });
}
}

#endif
