/*=========================================================================

  Program:   ApertureLighting
  Module:    TerrainMovingSun.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Mount Fuji through a day: per-texel apertures on a height field, lit by a moving sun.
//
//   TerrainMovingSun [fuji-terrain-rgb.png] [picture.png]
//
// Reads a Terrain-RGB tile (vtkTerrainRGBReader), computes one aperture per texel
// (vtkAperturePrecompute on the grid), and draws the raised surface with
// vtkApertureLightingMapper reading the apertures from the grid as a texture. The apertures are
// computed once; the sun moves freely. With a picture name it writes four times of day side by
// side; otherwise the sun crosses the sky in a window until you press q.

#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"
#include "vtkTerrainRGBReader.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkImageDataGeometryFilter.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkWarpScalar.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <iostream>
#include <string>

#ifndef APERTURE_EXAMPLE_DATA
#define APERTURE_EXAMPLE_DATA "."
#endif

namespace
{
struct Day
{
  vtkLight* Sun;
  vtkRenderWindow* Window;
  double Hour = 6.0;
};

// The sun at an hour of the day (6 to 18): rising in the east, highest at noon in the south.
void PlaceSun(vtkLight* sun, double hour)
{
  const double t = (hour - 6.0) / 12.0; // 0 at sunrise, 1 at sunset
  const double azimuth = vtkMath::RadiansFromDegrees(90.0 + 180.0 * t);
  const double elevation = vtkMath::RadiansFromDegrees(3.0 + 52.0 * std::sin(vtkMath::Pi() * t));
  // Compass: x east, y north, z up.
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetPosition(std::cos(elevation) * std::sin(azimuth), std::cos(elevation) * std::cos(azimuth),
    std::sin(elevation));
  // Low sun, warmer light.
  const double warm = std::sin(vtkMath::Pi() * t);
  sun->SetColor(1.0, 0.75 + 0.22 * warm, 0.5 + 0.42 * warm);
}

void OnTimer(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* day = static_cast<Day*>(clientData);
  day->Hour = day->Hour >= 18.0 ? 6.0 : day->Hour + 0.1;
  PlaceSun(day->Sun, day->Hour);
  day->Window->Render();
}
}

int main(int argc, char* argv[])
{
  const std::string tile =
    argc > 1 ? argv[1] : std::string(APERTURE_EXAMPLE_DATA) + "/fuji-terrain-rgb.png";
  const char* picture = argc > 2 ? argv[2] : nullptr;

  // Heights in metres on a 60 m grid.
  vtkNew<vtkTerrainRGBReader> reader;
  reader->SetFileName(tile.c_str());
  reader->SetSpacing(60.0, 60.0);

  // One aperture per texel of the grid, heights exaggerated 1.5 times.
  const double exaggeration = 1.5;
  vtkNew<vtkAperturePrecompute> apertures;
  apertures->SetInputConnection(reader->GetOutputPort());
  apertures->SetHeightScale(exaggeration);
  apertures->SetNumberOfRays(128);
  apertures->Update();
  vtkImageData* grid = vtkImageData::SafeDownCast(apertures->GetOutputDataObject(0));
  if (!grid || grid->GetNumberOfPoints() == 0)
  {
    std::cerr << "Could not compute apertures for " << tile << "\n";
    return 1;
  }

  // The surface, raised as the precompute raised it; the mapper reads the apertures from the
  // grid (per texel) with texture coordinates generated from x and y.
  vtkNew<vtkImageDataGeometryFilter> surface;
  surface->SetInputData(grid);
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputConnection(surface->GetOutputPort());
  warp->SetScaleFactor(exaggeration);
  warp->UseNormalOn(); // straight up, not along the grid's normals
  warp->SetNormal(0.0, 0.0, 1.0);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(warp->GetOutputPort());
  normals->SplittingOff();
  vtkNew<vtkApertureLightingMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->SetApertureImage(grid);
  mapper->ScalarVisibilityOff();
  mapper->SetSkyColor(0.55, 0.65, 0.85);
  mapper->SetSkyIntensity(0.35);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.86, 0.78);

  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  vtkApertureLightingMapper::SetLightRadius(sun, 0.0047);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AddLight(sun);
  renderer->SetBackground(0.09, 0.1, 0.12);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(15330.0, 15330.0, 0.0);
  camera->SetPosition(9000.0, -14000.0, 20000.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  camera->Zoom(2.0);

  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetWindowName("ApertureLighting: Mount Fuji through a day");

  if (picture)
  {
    // Four times of day side by side.
    window->SetOffScreenRendering(1);
    window->SetSize(480, 320);
    vtkNew<vtkImageAppend> day;
    day->SetAppendAxis(0);
    for (double hour : { 7.0, 10.0, 14.0, 17.5 })
    {
      PlaceSun(sun, hour);
      window->Render();
      vtkNew<vtkWindowToImageFilter> grab;
      grab->SetInput(window);
      grab->ReadFrontBufferOff();
      grab->Update();
      vtkNew<vtkImageData> frame;
      frame->DeepCopy(grab->GetOutput());
      day->AddInputData(frame);
    }
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(day->GetOutputPort());
    writer->SetFileName(picture);
    writer->Write();
    std::cout << "wrote " << picture << "\n";
    return 0;
  }

  window->SetSize(1024, 640);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  Day state{ sun, window };
  PlaceSun(sun, state.Hour);
  vtkNew<vtkCallbackCommand> tick;
  tick->SetClientData(&state);
  tick->SetCallback(OnTimer);
  interactor->AddObserver(vtkCommand::TimerEvent, tick);
  window->Render();
  interactor->CreateRepeatingTimer(40);
  std::cout << "The sun crosses the sky; drag to orbit, q to quit.\n";
  interactor->Start();
  return 0;
}
