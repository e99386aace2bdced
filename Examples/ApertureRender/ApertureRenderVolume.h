/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderVolume.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's volumes (read by ApertureRenderVolumeFile.h): an opacity preset or ramp, and
// the picture drawn by vtkApertureVolumeMapper (or, with --iso, an isosurface handed to the mesh
// pipeline).

#ifndef ApertureRenderVolume_h
#define ApertureRenderVolume_h

#include <string>

namespace ApertureRender
{
struct Input;
struct Options;
class MessageCapture;

// --iso: the isosurface of input.Volume at options.Iso becomes input.Mesh. False with one
// sentence in `error` when it is empty.
bool ContourVolume(const Options& options, Input& input, std::string& error);

// Draws input.Volume: the picture to -o, the window with -i. Returns the exit status.
int ShowVolume(const Options& options, const Input& input, MessageCapture& messages);
}

#endif
