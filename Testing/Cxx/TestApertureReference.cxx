/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureReference.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkApertureReference against analytic irradiance and an independent estimator:
// - a plane under a light of radius 0.3 rad overhead gets 1, tilted 40° gets cos 40°
//   (a cap fully above the horizon: ∫cap cos = π sin² r cos α), and under the sky 1 with no
//   noise;
// - the crease of a 90° concave corner, normal on the bisector, sees (1/π)∫ n·ω over a quarter
//   of the sphere = 1/√2 of the sky;
// - a plate over a plane (an occluder on port 1) blocks a light straight above;
// - a uniform environment of radiance 1 gives 1 on the plane;
// - on the bunny, the sky reference equals vtkAperturePrecompute's AmbientOcclusion (another
//   sampler, the same integral) and two seeds differ as the reported noise says they should;
// - bad input fails with an error.

#include "vtkAperturePrecompute.h"
#include "vtkApertureReference.h"
#include "vtkApertureTestHarness.h"
#include "vtkEnvironmentMap.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
using vtkApertureTest::Check;

vtkDataArray* Irradiance(vtkApertureReference* reference)
{
  return reference->GetOutput()->GetPointData()->GetArray("ReferenceIrradiance");
}

// Largest |value - expected| over the points, first component.
double Worst(vtkDataArray* values, double expected)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    worst = std::max(worst, std::abs(values->GetComponent(i, 0) - expected));
  }
  return worst;
}

// A square of side 2 around the origin in the z = height plane, as triangles.
vtkSmartPointer<vtkPolyData> Square(double height, int resolution)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, height);
  plane->SetPoint1(1, -1, height);
  plane->SetPoint2(-1, 1, height);
  plane->SetResolution(resolution, resolution);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}
}

int TestApertureReference(int argc, char* argv[])
{
  // A plane under lights and the sky.
  auto plane = Square(0.0, 8);
  vtkNew<vtkApertureReference> reference;
  reference->SetInputData(plane);
  reference->SetLightRadius(0.3);
  reference->SetNumberOfSamples(256);
  reference->SetLightDirection(0, 0, 2);
  reference->Update();
  double worst = Worst(Irradiance(reference), 1.0);
  Check(worst < 1e-3,
    "a light of radius 0.3 overhead gives 1 on a plane (worst " + std::to_string(worst) + ")");
  const double alpha = vtkMath::RadiansFromDegrees(40.0);
  reference->SetLightDirection(std::sin(alpha), 0.0, std::cos(alpha));
  reference->Update();
  // The sampled cosine over the cap is a quadrature: stratification keeps it tight.
  worst = Worst(Irradiance(reference), std::cos(alpha));
  Check(worst < 2e-3, "tilted 40 degrees it gives cos 40 (worst " + std::to_string(worst) + ")");
  reference->SetSourceToSky();
  reference->Update();
  worst = Worst(Irradiance(reference), 1.0) +
    Worst(reference->GetOutput()->GetPointData()->GetArray("ReferenceNoise"), 0.0);
  Check(worst < 1e-6, "the sky gives 1 on a plane, with no noise");

  // A uniform environment of radiance 1.
  vtkNew<vtkImageData> uniform;
  uniform->SetDimensions(64, 32, 1);
  vtkNew<vtkFloatArray> ones;
  ones->SetNumberOfComponents(3);
  ones->SetNumberOfTuples(64 * 32);
  ones->Fill(1.0);
  uniform->GetPointData()->SetScalars(ones);
  vtkNew<vtkEnvironmentMap> environment;
  environment->SetImage(uniform);
  reference->SetEnvironment(environment);
  reference->SetSourceToEnvironment();
  reference->Update();
  vtkDataArray* rgb = Irradiance(reference);
  Check(rgb->GetNumberOfComponents() == 3 && Worst(rgb, 1.0) < 1e-5,
    "a uniform environment of radiance 1 gives 1 (RGB)");

  // The crease of a 90-degree concave corner: floor z = 0 (x > 0) and wall x = 0 (z > 0).
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, -1, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(2, 1, 0);
  points->InsertNextPoint(2, -1, 0);
  points->InsertNextPoint(0, 1, 2);
  points->InsertNextPoint(0, -1, 2);
  points->InsertNextPoint(0, 0, 0); // the receiver, on the crease
  vtkNew<vtkCellArray> cells;
  // Fans around the receiver, so that it has edges to scale its ray offset.
  const vtkIdType fans[6][3] = { { 6, 0, 3 }, { 6, 3, 2 }, { 6, 2, 1 }, { 6, 1, 4 }, { 6, 4, 5 },
    { 6, 5, 0 } };
  for (const auto& fan : fans)
  {
    cells->InsertNextCell({ fan[0], fan[1], fan[2] });
  }
  vtkNew<vtkPolyData> corner;
  corner->SetPoints(points);
  corner->SetPolys(cells);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  const double s = std::sqrt(0.5);
  for (int i = 0; i < 7; ++i)
  {
    normals->InsertNextTuple3(s, 0.0, s);
  }
  corner->GetPointData()->SetNormals(normals);
  vtkNew<vtkApertureReference> crease;
  crease->SetInputData(corner);
  crease->SetSourceToSky();
  crease->SetNumberOfSamples(16384);
  crease->Update();
  const double seen = Irradiance(crease)->GetComponent(6, 0);
  Check(std::abs(seen - s) < 0.01,
    "the crease of a 90-degree corner sees " + std::to_string(seen) + " of the sky (1/sqrt 2)");

  // A plate above a plane, on the occluder port, hides a light overhead from the middle.
  vtkNew<vtkApertureReference> shaded;
  shaded->SetInputData(Square(0.0, 8));
  shaded->AddInputData(1, Square(0.5, 1));
  shaded->SetLightRadius(0.05);
  shaded->Update();
  vtkPolyData* out = shaded->GetOutput();
  vtkIdType middle = out->FindPoint(0.0, 0.0, 0.0);
  Check(Irradiance(shaded)->GetComponent(middle, 0) == 0.0,
    "an occluding plate hides a light overhead");
  Check(out->GetNumberOfPoints() == 81 && out->GetPointData()->GetNormals(),
    "the output is the receivers only, with the normals used");

  // The bunny: the sky reference is the cosine-weighted ambient occlusion of the precompute.
  char* bunnyName = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/stanford-bunny.obj");
  vtkNew<vtkOBJReader> bunny;
  bunny->SetFileName(bunnyName);
  delete[] bunnyName;
  bunny->Update();
  if (bunny->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cout << "FAIL the bunny cannot be read (is -D the Testing folder?)\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkAperturePrecompute> apertures;
  apertures->SetInputConnection(bunny->GetOutputPort());
  apertures->SetNumberOfRays(1024);
  apertures->ComputeAmbientOcclusionOn();
  apertures->Update();
  vtkNew<vtkApertureReference> sky;
  sky->SetInputConnection(bunny->GetOutputPort());
  sky->SetSourceToSky();
  sky->SetNumberOfSamples(1024);
  sky->Update();
  vtkNew<vtkApertureReference> other;
  other->SetInputConnection(bunny->GetOutputPort());
  other->SetSourceToSky();
  other->SetNumberOfSamples(1024);
  other->SetSeed(7);
  other->Update();
  vtkDataArray* ao = apertures->GetPolyDataOutput()->GetPointData()->GetArray("AmbientOcclusion");
  vtkDataArray* a = Irradiance(sky);
  vtkDataArray* b = Irradiance(other);
  vtkDataArray* noise = sky->GetOutput()->GetPointData()->GetArray("ReferenceNoise");
  double aoDifference = 0.0, seedDifference = 0.0, reported = 0.0, sum = 0.0;
  vtkIdType n = 0, skipped = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    if (std::isnan(a->GetComponent(i, 0)))
    {
      ++skipped; // points of no triangle
      continue;
    }
    ++n;
    aoDifference += std::abs(a->GetComponent(i, 0) - ao->GetComponent(i, 0));
    seedDifference += std::abs(a->GetComponent(i, 0) - b->GetComponent(i, 0));
    reported += noise->GetComponent(i, 0);
    sum += a->GetComponent(i, 0);
  }
  std::cout << "bunny sky, 1024 samples, " << n << " points (" << skipped
            << " of no triangle skipped): mean " << sum / n << ", mean |reference - AO| "
            << aoDifference / n << ", between seeds " << seedDifference / n
            << ", reported noise (mean standard error) " << reported / n << "\n";
  Check(aoDifference / n < 0.01, "the sky reference agrees with the precompute's AO within 1%");
  // Two independent estimates differ by sqrt(2) standard errors times sqrt(2/pi) on average;
  // the stratified sets do better than the independent-sample bound.
  Check(seedDifference / n < 1.13 * reported / n && seedDifference / n > 0.05 * reported / n,
    "two seeds differ within the reported noise");

  // Bad input.
  auto expect = [](vtkApertureReference* bad, const std::string& words, const std::string& what)
  {
    vtkNew<vtkTest::ErrorObserver> errors, executive;
    bad->AddObserver(vtkCommand::ErrorEvent, errors);
    bad->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
    bad->Update();
    const std::string message = errors->GetError() ? errors->GetErrorMessage() : std::string();
    std::cout << what << ": " << message.substr(std::min(message.size(), message.find("): ") + 3));
    Check(message.find(words) != std::string::npos &&
        bad->GetOutput()->GetPointData()->GetArray("ReferenceIrradiance") == nullptr,
      what);
  };
  vtkNew<vtkApertureReference> empty;
  vtkNew<vtkPolyData> nothing;
  empty->SetInputData(nothing);
  expect(empty, "empty", "empty input");
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkApertureReference> noPolygons;
  noPolygons->SetInputData(cloud);
  expect(noPolygons, "polygons", "points without polygons");
  vtkNew<vtkApertureReference> zero;
  zero->SetInputData(plane);
  zero->SetLightDirection(0, 0, 0);
  expect(zero, "not a direction", "a zero light direction");
  vtkNew<vtkApertureReference> nan;
  nan->SetInputData(plane);
  nan->SetLightDirection(std::nan(""), 0, 1);
  expect(nan, "not a direction", "a NaN light direction");
  vtkNew<vtkApertureReference> noEnvironment;
  noEnvironment->SetInputData(plane);
  noEnvironment->SetSourceToEnvironment();
  expect(noEnvironment, "needs an environment", "the environment source without one");
  return vtkApertureTest::Result();
}
