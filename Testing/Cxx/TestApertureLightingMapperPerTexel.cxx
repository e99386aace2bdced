/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperPerTexel.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The per-texel mode: apertures computed on the Fuji height field (one per texel) and read from
// a texture, with texture coordinates generated from the surface's x and y or taken from the
// input's own, render the same terrain as apertures computed per vertex on the same surface.

#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"
#include "vtkApertureTestHarness.h"
#include "vtkTerrainRGBReader.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkExtractVOI.h"
#include "vtkImageData.h"
#include "vtkImageDataGeometryFilter.h"
#include "vtkLight.h"
#include "vtkNew.h"
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

int TestApertureLightingMapperPerTexel(int argc, char* argv[])
{
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
