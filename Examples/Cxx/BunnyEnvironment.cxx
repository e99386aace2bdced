/*=========================================================================

  Program:   ApertureLighting
  Module:    BunnyEnvironment.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The Stanford bunny relit by HDR environments from its visibility matrix (Sattler et al. 2004).
//
//   BunnyEnvironment [bunny.obj] [picture.png] [environment.exr ...]
//
// Computes once which of 258 lightsphere directions each vertex sees
// (vtkOcclusionQueryVisibility, on the GPU), then relights it under each environment
// (vtkEnvironmentVisibilityLighting) as the environment turns around it: turning or switching
// the environment never recomputes the visibility. The environments default to the forest and
// sunrise maps. With a picture name (`-` for none) it renders every environment at four turns, one
// row per environment, and exits; otherwise it opens a window where the environment turns: e
// switches environments, +/- change the exposure, q quits.

#include "vtkEnvironmentVisibilityLighting.h"
#include "vtkOcclusionQueryVisibility.h"
#include "vtkOpenEXRReader.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#ifndef APERTURE_EXAMPLE_DATA
#define APERTURE_EXAMPLE_DATA "."
#endif

namespace
{
struct Scene
{
  vtkEnvironmentVisibilityLighting* Relight;
  std::vector<vtkSmartPointer<vtkOpenEXRReader>> Environments;
  std::vector<double> Exposures;
  size_t Current = 0;
  vtkRenderWindow* Window;
};

// The exposure, in stops, that brings the 95th percentile of the relit luminance over a full
// turn of the environment to 0.8 (just below white after gamma): bright but not burnt out.
double AutoExposure(vtkEnvironmentVisibilityLighting* relight)
{
  std::vector<double> luminance;
  for (double azimuth : { 0.0, 90.0, 180.0, 270.0 })
  {
    relight->SetAzimuth(azimuth);
    relight->Update();
    vtkFloatArray* lighting = vtkFloatArray::SafeDownCast(
      relight->GetOutput()->GetPointData()->GetArray("EnvironmentLighting"));
    for (vtkIdType i = 0; i < lighting->GetNumberOfTuples(); ++i)
    {
      const float* c = lighting->GetPointer(3 * i);
      luminance.push_back(0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]);
    }
  }
  relight->SetAzimuth(0.0);
  const auto bright = luminance.begin() + (luminance.size() * 95) / 100;
  std::nth_element(luminance.begin(), bright, luminance.end());
  return *bright > 0.0 ? std::log2(0.8 / *bright) : 0.0;
}

void ShowEnvironment(Scene* scene, size_t which)
{
  scene->Current = which;
  scene->Relight->SetEnvironmentConnection(scene->Environments[which]->GetOutputPort());
  scene->Relight->SetExposure(scene->Exposures[which]);
}

void OnTimer(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* scene = static_cast<Scene*>(clientData);
  scene->Relight->SetAzimuth(std::fmod(scene->Relight->GetAzimuth() + 2.0, 360.0));
  scene->Window->Render();
}

void OnKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* scene = static_cast<Scene*>(clientData);
  const std::string key = static_cast<vtkRenderWindowInteractor*>(caller)->GetKeySym();
  if (key == "e")
  {
    ShowEnvironment(scene, (scene->Current + 1) % scene->Environments.size());
    std::cout << "environment: " << scene->Environments[scene->Current]->GetFileName() << "\n";
  }
  else if (key == "plus" || key == "minus" || key == "KP_Add" || key == "KP_Subtract")
  {
    const double step = (key == "plus" || key == "KP_Add") ? 0.5 : -0.5;
    scene->Exposures[scene->Current] += step;
    scene->Relight->SetExposure(scene->Exposures[scene->Current]);
    std::cout << "exposure: " << scene->Exposures[scene->Current] << " stops\n";
  }
}
}

int main(int argc, char* argv[])
{
  const std::string data = APERTURE_EXAMPLE_DATA;
  const std::string bunny = argc > 1 ? argv[1] : data + "/stanford-bunny.obj";
  const char* picture = argc > 2 && std::string(argv[2]) != "-" ? argv[2] : nullptr;
  std::vector<std::string> files;
  for (int i = 3; i < argc; ++i)
  {
    files.emplace_back(argv[i]);
  }
  if (files.empty())
  {
    files = { data + "/env/forest.exr", data + "/env/sunrise.exr" };
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(360, 360);
  window->SetWindowName("ApertureLighting: bunny under HDR environments");
  if (picture)
  {
    window->SetOffScreenRendering(1);
  }

  // The visibility matrix: 258 directions (lightsphere level 3), rendered in this window's
  // OpenGL context. Computed once, whatever the environments do afterwards.
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(bunny.c_str());
  vtkNew<vtkOcclusionQueryVisibility> visibility;
  visibility->SetInputConnection(reader->GetOutputPort());
  visibility->SetLevel(3);
  visibility->SetRenderWindow(window);
  visibility->Update();
  if (visibility->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "Could not compute the visibility of " << bunny << "\n";
    return 1;
  }

  // The environments, Y up as the bunny is, each with its own exposure.
  vtkNew<vtkEnvironmentVisibilityLighting> relight;
  relight->SetInputConnection(visibility->GetOutputPort());
  relight->SetUpAxisToY();
  Scene scene{ relight, {}, {}, 0, window };
  for (const std::string& file : files)
  {
    vtkNew<vtkOpenEXRReader> environment;
    environment->SetFileName(file.c_str());
    environment->Update();
    if (environment->GetOutput()->GetNumberOfPoints() == 0)
    {
      std::cerr << "Could not read the environment " << file << "\n";
      return 1;
    }
    relight->SetEnvironmentConnection(environment->GetOutputPort());
    scene.Environments.emplace_back(environment);
    scene.Exposures.push_back(AutoExposure(relight));
  }
  ShowEnvironment(&scene, 0);

  // The relit colours drawn as they are: unlit, straight from EnvironmentColors.
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(relight->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("EnvironmentColors");
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.12, 0.13, 0.16);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(-0.02, 0.12, 0.5);
  camera->SetFocalPoint(-0.02, 0.1, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.4);
  window->AddRenderer(renderer);

  if (picture)
  {
    // One row per environment (the first at the top), the environment turned by 0, 90, 180 and
    // 270 degrees along each row.
    vtkNew<vtkImageAppend> rows;
    rows->SetAppendAxis(1);
    for (size_t e = files.size(); e-- > 0;)
    {
      ShowEnvironment(&scene, e);
      vtkNew<vtkImageAppend> row;
      row->SetAppendAxis(0);
      for (double azimuth : { 0.0, 90.0, 180.0, 270.0 })
      {
        relight->SetAzimuth(azimuth);
        window->Render();
        vtkNew<vtkWindowToImageFilter> grab;
        grab->SetInput(window);
        grab->ReadFrontBufferOff();
        grab->Update();
        vtkNew<vtkImageData> frame;
        frame->DeepCopy(grab->GetOutput());
        row->AddInputData(frame);
      }
      row->Update();
      vtkNew<vtkImageData> strip;
      strip->DeepCopy(row->GetOutput());
      rows->AddInputData(strip);
    }
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(rows->GetOutputPort());
    writer->SetFileName(picture);
    writer->Write();
    std::cout << "wrote " << picture << "\n";
    return 0;
  }

  window->SetSize(720, 720);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  vtkNew<vtkCallbackCommand> tick;
  tick->SetClientData(&scene);
  tick->SetCallback(OnTimer);
  interactor->AddObserver(vtkCommand::TimerEvent, tick);
  vtkNew<vtkCallbackCommand> keys;
  keys->SetClientData(&scene);
  keys->SetCallback(OnKey);
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
  window->Render();
  interactor->CreateRepeatingTimer(40);
  std::cout
    << "The environment turns; e: next environment, +/-: exposure, drag to orbit, q: quit\n";
  interactor->Start();
  return 0;
}
