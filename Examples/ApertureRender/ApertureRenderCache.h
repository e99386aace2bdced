/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderCache.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's --cache: the precomputed apertures in a VTK XML file (.vtp for meshes, .vti
// for height fields) with a fingerprint of what they were computed from.

#ifndef ApertureRenderCache_h
#define ApertureRenderCache_h

#include "vtkDataObject.h"
#include "vtkSmartPointer.h"

#include <string>

namespace ApertureRender
{
struct Input;
struct Options;
class MessageCapture;

// A fingerprint of what the apertures depend on: the geometry (points and cells, or the grid and
// its heights), the vertical scale, the number of rays and this program's version.
std::string Fingerprint(const Input& input, const Options& options);

// The apertures cached in `path` when they were made for `fingerprint`; otherwise nullptr, with
// the reason in `note` (empty when there is no cache yet).
vtkSmartPointer<vtkDataObject> ReadCache(const std::string& path, const std::string& fingerprint,
  bool heightField, MessageCapture& messages, std::string& note);

// Stores the apertures in `path`; false with one sentence in `error` when it cannot.
bool WriteCache(const std::string& path, vtkDataObject* apertures, const std::string& fingerprint,
  MessageCapture& messages, std::string& error);
}

#endif
