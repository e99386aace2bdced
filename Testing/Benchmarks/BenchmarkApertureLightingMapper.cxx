/*=========================================================================

  Program:   ApertureLighting
  Module:    BenchmarkApertureLightingMapper.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Frame time of vtkApertureLightingMapper against vtkPolyDataMapper, measured side by side in
// one run: a 1M-triangle height field (the Fuji tile resampled to 708 x 708 points) at 1024 x 768,
// median over an orbit of the camera, for each shading model (Exact, Horizon and Visibility mask
// also with an HDR environment as the sky; Horizon also per texel, from the aperture grid as big
// terrains take it), and for vtkSSAOPass (kernel 32) on the plain mapper as a peer reference. The
// configurations take turns, frame by frame, so that a noisy machine affects all of them alike.
// Both wall-clock time and the process's CPU time are measured: with Mesa's llvmpipe all rendering
// threads are the process's own, and CPU time does not count time lost to other processes.
//
// Usage: BenchmarkApertureLightingMapper <Testing/Data folder> [--quick]
//          [--side N] [--size WxH] [--frames N]
// --quick uses a small grid and window (a smoke test that the benchmark still works); --side sets
// the grid (2 (N - 1)^2 triangles), --size the window, --frames the frames per configuration.

#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"
#include "vtkEnvironmentMap.h"
#include "vtkTerrainRGBReader.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageDataGeometryFilter.h"
#include "vtkImageResize.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWarpScalar.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Configuration
{
  std::string Name;
  std::function<void()> Apply;
  std::vector<double> Wall, Cpu;
  double First = 0.0; // the first frame's wall time: shaders, buffers, tables
};

// CPU time of this process (all threads), in seconds.
double ProcessSeconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
    1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "Usage: " << argv[0] << " <Testing/Data folder> [--quick]\n";
    return 2;
  }
  const std::string data = argv[1];
  int side = 708, width = 1024, height = 768, frames = 30;
  for (int i = 2; i < argc; ++i)
  {
    const std::string option = argv[i];
    if (option == "--quick")
    {
      side = 64;
      width = 320;
      height = 240;
      frames = 3;
    }
    else if (option == "--side" && i + 1 < argc)
    {
      side = std::max(2, std::atoi(argv[++i]));
    }
    else if (option == "--size" && i + 1 < argc)
    {
      std::sscanf(argv[++i], "%dx%d", &width, &height);
    }
    else if (option == "--frames" && i + 1 < argc)
    {
      frames = std::max(1, std::atoi(argv[++i]));
    }
  }

  vtkNew<vtkTerrainRGBReader> reader;
  reader->SetFileName((data + "/fuji-terrain-rgb.png").c_str());
  reader->SetSpacing(60.0, 60.0);
  vtkNew<vtkImageResize> resize;
  resize->SetInputConnection(reader->GetOutputPort());
  resize->SetOutputDimensions(side, side, 1);
  // Frame times do not depend on how the apertures were found: the height-field path, which
  // also keeps the horizons that Horizon mode shades from, on a surface made from its grid.
  vtkNew<vtkAperturePrecompute> apertures;
  apertures->SetInputConnection(resize->GetOutputPort());
  apertures->ComputeHorizonAnglesOn();
  vtkNew<vtkImageDataGeometryFilter> surface;
  surface->SetInputConnection(apertures->GetOutputPort());
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputConnection(surface->GetOutputPort());
  warp->UseNormalOn();
  warp->SetNormal(0.0, 0.0, 1.0);
  // Point normals, as most meshes carry them (and as the masks need for their frame), for every
  // configuration alike.
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(warp->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  vtkPolyData* terrain = normals->GetOutput();
  // Masks are for meshes and their frame time does not depend on what they hold: the surface
  // gets a fixed pattern of 256-bit masks, about half of each open, for Visibility mask mode.
  vtkNew<vtkUnsignedCharArray> masks;
  masks->SetName("VisibilityMask");
  masks->SetNumberOfComponents(32);
  masks->SetNumberOfTuples(terrain->GetNumberOfPoints());
  for (vtkIdType i = 0; i < masks->GetNumberOfValues(); ++i)
  {
    masks->SetValue(i, static_cast<unsigned char>((i * 2654435761u) >> 24));
  }
  terrain->GetPointData()->AddArray(masks);
  const vtkIdType triangles = 2 * terrain->GetNumberOfPolys();

  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputData(terrain);
  plain->ScalarVisibilityOff();
  vtkNew<vtkApertureLightingMapper> aperture;
  aperture->SetInputData(terrain);
  aperture->ScalarVisibilityOff();
  aperture->SetSkyIntensity(0.3);
  vtkNew<vtkActor> actor;
  actor->GetProperty()->SetColor(0.85, 0.8, 0.7);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(-1.0, 0.2, 0.3);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);

  double bounds[6];
  terrain->GetBounds(bounds);
  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkSSAOPass> ssao;
  ssao->SetDelegatePass(basic);
  ssao->SetKernelSize(32);
  ssao->SetRadius(0.05 * (bounds[1] - bounds[0]));
  ssao->SetBias(0.01 * (bounds[5] - bounds[4]));
  ssao->BlurOn();

  auto use = [&](vtkMapper* mapper, bool withSSAO)
  {
    actor->SetMapper(mapper);
    renderer->SetPass(withSSAO ? static_cast<vtkRenderPass*>(ssao) : nullptr);
  };
  // A sky brighter toward its zenith (what it holds does not change the cost).
  vtkNew<vtkImageData> skyImage;
  skyImage->SetDimensions(256, 128, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(256 * 128);
  for (vtkIdType p = 0; p < 256 * 128; ++p)
  {
    const double v = (p / 256 + 0.5) / 128;
    radiance->SetTuple3(p, 0.2 + v, 0.3 + v, 0.5 + v);
  }
  skyImage->GetPointData()->SetScalars(radiance);
  vtkNew<vtkEnvironmentMap> sky;
  sky->SetImage(skyImage);
  auto model = [&](int mode, int lambert, bool environment = false)
  {
    use(aperture, false);
    aperture->SetShadingMode(mode);
    aperture->GetApertureLighting()->SetLambertMode(lambert);
    aperture->SetSkyEnvironment(environment ? sky.Get() : nullptr);
  };
  vtkNew<vtkApertureLightingMapper> perTexel;
  perTexel->SetInputData(terrain);
  perTexel->ScalarVisibilityOff();
  perTexel->SetSkyIntensity(0.3);
  perTexel->SetShadingModeToHorizon();
  perTexel->SetApertureImage(vtkImageData::SafeDownCast(apertures->GetOutputDataObject(0)));
  auto texels = [&](bool environment)
  {
    use(perTexel, false);
    perTexel->SetSkyEnvironment(environment ? sky.Get() : nullptr);
  };
  std::vector<Configuration> configurations = {
    { "vtkPolyDataMapper", [&]() { use(plain, false); }, {} },
    { "Standard", [&]() { model(vtkApertureLightingInterface::STANDARD, 0); }, {} },
    { "Exact", [&]() { model(vtkApertureLightingInterface::EXACT, 0); }, {} },
    { "Exact (lens moment)", [&]() { model(vtkApertureLightingInterface::EXACT, 1); }, {} },
    { "Smoothstep", [&]() { model(vtkApertureLightingInterface::SMOOTHSTEP, 0); }, {} },
    { "Simplified", [&]() { model(vtkApertureLightingInterface::SIMPLIFIED, 0); }, {} },
    { "BentNormal", [&]() { model(vtkApertureLightingInterface::BENT_NORMAL, 0); }, {} },
    { "Horizon", [&]() { model(vtkApertureLightingInterface::HORIZON, 0); }, {} },
    { "Visibility mask", [&]() { model(vtkApertureLightingInterface::VISIBILITY_MASK, 0); }, {} },
    { "Exact, HDR sky", [&]() { model(vtkApertureLightingInterface::EXACT, 0, true); }, {} },
    { "Horizon, HDR sky", [&]() { model(vtkApertureLightingInterface::HORIZON, 0, true); }, {} },
    { "Visibility mask, HDR sky",
      [&]() { model(vtkApertureLightingInterface::VISIBILITY_MASK, 0, true); }, {} },
    { "Horizon per texel", [&]() { texels(false); }, {} },
    { "Horizon per texel, HDR sky", [&]() { texels(true); }, {} },
    { "vtkSSAOPass (kernel 32)", [&]() { use(plain, true); }, {} },
  };

  vtkCamera* camera = renderer->GetActiveCamera();
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    bounds[4] };
  const double distance = 1.2 * (bounds[1] - bounds[0]);
  for (Configuration& c : configurations)
  {
    c.Apply();
    const auto start = std::chrono::steady_clock::now();
    window->Render(); // shaders, buffers
    window->WaitForCompletion();
    c.First = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  for (int frame = 0; frame < frames; ++frame)
  {
    const double angle = 2.0 * 3.141592653589793 * frame / frames;
    camera->SetFocalPoint(center);
    camera->SetPosition(center[0] + distance * std::cos(angle),
      center[1] + distance * std::sin(angle), center[2] + 0.6 * distance);
    camera->SetViewUp(0, 0, 1);
    renderer->ResetCameraClippingRange();
    for (Configuration& c : configurations)
    {
      c.Apply();
      window->Render(); // a configuration switch may rebuild shaders: not timed
      const double cpu = ProcessSeconds();
      const auto start = std::chrono::steady_clock::now();
      window->Render();
      window->WaitForCompletion();
      const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
      c.Wall.push_back(elapsed.count());
      c.Cpu.push_back(ProcessSeconds() - cpu);
    }
  }

  const double wallReference = Median(configurations[0].Wall);
  const double cpuReference = Median(configurations[0].Cpu);
  std::cout << "## vtkApertureLightingMapper benchmark\n\n"
            << triangles << " triangles (" << side << " x " << side << " height field), " << width
            << " x " << height << ", one sun and a sky, median of " << frames
            << " frames over an orbit\n\n"
            << "| mapper / shading | median frame (wall) | ratio (wall) | median frame (CPU) | "
               "ratio (CPU) | goal | first frame (wall) |\n"
            << "|---|---|---|---|---|---|---|\n";
  for (const Configuration& c : configurations)
  {
    const double wall = Median(c.Wall), cpu = Median(c.Cpu);
    const char* goal = c.Name == "Exact" ? "<= 1.3"
      : c.Name == "Smoothstep"           ? "<= 1.2"
      : c.Name == "Horizon"              ? "<= 1.4"
      : c.Name == "Visibility mask"      ? "<= 1.5"
                                         : "";
    std::printf("| %s | %.1f ms | %.2f | %.1f ms | %.2f | %s | %.2f s |\n", c.Name.c_str(),
      1000.0 * wall, wall / wallReference, 1000.0 * cpu, cpu / cpuReference, goal, c.First);
  }
  return 0;
}
