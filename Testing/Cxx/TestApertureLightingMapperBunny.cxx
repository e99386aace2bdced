/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperBunny.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The Stanford bunny under a sphere light (a positional light with a world-space radius) and a
// dim sky, in each shading model, left to right: standard, exact, smoothstep, simplified, bent
// normal.

#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestUtilities.h"

int TestApertureLightingMapperBunny(int argc, char* argv[])
{
  char* file = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/stanford-bunny.obj");
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(file);
  delete[] file;
  vtkNew<vtkAperturePrecompute> apertures;
  apertures->SetInputConnection(reader->GetOutputPort());
  apertures->SetNumberOfRays(128);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(1250, 250);
  window->SetMultiSamples(0);
  const int modes[] = { vtkApertureLightingInterface::STANDARD, vtkApertureLightingInterface::EXACT,
    vtkApertureLightingInterface::SMOOTHSTEP, vtkApertureLightingInterface::SIMPLIFIED,
    vtkApertureLightingInterface::BENT_NORMAL };
  for (int i = 0; i < 5; ++i)
  {
    vtkNew<vtkApertureLightingMapper> mapper;
    mapper->SetInputConnection(apertures->GetOutputPort());
    mapper->SetShadingMode(modes[i]);
    mapper->SetSkyColor(0.6, 0.7, 1.0);
    mapper->SetSkyIntensity(0.2);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.95, 0.85, 0.75);
    actor->GetProperty()->SetSpecular(0.2);
    actor->GetProperty()->SetSpecularPower(20.0);

    // A sphere light of radius 0.05 up and to the right of the bunny (about 0.2 away).
    vtkNew<vtkLight> lamp;
    lamp->SetLightTypeToSceneLight();
    lamp->SetPositional(true);
    lamp->SetConeAngle(180.0);
    lamp->SetPosition(0.15, 0.28, 0.15);
    lamp->SetIntensity(0.9);
    vtkApertureLightingMapper::SetLightRadius(lamp, 0.05);

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.2 * i, 0.0, 0.2 * (i + 1), 1.0);
    renderer->SetBackground(0.25, 0.28, 0.33);
    renderer->AddActor(actor);
    renderer->AddLight(lamp);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(-0.02, 0.1, 0.0);
    camera->SetPosition(-0.02, 0.12, 0.5);
    window->AddRenderer(renderer);
    renderer->ResetCamera();
    camera->Zoom(1.3);
  }
  window->Render();
  const int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
