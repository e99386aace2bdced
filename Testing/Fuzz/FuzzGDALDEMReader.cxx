/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzGDALDEMReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// libFuzzer target for the DEM reading path: the bytes as a file GDAL opens (in GDAL's memory
// file system), vtkGDALDEMReader on at most 64 x 64 texels of it (the update extent, as a tiled
// pipeline asks), then vtkAperturePrecompute's horizon sweeps on what it read. Any input must end
// in a height field or a reported error, without a crash, a leak or undefined behaviour, and every
// message it gives must be safe to print (FuzzMessages.h).

#include "FuzzMessages.h"

#include "vtkAperturePrecompute.h"
#include "vtkGDALDEMReader.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cpl_vsi.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  // Errors are the expected outcome for most inputs.
  FuzzMessageCheck messages;
  const char* name = "/vsimem/fuzz.tif";
  VSILFILE* file = VSIFileFromMemBuffer(name, const_cast<GByte*>(data), size, FALSE);
  if (!file)
  {
    return 0;
  }
  VSIFCloseL(file);
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(name);
  reader->UpdateInformation();
  int whole[6] = { 0, -1, 0, -1, 0, 0 };
  reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  if (whole[1] >= whole[0] && whole[3] >= whole[2])
  {
    const int extent[6] = { whole[0], std::min(whole[1], whole[0] + 63), whole[2],
      std::min(whole[3], whole[2] + 63), 0, 0 };
    reader->UpdateExtent(extent);
    vtkNew<vtkAperturePrecompute> horizons;
    horizons->SetInputData(reader->GetOutput());
    horizons->SetNumberOfSectors(4);
    horizons->Update();
  }
  VSIUnlink(name);
  return 0;
}
