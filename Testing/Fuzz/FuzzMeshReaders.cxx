/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzMeshReaders.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// libFuzzer target for the mesh path: the first byte picks a format (.obj, .ply or .vtp), the
// rest is the file, read as aperture-render reads it (VTK's readers behind the checks they need)
// and, when it gives a mesh, vtkAperturePrecompute on it, and the mappers' checks and packing of
// the arrays beyond one cap that a file may hold (HorizonAngles, VisibilityMask: any type, count
// or value). Any input must end in apertures or a reported error, without a crash, a leak or
// undefined behaviour; the error, and every message of the precompute and the checks, must be
// safe to print (FuzzMessages.h).

#include "FuzzMeshReaders.h"
#include "FuzzFile.h"
#include "FuzzMessages.h"

#include "ApertureRenderInput.h"
#include "ApertureRenderMesh.h"
#include "ApertureRenderMessages.h"

#include "vtkApertureLightingInterface.h"
#include "vtkAperturePrecompute.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace
{
// What the mappers do with a dataset's horizons and masks before they draw: check them, and pack
// what passes for the vertex buffers.
void PackBeyondOneCap(vtkDataSet* mesh)
{
  vtkNew<vtkApertureLightingInterface> lighting;
  for (int mode :
    { vtkApertureLightingInterface::HORIZON, vtkApertureLightingInterface::VISIBILITY_MASK })
  {
    lighting->SetShadingMode(mode);
    const int layout = lighting->CheckPackedLayout(mesh);
    if (layout > 0)
    {
      std::vector<vtkSmartPointer<vtkFloatArray>> attributes;
      lighting->PackAttributes(mesh, layout, attributes);
    }
  }
}
}

bool ReadFuzzMesh(
  const std::uint8_t* data, std::size_t size, ApertureRender::Input& input, std::string& error)
{
  const FuzzFile file(data, size, { ".obj", ".ply", ".vtp" });
  if (file.GetName().empty())
  {
    error = "no format byte";
    return false;
  }
  ApertureRender::MessageCapture messages;
  return ApertureRender::LoadMesh(file.GetName(), file.GetExtension(), messages, input, error);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  // Errors are the expected outcome for most inputs. While reading, VTK's readers' messages are
  // collected (and escaped) by the reading path itself.
  vtkObject::GlobalWarningDisplayOff();
  ApertureRender::Input input;
  std::string error;
  if (!ReadFuzzMesh(data, size, input, error))
  {
    FuzzMessageCheck::Require(error, "mesh reading error");
  }
  else
  {
    FuzzMessageCheck messages;
    PackBeyondOneCap(input.Mesh);
    vtkNew<vtkAperturePrecompute> apertures;
    apertures->SetInputData(input.Mesh);
    apertures->SetNumberOfRays(4);
    apertures->Update();
  }
  return 0;
}
