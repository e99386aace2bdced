/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperPerTexel.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The per-texel mode: apertures computed on the Fuji height field (one per texel) and read from
// a texture, with texture coordinates generated from the surface's x and y or taken from the
// input's own, render the same terrain as apertures computed per vertex on the same surface. A
// grid larger than one upload band (1200 x 1000 texels, uploaded 873 rows at a time) arrives
// whole: a plane whose texels are all open is lit evenly to its far edge.

#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"
#include "vtkApertureTestHarness.h"
#include "vtkTerrainRGBReader.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkExtractVOI.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageDataGeometryFilter.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestUtilities.h"
#include "vtkTextureMapToPlane.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWarpScalar.h"

#include <cmath>
#include <iostream>

using vtkApertureTest::Check;

namespace
{
// A plane under a sun overhead, shaded from a 1200 x 1000 grid of open apertures, is as bright
// by the grid's last rows as by its first.
void CheckLargeGrid()
{
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(1200, 1000, 1);
  const vtkIdType n = grid->GetNumberOfPoints();
  vtkNew<vtkFloatArray> bent, radius;
  bent->SetName("BentNormal");
  bent->SetNumberOfComponents(3);
  bent->SetNumberOfTuples(n);
  radius->SetName("ApertureRadius");
  radius->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    bent->SetTuple3(i, 0.0, 0.0, 1.0);
    radius->SetValue(i, static_cast<float>(0.5 * vtkMath::Pi()));
  }
  grid->GetPointData()->AddArray(bent);
  grid->GetPointData()->AddArray(radius);
  vtkNew<vtkPlaneSource> plane; // texture coordinates 0 to 1 over the grid
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetPoint1(1199.0, 0.0, 0.0);
  plane->SetPoint2(0.0, 999.0, 0.0);
  vtkNew<vtkApertureLightingMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  mapper->SetApertureImage(grid);
  mapper->SetSkyIntensity(0.1);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetIntensity(0.4);
  sun->SetPosition(600.0, 500.0, 1000.0);
  sun->SetFocalPoint(600.0, 500.0, 0.0);
  renderer->AddLight(sun);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(120, 100);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(599.5, 499.5, 3000.0);
  renderer->ResetCamera();
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 119, 99, 1, pixels, 0);
  // The mean value of 5 x 5 pixels around grid row 200 (the first band) and row 950 (the last).
  double quarters[2] = { 0.0, 0.0 };
  for (int y : { 0, 1 })
  {
    double display[3];
    renderer->SetWorldPoint(599.5, y ? 950.0 : 200.0, 0.0, 1.0);
    renderer->WorldToDisplay();
    renderer->GetDisplayPoint(display);
    const int cx = static_cast<int>(display[0]), cy = static_cast<int>(display[1]);
    for (int row = cy - 2; row <= cy + 2; ++row)
    {
      for (int x = 3 * (cx - 2); x < 3 * (cx + 3); ++x)
      {
        quarters[y] += pixels->GetValue(row * 120 * 3 + x) / 75.0;
      }
    }
  }
  std::cout << "1200 x 1000 grid: mean value " << quarters[0] << " at row 200, " << quarters[1]
            << " at row 950\n";
  Check(quarters[0] > 40.0 && quarters[0] < 250.0 && std::abs(quarters[0] - quarters[1]) < 1.0,
    "a grid of several upload bands reaches the texture whole");
}
}

int TestApertureLightingMapperPerTexel(int argc, char* argv[])
{
  CheckLargeGrid();
  char* file = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/fuji-terrain-rgb.png");
  vtkNew<vtkTerrainRGBReader> reader;
  reader->SetFileName(file);
  reader->SetSpacing(60.0, 60.0);
  delete[] file;
  vtkNew<vtkExtractVOI> sample;
  sample->SetInputConnection(reader->GetOutputPort());
  sample->SetSampleRate(4, 4, 1);
  sample->Update();
  vtkImageData* grid = sample->GetOutput();

  // Per texel: apertures on the grid.
  vtkNew<vtkAperturePrecompute> texels;
  texels->SetInputData(grid);
  texels->SetNumberOfRays(128);
  texels->Update();

  // Per vertex: the same surface (grid points raised by their heights, same triangles).
  vtkNew<vtkImageDataGeometryFilter> surface;
  surface->SetInputData(grid);
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputConnection(surface->GetOutputPort());
  vtkNew<vtkAperturePrecompute> vertices;
  vertices->SetInputConnection(warp->GetOutputPort());
  vertices->SetNumberOfRays(128);
  vertices->Update();

  // The per-texel surfaces carry no aperture arrays of their own: one without texture
  // coordinates, one with coordinates from 0 to 1 over the grid.
  vtkNew<vtkPolyData> bare;
  bare->ShallowCopy(vertices->GetOutputDataObject(0));
  bare->GetPointData()->RemoveArray("BentNormal");
  bare->GetPointData()->RemoveArray("ApertureRadius");
  double bounds[6];
  grid->GetBounds(bounds);
  vtkNew<vtkTextureMapToPlane> planeCoords;
  planeCoords->SetInputData(bare);
  planeCoords->SetOrigin(bounds[0], bounds[2], 0.0);
  planeCoords->SetPoint1(bounds[1], bounds[2], 0.0);
  planeCoords->SetPoint2(bounds[0], bounds[3], 0.0);
  planeCoords->AutomaticPlaneGenerationOff();
  planeCoords->Update();

  vtkNew<vtkApertureLightingMapper> mapper;
  mapper->ScalarVisibilityOff();
  mapper->SetSkyIntensity(0.3);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(-1.0, 0.3, 0.25);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);

  auto capture = [&](vtkUnsignedCharArray* pixels)
  {
    window->Render();
    window->GetPixelData(0, 0, 399, 299, 1, pixels, 0);
  };
  mapper->SetInputConnection(vertices->GetOutputPort());
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(7500, -9000, 14000);
  camera->SetFocalPoint(7500, 8000, 1000);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  vtkNew<vtkUnsignedCharArray> perVertex, generated, fromInput;
  capture(perVertex);
  mapper->SetApertureImage(texels->GetImageDataOutput());
  mapper->SetInputData(bare);
  capture(generated);
  mapper->SetInputConnection(planeCoords->GetOutputPort());
  capture(fromInput);

  for (vtkUnsignedCharArray* texel : { generated.Get(), fromInput.Get() })
  {
    double sum = 0.0, lit = 0.0;
    for (vtkIdType i = 0; i < perVertex->GetNumberOfValues(); ++i)
    {
      sum += std::abs(static_cast<double>(texel->GetValue(i)) - perVertex->GetValue(i));
      lit += texel->GetValue(i);
    }
    const double mean = sum / perVertex->GetNumberOfValues();
    std::cout << (texel == generated ? "generated" : "input") << " texture coordinates: mean "
              << "|per-texel - per-vertex| = " << mean << "/255, mean value "
              << lit / perVertex->GetNumberOfValues() << "/255\n";
    // Texture filtering (bilinear over 4 texels) and vertex interpolation (over a triangle's
    // 3 vertices) differ a little inside each cell.
    Check(mean <= 0.5 && lit / perVertex->GetNumberOfValues() >= 20.0,
      "per-texel apertures must render like per-vertex ones");
  }
  return vtkApertureTest::Result();
}
