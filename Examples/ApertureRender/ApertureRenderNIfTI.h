/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderNIfTI.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A NIfTI header checked before vtkNIFTIImageReader reads it: VTK 9.1's reader trusts the header
// of a .nii or .nii.gz file and crashes on a damaged one (found by FuzzVolumeReaders). Its
// fields are checked here, NIfTI-1 and NIfTI-2, in either byte order.

#ifndef ApertureRenderNIfTI_h
#define ApertureRenderNIfTI_h

#include <string>

namespace ApertureRender
{
// True when the file starts with a NIfTI-1 or NIfTI-2 header of a single-file volume ("n+1" or
// "n+2") whose dimensions (1 to 7 axes, each at least 1, at most 2^31 values in all), data
// type and bits, spacings, transforms and scaling are sound and whose data starts after the
// header (and, uncompressed, fits in the file). Otherwise false with one sentence in `error`.
bool CheckNIfTI(const std::string& name, std::string& error);
}

#endif
