/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzMeshReadersReplay.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The mesh fuzz target without libFuzzer (see FuzzReplay.h): every seed must read as a mesh
// with polygons or strips.

#include "ApertureRenderInput.h"
#include "FuzzMeshReaders.h"
#include "FuzzReplay.h"
#include "MeshFuzzSeeds.h"

#include "vtkPolyData.h"

int main(int argc, char* argv[])
{
  return RunFuzzReplay(argc, argv, MeshFuzzSeeds(), ".mesh",
    [](const FuzzSeed& seed)
    {
      ApertureRender::Input input;
      std::string error;
      const bool read = ReadFuzzMesh(
        reinterpret_cast<const std::uint8_t*>(seed.Bytes.data()), seed.Bytes.size(), input, error);
      return read && input.Mesh->GetNumberOfCells() > 0 ? std::string()
                                                        : "does not read as a mesh: " + error;
    });
}
