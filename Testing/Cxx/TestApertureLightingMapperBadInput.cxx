/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperBadInput.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkApertureLightingMapper with missing or malformed aperture arrays (absent, wrong component
// count, wrong size, NaN or infinite values, an aperture image without arrays) and odd light
// radii: one warning, standard shading, never black, no crash.

#include "vtkApertureLightingMapper.h"
#include "vtkApertureTestHarness.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

namespace
{
using vtkApertureTest::Check;

// A sphere with valid apertures; `spoil` then breaks them.
vtkSmartPointer<vtkPolyData> Sphere(const std::function<void(vtkPolyData*)>& spoil)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(32);
  source->SetPhiResolution(16);
  source->Update();
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(source->GetOutput());
  vtkNew<vtkFloatArray> bent;
  bent->DeepCopy(sphere->GetPointData()->GetNormals());
  bent->SetName("BentNormal");
  vtkNew<vtkFloatArray> radius;
  radius->SetName("ApertureRadius");
  radius->SetNumberOfTuples(sphere->GetNumberOfPoints());
  radius->Fill(0.5);
  sphere->GetPointData()->AddArray(bent);
  sphere->GetPointData()->AddArray(radius);
  spoil(sphere);
  return sphere;
}

// A per-texel aperture grid of nx x ny texels, all open to the sky above.
vtkSmartPointer<vtkImageData> ApertureGrid(int nx, int ny)
{
  auto grid = vtkSmartPointer<vtkImageData>::New();
  grid->SetDimensions(nx, ny, 1);
  vtkNew<vtkFloatArray> bent;
  bent->SetName("BentNormal");
  bent->SetNumberOfComponents(3);
  bent->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    bent->SetTuple3(i, 0.0, 0.0, 1.0);
  }
  vtkNew<vtkFloatArray> radius;
  radius->SetName("ApertureRadius");
  radius->SetNumberOfTuples(grid->GetNumberOfPoints());
  radius->Fill(1.5);
  grid->GetPointData()->AddArray(bent);
  grid->GetPointData()->AddArray(radius);
  return grid;
}
}

int TestApertureLightingMapperBadInput(int, char*[])
{
  vtkNew<vtkApertureLightingMapper> mapper;
  vtkNew<vtkTest::ErrorObserver> observer;
  mapper->GetApertureLighting()->AddObserver(vtkCommand::WarningEvent, observer);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(150, 150);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  renderer->ResetCamera();

  auto capture = [&](vtkUnsignedCharArray* pixels)
  {
    window->Render();
    window->GetPixelData(0, 0, 149, 149, 1, pixels, 0);
  };
  vtkNew<vtkUnsignedCharArray> standard, image;
  mapper->SetInputData(Sphere([](vtkPolyData*) {}));
  mapper->SetShadingModeToStandard();
  capture(standard);

  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  struct Case
  {
    std::string Name, Warning;
    std::function<void(vtkPolyData*)> Spoil;
  };
  const Case cases[] = {
    { "no arrays", "no point-data array named 'BentNormal'",
      [](vtkPolyData* pd)
      {
        pd->GetPointData()->RemoveArray("BentNormal");
        pd->GetPointData()->RemoveArray("ApertureRadius");
      } },
    { "two-component bent normals", "components",
      [](vtkPolyData* pd)
      {
        vtkNew<vtkFloatArray> flat;
        flat->SetName("BentNormal");
        flat->SetNumberOfComponents(2);
        flat->SetNumberOfTuples(pd->GetNumberOfPoints());
        flat->Fill(0.0);
        pd->GetPointData()->AddArray(flat);
      } },
    { "too few radii", "tuples",
      [](vtkPolyData* pd)
      {
        vtkDataArray::SafeDownCast(pd->GetPointData()->GetArray("ApertureRadius"))
          ->SetNumberOfTuples(pd->GetNumberOfPoints() / 2);
      } },
    { "NaN radius", "non-finite",
      [nan](vtkPolyData* pd)
      { pd->GetPointData()->GetArray("ApertureRadius")->SetComponent(7, 0, nan); } },
    { "infinite bent normal", "non-finite",
      [inf](vtkPolyData* pd)
      { pd->GetPointData()->GetArray("BentNormal")->SetComponent(3, 1, inf); } },
  };

  auto judge = [&](const std::string& name, const std::string& warning)
  {
    capture(image);
    double diff = 0.0, lit = 0.0;
    for (vtkIdType i = 0; i < image->GetNumberOfValues(); ++i)
    {
      diff += std::abs(static_cast<double>(image->GetValue(i)) - standard->GetValue(i));
      lit += image->GetValue(i);
    }
    diff /= image->GetNumberOfValues();
    lit /= image->GetNumberOfValues();
    const bool warned = observer->GetWarningMessage().find(warning) != std::string::npos;
    std::cout << name << ": warned " << warned << ", mean |image - standard| " << diff
              << "/255, mean value " << lit << "/255\n";
    Check(warned && diff <= 0.5 && lit >= 10.0, name + ": needs one warning and standard shading");
    observer->Clear();
  };

  mapper->SetShadingModeToExact();
  for (const Case& c : cases)
  {
    mapper->SetInputData(Sphere(c.Spoil));
    judge(c.Name, c.Warning);
  }

  // An aperture image without aperture arrays.
  vtkNew<vtkImageData> empty;
  empty->SetDimensions(4, 4, 1);
  empty->AllocateScalars(VTK_FLOAT, 1);
  mapper->SetInputData(Sphere([](vtkPolyData*) {}));
  mapper->SetApertureImage(empty);
  judge("aperture image without arrays", "no point-data array named 'BentNormal'");

  // An aperture grid wider than the context's textures: one warning, however many frames.
  const int largest =
    vtkTextureObject::GetMaximumTextureSize(vtkOpenGLRenderWindow::SafeDownCast(window));
  mapper->SetApertureImage(ApertureGrid(largest + 1, 2));
  judge("aperture grid wider than the textures", "larger than this OpenGL's textures");
  window->Render();
  Check(!observer->GetWarning(), "a grid too wide for the textures must warn only once");
  mapper->SetApertureImage(ApertureGrid(16, 2));
  capture(image);
  Check(!observer->GetWarning(), "a grid that fits must shade without a warning");
  mapper->SetApertureImage(nullptr);

  // The same problem twice warns once.
  mapper->SetInputData(Sphere(cases[0].Spoil));
  capture(image);
  observer->Clear();
  window->Render();
  Check(!observer->GetWarning(), "a persisting problem must warn only once");

  // Odd light radii: negative (no radius: the default), huge (clamped to a hemisphere).
  mapper->SetInputData(Sphere([](vtkPolyData*) {}));
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1, 1, 1);
  renderer->AddLight(light);
  for (double radius : { -3.0, 100.0, std::numeric_limits<double>::quiet_NaN() })
  {
    vtkApertureLightingMapper::SetLightRadius(light, radius);
    capture(image);
    double lit = 0.0;
    for (vtkIdType i = 0; i < image->GetNumberOfValues(); ++i)
    {
      lit += image->GetValue(i);
    }
    std::cout << "light radius " << radius << ": mean value " << lit / image->GetNumberOfValues()
              << "/255\n";
    Check(lit / image->GetNumberOfValues() >= 5.0, "odd light radii must still light the sphere");
  }
  return vtkApertureTest::Result();
}
