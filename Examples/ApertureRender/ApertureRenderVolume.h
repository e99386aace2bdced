/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderVolume.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's volumes: reading CT and MR files (.vti, .mha/.mhd, .nrrd/.nhdr, .nii and
// .nii.gz through VTK's readers, DICOM series from a folder through vtkApertureDICOMReader), an
// opacity preset or ramp, and the picture drawn by
// vtkApertureVolumeMapper (or, with --iso, an isosurface handed to the mesh pipeline).

#ifndef ApertureRenderVolume_h
#define ApertureRenderVolume_h

#include <string>

namespace ApertureRender
{
struct Input;
struct Options;
class MessageCapture;

// Whether `name` has the extension of a volume format (a .vti may still hold a height field).
bool IsVolumeFile(const std::string& name);

// Reads a volume into input.Volume; a 2D .vti (one slice) becomes input.Heights instead. False
// with one sentence in `error` when the file cannot be used.
bool LoadVolume(
  const std::string& name, MessageCapture& messages, Input& input, std::string& error);

// Reads the DICOM series of a folder into input.Volume. False with one sentence in `error` when
// the folder holds none, several, or one with missing slices.
bool LoadDICOM(
  const std::string& folder, MessageCapture& messages, Input& input, std::string& error);

// --iso: the isosurface of input.Volume at options.Iso becomes input.Mesh. False with one
// sentence in `error` when it is empty.
bool ContourVolume(const Options& options, Input& input, std::string& error);

// Draws input.Volume: the picture to -o, the window with -i. Returns the exit status.
int ShowVolume(const Options& options, const Input& input, MessageCapture& messages);
}

#endif
