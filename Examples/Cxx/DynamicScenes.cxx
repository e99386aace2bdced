/*=========================================================================

  Program:   ApertureLighting
  Module:    DynamicScenes.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Visibility kept current while things move (Sattler et al. 2004, §4 and §6), driven by
// vtkDynamicVisibilityDriver:
//
//   DynamicScenes deform [environment.exr] [picture.png]
//   DynamicScenes orbit [bunny.obj] [environment.exr] [picture.png]
//
// deform: a rippling ball, its visibility recomputed every frame at a coarse lightsphere level
// chosen to keep each update under 50 ms, relit by an HDR environment; when the animation stops
// (space), idle frames refine the lightsphere up to k = 258.
// orbit: the camera circles the Stanford bunny with vertex filtering on: each frame computes
// visibility (k = 66 while moving) only for the points of triangles coming into view.
// With a picture name the example runs a fixed animation, prints what each frame computed, writes
// a strip of frames and exits; otherwise it opens a window (space: pause or resume, q: quit).

#include "vtkDynamicVisibilityDriver.h"
#include "vtkEnvironmentVisibilityLighting.h"
#include "vtkOcclusionQueryVisibility.h"
#include "vtkOpenEXRReader.h"

#include "vtkActor.h"
#include "vtkArrayCalculator.h"
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
#include "vtkSphereSource.h"
#include "vtkWarpScalar.h"
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
struct Animation
{
  bool Orbit = false;
  bool Running = true;
  int Frame = 0;
  int TimerId = -1;
  vtkArrayCalculator* Ripple = nullptr;
  vtkRenderer* Renderer = nullptr;
  vtkOcclusionQueryVisibility* Visibility = nullptr;
  vtkDynamicVisibilityDriver* Driver = nullptr;
};

// The ripple's phase for a frame: rings running from pole to pole.
void SetPhase(vtkArrayCalculator* ripple, double phase)
{
  ripple->SetFunction(("0.18*sin(14*coordsZ-" + std::to_string(phase) + ")").c_str());
}

// One step of the animation: the ripple moves on, or the camera goes 10 degrees round.
void Step(Animation& animation)
{
  ++animation.Frame;
  if (animation.Orbit)
  {
    animation.Renderer->GetActiveCamera()->Azimuth(10.0);
  }
  else
  {
    SetPhase(animation.Ripple, 0.35 * animation.Frame);
  }
}

void Report(const Animation& animation)
{
  std::cout << "frame " << animation.Frame << ": "
            << (animation.Driver->GetMoving() ? "moving" : "idle") << ", k level "
            << animation.Driver->GetLevel() << ", "
            << animation.Visibility->GetNumberOfComputedPoints() << " points computed, "
            << animation.Visibility->GetNumberOfUnseenTriangles() << " triangles unseen, update "
            << static_cast<int>(1000.0 * animation.Driver->GetLastUpdateTime()) << " ms\n";
}

// The exposure, in stops, that puts the 95th percentile of the relit luminance at 0.8.
double AutoExposure(vtkEnvironmentVisibilityLighting* relight)
{
  relight->Update();
  auto* lighting = vtkFloatArray::SafeDownCast(
    relight->GetOutput()->GetPointData()->GetArray("EnvironmentLighting"));
  std::vector<double> luminance;
  for (vtkIdType i = 0; lighting && i < lighting->GetNumberOfTuples(); ++i)
  {
    const float* c = lighting->GetPointer(3 * i);
    luminance.push_back(0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]);
  }
  if (luminance.empty())
  {
    return 0.0;
  }
  const auto bright = luminance.begin() + (luminance.size() * 95) / 100;
  std::nth_element(luminance.begin(), bright, luminance.end());
  return *bright > 0.0 ? std::log2(0.8 / *bright) : 0.0;
}

void OnTimer(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* animation = static_cast<Animation*>(clientData);
  // The driver's refining frames come by timer too.
  const bool ours = callData && *static_cast<int*>(callData) == animation->TimerId;
  if (ours && animation->Running)
  {
    Step(*animation);
    animation->Renderer->GetRenderWindow()->Render();
  }
}

void OnKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* animation = static_cast<Animation*>(clientData);
  if (std::string(static_cast<vtkRenderWindowInteractor*>(caller)->GetKeySym()) == "space")
  {
    animation->Running = !animation->Running;
    std::cout << (animation->Running ? "running\n" : "paused: refining\n");
    // A paused animation is an idle scene: the driver refines it frame by frame.
    animation->Renderer->GetRenderWindow()->Render();
  }
}
}

int main(int argc, char* argv[])
{
  const std::string data = APERTURE_EXAMPLE_DATA;
  const std::string mode = argc > 1 ? argv[1] : "deform";
  if (mode != "deform" && mode != "orbit")
  {
    std::cerr << "usage: DynamicScenes deform [environment.exr] [picture.png]\n"
                 "       DynamicScenes orbit [bunny.obj] [environment.exr] [picture.png]\n";
    return 2;
  }
  Animation animation;
  animation.Orbit = mode == "orbit";
  int arg = 2;
  const std::string bunny =
    animation.Orbit && argc > arg ? argv[arg++] : data + "/stanford-bunny.obj";
  const std::string environmentFile = argc > arg ? argv[arg++] : data + "/env/forest.exr";
  const char* picture = argc > arg && std::string(argv[arg]) != "-" ? argv[arg] : nullptr;

  vtkNew<vtkRenderWindow> window;
  window->SetSize(360, 360);
  window->SetWindowName("ApertureLighting: dynamic scenes");
  if (picture)
  {
    window->SetOffScreenRendering(1);
  }
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.12, 0.13, 0.16);
  window->AddRenderer(renderer);
  animation.Renderer = renderer;

  // The geometry: a ball whose surface ripples, or the bunny.
  vtkNew<vtkSphereSource> ball;
  ball->SetThetaResolution(160);
  ball->SetPhiResolution(80);
  vtkNew<vtkArrayCalculator> ripple;
  ripple->SetInputConnection(ball->GetOutputPort());
  ripple->AddCoordinateScalarVariable("coordsZ", 2);
  ripple->SetResultArrayName("Ripple");
  SetPhase(ripple, 0.0);
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputConnection(ripple->GetOutputPort());
  warp->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Ripple");
  animation.Ripple = ripple;
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(bunny.c_str());

  vtkNew<vtkOcclusionQueryVisibility> visibility;
  visibility->SetInputConnection(animation.Orbit ? reader->GetOutputPort() : warp->GetOutputPort());
  visibility->SetRenderWindow(window);
  visibility->SetVertexFiltering(animation.Orbit);
  if (animation.Orbit)
  {
    // Rays cost in proportion to the points computed, which filtering keeps few; the GPU
    // backends render every direction's depth however few points need it.
    visibility->SetBackendToRayCast();
  }
  visibility->SetViewRenderer(renderer);
  animation.Visibility = visibility;

  vtkNew<vtkOpenEXRReader> environment;
  environment->SetFileName(environmentFile.c_str());
  environment->Update();
  if (environment->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "Could not read the environment " << environmentFile << "\n";
    return 1;
  }
  vtkNew<vtkEnvironmentVisibilityLighting> relight;
  relight->SetInputConnection(visibility->GetOutputPort());
  relight->SetEnvironmentConnection(environment->GetOutputPort());
  if (animation.Orbit)
  {
    relight->SetUpAxisToY();
  }

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(relight->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("EnvironmentColors");
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  if (animation.Orbit)
  {
    camera->SetPosition(-0.02, 0.12, 0.5);
    camera->SetFocalPoint(-0.02, 0.1, 0.0);
  }
  else
  {
    camera->SetPosition(3.0, 0.0, 1.2);
    camera->SetViewUp(0.0, 0.0, 1.0);
  }
  vtkAlgorithm* source = animation.Orbit ? static_cast<vtkAlgorithm*>(reader) : warp;
  source->Update();
  auto* surface = vtkPolyData::SafeDownCast(source->GetOutputDataObject(0));
  if (!surface || surface->GetNumberOfPolys() == 0)
  {
    std::cerr << "Could not read a surface from " << bunny << "\n";
    return 1;
  }
  renderer->ResetCamera(surface->GetBounds());
  camera->Zoom(animation.Orbit ? 1.4 : 1.2);

  // The driver: coarse while moving (within 50 ms an update), up to k = 258 when idle.
  vtkNew<vtkDynamicVisibilityDriver> driver;
  driver->SetVisibility(visibility);
  driver->SetLighting(relight);
  driver->SetProp(actor);
  driver->SetMaximumLevel(3);
  driver->SetTargetUpdateTime(0.05);
  // A static mesh computes each point once, so the orbit can afford k = 66 while it moves.
  driver->SetMinimumLevel(animation.Orbit ? 2 : 0);
  animation.Driver = driver;

  // Exposure from the first frame's lighting.
  visibility->SetLevel(2);
  relight->SetExposure(AutoExposure(relight));

  if (picture)
  {
    driver->Attach(renderer);
    vtkNew<vtkImageAppend> strip;
    strip->SetAppendAxis(0);
    auto grab = [&]()
    {
      vtkNew<vtkWindowToImageFilter> frame;
      frame->SetInput(window);
      frame->ReadFrontBufferOff();
      // The frame as the driver left it: a re-render would count as an idle frame.
      frame->ShouldRerenderOff();
      frame->Update();
      vtkNew<vtkImageData> copy;
      copy->DeepCopy(frame->GetOutput());
      strip->AddInputData(copy);
    };
    const int frames = animation.Orbit ? 36 : 12;
    vtkIdType computed = 0;
    for (int f = 0; f < frames; ++f)
    {
      window->Render();
      Report(animation);
      computed += visibility->GetNumberOfComputedPoints();
      if (f % (frames / 3) == 0)
      {
        grab();
      }
      Step(animation);
    }
    // Idle: the driver refines one level a frame.
    while (driver->NeedsRefinement())
    {
      window->Render();
      Report(animation);
      computed += visibility->GetNumberOfComputedPoints();
    }
    window->Render();
    grab();
    std::cout << computed << " point updates in " << animation.Frame << " frames ("
              << visibility->GetOutput()->GetNumberOfPoints() << " points)\n";
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(strip->GetOutputPort());
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
  driver->Attach(renderer, interactor);
  vtkNew<vtkCallbackCommand> tick;
  tick->SetClientData(&animation);
  tick->SetCallback(OnTimer);
  interactor->AddObserver(vtkCommand::TimerEvent, tick);
  vtkNew<vtkCallbackCommand> keys;
  keys->SetClientData(&animation);
  keys->SetCallback(OnKey);
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
  window->Render();
  animation.TimerId = interactor->CreateRepeatingTimer(40);
  std::cout << "space: pause (the lightsphere refines) or resume, drag to orbit, q: quit\n";
  interactor->Start();
  return 0;
}
