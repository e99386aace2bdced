/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzOpenEXRReaderReplay.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The EXR fuzz target without libFuzzer (see FuzzReplay.h): every seed must read as a 16 x 8
// image.

#include "FuzzReplay.h"
#include "OpenEXRFuzzSeeds.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenEXRReader.h"

int main(int argc, char* argv[])
{
  return RunFuzzReplay(argc, argv, OpenEXRFuzzSeeds(), ".exr",
    [](const FuzzSeed& seed)
    {
      vtkNew<vtkOpenEXRReader> reader;
      reader->SetMemoryBuffer(seed.Bytes.data());
      reader->SetMemoryBufferLength(static_cast<vtkIdType>(seed.Bytes.size()));
      reader->Update();
      int dims[3];
      reader->GetOutput()->GetDimensions(dims);
      return dims[0] == 16 && dims[1] == 8 ? std::string() : "does not read as a 16 x 8 image";
    });
}
