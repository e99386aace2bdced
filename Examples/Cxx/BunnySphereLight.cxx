/*=========================================================================

  Program:   ApertureLighting
  Module:    BunnySphereLight.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The Stanford bunny lit by a sphere light through ambient aperture lighting.
//
//   BunnySphereLight [bunny.obj] [picture.png]
//
// Computes the apertures once (vtkAperturePrecompute), then draws them with
// vtkApertureLightingMapper. With a picture name it renders that picture off screen and exits;
// otherwise it opens a window: press m to switch shading models, l/L to shrink or grow the
// light, q to quit.

#include "vtkApertureLightingInterface.h"
#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPNGWriter.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <iostream>
#include <string>

#ifndef APERTURE_EXAMPLE_DATA
#define APERTURE_EXAMPLE_DATA "."
#endif

namespace
{
struct Scene
{
  vtkApertureLightingMapper* Mapper;
  vtkLight* Light;
  vtkRenderWindow* Window;
};

void OnKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* scene = static_cast<Scene*>(clientData);
  const std::string key = static_cast<vtkRenderWindowInteractor*>(caller)->GetKeySym();
  if (key == "m")
  {
    const int modes = vtkApertureLightingInterface::STANDARD + 1;
    const int next = (scene->Mapper->GetShadingMode() + 1) % modes;
    scene->Mapper->SetShadingMode(next);
    std::cout << "shading: " << scene->Mapper->GetApertureLighting()->GetShadingModeAsString()
              << "\n";
  }
  else if (key == "l" || key == "L")
  {
    const double radius = vtkApertureLightingMapper::GetLightRadius(scene->Light);
    vtkApertureLightingMapper::SetLightRadius(
      scene->Light, key == "l" ? radius / 1.5 : radius * 1.5);
    std::cout << "light radius: " << vtkApertureLightingMapper::GetLightRadius(scene->Light)
              << "\n";
  }
  scene->Window->Render();
}
}

int main(int argc, char* argv[])
{
  const std::string bunny =
    argc > 1 ? argv[1] : std::string(APERTURE_EXAMPLE_DATA) + "/stanford-bunny.obj";
  const char* picture = argc > 2 ? argv[2] : nullptr;

  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(bunny.c_str());

  // The apertures: one visibility cap per vertex, 256 rays each.
  vtkNew<vtkAperturePrecompute> apertures;
  apertures->SetInputConnection(reader->GetOutputPort());
  apertures->SetNumberOfRays(256);
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(
    [](vtkObject*, unsigned long, void*, void* callData)
    {
      std::printf("\rapertures: %3.0f%%", 100.0 * *static_cast<double*>(callData));
      std::fflush(stdout);
    });
  apertures->AddObserver(vtkCommand::ProgressEvent, progress);
  apertures->Update();
  std::printf("\n");
  if (apertures->GetPolyDataOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "Could not compute apertures for " << bunny << "\n";
    return 1;
  }

  vtkNew<vtkApertureLightingMapper> mapper;
  mapper->SetInputConnection(apertures->GetOutputPort());
  mapper->SetShadingModeToExact();
  mapper->SetSkyColor(0.55, 0.65, 1.0);
  mapper->SetSkyIntensity(0.25);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.95, 0.85, 0.75);

  // A sphere light of radius 0.04 to the upper right: a positional light whose size travels on it.
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180.0);
  lamp->SetPosition(0.2, 0.25, 0.1);
  lamp->SetColor(1.0, 0.9, 0.75);
  vtkApertureLightingMapper::SetLightRadius(lamp, 0.04);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AddLight(lamp);
  renderer->SetBackground(0.12, 0.13, 0.16);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(-0.02, 0.12, 0.5);
  camera->SetFocalPoint(-0.02, 0.1, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.4);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 700);
  window->AddRenderer(renderer);
  window->SetWindowName("ApertureLighting: bunny and sphere light");

  if (picture)
  {
    window->SetOffScreenRendering(1);
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(picture);
    writer->Write();
    std::cout << "wrote " << picture << "\n";
    return 0;
  }

  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  Scene scene{ mapper, lamp, window };
  vtkNew<vtkCallbackCommand> keys;
  keys->SetCallback(OnKey);
  keys->SetClientData(&scene);
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
  std::cout << "m: shading model, l/L: smaller/larger light, q: quit\n";
  window->Render();
  interactor->Start();
  return 0;
}
