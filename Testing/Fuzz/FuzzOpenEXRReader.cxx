/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzOpenEXRReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// libFuzzer target for the EXR reading path: vtkOpenEXRReader on the bytes from memory and, when
// it gives an image, vtkEnvironmentMap resampling and querying it. Any input must end in an image
// or a reported error, without a crash, a leak or undefined behaviour, and every message it gives
// must be safe to print (FuzzMessages.h).

#include "FuzzMessages.h"

#include "vtkEnvironmentMap.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenEXRReader.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  // Errors are the expected outcome for most inputs.
  FuzzMessageCheck messages;
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetMemoryBuffer(data);
  reader->SetMemoryBufferLength(static_cast<vtkIdType>(size));
  // Declared sizes are checked before allocation; these keep a run within the fuzzer's memory.
  reader->SetMaximumSide(4096);
  reader->SetMaximumBytes(16 << 20);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (image->GetNumberOfPoints() > 0)
  {
    vtkNew<vtkEnvironmentMap> environment;
    environment->SetImage(image);
    const double up[3] = { 0.0, 0.0, 1.0 };
    double rgb[3];
    environment->Radiance(up, rgb);
    environment->Irradiance(up, rgb);
  }
  return 0;
}
