/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperTerrain.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Mount Fuji under a low sun and a blue sky, in each shading model, left to right: standard,
// exact, smoothstep, simplified, bent normal. The cast shadow of the summit and the dark valleys
// appear in the aperture models only.

#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"
#include "vtkTerrainRGBReader.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkExtractVOI.h"
#include "vtkImageDataGeometryFilter.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestUtilities.h"
#include "vtkWarpScalar.h"

int TestApertureLightingMapperTerrain(int argc, char* argv[])
{
  char* file = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/fuji-terrain-rgb.png");
  vtkNew<vtkTerrainRGBReader> reader;
  reader->SetFileName(file);
  reader->SetSpacing(60.0, 60.0);
  delete[] file;
  vtkNew<vtkExtractVOI> sample;
  sample->SetInputConnection(reader->GetOutputPort());
  sample->SetSampleRate(2, 2, 1);
  vtkNew<vtkImageDataGeometryFilter> surface;
  surface->SetInputConnection(sample->GetOutputPort());
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputConnection(surface->GetOutputPort());
  vtkNew<vtkAperturePrecompute> apertures;
  apertures->SetInputConnection(warp->GetOutputPort());
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
    mapper->ScalarVisibilityOff();
    mapper->SetShadingMode(modes[i]);
    mapper->SetSkyColor(0.55, 0.7, 1.0);
    mapper->SetSkyIntensity(0.35);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.85, 0.8, 0.7);

    // A sun 10 degrees above the western horizon, the size of the real one.
    vtkNew<vtkLight> sun;
    sun->SetLightTypeToSceneLight();
    sun->SetPosition(-1.0, 0.2, 0.18);
    sun->SetFocalPoint(0.0, 0.0, 0.0);
    sun->SetColor(1.0, 0.93, 0.8);
    sun->SetIntensity(1.1);
    vtkApertureLightingMapper::SetLightRadius(sun, 0.0047);

    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.2 * i, 0.0, 0.2 * (i + 1), 1.0);
    renderer->SetBackground(0.45, 0.55, 0.7);
    renderer->AddActor(actor);
    renderer->AddLight(sun);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(15000, 16000, 1000);
    camera->SetPosition(15000, -9000, 19000);
    camera->SetViewUp(0, 0, 1);
    window->AddRenderer(renderer);
    renderer->ResetCamera();
    camera->Zoom(1.45);
  }
  window->Render();
  const int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
