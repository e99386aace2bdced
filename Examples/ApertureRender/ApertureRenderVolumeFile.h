/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderVolumeFile.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's volume files: CT and MR volumes (.vti, .mha/.mhd, .nrrd/.nhdr, .nii and
// .nii.gz through VTK's readers, DICOM series from a folder through vtkApertureDICOMReader) read
// into an Input, with one sentence for what cannot be used.

#ifndef ApertureRenderVolumeFile_h
#define ApertureRenderVolumeFile_h

#include <string>

namespace ApertureRender
{
struct Input;
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

}

#endif
