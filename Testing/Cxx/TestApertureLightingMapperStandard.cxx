/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperStandard.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A sphere whose apertures are open (r = pi/2, bent normal = normal) under small lights renders
// in every aperture model as VTK's standard lighting does (mean |difference| <= 2/255), for a
// headlight, a directional sun, a small sphere light and a light kit, with specular highlights;
// closed apertures (r = 0) render dark.

#include "vtkApertureLightingMapper.h"
#include "vtkApertureTestHarness.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <string>

namespace
{
using vtkApertureTest::Check;

vtkSmartPointer<vtkPolyData> Sphere(double radius)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(64);
  source->SetPhiResolution(32);
  source->Update();
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(source->GetOutput());
  vtkNew<vtkFloatArray> bent;
  bent->DeepCopy(sphere->GetPointData()->GetNormals());
  bent->SetName("BentNormal");
  vtkNew<vtkFloatArray> apertures;
  apertures->SetName("ApertureRadius");
  apertures->SetNumberOfTuples(sphere->GetNumberOfPoints());
  apertures->Fill(radius);
  sphere->GetPointData()->AddArray(bent);
  sphere->GetPointData()->AddArray(apertures);
  return sphere;
}
}

int TestApertureLightingMapperStandard(int, char*[])
{
  vtkNew<vtkApertureLightingMapper> mapper;
  mapper->SetInputData(Sphere(0.5 * vtkMath::Pi()));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.7, 0.5);
  actor->GetProperty()->SetSpecular(0.4);
  actor->GetProperty()->SetSpecularPower(30.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  renderer->ResetCamera();

  auto capture = [&](vtkUnsignedCharArray* pixels)
  {
    window->Render();
    window->GetPixelData(0, 0, 199, 199, 1, pixels, 0);
  };

  // Light setups: each takes the renderer's lights down to what it needs.
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(1.0, 0.6, 0.8);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetIntensity(0.9);
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180.0);
  lamp->SetPosition(2.0, 1.5, 3.0);
  lamp->SetIntensity(0.8);
  vtkApertureLightingMapper::SetLightRadius(lamp, 0.005); // world units, about 1 mrad here
  vtkNew<vtkLightKit> kit;
  const std::pair<std::string, std::function<void()>> setups[] = {
    { "headlight", [&]() { renderer->RemoveAllLights(); } },
    { "directional sun",
      [&]()
      {
        renderer->RemoveAllLights();
        renderer->AddLight(sun);
      } },
    { "small sphere light",
      [&]()
      {
        renderer->RemoveAllLights();
        renderer->AddLight(lamp);
      } },
    { "light kit",
      [&]()
      {
        renderer->RemoveAllLights();
        kit->AddLightsToRenderer(renderer);
      } },
  };

  vtkNew<vtkUnsignedCharArray> standard, aperture;
  for (const auto& setup : setups)
  {
    setup.second();
    mapper->SetShadingModeToStandard();
    capture(standard);
    for (int mode = vtkApertureLightingInterface::EXACT;
         mode < vtkApertureLightingInterface::STANDARD; ++mode)
    {
      for (int lambert = 0; lambert < (mode == vtkApertureLightingInterface::EXACT ? 2 : 1);
           ++lambert)
      {
        mapper->SetShadingMode(mode);
        mapper->GetApertureLighting()->SetLambertMode(lambert);
        capture(aperture);
        double sum = 0.0;
        for (vtkIdType i = 0; i < standard->GetNumberOfValues(); ++i)
        {
          sum += std::abs(static_cast<double>(standard->GetValue(i)) - aperture->GetValue(i));
        }
        const double mean = sum / standard->GetNumberOfValues();
        std::cout << setup.first << ", " << mapper->GetApertureLighting()->GetShadingModeAsString()
                  << (lambert ? " (moment)" : "") << ": mean |aperture - standard| = " << mean
                  << "/255\n";
        Check(mean <= 2.0, "open apertures must render as standard lighting");
      }
    }
  }

  // Closed apertures: no light gets in, the highlight too is gone.
  mapper->SetInputData(Sphere(0.0));
  mapper->SetShadingModeToExact();
  setups[1].second();
  capture(aperture);
  int brightest = 0;
  for (vtkIdType i = 0; i < aperture->GetNumberOfValues(); ++i)
  {
    brightest = std::max(brightest, static_cast<int>(aperture->GetValue(i)));
  }
  std::cout << "closed apertures: brightest value " << brightest << "/255\n";
  Check(brightest <= 1, "closed apertures must render dark");
  return vtkApertureTest::Result();
}
