/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzVolumeReaders.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// libFuzzer target for the volume path: the first byte picks a format (.vti, .mha, .nrrd, .nii
// or .nii.gz), the rest is the file, read as aperture-render reads it (VTK's readers behind the
// checks it makes) and, when it gives a small volume, vtkVolumeAperturePrecompute on it under an
// opacity ramp over its scalars (a height field from a flat .vti gets vtkAperturePrecompute's
// horizons). Any input must end in apertures or a reported error, without a crash, a leak or
// undefined behaviour; the error, and every message of the precomputes, must be safe to print
// (FuzzMessages.h).

#include "FuzzVolumeReaders.h"
#include "FuzzFile.h"
#include "FuzzMessages.h"

#include "ApertureRenderInput.h"
#include "ApertureRenderMessages.h"
#include "ApertureRenderVolumeFile.h"

#include "vtkAperturePrecompute.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkVolumeAperturePrecompute.h"
#include "vtkVolumeProperty.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace
{
// Work stays small: larger volumes and fields are read, not lit.
constexpr vtkIdType MaximumPoints = 32 * 32 * 32;

void LightVolume(vtkImageData* volume)
{
  double range[2];
  volume->GetPointData()->GetScalars()->GetRange(range);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[1], 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  vtkNew<vtkVolumeAperturePrecompute> apertures;
  apertures->SetInputData(volume);
  apertures->SetVolumeProperty(property);
  apertures->SetNumberOfDirections(8);
  apertures->Update();
}
}

bool ReadFuzzVolume(
  const std::uint8_t* data, std::size_t size, ApertureRender::Input& input, std::string& error)
{
  const FuzzFile file(data, size, { ".vti", ".mha", ".nrrd", ".nii", ".nii.gz" });
  if (file.GetName().empty())
  {
    error = "no format byte";
    return false;
  }
  ApertureRender::MessageCapture messages;
  return ApertureRender::LoadVolume(file.GetName(), messages, input, error);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  // Errors are the expected outcome for most inputs. While reading, VTK's readers' messages are
  // collected (and escaped) by the reading path itself.
  vtkObject::GlobalWarningDisplayOff();
  ApertureRender::Input input;
  std::string error;
  if (!ReadFuzzVolume(data, size, input, error))
  {
    FuzzMessageCheck::Require(error, "volume reading error");
    return 0;
  }
  FuzzMessageCheck messages;
  if (input.Volume && input.Volume->GetNumberOfPoints() <= MaximumPoints)
  {
    LightVolume(input.Volume);
  }
  else if (input.Heights && input.Heights->GetNumberOfPoints() <= MaximumPoints)
  {
    vtkNew<vtkAperturePrecompute> horizons;
    horizons->SetInputData(input.Heights);
    horizons->SetNumberOfSectors(4);
    horizons->Update();
  }
  return 0;
}
