/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzVolumeReadersReplay.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The volume fuzz target without libFuzzer (see FuzzReplay.h): every seed must read as a volume
// or a height field.

#include "ApertureRenderInput.h"
#include "FuzzReplay.h"
#include "FuzzVolumeReaders.h"
#include "VolumeFuzzSeeds.h"

#include "vtkImageData.h"

int main(int argc, char* argv[])
{
  return RunFuzzReplay(argc, argv, VolumeFuzzSeeds(), ".volume",
    [](const FuzzSeed& seed)
    {
      ApertureRender::Input input;
      std::string error;
      const bool read = ReadFuzzVolume(
        reinterpret_cast<const std::uint8_t*>(seed.Bytes.data()), seed.Bytes.size(), input, error);
      return read && (input.Volume || input.Heights) ? std::string()
                                                     : "does not read as a volume: " + error;
    });
}
