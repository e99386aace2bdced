/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzGDALDEMReaderReplay.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The DEM fuzz target without libFuzzer (see FuzzReplay.h): every seed must read as a height
// field of at least 4 x 3 texels.

#include "FuzzReplay.h"
#include "GDALFuzzSeeds.h"

#include "vtkGDALDEMReader.h"
#include "vtkImageData.h"
#include "vtkNew.h"

#include <cpl_vsi.h>

int main(int argc, char* argv[])
{
  return RunFuzzReplay(argc, argv, GDALFuzzSeeds(), ".tif",
    [](const FuzzSeed& seed)
    {
      const char* name = "/vsimem/seed.tif";
      VSIFCloseL(VSIFileFromMemBuffer(name,
        reinterpret_cast<GByte*>(const_cast<char*>(seed.Bytes.data())), seed.Bytes.size(), FALSE));
      vtkNew<vtkGDALDEMReader> reader;
      reader->SetFileName(name);
      reader->Update();
      VSIUnlink(name);
      int dims[3];
      reader->GetOutput()->GetDimensions(dims);
      return dims[0] >= 4 && dims[1] >= 3 ? std::string() : "does not read as a height field";
    });
}
